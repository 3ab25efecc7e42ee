/**
 * Manifold reuse (contacts/manifold-cache.ts, `Params.manifoldReuseTolerance`): a polytope
 * manifold (box–box, convex mesh–box, convex mesh–mesh) is carried with the two shapes while
 * neither has moved more than the tolerance relative to the other, and computed again otherwise.
 * n = 2..6 for the cache; a box stack and a stack of convex-mesh cubes on a box in 3D and 4D.
 */
import { describe, expect, it } from 'vitest';
import { rotorFromPlane } from '@physin/algebra';
import { Body, ConvexMesh, HyperBox } from '@physin/engine';
import type { World } from '@physin/engine';
import { collide as collideShapes } from '../packages/engine/src/collision/collide.js';
import type { CollidableShape } from '../packages/engine/src/collision/index.js';
import { collideBoxBox } from '../packages/engine/src/collision/box-box.js';
import { createManifold, createPose, maxManifoldPoints } from '../packages/engine/src/collision/manifold.js';
import type { Manifold, Pose } from '../packages/engine/src/collision/manifold.js';
import { createNarrowphaseScratch } from '../packages/engine/src/collision/narrowphase-scratch-nd.js';
import { CACHE_APART, CACHE_MISS, CACHE_REUSE, ManifoldCache } from '../packages/engine/src/contacts/manifold-cache.js';
import type { ContactSet } from '../packages/engine/src/contacts/contact-set.js';
import { randomRotation, turn } from './support/poses.js';
import { randomUnitVector, seeded } from './support/random.js';
import { cubeBoundary } from './support/meshes.js';
import { addBox, addGround, addStack, axis, makeWorld, run } from './support/scenes.js';
import { box } from './support/shapes.js';

const DIMS = [2, 3, 4, 5, 6];
const MARGIN = 0.02;
const HALF = 0.5;
const TOLERANCE = 1e-4;

/** Pose of `local` composed after `outer` (the pair moved as one rigid body): x' = R x + t, M' = R M. */
function moved(n: number, pose: Pose, R: Float64Array, t: Float64Array): Pose {
  const out = createPose(n);
  for (let i = 0; i < n; i += 1) {
    let s = t[i]!;
    for (let c = 0; c < n; c += 1) s += R[i * n + c]! * pose.x[c]!;
    out.x[i] = s;
    for (let col = 0; col < n; col += 1) {
      let m = 0;
      for (let c = 0; c < n; c += 1) m += R[i * n + c]! * pose.M[c * n + col]!;
      out.M[i * n + col] = m;
    }
  }
  return out;
}

/** Box B (half 0.5) resting on box A (half 1) with a small tilt and offset: a face contact. */
function restingPair(n: number, rand: () => number): { pa: Pose; pb: Pose } {
  const pa = createPose(n);
  const pb = createPose(n);
  for (let i = 0; i < n; i += 1) if (i !== 1) pb.x[i] = 0.2 * (rand() - 0.5);
  pb.x[1] = 1 + HALF - 0.003;
  if (n >= 3) turn(n, pb.M, 0, 2, 0.3 * (rand() - 0.5));
  turn(n, pb.M, 0, 1, 0.002 * (rand() - 0.5));
  return { pa, pb };
}

function collide(n: number, pa: Pose, pb: Pose): Manifold {
  const m = createManifold(n, maxManifoldPoints(n));
  collideBoxBox(m, n, box(new Array(n).fill(1)), pa, box(new Array(n).fill(HALF)), pb, MARGIN, createNarrowphaseScratch(n));
  return m;
}

/** Separation and point per feature id. */
function byId(m: Manifold): Map<number, { s: number; p: number[] }> {
  const out = new Map<number, { s: number; p: number[] }>();
  for (let q = 0; q < m.count; q += 1) {
    out.set(m.ids[q]!, { s: m.separations[q]!, p: Array.from(m.points.subarray(q * m.n, (q + 1) * m.n)) });
  }
  return out;
}

function copyManifold(from: Manifold): Manifold {
  const m = createManifold(from.n, from.capacity);
  m.count = from.count;
  m.normal.set(from.normal);
  m.points.set(from.points);
  m.separations.set(from.separations);
  m.ids.set(from.ids);
  return m;
}

