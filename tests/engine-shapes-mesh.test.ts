import { determinant, dims, rotorToMatrix } from '@physin/algebra';
import { describe, expect, it } from 'vitest';
import { closedMeshMassProperties, ConvexMesh, HyperBox, simplexMassProperties } from '@physin/engine/internal';
import type { ConvexMeshShape } from '@physin/engine/internal';
import { cubeBoundary } from './support/meshes.js';
import type { TestMesh } from './support/meshes.js';
import { seeded, uniform } from './support/random.js';

// ---------------------------------------------------------------------------------------------
// Meshes built by the tests (independent of the library)

function expectRel(actual: number, expected: number, tol: number): void {
  const scale = Math.max(Math.abs(actual), Math.abs(expected), 1e-300);
  expect(Math.abs(actual - expected) / scale).toBeLessThanOrEqual(tol);
}

function factorial(n: number): number {
  return n <= 1 ? 1 : n * factorial(n - 1);
}

/** det[a_0 − p, …, a_(n−1) − p] with the library's general determinant. */
function coneDeterminant(n: number, points: number[][], p: number[]): number {
  const M = new Float64Array(n * n);
  for (let a = 0; a < n; a += 1) for (let c = 0; c < n; c += 1) M[c * n + a] = points[a][c] - p[c];
  return determinant(n, M);
}

/** Turns every facet so that its cone from the interior point `inside` is positive. */
function orientOutward(mesh: TestMesh, inside: number[]): TestMesh {
  const n = inside.length;
  const facets = mesh.facets.map((f) => {
    const det = coneDeterminant(
      n,
      f.map((i) => mesh.vertices[i]),
      inside,
    );
    return det > 0 ? f.slice() : [f[1], f[0], ...f.slice(2)];
  });
  return { vertices: mesh.vertices, facets };
}

/** The cross polytope |x|₁ <= 1: vertices ±e_i (index 2i for +, 2i+1 for −), one facet per orthant. */
function crossPolytope(n: number): TestMesh {
  const vertices: number[][] = [];
  for (let i = 0; i < n; i += 1) {
    for (const s of [1, -1]) {
      const v = new Array<number>(n).fill(0);
      v[i] = s;
      vertices.push(v);
    }
  }
  const facets: number[][] = [];
  for (let mask = 0; mask < 1 << n; mask += 1) facets.push([...Array(n).keys()].map((i) => 2 * i + ((mask >> i) & 1)));
  return { vertices, facets };
}

/** The n + 1 facets of a simplex (each leaves one vertex out). */
function simplexFacets(n: number): number[][] {
  return [...Array(n + 1).keys()].map((skip) => [...Array(n + 1).keys()].filter((i) => i !== skip));
}

/** A rotation matrix (det +1): a product of Givens turns by random angles in every plane. */
function randomRotation(n: number, rand: () => number): Float64Array {
  const Q = new Float64Array(n * n);
  for (let i = 0; i < n; i += 1) Q[i * n + i] = 1;
  for (let i = 0; i < n; i += 1) {
    for (let j = i + 1; j < n; j += 1) {
      const t = uniform(rand, -Math.PI, Math.PI);
      const [c, s] = [Math.cos(t), Math.sin(t)];
      for (let col = 0; col < n; col += 1) {
        const qi = Q[i * n + col];
        const qj = Q[j * n + col];
        Q[i * n + col] = c * qi - s * qj;
        Q[j * n + col] = s * qi + c * qj;
      }
    }
  }
  return Q;
}

/** Checks input vertex v = frameOffset + M(frameRotor)·local_v for every vertex, to tol. */
function expectFrameMapsBack(shape: ConvexMeshShape, input: number[][], tol: number): void {
  const n = shape.n;
  const D = dims(n);
  const M = rotorToMatrix(D, new Float64Array(n * n), shape.frameRotor);
  input.forEach((v, i) => {
    for (let r = 0; r < n; r += 1) {
      let x = shape.frameOffset[r];
      for (let c = 0; c < n; c += 1) x += M[r * n + c] * shape.vertices[i * n + c];
      expect(Math.abs(x - v[r])).toBeLessThanOrEqual(tol);
    }
  });
}

