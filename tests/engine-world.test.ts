/**
 * World: the specification's Node example, static and kinematic bodies, adding and removing bodies, the
 * argument checks (the world is left exactly as it was), and the non-finite policy.
 */
import { describe, expect, it } from 'vitest';
import { Body, dims, HalfSpace, HyperBox, HyperSphere, HyperTorus, NonFiniteStateError, World } from '@physin/engine';
import type { Dims } from '@physin/engine';
import { rotorApplyBivectorInverse, rotorExp, rotorFromPlane, rotorMul } from '@physin/algebra';
import { randomArray, seeded } from './support/random.js';

/** Every number of the world's observable state: each body's x, R, v, L, w, force, torque; gravity; params. */
function snapshot(world: World): string {
  const bodies = world.bodies.map((b) => ({
    id: b.id,
    type: b.type,
    mass: b.mass,
    state: Array.from(b.storage.subarray(b.storageOffset, b.storageOffset + Body.recordLength(b.D)), (x) =>
      Object.is(x, -0) ? '-0' : x,
    ),
  }));
  return JSON.stringify({
    bodies,
    gravity: Array.from(world.gravity),
    params: world.params,
    time: world.time,
    steps: world.stepCount,
  });
}

function spinningWorld(n: number, count: number): World {
  const D = dims(n);
  const rand = seeded(500 + n);
  const gravity = new Array(n).fill(0);
  gravity[1] = -9.81;
  const world = new World({ dimensions: n, gravity });
  for (let b = 0; b < count; b += 1) {
    const shape = b % 2 === 0 ? HyperBox(D, Array.from(randomArray(rand, n, 0.2, 1))) : HyperSphere(D, 0.4);
    world.addBody(
      new Body(D, {
        shape,
        mass: 1 + b,
        position: randomArray(rand, n, -5, 5),
        velocity: randomArray(rand, n),
        angularVelocity: randomArray(rand, D.k, -3, 3),
        name: `b${b}`,
      }),
    );
  }
  return world;
}

describe("the specification's section 11 example (Node, no three.js)", () => {
  it('runs 120 steps; the box lands on the half-space and rests there: y = 0.5 − penetration (≤ penetrationSlop + 1e-3), no sideways motion (< 1e-4), asleep by 2 s', () => {
    // The example as the specification gives it, unchanged but for the assertions.
    const D = dims(4);
    const world = new World({ dimensions: 4, gravity: [0, -9.81, 0, 0] });
    world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0, 0], 0), mass: 0 }));
    const body = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5, 0.5]), mass: 1, position: [0, 3, 0, 0] });
    world.addBody(body);
    // Free fall until the first contact: the closed form of semi-implicit Euler, exactly.
    const h = 1 / 60;
    for (let i = 1; i <= 30; i += 1) {
      world.step(1 / 60);
      const y = 3 - (9.81 * h * h * i * (i + 1)) / 2;
      expect(Math.abs(body.x[1]! - y)).toBeLessThan(1e-12);
    }
    for (let i = 30; i < 120; i += 1) world.step(1 / 60);
    const slop = world.params.penetrationSlop;
    expect(body.x[1]!).toBeLessThanOrEqual(0.5 + 1e-3);
    expect(body.x[1]!).toBeGreaterThan(0.5 - slop - 1e-3);
    for (const i of [0, 2, 3]) expect(Math.abs(body.x[i]!)).toBeLessThan(1e-4);
    expect(body.isSleeping).toBe(true);
    expect(body.kineticEnergy()).toBe(0);
    expect(world.time).toBeCloseTo(2, 12);
    expect(world.stepCount).toBe(120);
  });
});

