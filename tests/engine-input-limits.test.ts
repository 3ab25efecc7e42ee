/**
 * Issue 17, point 9: every public entry refuses a value that would make the state non-finite,
 * before anything changes. The bounds are `Body.limits` (docs/engine.md, "Limits on input").
 *
 * For each entry, in n = 2, 3, 4 and 5: the value just beyond each bound (the next double) throws
 * a TypeError/RangeError whose message names the argument and the bound, and the body or world is
 * unchanged bit for bit (`snapshotWorld` bytes, or every field of a loose body); the value at the
 * bound is accepted, and 10 steps of a world holding it stay finite.
 *
 * Then seeded fuzzing: 2,000 random calls with extreme values on a small 3D and 4D world; after
 * each call either it threw (TypeError/RangeError) and the world's snapshot bytes are unchanged, or
 * 3 more steps run without error and every number of every body is finite.
 */
import { describe, expect, it } from 'vitest';
import {
  Body,
  ConvexMesh,
  DistanceJoint,
  HalfSpace,
  HingeJoint,
  HyperBox,
  HyperSphere,
  HyperTorus,
  PointJoint,
  World,
  dims,
  snapshotWorld,
} from '@physin/engine';
import type { Dims, Joint, Shape } from '@physin/engine';

const LIM = Body.limits;
const NS = [2, 3, 4, 5];

/** The next double above x (toward +∞). */
function up(x: number): number {
  const f = new Float64Array([x]);
  const b = new BigInt64Array(f.buffer);
  if (x === 0) return Number.MIN_VALUE;
  b[0] = x > 0 ? b[0]! + 1n : b[0]! - 1n;
  return f[0]!;
}
/** The next double below x (toward −∞). */
function down(x: number): number {
  return -up(-x);
}

function vec(n: number, i: number, value: number, fill = 0): number[] {
  const v = new Array<number>(n).fill(fill);
  v[i] = value;
  return v;
}

/** Every number a body holds, as bits (so -0 and NaN compare exactly). */
function bodyBits(b: Body): string {
  const nums = [
    ...b.x,
    ...b.R,
    ...b.v,
    ...b.L,
    ...b.w,
    ...b.force,
    ...b.torque,
    ...b.inertia,
    ...b.invInertia,
    b.mass,
    b.invMass,
    b.hasTorque ? 1 : 0,
    b.isSleeping ? 1 : 0,
  ];
  return `${b.type} ${Buffer.from(new Float64Array(nums).buffer).toString('hex')}`;
}

function worldBytes(world: World): string {
  return Buffer.from(snapshotWorld(world)).toString('hex');
}

/** A ground (at y = 0, gravity along −y) and `body` if given. */
function worldWith(n: number, ...bodies: Body[]): World {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: vec(n, 1, -9.81) });
  world.addBody(new Body(D, { shape: HalfSpace(D, vec(n, 1, 1), 0), mass: 0 }));
  for (const b of bodies) world.addBody(b);
  return world;
}

function expectFinite(world: World): void {
  for (const b of world.bodies) {
    for (const x of [...b.stateView, ...b.force, ...b.torque]) {
      if (!Number.isFinite(x)) throw new Error(`${b.label} holds ${x}`);
    }
    expect(Number.isFinite(b.kineticEnergy())).toBe(true);
  }
}

/** 10 steps of `world` throw nothing and leave every number finite. */
function tenStepsFinite(world: World): void {
  for (let i = 0; i < 10; i += 1) world.step(1 / 60);
  expectFinite(world);
}

/** `call` throws a TypeError/RangeError matching `message`. */
function expectRefused(call: () => unknown, message: RegExp): void {
  let error: unknown = null;
  try {
    call();
  } catch (e) {
    error = e;
  }
  expect(error, `expected a refusal matching ${message}`).not.toBeNull();
  expect(error instanceof TypeError || error instanceof RangeError, String(error)).toBe(true);
  expect((error as Error).message).toMatch(message);
  expect((error as Error).message).toMatch(/Body\.limits|non-finite|must be/);
}

function box(D: Dims, a = 0.5): Shape {
  return HyperBox(D, new Array<number>(D.n).fill(a));
}

