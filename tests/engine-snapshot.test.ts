/**
 * Engine snapshots: `snapshotWorld(world)` and `restoreWorld(bytes)`.
 *
 * The key property: a restored world continued for 600 steps is bit-identical to the original
 * continued for 600 steps — every Float64 of every body's record (x, R, v, L, w, force, torque),
 * its sleep flag and timer, the clock, compared after every step. Scenes (gravity −9.81 e_1,
 * dt 1/60, sleep on): in 3D and 4D a ground half-space with friction, a stack of hypercubes,
 * tumbling boxes and hyperspheres, a torus and a convex mesh, a kinematic box, and every joint
 * type — a soft point joint, a rope, a rod, a weld of two boxes, a hinge with motor and limits in
 * a bivector plane, a hinge whose motor drives it into its limit until it breaks, a subspace
 * joint. Snapshots are taken mid-fall, just after the joint broke, and at rest (the stack asleep,
 * later woken). Also: piles of boxes in 3D and 4D (most broadphase pairs not touching); free
 * bodies and a simple contact in 2D and 5D; a bouncing ball restored at each of 150 steps;
 * commands between steps; bodies removed (a pending end event) and added again (reused proxy
 * ids); the last joint of a world removed or broken.
 *
 * Also: the snapshot of a restored world has the bytes of the original's at the same moment;
 * taking snapshots does not change the world; truncated, foreign, damaged, inconsistent and
 * wrong-version buffers throw errors that name 'bytes'; a shape kind the snapshot code does not
 * know is named; and every field of the classes a step reads is known to the snapshot code (a
 * field added later fails here until it is saved).
 */
import { describe, expect, it } from 'vitest';
import {
  Body,
  ConvexMesh,
  DistanceJoint,
  FixedJoint,
  HalfSpace,
  HingeJoint,
  HyperBox,
  HyperSphere,
  HyperTorus,
  PointJoint,
  SubspaceJoint,
  World,
  castRay,
  restoreWorld,
  snapshotWorld,
} from '@physin/engine';
import type { Joint } from '@physin/engine';
import { cubeBoundary } from './support/meshes.js';
import { worldParts } from '../packages/engine/src/snapshot/world-parts.js';
import { seeded, uniform } from './support/random.js';
import { axis, gravity } from './support/scenes.js';

const DT = 1 / 60;
const CONTINUE = 600;

/** Every body's record, sleep flag and sleep timer, as one array (compared bit for bit). */
function stateOf(world: World): Float64Array {
  const parts: number[] = [];
  for (const body of world.bodies) {
    const len = Body.recordLength(world.D);
    for (let i = 0; i < len; i += 1) parts.push(body.storage[body.storageOffset + i]!);
    parts.push(body.isSleeping ? 1 : 0, body.sleepTimer);
  }
  parts.push(world.time, world.stepCount);
  return Float64Array.from(parts);
}

/** Index of the first Float64 whose bits differ, or -1. */
function firstDifference(a: Float64Array, b: Float64Array): number {
  if (a.length !== b.length) return Math.min(a.length, b.length);
  const ua = new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
  const ub = new Uint8Array(b.buffer, b.byteOffset, b.byteLength);
  for (let i = 0; i < ua.length; i += 1) if (ua[i] !== ub[i]) return i >> 3;
  return -1;
}

function expectSameBytes(a: Uint8Array, b: Uint8Array, label: string): void {
  expect(a.length, `${label}: length`).toBe(b.length);
  let first = -1;
  for (let i = 0; i < a.length && first < 0; i += 1) if (a[i] !== b[i]) first = i;
  expect(first, `${label}: first differing byte`).toBe(-1);
}

/** Steps both worlds `steps` times and checks after every step that their states are bit-identical. */
function expectSameContinuation(a: World, b: World, steps: number, label: string): void {
  for (let s = 1; s <= steps; s += 1) {
    a.step(DT);
    b.step(DT);
    const d = firstDifference(stateOf(a), stateOf(b));
    if (d >= 0) expect.fail(`${label}: state differs after ${s} continued steps at Float64 ${d}`);
  }
  expect(a.constraints.length).toBe(b.constraints.length);
  expect(a.contactCount).toBe(b.contactCount);
  expect(a.touchingCount).toBe(b.touchingCount);
}

interface Scene {
  world: World;
  breakable: Joint;
  stackTop: Body;
}

/**
 * The rich scene in n = 3 or 4 (see the module). Deterministic: the same n gives the same world.
 */