describe('static and kinematic bodies', () => {
  for (const n of [2, 3, 4, 5, 6]) {
    it(`n = ${n}: under gravity a static body does not move (bit-exact); a kinematic body moves by x0 + v t and exp(-t ω/2) R0 (1e-12)`, () => {
      const D = dims(n);
      const rand = seeded(700 + n);
      const gravity = randomArray(rand, n, -10, 10);
      const world = new World({ dimensions: n, gravity });
      const x0 = randomArray(rand, n, -2, 2);
      const R0 = rotorFromPlane(D, new Float64Array(D.r), 0, n - 1, 0.8);
      const still = world.addBody(new Body(D, { shape: HyperBox(D, new Array(n).fill(0.5)), mass: 0, position: x0, rotor: R0 }));
      const v = randomArray(rand, n, -2, 2);
      const omega = randomArray(rand, D.k, -1.5, 1.5);
      const kin = world.addBody(
        new Body(D, {
          shape: HyperBox(D, Array.from(randomArray(rand, n, 0.3, 1))),
          type: 'kinematic',
          mass: 2,
          position: x0,
          rotor: R0,
          velocity: v,
          angularVelocity: omega,
        }),
      );
      kin.applyCentralForce(new Array(n).fill(100)); // ignored
      const stillState = Float64Array.from(still.stateView);
      const h = 1 / 60;
      const N = 180;
      for (let s = 0; s < N; s += 1) world.step(h);
      expect(Array.from(still.stateView)).toEqual(Array.from(stillState));
      const t = N * h;
      for (let i = 0; i < n; i += 1) expect(Math.abs(kin.x[i]! - (x0[i]! + v[i]! * t))).toBeLessThan(1e-12);
      expect(Array.from(kin.v)).toEqual(Array.from(v));
      expect(Array.from(kin.w)).toEqual(Array.from(omega));
      const expected = rotorMul(D, new Float64Array(D.r), rotorExp(D, new Float64Array(D.r), omega, t), R0);
      for (let a = 0; a < D.r; a += 1) expect(Math.abs(kin.R[a]! - expected[a]!)).toBeLessThan(1e-12);
      // Its L follows as I_world ω at the new orientation.
      const Lb = rotorApplyBivectorInverse(D, new Float64Array(D.k), kin.R, kin.L);
      const wb = rotorApplyBivectorInverse(D, new Float64Array(D.k), kin.R, omega);
      for (let p = 0; p < D.k; p += 1) expect(Math.abs(Lb[p]! - kin.inertia[p]! * wb[p]!)).toBeLessThan(1e-12);
    });
  }
});

describe('bodies in the world', () => {
  it('addBody / removeBody keep the order; the list is frozen; a removed body can join another world', () => {
    const D = dims(3);
    const a = new World({ dimensions: 3 });
    const b = new World({ dimensions: 3 });
    const bodies = [0, 1, 2].map(() => new Body(D, { shape: HyperSphere(D, 1) }));
    for (const body of bodies) a.addBody(body);
    expect(a.bodies).toEqual(bodies);
    expect(Object.isFrozen(a.bodies)).toBe(true);
    a.removeBody(bodies[1]!);
    expect(a.bodies).toEqual([bodies[0], bodies[2]]);
    b.addBody(bodies[1]!);
    expect(b.bodies).toEqual([bodies[1]]);
  });

  it('refuses a body added twice or to two worlds, a body of another n, a non-body, and removing a body not there', () => {
    const D = dims(3);
    const world = new World({ dimensions: 3 });
    const other = new World({ dimensions: 3 });
    const body = world.addBody(new Body(D, { shape: HyperSphere(D, 1) }));
    expect(() => world.addBody(body)).toThrow(/already in this world/);
    expect(() => other.addBody(body)).toThrow(/another world/);
    expect(() => world.addBody(new Body(dims(4), { shape: HyperSphere(dims(4), 1) }))).toThrow(/n = 4/);
    expect(() => world.addBody({} as Body)).toThrow(TypeError);
    expect(() => other.removeBody(body)).toThrow(/not in this world/);
    expect(() => world.removeBody(null as unknown as Body)).toThrow(TypeError);
  });

  it('new World checks its options', () => {
    expect(() => new World({ dimensions: 1 })).toThrow(RangeError);
    expect(() => new World({ dimensions: 9 })).toThrow(/'dimensions'/);
    expect(() => new World({ dimensions: 3.5 })).toThrow(RangeError);
    expect(() => new World({ dimensions: '3' as never })).toThrow(TypeError);
    expect(() => new World({ dimensions: 3, gravity: [0, -9.81] })).toThrow(/'gravity'/);
    expect(() => new World({ dimensions: 3, gravity: [0, NaN, 0] })).toThrow(RangeError);
    expect(() => new World({ dimensions: 3, gravty: [0, 1, 0] } as never)).toThrow(/'gravty'/);
  });

  it('step() without an argument uses params.fixedTimeStep; damping divides v and L by (1 + h c) per step', () => {
    const D = dims(3);
    const world = new World({ dimensions: 3, params: { fixedTimeStep: 1 / 100, linearDamping: 0.5, angularDamping: 2 } });
    const body = world.addBody(
      new Body(D, { shape: HyperBox(D, [1, 0.5, 0.2]), velocity: [1, 0, 0], angularVelocity: [0, 0, 1] }),
    );
    const L0 = Float64Array.from(body.L);
    for (let s = 0; s < 50; s += 1) world.step();
    expect(world.time).toBeCloseTo(0.5, 14);
    expect(Math.abs(body.v[0]! - (1 / (1 + 0.01 * 0.5)) ** 50)).toBeLessThan(1e-14);
    for (let p = 0; p < 3; p += 1) expect(Math.abs(body.L[p]! - L0[p]! * (1 / (1 + 0.01 * 2)) ** 50)).toBeLessThan(1e-14);
  });
});

