/**
 * The capsule (shapes/capsule.ts, collision/capsule-*.ts, the capsule ray cast) in n dimensions.
 *
 * - Mass properties: the exact formula against a seeded Monte Carlo estimate (n = 2..5), within
 *   5 standard errors of the estimate, and the ball limit h → 0.
 * - Every pair the capsule owns against brute force (n = 2..5, seeded poses): the signed
 *   separation is the maximum over unit directions u of min_B b·u − max_A a·u with each capsule
 *   written as its segment's two ends and each ball as its centre, minus the radii; found by
 *   sampling, hill climbing and an exact last step (the nearest point to the origin of the
 *   affine hull of the active support points), as tests/collision-convex-pairs.test.ts does.
 *   Where one point carries the contact, separation within 1e-12 m (measured 3e-15) and normal
 *   within 1e-6 (measured 1e-8, the brute force's own precision); where a face carries it, the
 *   deepest point within the face tie tolerance.
 * - Manifolds of resting cases: 2 points for a capsule lying on a half-space, a box, a convex
 *   mesh and on another capsule.
 * - Ray casts against the analytic hits and a bisection on the distance to the core segment.
 * - In a World (3D and 4D): rest heights, rolling down a slope, a heap in a bin of boxes, snapshots. (The kernels' allocation: tests/collision-narrowphase-allocation.test.ts.)
 */
import { describe, expect, it } from 'vitest';
import { rotorFromPlane, rotorToMatrix } from '@physin/algebra';
import {
  Body,
  ConvexMesh,
  dims,
  HalfSpace,
  HyperBox,
  HyperCapsule,
  HyperSphere,
  World,
  defaultParams,
  castRay,
  queryBox,
  restoreWorld,
  snapshotWorld,
} from '@physin/engine';
import type { Dims, Shape } from '@physin/engine';
import { collide, createManifold, createNarrowphaseScratch } from '../packages/engine/src/collision/index.js';
import type { CollidableShape, Manifold, Pose } from '../packages/engine/src/collision/index.js';
import { createPose } from '../packages/engine/src/collision/manifold.js';
import { createRayHit, rayCastShape } from '../packages/engine/src/collision/raycast.js';
import { capsuleMoments } from '../packages/engine/src/shapes/capsule.js';
import { ballVolume } from '../packages/engine/src/shapes/ball-volume.js';
import { cubeBoundary } from './support/meshes.js';
import { randomRotation } from './support/poses.js';
import { randomUnitVector, seeded, uniform } from './support/random.js';

type Collidable = Shape & CollidableShape;

function dot(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let s = 0;
  for (let i = 0; i < a.length; i += 1) s += a[i]! * b[i]!;
  return s;
}