function richScene(n: number): Scene {
  const world = new World({ dimensions: n, gravity: gravity(n), params: { allowSleep: true } });
  const D = world.D;
  const rand = seeded(1234 + n);
  const at = (...lead: number[]): number[] => {
    const p = new Array<number>(n).fill(0);
    lead.forEach((v, i) => {
      if (i < n) p[i] = v;
    });
    return p;
  };
  world.addBody(new Body(D, { shape: HalfSpace(D, axis(n, 1), 0), mass: 0, material: { friction: 0.6 }, name: 'ground' }));
  // A stack of hypercubes (sleeps once settled).
  const cube = HyperBox(D, new Array<number>(n).fill(0.25));
  let stackTop: Body | null = null;
  for (let i = 0; i < 4; i += 1) {
    stackTop = world.addBody(
      new Body(D, { shape: cube, mass: 1, position: at(0, 0.25 + 0.5 * i + 0.01 * i), name: `stack${i}` }),
    );
  }
  // Tumbling boxes and balls.
  for (let i = 0; i < 5; i += 1) {
    const rotor = new Float64Array(D.r);
    rotor[0] = 1;
    const w = Array.from({ length: D.k }, () => uniform(rand, -2, 2));
    const shape =
      i % 2 === 0
        ? HyperBox(
            D,
            Array.from({ length: n }, () => uniform(rand, 0.15, 0.35)),
          )
        : HyperSphere(D, uniform(rand, 0.15, 0.3));
    world.addBody(
      new Body(D, {
        shape,
        mass: uniform(rand, 0.5, 2),
        position: at(2 + 0.8 * i, 1 + 0.7 * i, uniform(rand, -0.3, 0.3)),
        angularVelocity: w,
        velocity: at(uniform(rand, -1, 1), 0, uniform(rand, -0.5, 0.5)),
        material: { friction: uniform(rand, 0.2, 0.8), restitution: i === 1 ? 0.4 : 0 },
      }),
    );
  }
  // A torus and a convex mesh.
  world.addBody(
    new Body(D, {
      shape: HyperTorus(D, 0.4, 0.1, [0, 2]),
      mass: 1,
      position: at(-2, 1.5, 0.5),
      angularVelocity: Array.from({ length: D.k }, (_, p) => (p === 1 ? 1 : 0)),
    }),
  );
  const mesh = cubeBoundary(
    n,
    new Array<number>(n).fill(0.2).map((a, c) => a + 0.05 * c),
  );
  world.addBody(
    new Body(D, {
      shape: ConvexMesh(D, mesh.vertices, mesh.facets),
      mass: 1.5,
      position: at(-2, 3, -0.5),
      angularVelocity: Array.from({ length: D.k }, (_, p) => 0.3 * (p + 1)),
    }),
  );
  // A kinematic box sliding along the ground, pushing what it meets.
  world.addBody(
    new Body(D, {
      shape: HyperBox(D, new Array<number>(n).fill(0.3)),
      type: 'kinematic',
      mass: 0,
      position: at(6, 0.3, 0),
      velocity: at(-0.5),
    }),
  );

  // Joints: a soft point joint with a rope to a second ball.
  const bob = world.addBody(new Body(D, { shape: HyperSphere(D, 0.15), mass: 1, position: at(-4, 3, 0), velocity: at(0, 0, 1) }));
  world.addConstraint(new PointJoint(bob, null, at(0, 0.5), at(-4, 3.5, 0), { hertz: 4, damping: 0.3 }));
  const bob2 = world.addBody(new Body(D, { shape: HyperSphere(D, 0.1), mass: 0.5, position: at(-4.5, 2.2, 0) }));
  world.addConstraint(new DistanceJoint(bob, bob2, at(), at(), { mode: 'rope', rest: 0.9 }));
  // A rod from the second ball to a box, which lies on the ground.
  const rodBox = world.addBody(
    new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.15)), mass: 1, position: at(-4.5, 0.6, 0.4) }),
  );
  world.addConstraint(new DistanceJoint(bob2, rodBox, at(), at(0.15, 0.15), { mode: 'rod' }));
  // A weld of two boxes falling on the ground.
  const w1 = world.addBody(
    new Body(D, {
      shape: HyperBox(
        D,
        at(0.3, 0.1, 0.2, 0.2).map((v) => v || 0.2),
      ),
      mass: 1,
      position: at(4, 2.5, -1),
    }),
  );
  const w2 = world.addBody(new Body(D, { shape: cube, mass: 1, position: at(4.5, 2.8, -1) }));
  world.addConstraint(new FixedJoint(w1, w2, at(0.3, 0.1), at(-0.2, -0.2), { breakForce: 1e6 }));
  // A wheel on a hinge with motor and limits (held), and a breakable one driven into its limit.
  const wheel = world.addBody(
    new Body(D, {
      shape: HyperBox(
        D,
        at(0.5, 0.1, 0.1, 0.1).map((v) => v || 0.1),
      ),
      mass: 2,
      position: at(0, 4, 2),
    }),
  );
  // Its plane is the simple bivector e01 + e02 (normalised by the joint: a rounding that the restore must not redo).
  const plane = Array.from({ length: D.k }, (_, p) => (p < 2 ? 1 : 0));
  world.addConstraint(
    new HingeJoint(wheel, null, at(), at(0, 4, 2), {
      plane,
      motorSpeed: 1.5,
      maxMotorTorque: 5,
      lowerAngle: -0.5,
      upperAngle: 2,
      hertz: 30,
      damping: 1,
    }),
  );
  const lever = world.addBody(
    new Body(D, {
      shape: HyperBox(
        D,
        at(0.4, 0.05, 0.05, 0.05).map((v) => v || 0.05),
      ),
      mass: 1,
      position: at(0, 4, -2),
    }),
  );
  const breakable = world.addConstraint(
    new HingeJoint(lever, null, at(-0.4), at(-0.4, 4, -2), {
      plane: 0,
      motorSpeed: 3,
      maxMotorTorque: 80,
      upperAngle: 0.6,
      breakTorque: 40,
    }),
  );
  // A subspace joint: a box kept in the plane of axes 0 and 1 (turning only in it), sliding on the ground.
  const slider = world.addBody(new Body(D, { shape: cube, mass: 1, position: at(-1, 0.6, -2), velocity: at(1.5, 0, 2) }));
  const freePlane = [0];
  const lockAxes = [...Array(n).keys()].filter((c) => c >= 2);
  world.addConstraint(
    new SubspaceJoint(slider, null, { lockAxes, freePlanes: freePlane, localA: at(), localB: at(0, 0, -2), worldFrame: n === 4 }),
  );
  return { world, breakable, stackTop: stackTop! };
}