/** The cross-polytope ±s·e_i centred at c: its size (largest distance from the vertex mean) is s. */
function crossPolytope(D: Dims, s: number, c: number[] = new Array<number>(D.n).fill(0)) {
  const n = D.n;
  const vertices: number[][] = [];
  for (let i = 0; i < n; i += 1) {
    for (const sign of [1, -1]) {
      const v = [...c];
      v[i] = c[i]! + sign * s;
      vertices.push(v);
    }
  }
  const facets: number[][] = [];
  for (let mask = 0; mask < 1 << n; mask += 1) {
    const f: number[] = [];
    for (let i = 0; i < n; i += 1) f.push(2 * i + ((mask >> i) & 1));
    facets.push(f);
  }
  return ConvexMesh(D, vertices, facets);
}

describe('Body.limits: the bounds are documented numbers', () => {
  it('is frozen and keeps every derived product far from overflow', () => {
    expect(Object.isFrozen(LIM)).toBe(true);
    // what physics needs is inside: a 1e-6 kg bead, a 1e6 kg ship, a 1000 m/s bullet, a 1 cm cube, a planet
    expect(LIM.minMass).toBeLessThanOrEqual(1e-6);
    expect(LIM.maxMass).toBeGreaterThanOrEqual(1e6);
    expect(LIM.maxVelocity).toBeGreaterThanOrEqual(1000);
    expect(LIM.minLength).toBeLessThanOrEqual(0.01);
    expect(LIM.maxLength).toBeGreaterThanOrEqual(6.4e6);
    // the largest products a step forms from values within the bounds (docs/engine.md)
    const worst = [
      1 / LIM.minMass,
      1 / LIM.minInertia,
      LIM.maxInertia * LIM.maxAngularVelocity, // L
      LIM.maxInertia * LIM.maxAngularVelocity ** 2, // energy, angular
      LIM.maxMass * LIM.maxVelocity ** 2, // energy, linear
      (LIM.maxForce / LIM.minMass) * 1e3, // velocity after one step of 1000 s
      (LIM.maxTorque / LIM.minInertia) * 1e3, // ω after one step of 1000 s
      (LIM.maxTorque / LIM.minInertia) ** 2 * LIM.maxInertia * 1e6, // its energy
      LIM.maxPosition ** 2 * 8, // a squared distance in 8D
    ];
    for (const w of worst) expect(w).toBeLessThan(1e200);
  });
});