/** In its own frame a mesh must have its centroid at 0 and a diagonal covariance equal to massProperties. */
function expectPrincipalFrame(shape: ConvexMeshShape, tol: number): void {
  const n = shape.n;
  const again = closedMeshMassProperties(n, shape.vertices, shape.facets);
  expectRel(again.volume, shape.volume, 1e-13);
  const mp = shape.massProperties(dims(n), again.mass);
  let trace = 0;
  for (let i = 0; i < n; i += 1) trace += mp.covariance[i];
  let size = 0;
  for (const x of shape.vertices) size = Math.max(size, Math.abs(x));
  for (let r = 0; r < n; r += 1) {
    expect(Math.abs(again.centroid[r])).toBeLessThanOrEqual(tol * size);
    for (let c = 0; c < n; c += 1) {
      const expected = r === c ? mp.covariance[r] : 0;
      expect(Math.abs(again.covariance[r * n + c] - expected)).toBeLessThanOrEqual(tol * trace);
    }
  }
}

const NS = [2, 3, 4, 5];

// ---------------------------------------------------------------------------------------------

describe('test plan 4: a box given as a convex mesh matches HyperBox', () => {
  it('the Kuhn triangulation of the n-cube boundary is closed and has 2n(n−1)! facets', () => {
    for (const n of [2, 3, 4, 5, 6]) {
      const mesh = orientOutward(cubeBoundary(n, new Array(n).fill(1)), new Array(n).fill(0));
      expect(mesh.facets.length).toBe(2 * n * factorial(n - 1));
      // closedMeshMassProperties checks closed + consistently oriented, and the volume is 2ⁿ
      expectRel(closedMeshMassProperties(n, mesh.vertices, mesh.facets).volume, 2 ** n, 1e-14);
    }
  });

  it('axis-aligned, centred: volume, covariance and inertia equal HyperBox for n = 2..5 (1e-12 relative)', () => {
    const rand = seeded(4);
    for (const n of NS) {
      const D = dims(n);
      const a = Array.from({ length: n }, () => uniform(rand, 0.3, 1.5));
      const mass = uniform(rand, 0.5, 4);
      const mesh = ConvexMesh(D, cubeBoundary(n, a).vertices, cubeBoundary(n, a).facets);
      const box = HyperBox(D, a).massProperties(D, mass);
      const mp = mesh.massProperties(D, mass);
      expectRel(mp.volume, box.volume, 1e-12);
      for (let i = 0; i < n; i += 1) expectRel(mp.covariance[i], box.covariance[i], 1e-12);
      for (let p = 0; p < D.k; p += 1) expectRel(mp.inertia[p], box.inertia[p], 1e-12);
      expect(mesh.kind).toBe('mesh');
      expect(mesh.n).toBe(n);
      expect(mesh.facetCount).toBe(2 * n * factorial(n - 1));
      expect(Object.isFrozen(mesh)).toBe(true);
    }
  });

  it('not centred on the origin: frameOffset = the centre, frameRotor = identity, same mass properties (1e-12)', () => {
    const rand = seeded(5);
    for (const n of NS) {
      const D = dims(n);
      const a = Array.from({ length: n }, () => uniform(rand, 0.3, 1.5));
      const centre = Array.from({ length: n }, () => uniform(rand, -20, 20));
      const cube = cubeBoundary(n, a, centre);
      const mesh = ConvexMesh(D, cube.vertices, cube.facets);
      const box = HyperBox(D, a).massProperties(D, 1);
      const mp = mesh.massProperties(D, 1);
      expectRel(mp.volume, box.volume, 1e-12);
      for (let i = 0; i < n; i += 1) expectRel(mp.covariance[i], box.covariance[i], 1e-12);
      for (let c = 0; c < n; c += 1) expect(Math.abs(mesh.frameOffset[c] - centre[c])).toBeLessThanOrEqual(1e-12 * 20);
      expect(Math.abs(mesh.frameRotor[0] - 1)).toBeLessThanOrEqual(1e-15);
      for (let b = 1; b < D.r; b += 1) expect(Math.abs(mesh.frameRotor[b])).toBeLessThanOrEqual(1e-15);
      // in its own frame the box is centred and axis-aligned: |local coordinate c| = a_c at every corner
      for (let v = 0; v < mesh.vertexCount; v += 1) {
        for (let c = 0; c < n; c += 1) expectRel(Math.abs(mesh.vertices[v * n + c]), a[c], 1e-12);
      }
      expectFrameMapsBack(mesh, cube.vertices, 1e-12 * 20);
    }
  });

  it('rotated and moved: the principal frame is recovered; inertia equal up to order (1e-12)', () => {
    const rand = seeded(6);
    for (const n of NS) {
      const D = dims(n);
      const a = [0.5, 0.8, 1.1, 1.4, 1.7].slice(0, n);
      const centre = Array.from({ length: n }, () => uniform(rand, -3, 3));
      const Q = randomRotation(n, rand);
      const cube = cubeBoundary(n, a, centre, Q);
      const mesh = ConvexMesh(D, cube.vertices, cube.facets);
      const box = HyperBox(D, a).massProperties(D, 2);
      const mp = mesh.massProperties(D, 2);
      expectRel(mp.volume, box.volume, 1e-12);
      const sorted = (x: Float64Array): number[] => Array.from(x).sort((p, q) => p - q);
      const [mc, bc] = [sorted(mp.covariance), sorted(box.covariance)];
      const [mi, bi] = [sorted(mp.inertia), sorted(box.inertia)];
      for (let i = 0; i < n; i += 1) expectRel(mc[i], bc[i], 1e-12);
      for (let p = 0; p < D.k; p += 1) expectRel(mi[p], bi[p], 1e-12);
      // in the principal frame the box is axis-aligned: along local axis c every corner sits at ±a_σ(c),
      // where σ matches the covariance order
      for (let c = 0; c < n; c += 1) {
        const sigma = box.covariance.findIndex((x) => Math.abs(x - mp.covariance[c]) <= 1e-12 * x);
        expect(sigma).toBeGreaterThanOrEqual(0);
        for (let v = 0; v < mesh.vertexCount; v += 1) expectRel(Math.abs(mesh.vertices[v * n + c]), a[sigma], 1e-12);
      }
      for (let c = 0; c < n; c += 1) expect(Math.abs(mesh.frameOffset[c] - centre[c])).toBeLessThanOrEqual(1e-12 * 3);
      expectFrameMapsBack(mesh, cube.vertices, 1e-12 * 3);
      expectPrincipalFrame(mesh, 1e-13);
      // the full covariance from closedMeshMassProperties is Q diag(m a²/3) Qᵀ (1e-12 of the trace)
      const full = closedMeshMassProperties(n, cube.vertices, orientOutward(cube, centre).facets, 0.25);
      const m = 0.25 * full.volume;
      const trace = a.reduce((s, x) => s + (m * x * x) / 3, 0);
      for (let r = 0; r < n; r += 1) {
        for (let c = 0; c < n; c += 1) {
          let expected = 0;
          for (let e = 0; e < n; e += 1) expected += (Q[r * n + e] * Q[c * n + e] * m * a[e] * a[e]) / 3;
          expect(Math.abs(full.covariance[r * n + c] - expected)).toBeLessThanOrEqual(1e-12 * trace);
        }
      }
    }
  });

  it('facet planes: outward unit normals, every vertex on the inner side, each facet on its own plane (1e-13)', () => {
    const rand = seeded(7);
    for (const n of NS) {
      const a = [0.5, 0.8, 1.1, 1.4, 1.7].slice(0, n);
      const cube = cubeBoundary(n, a, new Array(n).fill(1), randomRotation(n, rand));
      const mesh = ConvexMesh(dims(n), cube.vertices, cube.facets);
      for (let f = 0; f < mesh.facetCount; f += 1) {
        let len = 0;
        for (let c = 0; c < n; c += 1) len += mesh.facetNormals[f * n + c] ** 2;
        expect(Math.abs(Math.sqrt(len) - 1)).toBeLessThanOrEqual(1e-14);
        // the box's offsets are its half extents, and every corner is inside
        expect(a.some((x) => Math.abs(x - mesh.facetOffsets[f]) <= 1e-13)).toBe(true);
        for (let v = 0; v < mesh.vertexCount; v += 1) {
          let d = -mesh.facetOffsets[f];
          for (let c = 0; c < n; c += 1) d += mesh.facetNormals[f * n + c] * mesh.vertices[v * n + c];
          const onFacet = Array.from(mesh.facets.subarray(f * n, f * n + n)).includes(v);
          if (onFacet) expect(Math.abs(d)).toBeLessThanOrEqual(1e-13);
          else expect(d).toBeLessThanOrEqual(1e-13);
        }
      }
      // stored facets are outward: every cone from the centroid (the local origin) is positive
      for (let f = 0; f < mesh.facetCount; f += 1) {
        const pts = Array.from(mesh.facets.subarray(f * n, f * n + n), (i) =>
          Array.from(mesh.vertices.subarray(i * n, i * n + n)),
        );
        expect(coneDeterminant(n, pts, new Array(n).fill(0))).toBeGreaterThan(0);
      }
    }
  });
});