/** Runs the scene until `done()` or `limit` steps; returns the steps taken. */
function runUntil(world: World, done: () => boolean, limit: number): number {
  let s = 0;
  while (s < limit && !done()) {
    world.step(DT);
    s += 1;
  }
  return s;
}

describe('snapshot and restore: bit-identical continuation, every joint type, 3D and 4D', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: mid-fall, just after a joint broke, and at rest`, () => {
      // Mid-fall: the tumbling bodies in the air, the stack settling.
      const { world, breakable } = richScene(n);
      runUntil(world, () => false, 20);
      expect(
        world.bodies.some((b) => b.v[1]! < -1),
        'something falls',
      ).toBe(true);
      const mid = restoreWorld(snapshotWorld(world));
      expectSameBytes(snapshotWorld(mid), snapshotWorld(world), `n = ${n}, mid-fall: snapshot of the restored world`);
      expectSameContinuation(world, mid, CONTINUE, `n = ${n}, mid-fall`);
      expect(breakable.broken, 'the breakable hinge broke within the continued steps').toBe(true);
      expectSameBytes(snapshotWorld(mid), snapshotWorld(world), `n = ${n}, ${CONTINUE} steps after mid-fall`);

      // Just after the break.
      const second = richScene(n);
      const steps = runUntil(second.world, () => second.breakable.broken, 600);
      expect(second.breakable.broken, 'the breakable hinge breaks').toBe(true);
      expect(steps).toBeGreaterThan(2);
      const afterBreak = restoreWorld(snapshotWorld(second.world));
      expect(afterBreak.constraints.length).toBe(second.world.constraints.length);
      expectSameContinuation(second.world, afterBreak, CONTINUE, `n = ${n}, after the break`);

      // At rest: the stack asleep; the kinematic box later pushes the tumbled bodies into it and wakes it.
      const third = richScene(n);
      runUntil(third.world, () => third.world.stepCount >= 60 && third.stackTop.isSleeping, 500);
      expect(third.stackTop.isSleeping, 'the stack sleeps').toBe(true);
      const rest = restoreWorld(snapshotWorld(third.world));
      const top = rest.bodies[third.world.bodies.indexOf(third.stackTop)]!;
      expect(top.isSleeping).toBe(true);
      expectSameContinuation(third.world, rest, CONTINUE, `n = ${n}, at rest`);
      expect(top.isSleeping, 'the stack was woken by the pushed bodies').toBe(false);
      // A snapshot of a restored world restores to the same bytes again.
      const again = restoreWorld(snapshotWorld(rest));
      expectSameBytes(snapshotWorld(again), snapshotWorld(third.world), `n = ${n}, restored twice`);
    });
  }
});

describe('snapshot and restore: free bodies and a simple contact, n = 2 and 5', () => {
  for (const n of [2, 5]) {
    it(`n = ${n}`, () => {
      const world = new World({ dimensions: n, gravity: gravity(n), params: { allowSleep: true } });
      const D = world.D;
      const rand = seeded(99 + n);
      world.addBody(new Body(D, { shape: HalfSpace(D, axis(n, 1), 0), mass: 0, material: { friction: 0.5 } }));
      for (let i = 0; i < 4; i += 1) {
        const p = new Array<number>(n).fill(0);
        p[0] = 1.2 * i;
        p[1] = 0.6 + 0.9 * i;
        world.addBody(
          new Body(D, {
            shape: i % 2 === 0 ? HyperBox(D, new Array<number>(n).fill(0.25)) : HyperSphere(D, 0.3),
            mass: 1 + i,
            position: p,
            angularVelocity: Array.from({ length: D.k }, () => uniform(rand, -3, 3)),
            velocity: Array.from({ length: n }, () => uniform(rand, -1, 1)),
          }),
        );
      }
      // A free body far from everything, with no gravity acting on its spin: a torque-free tumble.
      const far = new Array<number>(n).fill(50);
      world.addBody(
        new Body(D, {
          shape: HyperBox(
            D,
            Array.from({ length: n }, (_, c) => 0.1 + 0.1 * c),
          ),
          mass: 1,
          position: far,
          angularVelocity: Array.from({ length: D.k }, (_, p) => 1 + p),
        }),
      );
      world.step(DT);
      const restored = restoreWorld(snapshotWorld(world));
      expectSameContinuation(world, restored, CONTINUE, `n = ${n}`);
      expect(world.touchingCount).toBeGreaterThan(0);
      expectSameBytes(snapshotWorld(world), snapshotWorld(restored), `n = ${n}, after ${CONTINUE} steps`);
    });
  }
});

describe('snapshot and restore: piles, where most broadphase pairs do not touch', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a pile of jittered, turned boxes restored mid-fall and after landing`, () => {
      const world = new World({ dimensions: n, gravity: gravity(n), params: { allowSleep: false } });
      const D = world.D;
      const rand = seeded(7 + n);
      world.addBody(new Body(D, { shape: HalfSpace(D, axis(n, 1), 0), mass: 0, material: { friction: 0.5 } }));
      const cube = HyperBox(D, new Array<number>(n).fill(0.5));
      const side = n === 3 ? 4 : 3;
      const layers = 3;
      const horizontal = [...Array(n).keys()].filter((a) => a !== 1);
      const perLayer = side ** horizontal.length;
      for (let i = 0; i < perLayer * layers; i += 1) {
        const p = new Array<number>(n).fill(0);
        let cell = i % perLayer;
        for (const a of horizontal) {
          p[a] = ((cell % side) - (side - 1) / 2) * 1.05 + uniform(rand, -0.2, 0.2);
          cell = Math.floor(cell / side);
        }
        p[1] = 0.6 + 1.2 * Math.floor(i / perLayer) + uniform(rand, -0.1, 0.1);
        world.addBody(
          new Body(D, {
            shape: cube,
            mass: 1,
            position: p,
            angularVelocity: Array.from({ length: D.k }, () => uniform(rand, -1, 1)),
          }),
        );
      }
      for (const steps of [25, 150]) {
        while (world.stepCount < steps) world.step(DT);
        expect(world.contactCount).toBeGreaterThan(world.touchingCount);
        const restored = restoreWorld(snapshotWorld(world));
        expectSameBytes(snapshotWorld(restored), snapshotWorld(world), `pile n = ${n} at ${steps}`);
        expectSameContinuation(world, restored, 150, `pile n = ${n} from step ${steps}`);
      }
    });
  }
});