describe('ManifoldCache: a reused box–box manifold is the fresh one, moved with the boxes', () => {
  for (const n of DIMS) {
    it(`n = ${n}: the pair moved as one rigid body: the reused manifold equals the fresh one to 1e-12, same ids`, () => {
      const rand = seeded(500 + n);
      const { pa, pb } = restingPair(n, rand);
      const m0 = collide(n, pa, pb);
      expect(m0.count).toBeGreaterThan(0);
      const cache = new ManifoldCache(n, maxManifoldPoints(n));
      const numbers = Float64Array.of(TOLERANCE, Math.sqrt(n) * HALF);
      expect(cache.check(0, pa, pb, numbers)).toBe(CACHE_MISS); // nothing cached yet
      cache.store(0, m0, pa, pb);
      // A rigid motion of the whole pair leaves B's pose in A's frame as it was.
      const R = randomRotation(rand, n);
      const t = randomUnitVector(rand, n).map((v) => 3 * v);
      const qa = moved(n, pa, R, t);
      const qb = moved(n, pb, R, t);
      expect(cache.check(0, qa, qb, numbers)).toBe(CACHE_REUSE);
      const reused = copyManifold(m0);
      cache.reuse(0, reused, qa, qb);
      const fresh = collide(n, qa, qb);
      expect(reused.count).toBe(fresh.count);
      for (let c = 0; c < n; c += 1) expect(Math.abs(reused.normal[c]! - fresh.normal[c]!)).toBeLessThan(1e-12);
      const want = byId(fresh);
      for (const [id, got] of byId(reused)) {
        const w = want.get(id);
        expect(w, `id ${id}`).toBeDefined();
        expect(Math.abs(got.s - w!.s)).toBeLessThan(1e-12);
        for (let c = 0; c < n; c += 1) expect(Math.abs(got.p[c]! - w!.p[c]!)).toBeLessThan(1e-12);
      }
    });

    it(`n = ${n}: B moved by less than the tolerance: reused; separations within the tolerance of fresh ones; beyond it: not reused`, () => {
      const rand = seeded(600 + n);
      const { pa, pb } = restingPair(n, rand);
      const m0 = collide(n, pa, pb);
      const cache = new ManifoldCache(n, maxManifoldPoints(n));
      const radius = Math.sqrt(n) * HALF;
      const numbers = Float64Array.of(TOLERANCE, radius);
      cache.check(0, pa, pb, numbers);
      cache.store(0, m0, pa, pb);
      // Within: a shift of 0.4 tol and a turn whose rim moves by at most 0.4 tol.
      const near = createPose(n);
      near.M.set(pb.M);
      turn(n, near.M, 0, 1, (0.4 * TOLERANCE) / (2 * radius));
      const dir = randomUnitVector(rand, n);
      for (let i = 0; i < n; i += 1) near.x[i] = pb.x[i]! + 0.4 * TOLERANCE * dir[i]!;
      expect(cache.check(0, pa, near, numbers)).toBe(CACHE_REUSE);
      const reused = copyManifold(m0);
      cache.reuse(0, reused, pa, near);
      const want = byId(collide(n, pa, near));
      let compared = 0;
      for (const [id, got] of byId(reused)) {
        const w = want.get(id);
        if (w === undefined) continue;
        compared += 1;
        expect(Math.abs(got.s - w.s)).toBeLessThanOrEqual(TOLERANCE);
      }
      expect(compared).toBe(m0.count);
      // Beyond: a shift of 1.5 tol alone.
      const far = createPose(n);
      far.M.set(pb.M);
      for (let i = 0; i < n; i += 1) far.x[i] = pb.x[i]! + 1.5 * TOLERANCE * dir[i]!;
      expect(cache.check(0, pa, far, numbers)).toBe(CACHE_MISS);
      // A turn by 1.5 tol at the rim, and no shift.
      const turned = createPose(n);
      turned.M.set(pb.M);
      turned.x.set(pb.x);
      turn(n, turned.M, 0, 1, (1.5 * TOLERANCE) / radius);
      expect(cache.check(0, pa, turned, numbers)).toBe(CACHE_MISS);
      // A non-finite pose is never served from the cache.
      const bad = createPose(n);
      bad.M.set(pb.M);
      bad.x.set(pb.x);
      bad.x[0] = Number.NaN;
      expect(cache.check(0, pa, bad, numbers)).toBe(CACHE_MISS);
      // A forgotten slot is not reused.
      cache.forget(0);
      expect(cache.check(0, pa, pb, numbers)).toBe(CACHE_MISS);
    });
  }
});