describe('each entry: at the bound accepted and stepped finite; just beyond refused, nothing changed', () => {
  for (const n of NS) {
    const D = dims(n);
    const k = D.k;

    it(`n = ${n}: new Body — mass, position, velocity, angularVelocity`, () => {
      const make = (o: Record<string, unknown>) => new Body(D, { shape: box(D), ...o } as never);
      for (const [option, value, message] of [
        ['mass', down(LIM.minMass), /option 'mass' must be 0 \(static\) or within \[1e-12, 1e12\] kg/],
        ['mass', up(LIM.maxMass), /option 'mass' must be 0 \(static\) or within \[1e-12, 1e12\] kg/],
        ['mass', 1e-300, /option 'mass'/],
        ['position', vec(n, n - 1, up(LIM.maxPosition)), /option 'position'\[\d\] must be within ±1e12 m/],
        ['position', vec(n, 0, -1e308), /option 'position'\[0\]/],
        ['velocity', vec(n, 0, down(-LIM.maxVelocity)), /option 'velocity'\[0\] must be within ±1e8 m\/s/],
        [
          'angularVelocity',
          vec(k, k - 1, up(LIM.maxAngularVelocity)),
          /option 'angularVelocity'\[\d\] must be within ±1e6 rad\/s/,
        ],
      ] as const) {
        expectRefused(() => make({ [option]: value }), message);
      }
      const bodies = [
        make({ mass: LIM.minMass, position: vec(n, 1, 2) }),
        make({ mass: LIM.maxMass, position: vec(n, 1, 4) }),
        make({ mass: 1, position: vec(n, 0, LIM.maxPosition, 0) }),
        make({ mass: 1, position: vec(n, 0, -LIM.maxPosition) }),
        make({ mass: 1, position: vec(n, 1, 6), velocity: vec(n, 0, LIM.maxVelocity) }),
        make({ mass: 1, position: vec(n, 1, 8), angularVelocity: vec(k, 0, -LIM.maxAngularVelocity) }),
        make({
          mass: LIM.minMass,
          position: vec(n, 1, 10),
          angularVelocity: new Array(k).fill(LIM.maxAngularVelocity),
          velocity: new Array(n).fill(-LIM.maxVelocity),
        }),
        make({
          type: 'kinematic',
          mass: LIM.maxMass,
          position: vec(n, 1, 12),
          velocity: vec(n, 0, LIM.maxVelocity),
          angularVelocity: vec(k, 0, LIM.maxAngularVelocity),
        }),
      ];
      tenStepsFinite(worldWith(n, ...bodies));
    });

    it(`n = ${n}: shape factories — box, ball, torus, half-space and convex mesh sizes`, () => {
      const one = new Array<number>(n).fill(1);
      expectRefused(
        () => HyperBox(D, vec(n, 0, down(LIM.minLength), 1)),
        /HyperBox: argument 'halfExtents'\[0\] must be within \[1e-9, 1e9\] m/,
      );
      expectRefused(
        () => HyperBox(D, vec(n, n - 1, up(LIM.maxLength), 1)),
        /argument 'halfExtents'\[\d\] must be within \[1e-9, 1e9\] m/,
      );
      expectRefused(() => HyperBox(D, vec(n, 0, 1e-300, 1)), /'halfExtents'\[0\]/);
      expectRefused(() => HyperBox(D, new Array(n).fill(1e200)), /'halfExtents'\[0\]/);
      expectRefused(() => HyperSphere(D, down(LIM.minLength)), /HyperSphere: argument 'radius' must be within \[1e-9, 1e9\] m/);
      expectRefused(() => HyperSphere(D, up(LIM.maxLength)), /argument 'radius'/);
      expectRefused(
        () => HyperTorus(D, 1, down(LIM.minLength), 0),
        /HyperTorus: argument 'minorRadius' must be within \[1e-9, 1e9\] m/,
      );
      expectRefused(() => HyperTorus(D, up(LIM.maxLength), 1, 0), /HyperTorus: argument 'majorRadius' must be within/);
      expectRefused(
        () => HalfSpace(D, vec(n, 1, 1), up(LIM.maxPosition)),
        /HalfSpace: argument 'offset' \/ \|normal\| must be within ±1e12 m/,
      );
      expectRefused(() => HalfSpace(D, vec(n, 1, 1e-300), 1), /HalfSpace: argument 'offset' \/ \|normal\|/);
      expectRefused(() => crossPolytope(D, down(LIM.minLength)), /ConvexMesh: the mesh's size .* must be within \[1e-9, 1e9\] m/);
      expectRefused(() => crossPolytope(D, up(LIM.maxLength)), /ConvexMesh: the mesh's size/);
      expectRefused(
        () => crossPolytope(D, 1, vec(n, 0, LIM.maxPosition)),
        /ConvexMesh: 'vertices'\[0\] coordinate 0 must be within ±1e12 m/,
      );
      expectRefused(
        () => box(D).massProperties(D, down(LIM.minMass)),
        /HyperBox\.massProperties: argument 'mass' must be within \[1e-12, 1e12\] kg/,
      );
      expectRefused(() => HyperSphere(D, 1).massProperties(D, up(LIM.maxMass)), /argument 'mass'/);
      void one;

      const shapes: Shape[] = [
        HyperBox(D, vec(n, 0, LIM.minLength, 0.5)),
        HyperBox(D, vec(n, 0, LIM.maxLength, 0.5)),
        HyperSphere(D, LIM.minLength),
        HyperSphere(D, LIM.maxLength),
        HyperTorus(D, 2 * LIM.minLength, LIM.minLength, 0),
        HyperTorus(D, LIM.maxLength, 1, 0),
        crossPolytope(D, LIM.minLength),
        crossPolytope(D, LIM.maxLength),
        crossPolytope(D, 1, vec(n, 0, LIM.maxPosition - 1)),
      ];
      expect(HalfSpace(D, vec(n, 1, 1), LIM.maxPosition).offset).toBe(LIM.maxPosition);
      // every shape at a size bound, with the smallest and the largest mass: inertia within its bounds, and it steps
      for (const mass of [LIM.minMass, 1, LIM.maxMass]) {
        const bodies = shapes.map(
          (shape, i) =>
            new Body(D, { shape, mass, position: vec(n, 1, 3 * LIM.maxLength * (i + 1)), angularVelocity: vec(k, 0, 1) }),
        );
        for (const b of bodies) {
          for (const I of b.inertia) {
            expect(I).toBeGreaterThanOrEqual(LIM.minInertia);
            expect(I).toBeLessThanOrEqual(LIM.maxInertia);
          }
        }
        tenStepsFinite(worldWith(n, ...bodies));
      }
    });

    it(`n = ${n}: a shape whose inertia would leave the bounds is refused by new Body and setMass`, () => {
      // a shape-like object with a custom massProperties (any object with kind and massProperties is accepted)
      const tiny = {
        kind: 'mesh',
        n,
        massProperties: (_: Dims, m: number) => ({
          volume: 1,
          covariance: new Float64Array(n),
          inertia: new Float64Array(k).fill(m * 1e-300),
        }),
      };
      const huge = {
        kind: 'mesh',
        n,
        massProperties: (_: Dims, m: number) => ({
          volume: 1,
          covariance: new Float64Array(n),
          inertia: new Float64Array(k).fill(m * 1e300),
        }),
      };
      expectRefused(
        () => new Body(D, { shape: tiny as never, mass: 1 }),
        /option 'shape' with option 'mass' gives principal inertia\[0\] = 1e-300 .* outside \[1e-40, 1e40\]/,
      );
      expectRefused(() => new Body(D, { shape: huge as never, mass: 1 }), /principal inertia\[0\] = 1e\+300/);
      const body = new Body(D, { shape: tiny as never, mass: 0 });
      const before = bodyBits(body);
      expectRefused(() => body.setMass(1), /Body\.setMass: argument 'm' gives principal inertia/);
      expect(bodyBits(body)).toBe(before);
    });

    it(`n = ${n}: Body setters and apply* — just beyond refused with the world unchanged bit for bit`, () => {
      const body = new Body(D, { shape: box(D), mass: 1, position: vec(n, 1, 2), name: 'probe' });
      // heavy and wide enough for the force and torque bounds to be reached within the accelerations'
      const heavy = new Body(D, { shape: box(D, 2e4), mass: LIM.maxMass, position: vec(n, 1, 1e5), name: 'heavy' });
      const world = worldWith(n, body, heavy);
      world.step(1 / 60);
      const r1 = vec(n, 0, 1);
      const cases: [() => unknown, RegExp][] = [
        [() => body.setPositionN(vec(n, 0, up(LIM.maxPosition))), /Body\.setPositionN: argument 'p'\[0\] must be within ±1e12 m/],
        [() => body.setPositionN(vec(n, n - 1, -1e308)), /argument 'p'\[\d\]/],
        [
          () => body.setLinearVelocity(vec(n, 0, up(LIM.maxVelocity))),
          /Body\.setLinearVelocity: argument 'v'\[0\] must be within ±1e8 m\/s/,
        ],
        [() => body.setLinearVelocity(vec(n, 0, 1e308)), /argument 'v'\[0\]/],
        [
          () => body.setAngularVelocity(vec(k, 0, down(-LIM.maxAngularVelocity))),
          /Body\.setAngularVelocity: argument 'w'\[0\] must be within ±1e6 rad\/s/,
        ],
        [() => body.setMass(down(LIM.minMass)), /Body\.setMass: argument 'm' must be 0 \(static\) or within \[1e-12, 1e12\] kg/],
        [() => body.setMass(1e-300), /argument 'm'/],
        [() => body.setMass(up(LIM.maxMass)), /argument 'm'/],
        [
          () => body.applyCentralImpulse(vec(n, 0, up(LIM.maxImpulse))),
          /Body\.applyCentralImpulse: argument 'j'\[0\] must be within ±1e20 N·s/,
        ],
        [
          () => body.applyCentralImpulse(vec(n, 0, 1e9)),
          /argument 'j' would make body \d+ \('probe'\)'s velocity\[0\] .*beyond ±1e8 m\/s/,
        ],
        [() => body.applyImpulse(vec(n, 0, up(LIM.maxImpulse)), r1), /Body\.applyImpulse: argument 'j'\[0\]/],
        [
          () => body.applyImpulse(vec(n, 1, 1), vec(n, 0, up(LIM.maxPosition))),
          /Body\.applyImpulse: argument 'r'\[0\] must be within ±1e12 m/,
        ],
        [
          () => body.applyImpulse(vec(n, 1, 1e7), vec(n, 0, 1)),
          /arguments 'j' and 'r' would make .*angular velocity\[0\] .*beyond ±1e6 rad\/s/,
        ],
        [
          () => body.applyCentralForce(vec(n, 0, up(LIM.maxForce))),
          /Body\.applyCentralForce: argument 'f'\[0\] must be within ±1e20 N/,
        ],
        [() => body.applyForce(vec(n, 0, up(LIM.maxForce)), r1), /Body\.applyForce: argument 'f'\[0\]/],
        [() => body.applyForce(vec(n, 1, 1), vec(n, 0, up(LIM.maxPosition))), /Body\.applyForce: argument 'r'\[0\]/],
        [
          () => body.applyTorque(vec(k, k - 1, up(LIM.maxTorque))),
          /Body\.applyTorque: argument 't'\[\d\] must be within ±1e32 N·m/,
        ],
        // a mass of 1: a force above 1e12 N gives more than the largest acceleration
        [
          () => body.applyCentralForce(vec(n, 0, up(LIM.maxAcceleration))),
          /Body\.applyCentralForce: argument 'f' would give body \d+ \('probe'\) an acceleration\[0\] .* beyond ±1e12 m\/s²/,
        ],
        [
          () => body.applyForce(vec(n, n - 1, -up(LIM.maxAcceleration)), r1),
          /Body\.applyForce: argument 'f' would give .*acceleration\[\d\]/,
        ],
        // inertia 1/6: a torque of 2e11 N·m gives 1.2e12 rad/s²
        [
          () => body.applyTorque(vec(k, 0, 2e11)),
          /Body\.applyTorque: argument 't' would give .*an angular acceleration \(I⁻¹ τ\) of 1\.2\d*e12 rad\/s², beyond ±1e12 rad\/s²/,
        ],
        [() => body.applyForce(vec(n, 1, 2e11), vec(n, 0, 1)), /arguments 'f' and 'r' would give .*angular acceleration/],
      ];
      for (const [call, message] of cases) {
        const before = worldBytes(world);
        const bits = bodyBits(body);
        expectRefused(call, message);
        expect(worldBytes(world), message.source).toBe(before);
        expect(bodyBits(body), message.source).toBe(bits);
      }
      // accumulations: a second force (or torque) at the bound takes the sum beyond it
      body.applyCentralForce(vec(n, 0, LIM.maxAcceleration)); // mass 1: exactly the largest acceleration
      expectRefused(() => body.applyCentralForce(vec(n, 0, 1e-3)), /argument 'f' would give .*acceleration\[0\]/);
      heavy.applyCentralForce(vec(n, 0, LIM.maxForce));
      const before = worldBytes(world);
      expectRefused(
        () => heavy.applyCentralForce(vec(n, 0, 1e5)),
        /argument 'f' would make body \d+ \('heavy'\)'s force\[0\] .*beyond ±1e20 N/,
      );
      expect(worldBytes(world)).toBe(before);
      // r ∧ f = 1e12 · 1e20: the torque at its bound, then any more in the same sense is refused
      heavy.applyForce(vec(n, 1, LIM.maxForce), vec(n, 0, LIM.maxPosition));
      expect(heavy.torque[0]).toBe(LIM.maxTorque);
      const withTorque = worldBytes(world);
      expectRefused(
        () => heavy.applyForce(vec(n, 1, -1e17), vec(n, 0, -1)),
        /arguments 'f' and 'r' would make .*torque\[0\] .*beyond ±1e32 N·m/,
      );
      expectRefused(() => heavy.applyTorque(vec(k, 0, 1e17)), /argument 't' would make .*torque\[0\] .*beyond ±1e32 N·m/);
      expect(worldBytes(world)).toBe(withTorque);
      tenStepsFinite(world);
    });

    it(`n = ${n}: Body setters and apply* — at the bound accepted, and 10 steps stay finite`, () => {
      const make = (y: number, mass = 1) => new Body(D, { shape: box(D), mass, position: vec(n, 1, y) });
      const bodies = Array.from({ length: 11 }, (_, i) => make(2 + 3 * i));
      const heavy = make(40, LIM.maxMass);
      const world = worldWith(n, ...bodies, heavy);
      world.step(1 / 60);
      bodies[0]!.setPositionN(vec(n, 0, LIM.maxPosition));
      bodies[1]!.setLinearVelocity(vec(n, 0, -LIM.maxVelocity));
      bodies[2]!.setAngularVelocity(new Array(k).fill(LIM.maxAngularVelocity));
      bodies[3]!.setMass(LIM.minMass);
      bodies[4]!.setMass(LIM.maxMass);
      // an impulse at the bound on the heaviest body gives it exactly the largest velocity
      heavy.applyCentralImpulse(vec(n, 0, LIM.maxImpulse));
      expect(heavy.v[0]).toBe(LIM.maxVelocity);
      heavy.applyCentralForce(vec(n, 1, LIM.maxForce)); // 1e8 m/s²
      bodies[5]!.applyCentralForce(vec(n, 0, LIM.maxAcceleration)); // mass 1: the largest acceleration
      bodies[6]!.applyTorque(vec(k, 0, LIM.maxAngularAcceleration / 6)); // inertia 1/6: the largest angular acceleration
      bodies[7]!.applyForce(vec(n, 1, 0.01), vec(n, 0, LIM.maxPosition)); // an arm at its bound
      bodies[8]!.applyImpulse(vec(n, 1, 1e5), vec(n, 0, 1)); // ω within the bound
      bodies[9]!.setMass(LIM.minMass).applyCentralForce(new Array(n).fill(0.5)).applyTorque(new Array(k).fill(1e-2));
      bodies[10]!.setPositionN(new Array(n).fill(-LIM.maxPosition)).setLinearVelocity(new Array(n).fill(-LIM.maxVelocity));
      tenStepsFinite(world);
    });

    it(`n = ${n}: joints — anchors, rest length, softness, motor`, () => {
      const a = new Body(D, { shape: box(D), mass: 1, position: vec(n, 1, 2) });
      const b = new Body(D, { shape: box(D), mass: 1, position: vec(n, 1, 4) });
      const world = worldWith(n, a, b);
      const zero = new Array<number>(n).fill(0);
      const before = worldBytes(world);
      const cases: [() => unknown, RegExp][] = [
        [
          () => new PointJoint(a, b, vec(n, 0, up(LIM.maxPosition)), zero),
          /new PointJoint: argument 'localA'\[0\] must be within ±1e12 m/,
        ],
        [() => new PointJoint(a, null, zero, vec(n, 0, -1e300)), /argument 'localB'\[0\]/],
        [
          () => new PointJoint(a, b, zero, zero, { hertz: up(LIM.maxJointStiffness) }),
          /argument 'opts\.hertz' must be within ±1e12 Hz/,
        ],
        [() => new PointJoint(a, b, zero, zero, { hertz: 5, damping: 1e300 }), /argument 'opts\.damping' must be within ±1e12/],
        [
          () => new DistanceJoint(a, b, zero, zero, { rest: up(LIM.maxPosition) }),
          /argument 'opts\.rest' must be within ±1e12 m/,
        ],
        [
          () => new HingeJoint(a, b, zero, zero, { plane: 0, motorSpeed: up(LIM.maxAngularVelocity), maxMotorTorque: 1 }),
          /argument 'opts\.motorSpeed' must be within ±1e6 rad\/s/,
        ],
        [
          () => new HingeJoint(a, b, zero, zero, { plane: 0, motorSpeed: 1, maxMotorTorque: up(LIM.maxTorque) }),
          /argument 'opts\.maxMotorTorque' must be within ±1e32 N·m/,
        ],
      ];
      for (const [call, message] of cases) {
        expectRefused(call, message);
        expect(worldBytes(world), message.source).toBe(before);
      }
      const hinge = world.addConstraint(
        new HingeJoint(a, b, vec(n, 1, 1), vec(n, 1, -1), { plane: 0, motorSpeed: 1, maxMotorTorque: 1 }),
      );
      const point = world.addConstraint(new PointJoint(a, null, zero, vec(n, 1, 2)));
      const live = worldBytes(world);
      expectRefused(
        () => hinge.setMotor(-up(LIM.maxAngularVelocity), 1),
        /HingeJoint\.setMotor: argument 'speed' must be within ±1e6 rad\/s/,
      );
      expectRefused(() => hinge.setMotor(1, up(LIM.maxTorque)), /argument 'maxTorque' must be within ±1e32 N·m/);
      expectRefused(() => point.setSoftness(up(LIM.maxJointStiffness), 1), /PointJoint\.setSoftness: argument 'hertz'/);
      expectRefused(
        () => point.setAnchors(vec(n, 0, up(LIM.maxPosition)), null),
        /PointJoint\.setAnchors: argument 'localA'\[0\]/,
      );
      expect(worldBytes(world)).toBe(live);
      // at the bounds: accepted, and a world holding each one steps finite
      hinge.setMotor(LIM.maxAngularVelocity, LIM.maxTorque);
      point.setSoftness(LIM.maxJointStiffness, LIM.maxJointStiffness);
      tenStepsFinite(world);
      const pivot = vec(n, 0, LIM.maxPosition);
      pivot[1] = 2;
      const joints: ((p: Body, q: Body) => Joint)[] = [
        (p, q) =>
          new HingeJoint(p, q, vec(n, 1, 1), vec(n, 1, -1), {
            plane: 0,
            motorSpeed: -LIM.maxAngularVelocity,
            maxMotorTorque: LIM.maxTorque,
          }),
        (p) => new PointJoint(p, null, zero, vec(n, 1, 2), { hertz: LIM.maxJointStiffness, damping: LIM.maxJointStiffness }),
        (p) => new DistanceJoint(p, null, zero, vec(n, 1, 8), { rest: LIM.maxPosition }),
        (p, q) => new DistanceJoint(p, q, vec(n, 0, -LIM.maxPosition), vec(n, 0, LIM.maxPosition)),
        // a pendulum whose arm is the largest anchor (the joint satisfied at the start)
        (p) => new PointJoint(p, null, vec(n, 0, LIM.maxPosition), pivot),
      ];
      for (const joint of joints) {
        const p = new Body(D, { shape: box(D), mass: 1, position: vec(n, 1, 2) });
        const q = new Body(D, { shape: box(D), mass: 1, position: vec(n, 1, 4) });
        const w = worldWith(n, p, q);
        w.addConstraint(joint(p, q));
        tenStepsFinite(w);
      }
    });
  }
});

/** mulberry32: a small seeded generator. */
function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const MAGNITUDES = [
  0,
  1e-300,
  1e-40,
  1e-13,
  LIM.minMass,
  LIM.minLength,
  1e-6,
  1e-3,
  0.5,
  1,
  10,
  1000,
  1e6,
  LIM.maxVelocity,
  up(LIM.maxVelocity),
  LIM.maxLength,
  LIM.maxMass,
  LIM.maxPosition,
  up(LIM.maxPosition),
  1e15,
  LIM.maxForce,
  up(LIM.maxForce),
  1e25,
  LIM.maxTorque,
  up(LIM.maxTorque),
  1e40,
  1e100,
  1e200,
  1e300,
  1e308,
  Number.MAX_VALUE,
];

describe('seeded fuzzing: 2,000 calls with extreme values either throw before changing anything or keep the world finite', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: 2,000 calls, 3 steps after each accepted one`, () => {
      const D = dims(n);
      const k = D.k;
      const random = rng(0x17_09 + n);
      const pick = <T>(list: readonly T[]): T => list[Math.floor(random() * list.length)]!;
      const extreme = (): number => (random() < 0.5 ? -1 : 1) * pick(MAGNITUDES);
      const list = (len: number): number[] => {
        const v = new Array<number>(len).fill(0);
        const count = 1 + Math.floor(random() * len);
        for (let i = 0; i < count; i += 1) v[Math.floor(random() * len)] = extreme();
        return v;
      };
      const size = (): number => pick(MAGNITUDES.filter((m) => m > 0));
      // the world is rebuilt every 100 calls: the property is about one call and the 3 steps after
      // it; a world left to run thousands of steps among extreme bodies is a solver question
      // (see the report of issue 17: contacts between bodies 1e9 m wide at 1e12 m pump energy)
      let world = worldWith(n);
      const shapes: (() => Shape)[] = [
        () => HyperBox(D, Array.from({ length: n }, size)),
        () => HyperSphere(D, size()),
        () => HyperTorus(D, size(), size(), 0),
        () => crossPolytope(D, size(), list(n)),
      ];
      const addBody = (): void => {
        const shape = pick(shapes)();
        world.addBody(
          new Body(D, {
            shape,
            mass: Math.abs(extreme()),
            position: list(n),
            velocity: list(n),
            angularVelocity: list(k),
            type: random() < 0.1 ? 'kinematic' : 'dynamic',
          }),
        );
      };
      const fresh = (): void => {
        world = worldWith(n);
        for (let i = 0; i < 3; i += 1) world.addBody(new Body(D, { shape: box(D), mass: 1, position: vec(n, 1, 1 + 2 * i) }));
      };
      fresh();
      const calls: ((b: Body) => unknown)[] = [
        (b) => b.setPositionN(list(n)),
        (b) => b.setLinearVelocity(list(n)),
        (b) => b.setAngularVelocity(list(k)),
        (b) => b.applyCentralImpulse(list(n)),
        (b) => b.applyImpulse(list(n), list(n)),
        (b) => b.applyCentralForce(list(n)),
        (b) => b.applyForce(list(n), list(n)),
        (b) => b.applyTorque(list(k)),
        (b) => b.setMass(Math.abs(extreme())),
        (b) => b.rotateInPlane(0, 1, extreme()),
        () => addBody(),
        (b) => (world.bodies.length > 3 && b.type !== 'static' ? world.removeBody(b) : undefined),
      ];
      let refused = 0;
      let accepted = 0;
      for (let c = 0; c < 2000; c += 1) {
        if (c % 100 === 0) fresh();
        const bodies = world.bodies;
        const body = bodies[1 + Math.floor(random() * (bodies.length - 1))]!;
        const call = pick(calls);
        const before = worldBytes(world);
        let error: unknown = null;
        try {
          call(body);
        } catch (e) {
          error = e;
        }
        if (error !== null) {
          if (!(error instanceof TypeError || error instanceof RangeError)) throw error;
          expect(worldBytes(world), `call ${c}: ${String(error)}`).toBe(before);
          refused += 1;
          continue;
        }
        accepted += 1;
        try {
          for (let s = 0; s < 3; s += 1) world.step(1 / 60);
        } catch (e) {
          throw new Error(
            `call ${c} (${calls.indexOf(call)}) on ${body.label} (m ${body.mass}, I ${[...body.inertia]}, v ${[...body.v]}, w ${[...body.w]}, f ${[...body.force]}, t ${[...body.torque]}): ${String(e)}`,
            { cause: e },
          );
        }
        expectFinite(world);
      }
      expect(refused).toBeGreaterThan(200);
      expect(accepted).toBeGreaterThan(200);
    });
  }
});

describe('world gravity', () => {
  it('refuses a gravity beyond the acceleration bound, at new World and setGravity, before anything changes', () => {
    const bound = Body.limits.maxAcceleration;
    expect(() => new World({ dimensions: 3, gravity: [0, -bound * 1.0000001, 0] })).toThrow(/'gravity'\[1\] must be within/);
    const world = new World({ dimensions: 4, gravity: [0, -bound, 0, 0] });
    expect(() => world.setGravity([0, 0, 0, 1e308])).toThrow(RangeError);
    expect(() => world.setGravity([0, 0, 0, 1e308])).toThrow(/'g'\[3\]/);
    expect([...world.gravity]).toEqual([0, -bound, 0, 0]);
  });
});