describe('snapshot is read-only and restore keeps the order', () => {
  it('an empty world and a world of static bodies only', () => {
    for (const n of [2, 8]) {
      const empty = new World({ dimensions: n, gravity: gravity(n), params: { subSteps: 2 } });
      empty.step(DT);
      const copy = restoreWorld(snapshotWorld(empty));
      expect(copy.n).toBe(n);
      expect(copy.bodies.length).toBe(0);
      expect(copy.params.subSteps).toBe(2);
      expect(copy.stepCount).toBe(1);
      expectSameBytes(snapshotWorld(copy), snapshotWorld(empty), `empty n = ${n}`);
      const D = empty.D;
      empty.addBody(new Body(D, { shape: HalfSpace(D, axis(n, 1), 0), mass: 0 }));
      empty.addBody(new Body(D, { shape: HyperSphere(D, 1), mass: 0, position: axis(n, 0, 3) }));
      const statics = restoreWorld(snapshotWorld(empty));
      expectSameContinuation(empty, statics, 10, `static bodies n = ${n}`);
      expectSameBytes(snapshotWorld(statics), snapshotWorld(empty), `static bodies n = ${n}`);
    }
  });

  it('taking snapshots does not change the world (3D rich scene)', () => {
    const a = richScene(3).world;
    const b = richScene(3).world;
    for (let s = 0; s < 300; s += 1) {
      a.step(DT);
      b.step(DT);
      if (s % 7 === 0) snapshotWorld(a);
    }
    expect(firstDifference(stateOf(a), stateOf(b))).toBe(-1);
    expectSameBytes(snapshotWorld(a), snapshotWorld(b), 'after 300 steps');
  });

  it('a restored world lists its bodies and joints in the original order', () => {
    const { world } = richScene(4);
    world.step(DT);
    const restored = restoreWorld(snapshotWorld(world));
    world.bodies.forEach((body, i) => {
      const copy = restored.bodies[i]!;
      expect(copy).not.toBe(body);
      expect(Array.from(copy.x)).toEqual(Array.from(body.x));
      expect(copy.mass).toBe(body.mass);
      expect(copy.material).toEqual(body.material);
    });
    world.constraints.forEach((joint, j) => {
      const copy = restored.constraints[j]!;
      expect(copy.constructor).toBe(joint.constructor);
      expect(restored.bodies.indexOf(copy.bodyA)).toBe(world.bodies.indexOf(joint.bodyA));
      expect(Array.from(copy.lambda)).toEqual(Array.from(joint.lambda));
    });
  });

  it('a body removed before the snapshot still ends its contact at the next step', () => {
    const { world, stackTop } = richScene(3);
    for (let s = 0; s < 90; s += 1) world.step(DT);
    world.removeBody(stackTop);
    const restored = restoreWorld(snapshotWorld(world));
    expectSameBytes(snapshotWorld(restored), snapshotWorld(world), 'with a departed body');
    world.step(DT);
    restored.step(DT);
    expect(world.contactEvents.endCount).toBeGreaterThan(0);
    expect(restored.contactEvents.endCount).toBe(world.contactEvents.endCount);
    const ev = world.contactEvents;
    const rv = restored.contactEvents;
    for (let i = 0; i < ev.endCount; i += 1) {
      for (const [x, y] of [
        [ev.endA[i]!, rv.endA[i]!],
        [ev.endB[i]!, rv.endB[i]!],
      ] as const) {
        const index = world.bodies.indexOf(x);
        if (index >= 0) expect(restored.bodies.indexOf(y)).toBe(index);
        else {
          expect(x).toBe(stackTop);
          expect(restored.bodies.includes(y)).toBe(false);
          expect(Array.from(y.x)).toEqual(Array.from(x.x));
        }
      }
    }
    expectSameContinuation(world, restored, 200, 'after the removal');
  });

  it('a world with bodies removed and added again keeps its proxy ids and continues identically', () => {
    const { world } = richScene(3);
    for (let s = 0; s < 30; s += 1) world.step(DT);
    const gone = [world.bodies[6]!, world.bodies[7]!];
    for (const body of gone) world.removeBody(body);
    world.step(DT);
    const restored = restoreWorld(snapshotWorld(world));
    // The removed bodies go back into both worlds: they must get the same (reused) proxy ids.
    for (const body of gone) {
      const ids = body.proxyId;
      world.addBody(body);
      const copy = new Body(restored.D, { shape: body.shape, mass: body.mass, material: body.material });
      copy.storage.set(
        body.storage.subarray(body.storageOffset, body.storageOffset + Body.recordLength(world.D)),
        copy.storageOffset,
      );
      restored.addBody(copy);
      expect(ids).toBe(-1);
      expect(copy.proxyId).toBe(body.proxyId);
    }
    expect(gone[0]!.proxyId).not.toBe(gone[1]!.proxyId);
    expectSameContinuation(world, restored, 300, 'after re-adding');
  });
});

