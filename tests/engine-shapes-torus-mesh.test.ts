import { determinant, dims } from '@physin/algebra';
import { describe, expect, it } from 'vitest';
import { closedMeshMassProperties, HyperTorus } from '@physin/engine/internal';

/**
 * Seed plan 9 (mass part): the analytic torus against a tessellated torus integrated by
 * closedMeshMassProperties (signed cones, valid for a non-convex closed mesh).
 *
 * The boundary of the solid n-torus is S¹ × S^(n−2): the core circle (angle φ in the plane
 * (i, j)) times the sphere of radius r round it. It is tessellated as (a polygon of M sides) ×
 * (a triangulated sphere), every prism split into simplices by the staircase rule with the
 * sphere vertices in global order, so neighbouring prisms agree on their shared faces.
 * Vertices lie on the true surface, so the mesh is inscribed and its error is O(h²).
 */

interface Sphere {
  /** Unit vectors in R^(n−1): component 0 is radial (away from the core circle), the rest the other axes. */
  points: number[][];
  /** (n−1)-tuples of point indices, sorted ascending. */
  simplices: number[][];
}

/** S¹ as a regular polygon of N sides. */
function circle(N: number): Sphere {
  const points = Array.from({ length: N }, (_, b) => [Math.cos((2 * Math.PI * b) / N), Math.sin((2 * Math.PI * b) / N)]);
  const simplices = Array.from({ length: N }, (_, b) => [b, (b + 1) % N].sort((x, y) => x - y));
  return { points, simplices };
}

/** S² as an octahedron whose faces are each cut into s² triangles, projected onto the sphere. */
function sphere2(s: number): Sphere {
  const points: number[][] = [];
  const index = new Map<string, number>();
  const pointAt = (p: number[]): number => {
    const len = Math.hypot(p[0], p[1], p[2]);
    const key = p.map((x) => (x / len).toFixed(12)).join(',');
    let i = index.get(key);
    if (i === undefined) {
      i = points.length;
      index.set(key, i);
      points.push(p.map((x) => x / len));
    }
    return i;
  };
  const simplices: number[][] = [];
  for (const sx of [1, -1]) {
    for (const sy of [1, -1]) {
      for (const sz of [1, -1]) {
        const [A, B, C] = [
          [sx, 0, 0],
          [0, sy, 0],
          [0, 0, sz],
        ];
        const at = (u: number, v: number): number => {
          const w = s - u - v;
          return pointAt([0, 1, 2].map((c) => (w * A[c] + u * B[c] + v * C[c]) / s));
        };
        for (let u = 0; u < s; u += 1) {
          for (let v = 0; v < s - u; v += 1) {
            simplices.push([at(u, v), at(u + 1, v), at(u, v + 1)]);
            if (u + v < s - 1) simplices.push([at(u + 1, v), at(u + 1, v + 1), at(u, v + 1)]);
          }
        }
      }
    }
  }
  return { points, simplices: simplices.map((t) => t.slice().sort((x, y) => x - y)) };
}

/** det[a_0 − p, …, a_(n−1) − p]. */
function coneDeterminant(n: number, pts: number[][], p: number[]): number {
  const M = new Float64Array(n * n);
  for (let a = 0; a < n; a += 1) for (let c = 0; c < n; c += 1) M[c * n + a] = pts[a][c] - p[c];
  return determinant(n, M);
}

/** Boundary of the solid torus (R, r) with the core circle in plane (pi, pj), M segments round the core. */
function torusMesh(n: number, R: number, r: number, pi: number, pj: number, M: number, S: Sphere) {
  const others = [...Array(n).keys()].filter((c) => c !== pi && c !== pj);
  const P = S.points.length;
  const vertices: number[][] = [];
  for (let a = 0; a < M; a += 1) {
    const phi = (2 * Math.PI * a) / M;
    for (const s of S.points) {
      const v = new Array<number>(n).fill(0);
      v[pi] = (R + r * s[0]) * Math.cos(phi);
      v[pj] = (R + r * s[0]) * Math.sin(phi);
      others.forEach((c, m) => {
        v[c] = r * s[m + 1];
      });
      vertices.push(v);
    }
  }
  const facets: number[][] = [];
  for (let a = 0; a < M; a += 1) {
    const [s0, s1] = [a, (a + 1) % M];
    for (const simplex of S.simplices) {
      // staircase: (s0, b_0..b_t), (s1, b_t..b_m)
      for (let t = 0; t < simplex.length; t += 1) {
        const f = [...simplex.slice(0, t + 1).map((b) => s0 * P + b), ...simplex.slice(t).map((b) => s1 * P + b)];
        // outward: positive cone from the nearest point of the core circle
        const centre = new Array<number>(n).fill(0);
        for (const i of f) for (let c = 0; c < n; c += 1) centre[c] += vertices[i][c] / n;
        const rho = Math.hypot(centre[pi], centre[pj]);
        const core = new Array<number>(n).fill(0);
        core[pi] = (R * centre[pi]) / rho;
        core[pj] = (R * centre[pj]) / rho;
        const det = coneDeterminant(
          n,
          f.map((i) => vertices[i]),
          core,
        );
        facets.push(det > 0 ? f : [f[1], f[0], ...f.slice(2)]);
      }
    }
  }
  return { vertices, facets };
}

