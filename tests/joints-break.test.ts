/**
 * Joints: breaking. A joint whose force (|linear impulse|/h) passes breakForce, or whose torque
 * (|angular impulse, limits included, motor excluded|/h) passes breakTorque, breaks: it fires
 * 'broken' once, after the step, and leaves the world.
 *
 * Scenes (gravity −9.81 e_1, dt 1/60, sleep off), each starting in static equilibrium at rest:
 * - a 1 kg ball hanging by a PointJoint at its centre from a world point: static load m g = 9.81 N;
 * - a 1 kg box cantilevered by a FixedJoint 1 m from its centre: load 9.81 N and m g · 1 m =
 *   9.81 N·m.
 * "Just above" is 1.02 × the static load, "just below" 0.98 ×. Held: 5 s without breaking and the
 * body still in place (< 1e-3 m). Broken: `joint.broken`, exactly one 'broken' event over 2 s, the
 * joint gone from `world.constraints`, and the body then falls freely (its vertical speed within
 * 0.05 m/s and its drop within 5 % of semi-implicit free fall, over the ≥ 1 s after the break).
 *
 * A motor alone never breaks its joint: a 10 kg wheel on a hinge (g = 0, so nothing else loads the
 * joint) spun up by a 50 N·m motor, breakTorque 1 N·m and breakForce 1 N, runs 3 s unbroken and
 * reaches the motor speed; the control — the same motor pushing into a limit — breaks it (the limit
 * carries the torque).
 */
import { describe, expect, it } from 'vitest';
import { Body, FixedJoint, HingeJoint, HyperBox, HyperSphere, PointJoint } from '@physin/engine';
import type { Joint } from '@physin/engine';
import { G, makeWorld } from './support/scenes.js';

const DT = 1 / 60;

function run(world: { step(dt: number): unknown }, steps: number, each?: () => void): void {
  for (let s = 0; s < steps; s += 1) {
    world.step(DT);
    if (each) each();
  }
}

function hangingBall(breakForce: number) {
  const world = makeWorld(3);
  const body = world.addBody(new Body(world.D, { shape: HyperSphere(world.D, 0.1), mass: 1, position: [0, 0, 0] }));
  const joint = world.addConstraint(new PointJoint(body, null, [0, 0, 0], [0, 0, 0], { breakForce }));
  return { world, body, joint };
}

function cantilever(breakTorque: number) {
  const world = makeWorld(3);
  const body = world.addBody(new Body(world.D, { shape: HyperBox(world.D, [0.5, 0.1, 0.1]), mass: 1, position: [1, 0, 0] }));
  const joint = world.addConstraint(new FixedJoint(body, null, [-1, 0, 0], [0, 0, 0], { breakTorque }));
  return { world, body, joint };
}

/** Counts 'broken' events; checks the joint left the world and the body falls freely afterwards. */
function expectBreaks(world: ReturnType<typeof makeWorld>, body: Body, joint: Joint, label: string) {
  let events = 0;
  let eventJoint: unknown = null;
  joint.addEventListener('broken', (e) => {
    events += 1;
    eventJoint = e.joint;
  });
  let brokeAt = -1;
  let vAtBreak = 0;
  let yAtBreak = 0;
  run(world, 120, () => {
    if (brokeAt < 0 && joint.broken) {
      brokeAt = world.stepCount;
      vAtBreak = body.v[1]!;
      yAtBreak = body.x[1]!;
    }
  });
  // Semi-implicit Euler from (y, v) over N steps of h: y_N = y + N h v − g h² N(N+1)/2.
  const N = world.stepCount - brokeAt;
  const freeFall = N * DT * vAtBreak - (G * DT * DT * N * (N + 1)) / 2;
  const report = `${label}: broke at step ${brokeAt}, ${events} event(s), constraints left ${world.constraints.length}, v_y ${body.v[1]!.toFixed(4)} (at break ${vAtBreak.toFixed(4)}), fell ${(body.x[1]! - yAtBreak).toFixed(4)} m in ${N} steps (free fall ${freeFall.toFixed(4)} m)`;
  console.log(report);
  expect(joint.broken, report).toBe(true);
  expect(events, report).toBe(1);
  expect(eventJoint, report).toBe(joint);
  expect(world.constraints.includes(joint), report).toBe(false);
  // Free fall after the break: Δv = −g Δt.
  const fallSteps = world.stepCount - brokeAt;
  expect(Math.abs(body.v[1]! - vAtBreak + G * fallSteps * DT), report).toBeLessThan(0.05);
  expect(fallSteps, report).toBeGreaterThanOrEqual(60);
  // ...and it moves: the position follows the free fall within 5 %.
  expect(Math.abs(body.x[1]! - yAtBreak - freeFall), report).toBeLessThan(0.05 * Math.abs(freeFall));
}