describe('snapshot between commands', () => {
  it('pending forces and torques, a teleport, a wake, new parameters and gravity, a query: all carried', () => {
    const { world } = richScene(4);
    for (let s = 0; s < 240; s += 1) world.step(DT);
    const D = world.D;
    const sleeper = world.bodies.find((b) => b.isSleeping && b.type === 'dynamic')!;
    expect(sleeper, 'a sleeping body').toBeDefined();
    const mover = world.bodies.find((b) => !b.isSleeping && b.type === 'dynamic')!;
    mover.applyForce([1, 5, 0, 2], [0.1, 0, 0.05, 0]);
    mover.applyTorque(Array.from({ length: D.k }, (_, p) => 0.1 * p));
    world.bodies[3]!.setPositionN([0.3, 3, 0.1, -0.2]);
    sleeper.setLinearVelocity([0, 2, 0, 0]);
    world.setParams({ iterations: 7, linearDamping: 0.05, manifoldReuseTolerance: 2e-4 });
    world.setGravity([0.5, -9, 0, 0.1]);
    castRay(world, [0, 10, 0, 0], [0, -1, 0, 0], 20);
    const restored = restoreWorld(snapshotWorld(world));
    expect(restored.params).toEqual(world.params);
    expect(Array.from(restored.gravity)).toEqual(Array.from(world.gravity));
    expect(restored.time).toBe(world.time);
    expect(restored.stepCount).toBe(world.stepCount);
    expectSameContinuation(world, restored, CONTINUE, 'after commands');
  });

  it('shapes come back with the same fields and mass properties, a mesh included', () => {
    const { world } = richScene(4);
    const restored = restoreWorld(snapshotWorld(world));
    world.bodies.forEach((body, i) => {
      const a = body.shape as unknown as Record<string, unknown>;
      const b = restored.bodies[i]!.shape as unknown as Record<string, unknown>;
      expect(Object.keys(b)).toEqual(Object.keys(a));
      for (const key of Object.keys(a)) {
        if (typeof a[key] === 'function' || key === 'colliders') continue;
        expect(b[key], `${a.kind} field ${key}`).toEqual(a[key]);
      }
      expect(b.colliders).toBe(a.colliders);
      if (body.mass > 0) {
        const ma = body.shape.massProperties(world.D, 2.5);
        const mb = restored.bodies[i]!.shape.massProperties(world.D, 2.5);
        expect(Array.from(mb.inertia)).toEqual(Array.from(ma.inertia));
        expect(mb.volume).toBe(ma.volume);
      }
    });
    // Bodies sharing a shape share it after the restore too (one shape table entry).
    expect(restored.bodies[1]!.shape).toBe(restored.bodies[2]!.shape);
  });
});

describe('the last joint of a world removed or broken', () => {
  for (const how of ['removed', 'broken'] as const) {
    it(`${how}: the world steps on (it used to hang when removed) and its restored copy matches it`, () => {
      const world = new World({ dimensions: 3, gravity: gravity(3), params: { allowSleep: false } });
      const D = world.D;
      world.addBody(new Body(D, { shape: HalfSpace(D, axis(3, 1), 0), mass: 0 }));
      const boxes = [0, 1, 2].map((i) =>
        world.addBody(new Body(D, { shape: HyperBox(D, [0.3, 0.3, 0.3]), mass: 1, position: [2 * i, 0.3, 0] })),
      );
      const rod = world.addBody(new Body(D, { shape: HyperBox(D, [0.4, 0.05, 0.05]), mass: 1, position: [0, 4, 0] }));
      const joint = world.addConstraint(
        new PointJoint(boxes[2]!, rod, [0, 0, 0], [0, -3.7, 0], how === 'broken' ? { breakForce: 5 } : {}),
      );
      for (let s = 0; s < 30; s += 1) world.step(DT);
      if (how === 'removed') world.removeConstraint(joint);
      else runUntil(world, () => joint.broken, 100);
      expect(world.constraints.length).toBe(0);
      const restored = restoreWorld(snapshotWorld(world));
      expectSameContinuation(world, restored, 120, `last joint ${how}`);
      expect(rod.x[1], 'the rod fell to the ground').toBeLessThan(0.5);
    });
  }
});

