import { describe, expect, it } from 'vitest';
import { createManifold, createPose, maxManifoldPoints } from '../packages/engine/src/collision/manifold.js';
import { collideMeshHalfSpace } from '../packages/engine/src/collision/mesh-halfspace.js';
import { collideMeshSphere, MESH_INSIDE_ID } from '../packages/engine/src/collision/mesh-sphere.js';
import type { CollisionHalfSpace, CollisionMesh } from '../packages/engine/src/collision/narrowphase-shapes.js';
import { createNarrowphaseScratch } from '../packages/engine/src/collision/narrowphase-scratch-nd.js';
import { closestPointOnSimplex } from '../packages/engine/src/collision/simplex-closest.js';
import { randomArray, seeded, uniform } from './support/random.js';
import { randomPose } from './support/poses.js';

const DIMS = [2, 3, 4, 5, 6];

/** The cross polytope |x|₁ <= s: vertices ±s e_i (index 2i: +, 2i + 1: −), 2ⁿ facets. */
function crossPolytope(n: number, s: number): CollisionMesh {
  const vertices = new Float64Array(2 * n * n);
  for (let i = 0; i < n; i += 1) {
    vertices[2 * i * n + i] = s;
    vertices[(2 * i + 1) * n + i] = -s;
  }
  const count = 1 << n;
  const facets = new Int32Array(count * n);
  const facetNormals = new Float64Array(count * n);
  const facetOffsets = new Float64Array(count).fill(s / Math.sqrt(n));
  for (let mask = 0; mask < count; mask += 1) {
    for (let i = 0; i < n; i += 1) {
      const plus = (mask & (1 << i)) !== 0;
      facets[mask * n + i] = plus ? 2 * i : 2 * i + 1;
      facetNormals[mask * n + i] = (plus ? 1 : -1) / Math.sqrt(n);
    }
  }
  return { kind: 'mesh', vertices, facets, facetNormals, facetOffsets };
}

/** Projection onto the ℓ1 ball of radius s (Duchi et al. 2008): independent of the mesh code. */
function projectL1(c: Float64Array, s: number): Float64Array {
  const n = c.length;
  let l1 = 0;
  for (let i = 0; i < n; i += 1) l1 += Math.abs(c[i]);
  if (l1 <= s) return Float64Array.from(c);
  const u = Array.from(c, Math.abs).sort((a, b) => b - a);
  let sum = 0;
  let theta = 0;
  for (let j = 0; j < n; j += 1) {
    sum += u[j];
    const t = (sum - s) / (j + 1);
    if (u[j] - t > 0) theta = t;
  }
  return Float64Array.from(c, (v) => Math.sign(v) * Math.max(Math.abs(v) - theta, 0));
}

/** Euclidean projection onto the probability simplex (sort-based). */
function projectSimplex(y: Float64Array): Float64Array {
  const u = Array.from(y).sort((a, b) => b - a);
  let sum = 0;
  let theta = 0;
  for (let j = 0; j < u.length; j += 1) {
    sum += u[j];
    const t = (sum - 1) / (j + 1);
    if (u[j] - t > 0) theta = t;
  }
  return Float64Array.from(y, (v) => Math.max(v - theta, 0));
}

/**
 * Brute-force minimisation of |V λ − p|² over the simplex: accelerated projected gradient with
 * restarts, many iterations. Returns the point.
 */