/** The world's contacts (internal). */
function contactsOf(world: World): ContactSet {
  return (world as unknown as { contacts: ContactSet }).contacts;
}

/**
 * Largest |s_world − s_fresh| by feature id over the contacts whose pair `keep` accepts, and the
 * count of those pairs (fresh = the narrowphase now, through the dispatch the world uses).
 */
function worstSeparationError(world: World, keep: (kindA: string, kindB: string) => boolean): { worst: number; pairs: number } {
  const set = contactsOf(world);
  const n = world.n;
  let worst = 0;
  let pairs = 0;
  for (let i = 0; i < set.count; i += 1) {
    const slot = set.order[i]!;
    const A = set.bodyA[slot] as Body;
    const B = set.bodyB[slot] as Body;
    if (!keep(A.shape.kind, B.shape.kind)) continue;
    const m = set.manifolds[slot]!;
    if (m.count === 0) continue;
    pairs += 1;
    const fresh = createManifold(n, maxManifoldPoints(n));
    const sA = A.shape as unknown as CollidableShape;
    const sB = B.shape as unknown as CollidableShape;
    collideShapes(fresh, n, sA, A.pose!, sB, B.pose!, MARGIN, createNarrowphaseScratch(n));
    const want = byId(fresh);
    for (const [id, got] of byId(m)) {
      const w = want.get(id);
      if (w !== undefined) worst = Math.max(worst, Math.abs(got.s - w.s));
    }
  }
  return { worst, pairs };
}

const boxBox = (a: string, b: string): boolean => a === 'box' && b === 'box';
const withMesh = (a: string, b: string): boolean => a === 'mesh' || b === 'mesh';

