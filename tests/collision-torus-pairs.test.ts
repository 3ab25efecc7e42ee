/**
 * Torus–box, torus–convex mesh, torus–capsule and torus–torus (collision/torus-pairs.ts), and the
 * ball resting in a ring (collision/torus-sphere.ts).
 *
 * - Against brute force (seeded random poses, about half of them overlapping; n = 2..6 for box
 *   and mesh, 3..6 for capsule and torus): the gap is the minimum over 20 000 angles of the core
 *   circle, refined by ternary search, of the exact distance from the core point to the other
 *   shape's core (a box, or a mesh made of a box's boundary, by clamping in the box's frame,
 *   inside: the nearest face; a segment; a circle in closed form), minus the radii. With margin 0
 *   (one candidate within the tie band) the kernel's separation matches it within 1e-9 m (box and
 *   mesh, whose minimum may sit on a kink where two faces tie: 1e-8 m; a minimum flat within
 *   featureTieTolerance over its bracket, carried by ring samples, within that tolerance, in at
 *   most 1 case in 8) and its normal within 1e-6; with margin 0.02 it reports a contact exactly
 *   when the brute-force gap is below 0.02 (borderline cases within 1e-6 skipped).
 * - A ring over a square bar: two points (its two top edges), one normal straight down.
 * - Rest in a World (default params, 1/60 s): a 3D torus flat on a box (centre at the box's top
 *   + r), a ring hanging on a square bar, a torus flat on a convex mesh (3D, 4D), a ring hanging
 *   from a fixed ring for 600 steps (3D, 4D), a ball resting in a ring (3D, 4D; two ball sizes),
 *   a capsule across a ring: each at its analytic height within params.penetrationSlop.
 * - A pile (30 tori in 3D, 20 in 4D, dropped into a bin of static boxes, default params): after
 *   10 s every torus sleeps, and the worst penetration (core-circle distances by brute force,
 *   depths below the bin's faces) is within 1.1 (3D) and 1.02 (4D) slops.
 * - Allocation: none in steady state (child process on the built engine).
 */
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';
import { ensureBuiltEngine, root } from './support/built-engine.js';
import { rotorExp, rotorToMatrix } from '@physin/algebra';
import { Body, ConvexMesh, dims, HyperBox, HyperCapsule, HyperSphere, HyperTorus, World } from '@physin/engine';
import type { Shape } from '@physin/engine';
import { collide, createManifold, createNarrowphaseScratch } from '../packages/engine/src/collision/index.js';
import type { CollidableShape, Pose } from '../packages/engine/src/collision/index.js';
import { createPose } from '../packages/engine/src/collision/manifold.js';
import type { CollisionTorus } from '../packages/engine/src/collision/narrowphase-shapes.js';
import { torusColliders } from '../packages/engine/src/collision/torus-colliders.js';
import { cubeBoundary } from './support/meshes.js';
import { randomRotation } from './support/poses.js';
import { randomArray, seeded, uniform } from './support/random.js';

const SLOP = 0.005; // params.penetrationSlop (default)
const TIE = 5e-4; // the narrowphase's default featureTieTolerance (m)
const RING_SAMPLES = 32; // 4 × the default torusRingPoints: ids below this are ring samples

const torusShape = (R: number, r: number, i: number, j: number): CollidableShape & CollisionTorus =>
  ({ kind: 'torus', majorRadius: R, minorRadius: r, planeI: i, planeJ: j, colliders: torusColliders }) as never;

/** The core point of torus (pose) at θ, world. */
function corePoint(n: number, t: CollisionTorus, pose: Pose, theta: number): Float64Array {
  const out = new Float64Array(n);
  for (let i = 0; i < n; i += 1) {
    out[i] =
      pose.x[i]! + t.majorRadius * (Math.cos(theta) * pose.M[i * n + t.planeI]! + Math.sin(theta) * pose.M[i * n + t.planeJ]!);
  }
  return out;
}

function toLocal(n: number, pose: Pose, p: ArrayLike<number>): Float64Array {
  const out = new Float64Array(n);
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let i = 0; i < n; i += 1) s += pose.M[i * n + c]! * (p[i]! - pose.x[i]!);
    out[c] = s;
  }
  return out;
}

function toWorldDir(n: number, pose: Pose, d: ArrayLike<number>): Float64Array {
  const out = new Float64Array(n);
  for (let i = 0; i < n; i += 1) for (let c = 0; c < n; c += 1) out[i] = out[i]! + pose.M[i * n + c]! * d[c]!;
  return out;
}

/**
 * Signed distance from a local point p to the other shape's core, and the unit direction (local)
 * in which the other shape moves away from p (from p to the nearest core point; inside: minus the
 * nearest face's normal).
 */
type CoreDistance = (p: Float64Array) => { d: number; dir: Float64Array; alt?: Float64Array[] };

