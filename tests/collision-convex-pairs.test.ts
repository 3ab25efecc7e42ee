/**
 * Convex mesh–box and convex mesh–convex mesh (collision/convex-polytope.ts, mesh-polytope.ts).
 *
 * - Against brute force (n = 2..5, seeded): random hulls of point clouds and random boxes, in
 *   every order, placed so that about half overlap. The signed separation and normal of GJK/EPA
 *   match the maximum over unit directions u of min_B b·u − max_A a·u (= −(h_A(u) + h_B(−u))),
 *   found by sampling directions (plus every facet normal), hill climbing on the sphere, and a
 *   last exact step: the nearest point to the origin of the affine hull of the active support
 *   points of A − B.
 * - The manifold: collide finds a contact iff the separation is below the margin; its deepest
 *   point's separation and its normal agree with the signed distance (within the face tie
 *   tolerance where a face carries the contact); box–mesh is mesh–box with the normal flipped.
 * - Rest heights in a World (3D, 4D) and a pile of convex bodies on a box floor.
 */
import { describe, expect, it } from 'vitest';
import { rotorApplyVector } from '@physin/algebra';
import { Body, ConvexMesh, dims, HyperBox, World } from '@physin/engine';
import type { Dims, Shape } from '@physin/engine';
import {
  collide,
  createManifold,
  createNarrowphaseScratch,
  polytopeSeparation,
  resetCollisionWarnings,
} from '../packages/engine/src/collision/index.js';
import type { CollidableShape, Pose } from '../packages/engine/src/collision/index.js';
import { createPose } from '../packages/engine/src/collision/manifold.js';
import { cubeBoundary } from './support/meshes.js';
import { randomRotation } from './support/poses.js';
import { randomUnitVector, seeded, uniform } from './support/random.js';

type Poly = { shape: Shape & CollidableShape; local: number[][] };

/** Facets of the convex hull of points in general position, by brute force over n-subsets. */
function hullFacets(n: number, pts: number[][]): number[][] {
  const facets: number[][] = [];
  const idx: number[] = [];
  const k = pts.length;
  const rec = (start: number) => {
    if (idx.length === n) {
      const normal = hyperplaneNormal(
        n,
        idx.map((i) => pts[i]!),
      );
      if (!normal) return;
      const o = dot(normal, pts[idx[0]!]!);
      let pos = 0;
      let neg = 0;
      for (let j = 0; j < k; j += 1) {
        if (idx.includes(j)) continue;
        const s = dot(normal, pts[j]!) - o;
        if (s > 1e-9) pos += 1;
        else if (s < -1e-9) neg += 1;
      }
      if (pos === 0 || neg === 0) facets.push(idx.slice());
      return;
    }
    for (let i = start; i < k; i += 1) {
      idx.push(i);
      rec(i + 1);
      idx.pop();
    }
  };
  rec(0);
  return facets;
}

function dot(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let s = 0;
  for (let i = 0; i < a.length; i += 1) s += a[i]! * b[i]!;
  return s;
}

/** Unit normal of the hyperplane through n points (Gram–Schmidt), or null when degenerate. */
function hyperplaneNormal(n: number, p: number[][]): number[] | null {
  const basis: number[][] = [];
  for (let k = 1; k < p.length; k += 1) {
    const e = p[k]!.map((x, c) => x - p[0]![c]!);
    if (!addToBasis(basis, e, 1e-12)) return null;
  }
  for (let a = 0; a < n; a += 1) {
    const e = new Array<number>(n).fill(0);
    e[a] = 1;
    const copy = basis.slice();
    if (addToBasis(copy, e, 1e-3)) return copy[copy.length - 1]!;
  }
  return null;
}

function addToBasis(basis: number[][], e: number[], tol: number): boolean {
  for (let pass = 0; pass < 2; pass += 1) {
    for (const b of basis) {
      const s = dot(b, e);
      for (let c = 0; c < e.length; c += 1) e[c] -= s * b[c]!;
    }
  }
  const l = Math.sqrt(dot(e, e));
  if (!(l > tol)) return false;
  basis.push(e.map((x) => x / l));
  return true;
}