describe('manifold reuse in the world', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a resting stack of 3: every box–box separation stays within the tolerance of a fresh narrowphase (300 steps)`, () => {
      const world = makeWorld(n);
      addGround(world, { friction: 0.5 });
      addStack(world, 3, HALF, { friction: 0.5 });
      let worst = 0;
      run(world, 300, 1 / 60, () => {
        const r = worstSeparationError(world, boxBox);
        expect(r.pairs).toBe(2);
        worst = Math.max(worst, r.worst);
      });
      // The step's narrowphase ran before the step moved the boxes; the fresh one sees the moved
      // poses. Motion of a resting stack in one step is far below the tolerance.
      expect(worst).toBeLessThanOrEqual(TOLERANCE);
    });

    it(`n = ${n}: a box sliding fast over a box is computed afresh every step: bit-identical to tolerance 0`, () => {
      const build = (tolerance: number): [World, Body] => {
        const world = makeWorld(n, { manifoldReuseTolerance: tolerance });
        addGround(world, { friction: 0.5 });
        addBox(world, axis(n, 1, 1), 1, { mass: 0, material: { friction: 0.1 } });
        const velocity = axis(n, 0, 2);
        return [world, addBox(world, axis(n, 1, 2.5), HALF, { material: { friction: 0.1 }, velocity })];
      };
      const [wa, a] = build(TOLERANCE);
      const [wb, b] = build(0);
      run(wa, 30);
      run(wb, 30);
      expect(Math.abs(a.v[0]!)).toBeGreaterThan(1); // still sliding: never within the tolerance
      expect(Array.from(a.x)).toEqual(Array.from(b.x));
      expect(Array.from(a.v)).toEqual(Array.from(b.v));
    });

    it(`n = ${n}: a resting box moved by hand to overhang its support tips off: its old manifold is not reused`, () => {
      const world = makeWorld(n, { manifoldReuseTolerance: 1e-3 });
      addGround(world, { friction: 0.5 });
      const [, top] = addStack(world, 2, HALF, { friction: 0.5 });
      run(world, 60);
      // Slide it sideways by 0.9 of its width: its centre of mass is then 0.4 beyond the edge of
      // the box below. The old manifold's points, carried with the two boxes, would still hold it
      // flat on four corners, two of them over empty space.
      const x = Array.from(top!.x);
      x[0] = x[0]! + 0.9;
      top!.setPositionN(x);
      run(world, 90);
      expect(top!.x[1]!).toBeLessThan(HALF + 0.1); // fell off, down to the ground
    });
  }
});

describe('a box pair passed on its kept separation (manifold-cache.ts, storeApart)', () => {
  for (const n of [2, 3, 4]) {
    it(`n = ${n}: is apart: the narrowphase at that moment finds no point (a heap of boxes, 240 steps)`, () => {
      const world = makeWorld(n);
      addGround(world, { friction: 0.5 });
      const rand = seeded(7 + n);
      for (let i = 0; i < 40; i += 1) {
        const p = Array.from({ length: n }, () => 0.3 * (rand() - 0.5));
        p[0] = (i % 4) * 1.1 + 0.3 * rand();
        p[1] = 0.7 + Math.floor(i / 4) * 1.2;
        // turned in the plane of axes 0 and n − 1 (yawed for n >= 3): near pairs apart on a slant
        const D = world.D;
        const rotor = rotorFromPlane(D, new Float64Array(D.r), 0, n - 1, 3 * rand());
        const shape = HyperBox(D, new Array<number>(n).fill(0.3 + 0.2 * rand()));
        world.addBody(new Body(D, { shape, mass: 1, position: p, rotor, material: { friction: 0.5 } }));
      }
      const set = contactsOf(world);
      const cache = (set as unknown as { cache: ManifoldCache }).cache;
      const check = cache.check.bind(cache);
      const fresh = createManifold(n, maxManifoldPoints(n));
      const scratch = createNarrowphaseScratch(n);
      let kept = 0;
      let found = 0;
      cache.check = (slot, poseA, poseB, numbers) => {
        const cached = check(slot, poseA, poseB, numbers);
        if (cached === CACHE_APART) {
          kept += 1;
          const [a, b] = [set.shapeA[slot], set.shapeB[slot]] as unknown as CollidableShape[];
          collideShapes(fresh, n, a!, poseA, b!, poseB, numbers[3]!, scratch);
          if (fresh.count > 0) found += 1;
        }
        return cached;
      };
      run(world, 240);
      expect(found).toBe(0);
      expect(kept).toBeGreaterThan(100);
    });
  }
});

describe('manifold reuse for convex meshes in the world', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: two convex-mesh cubes stacked on a static box: reused, every separation within the tolerance of a fresh narrowphase (300 steps)`, () => {
      const world = makeWorld(n);
      const D = world.D;
      const material = { friction: 0.5 };
      world.addBody(
        new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(1)), mass: 0, position: axis(n, 1, -1), material }),
      );
      const cube = cubeBoundary(n, new Array<number>(n).fill(HALF));
      const shape = ConvexMesh(D, cube.vertices, cube.facets);
      for (let k = 0; k < 2; k += 1)
        world.addBody(new Body(D, { shape, mass: 1, position: axis(n, 1, HALF + 2 * k * HALF), material }));
      // Count the reuses: the cache of the world's contact set, wrapped (internal).
      const cache = (contactsOf(world) as unknown as { cache: ManifoldCache }).cache;
      let reused = 0;
      const reuse = cache.reuse.bind(cache);
      cache.reuse = (...args: Parameters<ManifoldCache['reuse']>) => {
        reused += 1;
        reuse(...args);
      };
      let worst = 0;
      run(world, 300, 1 / 60, () => {
        const r = worstSeparationError(world, withMesh);
        expect(r.pairs).toBe(2);
        worst = Math.max(worst, r.worst);
      });
      expect(worst).toBeLessThanOrEqual(TOLERANCE);
      // At rest most sub-steps reuse both manifolds (2 pairs × 300 steps × the sub-steps).
      expect(reused).toBeGreaterThan(300);
      for (const b of world.bodies.slice(1)) expect(Math.abs(b.v[1]!)).toBeLessThan(1e-3);
    });
  }
});