function bruteClosest(n: number, verts: Float64Array, p: Float64Array): Float64Array {
  const m = verts.length / n;
  let lip = 0;
  for (let i = 0; i < verts.length; i += 1) lip += verts[i] * verts[i];
  const step = 1 / (2 * lip);
  let lambda: Float64Array = new Float64Array(m).fill(1 / m);
  let y: Float64Array = Float64Array.from(lambda);
  const x = new Float64Array(n);
  const trialStep = new Float64Array(m);
  let t = 1;
  let fPrev = Infinity;
  const point = (l: Float64Array, into: Float64Array) => {
    into.fill(0);
    for (let a = 0; a < m; a += 1) for (let c = 0; c < n; c += 1) into[c] += l[a] * verts[a * n + c];
    return into;
  };
  for (let it = 0; it < 20000; it += 1) {
    point(y, x);
    for (let a = 0; a < m; a += 1) {
      let g = 0;
      for (let c = 0; c < n; c += 1) g += 2 * verts[a * n + c] * (x[c] - p[c]);
      trialStep[a] = y[a] - step * g;
    }
    const next = projectSimplex(trialStep);
    point(next, x);
    let f = 0;
    for (let c = 0; c < n; c += 1) f += (x[c] - p[c]) ** 2;
    if (f > fPrev) {
      // restart the momentum when the objective goes up
      t = 1;
      y = Float64Array.from(lambda);
      fPrev = Infinity;
      continue;
    }
    fPrev = f;
    const tNext = (1 + Math.sqrt(1 + 4 * t * t)) / 2;
    for (let a = 0; a < m; a += 1) y[a] = next[a] + ((t - 1) / tNext) * (next[a] - lambda[a]);
    lambda = next;
    t = tNext;
  }
  return point(lambda, new Float64Array(n));
}

describe('closest point on a simplex', () => {
  it('matches a brute-force minimisation to 1e-9 and satisfies the optimality condition, n = 2..6', () => {
    for (const n of DIMS) {
      const rand = seeded(800 + n);
      const out = new Float64Array(n);
      for (let trial = 0; trial < 12; trial += 1) {
        // a full n-simplex or a facet-like (n−1)-simplex, and a point inside or outside
        const m = trial % 2 ? n + 1 : n;
        const verts = randomArray(rand, m * n, -1, 1);
        const p = randomArray(rand, n, trial % 3 ? -2.5 : -0.3, trial % 3 ? 2.5 : 0.3);
        const bary = new Float64Array(m);
        const dist = closestPointOnSimplex(out, n, verts, p, bary);
        const brute = bruteClosest(n, verts, p);
        let bruteDist = 0;
        let gap = 0;
        for (let c = 0; c < n; c += 1) {
          bruteDist += (brute[c] - p[c]) ** 2;
          gap = Math.max(gap, Math.abs(brute[c] - out[c]));
        }
        expect(Math.abs(dist - Math.sqrt(bruteDist))).toBeLessThanOrEqual(1e-9);
        expect(gap).toBeLessThanOrEqual(1e-9);
        // barycentric coordinates: non-negative, sum 1, reproduce the point
        let sum = 0;
        for (let a = 0; a < m; a += 1) {
          expect(bary[a]).toBeGreaterThanOrEqual(0);
          sum += bary[a];
        }
        expect(Math.abs(sum - 1)).toBeLessThanOrEqual(1e-12);
        // optimality: (p − q)·(v − q) <= 0 for every vertex v
        for (let a = 0; a < m; a += 1) {
          let dot = 0;
          for (let c = 0; c < n; c += 1) dot += (p[c] - out[c]) * (verts[a * n + c] - out[c]);
          expect(dot).toBeLessThanOrEqual(1e-12);
        }
      }
    }
  });

  it('validates its arguments', () => {
    const out = new Float64Array(3);
    expect(() => closestPointOnSimplex(out, 3, new Float64Array(14), [0, 0, 0])).toThrow(TypeError);
    expect(() => closestPointOnSimplex(out, 3, new Float64Array(15), [0, 0, 0])).toThrow(/1 to 4 points/);
    expect(() => closestPointOnSimplex(out, 3, [0, 0, Number.NaN], [0, 0, 0])).toThrow(RangeError);
    expect(() => closestPointOnSimplex(new Float64Array(2), 3, [0, 0, 0], [0, 0, 0])).toThrow(/out/);
  });
});