function boxDistance(n: number, h: ArrayLike<number>): CoreDistance {
  return (p) => {
    const q = new Float64Array(n);
    let d2 = 0;
    let face = 0;
    let faceGap = -Infinity;
    for (let c = 0; c < n; c += 1) {
      q[c] = Math.min(h[c]!, Math.max(-h[c]!, p[c]!)) - p[c]!;
      d2 += q[c]! * q[c]!;
      const g = Math.abs(p[c]!) - h[c]!;
      if (g > faceGap) {
        faceGap = g;
        face = c;
      }
    }
    if (d2 > 0) {
      const d = Math.sqrt(d2);
      return { d, dir: q.map((x) => x / d) };
    }
    const dir = new Float64Array(n);
    dir[face] = p[face]! < 0 ? 1 : -1;
    // inside, the faces as near as the nearest (within 1e-7 m) give valid normals too
    const alt: Float64Array[] = [];
    // (the far face of the same axis too, where the point is midway between them: the deepest
    // point of a core circle cutting through a slab lies there)
    for (let c = 0; c < n; c += 1) {
      if (Math.abs(p[c]!) - h[c]! < faceGap - 1e-7) continue;
      for (const sgn of [1, -1]) {
        if (c === face && sgn === dir[face]) continue;
        if (c === face && Math.abs(p[c]!) > 1e-7) continue;
        if (c !== face && sgn !== (p[c]! < 0 ? 1 : -1) && Math.abs(p[c]!) > 1e-7) continue;
        const d = new Float64Array(n);
        d[c] = sgn;
        alt.push(d);
      }
    }
    return { d: faceGap, dir, alt };
  };
}

function segmentDistance(n: number, hh: number): CoreDistance {
  return (p) => {
    const q = new Float64Array(n);
    q[1] = Math.min(hh, Math.max(-hh, p[1]!));
    for (let c = 0; c < n; c += 1) q[c] = q[c]! - p[c]!;
    const d = Math.hypot(...q);
    return { d, dir: q.map((x) => x / d) };
  };
}

function circleDistance(n: number, t: CollisionTorus): CoreDistance {
  return (p) => {
    const rho = Math.hypot(p[t.planeI]!, p[t.planeJ]!);
    const q = new Float64Array(n);
    q[t.planeI] = (t.majorRadius * p[t.planeI]!) / rho;
    q[t.planeJ] = (t.majorRadius * p[t.planeJ]!) / rho;
    for (let c = 0; c < n; c += 1) q[c] = q[c]! - p[c]!;
    const d = Math.hypot(...q);
    return { d, dir: q.map((x) => x / d) };
  };
}

/**
 * Brute force: min over θ of dist(c(θ), B's core) − radii; 20 000 samples, then golden section
 * round the best one. Returns the gap and the world normal (A to B).
 */
function bruteForce(
  n: number,
  t: CollisionTorus,
  poseA: Pose,
  poseB: Pose,
  dist: CoreDistance,
  radii: number,
): { gap: number; normals: Float64Array[]; theta: number } {
  const f = (theta: number) => dist(toLocal(n, poseB, corePoint(n, t, poseA, theta))).d;
  const SAMPLES = 20000;
  let best = 0;
  let bestF = Infinity;
  for (let k = 0; k < SAMPLES; k += 1) {
    const v = f((2 * Math.PI * k) / SAMPLES);
    if (v < bestF) {
      bestF = v;
      best = k;
    }
  }
  let lo = (2 * Math.PI * (best - 1)) / SAMPLES;
  let hi = (2 * Math.PI * (best + 1)) / SAMPLES;
  for (let it = 0; it < 80; it += 1) {
    const m1 = lo + (hi - lo) / 3;
    const m2 = hi - (hi - lo) / 3;
    if (f(m1) < f(m2)) hi = m2;
    else lo = m1;
  }
  const theta = (lo + hi) / 2;
  const res = dist(toLocal(n, poseB, corePoint(n, t, poseA, theta)));
  const normals = [res.dir, ...(res.alt ?? [])].map((d) => toWorldDir(n, poseB, d));
  return { gap: res.d - t.minorRadius - radii, normals, theta };
}

function randomPoseNear(rand: () => number, n: number, spread: number): Pose {
  const pose = createPose(n);
  pose.M.set(randomRotation(rand, n));
  pose.x.set(randomArray(rand, n, -spread, spread));
  return pose;
}

interface PairCase {
  name: string;
  other: (n: number, rand: () => number) => { shape: CollidableShape; dist: CoreDistance; radii: number; anchor?: Float64Array };
}