/** A random hull: `count` points in a ball of radius r, the hull's vertices kept. */
function randomHull(D: Dims, rand: () => number, count: number, r: number): Poly {
  const n = D.n;
  const pts: number[][] = [];
  for (let i = 0; i < count; i += 1) {
    const u = randomUnitVector(rand, n);
    const s = r * (0.4 + 0.6 * rand());
    pts.push(Array.from(u, (x) => x * s * (0.6 + 0.8 * rand())));
  }
  const facets = hullFacets(n, pts);
  const used = [...new Set(facets.flat())].sort((a, b) => a - b);
  const remap = new Map(used.map((v, i) => [v, i]));
  const vertices = used.map((v) => pts[v]!);
  const shape = ConvexMesh(
    D,
    vertices,
    facets.map((f) => f.map((v) => remap.get(v)!)),
  ) as Shape & CollidableShape;
  return { shape, local: localVertices(shape) };
}

function randomBox(D: Dims, rand: () => number): Poly {
  const he = Array.from({ length: D.n }, () => uniform(rand, 0.2, 0.9));
  const shape = HyperBox(D, he) as Shape & CollidableShape;
  return { shape, local: localVertices(shape) };
}

/** Vertices in the shape's own frame (a mesh: its principal frame; a box: its corners). */
function localVertices(shape: Shape): number[][] {
  const s = shape as unknown as { kind: string; vertices?: Float64Array; halfExtents?: ArrayLike<number>; n?: number };
  if (s.kind === 'mesh') {
    const n = s.n!;
    const out: number[][] = [];
    for (let k = 0; k < s.vertices!.length / n; k += 1) out.push(Array.from(s.vertices!.subarray(k * n, k * n + n)));
    return out;
  }
  const h = Array.from(s.halfExtents!);
  const n = h.length;
  const out: number[][] = [];
  for (let m = 0; m < 1 << n; m += 1) out.push(h.map((x, c) => ((m >> c) & 1 ? x : -x)));
  return out;
}

function worldVertices(n: number, poly: Poly, pose: Pose): number[][] {
  return poly.local.map((v) => {
    const w = new Array<number>(n);
    for (let i = 0; i < n; i += 1) {
      let s = pose.x[i]!;
      for (let c = 0; c < n; c += 1) s += pose.M[i * n + c]! * v[c]!;
      w[i] = s;
    }
    return w;
  });
}

/** g(u) = min_B b·u − max_A a·u: the separation along u (A to B). */
function axisSeparation(A: number[][], B: number[][], u: ArrayLike<number>): number {
  let hiA = -Infinity;
  for (const a of A) hiA = Math.max(hiA, dot(a, u));
  let loB = Infinity;
  for (const b of B) loB = Math.min(loB, dot(b, u));
  return loB - hiA;
}

/** How far a world point lies outside the shape (the largest facet-plane distance; <= 0 inside). */
function outside(n: number, poly: Poly, pose: Pose, p: number[]): number {
  const local = new Array<number>(n).fill(0);
  for (let c = 0; c < n; c += 1) for (let i = 0; i < n; i += 1) local[c] += pose.M[i * n + c]! * (p[i]! - pose.x[i]!);
  const s = poly.shape as unknown as {
    kind: string;
    facetNormals?: Float64Array;
    facetOffsets?: Float64Array;
    halfExtents?: ArrayLike<number>;
  };
  let worst = -Infinity;
  if (s.kind === 'mesh') {
    for (let f = 0; f < s.facetOffsets!.length; f += 1) {
      let d = -s.facetOffsets![f]!;
      for (let c = 0; c < n; c += 1) d += s.facetNormals![f * n + c]! * local[c]!;
      worst = Math.max(worst, d);
    }
  } else {
    for (let c = 0; c < n; c += 1) worst = Math.max(worst, Math.abs(local[c]!) - s.halfExtents![c]!);
  }
  return worst;
}

function normalise(v: number[]): number[] {
  const l = Math.sqrt(dot(v, v));
  return v.map((x) => x / l);
}