describe('cross polytope (identity 13) and simplex', () => {
  it('cross polytope volume 2ⁿ/n! = 2, 4/3, 2/3, 4/15, 4/45 for n = 2..6 (1e-13 relative)', () => {
    const expected = [2, 4 / 3, 2 / 3, 4 / 15, 4 / 45];
    [2, 3, 4, 5, 6].forEach((n, i) => {
      const cp = crossPolytope(n);
      const mesh = ConvexMesh(dims(n), cp.vertices, cp.facets);
      expectRel(mesh.volume, expected[i], 1e-13);
      expectRel(mesh.massProperties(dims(n), 1).volume, 2 ** n / factorial(n), 1e-13);
    });
  });

  it('cross polytope C_ii = m·2/((n+1)(n+2)): mesh method (1e-13) and Monte Carlo with exact samples (within 4 SE)', () => {
    const rand = seeded(13);
    for (const n of [2, 3, 4, 5, 6]) {
      const D = dims(n);
      const cp = crossPolytope(n);
      const mesh = ConvexMesh(D, cp.vertices, cp.facets);
      const mp = mesh.massProperties(D, 3);
      const formula = (3 * 2) / ((n + 1) * (n + 2));
      for (let i = 0; i < n; i += 1) expectRel(mp.covariance[i], formula, 1e-13);
      // uniform points in |x|₁ <= 1: x_i = ±E_i / (E_1 + … + E_(n+1)), E exponential (Dirichlet(1, …, 1))
      const samples = 60_000;
      let s2 = 0;
      let s4 = 0;
      for (let s = 0; s < samples; s += 1) {
        const e = Array.from({ length: n + 1 }, () => -Math.log(1 - rand()));
        const total = e.reduce((p, q) => p + q, 0);
        const x0 = e[0] / total; // the sign does not change x0²
        s2 += x0 * x0;
        s4 += x0 ** 4;
      }
      const mean = s2 / samples;
      const se = Math.sqrt((s4 / samples - mean * mean) / samples);
      expect(Math.abs(3 * mean - formula)).toBeLessThan(4 * 3 * se);
    }
  });

  it('a random simplex: simplexMassProperties, closedMeshMassProperties and ConvexMesh agree with the closed form (1e-12)', () => {
    const rand = seeded(21);
    for (const n of [2, 3, 4, 5, 6]) {
      const D = dims(n);
      const v = Array.from({ length: n + 1 }, () => Array.from({ length: n }, () => uniform(rand, -1, 2)));
      // the closed form, written out here: volume |det|/n!, second moment about the origin
      const E = new Float64Array(n * n);
      for (let a = 0; a < n; a += 1) for (let c = 0; c < n; c += 1) E[c * n + a] = v[a + 1][c] - v[0][c];
      const volume = Math.abs(determinant(n, E)) / factorial(n);
      const sum = new Array<number>(n).fill(0);
      for (const p of v) for (let c = 0; c < n; c += 1) sum[c] += p[c];
      const g = sum.map((x) => x / (n + 1));
      const aboutCentroid = (r: number, c: number): number => {
        let s = sum[r] * sum[c];
        for (const p of v) s += p[r] * p[c];
        return (volume * s) / ((n + 1) * (n + 2)) - volume * g[r] * g[c];
      };
      const sx = simplexMassProperties(n, v);
      const facets = orientOutward({ vertices: v, facets: simplexFacets(n) }, g).facets;
      const closed = closedMeshMassProperties(n, v, facets);
      for (const res of [sx, closed]) {
        expectRel(res.volume, volume, 1e-12);
        expectRel(res.mass, volume, 1e-12);
        for (let c = 0; c < n; c += 1) expect(Math.abs(res.centroid[c] - g[c])).toBeLessThanOrEqual(1e-12);
        for (let r = 0; r < n; r += 1) {
          for (let c = 0; c < n; c += 1)
            expect(Math.abs(res.covariance[r * n + c] - aboutCentroid(r, c))).toBeLessThanOrEqual(1e-12 * volume);
        }
      }
      expectRel(Math.abs(sx.signedVolume), volume, 1e-12);
      // the mesh shape: its principal covariance is the spectrum of the closed form's matrix
      const mesh = ConvexMesh(D, v, simplexFacets(n));
      expectRel(mesh.volume, volume, 1e-12);
      let traceExpected = 0;
      for (let c = 0; c < n; c += 1) traceExpected += aboutCentroid(c, c) / volume;
      const mp = mesh.massProperties(D, 1);
      expectRel(
        mp.covariance.reduce((p, q) => p + q, 0),
        traceExpected,
        1e-12,
      );
      expectPrincipalFrame(mesh, 1e-12);
      expectFrameMapsBack(mesh, v, 1e-12 * 3);
    }
  });

  it('the simplex closed form matches Monte Carlo (n = 4, Dirichlet sampling, every entry within 4 SE)', () => {
    const rand = seeded(99);
    const n = 4;
    const v = Array.from({ length: n + 1 }, () => Array.from({ length: n }, () => uniform(rand, -1, 1)));
    const res = simplexMassProperties(n, v, 2);
    const samples = 80_000;
    const m1 = new Float64Array(n * n);
    const m2 = new Float64Array(n * n);
    for (let s = 0; s < samples; s += 1) {
      const e = Array.from({ length: n + 1 }, () => -Math.log(1 - rand()));
      const total = e.reduce((p, q) => p + q, 0);
      const y = new Array<number>(n).fill(0);
      for (let a = 0; a <= n; a += 1) for (let c = 0; c < n; c += 1) y[c] += (e[a] / total) * v[a][c];
      for (let c = 0; c < n; c += 1) y[c] -= res.centroid[c];
      for (let r = 0; r < n; r += 1) {
        for (let c = 0; c < n; c += 1) {
          m1[r * n + c] += y[r] * y[c];
          m2[r * n + c] += (y[r] * y[c]) ** 2;
        }
      }
    }
    for (let i = 0; i < n * n; i += 1) {
      const mean = m1[i] / samples;
      const se = Math.sqrt((m2[i] / samples - mean * mean) / samples);
      expect(Math.abs(res.mass * mean - res.covariance[i])).toBeLessThan(4 * res.mass * se);
    }
  });

  it('a regular hexagon (n = 2): area (3√3/2)ρ² and C_ii = m·5ρ²/24 (1e-13)', () => {
    const rho = 1.2;
    const vertices = Array.from({ length: 6 }, (_, i) => [
      rho * Math.cos((i * Math.PI) / 3) + 5,
      rho * Math.sin((i * Math.PI) / 3),
    ]);
    const facets = Array.from({ length: 6 }, (_, i) => [i, (i + 1) % 6]);
    const mesh = ConvexMesh(dims(2), vertices, facets);
    const mp = mesh.massProperties(dims(2), 1);
    expectRel(mp.volume, ((3 * Math.sqrt(3)) / 2) * rho * rho, 1e-13);
    expectRel(mp.covariance[0], (5 * rho * rho) / 24, 1e-13);
    expectRel(mp.covariance[1], (5 * rho * rho) / 24, 1e-13);
    expect(mesh.frameOffset[0]).toBeCloseTo(5, 13);
  });
});