function normalise(v: number[]): number[] {
  const l = Math.sqrt(dot(v, v));
  return v.map((x) => x / l);
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

/** g(u) = min_B b·u − max_A a·u: the separation of two point sets' hulls along u (A to B). */
function axisSeparation(A: number[][], B: number[][], u: ArrayLike<number>): number {
  let hiA = -Infinity;
  for (const a of A) hiA = Math.max(hiA, dot(a, u));
  let loB = Infinity;
  for (const b of B) loB = Math.min(loB, dot(b, u));
  return loB - hiA;
}

/** The exact optimum near u: the nearest point to the origin of the affine hull of the active supports of A − B. */
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

/** Brute-force signed distance of the hulls of A and B and its direction (see the module comment). */
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

function toWorld(n: number, pose: Pose, v: ArrayLike<number>): number[] {
  const w = new Array<number>(n);
  for (let i = 0; i < n; i += 1) {
    let s = pose.x[i]!;
    for (let c = 0; c < n; c += 1) s += pose.M[i * n + c]! * v[c]!;
    w[i] = s;
  }
  return w;
}

/** A shape as a point set and a radius: capsule = its segment's ends + r, ball = centre + r, polytope = vertices + 0. */
function asPoints(n: number, shape: Collidable, pose: Pose): { pts: number[][]; r: number; normals: number[][] } {
  const s = shape as unknown as {
    kind: string;
    halfHeight?: number;
    radius?: number;
    halfExtents?: ArrayLike<number>;
    vertices?: Float64Array;
    facetNormals?: Float64Array;
  };
  const axis = (c: number, g: number) => Array.from({ length: n }, (_, i) => g * pose.M[i * n + c]!);
  if (s.kind === 'capsule') {
    const e = new Array<number>(n).fill(0);
    e[1] = s.halfHeight!;
    const f = e.map((x) => -x);
    return { pts: [toWorld(n, pose, f), toWorld(n, pose, e)], r: s.radius!, normals: [] };
  }
  if (s.kind === 'sphere') return { pts: [Array.from(pose.x)], r: s.radius!, normals: [] };
  if (s.kind === 'box') {
    const h = Array.from(s.halfExtents!);
    const pts: number[][] = [];
    for (let m = 0; m < 1 << n; m += 1)
      pts.push(
        toWorld(
          n,
          pose,
          h.map((x, c) => ((m >> c) & 1 ? x : -x)),
        ),
      );
    const normals: number[][] = [];
    for (let c = 0; c < n; c += 1) normals.push(axis(c, 1), axis(c, -1));
    return { pts, r: 0, normals };
  }
  const pts: number[][] = [];
  for (let k = 0; k < s.vertices!.length / n; k += 1) pts.push(toWorld(n, pose, s.vertices!.subarray(k * n, k * n + n)));
  const normals: number[][] = [];
  const N = s.facetNormals!;
  for (let f = 0; f < N.length / n; f += 1) {
    const w = new Array<number>(n).fill(0);
    for (let i = 0; i < n; i += 1) for (let c = 0; c < n; c += 1) w[i] += pose.M[i * n + c]! * N[f * n + c]!;
    normals.push(w);
  }
  return { pts, r: 0, normals };
}

function randomPoseNear(rand: () => number, n: number, dist: number): Pose {
  const p = createPose(n);
  p.M.set(randomRotation(rand, n));
  const dir = randomUnitVector(rand, n);
  for (let i = 0; i < n; i += 1) p.x[i] = dist * dir[i]!;
  return p;
}

/** A cube as a convex mesh (half extent a), and a cross-polytope (octahedron in 3D) of radius a. */
function cubeMesh(D: Dims, a: number): Collidable {
  const m = cubeBoundary(D.n, new Array<number>(D.n).fill(a));
  return ConvexMesh(D, m.vertices, m.facets) as Collidable;
}

function crossPolytope(D: Dims, a: number): Collidable {
  const n = D.n;
  const vertices: number[][] = [];
  for (let c = 0; c < n; c += 1) {
    for (const s of [1, -1]) {
      const v = new Array<number>(n).fill(0);
      v[c] = s * a;
      vertices.push(v);
    }
  }
  const facets: number[][] = [];
  for (let m = 0; m < 1 << n; m += 1) facets.push(Array.from({ length: n }, (_, c) => 2 * c + ((m >> c) & 1)));
  return ConvexMesh(D, vertices, facets) as Collidable;
}

describe('HyperCapsule mass properties', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: volume and covariance match a seeded Monte Carlo estimate within 5 standard errors`, () => {
      const h = 0.7;
      const r = 0.4;
      const D = dims(n);
      const shape = HyperCapsule(D, h, r);
      const mass = 2.5;
      const mp = shape.massProperties(D, mass);
      const exact = capsuleMoments(n, h, r);
      expect(mp.volume).toBe(exact.volume);
      // sample the box [−r, r]^(n−1) × [−h − r, h + r] (axis 1 the long one)
      const rand = seeded(700 + n);
      const samples = n <= 3 ? 400_000 : 1_000_000;
      const half = Array.from({ length: n }, (_, c) => (c === 1 ? h + r : r));
      let boxVolume = 1;
      for (const x of half) boxVolume *= 2 * x;
      let inside = 0;
      let sumAlong = 0;
      let sumAlong2 = 0;
      let sumAcross = 0;
      let sumAcross2 = 0;
      const p = new Float64Array(n);
      for (let s = 0; s < samples; s += 1) {
        for (let c = 0; c < n; c += 1) p[c] = uniform(rand, -half[c]!, half[c]!);
        const y = p[1]!;
        const yc = Math.max(-h, Math.min(h, y));
        let d2 = (y - yc) ** 2;
        for (let c = 0; c < n; c += 1) if (c !== 1) d2 += p[c]! * p[c]!;
        if (d2 > r * r) continue;
        inside += 1;
        sumAlong += y * y;
        sumAlong2 += y ** 4;
        sumAcross += p[0]! * p[0]!;
        sumAcross2 += p[0]! ** 4;
      }
      const frac = inside / samples;
      const volume = frac * boxVolume;
      const volumeSe = boxVolume * Math.sqrt((frac * (1 - frac)) / samples);
      expect(Math.abs(volume - exact.volume)).toBeLessThan(5 * volumeSe);
      const along = sumAlong / inside;
      const alongSe = Math.sqrt((sumAlong2 / inside - along * along) / inside);
      const across = sumAcross / inside;
      const acrossSe = Math.sqrt((sumAcross2 / inside - across * across) / inside);
      expect(Math.abs(along - exact.along)).toBeLessThan(5 * alongSe);
      expect(Math.abs(across - exact.across)).toBeLessThan(5 * acrossSe);
      // the standard errors are small: 5 of them pin the formula to 1.5 % or better
      expect(alongSe / along).toBeLessThan(3e-3);
      expect(acrossSe / across).toBeLessThan(3e-3);
      expect(mp.covariance[1]).toBeCloseTo(mass * exact.along, 12);
      expect(mp.covariance[0]).toBeCloseTo(mass * exact.across, 12);
      for (let c = 2; c < n; c += 1) expect(mp.covariance[c]).toBe(mp.covariance[0]);
    });
  }

  it('tends to the ball as h → 0 and to the cylinder terms as r → 0 (n = 2..8)', () => {
    for (let n = 2; n <= 8; n += 1) {
      const r = 0.3;
      const ball = capsuleMoments(n, 1e-12, r);
      expect(ball.volume).toBeCloseTo(ballVolume(n, r), 9);
      expect(ball.along).toBeCloseTo((r * r) / (n + 2), 12);
      expect(ball.across).toBeCloseTo((r * r) / (n + 2), 12);
      // a thin rod of length 2h: along h²/3 (relative 1e-4 for r = 1e-6 ... the caps and the width vanish)
      const rod = capsuleMoments(n, 1, 1e-6);
      expect(Math.abs(rod.along - 1 / 3)).toBeLessThan(1e-5);
    }
    // 3D: the classical capsule, m = ρ(πr²·2h + 4πr³/3), I_axis = m_cyl r²/2 + m_caps·2r²/5
    const h = 0.5;
    const r = 0.2;
    const cap = capsuleMoments(3, h, r);
    const vc = Math.PI * r * r * 2 * h;
    const vb = (4 / 3) * Math.PI * r ** 3;
    expect(cap.volume).toBeCloseTo(vc + vb, 14);
    const iAxis = (vc * r * r) / 2 + (vb * 2 * r * r) / 5;
    expect(2 * cap.across * cap.volume).toBeCloseTo(iAxis, 14);
    // about a diameter through the centre: cylinder m(r²/4 + (2h)²/12), caps (2r²/5 + h² + 3hr/4)·m_caps
    const iDiam = vc * ((r * r) / 4 + (4 * h * h) / 12) + vb * ((2 * r * r) / 5 + h * h + (3 * h * r) / 4);
    expect((cap.across + cap.along) * cap.volume).toBeCloseTo(iDiam, 14);
  });

  it('checks its arguments (dimensions first, Body.limits)', () => {
    const D = dims(3);
    expect(() => HyperCapsule(D, 0, 1)).toThrow(RangeError);
    expect(() => HyperCapsule(D, 1, -1)).toThrow(/radius/);
    expect(() => HyperCapsule(D, 1e10, 1)).toThrow(/halfHeight/);
    expect(() => HyperCapsule(D, 1, Number.NaN)).toThrow(RangeError);
    expect(() => HyperCapsule(D, '1' as unknown as number, 1)).toThrow(TypeError);
    expect(() => HyperCapsule(3 as unknown as Dims, 1, 1)).toThrow(TypeError);
    const c = HyperCapsule(D, 0.5, 0.25);
    expect(Object.isFrozen(c)).toBe(true);
    expect(c.kind).toBe('capsule');
    expect(c.n).toBe(3);
    expect(() => c.massProperties(dims(4), 1)).toThrow(/n = 4/);
  });
});

const MARGIN = 0.02;

function deepest(m: Manifold): number {
  let s = Infinity;
  for (let k = 0; k < m.count; k += 1) s = Math.min(s, m.separations[k]!);
  return s;
}

describe('capsule pairs against brute force (seeded, n = 2..5)', () => {
  const kinds = ['sphere', 'capsule', 'box', 'mesh'] as const;
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: separation and normal of capsule–ball, –capsule, –box and –mesh`, () => {
      const D = dims(n);
      const rand = seeded(9100 + n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const swapped = createManifold(n);
      const tie = scratch.featureTieTolerance;
      let contacts = 0;
      let exactContacts = 0;
      let worstSep = 0;
      let worstNormal = 0;
      const trials = n === 2 ? 40 : n === 3 ? 30 : n === 4 ? 16 : 8;
      for (let t = 0; t < trials; t += 1) {
        for (const kind of kinds) {
          const A = HyperCapsule(D, uniform(rand, 0.1, 0.8), uniform(rand, 0.1, 0.5)) as Collidable;
          const B: Collidable =
            kind === 'sphere'
              ? (HyperSphere(D, uniform(rand, 0.1, 0.6)) as Collidable)
              : kind === 'capsule'
                ? (HyperCapsule(D, uniform(rand, 0.1, 0.8), uniform(rand, 0.1, 0.5)) as Collidable)
                : kind === 'box'
                  ? (HyperBox(
                      D,
                      Array.from({ length: n }, () => uniform(rand, 0.2, 0.7)),
                    ) as Collidable)
                  : t % 2 === 0
                    ? cubeMesh(D, uniform(rand, 0.3, 0.6))
                    : crossPolytope(D, uniform(rand, 0.5, 0.9));
          const pa = randomPoseNear(rand, n, 0);
          const pb = randomPoseNear(rand, n, uniform(rand, 0.2, 1.5));
          const a = asPoints(n, A, pa);
          const b = asPoints(n, B, pb);
          const brute = bruteSeparation(
            n,
            a.pts,
            b.pts,
            rand,
            b.normals.map((v) => v.map((x) => -x)),
          );
          const sep = brute.sep - a.r - b.r;
          const hit = collide(out, n, A, pa, B, pb, MARGIN, scratch);
          // the other order gives the same contacts with the normal flipped
          const hit2 = collide(swapped, n, B, pb, A, pa, MARGIN, scratch);
          expect(hit2).toBe(hit);
          if (sep < MARGIN - tie) expect(hit, `${kind} t=${t} sep=${sep}`).toBe(true);
          if (sep >= MARGIN + 1e-9) expect(hit).toBe(false);
          if (!hit) continue;
          contacts += 1;
          // capsule–capsule runs again with the roles swapped (the same table): equal up to rounding
          for (let i = 0; i < n; i += 1) expect(Math.abs(swapped.normal[i]! + out.normal[i]!)).toBeLessThan(1e-12);
          expect(Math.abs(deepest(swapped) - deepest(out))).toBeLessThan(1e-12);
          expect(Math.abs(dot(out.normal, out.normal) - 1)).toBeLessThan(1e-12);
          const d = deepest(out);
          // the normal's own axis separation never beats the brute-force maximum
          const along = axisSeparation(a.pts, b.pts, out.normal) - a.r - b.r;
          expect(along).toBeLessThanOrEqual(sep + 1e-9);
          const face = (kind === 'box' || kind === 'mesh') && (out.ids[0]! & 0x80000000) === 0;
          if (face) {
            // a face of B carries the contact: its axis is within the tie of the best one
            expect(d).toBeGreaterThan(sep - 1e-9);
            expect(d).toBeLessThan(sep + 2 * tie);
            expect(along).toBeGreaterThan(sep - tie - 1e-9);
            continue;
          }
          exactContacts += 1;
          worstSep = Math.max(worstSep, Math.abs(d - sep));
          expect(Math.abs(d - sep), `${kind} t=${t}`).toBeLessThan(1e-12);
          expect(Math.abs(along - sep)).toBeLessThan(1e-12);
          // the direction: unique unless the segments are parallel or a ball sits on a segment
          const err = Math.sqrt(out.normal.reduce((s, x, i) => s + (x - brute.u[i]!) ** 2, 0));
          worstNormal = Math.max(worstNormal, err);
        }
      }
      expect(contacts).toBeGreaterThan(trials);
      expect(exactContacts).toBeGreaterThan(trials / 2);
      expect(worstSep).toBeLessThan(1e-12);
      expect(worstNormal).toBeLessThan(1e-6);
      if (process.env.CAPSULE_FIGURES)
        console.log(`n = ${n}: ${contacts} contacts, ${exactContacts} exact; worst |Δsep| ${worstSep}, |Δnormal| ${worstNormal}`);
    });
  }

  it('deep penetration: a segment inside a box or crossing another capsule still gets the least-translation normal and depth', () => {
    for (const n of [2, 3, 4, 5]) {
      const D = dims(n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const cap = HyperCapsule(D, 0.3, 0.1) as Collidable;
      const box = HyperBox(D, new Array<number>(n).fill(1)) as Collidable;
      const pa = createPose(n);
      const pb = createPose(n);
      // the capsule (along y) inside the box, nearest to the +x face (0.8 in: x = 0.2 from it)
      pa.x[0] = 0.8;
      expect(collide(out, n, cap, pa, box, pb, MARGIN, scratch)).toBe(true);
      expect(deepest(out)).toBeCloseTo(-0.2 - 0.1, 12);
      expect(out.normal[0]).toBeCloseTo(-1, 12);
      // two crossing capsules: depth rA + rB in n >= 3 (escape normal to both axes)
      const c2 = HyperCapsule(D, 0.5, 0.2) as Collidable;
      const pc = createPose(n);
      pc.M.fill(0);
      for (let i = 0; i < n; i += 1) pc.M[i * n + i] = 1;
      // B's axis along x: swap axes 0 and 1 (a rotation by 90° in the xy plane)
      pc.M[0 * n + 0] = 0;
      pc.M[1 * n + 1] = 0;
      pc.M[0 * n + 1] = -1;
      pc.M[1 * n + 0] = 1;
      pc.x[1] = 0.1;
      pa.x.fill(0);
      expect(collide(out, n, cap, pa, c2, pc, MARGIN, scratch)).toBe(true);
      if (n >= 3) {
        expect(deepest(out)).toBeCloseTo(-0.3, 12);
        expect(Math.abs(out.normal[0]!) + Math.abs(out.normal[1]!)).toBeLessThan(1e-12);
      } else {
        // 2D: B's segment crosses A's at y = 0.1; least escape: A's segment (y in ±0.3) leaves B's
        // along y by 0.3 − 0.1 = 0.2 upward... i.e. B moves +y by 0.3 − 0.1 = 0.2; or along x by 0.5
        expect(deepest(out)).toBeCloseTo(-(0.3 - 0.1) - 0.3, 12);
        expect(out.normal[1]).toBeCloseTo(1, 12);
      }
    }
  });
});