/** Brute-force signed distance and normal (see the module comment). */
function bruteSeparation(
  n: number,
  A: number[][],
  B: number[][],
  rand: () => number,
  extra: number[][],
): { sep: number; u: number[] } {
  const starts: { g: number; u: number[] }[] = [];
  const samples = n === 2 ? 400 : n === 3 ? 1500 : 2500;
  for (let s = 0; s < samples; s += 1) {
    const u = Array.from(randomUnitVector(rand, n));
    starts.push({ g: axisSeparation(A, B, u), u });
  }
  for (const u of extra) starts.push({ g: axisSeparation(A, B, u), u });
  starts.sort((p, q) => q.g - p.g);
  let best = { g: -Infinity, u: [] as number[] };
  // up to 8 starts from different basins: the best samples, pairwise more than ~25° apart
  const chosen: { g: number; u: number[] }[] = [];
  for (const s of starts) {
    if (chosen.length === 8) break;
    if (chosen.every((c) => dot(c.u, s.u) < 0.9)) chosen.push(s);
  }
  for (const start of chosen) {
    let { g, u } = start;
    let step = 0.05;
    const tries = 40 * n;
    while (step > 1e-13) {
      let improved = false;
      for (let t = 0; t < tries; t += 1) {
        const r = randomUnitVector(rand, n);
        let v = normalise(u.map((x, c) => x + step * r[c]!));
        let gv = axisSeparation(A, B, v);
        if (!(gv > g)) continue;
        // follow a direction that works, doubling the stride while it keeps improving
        let stride = step;
        for (;;) {
          g = gv;
          u = v;
          stride *= 2;
          v = normalise(u.map((x, c) => x + stride * r[c]!));
          gv = axisSeparation(A, B, v);
          if (!(gv > g)) break;
        }
        improved = true;
        break;
      }
      if (!improved) step /= 2;
      else step = Math.min(0.05, step * 1.5);
    }
    for (const delta of [1e-2, 3e-3, 1e-3, 3e-4, 1e-4, 1e-5, 1e-6]) {
      const polished = polish(n, A, B, u, delta);
      if (polished && axisSeparation(A, B, polished) >= g) {
        u = polished;
        g = axisSeparation(A, B, u);
      }
    }
    if (g > best.g) best = { g, u };
  }
  return { sep: best.g, u: best.u };
}

/**
 * The exact optimum near u: the active support points of A − B at u (within delta), the nearest
 * point v of their affine hull to the origin, u = ±v/|v| (the sign with the larger separation).
 */
function polish(n: number, A: number[][], B: number[][], u: number[], delta: number): number[] | null {
  const hiA = Math.max(...A.map((a) => dot(a, u)));
  const loB = Math.min(...B.map((b) => dot(b, u)));
  const activeA = A.filter((a) => dot(a, u) >= hiA - delta);
  const activeB = B.filter((b) => dot(b, u) <= loB + delta);
  const pts: number[][] = [];
  for (const a of activeA) for (const b of activeB) pts.push(a.map((x, c) => x - b[c]!));
  const basis: number[][] = [];
  for (const p of pts.slice(1))
    addToBasis(
      basis,
      p.map((x, c) => x - pts[0]![c]!),
      1e-9,
    );
  // nearest point of p0 + span(basis) to the origin
  const v = pts[0]!.slice();
  for (const b of basis) {
    const s = dot(b, v);
    for (let c = 0; c < n; c += 1) v[c] -= s * b[c]!;
  }
  const l = Math.sqrt(dot(v, v));
  if (!(l > 1e-12)) return null;
  const plus = v.map((x) => x / l);
  const minus = plus.map((x) => -x);
  return axisSeparation(A, B, plus) >= axisSeparation(A, B, minus) ? plus : minus;
}

