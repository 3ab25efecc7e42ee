/**
 * Joints: the hinge in 3D and 4D — a motor, limits, a motor into a limit, and the angle tracked
 * across turns.
 *
 * The rig: a static base (a hypercube of half-extent 0.2 at the origin) and an arm (a box of
 * half-extents 0.5 along x, 0.1, 0.15, 0.2 across, 2 kg) centred at (0.6, 0, …), joined by a
 * HingeJoint at the origin (anchor 0 on the base, −0.6 e_0 on the arm). Both start with the
 * identity rotor, so the hinge angle is 0 at the start. Gravity −9.81 e_1 unless the test says
 * g = 0; dt 1/60, one sub-step, sleep off.
 *
 * Measured from the bodies' rotors (tests/support/joints.ts), not from the joint: the relative
 * rotor Q = R_base~ R_arm; the angle in the free plane F = (i, j) is 2 atan2(−⟨Q⟩_F, ⟨Q⟩_0),
 * unwrapped across steps; the locked-plane error is 2|⟨Q'⟩_P| for every other plane P, with
 * Q' = Q exp(+θF/2) (the free turn undone) — the brief's §8.
 *
 * Tolerances (the issue's): locked planes within 1e-3 rad over 10 s with a 2 rad/s motor; a limit
 * stops the arm within 0.01 rad of it; a motor driven into a limit stalls there (within 0.01 rad,
 * and slower than 0.01 rad/s over the last 2 s). The joint's own `angle` must agree with ours to
 * 1e-6 rad; 10 turns must read 20π within 0.01 rad.
 */
import { describe, expect, it } from 'vitest';
import { Body, HingeJoint, HyperBox } from '@physin/engine';
import type { Dims, World } from '@physin/engine';
import { freePlaneAngle, lockedPlaneError, relativeRotor, unwrap } from './support/joints.js';
import { makeWorld } from './support/scenes.js';

const DT = 1 / 60;

interface HingeOptions {
  plane: number;
  lowerAngle?: number;
  upperAngle?: number;
  motorSpeed?: number;
  maxMotorTorque?: number;
}

function rig(n: number, options: HingeOptions, g = 9.81, arm: 'arm' | 'wheel' = 'arm') {
  const world: World = makeWorld(n, {}, g);
  const D: Dims = world.D;
  const base = world.addBody(new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.2)), mass: 0, name: 'base' }));
  const half = [0.5, 0.1, 0.15, 0.2, 0.25].slice(0, n);
  const position = new Array<number>(n).fill(0);
  const localB = new Array<number>(n).fill(0);
  if (arm === 'arm') {
    position[0] = 0.6;
    localB[0] = -0.6;
  } else {
    half.fill(0.3);
    half[0] = 0.5;
  }
  const body = world.addBody(new Body(D, { shape: HyperBox(D, half), mass: 2, position, name: arm }));
  const hinge = world.addConstraint(new HingeJoint(base, body, new Array<number>(n).fill(0), localB, options));
  let angle = 0;
  let worstLocked = 0;
  const history: number[] = [];
  const step = (): void => {
    world.step(DT);
    const Q = relativeRotor(D, base, body);
    angle = unwrap(angle, freePlaneAngle(Q, options.plane));
    worstLocked = Math.max(worstLocked, lockedPlaneError(D, Q, options.plane));
    history.push(angle);
  };
  return {
    world,
    D,
    base,
    body,
    hinge,
    step,
    get angle() {
      return angle;
    },
    get worstLocked() {
      return worstLocked;
    },
    history,
  };
}

describe('a hinge with a motor keeps its locked planes (1e-3 rad over 10 s at 2 rad/s)', () => {
  it('4D, free plane (x w) (index 2), motor 2 rad/s, 100 N·m, gravity across the plane: the five locked planes stay within 1e-3 rad for 10 s; the angle reaches 20 rad (±0.05)', () => {
    const r = rig(4, { plane: 2, motorSpeed: 2, maxMotorTorque: 100 });
    let worstAngleDiff = 0;
    for (let s = 0; s < 600; s += 1) {
      r.step();
      worstAngleDiff = Math.max(worstAngleDiff, Math.abs(r.hinge.angle - r.angle));
    }
    const report = `4D hinge, motor 2 rad/s: worst locked-plane error ${r.worstLocked.toExponential(3)} rad, angle ${r.angle.toFixed(5)} rad (joint.angle ${r.hinge.angle.toFixed(5)}, worst difference ${worstAngleDiff.toExponential(2)}), hinge point error ${r.hinge.error().toExponential(2)} m`;
    console.log(report);
    expect(r.worstLocked, report).toBeLessThan(1e-3);
    expect(Math.abs(r.angle - 20), report).toBeLessThan(0.05);
    expect(worstAngleDiff, report).toBeLessThan(1e-6);
  });

  it('3D, free plane (x z) (index 1), motor 2 rad/s, 100 N·m, gravity across the plane: the two locked planes stay within 1e-3 rad for 10 s', () => {
    const r = rig(3, { plane: 1, motorSpeed: 2, maxMotorTorque: 100 });
    for (let s = 0; s < 600; s += 1) r.step();
    const report = `3D hinge, motor 2 rad/s: worst locked-plane error ${r.worstLocked.toExponential(3)} rad, angle ${r.angle.toFixed(5)} rad`;
    console.log(report);
    expect(r.worstLocked, report).toBeLessThan(1e-3);
    expect(Math.abs(r.angle - 20), report).toBeLessThan(0.05);
  });
});