/** A pose whose local axis 1 (the capsule's) lies along world axis 0: a quarter turn in the (0, 1) plane. */
function lyingPose(n: number, x: number[]): Pose {
  const p = createPose(n);
  p.M[0 * n + 0] = 0;
  p.M[1 * n + 1] = 0;
  p.M[0 * n + 1] = 1;
  p.M[1 * n + 0] = -1;
  p.x.set(x);
  return p;
}

describe('resting manifolds have two points', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: a capsule lying on a half-space, a box, a convex mesh and another capsule`, () => {
      const D = dims(n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const cap = HyperCapsule(D, 0.5, 0.2) as Collidable;
      const up = new Array<number>(n).fill(0);
      up[1] = 1;
      const ground = HalfSpace(D, up, 0) as Collidable;
      const centre = new Array<number>(n).fill(0);
      centre[1] = 0.2 - 0.001;
      const pa = lyingPose(n, centre);
      const pg = createPose(n);
      const check = (B: Collidable, pb: Pose, gap: number) => {
        expect(collide(out, n, cap, pa, B, pb, MARGIN, scratch)).toBe(true);
        expect(out.count).toBe(2);
        for (let k = 0; k < 2; k += 1) {
          expect(out.separations[k]).toBeCloseTo(gap, 12);
          expect(out.points[k * n + 1]).toBeCloseTo(gap / 2, 12);
        }
        expect(Math.abs(out.points[0]! - out.points[n]!)).toBeCloseTo(1, 12);
        expect(out.normal[1]).toBeCloseTo(-1, 12);
        expect(out.ids[0]).not.toBe(out.ids[1]);
        // the same features after a small slide: the same ids (warm starting)
        const ids = Array.from(out.ids.subarray(0, 2));
        pa.x[0] += 1e-3;
        expect(collide(out, n, cap, pa, B, pb, MARGIN, scratch)).toBe(true);
        expect(Array.from(out.ids.subarray(0, 2))).toEqual(ids);
        pa.x[0] -= 1e-3;
      };
      check(ground, pg, -0.001);
      // a box and a cube mesh whose top face is y = 0
      const pb = createPose(n);
      pb.x[1] = -1;
      check(HyperBox(D, new Array<number>(n).fill(1)) as Collidable, pb, -0.001);
      check(cubeMesh(D, 1), pb, -0.001);
      // another capsule lying parallel below it, touching at y = 0
      const pc = lyingPose(
        n,
        centre.map((_, i) => (i === 1 ? -0.2 : 0)),
      );
      check(cap, pc, -0.001);
      // a capsule standing on the ground: one point
      const standing = createPose(n);
      standing.x[1] = 0.7 - 0.001;
      expect(collide(out, n, cap, standing, ground, pg, MARGIN, scratch)).toBe(true);
      expect(out.count).toBe(1);
      expect(out.separations[0]).toBeCloseTo(-0.001, 12);
    });
  }

  it('the two points of a capsule half over a box edge end at the edge', () => {
    const n = 3;
    const D = dims(n);
    const scratch = createNarrowphaseScratch(n);
    const out = createManifold(n);
    const cap = HyperCapsule(D, 0.5, 0.2) as Collidable;
    const pa = lyingPose(n, [1, 0.2, 0]);
    const pb = createPose(n);
    pb.x[1] = -1;
    expect(collide(out, n, cap, pa, HyperBox(D, [1, 1, 1]) as Collidable, pb, MARGIN, scratch)).toBe(true);
    expect(out.count).toBe(2);
    const xs = [out.points[0]!, out.points[n]!].sort((p, q) => p - q);
    expect(xs[0]).toBeCloseTo(0.5, 12);
    expect(xs[1]).toBeCloseTo(1, 12);
  });
});

describe('ray casts against a capsule', () => {
  it('hits the side, the caps and starts inside, as the analytic values (3D, 4D)', () => {
    for (const n of [3, 4]) {
      const hit = createRayHit(n);
      const cap = HyperCapsule(dims(n), 0.5, 0.25);
      const x = new Float64Array(n);
      const M = new Float64Array(n * n);
      for (let i = 0; i < n; i += 1) M[i * n + i] = 1;
      const o = new Array<number>(n).fill(0);
      const d = new Array<number>(n).fill(0);
      // from +x toward the side
      o[0] = 2;
      o[1] = 0.3;
      d[0] = -1;
      expect(rayCastShape(n, cap, x, M, o, d, 10, hit)).toBeCloseTo(1.75, 14);
      expect(hit.normal[0]).toBeCloseTo(1, 14);
      // from above along the axis: the cap's top at h + r = 0.75
      o.fill(0);
      d.fill(0);
      o[1] = 3;
      d[1] = -2;
      expect(rayCastShape(n, cap, x, M, o, d, 10, hit)).toBeCloseTo(2.25, 14);
      expect(hit.normal[1]).toBeCloseTo(1, 14);
      // oblique onto the cap: from (0.2, 2) straight down hits y = 0.5 + √(r² − 0.2²) = 0.65
      o[0] = 0.2;
      d[1] = -1;
      expect(rayCastShape(n, cap, x, M, o, d, 10, hit)).toBeCloseTo(3 - 0.65, 14);
      expect(hit.normal[0]).toBeCloseTo(0.2 / 0.25, 14);
      // too short, a miss, a start inside
      expect(rayCastShape(n, cap, x, M, o, d, 2, hit)).toBe(-1);
      o[0] = 0.3;
      expect(rayCastShape(n, cap, x, M, o, d, 10, hit)).toBe(-1);
      o[0] = 0.1;
      o[1] = 0.6;
      expect(rayCastShape(n, cap, x, M, o, d, 10, hit)).toBe(0);
      expect(hit.normal[1]).toBe(1);
    }
  });

  it('random rays (n = 2..5, seeded) hit where a bisection on the distance to the segment says', () => {
    let hits = 0;
    for (const n of [2, 3, 4, 5]) {
      const rand = seeded(4400 + n);
      const hit = createRayHit(n);
      for (let t = 0; t < 200; t += 1) {
        const h = uniform(rand, 0.1, 1);
        const r = uniform(rand, 0.1, 0.5);
        const cap = HyperCapsule(dims(n), h, r);
        const pose = randomPoseNear(rand, n, uniform(rand, 0, 0.5));
        const o = Array.from(randomUnitVector(rand, n), (v) => 2.5 * v);
        // aim near the centre
        const aim = Array.from(randomUnitVector(rand, n), (v, i) => 0.6 * v - o[i]!);
        const dist = (p: number[]) => {
          const w = p.map((v, i) => v - pose.x[i]!);
          let s = 0;
          for (let i = 0; i < n; i += 1) s += pose.M[i * n + 1]! * w[i]!;
          s = Math.max(-h, Math.min(h, s));
          let d2 = 0;
          for (let i = 0; i < n; i += 1) d2 += (w[i]! - s * pose.M[i * n + 1]!) ** 2;
          return Math.sqrt(d2) - r;
        };
        const len = Math.sqrt(dot(aim, aim));
        const u = aim.map((v) => v / len);
        const at = (s: number) => o.map((v, i) => v + s * u[i]!);
        // march (the distance is 1-Lipschitz: steps of the distance never pass the surface)
        let s = 0;
        let found = false;
        for (let k = 0; k < 10000 && s < 10; k += 1) {
          const f = dist(at(s));
          if (f < 1e-13) {
            found = true;
            break;
          }
          s += f;
        }
        const got = rayCastShape(n, cap, pose.x, pose.M, o, aim, 10, hit);
        if (!found) {
          expect(got).toBe(-1);
          continue;
        }
        hits += 1;
        expect(Math.abs(got - s)).toBeLessThan(1e-9);
        // the normal is the gradient of the distance at the hit
        const p = at(got);
        const g = p.map((_, i) => {
          const e = 1e-6;
          const q = p.slice();
          q[i] += e;
          const qm = p.slice();
          qm[i] -= e;
          return (dist(q) - dist(qm)) / (2 * e);
        });
        for (let i = 0; i < n; i += 1) expect(Math.abs(hit.normal[i]! - g[i]!)).toBeLessThan(1e-6);
      }
    }
    expect(hits).toBeGreaterThan(300);
  });
});

describe('world queries find capsules (3D, 4D)', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: castRay hits a turned capsule body where the analytic cast does; queryBox finds it by its bounds`, () => {
      const D = dims(n);
      const world = new World({ dimensions: n });
      const h = 0.5;
      const r = 0.2;
      // lying along x at (1, 2, 0, …)
      const body = world.addBody(
        new Body(D, {
          shape: HyperCapsule(D, h, r),
          mass: 0,
          position: Array.from({ length: n }, (_, i) => (i === 0 ? 1 : i === 1 ? 2 : 0)),
          rotor: rotorFromPlane(D, new Float64Array(D.r), 0, 1, Math.PI / 2),
        }),
      );
      world.step(1 / 60);
      // straight down onto the cap's side at x = 1.6: the cap's ball (centre x = 1.5) is hit at y = 2 + √(r² − 0.1²)
      const origin = Array.from({ length: n }, (_, i) => (i === 0 ? 1.6 : i === 1 ? 5 : 0));
      const down = Array.from({ length: n }, (_, i) => (i === 1 ? -1 : 0));
      const hit = castRay(world, origin, down, 10);
      expect(hit).not.toBeNull();
      expect(hit!.body).toBe(body);
      expect(hit!.distance).toBeCloseTo(3 - Math.sqrt(r * r - 0.01), 12);
      expect(hit!.normal[0]).toBeCloseTo(0.1 / r, 12);
      // its bounds: x in [1 − h − r, 1 + h + r], y in [2 − r, 2 + r]
      const box = (lo: number[], hi: number[]) => queryBox(world, lo, hi);
      const at = (x: number, y: number, e: number) => [
        Array.from({ length: n }, (_, i) => (i === 0 ? x - e : i === 1 ? y - e : -e)),
        Array.from({ length: n }, (_, i) => (i === 0 ? x + e : i === 1 ? y + e : e)),
      ];
      expect(box(...(at(1.69, 2, 0.001) as [number[], number[]]))).toEqual([body]);
      expect(box(...(at(1.72, 2, 0.001) as [number[], number[]]))).toEqual([]);
      expect(box(...(at(1, 2.19, 0.001) as [number[], number[]]))).toEqual([body]);
      expect(box(...(at(1, 2.22, 0.001) as [number[], number[]]))).toEqual([]);
    });
  }
});