describe('snapshot at every step of a bounce', () => {
  it('a ball bouncing on the ground (restitution 0.9, speculative contacts): every moment continues identically', () => {
    const world = new World({ dimensions: 3, gravity: gravity(3), params: { allowSleep: true } });
    const D = world.D;
    world.addBody(new Body(D, { shape: HalfSpace(D, axis(3, 1), 0), mass: 0, material: { restitution: 0.9 } }));
    world.addBody(
      new Body(D, {
        shape: HyperSphere(D, 0.2),
        mass: 1,
        position: [0, 1.5, 0],
        velocity: [0.3, -6, 0],
        material: { restitution: 0.9, friction: 0.4 },
        angularVelocity: [0, 2, 1],
      }),
    );
    world.addBody(
      new Body(D, {
        shape: HyperBox(D, [0.2, 0.2, 0.2]),
        mass: 1,
        position: [1.5, 1.2, 0],
        velocity: [0, -8, 0],
        material: { restitution: 0.7 },
      }),
    );
    const AHEAD = 3;
    const states: Float64Array[] = [];
    const snaps: Uint8Array[] = [];
    for (let s = 0; s < 150; s += 1) {
      snaps.push(snapshotWorld(world));
      states.push(stateOf(world));
      world.step(DT);
    }
    states.push(stateOf(world));
    let bounces = 0;
    for (let s = 0; s + AHEAD < states.length; s += 1) {
      const restored = restoreWorld(snaps[s]!);
      for (let i = 0; i < AHEAD; i += 1) restored.step(DT);
      const d = firstDifference(stateOf(restored), states[s + AHEAD]!);
      if (d >= 0) expect.fail(`restored at step ${s}: differs ${AHEAD} steps later at Float64 ${d}`);
      const before = states[s]!;
      const after = states[s + 1]!;
      // The ball is body 1: its record starts after body 0's (record + 2 numbers); v_1 follows x (3) and R (4).
      const vy = Body.recordLength(D) + 2 + 3 + 4 + 1;
      if (before[vy]! < 0 && after[vy]! > 0) bounces += 1;
    }
    expect(bounces, 'the ball bounced').toBeGreaterThanOrEqual(2);
  });
});

/**
 * The fields of every object a step reads, as the snapshot code knows them: saved, rebuilt by the
 * world's own calls on restore (list order, counts, owners), derived or constant, or scratch of
 * one sub-step. A field added to one of these classes fails this test: if a later step reads
 * it, save it in packages/engine/src/snapshot/ (and check the continuation tests); then list it.
 */