function facetNormalsWorld(n: number, poly: Poly, pose: Pose, sign: number): number[][] {
  const s = poly.shape as unknown as { kind: string; facetNormals?: Float64Array };
  const out: number[][] = [];
  if (s.kind === 'mesh') {
    const N = s.facetNormals!;
    for (let f = 0; f < N.length / n; f += 1) {
      const w = new Array<number>(n).fill(0);
      for (let i = 0; i < n; i += 1) for (let c = 0; c < n; c += 1) w[i] += pose.M[i * n + c]! * N[f * n + c]!;
      out.push(w.map((x) => sign * x));
    }
  } else {
    for (let c = 0; c < n; c += 1) {
      for (const g of [1, -1]) out.push(Array.from({ length: n }, (_, i) => sign * g * pose.M[i * n + c]!));
    }
  }
  return out;
}

describe('contact manifolds of mesh–box and mesh–mesh (seeded, n = 2..6)', () => {
  for (const n of [2, 3, 4, 5, 6]) {
    it(`n = ${n}: a contact iff the separation is below the margin; the deepest point at the true separation (1e-9) or within the face tie; box–mesh = mesh–box flipped`, () => {
      const D = dims(n);
      const rand = seeded(2000 + n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const swapped = createManifold(n);
      const tie = scratch.featureTieTolerance;
      const margin = 0.02;
      let contacts = 0;
      let worstShallow = 0;
      const trials = n <= 4 ? 60 : 20;
      for (let t = 0; t < trials; t += 1) {
        const meshB = t % 2 === 0;
        const A = randomHull(D, rand, n + 4 + (t % 3), 0.8);
        const B = meshB ? randomHull(D, rand, n + 5, 0.8) : randomBox(D, rand);
        const pa = createPose(n);
        const pb = createPose(n);
        pa.M.set(randomRotation(rand, n));
        pb.M.set(randomRotation(rand, n));
        const dir = randomUnitVector(rand, n);
        const dist = uniform(rand, 0.3, n >= 5 ? 1.2 : 1.6);
        for (let i = 0; i < n; i += 1) pb.x[i] = dist * dir[i]!;
        const normal = new Float64Array(n);
        const sep = polytopeSeparation(n, A.shape, pa, B.shape, pb, normal);
        const hit = collide(out, n, A.shape, pa, B.shape, pb, margin, scratch);
        expect(hit).toBe(sep < margin);
        if (!hit) {
          expect(out.count).toBe(0);
          continue;
        }
        contacts += 1;
        expect(out.count).toBeGreaterThan(0);
        expect(Math.abs(Math.hypot(...out.normal) - 1)).toBeLessThan(1e-12);
        let deepest = Infinity;
        for (let p = 0; p < out.count; p += 1) {
          expect(out.separations[p]!).toBeLessThan(margin);
          deepest = Math.min(deepest, out.separations[p]!);
        }
        // heights along a face normal are never below the true separation by more than the tie
        expect(deepest).toBeGreaterThan(sep - tie - 1e-9);
        // and the deepest point carries the whole depth
        expect(deepest).toBeLessThan(sep + 1e-9);
        worstShallow = Math.max(worstShallow, deepest - sep);
        // each point is midway between a point of A's surface and one of B's: p ∓ (s/2)·normal lie on
        // or inside A and B (1e-9), and the one nearer its own shape touches its boundary
        for (let p = 0; p < out.count; p += 1) {
          const half = out.separations[p]! / 2;
          const onA = Array.from({ length: n }, (_, i) => out.points[p * n + i]! - half * out.normal[i]!);
          const onB = Array.from({ length: n }, (_, i) => out.points[p * n + i]! + half * out.normal[i]!);
          const dA = outside(n, A, pa, onA);
          const dB = outside(n, B, pb, onB);
          expect(dA).toBeLessThan(1e-9);
          expect(dB).toBeLessThan(1e-9);
          expect(Math.max(dA, dB)).toBeGreaterThan(-1e-9);
        }
        // the manifold normal separates as well as the face it came from: within the tie of the best
        expect(axisSeparation(worldVertices(n, A, pa), worldVertices(n, B, pb), out.normal)).toBeGreaterThan(sep - tie - 1e-9);
        if (!meshB) {
          expect(collide(swapped, n, B.shape, pb, A.shape, pa, margin, scratch)).toBe(true);
          expect(swapped.count).toBe(out.count);
          for (let c = 0; c < n; c += 1) expect(swapped.normal[c]).toBe(-out.normal[c]!);
          for (let p = 0; p < out.count; p += 1) {
            expect(swapped.ids[p]).toBe(out.ids[p]);
            expect(swapped.separations[p]).toBe(out.separations[p]);
          }
        }
      }
      console.log(
        `n = ${n}: ${contacts} contacts of ${trials}; deepest manifold point above the true separation by at most ${worstShallow.toExponential(2)}`,
      );
      expect(contacts).toBeGreaterThan(trials / 4);
    });
  }
});

describe('faces flush: a cube as a mesh (coplanar simplices) on a box or on itself, n = 2..6', () => {
  for (const n of [2, 3, 4, 5, 6]) {
    it(`n = ${n}: overlapping, touching and apart within the margin: exact separation, the whole face (2^(n−1) points)`, () => {
      const D = dims(n);
      const cube = cubeBoundary(n, new Array<number>(n).fill(0.15));
      const mesh = ConvexMesh(D, cube.vertices, cube.facets) as Shape & CollidableShape;
      const box = HyperBox(D, new Array<number>(n).fill(0.15)) as Shape & CollidableShape;
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      for (const B of [box, mesh]) {
        for (const y of [0.1, 0.29, 0.3, 0.305, 0.31]) {
          const pa = createPose(n);
          const pb = createPose(n);
          pb.x[0] = 0.05;
          pb.x[1] = y;
          const normal = new Float64Array(n);
          expect(Math.abs(polytopeSeparation(n, mesh, pa, B, pb, normal) - (y - 0.3))).toBeLessThan(1e-12);
          expect(collide(out, n, mesh, pa, B, pb, 0.02, scratch)).toBe(true);
          expect(out.count).toBe(2 ** (n - 1));
          expect(out.normal[1]).toBe(1);
          for (let p = 0; p < out.count; p += 1) expect(Math.abs(out.separations[p]! - (y - 0.3))).toBeLessThan(1e-12);
        }
      }
    });
  }
});

describe('a face of many vertices (a prism over an 80-gon, 3D)', () => {
  it('a box resting on its cap, turned: 4 points at the box corners, at the overlap (1e-12), inside both shapes', () => {
    const D = dims(3);
    const N = 80;
    const vertices: number[][] = [];
    for (const y of [0.1, -0.1])
      for (let i = 0; i < N; i += 1)
        vertices.push([0.5 * Math.cos((2 * Math.PI * i) / N), y, 0.5 * Math.sin((2 * Math.PI * i) / N)]);
    const facets: number[][] = [];
    for (let i = 1; i < N - 1; i += 1) facets.push([0, i, i + 1], [N, N + i + 1, N + i]);
    for (let i = 0; i < N; i += 1) {
      const j = (i + 1) % N;
      facets.push([i, j, N + i], [j, N + j, N + i]);
    }
    const prism: Poly = { shape: ConvexMesh(D, vertices, facets) as Shape & CollidableShape, local: [] };
    prism.local = localVertices(prism.shape);
    const box: Poly = { shape: HyperBox(D, [0.3, 0.1, 0.2]) as Shape & CollidableShape, local: [] };
    box.local = localVertices(box.shape);
    const pa = createPose(3);
    const pb = createPose(3);
    const angle = 0.2;
    pb.M.set([Math.cos(angle), 0, Math.sin(angle), 0, 1, 0, -Math.sin(angle), 0, Math.cos(angle)]);
    pb.x.set([0.02, 0.1 + 0.1 - 0.01, -0.03]);
    const scratch = createNarrowphaseScratch(3);
    for (const [A, poseA, B, poseB, sign] of [
      [prism, pa, box, pb, 1],
      [box, pb, prism, pa, -1],
    ] as const) {
      const out = createManifold(3);
      expect(collide(out, 3, A.shape, poseA, B.shape, poseB, 0.02, scratch)).toBe(true);
      expect(out.count).toBe(4);
      expect(Math.abs(out.normal[1]! - sign)).toBeLessThan(1e-12);
      for (let p = 0; p < 4; p += 1) {
        expect(Math.abs(out.separations[p]! + 0.01)).toBeLessThan(1e-12);
        const half = out.separations[p]! / 2;
        const onA = [0, 1, 2].map((i) => out.points[p * 3 + i]! - half * out.normal[i]!);
        const onB = [0, 1, 2].map((i) => out.points[p * 3 + i]! + half * out.normal[i]!);
        expect(Math.abs(outside(3, A, poseA, onA))).toBeLessThan(1e-12);
        expect(Math.abs(outside(3, B, poseB, onB))).toBeLessThan(1e-12);
      }
    }
  });
});

describe('GJK / EPA signed distance against brute force (seeded, n = 2..5)', () => {
  const worst = { sep: 0, normal: 0 };
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: overlap, separation and normal of random hull and box pairs`, () => {
      const D = dims(n);
      const rand = seeded(1000 + n);
      const trials = n <= 3 ? 60 : n === 4 ? 45 : 30;
      let overlaps = 0;
      for (let t = 0; t < trials; t += 1) {
        const kind = t % 3; // 0: mesh–mesh, 1: mesh–box, 2: box–mesh
        const A = kind === 2 ? randomBox(D, rand) : randomHull(D, rand, n + 4 + (t % 4), 0.8);
        const B = kind === 1 ? randomBox(D, rand) : randomHull(D, rand, n + 4 + ((t + 1) % 4), 0.8);
        const pa = createPose(n);
        const pb = createPose(n);
        pa.M.set(randomRotation(rand, n));
        pb.M.set(randomRotation(rand, n));
        for (let i = 0; i < n; i += 1) pa.x[i] = uniform(rand, -1, 1);
        const dir = randomUnitVector(rand, n);
        const dist = uniform(rand, 0.3, 1.9);
        for (let i = 0; i < n; i += 1) pb.x[i] = pa.x[i]! + dist * dir[i]!;
        const normal = new Float64Array(n);
        const sep = polytopeSeparation(n, A.shape, pa, B.shape, pb, normal);
        const wa = worldVertices(n, A, pa);
        const wb = worldVertices(n, B, pb);
        const extra = [...facetNormalsWorld(n, A, pa, 1), ...facetNormalsWorld(n, B, pb, -1)];
        const brute = bruteSeparation(n, wa, wb, rand, extra);
        expect(sep < 0).toBe(brute.sep < 0);
        if (sep < 0) overlaps += 1;
        const dSep = Math.abs(sep - brute.sep);
        const dNormal = Math.sqrt(brute.u.reduce((s, x, c) => s + (x - normal[c]!) ** 2, 0));
        worst.sep = Math.max(worst.sep, dSep);
        worst.normal = Math.max(worst.normal, dNormal);
        expect(dSep).toBeLessThan(1e-12);
        expect(dNormal).toBeLessThan(1e-7);
        // the normal achieves the separation
        expect(Math.abs(axisSeparation(wa, wb, normal) - sep)).toBeLessThan(1e-12);
      }
      expect(overlaps).toBeGreaterThan(trials / 5);
      expect(overlaps).toBeLessThan(trials - trials / 5);
    });
  }
  it('reports the worst errors', () => {
    console.log(
      `convex pairs vs brute force: worst |Δseparation| ${worst.sep.toExponential(2)}, worst |Δnormal| ${worst.normal.toExponential(2)}`,
    );
  });
});

/** Householder reflection (n×n, row-major) taking the unit vector a to the unit vector b. */
function reflection(n: number, a: number[], b: number[]): number[][] {
  const w = normalise(a.map((x, i) => x - b[i]!));
  return Array.from({ length: n }, (_, i) => Array.from({ length: n }, (_, j) => (i === j ? 1 : 0) - 2 * w[i]! * w[j]!));
}

function apply(H: number[][], v: number[]): number[] {
  return H.map((row) => dot(row, v));
}

/** A convex mesh from points (its hull), turned by H; with its facets found by brute force. */
function meshFrom(D: Dims, points: number[][], H?: number[][]): Shape {
  const pts = H ? points.map((p) => apply(H, p)) : points;
  return ConvexMesh(D, pts, hullFacets(D.n, pts));
}

const PHI = (1 + Math.sqrt(5)) / 2;
/** The 12 vertices of the icosahedron with edge 2s: cyclic permutations of (0, ±s, ±φs). */
function icosahedron(s: number): number[][] {
  const out: number[][] = [];
  for (const a of [-1, 1]) {
    for (const b of [-1, 1]) {
      out.push([0, a * s, b * PHI * s], [a * s, b * PHI * s, 0], [b * PHI * s, 0, a * s]);
    }
  }
  return out;
}

/** The 2n vertices ±s e_i of the cross-polytope. */
function crossPolytope(n: number, s: number): number[][] {
  const out: number[][] = [];
  for (let i = 0; i < n; i += 1) for (const g of [1, -1]) out.push(Array.from({ length: n }, (_, c) => (c === i ? g * s : 0)));
  return out;
}

function down(n: number): number[] {
  return Array.from({ length: n }, (_, i) => (i === 1 ? -1 : 0));
}

function makeWorld(n: number): World {
  resetCollisionWarnings();
  return new World({ dimensions: n, gravity: down(n).map((x) => 9.81 * x), params: { allowSleep: false } });
}

/** The lowest world height of a mesh body's vertices. */
function lowestVertex(body: Body): number {
  const n = body.x.length;
  const mesh = body.shape as unknown as { vertices: Float64Array };
  const u = new Float64Array(n);
  let low = Infinity;
  for (let k = 0; k < mesh.vertices.length / n; k += 1) {
    rotorApplyVector(body.D, u, body.R, mesh.vertices.subarray(k * n, k * n + n));
    low = Math.min(low, body.x[1]! + u[1]!);
  }
  return low;
}

interface RestCase {
  name: string;
  n: number;
  /** Builds the scene; returns the resting body and the analytic height of its centre. */
  build: (world: World) => { body: Body; height: number };
}

const REST: RestCase[] = [
  {
    name: 'an icosahedron (12 vertices, face down) on a static box, 3D',
    n: 3,
    build(world) {
      const D = world.D;
      const s = 0.3;
      // turn a face normal (1, 1, 1)/√3 to −y: the facet through three vertices with all coordinates >= 0
      const H = reflection(3, normalise([1, 1, 1]), down(3));
      const mesh = meshFrom(D, icosahedron(s), H);
      const inradius = (PHI * PHI * s) / Math.sqrt(3);
      world.addBody(new Body(D, { shape: HyperBox(D, [2, 0.5, 2]), mass: 0, position: [0, -0.5, 0] }));
      const body = world.addBody(new Body(D, { shape: mesh, mass: 1, position: [0.1, inradius + 0.05, -0.05] }));
      return { body, height: inradius };
    },
  },
  {
    name: 'a box on a static octahedron (face up), 3D',
    n: 3,
    build(world) {
      const D = world.D;
      const s = 0.8;
      const H = reflection(3, normalise([1, 1, 1]), [0, 1, 0]);
      const octa = meshFrom(D, crossPolytope(3, s), H);
      world.addBody(new Body(D, { shape: octa, mass: 0, position: [0, 0, 0] }));
      const half = 0.15;
      const top = s / Math.sqrt(3);
      const body = world.addBody(
        new Body(D, { shape: HyperBox(D, [half, half, half]), mass: 1, position: [0, top + half + 0.05, 0] }),
      );
      return { body, height: top + half };
    },
  },
  {
    name: 'a 4D cross-polytope (facet down) on a static hyperbox',
    n: 4,
    build(world) {
      const D = world.D;
      const s = 0.5;
      const H = reflection(4, normalise([1, 1, 1, 1]), down(4));
      const mesh = meshFrom(D, crossPolytope(4, s), H);
      world.addBody(new Body(D, { shape: HyperBox(D, [2, 0.5, 2, 2]), mass: 0, position: [0, -0.5, 0, 0] }));
      const inradius = s / 2;
      const body = world.addBody(new Body(D, { shape: mesh, mass: 1, position: [0.05, inradius + 0.05, 0, -0.05] }));
      return { body, height: inradius };
    },
  },
];

describe('rest heights in a World', () => {
  for (const c of REST) {
    it(`${c.name}: at rest after 3 s at the analytic height within the penetration slop, no sinking over 10 s`, () => {
      const world = makeWorld(c.n);
      const warn = console.warn;
      const warnings: unknown[] = [];
      console.warn = (...args: unknown[]) => void warnings.push(args);
      try {
        const { body, height } = c.build(world);
        const slop = world.params.penetrationSlop;
        const dt = 1 / 60;
        for (let s = 0; s < 180; s += 1) world.step(dt);
        const h3 = body.x[1]!;
        let speed = 0;
        for (const v of body.v) speed = Math.max(speed, Math.abs(v));
        for (let s = 0; s < 420; s += 1) world.step(dt);
        const h10 = body.x[1]!;
        console.log(
          `${c.name}: height − analytic at 3 s ${(h3 - height).toExponential(3)}, at 10 s ${(h10 - height).toExponential(3)}, |v| at 3 s ${speed.toExponential(2)}`,
        );
        expect(warnings).toEqual([]);
        expect(Math.abs(h3 - height)).toBeLessThan(slop);
        expect(speed).toBeLessThan(1e-3);
        expect(Math.abs(h10 - height)).toBeLessThan(slop);
        expect(Math.abs(h10 - h3)).toBeLessThan(1e-5);
      } finally {
        console.warn = warn;
      }
    });
  }
});

describe('a pile of convex bodies on a box floor settles without tunnelling', () => {
  for (const n of [3, 4]) {
    const count = n === 3 ? 20 : 12;
    it(`n = ${n}: ${count} convex meshes (icosahedra or cross-polytopes, random hulls, cubes) dropped in a heap, every one above the floor after 5 s`, () => {
      const world = makeWorld(n);
      const D = world.D;
      const rand = seeded(77 + n);
      const warn = console.warn;
      const warnings: unknown[] = [];
      console.warn = (...args: unknown[]) => void warnings.push(args);
      try {
        const floorHalf = Array.from({ length: n }, (_, i) => (i === 1 ? 0.5 : 2.5));
        world.addBody(new Body(D, { shape: HyperBox(D, floorHalf), mass: 0, position: down(n).map((x) => 0.5 * x) }));
        const bodies: Body[] = [];
        const perLayer = n === 3 ? 5 : 4;
        for (let k = 0; k < count; k += 1) {
          let shape: Shape;
          const kind = k % 3;
          if (kind === 0) shape = meshFrom(D, n === 3 ? icosahedron(0.15) : crossPolytope(n, 0.3));
          else if (kind === 1) shape = randomHull(D, rand, n + 6, 0.3).shape;
          else {
            // a cube as a mesh: each square facet split into simplices (coplanar facets)
            const cube = cubeBoundary(n, new Array<number>(n).fill(0.15));
            shape = ConvexMesh(D, cube.vertices, cube.facets);
          }
          const layer = Math.floor(k / perLayer);
          const slot = k % perLayer;
          const position = Array.from({ length: n }, (_, i) => (i === 1 ? 0.4 + 0.65 * layer : uniform(rand, -0.15, 0.15)));
          position[0] = (slot - (perLayer - 1) / 2) * 0.45 + uniform(rand, -0.05, 0.05);
          bodies.push(world.addBody(new Body(D, { shape, mass: 1, position })));
        }
        for (let s = 0; s < 300; s += 1) world.step(1 / 60);
        let lowest = Infinity;
        for (const b of bodies) lowest = Math.min(lowest, lowestVertex(b));
        console.log(`pile n = ${n}: lowest vertex after 5 s ${lowest.toExponential(3)} (floor at 0)`);
        expect(warnings).toEqual([]);
        for (const b of bodies) expect(b.x[1]!).toBeGreaterThan(0);
        expect(lowest).toBeGreaterThan(-world.params.penetrationSlop - 1e-4);
      } finally {
        console.warn = warn;
      }
    });
  }
});