const CASES: PairCase[] = [
  {
    name: 'box',
    other: (n, rand) => {
      const h = randomArray(rand, n, 0.3, 1.2);
      return { shape: { kind: 'box', halfExtents: h } as never, dist: boxDistance(n, h), radii: 0 };
    },
  },
  {
    name: 'mesh (a box as simplices)',
    other: (n, rand) => {
      const h = Array.from(randomArray(rand, n, 0.3, 1.2));
      const m = cubeBoundary(n, h);
      const mesh = ConvexMesh(dims(n), m.vertices, m.facets);
      // the mesh's principal frame of a box is the box's frame up to axis order and signs
      return { shape: mesh as never, dist: meshAsBoxDistance(n, mesh, h), radii: 0 };
    },
  },
  {
    name: 'capsule',
    other: (n, rand) => {
      const hh = uniform(rand, 0.2, 1.2);
      const rb = uniform(rand, 0.1, 0.5);
      return {
        shape: { kind: 'capsule', halfHeight: hh, radius: rb } as never,
        dist: segmentDistance(n, hh),
        radii: rb,
      };
    },
  },
  {
    name: 'torus',
    other: (n, rand) => {
      const Rb = uniform(rand, 0.8, 1.6);
      const rb = uniform(rand, 0.1, 0.35);
      const i = Math.floor(uniform(rand, 0, n - 1));
      const j = i + 1 + Math.floor(uniform(rand, 0, n - 1 - i));
      const t = torusShape(Rb, rb, i, j);
      const anchor = new Float64Array(n);
      anchor[i] = Rb; // a point of B's core circle, placed near A's tube
      return { shape: t, dist: circleDistance(n, t), radii: rb, anchor };
    },
  },
];

/**
 * The distance to a convex mesh built from a box's boundary, in the mesh's own (principal) frame:
 * the box's frame there is found from the mesh's vertices (each axis of the box is a vertex
 * difference), so the exact distance is clamping in that frame.
 */
function meshAsBoxDistance(n: number, mesh: { vertices: ArrayLike<number> }, h: number[]): CoreDistance {
  const V = mesh.vertices;
  const vert = (k: number) => Array.from({ length: n }, (_, c) => V[k * n + c]!);
  // vertex 0 is the corner (−h); vertex 2^c raises axis c
  const v0 = vert(0);
  const axes = Array.from({ length: n }, (_, c) => {
    const v = vert(1 << c);
    const d = v.map((x, k) => x - v0[k]!);
    const len = Math.hypot(...d);
    return d.map((x) => x / len);
  });
  const centre = v0.map((x, k) => x + axes.reduce((s, a, c) => s + a[k]! * h[c]!, 0));
  const inBox = boxDistance(n, h);
  return (p) => {
    const local = new Float64Array(n);
    for (let c = 0; c < n; c += 1) local[c] = axes[c]!.reduce((s, a, k) => s + a * (p[k]! - centre[k]!), 0);
    const res = inBox(local);
    const turn = (v: Float64Array) => {
      const dir = new Float64Array(n);
      for (let k = 0; k < n; k += 1) for (let c = 0; c < n; c += 1) dir[k] = dir[k]! + axes[c]![k]! * v[c]!;
      return dir;
    };
    return { d: res.d, dir: turn(res.dir), alt: res.alt?.map(turn) };
  };
}

describe('torus pairs against brute force', () => {
  for (const pair of CASES) {
    it(`torus–${pair.name}: gap within 1e-9 m (box, mesh: 1e-8), normal within 1e-6, contact iff gap < margin (n = 2 or 3..6)`, () => {
      // in 2D a circle and a segment or another circle cross (their distance 0, its direction
      // undefined) whenever the solids overlap deeply: those pairs are checked from n = 3
      for (const n of pair.name === 'capsule' || pair.name === 'torus' ? [3, 4, 5, 6] : [2, 3, 4, 5, 6]) {
        const rand = seeded(1800 + n * 31 + pair.name.length);
        // a box's or a mesh's minimum may sit on a kink (two faces tie), where the search converges linearly
        const gapTol = pair.name === 'torus' || pair.name === 'capsule' ? 1e-9 : 1e-8;
        const scratch = createNarrowphaseScratch(n);
        const out = createManifold(n);
        let hits = 0;
        let checked = 0;
        let flat = 0;
        for (let trial = 0; trial < 64; trial += 1) {
          const R = uniform(rand, 0.8, 1.5);
          const r = uniform(rand, 0.1, 0.4);
          const i = Math.floor(uniform(rand, 0, n - 1));
          const j = i + 1 + Math.floor(uniform(rand, 0, n - 1 - i));
          const t = torusShape(R, r, i, j);
          const other = pair.other(n, rand);
          const poseA = randomPoseNear(rand, n, 0.2);
          // B near a random point of the tube so that about half the pairs overlap
          const near = corePoint(n, t, poseA, uniform(rand, 0, 2 * Math.PI));
          const poseB = randomPoseNear(rand, n, 0);
          const spread = 0.9 * Math.sqrt(3 / n);
          for (let c = 0; c < n; c += 1) poseB.x[c] = near[c]! + uniform(rand, -spread, spread);
          if (other.anchor) {
            const off = toWorldDir(n, poseB, other.anchor);
            for (let c = 0; c < n; c += 1) poseB.x[c] = poseB.x[c]! - off[c]!;
          }
          const brute = bruteForce(n, t, poseA, poseB, other.dist, other.radii);
          if (Math.abs(brute.gap) < 1e-6 || Math.abs(brute.gap - 0.02) < 1e-6) continue;
          const hit02 = collide(out, n, t, poseA, other.shape, poseB, 0.02, scratch);
          expect(hit02).toBe(brute.gap < 0.02);
          // the swapped order gives the same contact with the normal flipped
          const hit = collide(out, n, t, poseA, other.shape, poseB, 0, scratch);
          expect(hit).toBe(brute.gap < 0);
          if (!hit) continue;
          hits += 1;
          const check = (m: typeof out, sign: number) => {
            let deepest = 0;
            for (let p = 1; p < m.count; p += 1) if (m.separations[p]! < m.separations[deepest]!) deepest = p;
            if (m.ids[deepest]! < RING_SAMPLES) {
              // a minimum flat within featureTieTolerance over its bracket is carried by the ring samples
              flat += 1;
              expect(Math.abs(m.separations[deepest]! - brute.gap)).toBeLessThanOrEqual(TIE);
              return;
            }
            expect(Math.abs(m.separations[deepest]! - brute.gap)).toBeLessThanOrEqual(gapTol);
            let dn = Infinity;
            for (const e of brute.normals) {
              let d = 0;
              for (let c = 0; c < n; c += 1) d = Math.max(d, Math.abs(sign * m.normal[c]! - e[c]!));
              dn = Math.min(dn, d);
            }
            expect(dn).toBeLessThanOrEqual(1e-6);
          };
          check(out, 1);
          // the other order: the same contact, the normal flipped
          const back = createManifold(n);
          expect(collide(back, n, other.shape, poseB, t, poseA, 0, scratch)).toBe(true);
          if (pair.name !== 'torus') check(back, -1);
          checked += 1;
        }
        expect(hits).toBeGreaterThanOrEqual(8);
        expect(checked).toBe(hits);
        expect(flat).toBeLessThanOrEqual(hits / 8);
      }
    });
  }
});