/** Relative errors of volume and of each C_ii/m of the tessellation against HyperTorus. */
function errors(n: number, M: number, S: Sphere, R: number, r: number, pi: number, pj: number) {
  const D = dims(n);
  const mesh = torusMesh(n, R, r, pi, pj, M, S);
  const res = closedMeshMassProperties(n, mesh.vertices, mesh.facets);
  const exact = HyperTorus(D, R, r, [pi, pj]).massProperties(D, 1);
  const volume = (res.volume - exact.volume) / exact.volume;
  const covariance = Array.from(exact.covariance, (c, i) => (res.covariance[i * n + i] / res.mass - c) / c);
  let offDiagonal = 0;
  let centroid = 0;
  for (let a = 0; a < n; a += 1) {
    centroid = Math.max(centroid, Math.abs(res.centroid[a]));
    for (let b = 0; b < n; b += 1)
      if (a !== b) offDiagonal = Math.max(offDiagonal, Math.abs(res.covariance[a * n + b] / res.mass));
  }
  return { volume, covariance, offDiagonal, centroid, facets: mesh.facets.length, res, exact };
}

describe('torus: analytic formulas against a tessellated torus (closedMeshMassProperties)', () => {
  const [R, r] = [2, 0.7];

  it('3D (core in xz): errors shrink 4× (3.8..4.2) per doubling; Richardson-extrapolated values agree to 1e-5', () => {
    const levels = [
      errors(3, 64, circle(16), R, r, 0, 2),
      errors(3, 128, circle(32), R, r, 0, 2),
      errors(3, 256, circle(64), R, r, 0, 2),
    ];
    for (let l = 1; l < levels.length; l += 1) {
      const ratio = levels[l - 1].volume / levels[l].volume;
      expect(ratio).toBeGreaterThan(3.8);
      expect(ratio).toBeLessThan(4.2);
      for (let c = 0; c < 3; c += 1) {
        const q = levels[l - 1].covariance[c] / levels[l].covariance[c];
        expect(q).toBeGreaterThan(3.8);
        expect(q).toBeLessThan(4.2);
      }
    }
    const fine = levels[2];
    // the inscribed mesh is smaller than the torus by O(h²): measured 1.7e-3 at 256 × 64 segments
    expect(fine.volume).toBeLessThan(0);
    expect(Math.abs(fine.volume)).toBeLessThan(2.5e-3);
    // Richardson, (4 e_fine − e_coarse)/3, removes the h² term: measured ≤ 5e-6, the O(h⁴) remainder
    const extrapolated = (4 * levels[2].volume - levels[1].volume) / 3;
    expect(Math.abs(extrapolated)).toBeLessThan(1e-5);
    for (let c = 0; c < 3; c += 1) {
      expect(Math.abs((4 * levels[2].covariance[c] - levels[1].covariance[c]) / 3)).toBeLessThan(1e-5);
    }
    // symmetry: centroid at the origin, covariance diagonal (to rounding)
    expect(fine.centroid).toBeLessThan(1e-12);
    expect(fine.offDiagonal).toBeLessThan(1e-12);
  });

  it('3D identity 15 from the mesh: I_axis → m(R² + 3r²/4), I_diameter → m(4R² + 5r²)/8 (extrapolated, 1e-5)', () => {
    const [coarse, fine] = [errors(3, 128, circle(32), R, r, 0, 1), errors(3, 256, circle(64), R, r, 0, 1)];
    const inertia = (e: ReturnType<typeof errors>, i: number, j: number): number =>
      (e.res.covariance[i * 3 + i] + e.res.covariance[j * 3 + j]) / e.res.mass;
    const axis = (4 * inertia(fine, 0, 1) - inertia(coarse, 0, 1)) / 3;
    const diameter = (4 * inertia(fine, 1, 2) - inertia(coarse, 1, 2)) / 3;
    expect(Math.abs(axis / (R * R + (3 * r * r) / 4) - 1)).toBeLessThan(1e-5);
    expect(Math.abs(diameter / ((4 * R * R + 5 * r * r) / 8) - 1)).toBeLessThan(1e-5);
  });

  it('4D (core in yw): errors shrink ~4× (3.6..4.4) per doubling; Richardson-extrapolated values agree to 1e-3', () => {
    // the S² of the tube is an octahedron cut into s² triangles per face: its error dominates
    const coarse = errors(4, 24, sphere2(6), R, r, 1, 3);
    const fine = errors(4, 48, sphere2(12), R, r, 1, 3);
    expect(fine.facets).toBe(48 * 8 * 144 * 3);
    const ratio = coarse.volume / fine.volume;
    expect(ratio).toBeGreaterThan(3.6);
    expect(ratio).toBeLessThan(4.4);
    for (let c = 0; c < 4; c += 1) {
      const q = coarse.covariance[c] / fine.covariance[c];
      expect(q).toBeGreaterThan(3.6);
      expect(q).toBeLessThan(4.4);
    }
    // measured: volume −1.3e-2 at 48 × (s = 12); extrapolated −4.9e-4, the higher-order remainder of the coarse S²
    expect(fine.volume).toBeLessThan(0);
    expect(Math.abs(fine.volume)).toBeLessThan(1.5e-2);
    expect(Math.abs((4 * fine.volume - coarse.volume) / 3)).toBeLessThan(1e-3);
    for (let c = 0; c < 4; c += 1) expect(Math.abs((4 * fine.covariance[c] - coarse.covariance[c]) / 3)).toBeLessThan(1e-3);
    expect(fine.centroid).toBeLessThan(1e-12);
    expect(fine.offDiagonal).toBeLessThan(1e-12);
  });
});
