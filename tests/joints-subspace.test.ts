/**
 * Joints: the specification's 4D pin (identity 26 of the brief's §10) and the slide of `setAnchors`.
 *
 * The pin: SubspaceJoint(body, null, { lockAxes: [3], lockPlanes: [2, 4, 5], worldFrame: true })
 * holds the position on w and the three planes that hold w, (x w), (y w), (z w), in the world
 * frame; the body keeps a full 3D motion. Identity 26: w and those three ω components stay 0.
 *
 * The body: a 4D box of half-extents [0.5, 0.3, 0.2, 0.4], 1 kg, tumbling in the three planes of
 * xyz at seeded rates of 1–3 rad/s, moving at a seeded velocity in x, y, z, under gravity −9.81 e_1
 * (no ground). Two starts: axis-aligned, and turned 0.4 rad in the (x w) plane before the pin is
 * made — then its inertia couples the w-planes to the 3D ones, and the joint has real work to do
 * (a free body started that way gains w-plane ω, checked as the control). A third run also pushes
 * the body every step with a seeded force of 1–5 N with a w component at a seeded arm.
 *
 * Tolerance (the brief's): |x_w|, |ω_xw|, |ω_yw|, |ω_zw| ≤ 1e-6 at every step of 10 s at 1/60, and
 * the rotation since the start, U = R R₀~, keeps e_w fixed (its w-plane and e0123 parts ≤ 1e-6).
 *
 * The slide (the axis-aligned tumbling box, so that it tests the slide alone): `setAnchors(null, [0, 0, 0, 1.5])` moves the pin's hyperplane to w = 1.5. The joint
 * keeps its impulses, so the body slides there: no step moves it along w by more than
 * constraintMaxBias · dt (10 m/s default → 0.1667 m at 1/60; also with constraintMaxBias 2), it does
 * not pass 1.5 by more than constraintSlop, it comes within constraintSlop + 1e-6 of 1.5 within 2 s and stays there for the
 * next second, and the w-planes stay within 1e-6 throughout.
 */
import { describe, expect, it } from 'vitest';
import { rotorFromPlane, rotorMul, rotorReverse } from '@physin/algebra';
import { Body, defaultParams, HyperBox, SubspaceJoint } from '@physin/engine';
import type { Params } from '@physin/engine';
import { randomArray, randomUnitVector, seeded, uniform } from './support/random.js';
import { makeWorld } from './support/scenes.js';

const DT = 1 / 60;
const W_PLANES = [2, 4, 5] as const;

interface PinOptions {
  turned: boolean;
  pushes: boolean;
  pin: boolean;
  seed: number;
  params?: Partial<Params>;
}

function pinned(o: PinOptions) {
  const rand = seeded(o.seed);
  const world = makeWorld(4, o.params ?? {});
  const D = world.D;
  const rotor = o.turned ? rotorFromPlane(D, new Float64Array(D.r), 0, 3, 0.4) : undefined;
  const w = [uniform(rand, 1, 3), uniform(rand, -3, -1), 0, uniform(rand, 1, 3), 0, 0];
  const velocity = [...randomArray(rand, 3, -1, 1), 0];
  const body = world.addBody(
    new Body(D, {
      shape: HyperBox(D, [0.5, 0.3, 0.2, 0.4]),
      mass: 1,
      position: [0, 5, 0, 0],
      velocity,
      angularVelocity: w,
      ...(rotor ? { rotor } : {}),
    }),
  );
  const R0rev = rotorReverse(D, new Float64Array(D.r), body.R);
  const joint = o.pin
    ? world.addConstraint(new SubspaceJoint(body, null, { lockAxes: [3], lockPlanes: [2, 4, 5], worldFrame: true }))
    : null;
  let wTarget = 0;
  const worst = { x: 0, omega: 0, turn: 0 };
  const measure = (): void => {
    worst.x = Math.max(worst.x, Math.abs(body.x[3]! - wTarget));
    for (const p of W_PLANES) worst.omega = Math.max(worst.omega, Math.abs(body.w[p]!));
    const U = rotorMul(D, new Float64Array(D.r), body.R, R0rev);
    // U in the rotor storage [1, e01, e02, e03, e12, e13, e23, e0123]: the w-planes are e03, e13, e23.
    for (const a of [3, 5, 6, 7]) worst.turn = Math.max(worst.turn, 2 * Math.abs(U[a]!));
  };
  const step = (): void => {
    if (o.pushes) {
      const f = randomUnitVector(rand, 4).map((x) => x * uniform(rand, 1, 5));
      body.applyForce(f, randomArray(rand, 4, -0.4, 0.4));
    }
    world.step(DT);
    measure();
  };
  return {
    world,
    body,
    joint,
    worst,
    step,
    setTarget(t: number) {
      wTarget = t;
    },
    reset() {
      worst.x = 0;
      worst.omega = 0;
      worst.turn = 0;
    },
  };
}