describe('torus pairs: contact sets of several points', () => {
  it('a ring over a square bar touches its two top edges: two points, one normal straight down (3D, 4D, 5D)', () => {
    for (const n of [3, 4, 5]) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const R = 1;
      const r = 0.2;
      const a = 0.4;
      const half = new Float64Array(n).fill(2);
      half[0] = a;
      half[1] = 0.2;
      const bar = { kind: 'box', halfExtents: half } as never as CollidableShape;
      const poseBar = createPose(n);
      poseBar.x[1] = -0.2; // top face at y = 0
      const ring = torusShape(R, r, 0, 1);
      const y = -Math.sqrt((R - r) ** 2 - a * a);
      const delta = 0.004; // sunk by 4 mm
      const poseRing = createPose(n);
      poseRing.x[1] = y - delta;
      expect(collide(out, n, ring, poseRing, bar, poseBar, 0.02, scratch)).toBe(true);
      expect(out.count).toBe(2);
      expect(Math.abs(out.normal[1]! + 1)).toBeLessThanOrEqual(1e-12);
      // each edge's own normal is at cos α = |y| / (R − r) from the vertical; its gap, measured along
      // the vertical, is the sinking itself to first order: −δ (within δ²/(R − r))
      for (let p = 0; p < 2; p += 1) expect(Math.abs(out.separations[p]! + delta)).toBeLessThanOrEqual(delta ** 2 / (R - r));
      // the points lie midway between the tube and the edges: within δ/2 of the edges (±a, 0)
      const xs = [out.points[0]!, out.points[n]!].sort((u, v) => u - v);
      expect(Math.abs(xs[0]! + a)).toBeLessThanOrEqual(delta / 2);
      expect(Math.abs(xs[1]! - a)).toBeLessThanOrEqual(delta / 2);
      expect(Math.abs(out.points[1]!)).toBeLessThanOrEqual(delta / 2);
    }
  });
});

// ————————————————————————————————————————————— rest in a World

function world(n: number): World {
  const g = new Array<number>(n).fill(0);
  g[1] = -9.81;
  return new World({ dimensions: n, gravity: g, params: { allowSleep: false } });
}

function vec(n: number, entries: Record<number, number>): number[] {
  const v = new Array<number>(n).fill(0);
  for (const [k, x] of Object.entries(entries)) v[Number(k)] = x;
  return v;
}

function add(w: World, shape: Shape, position: number[], mass: number): Body {
  return w.addBody(new Body(w.D, { shape, position, mass }));
}

/** Steps 1/60 s `steps` times; returns the largest and the last |y − expected| of `body`. */
function settle(w: World, body: Body, expected: number, steps: number, after = 120): { worst: number; last: number } {
  let worst = 0;
  let last = 0;
  for (let s = 1; s <= steps; s += 1) {
    w.step(1 / 60);
    last = Math.abs(body.x[1]! - expected);
    if (s > after) worst = Math.max(worst, last);
  }
  return { worst, last };
}