describe('bad input leaves the world exactly as it was', () => {
  const D = dims(4);
  const calls: [string, (w: World, b: Body) => unknown, 'TypeError' | 'RangeError', RegExp][] = [
    ['step(0)', (w) => w.step(0), 'RangeError', /'dt'/],
    ['step(-1/60)', (w) => w.step(-1 / 60), 'RangeError', /'dt'/],
    ['step(NaN)', (w) => w.step(NaN), 'RangeError', /'dt'/],
    ['step(Infinity)', (w) => w.step(Infinity), 'RangeError', /'dt'/],
    ["step('1/60')", (w) => w.step('1/60' as never), 'TypeError', /'dt'/],
    ['setGravity of length 3', (w) => w.setGravity([0, -9.81, 0]), 'TypeError', /'g'/],
    ['setGravity with NaN', (w) => w.setGravity([0, NaN, 0, 0]), 'RangeError', /'g'/],
    ['setParams with one bad entry', (w) => w.setParams({ iterations: 4, rotorTolerance: -1 }), 'RangeError', /'rotorTolerance'/],
    ['setParams with an unknown name', (w) => w.setParams({ iterations: 4, substeps: 2 } as never), 'RangeError', /'substeps'/],
    ['addBody twice', (w, b) => w.addBody(b), 'RangeError', /'body'/],
    ['addBody of another n', (w) => w.addBody(new Body(dims(3), { shape: HyperSphere(dims(3), 1) })), 'RangeError', /'body'/],
    ['removeBody not in the world', (w) => w.removeBody(new Body(D, { shape: HyperSphere(D, 1) })), 'RangeError', /'body'/],
    ['setLinearVelocity of length 3', (_w, b) => b.setLinearVelocity([1, 2, 3]), 'TypeError', /'v'/],
    ['setAngularVelocity with Infinity', (_w, b) => b.setAngularVelocity([0, 0, 0, 0, 0, Infinity]), 'RangeError', /'w'/],
    ['setPositionN with NaN', (_w, b) => b.setPositionN([0, NaN, 0, 0]), 'RangeError', /'p'/],
    ['rotateInPlane(2, 2, 1)', (_w, b) => b.rotateInPlane(2, 2, 1), 'RangeError', /'i' and 'j'/],
    ['rotateInPlane(0, 7, 1)', (_w, b) => b.rotateInPlane(0, 7, 1), 'RangeError', /'j'/],
    ['applyImpulse with a short arm', (_w, b) => b.applyImpulse([1, 0, 0, 0], [1, 0]), 'TypeError', /'r'/],
    ['applyForce with NaN', (_w, b) => b.applyForce([NaN, 0, 0, 0], [0, 0, 0, 0]), 'RangeError', /'f'/],
    ['applyTorque of length 4', (_w, b) => b.applyTorque([1, 2, 3, 4]), 'TypeError', /'t'/],
    ['applyCentralImpulse with Infinity', (_w, b) => b.applyCentralImpulse([Infinity, 0, 0, 0]), 'RangeError', /'j'/],
    ['setMass(-2)', (_w, b) => b.setMass(-2), 'RangeError', /'m'/],
    [
      'setAngularVelocity of length 4 (a vector, not a bivector)',
      (_w, b) => b.setAngularVelocity([0, 0, 1, 0]),
      'TypeError',
      /'w'/,
    ],
    ['applyForce with an arm of length 5', (_w, b) => b.applyForce([1, 0, 0, 0], [0, 0, 0, 0, 1]), 'TypeError', /'r'/],
    [
      'addBody of a body that belongs to another world',
      (w) => {
        const other = new World({ dimensions: 4 });
        w.addBody(other.addBody(new Body(D, { shape: HyperSphere(D, 1) })));
      },
      'RangeError',
      /another world/,
    ],
    // Building a body or a shape with bad arguments throws before anything reaches the world.
    ['new Body with a negative mass', () => new Body(D, { shape: HyperSphere(D, 1), mass: -1 }), 'RangeError', /'mass'/],
    [
      'new Body with a position of length 3',
      () => new Body(D, { shape: HyperSphere(D, 1), position: [0, 1, 0] }),
      'TypeError',
      /'position'/,
    ],
    [
      'new Body with a non-finite velocity',
      () => new Body(D, { shape: HyperSphere(D, 1), velocity: [0, NaN, 0, 0] }),
      'RangeError',
      /'velocity'/,
    ],
    ['new Body with a 3D box in a 4D world', () => new Body(D, { shape: HyperBox(dims(3), [1, 1, 1]) }), 'RangeError', /'shape'/],
    ['HyperBox with a negative half-extent', () => HyperBox(D, [0.5, -0.5, 0.5, 0.5]), 'RangeError', /'halfExtents'/],
    ['HyperTorus with minor radius >= major radius', () => HyperTorus(D, 1, 1, 0), 'RangeError', /'minorRadius'/],
    ['HyperTorus with a plane axis out of range', () => HyperTorus(D, 2, 0.5, [0, 4]), 'RangeError', /'plane\[1\]' must/],
  ];
  for (const [what, call, kind, message] of calls) {
    it(`${what}: ${kind} naming the argument; snapshot of every body, gravity and params unchanged`, () => {
      const world = spinningWorld(4, 4);
      const body = world.bodies[1]!;
      body.applyForce([1, 2, 3, 4], [0.1, 0, 0, 0]); // pending forces are part of the snapshot
      for (let s = 0; s < 3; s += 1) world.step(1 / 60);
      body.applyForce([1, 2, 3, 4], [0.1, 0, 0, 0]);
      const before = snapshot(world);
      let err: Error | null = null;
      try {
        call(world, body);
      } catch (e) {
        err = e as Error;
      }
      expect(err).not.toBeNull();
      expect(err!.constructor.name).toBe(kind);
      expect(err!.message).toMatch(message);
      expect(snapshot(world)).toBe(before);
    });
  }
});