describe('refusals: nothing is built from a bad mesh', () => {
  const D3 = dims(3);
  const cube = cubeBoundary(3, [1, 1, 1]);

  it('a cube with one corner pushed in is not convex; the message names a vertex and a facet', () => {
    const vertices = cube.vertices.map((v) => v.slice());
    vertices[7] = [0.2, 0.2, 0.2];
    expect(() => ConvexMesh(D3, vertices, cube.facets)).toThrow(RangeError);
    expect(() => ConvexMesh(D3, vertices, cube.facets)).toThrow(
      /not convex: 'vertices'\[\d\] \(.*\) lies outside the plane of 'facets'\[\d+\] by/,
    );
    // 4D: a tesseract with one corner pushed in
    const t = cubeBoundary(4, [1, 1, 1, 1]);
    const tv = t.vertices.map((v) => v.slice());
    tv[15] = [0.5, 0.5, 0.5, 0.5];
    expect(() => ConvexMesh(dims(4), tv, t.facets)).toThrow(/not convex/);
  });

  it('the convexity tolerance scales with the mesh size (default 1e-7 of it)', () => {
    for (const scale of [1e-3, 1, 1e3]) {
      // corner 6 is off the diagonals the Kuhn triangles of its faces share, so moving it out folds them
      const ok = cube.vertices.map((v) => v.map((x) => x * scale));
      ok[6] = ok[6].map((x) => x * (1 + 1e-9)); // out by 1e-9 of the size: rounding-level
      expectRel(ConvexMesh(D3, ok, cube.facets).volume, 8 * scale ** 3, 1e-8);
      const bad = cube.vertices.map((v) => v.map((x) => x * scale));
      bad[6] = bad[6].map((x) => x * (1 + 1e-5)); // out by 1e-5 of the size: a real fold
      expect(() => ConvexMesh(D3, bad, cube.facets)).toThrow(/not convex/);
      expect(ConvexMesh(D3, bad, cube.facets, { tolerance: 1e-3 }).volume).toBeGreaterThan(0);
    }
  });

  it('an open mesh (a facet missing) and a mesh with a facet doubled are refused', () => {
    expect(() => ConvexMesh(D3, cube.vertices, cube.facets.slice(1))).toThrow(/'facets' is not closed/);
    expect(() => ConvexMesh(D3, cube.vertices, [...cube.facets, cube.facets[0]])).toThrow(/more than 2 facets/);
    const t = cubeBoundary(4, [1, 1, 1, 1]);
    expect(() => ConvexMesh(dims(4), t.vertices, t.facets.slice(0, -1))).toThrow(/not closed/);
    expect(() => closedMeshMassProperties(3, cube.vertices, orientOutward(cube, [0, 0, 0]).facets.slice(2))).toThrow(
      /not closed/,
    );
  });

  it('closedMeshMassProperties refuses inconsistently oriented facets', () => {
    const good = orientOutward(cube, [0, 0, 0]);
    const flipped = good.facets.map((f, i) => (i === 3 ? [f[1], f[0], f[2]] : f));
    expect(() => closedMeshMassProperties(3, good.vertices, flipped)).toThrow(/oriented inconsistently/);
    // all inward is fine: the sign of the total tells
    const inward = good.facets.map((f) => [f[1], f[0], f[2]]);
    expectRel(closedMeshMassProperties(3, good.vertices, inward).volume, 8, 1e-14);
  });

  it('degenerate facets, indices out of range, bad types and lengths', () => {
    const v = cube.vertices;
    expect(() => ConvexMesh(D3, v, [[0, 0, 1], ...cube.facets.slice(1)])).toThrow(/'facets'\[0\] repeats vertex 0/);
    expect(() => ConvexMesh(D3, v, [[0, 1, 8], ...cube.facets.slice(1)])).toThrow(
      /'facets'\[0\]\[2\] must be a vertex index in \[0, 7\]/,
    );
    expect(() => ConvexMesh(D3, v, [[0, 1, 2.5], ...cube.facets.slice(1)])).toThrow(RangeError);
    expect(() => ConvexMesh(D3, v, [[0, 1], ...cube.facets.slice(1)])).toThrow(TypeError);
    expect(() =>
      ConvexMesh(
        D3,
        [
          [0, 0, 0],
          [1, 0, 0],
          [0, 1, 0],
        ],
        [[0, 1, 2]],
      ),
    ).toThrow(/at least 4 points/);
    const nan = v.map((p) => p.slice());
    nan[2][1] = Number.NaN;
    expect(() => ConvexMesh(D3, nan, cube.facets)).toThrow(/'vertices'\[2\]\[1\] must be finite/);
    expect(() =>
      ConvexMesh(
        D3,
        v.map((p) => p.slice(0, 2)),
        cube.facets,
      ),
    ).toThrow(TypeError);
    expect(() => ConvexMesh(D3, [1, 2, 3, 4], cube.facets)).toThrow(/multiple of 3/);
    expect(() => ConvexMesh(D3, 'mesh', cube.facets)).toThrow(TypeError);
    expect(() => ConvexMesh({} as never, v, cube.facets)).toThrow(TypeError);
    expect(() => ConvexMesh(D3, v, cube.facets, { tolerance: 0 })).toThrow(/'options.tolerance' must be > 0/);
    // a degenerate (zero-area) triangle: three collinear points in a closed mesh
    const line = [
      [0, 0, 0],
      [1, 0, 0],
      [2, 0, 0],
      [0, 1, 0],
      [0, 0, 1],
    ];
    expect(() =>
      ConvexMesh(D3, line, [
        [0, 1, 2],
        [0, 1, 3],
        [1, 2, 3],
        [0, 2, 3],
        [0, 1, 4],
        [1, 2, 4],
        [0, 2, 4],
      ]),
    ).toThrow(/degenerate/);
    // flat: four coplanar points with a tetrahedron's connectivity
    const flat = [
      [0, 0, 0],
      [1, 0, 0],
      [0, 1, 0],
      [1, 1, 0],
    ];
    expect(() => ConvexMesh(D3, flat, simplexFacets(3))).toThrow(/flat/);
    // a vertex used by no facet
    expect(() => ConvexMesh(D3, [...v, [0, 0, 0]], cube.facets)).toThrow(/'vertices'\[8\] is used by no facet/);
  });

  it("the caller's arrays are copied, not changed (facets are re-oriented in the copy)", () => {
    const facets = cube.facets.map((f) => f.slice());
    const flat = new Int32Array(facets.flat());
    const before = Array.from(flat);
    const mesh = ConvexMesh(D3, cube.vertices.flat(), flat);
    expect(Array.from(flat)).toEqual(before);
    expect(mesh.volume).toBeCloseTo(8, 13);
    expect(mesh.facets).not.toBe(flat);
  });
});