describe('tori at rest in a World', () => {
  it('a 3D torus lying flat on a box rests at the box top + r, within the slop', () => {
    const n = 3;
    const w = world(n);
    const D = w.D;
    add(w, HyperBox(D, [3, 0.5, 3]), vec(n, { 1: -0.5 }), 0);
    const R = 1;
    const r = 0.25;
    const torus = add(w, HyperTorus(D, R, r, [0, 2]), vec(n, { 1: r + 0.05 }), 1);
    const { worst, last } = settle(w, torus, r, 300);
    expect(worst).toBeLessThanOrEqual(SLOP);
    expect(last).toBeLessThanOrEqual(SLOP);
    expect(Math.hypot(torus.x[0]!, torus.x[2]!)).toBeLessThan(1e-3);
  });

  it('a 3D ring hanging on a square bar (a box) rests on the bar’s two top edges at the analytic height', () => {
    const n = 3;
    const w = world(n);
    const D = w.D;
    const a = 0.4; // half width of the bar (x); its top at y = 0, its length along z through the hole
    add(w, HyperBox(D, [a, 0.2, 2]), vec(n, { 1: -0.2 }), 0);
    const R = 1;
    const r = 0.2;
    // the ring in the xy plane: its inner tube on the edges (±a, 0), |edge − centre| = R − r
    const y = -Math.sqrt((R - r) ** 2 - a * a);
    const ring = add(w, HyperTorus(D, R, r, [0, 1]), vec(n, { 1: y + 0.03 }), 1);
    const { worst, last } = settle(w, ring, y, 300);
    expect(worst).toBeLessThanOrEqual(SLOP);
    expect(last).toBeLessThanOrEqual(SLOP);
    expect(Math.abs(ring.x[0]!)).toBeLessThan(1e-3);
  });

  it('a torus lying flat on a convex mesh (3D, 4D) rests at the mesh top + r', () => {
    for (const n of [3, 4]) {
      const w = world(n);
      const D = w.D;
      const h = new Array<number>(n).fill(2.5);
      h[1] = 0.5;
      const m = cubeBoundary(n, h);
      add(w, ConvexMesh(D, m.vertices, m.facets), vec(n, { 1: -0.5 }), 0);
      const r = 0.25;
      const torus = add(w, HyperTorus(D, 1, r, [0, 2]), vec(n, { 1: r + 0.05 }), 1);
      const { worst, last } = settle(w, torus, r, 300);
      expect(worst).toBeLessThanOrEqual(SLOP);
      expect(last).toBeLessThanOrEqual(SLOP);
    }
  });

  it('a ring hangs from a fixed ring for 10 s (3D, 4D): linked, at the analytic height within the slop', () => {
    for (const n of [3, 4]) {
      const w = world(n);
      const D = w.D;
      const R = 1;
      const r = 0.2;
      add(w, HyperTorus(D, R, r, [0, 1]), vec(n, {}), 0); // fixed, vertical, in the xy plane
      // hanging, in the yz plane: its top core point rests 2r above the fixed ring's bottom one
      const y = -(2 * R - 2 * r);
      const link = add(w, HyperTorus(D, R, r, [1, 2]), vec(n, { 1: y + 0.02 }), 1);
      const { worst, last } = settle(w, link, y, 600);
      expect(worst).toBeLessThanOrEqual(SLOP);
      expect(last).toBeLessThanOrEqual(SLOP);
      // still linked: its centre has not moved off the fixed ring's plane
      for (let c = 0; c < n; c += 1) if (c !== 1) expect(Math.abs(link.x[c]!)).toBeLessThan(1e-3);
    }
  });

  it('a ball rests in a ring (3D, 4D) at its analytic height within the slop', () => {
    for (const n of [3, 4]) {
      const R = 1;
      const r = 0.25;
      for (const rho of [1.2, 0.9]) {
        const w = world(n);
        const D = w.D;
        add(w, HyperTorus(D, R, r, [0, 2]), vec(n, {}), 0); // lying flat, fixed
        const y = Math.sqrt((rho + r) ** 2 - R * R);
        const ball = add(w, HyperSphere(D, rho), vec(n, { 1: y + 0.02 }), 1);
        const { worst, last } = settle(w, ball, y, 300);
        expect(worst).toBeLessThanOrEqual(SLOP);
        expect(last).toBeLessThanOrEqual(SLOP);
        for (let c = 0; c < n; c += 1) if (c !== 1) expect(Math.abs(ball.x[c]!)).toBeLessThan(1e-6);
      }
    }
  });

  it('a capsule (HyperCapsule) lying across a ring rests on it (3D)', () => {
    const n = 3;
    const w = world(n);
    const D = w.D;
    const R = 1;
    const r = 0.2;
    add(w, HyperTorus(D, R, r, [0, 2]), vec(n, {}), 0);
    const rb = 0.15;
    const hh = 1.5;
    // the capsule lies along x (turned from its y axis by a quarter turn in the xy plane)
    const cap = w.addBody(
      new Body(D, { shape: HyperCapsule(D, hh, rb), position: vec(n, { 1: r + rb + 0.02 }), mass: 1, rotor: quarterTurnXY(n) }),
    );
    const { worst, last } = settle(w, cap, r + rb, 300);
    expect(worst).toBeLessThanOrEqual(SLOP);
    expect(last).toBeLessThanOrEqual(SLOP);
  });
});