describe('breaking: breakForce just above the static load holds, just below it breaks', () => {
  it('a 1 kg ball on a point joint with breakForce 1.02 m g holds for 5 s (moves < 1e-3 m); joint.force reads m g within 2 %', () => {
    const { world, body, joint } = hangingBall(1.02 * G);
    let events = 0;
    joint.addEventListener('broken', () => (events += 1));
    let drift = 0;
    run(world, 300, () => (drift = Math.max(drift, Math.hypot(...body.x))));
    const report = `breakForce 1.02 mg: broken ${joint.broken}, events ${events}, drift ${drift.toExponential(2)}, force ${joint.force.toFixed(4)} N`;
    console.log(report);
    expect(joint.broken, report).toBe(false);
    expect(events, report).toBe(0);
    expect(world.constraints.includes(joint), report).toBe(true);
    expect(drift, report).toBeLessThan(1e-3);
    expect(Math.abs(joint.force - G) / G, report).toBeLessThan(0.02);
  });

  it("with breakForce 0.98 m g it breaks, fires 'broken' once, leaves the world, and the ball falls freely", () => {
    const { world, body, joint } = hangingBall(0.98 * G);
    expectBreaks(world, body, joint, 'breakForce 0.98 mg');
  });

  it('setBreak(0.98 m g, 0) on a holding joint breaks it within 2 steps (and fires once)', () => {
    const { world, body, joint } = hangingBall(0);
    run(world, 60);
    expect(joint.broken).toBe(false);
    joint.setBreak(0.98 * G, 0);
    let events = 0;
    joint.addEventListener('broken', () => (events += 1));
    let steps = 0;
    while (!joint.broken && steps < 10) {
      world.step(DT);
      steps += 1;
    }
    run(world, 30);
    const report = `setBreak: broke after ${steps} step(s), ${events} event(s), body y ${body.x[1]!.toFixed(3)} after 30 more steps (free fall from rest: −1.27 m)`;
    console.log(report);
    expect(steps, report).toBeLessThanOrEqual(2);
    expect(events, report).toBe(1);
    expect(world.constraints.length, report).toBe(0);
    expect(body.x[1]!, report).toBeLessThan(-1);
  });
});

describe('breaking: breakTorque just above the static torque holds, just below it breaks (fixed joint, cantilever)', () => {
  it('a 1 kg cantilever 1 m out (torque m g · 1 m) with breakTorque 1.02 m g holds for 5 s (< 1e-3 m); joint.torque reads m g within 2 %', () => {
    const { world, body, joint } = cantilever(1.02 * G);
    let drift = 0;
    run(world, 300, () => (drift = Math.max(drift, Math.hypot(body.x[0]! - 1, body.x[1]!, body.x[2]!))));
    const report = `breakTorque 1.02 mg·1m: broken ${joint.broken}, drift ${drift.toExponential(2)}, torque ${joint.torque.toFixed(4)} N·m, force ${joint.force.toFixed(4)} N`;
    console.log(report);
    expect(joint.broken, report).toBe(false);
    expect(drift, report).toBeLessThan(1e-3);
    expect(Math.abs(joint.torque - G) / G, report).toBeLessThan(0.02);
  });

  it('with breakTorque 0.98 m g · 1 m it breaks, fires once, leaves the world, and the box falls freely', () => {
    const { world, body, joint } = cantilever(0.98 * G);
    expectBreaks(world, body, joint, 'breakTorque 0.98 mg·1m');
  });
});

describe('a motor alone never breaks its joint; a motor pushing into a limit does', () => {
  function wheel(limits: boolean) {
    const world = makeWorld(3, {}, 0);
    const D = world.D;
    const base = world.addBody(new Body(D, { shape: HyperBox(D, [0.2, 0.2, 0.2]), mass: 0 }));
    const body = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.2]), mass: 10 }));
    const hinge = world.addConstraint(
      new HingeJoint(base, body, [0, 0, 0], [0, 0, 0], {
        plane: 0,
        motorSpeed: 5,
        maxMotorTorque: 50,
        breakForce: 1,
        breakTorque: 1,
        ...(limits ? { lowerAngle: -0.2, upperAngle: 0.2 } : {}),
      }),
    );
    let events = 0;
    hinge.addEventListener('broken', () => (events += 1));
    let maxMotor = 0;
    run(world, 180, () => (maxMotor = Math.max(maxMotor, Math.abs(hinge.motorTorque))));
    return { world, body, hinge, events, maxMotor };
  }

  it('a 10 kg wheel (I 1.67 kg·m²) spun up by a 50 N·m motor to 5 rad/s, breakTorque 1 N·m, breakForce 1 N, g = 0: unbroken after 3 s, spinning at 5 rad/s (±0.01)', () => {
    const r = wheel(false);
    const report = `motor alone: broken ${r.hinge.broken}, events ${r.events}, largest motorTorque ${r.maxMotor.toFixed(2)} N·m, ω_xy ${r.body.w[0]!.toFixed(4)} rad/s`;
    console.log(report);
    expect(r.maxMotor, report).toBeGreaterThan(10); // the motor did pull hard (50 N·m ≫ breakTorque)
    expect(r.hinge.broken, report).toBe(false);
    expect(r.events, report).toBe(0);
    expect(Math.abs(r.body.w[0]! - 5), report).toBeLessThan(0.01);
  });

  it('the same motor driven into a limit at 0.2 rad breaks the joint (the limit counts toward breakTorque), firing once', () => {
    const r = wheel(true);
    const report = `motor into a limit: broken ${r.hinge.broken}, events ${r.events}`;
    console.log(report);
    expect(r.hinge.broken, report).toBe(true);
    expect(r.events, report).toBe(1);
    expect(r.world.constraints.length, report).toBe(0);
  });
});