describe('mesh–half-space', () => {
  it('a cross polytope: every vertex below the plane + margin with its exact height, n = 2..6', () => {
    for (const n of DIMS) {
      const rand = seeded(900 + n);
      const mesh = crossPolytope(n, 0.8);
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 2 * n);
      const normal = new Float64Array(n);
      normal[1] = 1;
      const floor: CollisionHalfSpace = { kind: 'halfspace', normal, offset: 0 };
      for (let trial = 0; trial < 10; trial += 1) {
        const pm = randomPose(rand, n, 0.2);
        pm.x[1] = uniform(rand, 0.3, 0.8);
        const hit = collideMeshHalfSpace(all, n, mesh, pm, floor, createPose(n), 0.05, scratch);
        const expected = new Map<number, number>();
        for (let v = 0; v < 2 * n; v += 1) {
          let y = pm.x[1];
          for (let c = 0; c < n; c += 1) y += pm.M[n + c] * mesh.vertices[v * n + c];
          if (y < 0.05) expected.set(v, y);
        }
        expect(hit).toBe(expected.size > 0);
        expect(all.count).toBe(expected.size);
        for (let p = 0; p < all.count; p += 1) {
          const y = expected.get(all.ids[p]);
          expect(y).toBeDefined();
          expect(Math.abs(all.separations[p] - (y as number))).toBeLessThanOrEqual(1e-12);
          expect(Math.abs(all.points[p * n + 1] - (y as number) / 2)).toBeLessThanOrEqual(1e-12);
        }
      }
      // axis-aligned, one vertex down: one point at depth x_1 − s
      const pm = createPose(n);
      pm.x[1] = 0.79;
      const out = createManifold(n);
      expect(collideMeshHalfSpace(out, n, mesh, pm, floor, createPose(n), 0.005, scratch)).toBe(true);
      expect(out.count).toBe(1);
      expect(out.ids[0]).toBe(3); // −s e_1
      expect(Math.abs(out.separations[0] + 0.01)).toBeLessThanOrEqual(1e-12);
      expect(out.count).toBeLessThanOrEqual(maxManifoldPoints(n));
    }
  });
});