describe('a pile of tori in a bin of boxes (3D, 4D)', () => {
  const R = 0.5;
  const r = 0.15;
  /** Distance from the point p to the core circle (centre x, plane u, v) of radius R. */
  function circlePointDistance(p: number[], x: number[], u: number[], v: number[]): number {
    const d = p.map((pc, i) => pc - x[i]!);
    const a = d.reduce((s, dc, i) => s + dc * u[i]!, 0);
    const b = d.reduce((s, dc, i) => s + dc * v[i]!, 0);
    const rho = Math.hypot(a, b);
    return Math.hypot(...d.map((dc, i) => dc - (R / rho) * (a * u[i]! + b * v[i]!)));
  }
  type Frame = { x: number[]; u: number[]; v: number[] };
  /** Distance between two core circles: every local minimum of 720 samples round A's, refined by ternary search. */
  function circleDistance(A: Frame, B: Frame): number {
    const f = (t: number) =>
      circlePointDistance(
        A.x.map((xc, i) => xc + R * (Math.cos(t) * A.u[i]! + Math.sin(t) * A.v[i]!)),
        B.x,
        B.u,
        B.v,
      );
    const K = 720;
    const g = Array.from({ length: K }, (_, k) => f((2 * Math.PI * k) / K));
    let best = Infinity;
    for (let k = 0; k < K; k += 1) {
      if (!(g[k]! <= g[(k + K - 1) % K]! && g[k]! <= g[(k + 1) % K]!)) continue;
      let lo = (2 * Math.PI * (k - 1)) / K;
      let hi = (2 * Math.PI * (k + 1)) / K;
      for (let it = 0; it < 60; it += 1) {
        const m1 = lo + (hi - lo) / 3;
        const m2 = hi - (hi - lo) / 3;
        if (f(m1) < f(m2)) hi = m2;
        else lo = m1;
      }
      best = Math.min(best, f((lo + hi) / 2));
    }
    return best;
  }

  // Before the depth-weighted reduction (torus-pairs.ts) the 3D pile sank to 20.7 mm and never
  // slept (fastest torus 0.08 m/s after 10 s): two rings lying flat on each other cross twice,
  // and the second crossing lost its point to shallow ring samples spread round the circle.
  // The piles are chaotic: any change to the solver moves them. With the grouped shock passes
  // (docs/solver.md) the 3D pile of seed 1900 has a mean of 2.79 mm (2.39 before); over five seeds
  // (1900, 2000, …, 2300) the means are 1.87-2.79 mm (before 2.13-2.39; median 2.12 against 2.37)
  // and the worst 5.04-5.35 mm (before 4.97-5.38).
  for (const [n, count, H, worstBound, meanBound] of [
    [3, 30, 1.6, 5.5e-3, 3.0e-3],
    [4, 20, 0.9, 5.1e-3, 2.0e-3],
  ] as const) {
    it(`n = ${n}: ${count} tori dropped in a bin fall asleep within 10 s, worst penetration < ${(worstBound * 1000).toFixed(1)} mm, mean < ${(meanBound * 1000).toFixed(1)} mm`, () => {
      const D = dims(n);
      const world = new World({ dimensions: n, gravity: Array.from({ length: n }, (_, i) => (i === 1 ? -9.81 : 0)) });
      const material = { friction: 0.5, restitution: 0 };
      const half = (axis: number, across: number, up: number) =>
        Array.from({ length: n }, (_, c) => (c === axis ? across : c === 1 ? up : H + 1));
      // the floor (top at y = 0), and two walls across every horizontal axis (inner faces at ±H)
      world.addBody(
        new Body(D, {
          shape: HyperBox(D, half(1, 0.5, 0.5)),
          mass: 0,
          position: Array.from({ length: n }, (_, c) => (c === 1 ? -0.5 : 0)),
          material,
        }),
      );
      const horizontal = Array.from({ length: n }, (_, c) => c).filter((c) => c !== 1);
      for (const axis of horizontal) {
        for (const side of [-1, 1]) {
          const position = Array.from({ length: n }, (_, c) => (c === axis ? side * (H + 0.5) : c === 1 ? 5 : 0));
          world.addBody(new Body(D, { shape: HyperBox(D, half(axis, 0.5, 5)), mass: 0, position, material }));
        }
      }
      // seeded start poses: a grid 1.3 m apart, jittered by ±0.1 m, uniform random rotors
      const rand = seeded(1900 + n);
      const spacing = 1.3;
      const side = Math.floor((2 * H) / spacing);
      const perLayer = side ** horizontal.length;
      const shape = HyperTorus(D, R, r, [0, 2]);
      const bodies: Body[] = [];
      for (let k = 0; k < count; k += 1) {
        const position = new Array<number>(n).fill(0);
        position[1] = 0.8 + Math.floor(k / perLayer) * spacing + uniform(rand, -0.1, 0.1);
        let cell = k % perLayer;
        for (const c of horizontal) {
          position[c] = -((side - 1) * spacing) / 2 + (cell % side) * spacing + uniform(rand, -0.1, 0.1);
          cell = Math.floor(cell / side);
        }
        const B = Array.from({ length: D.k }, () => uniform(rand, -Math.PI, Math.PI));
        const rotor = rotorExp(D, new Float64Array(D.r), B);
        bodies.push(world.addBody(new Body(D, { shape, mass: 1, position, rotor, material })));
      }
      for (let s = 0; s < 600; s += 1) world.step(1 / 60);
      const frames: Frame[] = bodies.map((b) => {
        const M = rotorToMatrix(D, new Float64Array(n * n), b.R);
        return {
          x: Array.from(b.x),
          u: Array.from({ length: n }, (_, i) => M[i * n]!),
          v: Array.from({ length: n }, (_, i) => M[i * n + 2]!),
        };
      });
      const depths: number[] = [];
      for (let a = 0; a < count; a += 1) {
        const T = frames[a]!;
        // depth below a bin face {p : p·dir = offset}: the torus's lowest point along dir is
        // x·dir − R·|dir's part in the circle's plane| − r
        const depthBelow = (dir: number[], offset: number) => {
          const du = dir.reduce((s, dc, i) => s + dc * T.u[i]!, 0);
          const dv = dir.reduce((s, dc, i) => s + dc * T.v[i]!, 0);
          return offset - (dir.reduce((s, dc, i) => s + dc * T.x[i]!, 0) - R * Math.hypot(du, dv) - r);
        };
        depths.push(
          depthBelow(
            Array.from({ length: n }, (_, c) => (c === 1 ? 1 : 0)),
            0,
          ),
        );
        for (const c of horizontal) {
          for (const sgn of [-1, 1])
            depths.push(
              depthBelow(
                Array.from({ length: n }, (_, i) => (i === c ? sgn : 0)),
                -H,
              ),
            );
          expect(Math.abs(T.x[c]!)).toBeLessThan(H);
        }
        for (let b = a + 1; b < count; b += 1) {
          const U = frames[b]!;
          if (Math.hypot(...T.x.map((xc, i) => xc - U.x[i]!)) > 2 * (R + r)) continue;
          depths.push(2 * r - circleDistance(T, U));
        }
      }
      const overlaps = depths.filter((d) => d > 0);
      const worst = Math.max(...overlaps);
      const mean = overlaps.reduce((s, d) => s + d, 0) / overlaps.length;
      if (process.env.TORUS_FIGURES)
        console.log(`n = ${n} pile: worst ${worst * 1000} mm, mean ${mean * 1000} mm, ${overlaps.length} overlaps`);
      expect(worst).toBeLessThan(worstBound);
      expect(mean).toBeLessThan(meanBound);
      for (const b of bodies) expect(b.isSleeping).toBe(true);
    });
  }
});