/** A rotor turning local axis 1 (y) onto axis 0 (x): the capsule lies along x. */
function lyingRotor(D: Dims): Float64Array {
  return rotorFromPlane(D, new Float64Array(D.r), 0, 1, Math.PI / 2);
}

function settle(world: World, seconds: number): void {
  const steps = Math.round(seconds * 60);
  for (let s = 0; s < steps; s += 1) world.step(1 / 60);
}

describe('capsules at rest in a World (3D, 4D)', () => {
  const slop = defaultParams.penetrationSlop;
  for (const n of [3, 4]) {
    const gravity = (g: number) => Array.from({ length: n }, (_, i) => (i === 1 ? -g : 0));
    const up = Array.from({ length: n }, (_, i) => (i === 1 ? 1 : 0));
    const at = (y: number, x = 0) => Array.from({ length: n }, (_, i) => (i === 1 ? y : i === 0 ? x : 0));

    for (const ground of ['half-space', 'box', 'convex mesh'] as const) {
      it(`n = ${n}: a capsule lying on a ${ground} rests at height r within the slop, without drift or roll`, () => {
        const D = dims(n);
        // sleep off: the capsule must stay still under the solver, not merely be put to sleep
        const world = new World({ dimensions: n, gravity: gravity(9.81), params: { allowSleep: false } });
        if (ground === 'half-space') world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
        else if (ground === 'box')
          world.addBody(new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(3)), mass: 0, position: at(-3) }));
        else world.addBody(new Body(D, { shape: cubeMesh(D, 3), mass: 0, position: at(-3) }));
        const r = 0.2;
        const body = world.addBody(
          new Body(D, {
            shape: HyperCapsule(D, 0.6, r),
            mass: 1,
            // dropped tilted by 0.1 rad, off the origin: it lands on one end and settles flat
            position: at(r + 0.1, 0.37),
            rotor: rotorFromPlane(D, new Float64Array(D.r), 0, 1, Math.PI / 2 + 0.1),
          }),
        );
        settle(world, 2);
        const x0 = Float64Array.from(body.x);
        const R0 = Float64Array.from(body.R);
        settle(world, 3);
        expect(Math.abs(body.x[1]! - r)).toBeLessThan(slop);
        if (process.env.CAPSULE_FIGURES) {
          const drift = Math.max(...Array.from(body.x, (v, i) => (i === 1 ? 0 : Math.abs(v - x0[i]!))));
          const turn = Math.max(...Array.from(body.R, (v, i) => Math.abs(v - R0[i]!)));
          console.log(`n = ${n}, lying on a ${ground}: height − r = ${body.x[1]! - r}, drift ${drift}, rotor change ${turn}`);
        }
        for (let i = 0; i < n; i += 1) if (i !== 1) expect(Math.abs(body.x[i]! - x0[i]!)).toBeLessThan(1e-6);
        for (let i = 0; i < R0.length; i += 1) expect(Math.abs(body.R[i]! - R0[i]!)).toBeLessThan(1e-6);
        let speed = 0;
        for (const v of body.v) speed += v * v;
        expect(Math.sqrt(speed)).toBeLessThan(1e-4);
      });
    }

    it(`n = ${n}: a capsule standing up rests at h + r; a box rests on two lying capsules`, () => {
      const D = dims(n);
      const world = new World({ dimensions: n, gravity: gravity(9.81) });
      world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
      const h = 0.4;
      const r = 0.15;
      const standing = world.addBody(new Body(D, { shape: HyperCapsule(D, h, r), mass: 1, position: at(h + r + 0.02, -3) }));
      // static capsules lying along x at z = ±0.2 (4D: at (z, w) = (±0.2, ±0.2), so that their
      // contact lines span the box's bottom), a box on top (its bottom spans z, w in ±0.3)
      const rails: Body[] = [];
      const spots =
        n === 3
          ? [[-0.2], [0.2]]
          : [
              [-0.2, -0.2],
              [-0.2, 0.2],
              [0.2, -0.2],
              [0.2, 0.2],
            ];
      for (const spot of spots) {
        const p = at(0.5);
        for (let k = 0; k < spot.length; k += 1) p[2 + k] = spot[k]!;
        rails.push(world.addBody(new Body(D, { shape: HyperCapsule(D, 1, 0.1), mass: 0, position: p, rotor: lyingRotor(D) })));
      }
      const half = 0.3;
      const box = world.addBody(
        new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(half)), mass: 1, position: at(0.5 + 0.1 + half + 0.02) }),
      );
      settle(world, 4);
      expect(Math.abs(standing.x[1]! - (h + r))).toBeLessThan(slop);
      if (process.env.CAPSULE_FIGURES) {
        console.log(
          `n = ${n}: standing − (h + r) = ${standing.x[1]! - (h + r)}, box on rails − analytic = ${box.x[1]! - (0.5 + 0.1 + half)}`,
        );
      }
      expect(Math.abs(box.x[1]! - (0.5 + 0.1 + half))).toBeLessThan(slop);
      expect(rails.length).toBe(spots.length);
      let speed = 0;
      for (const v of box.v) speed += v * v;
      expect(Math.sqrt(speed)).toBeLessThan(1e-3);
    });
  }
});