describe('mesh–sphere', () => {
  it('a cross polytope against balls all round it: distance from the ℓ1 projection (1e-9), n = 2..6', () => {
    for (const n of DIMS) {
      const rand = seeded(1000 + n);
      const s = 1.2;
      const mesh = crossPolytope(n, s);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      let inside = 0;
      let outside = 0;
      for (let trial = 0; trial < 40; trial += 1) {
        const pm = randomPose(rand, n, 1);
        const local = randomArray(rand, n, -1.4, 1.4);
        if (trial % 3 === 0) {
          // every third centre inside the polytope (|c|₁ up to 0.95 s)
          let l1 = 0;
          for (let c = 0; c < n; c += 1) l1 += Math.abs(local[c]);
          const scale = (uniform(rand, 0.5, 0.95) * s) / l1;
          for (let c = 0; c < n; c += 1) local[c] *= scale;
        }
        const ps = createPose(n);
        for (let i = 0; i < n; i += 1) {
          let v = pm.x[i];
          for (let c = 0; c < n; c += 1) v += pm.M[i * n + c] * local[c];
          ps.x[i] = v;
        }
        const rho = uniform(rand, 0.05, 0.6);
        let l1 = 0;
        for (let c = 0; c < n; c += 1) l1 += Math.abs(local[c]);
        let expected: number;
        const nl = new Float64Array(n);
        if (l1 <= s) {
          // inside: the facet of least depth, plane distance (|c|₁ − s)/√n
          expected = (l1 - s) / Math.sqrt(n) - rho;
          for (let c = 0; c < n; c += 1) nl[c] = (local[c] >= 0 ? 1 : -1) / Math.sqrt(n);
        } else {
          const q = projectL1(local, s);
          let d = 0;
          for (let c = 0; c < n; c += 1) d += (local[c] - q[c]) ** 2;
          d = Math.sqrt(d);
          expected = d - rho;
          for (let c = 0; c < n; c += 1) nl[c] = (local[c] - q[c]) / d;
        }
        const hit = collideMeshSphere(out, n, mesh, pm, { kind: 'sphere', radius: rho }, ps, 0.02, scratch);
        expect(hit).toBe(expected < 0.02);
        if (!hit) continue;
        if (l1 <= s) inside += 1;
        else outside += 1;
        expect((out.ids[0] & MESH_INSIDE_ID) !== 0).toBe(l1 <= s);
        expect(Math.abs(out.separations[0] - expected)).toBeLessThanOrEqual(1e-9);
        for (let i = 0; i < n; i += 1) {
          let e = 0;
          for (let c = 0; c < n; c += 1) e += pm.M[i * n + c] * nl[c];
          // a ball centred exactly on a ridge has two valid normals; random centres never are
          expect(Math.abs(out.normal[i] - e)).toBeLessThanOrEqual(1e-9);
        }
      }
      expect(inside).toBeGreaterThan(0);
      expect(outside).toBeGreaterThan(0);
    }
  });

  it('a single simplex as a mesh agrees with the closest point of the solid simplex (1e-12)', () => {
    for (const n of DIMS) {
      const rand = seeded(1100 + n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const verts = randomArray(rand, (n + 1) * n, -1, 1);
      // facets: every n-subset, the normal pointing away from the left-out vertex
      const facets: number[] = [];
      const normals: number[] = [];
      const offsets: number[] = [];
      for (let skip = 0; skip <= n; skip += 1) {
        const idx = [...Array(n + 1).keys()].filter((v) => v !== skip);
        const facet = new Float64Array(n * n);
        idx.forEach((v, a) => facet.set(verts.subarray(v * n, v * n + n), a * n));
        // outward normal: minus the part of (left-out vertex − facet vertex) orthogonal to the facet's edges
        const edges: Float64Array[] = [];
        for (let a = 1; a < n; a += 1) {
          const e = new Float64Array(n);
          for (let c = 0; c < n; c += 1) e[c] = facet[a * n + c] - facet[c];
          for (const g of edges) {
            let dot = 0;
            for (let c = 0; c < n; c += 1) dot += e[c] * g[c];
            for (let c = 0; c < n; c += 1) e[c] -= dot * g[c];
          }
          const len = Math.hypot(...e);
          for (let c = 0; c < n; c += 1) e[c] /= len;
          edges.push(e);
        }
        const w = new Float64Array(n);
        for (let c = 0; c < n; c += 1) w[c] = verts[skip * n + c] - facet[c];
        for (const g of edges) {
          let dot = 0;
          for (let c = 0; c < n; c += 1) dot += w[c] * g[c];
          for (let c = 0; c < n; c += 1) w[c] -= dot * g[c];
        }
        const len = Math.hypot(...w);
        let off = 0;
        for (let c = 0; c < n; c += 1) {
          normals.push(-w[c] / len);
          off += (-w[c] / len) * facet[c];
        }
        offsets.push(off);
        facets.push(...idx);
      }
      const mesh: CollisionMesh = {
        kind: 'mesh',
        vertices: verts,
        facets: Int32Array.from(facets),
        facetNormals: Float64Array.from(normals),
        facetOffsets: Float64Array.from(offsets),
      };
      const closest = new Float64Array(n);
      for (let trial = 0; trial < 20; trial += 1) {
        const c = randomArray(rand, n, -2, 2);
        const ps = createPose(n);
        ps.x.set(c);
        const dist = closestPointOnSimplex(closest, n, verts, c);
        if (dist === 0) continue; // inside: covered by the cross polytope test
        const rho = dist + 0.01;
        expect(collideMeshSphere(out, n, mesh, createPose(n), { kind: 'sphere', radius: rho }, ps, 0, scratch)).toBe(true);
        expect(Math.abs(out.separations[0] + 0.01)).toBeLessThanOrEqual(1e-12);
        for (let k = 0; k < n; k += 1) {
          expect(Math.abs(out.normal[k] - (c[k] - closest[k]) / dist)).toBeLessThanOrEqual(1e-9);
        }
      }
    }
  });

  it('feature ids name the touched feature whichever facet found it', () => {
    const n = 3;
    const mesh = crossPolytope(n, 1);
    const scratch = createNarrowphaseScratch(n);
    const out = createManifold(n);
    const ps = createPose(n);
    const ids = new Set<number>();
    // balls beyond the vertex +e_0, in different directions: always the same vertex feature
    for (const [a, b] of [
      [0.1, 0.05],
      [-0.1, 0.07],
      [0.08, -0.1],
    ]) {
      ps.x.set([1.3, a, b]);
      expect(collideMeshSphere(out, n, mesh, createPose(n), { kind: 'sphere', radius: 0.5 }, ps, 0, scratch)).toBe(true);
      ids.add(out.ids[0]);
    }
    expect(ids.size).toBe(1);
  });
});