/** The unit rotor of a quarter turn in the xy plane (bivector component 0 is the plane (0, 1)): lays the capsule's y axis along x. */
function quarterTurnXY(n: number): Float64Array {
  const D = dims(n);
  const B = new Float64Array(D.k);
  B[0] = Math.PI / 2;
  return rotorExp(D, new Float64Array(D.r), B);
}

// ————————————————————————————————————————————— allocation (built engine, child process)

/**
 * As tests/collision-narrowphase-allocation.test.ts: a child node with a large young generation
 * collides posed torus pairs of every kind the torus owns (ball, half-space, box, mesh, capsule,
 * torus; both orders; touching, overlapping and apart; n = 3..6) through collideScratch, warms
 * up, then measures three windows: none may collect garbage or grow the new space by 64 KB (the
 * measuring costs about 12 KB). It also reports the mean µs per call of each kind (not asserted).
 */
const ALLOCATION_SCRIPT = String.raw`
import { PerformanceObserver, performance } from 'node:perf_hooks';
import v8 from 'node:v8';
const base = process.argv[process.argv.length - 1];
const E = await import(base + '/internal.js');
const { collideScratch } = await import(base + '/collision/collide.js');
const { NARROWPHASE_MARGIN } = await import(base + '/collision/narrowphase-scratch.js');
const { dims, HyperBox, HyperSphere, HalfSpace, HyperTorus, ConvexMesh, HyperCapsule } = E;
let seed = 4242;
const rand = () => {
  seed = (seed + 0x6d2b79f5) >>> 0;
  let t = seed;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
function rotation(n) {
  const M = new Float64Array(n * n);
  for (let i = 0; i < n * n; i += 1) M[i] = 2 * rand() - 1;
  for (let c = 0; c < n; c += 1) {
    for (let p = 0; p < c; p += 1) {
      let d = 0;
      for (let i = 0; i < n; i += 1) d += M[i * n + c] * M[i * n + p];
      for (let i = 0; i < n; i += 1) M[i * n + c] -= d * M[i * n + p];
    }
    let l = 0;
    for (let i = 0; i < n; i += 1) l += M[i * n + c] ** 2;
    for (let i = 0; i < n; i += 1) M[i * n + c] /= Math.sqrt(l);
  }
  return M;
}
function crossPolytope(D, s) {
  const n = D.n;
  const vertices = [];
  for (let i = 0; i < n; i += 1) for (const g of [1, -1]) vertices.push(Array.from({ length: n }, (_, c) => (c === i ? g * s : 0)));
  const facets = [];
  for (let mask = 0; mask < 1 << n; mask += 1) facets.push(Array.from({ length: n }, (_, i) => 2 * i + ((mask >> i) & 1)));
  return ConvexMesh(D, vertices, facets);
}
const OTHERS = ['ball', 'floor', 'box', 'mesh', 'capsule', 'torus'];
const sets = [];
for (let n = 3; n <= 6; n += 1) {
  const D = dims(n);
  const up = new Array(n).fill(0);
  up[1] = 1;
  const torus = HyperTorus(D, 1, 0.3, [0, 2]);
  const shapes = {
    ball: HyperSphere(D, 0.6),
    floor: HalfSpace(D, up, 0),
    box: HyperBox(D, Array.from({ length: n }, (_, i) => 0.5 + 0.1 * i)),
    mesh: crossPolytope(D, 0.8),
    capsule: HyperCapsule(D, 0.5, 0.3),
    torus: HyperTorus(D, 0.8, 0.25, [1, 2]),
  };
  for (const kind of OTHERS) {
    const pairs = [];
    for (let t = 0; t < 8; t += 1) {
      const pa = E.createPose(n);
      const pb = E.createPose(n);
      pa.M.set(rotation(n));
      pb.M.set(rotation(n));
      for (let i = 0; i < n; i += 1) pb.x[i] = (rand() - 0.5) * 2.4;
      // swap every other pair: the other kind as shape A
      pairs.push(t % 2 === 0 ? { A: torus, pa, B: shapes[kind], pb } : { A: shapes[kind], pa: pb, B: torus, pb: pa });
    }
    sets.push({ n, kind, pairs, scratch: E.createNarrowphaseScratch(n), out: E.createManifold(n), time: 0, calls: 0 });
  }
}
let hits = 0;
function pass(timed) {
  for (const set of sets) {
    const t0 = timed ? performance.now() : 0;
    for (const p of set.pairs) {
      set.scratch.scalars[NARROWPHASE_MARGIN] = 0.02;
      if (collideScratch(set.out, set.n, p.A, p.pa, p.B, p.pb, set.scratch)) hits += 1;
    }
    if (timed) {
      set.time += performance.now() - t0;
      set.calls += set.pairs.length;
    }
  }
}
const gcs = [];
const observer = new PerformanceObserver((list) => {
  for (const entry of list.getEntries()) gcs.push(entry.startTime);
});
observer.observe({ entryTypes: ['gc'] });
for (let w = 0; w < 60; w += 1) pass(false);
await new Promise((resolve) => setTimeout(resolve, 100));
for (let w = 0; w < 20; w += 1) pass(true);
const windows = [];
for (let w = 0; w < 3; w += 1) {
  globalThis.gc();
  globalThis.gc();
  await new Promise((resolve) => setTimeout(resolve, 50));
  const before = v8.getHeapSpaceStatistics().find((s) => s.space_name === 'new_space').space_used_size;
  const t0 = performance.now();
  for (let p = 0; p < 20; p += 1) pass(false);
  const t1 = performance.now();
  const after = v8.getHeapSpaceStatistics().find((s) => s.space_name === 'new_space').space_used_size;
  windows.push({ newSpace: after - before, collections: gcs.filter((g) => g >= t0 && g <= t1).length });
}
observer.disconnect();
const cost = {};
for (const s of sets) cost[s.n + 'D ' + s.kind] = +((1000 * s.time) / s.calls).toFixed(2);
console.log(JSON.stringify({ hits, windows, cost }));
`;

describe('torus pairs allocate nothing in steady state (built engine, child process)', () => {
  let result: { hits: number; windows: { newSpace: number; collections: number }[]; cost: Record<string, number> };
  beforeAll(() => {
    ensureBuiltEngine();
    const out = execFileSync(
      process.execPath,
      [
        '--expose-gc',
        '--max-semi-space-size=256',
        '--min-semi-space-size=64',
        '--input-type=module',
        '-e',
        ALLOCATION_SCRIPT,
        pathToFileURL(join(root, 'packages/engine/dist')).href,
      ],
      { cwd: root, encoding: 'utf8' },
    );
    result = JSON.parse(out.trim().split('\n').pop()!) as typeof result;
  });

  it('torus against every kind, both orders, n = 3..6', () => {
    expect(result.hits).toBeGreaterThan(0);
    expect(result.windows.length).toBe(3);
    for (const w of result.windows) {
      expect(w.collections).toBe(0);
      expect(w.newSpace).toBeLessThan(64 * 1024);
    }
  });
});
