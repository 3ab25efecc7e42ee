/**
 * Joints: collideConnected. By default the two bodies of a joint do not touch each other; with
 * `collideConnected: true` they do. Other pairs are not affected.
 *
 * Scene: a static box (half-extents 0.5) at the origin; a 1 kg ball (ρ 0.2) 2 m above it, tied to
 * the box's centre by a rope (DistanceJoint, mode 'rope', rest 3 m), gravity −9.81 e_1, dt 1/60,
 * 3 s, sleep off. The rope is slack while the ball falls. collideConnected false: the ball falls
 * through the box and the rope catches it 3 m below the centre (y within 0.05 of −3);
 * true: it lands on the box and rests on top (y = 0.5 + 0.2 within penetrationSlop + 1e-3).
 * A second ball, not in the joint, dropped onto the box beside the first, lands in both cases.
 */
import { describe, expect, it } from 'vitest';
import { Body, defaultParams, DistanceJoint, HyperBox, HyperSphere, PointJoint } from '@physin/engine';
import { makeWorld } from './support/scenes.js';

function drop(n: number, collideConnected: boolean | undefined) {
  const world = makeWorld(n);
  const D = world.D;
  const zero = new Array<number>(n).fill(0);
  const box = world.addBody(new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.5)), mass: 0, name: 'box' }));
  const p1 = [...zero];
  p1[1] = 2;
  const ball = world.addBody(new Body(D, { shape: HyperSphere(D, 0.2), mass: 1, position: p1, name: 'tied' }));
  const p2 = [...zero];
  p2[1] = 2;
  p2[0] = 0.3;
  p2[2] = 0.3;
  const other = world.addBody(new Body(D, { shape: HyperSphere(D, 0.1), mass: 1, position: p2, name: 'free' }));
  const opts =
    collideConnected === undefined ? { rest: 3, mode: 'rope' as const } : { rest: 3, mode: 'rope' as const, collideConnected };
  const joint = world.addConstraint(new DistanceJoint(ball, box, zero, zero, opts));
  for (let s = 0; s < 180; s += 1) world.step(1 / 60);
  return { ball, other, joint, box };
}

const REST_TOL = defaultParams.penetrationSlop + 1e-3;

describe('collideConnected: the two bodies of a joint touch only when it is true', () => {
  for (const n of [3, 4]) {
    it(`${n}D, collideConnected default (false): the tied ball falls through the box and hangs on the rope at y = −3 (±0.05); the free ball lands on the box`, () => {
      const r = drop(n, undefined);
      const report = `${n}D collideConnected default: tied ball y ${r.ball.x[1]!.toFixed(4)}, free ball y ${r.other.x[1]!.toFixed(4)}, joint.collideConnected ${r.joint.collideConnected}`;
      console.log(report);
      expect(r.joint.collideConnected, report).toBe(false);
      expect(Math.abs(r.ball.x[1]! + 3), report).toBeLessThan(0.05);
      expect(Math.abs(r.other.x[1]! - 0.6), report).toBeLessThan(REST_TOL);
    });

    it(`${n}D, collideConnected true: the tied ball lands on the box and rests at y = 0.7 (± slop + 1e-3); so does the free one`, () => {
      const r = drop(n, true);
      const report = `${n}D collideConnected true: tied ball y ${r.ball.x[1]!.toFixed(4)}, free ball y ${r.other.x[1]!.toFixed(4)}`;
      console.log(report);
      expect(r.joint.collideConnected, report).toBe(true);
      expect(Math.abs(r.ball.x[1]! - 0.7), report).toBeLessThan(REST_TOL);
      expect(Math.abs(r.other.x[1]! - 0.6), report).toBeLessThan(REST_TOL);
    });
  }

  it('two dynamic boxes (g = 0) overlapping by 0.2 m, joined by a point joint at the top of the overlap: false leaves them overlapping and still (|v| < 1e-6), true pushes them apart', () => {
    const out: number[] = [];
    for (const collideConnected of [false, true]) {
      const world = makeWorld(3, {}, 0);
      const D = world.D;
      const a = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0, 0] }));
      const b = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0.8, 0, 0] }));
      // Anchors at the top of the overlap, (0.4, 0.5, 0): a contact pushing the boxes apart turns
      // them about it (they open like a book); without contacts nothing moves.
      world.addConstraint(new PointJoint(a, b, [0.4, 0.5, 0], [-0.4, 0.5, 0], { collideConnected }));
      for (let s = 0; s < 60; s += 1) world.step(1 / 60);
      out.push(Math.hypot(...a.v) + Math.hypot(...b.v) + Math.hypot(...a.w) + Math.hypot(...b.w));
    }
    const report = `overlapping pair: motion with false ${out[0]!.toExponential(2)}, with true ${out[1]!.toExponential(2)}`;
    console.log(report);
    expect(out[0]!, report).toBeLessThan(1e-6);
    expect(out[1]!, report).toBeGreaterThan(1e-3);
  });
});