describe("identity 26: the specification's 4D pin keeps w and the planes (x w), (y w), (z w) at 0 (1e-6) while the body tumbles in 3D", () => {
  const starts = [
    { label: 'axis-aligned box', turned: false, pushes: false, seed: 2601 },
    { label: 'box turned 0.4 rad in (x w) (inertia couples w-planes to 3D planes)', turned: true, pushes: false, seed: 2602 },
    {
      label: 'turned box pushed every step by a seeded 1–5 N force with a w component at a seeded arm',
      turned: true,
      pushes: true,
      seed: 2603,
    },
  ];
  for (const s of starts) {
    it(`identity 26, ${s.label}: |x_w|, |ω_xw|, |ω_yw|, |ω_zw| and the w-part of the turn ≤ 1e-6 over 10 s`, () => {
      const r = pinned({ ...s, pin: true });
      for (let i = 0; i < 600; i += 1) r.step();
      const spin = Math.hypot(r.body.w[0]!, r.body.w[1]!, r.body.w[3]!);
      const report = `${s.label}: worst |x_w| ${r.worst.x.toExponential(2)}, |ω_w-planes| ${r.worst.omega.toExponential(2)}, w-part of the turn ${r.worst.turn.toExponential(2)}; 3D spin at the end ${spin.toFixed(3)} rad/s; joint.error() ${r.joint!.error().toExponential(2)}, angularError() ${r.joint!.angularError().toExponential(2)}`;
      console.log(report);
      expect(r.worst.x, report).toBeLessThanOrEqual(1e-6);
      expect(r.worst.omega, report).toBeLessThanOrEqual(1e-6);
      expect(r.worst.turn, report).toBeLessThanOrEqual(1e-6);
      expect(spin, report).toBeGreaterThan(0.5); // it does tumble
    });
  }

  it('control: without the pin, the turned box gains w-plane ω > 0.01 rad/s (so the pin test can fail)', () => {
    const r = pinned({ turned: true, pushes: false, pin: false, seed: 2602 });
    for (let i = 0; i < 600; i += 1) r.step();
    console.log(
      `no pin: worst |ω_w-planes| ${r.worst.omega.toExponential(2)}, w-part of the turn ${r.worst.turn.toExponential(2)}`,
    );
    expect(r.worst.omega).toBeGreaterThan(0.01);
  });
});

describe('setAnchors(null, [0, 0, 0, 1.5]) slides the pinned body to w = 1.5 without a jump (speed ≤ constraintMaxBias)', () => {
  for (const maxBias of [defaultParams.constraintMaxBias, 2]) {
    it(`constraintMaxBias ${maxBias} m/s: every step moves w by ≤ ${maxBias}·dt, |v_w| ≤ ${maxBias}, no overshoot beyond slop, within slop + 1e-6 of 1.5 within 2 s and for the second after${maxBias === 2 ? ' (it takes ≥ 0.7 s)' : ''}; w-planes ≤ 1e-6 throughout`, () => {
      const params = maxBias === defaultParams.constraintMaxBias ? {} : { constraintMaxBias: maxBias };
      const r = pinned({ turned: false, pushes: false, pin: true, seed: 2604, params });
      for (let i = 0; i < 60; i += 1) r.step();
      expect(Math.abs(r.body.x[3]!)).toBeLessThanOrEqual(1e-6);
      r.joint!.setAnchors(null, [0, 0, 0, 1.5]);
      r.reset();
      const slop = defaultParams.constraintSlop;
      let prev = r.body.x[3]!;
      let maxStep = 0;
      let maxSpeed = 0;
      let highest = -Infinity;
      let arrived = -1;
      for (let i = 1; i <= 120; i += 1) {
        r.step();
        const wNow = r.body.x[3]!;
        maxStep = Math.max(maxStep, Math.abs(wNow - prev));
        maxSpeed = Math.max(maxSpeed, Math.abs(r.body.v[3]!));
        highest = Math.max(highest, wNow);
        if (arrived < 0 && Math.abs(wNow - 1.5) <= slop + 1e-6) arrived = i;
        prev = wNow;
      }
      const slideOmega = r.worst.omega;
      r.setTarget(1.5);
      r.reset();
      for (let i = 0; i < 60; i += 1) r.step();
      const report = `maxBias ${maxBias}: largest w step ${maxStep.toFixed(5)} m (bound ${(maxBias * DT).toFixed(5)}), largest |v_w| ${maxSpeed.toFixed(4)}, highest w ${highest.toFixed(6)}, arrived (within slop) at step ${arrived}, then |w − 1.5| ≤ ${r.worst.x.toExponential(2)} and w-planes ≤ ${Math.max(slideOmega, r.worst.omega).toExponential(2)}`;
      console.log(report);
      expect(maxStep, report).toBeLessThanOrEqual(maxBias * DT * (1 + 1e-9));
      expect(maxSpeed, report).toBeLessThanOrEqual(maxBias * (1 + 1e-9));
      expect(highest, report).toBeLessThanOrEqual(1.5 + slop);
      expect(arrived, report).toBeGreaterThan(0);
      if (maxBias === 2) expect(arrived, report).toBeGreaterThanOrEqual(42);
      expect(r.worst.x, report).toBeLessThanOrEqual(slop + 1e-6);
      expect(Math.max(slideOmega, r.worst.omega), report).toBeLessThanOrEqual(1e-6);
    });
  }
});