describe('hinge limits stop the arm at the limit (within 0.01 rad)', () => {
  for (const n of [3, 4]) {
    it(`${n}D, free plane (x y), limits [−0.5, 0.5], the arm falls from the horizontal: it never passes −0.5 by more than 0.01 rad and rests within 0.01 rad of −0.5; locked planes < 1e-3 rad`, () => {
      const r = rig(n, { plane: 0, lowerAngle: -0.5, upperAngle: 0.5 });
      let lowest = Infinity;
      for (let s = 0; s < 180; s += 1) {
        r.step();
        lowest = Math.min(lowest, r.angle);
      }
      const report = `${n}D limit −0.5: lowest angle ${lowest.toFixed(5)}, final ${r.angle.toFixed(5)} (joint.angle ${r.hinge.angle.toFixed(5)}), locked ${r.worstLocked.toExponential(2)}`;
      console.log(report);
      expect(lowest, report).toBeGreaterThanOrEqual(-0.5 - 0.01);
      expect(Math.abs(r.angle + 0.5), report).toBeLessThanOrEqual(0.01);
      expect(r.worstLocked, report).toBeLessThan(1e-3);
    });
  }

  it('without limits the same arm falls past −0.5 (to below −1.4): the limit test can fail', () => {
    const r = rig(3, { plane: 0 });
    let lowest = Infinity;
    for (let s = 0; s < 60; s += 1) {
      r.step();
      lowest = Math.min(lowest, r.angle);
    }
    expect(lowest).toBeLessThan(-1.4);
  });
});

describe('a motor driven into a limit stalls there (within 0.01 rad, < 0.01 rad/s over the last 2 s)', () => {
  const cases = [
    { n: 4, plane: 2, speed: 2, limits: [-1, 1] as const, at: 1, what: 'upper limit 1' },
    { n: 4, plane: 2, speed: -2, limits: [-1, 1] as const, at: -1, what: 'lower limit −1' },
    {
      n: 4,
      plane: 5,
      speed: 2,
      limits: [-4, 4] as const,
      at: 4,
      what: 'upper limit 4 rad (beyond π: the angle is tracked, not wrapped)',
    },
    {
      n: 3,
      plane: 1,
      speed: 2,
      limits: [-0.3, 0.7] as const,
      at: 0.7,
      what: 'upper limit 0.7, set with setMotor/setLimits after construction',
    },
  ];
  for (const c of cases) {
    it(`${c.n}D, free plane ${c.plane}, motor ${c.speed} rad/s at 50 N·m into the ${c.what}: stalls there`, () => {
      const late = c.what.includes('setMotor');
      const r = late
        ? rig(c.n, { plane: c.plane })
        : rig(c.n, { plane: c.plane, lowerAngle: c.limits[0], upperAngle: c.limits[1], motorSpeed: c.speed, maxMotorTorque: 50 });
      if (late) {
        r.hinge.setMotor(c.speed, 50);
        r.hinge.setLimits(c.limits[0], c.limits[1]);
      }
      for (let s = 0; s < 300; s += 1) r.step();
      const tail = r.history.slice(-120);
      const far = Math.max(...tail.map((a) => Math.abs(a - c.at)));
      let speed = 0;
      for (let i = 1; i < tail.length; i += 1) speed = Math.max(speed, Math.abs(tail[i]! - tail[i - 1]!) / DT);
      const report = `${c.n}D motor ${c.speed} into ${c.at}: last 2 s |angle − limit| ≤ ${far.toExponential(2)}, |dθ/dt| ≤ ${speed.toExponential(2)}, joint.angle ${r.hinge.angle.toFixed(5)}, motorTorque ${r.hinge.motorTorque.toFixed(3)} N·m, locked ${r.worstLocked.toExponential(2)}`;
      console.log(report);
      expect(far, report).toBeLessThanOrEqual(0.01);
      expect(speed, report).toBeLessThan(0.01);
      expect(Math.abs(r.hinge.angle - c.at), report).toBeLessThanOrEqual(0.01);
    });
  }
});

describe('the hinge angle is tracked across turns (10 turns report 20π)', () => {
  const cases = [
    { n: 3, plane: 0, turns: 10 },
    { n: 3, plane: 0, turns: -10 },
    { n: 4, plane: 5, turns: 10 },
  ];
  for (const c of cases) {
    it(`${c.n}D, free plane ${c.plane}: a wheel spun at ${c.turns > 0 ? '' : '−'}2π rad/s (motor holding it) for 10 s reports ${c.turns > 0 ? '' : '−'}20π within 0.01 rad, and agrees with the angle from the rotors to 1e-6`, () => {
      const omega = (2 * Math.PI * c.turns) / 10;
      const r = rig(c.n, { plane: c.plane, motorSpeed: omega, maxMotorTorque: 10 }, 0, 'wheel');
      const w = new Array<number>(r.D.k).fill(0);
      w[c.plane] = omega;
      r.body.setAngularVelocity(w);
      let worstDiff = 0;
      for (let s = 0; s < 600; s += 1) {
        r.step();
        worstDiff = Math.max(worstDiff, Math.abs(r.hinge.angle - r.angle));
      }
      const target = 2 * Math.PI * c.turns;
      const report = `${c.n}D wheel, ${c.turns} turns: joint.angle ${r.hinge.angle.toFixed(6)}, ours ${r.angle.toFixed(6)}, ${c.turns > 0 ? '' : '−'}20π = ${target.toFixed(6)}; worst |joint − ours| ${worstDiff.toExponential(2)}`;
      console.log(report);
      expect(Math.abs(r.hinge.angle - target), report).toBeLessThan(0.01);
      expect(worstDiff, report).toBeLessThan(1e-6);
    });
  }
});