describe('a capsule rolls down a slope as the analytic solid of revolution (3D, 4D)', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: distance after 1 s = a·dt²·N(N+1)/2 with a = g sin θ / (1 + I/(m r²)), I = 2m·C_across (1e-9 relative)`, () => {
      const D = dims(n);
      const theta = (15 * Math.PI) / 180;
      const g = 9.81;
      // the slope's outward normal (sin θ, cos θ, 0, …): downhill is along (cos θ, −sin θ, 0, …)
      const N = Array.from({ length: n }, (_, i) => (i === 0 ? Math.sin(theta) : i === 1 ? Math.cos(theta) : 0));
      const down = Array.from({ length: n }, (_, i) => (i === 0 ? Math.cos(theta) : i === 1 ? -Math.sin(theta) : 0));
      const world = new World({
        dimensions: n,
        gravity: Array.from({ length: n }, (_, i) => (i === 1 ? -g : 0)),
        params: { allowSleep: false },
      });
      world.addBody(new Body(D, { shape: HalfSpace(D, N, 0), mass: 0 }));
      const h = 0.5;
      const r = 0.2;
      // the axis along z (local y turned onto axis 2), resting on the slope: it rolls without slipping (μ = 0.5 > tan θ·…)
      const body = world.addBody(
        new Body(D, {
          shape: HyperCapsule(D, h, r),
          mass: 1,
          position: N.map((v) => v * r),
          rotor: rotorFromPlane(D, new Float64Array(D.r), 1, 2, Math.PI / 2),
        }),
      );
      const x0 = Float64Array.from(body.x);
      const steps = 60;
      const dt = 1 / 60;
      for (let s = 0; s < steps; s += 1) world.step(dt);
      const travelled = dot(
        Array.from(body.x, (v, i) => v - x0[i]!),
        down,
      );
      // the rotation of rolling is in the plane of two axes across the capsule: I = C_ii + C_jj = 2 m C_across
      const I = 2 * capsuleMoments(n, h, r).across;
      const a = (g * Math.sin(theta)) / (1 + I / (r * r));
      // symplectic Euler from rest: x_N = a·dt²·N(N + 1)/2
      const expected = (a * dt * dt * steps * (steps + 1)) / 2;
      expect(Math.abs(travelled - expected) / expected).toBeLessThan(1e-9);
      // it stays on the slope: the height of its axis above the plane is r
      expect(Math.abs(dot(body.x, N) - r)).toBeLessThan(1e-9);
    });
  }
});

describe('a heap of capsules (3D, 4D)', () => {
  /** The distance between two segments p0 + s·(p1 − p0), q0 + t·(q1 − q0), by nested ternary search (convex in s and t). */
  function segmentDistance(p0: number[], p1: number[], q0: number[], q1: number[]): number {
    const at = (a: number[], b: number[], s: number) => a.map((v, i) => v + s * (b[i]! - v));
    const inner = (p: number[]) => {
      let lo = 0;
      let hi = 1;
      const f = (t: number) => Math.hypot(...at(q0, q1, t).map((v, i) => v - p[i]!));
      for (let k = 0; k < 100; k += 1) {
        const m1 = lo + (hi - lo) / 3;
        const m2 = hi - (hi - lo) / 3;
        if (f(m1) < f(m2)) hi = m2;
        else lo = m1;
      }
      return f((lo + hi) / 2);
    };
    let lo = 0;
    let hi = 1;
    for (let k = 0; k < 100; k += 1) {
      const m1 = lo + (hi - lo) / 3;
      const m2 = hi - (hi - lo) / 3;
      if (inner(at(p0, p1, m1)) < inner(at(p0, p1, m2))) hi = m2;
      else lo = m1;
    }
    return inner(at(p0, p1, (lo + hi) / 2));
  }

  for (const n of [3, 4]) {
    it(`n = ${n}: capsules dropped in a bin of boxes neither sink into the floor nor into each other (within 2 slops)`, () => {
      const D = dims(n);
      const slop = defaultParams.penetrationSlop;
      const world = new World({ dimensions: n, gravity: Array.from({ length: n }, (_, i) => (i === 1 ? -9.81 : 0)) });
      world.addBody(
        new Body(D, {
          shape: HalfSpace(
            D,
            Array.from({ length: n }, (_, i) => (i === 1 ? 1 : 0)),
            0,
          ),
          mass: 0,
        }),
      );
      // a bin: two static box walls across every horizontal axis, 1.6 m apart
      for (let axis = 0; axis < n; axis += 1) {
        if (axis === 1) continue;
        for (const side of [-1, 1]) {
          const half = Array.from({ length: n }, (_, c) => (c === axis ? 0.5 : c === 1 ? 3 : 1.3));
          const position = Array.from({ length: n }, (_, c) => (c === axis ? side * 1.3 : c === 1 ? 3 : 0));
          world.addBody(new Body(D, { shape: HyperBox(D, half), mass: 0, position }));
        }
      }
      const rand = seeded(5150 + n);
      const count = n === 3 ? 24 : 16;
      const bodies: { body: Body; h: number; r: number }[] = [];
      for (let k = 0; k < count; k += 1) {
        const h = uniform(rand, 0.15, 0.4);
        const r = uniform(rand, 0.1, 0.2);
        const position = Array.from({ length: n }, (_, i) => (i === 1 ? 0.5 + 0.45 * k : uniform(rand, -0.25, 0.25)));
        const rotor = rotorFromPlane(D, new Float64Array(D.r), 1, 2 + (k % (n - 2)), uniform(rand, -Math.PI, Math.PI));
        bodies.push({ body: world.addBody(new Body(D, { shape: HyperCapsule(D, h, r), mass: 1, position, rotor })), h, r });
      }
      for (let s = 0; s < 300; s += 1) world.step(1 / 60);
      const ends = bodies.map(({ body, h }) => {
        const M = rotorToMatrix(D, new Float64Array(n * n), body.R);
        const axis = Array.from({ length: n }, (_, i) => M[i * n + 1]!);
        return [Array.from(body.x, (v, i) => v - h * axis[i]!), Array.from(body.x, (v, i) => v + h * axis[i]!)];
      });
      let floor = Infinity;
      let between = Infinity;
      for (let a = 0; a < count; a += 1) {
        const [p0, p1] = ends[a]!;
        floor = Math.min(floor, Math.min(p0![1]!, p1![1]!) - bodies[a]!.r);
        for (let b = a + 1; b < count; b += 1) {
          const [q0, q1] = ends[b]!;
          between = Math.min(between, segmentDistance(p0!, p1!, q0!, q1!) - bodies[a]!.r - bodies[b]!.r);
        }
      }
      if (process.env.CAPSULE_FIGURES)
        console.log(`n = ${n} heap: deepest into the floor ${-floor}, between capsules ${-between}`);
      expect(floor).toBeGreaterThan(-2 * slop);
      expect(between).toBeGreaterThan(-2 * slop);
      // every capsule is still in the bin (its walls' inner faces at ±0.8)
      for (const { body } of bodies) for (let i = 0; i < n; i += 1) if (i !== 1) expect(Math.abs(body.x[i]!)).toBeLessThan(0.8);
    });
  }
});

describe('capsules in snapshots', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a world of falling capsules restored mid-fall continues bit for bit`, () => {
      const D = dims(n);
      const world = new World({ dimensions: n, gravity: Array.from({ length: n }, (_, i) => (i === 1 ? -9.81 : 0)) });
      world.addBody(
        new Body(D, {
          shape: HalfSpace(
            D,
            Array.from({ length: n }, (_, i) => (i === 1 ? 1 : 0)),
            0,
          ),
          mass: 0,
        }),
      );
      const rand = seeded(31 + n);
      for (let k = 0; k < 6; k += 1) {
        world.addBody(
          new Body(D, {
            shape: HyperCapsule(D, uniform(rand, 0.2, 0.6), uniform(rand, 0.1, 0.3)),
            mass: 1,
            position: Array.from({ length: n }, (_, i) => (i === 1 ? 0.8 + 0.9 * k : uniform(rand, -0.3, 0.3))),
            rotor: rotorFromPlane(D, new Float64Array(D.r), 0, 1, uniform(rand, -Math.PI, Math.PI)),
          }),
        );
      }
      settle(world, 0.5);
      const copy = restoreWorld(snapshotWorld(world));
      const shape = copy.bodies[1]!.shape as unknown as { kind: string; halfHeight: number; radius: number };
      const original = world.bodies[1]!.shape as unknown as { kind: string; halfHeight: number; radius: number };
      expect(shape.kind).toBe('capsule');
      expect(shape.halfHeight).toBe(original.halfHeight);
      expect(shape.radius).toBe(original.radius);
      settle(world, 1);
      settle(copy, 1);
      for (let b = 0; b < world.bodies.length; b += 1) {
        expect(Array.from(copy.bodies[b]!.x)).toEqual(Array.from(world.bodies[b]!.x));
        expect(Array.from(copy.bodies[b]!.R)).toEqual(Array.from(world.bodies[b]!.R));
      }
    });
  }
});