const KNOWN_FIELDS: Record<string, readonly string[]> = {
  Body: [
    'id',
    'name',
    'D',
    'shape',
    'materialValue',
    'groupBits',
    'maskBits',
    'sensorFlag',
    'motion',
    'massValue',
    'invMass',
    'inertia',
    'invInertia',
    'comOffset',
    'storage',
    'storageOffset',
    'hasTorque',
    'owner',
    'proxyId',
    'pose',
    'sleeping',
    'sleepTimer',
    'poseDirty',
    'worldIndex',
    'solverSlot',
    'jointPeers',
    'jointCount',
    'listeners',
    'boundingRadius',
    'views',
    // derived: whether inertia and invInertia are shared with bodies of the same shape and mass (a restored body owns its own)
    'ownsInertia',
  ],
  World: [
    'D',
    'n',
    'currentParams',
    'gravityValue',
    'bodyList',
    'bodyView',
    'stepState',
    'scratch',
    'constants',
    'clock',
    'broadphase',
    'bodyOfProxy',
    'proxyTables',
    'partProxies',
    'narrowScratch',
    'contacts',
    'solverBodies',
    'solver',
    'islands',
    'jointList',
    'jointView',
    'jointSolver',
    // derived: the joint bookkeeping, brought by the first joint added
    'jointOps',
    'brokenJoints',
    'jointOwner',
    'reach',
    // scratch, and a flag set again as the restored bodies get their proxies
    'lazyPose',
    'lazyPoses',
    'boundsStale',
    'events',
    'collisionEvent',
    'filterFn',
    'setSleeping',
    'owner',
    'stepParams',
    'solverPasses',
    'holes',
    // derived: the awake set is rebuilt from the bodies' flags after a restore
    'awake',
    'wakeOther',
  ],
  ContactSet: [
    'n',
    'pointCapacity',
    'order',
    'count',
    'keys',
    'bodyA',
    'bodyB',
    'shapeA',
    'shapeB',
    'poseA',
    'poseB',
    'partA',
    'partB',
    'proxies',
    'manifolds',
    'normalImpulse',
    'approachSpeed',
    'patchTangent',
    'patchTwist',
    'k',
    'friction',
    'restitution',
    'flags',
    'capacity',
    'freeSlots',
    'freeCount',
    'orderNext',
    'oldIds',
    'oldNormal',
    'oldApproach',
    'oldPoints',
    'oldTaken',
    'newMatched',
    'cache',
    'reuseNumbers',
    // derived: gathered each sub-step; the contact lists are rebuilt after takeSlots
    'active',
    'activeCount',
    'gathered',
    'links',
    'orderHoles',
    'solverSet',
  ],
  ManifoldCache: ['n', 'P', 'valid', 'data', 'S', 'NO', 'LO', 'now', 'world'],
  // The root World's cache: ManifoldCache with the 4D reuse written out, no field of its own.
  ManifoldCacheND: ['n', 'P', 'valid', 'data', 'S', 'NO', 'LO', 'now', 'world'],
  TreeBroadphase: [
    'n',
    'margin',
    'pairs',
    'pairCount',
    'addedPairs',
    'addedCount',
    'removedPairs',
    'removedCount',
    'stats',
    'capacity',
    'flags',
    'tightMin',
    'tightMax',
    'fatMin',
    'fatMax',
    'planeNormal',
    'planeOffset',
    'highWater',
    'moved',
    'movedCount',
    // derived: set by a wake, a sleep or a restore
    'reportStale',
    'halfSpaces',
    'halfSpaceCount',
    'freeIds',
    'freeCount',
    'liveCount',
    'keys',
    'keyCount',
    'keysNext',
    'cand',
    'candCount',
    'dropped',
    'droppedCount',
    'qMin',
    'qMax',
    'rayO',
    'rayD',
    'shift',
    'incremental',
    // the tree and the changes waiting for it: rebuilt from the fat boxes by a restore
    'boxTree',
    'leafOf',
    'waiting',
    'pending',
    'pendingCount',
    'doomed',
    'doomedCount',
    'selfPairs',
  ],
  ContactEvents: [
    'n',
    'beginCount',
    'beginA',
    'beginB',
    'beginPoint',
    'beginNormal',
    'beginImpulse',
    'beginPartA',
    'beginPartB',
    'endCount',
    'endA',
    'endB',
    'endPartA',
    'endPartB',
    'laterA',
    'laterB',
    'laterPartA',
    'laterPartB',
    'laterCount',
  ],
  PointJoint: ['id', 'D', 'a', 'b', 'anchorA', 'anchorB', 'state', 'lambda', 'owner', 'brokenFlag', 'collide', 'listeners'],
  DistanceJoint: [
    'id',
    'D',
    'a',
    'b',
    'anchorA',
    'anchorB',
    'state',
    'lambda',
    'owner',
    'brokenFlag',
    'collide',
    'listeners',
    'modeIndex',
  ],
  FixedJoint: [
    'id',
    'D',
    'a',
    'b',
    'anchorA',
    'anchorB',
    'state',
    'lambda',
    'owner',
    'brokenFlag',
    'collide',
    'listeners',
    'frameA',
    'frameB',
    'planes',
  ],
  HingeJoint: [
    'id',
    'D',
    'a',
    'b',
    'anchorA',
    'anchorB',
    'state',
    'lambda',
    'owner',
    'brokenFlag',
    'collide',
    'listeners',
    'frameA',
    'frameB',
    'planeValue',
  ],
  SubspaceJoint: [
    'id',
    'D',
    'a',
    'b',
    'anchorA',
    'anchorB',
    'state',
    'lambda',
    'owner',
    'brokenFlag',
    'collide',
    'listeners',
    'axes',
    'planes',
    'world1',
    'frameA',
    'frameB',
  ],
};

describe('the snapshot code knows every field', () => {
  it('no class a step reads has a field the snapshot code has not been told about', () => {
    const world = new World({ dimensions: 3 });
    const D = world.D;
    const a = world.addBody(new Body(D, { shape: HyperBox(D, [1, 1, 1]), mass: 1 }));
    const b = world.addBody(new Body(D, { shape: HyperBox(D, [1, 1, 1]), mass: 1, position: [0, 3, 0] }));
    const parts = worldParts(world);
    const zero = [0, 0, 0];
    const objects: [string, object][] = [
      ['Body', a],
      ['World', world],
      ['ContactSet', parts.contacts],
      ['ManifoldCacheND', parts.contacts.manifoldCache],
      ['TreeBroadphase', parts.broadphase],
      ['ContactEvents', parts.events],
      ['PointJoint', new PointJoint(a, b, zero, zero)],
      ['DistanceJoint', new DistanceJoint(a, b, zero, zero)],
      ['FixedJoint', new FixedJoint(a, b, zero, zero)],
      ['HingeJoint', new HingeJoint(a, b, zero, zero)],
      ['SubspaceJoint', new SubspaceJoint(a, b, { lockAxes: [0] })],
    ];
    for (const [name, object] of objects) {
      expect(object.constructor.name).toBe(name);
      const known = new Set(KNOWN_FIELDS[name]);
      const keys = Object.keys(object);
      const added = keys.filter((k) => !known.has(k));
      const removed = [...known].filter((k) => !keys.includes(k));
      expect({ name, added, removed }, `${name}: save new fields in packages/engine/src/snapshot/, then list them here`).toEqual({
        name,
        added: [],
        removed: [],
      });
    }
  });
});