describe('non-finite state: caught, named, undone', () => {
  function failing(n: number, D: Dims = dims(n)) {
    const world = spinningWorld(n, 5);
    const bad = world.bodies[2]!;
    return { world, bad, D };
  }

  it('a position that overflows: NonFiniteStateError names the body and field; every body is back to its state before the step', () => {
    const { world, bad } = failing(4);
    world.step(1 / 60);
    // Values no call accepts (Body.limits): written into the fields directly, as a bug would
    // (setPositionN first, so the world reads the moved pose).
    bad.setPositionN([1e12, 0, 0, 0]);
    bad.x[0] = 1.79e308;
    bad.v[0] = 1e308;
    const before = snapshot(world);
    let err: unknown = null;
    try {
      world.step(1 / 60);
    } catch (e) {
      err = e;
    }
    expect(err).toBeInstanceOf(NonFiniteStateError);
    const e = err as NonFiniteStateError;
    expect(e.body).toBe(bad);
    expect(e.field).toBe('x');
    expect(e.message).toContain(`body ${bad.id} ('b2')`);
    expect(e.message).toContain('non-finite x');
    expect(snapshot(world)).toBe(before);
    // Remove the body and the world carries on; the others were never touched by it.
    world.removeBody(bad);
    expect(() => world.step(1 / 60)).not.toThrow();
    for (const b of world.bodies) for (const x of b.stateView) expect(Number.isFinite(x)).toBe(true);
  });

  it('a torque whose impulse overflows L is reported as L; in sub-step 2 of 3 the earlier sub-steps are undone too', () => {
    const { world, bad } = failing(3);
    world.setParams({ subSteps: 3 });
    // A torque of 1.7e308 is refused at the call (Body.limits: engine-input-limits); written into
    // the field directly, it is finite, but over a sub-step of 20 s its impulse overflows L in
    // sub-step 1.
    expect(() => bad.applyTorque([1.7e308, 0, 0])).toThrow(RangeError);
    bad.torque[0] = 1.7e308;
    bad.hasTorque = true;
    const before = snapshot(world);
    expect(() => world.step(60)).toThrow(NonFiniteStateError);
    expect(snapshot(world)).toBe(before);
    let err: NonFiniteStateError | null = null;
    try {
      world.step(60);
    } catch (e) {
      err = e as NonFiniteStateError;
    }
    expect(err!.field).toBe('L');
    expect(err!.subStep).toBe(0);
    // A velocity that only overflows in the second sub-step.
    const { world: w2, bad: b2 } = failing(3);
    w2.setParams({ subSteps: 3 });
    // h = 0.5: x = 0.5e308 → 1.3e308 (sub-step 1) → overflow (sub-step 2).
    b2.setPositionN([1e12, 0, 0]);
    b2.x[0] = 0.5e308;
    b2.v[0] = 1.6e308;
    const before2 = snapshot(w2);
    try {
      w2.step(1.5);
    } catch (e) {
      err = e as NonFiniteStateError;
    }
    expect(err!.body).toBe(b2);
    expect(err!.subStep).toBe(1);
    expect(snapshot(w2)).toBe(before2);
  });
});