describe('ConvexMesh.fromTriangles (three.js triangle lists)', () => {
  /** Like three.js BoxGeometry: 4 vertices per face (24), 2 triangles per face, Float32 positions. */
  function boxGeometry(w: number, h: number, d: number): { positions: Float32Array; index: Uint16Array } {
    const positions: number[] = [];
    const index: number[] = [];
    const faces: [number, number, number][] = [
      [0, 1, 2],
      [0, 1, 2],
      [1, 2, 0],
      [1, 2, 0],
      [2, 0, 1],
      [2, 0, 1],
    ];
    const half = [w / 2, h / 2, d / 2];
    faces.forEach(([u, v, axis], f) => {
      const sign = f % 2 === 0 ? 1 : -1;
      const base = positions.length / 3;
      for (const [su, sv] of [
        [-1, 1],
        [1, 1],
        [-1, -1],
        [1, -1],
      ]) {
        const p = [0, 0, 0];
        p[u] = su * half[u];
        p[v] = sv * half[v];
        p[axis] = sign * half[axis];
        positions.push(...p);
      }
      index.push(base, base + 2, base + 1, base + 2, base + 3, base + 1);
    });
    return { positions: Float32Array.from(positions), index: Uint16Array.from(index) };
  }

  /** Like three.js SphereGeometry: a (W+1)×(H+1) grid with seam and pole copies. */
  function sphereGeometry(radius: number, W: number, H: number): { positions: Float32Array; index: Uint32Array } {
    const positions: number[] = [];
    const grid: number[][] = [];
    for (let iy = 0; iy <= H; iy += 1) {
      const row: number[] = [];
      for (let ix = 0; ix <= W; ix += 1) {
        const [u, v] = [ix / W, iy / H];
        positions.push(
          -radius * Math.cos(u * 2 * Math.PI) * Math.sin(v * Math.PI),
          radius * Math.cos(v * Math.PI),
          radius * Math.sin(u * 2 * Math.PI) * Math.sin(v * Math.PI),
        );
        row.push(positions.length / 3 - 1);
      }
      grid.push(row);
    }
    const index: number[] = [];
    for (let iy = 0; iy < H; iy += 1) {
      for (let ix = 0; ix < W; ix += 1) {
        const [a, b, c, d] = [grid[iy][ix + 1], grid[iy][ix], grid[iy + 1][ix], grid[iy + 1][ix + 1]];
        if (iy !== 0) index.push(a, b, d);
        if (iy !== H - 1) index.push(b, c, d);
      }
    }
    return { positions: Float32Array.from(positions), index: Uint32Array.from(index) };
  }

  it('a BoxGeometry (indexed, 24 repeated corners) merges to 8 vertices and matches HyperBox (1e-7: Float32 input)', () => {
    const D = dims(3);
    const { positions, index } = boxGeometry(2, 1, 0.6);
    const mesh = ConvexMesh.fromTriangles(D, positions, index);
    expect(mesh.vertexCount).toBe(8);
    expect(mesh.facetCount).toBe(12);
    const box = HyperBox(D, [1, 0.5, 0.3]).massProperties(D, 1.5);
    const mp = mesh.massProperties(D, 1.5);
    expectRel(mp.volume, box.volume, 1e-7);
    for (let i = 0; i < 3; i += 1) expectRel(mp.covariance[i], box.covariance[i], 1e-7);
    // non-indexed: every three positions are a triangle
    const flat: number[] = [];
    for (const i of index) flat.push(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
    const again = ConvexMesh.fromTriangles(D, Float32Array.from(flat));
    expect(again.vertexCount).toBe(8);
    expectRel(again.volume, mesh.volume, 1e-15);
  });

  it('a SphereGeometry needs mergeTolerance (its seam is not exactly repeated); with it, it is a closed convex ball', () => {
    const D = dims(3);
    const { positions, index } = sphereGeometry(0.8, 32, 16);
    expect(() => ConvexMesh.fromTriangles(D, positions, index)).toThrow(/not closed.*mergeTolerance/);
    const mesh = ConvexMesh.fromTriangles(D, positions, index, { mergeTolerance: 1e-6 });
    expect(mesh.vertexCount).toBe(32 * 15 + 2);
    const ball = (4 / 3) * Math.PI * 0.8 ** 3;
    // an inscribed polyhedron: a little smaller than the ball (1.3% at 32×16), never larger
    expect(mesh.volume).toBeLessThan(ball);
    expect(mesh.volume).toBeGreaterThan(0.98 * ball);
    const c = mesh.massProperties(D, 1).covariance;
    for (let i = 0; i < 3; i += 1) expect(Math.abs(c[i] - 0.8 ** 2 / 5) / (0.8 ** 2 / 5)).toBeLessThan(0.03);
  });

  it('refuses a non-3D Dims, a bad index array and a bad merge tolerance', () => {
    const { positions, index } = boxGeometry(1, 1, 1);
    expect(() => ConvexMesh.fromTriangles(dims(4), positions, index)).toThrow(/n = 3/);
    expect(() => ConvexMesh.fromTriangles(dims(3), positions, [0, 1])).toThrow(TypeError);
    expect(() => ConvexMesh.fromTriangles(dims(3), positions, [0, 1, 99])).toThrow(RangeError);
    expect(() => ConvexMesh.fromTriangles(dims(3), positions.subarray(0, 12))).toThrow(TypeError);
    expect(() => ConvexMesh.fromTriangles(dims(3), positions, index, { mergeTolerance: -1 })).toThrow(RangeError);
  });
});