describe('restore refuses bad bytes, naming the argument', () => {
  const { world } = richScene(3);
  world.step(DT);
  const good = snapshotWorld(world);

  it('accepts the good bytes, also as a view into a larger buffer at any alignment', () => {
    for (const offset of [8, 1, 2, 3]) {
      const big = new Uint8Array(good.length + 16);
      big.set(good, offset);
      const restored = restoreWorld(big.subarray(offset, offset + good.length));
      expectSameBytes(snapshotWorld(restored), good, `restored from a view at offset ${offset}`);
    }
  });

  it('TypeError for a value that is not a Uint8Array', () => {
    for (const bad of [null, undefined, 'bytes', [1, 2, 3], good.buffer, new Float64Array(4)]) {
      expect(() => restoreWorld(bad as unknown as Uint8Array)).toThrow(TypeError);
      expect(() => restoreWorld(bad as unknown as Uint8Array)).toThrow(/'bytes'/);
    }
  });

  it('RangeError for a truncated buffer, at any length', () => {
    for (const length of [0, 3, 15, 16, 100, good.length >> 1, good.length - 1]) {
      expect(() => restoreWorld(good.slice(0, length)), `length ${length}`).toThrow(RangeError);
      expect(() => restoreWorld(good.slice(0, length)), `length ${length}`).toThrow(/'bytes' is truncated/);
    }
  });

  it('RangeError for a foreign buffer, a damaged one, extra bytes and another version', () => {
    const foreign = new Uint8Array(256).map((_, i) => (i * 37) & 255);
    expect(() => restoreWorld(foreign)).toThrow(/'bytes' is not a PhysiN world snapshot/);
    const damaged = good.slice();
    damaged[good.length >> 1] ^= 1;
    expect(() => restoreWorld(damaged)).toThrow(RangeError);
    expect(() => restoreWorld(damaged)).toThrow(/'bytes' is damaged/);
    const longer = new Uint8Array(good.length + 4);
    longer.set(good);
    expect(() => restoreWorld(longer)).toThrow(/'bytes' has 4 bytes past the end/);
    const other = good.slice();
    new DataView(other.buffer).setUint32(4, 1, true);
    expect(() => restoreWorld(other)).toThrow(RangeError);
    expect(() => restoreWorld(other)).toThrow(/'bytes' is a snapshot of format version 1; this build reads version 3/);
  });

  it('RangeError naming bytes for a well-framed snapshot whose contents are inconsistent', async () => {
    // Reframe a payload with a wrong dimension byte: the checksum passes, the contents do not.
    const { fnv1a } = await import('../packages/engine/src/snapshot/format.js');
    const bad = good.slice();
    bad[16] = 9;
    new DataView(bad.buffer).setUint32(12, fnv1a(bad, 16, bad.length), true);
    expect(() => restoreWorld(bad)).toThrow(/'bytes' is not a valid snapshot: the dimension is 9/);
    // A huge shape count fails at once (no allocation of its items): find the count after the
    // parameters, gravity, clock (time, steps, the remainder of advance) and flag, and set it to 2^25.
    const view = new DataView(good.buffer);
    let at = 17;
    const params = view.getUint32(at, true);
    at += 4;
    for (let i = 0; i < params; i += 1) {
      at += 4 + view.getUint32(at, true);
      at += view.getUint8(at) === 1 ? 2 : 9;
    }
    at += 3 * 8 + 8 + 8 + 8 + 1;
    expect(view.getUint32(at, true), 'the shape count').toBe(new Set(world.bodies.map((b) => b.shape)).size);
    const huge = good.slice();
    new DataView(huge.buffer).setUint32(at, 1 << 25, true);
    new DataView(huge.buffer).setUint32(12, fnv1a(huge, 16, huge.length), true);
    expect(() => restoreWorld(huge)).toThrow(/'bytes' is truncated: the shape count is 33554432/);
  });
});

describe('snapshot refuses what it cannot rebuild', () => {
  it('a shape kind it does not know is named', () => {
    const world = new World({ dimensions: 3 });
    const D = world.D;
    const box = HyperBox(D, [0.5, 0.5, 0.5]);
    const body = world.addBody(new Body(D, { shape: box, mass: 1 }));
    // a kind no factory registered (the world itself would not place it)
    (body as unknown as { shape: unknown }).shape = { ...box, kind: 'cone' };
    expect(() => snapshotWorld(world)).toThrow(/shape of kind 'cone'/);
  });

  it('a joint class it does not know is named (a subclass would come back as its base class)', () => {
    const world = new World({ dimensions: 3 });
    const D = world.D;
    const a = world.addBody(new Body(D, { shape: HyperSphere(D, 0.5), mass: 1 }));
    class TetherJoint extends PointJoint {}
    world.addConstraint(new TetherJoint(a, null, [0, 0, 0], [0, 1, 0]));
    expect(() => snapshotWorld(world)).toThrow(/a joint of type TetherJoint is not supported/);
  });
});
