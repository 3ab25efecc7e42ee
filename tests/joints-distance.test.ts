/**
 * Joints: DistanceJoint modes. A rope holds only the upper bound (length ≤ rest), a strut only
 * the lower bound (length ≥ rest), a rod both.
 *
 * Scenes: a 1 kg ball (ρ 0.1) joined at its centre to the world point (0, 0, 0), rest 1 m,
 * gravity −9.81 e_1, dt 1/60, 3 s, sleep off. The length is measured from the ball's centre after
 * every step. The seeded sideways speeds come from seeded(…).
 *
 * Tolerance on a held bound: 0.01 m (1 % of the rest length). A bound that must NOT be held is shown
 * to be left by far more (≥ 0.3 m), so each mode is told apart from the other two.
 */
import { describe, expect, it } from 'vitest';
import { Body, DistanceJoint, HyperSphere } from '@physin/engine';
import { seeded, uniform } from './support/random.js';
import { makeWorld } from './support/scenes.js';

const TOL = 0.01;

type Mode = 'rod' | 'rope' | 'strut';

/** Runs the ball from `position` with `velocity` on a joint of the given mode; returns the length range. */
function swing(n: number, mode: Mode, position: number[], velocity: number[], seconds = 3) {
  const world = makeWorld(n);
  const body = world.addBody(new Body(world.D, { shape: HyperSphere(world.D, 0.1), mass: 1, position, velocity }));
  const zero = new Array<number>(n).fill(0);
  world.addConstraint(new DistanceJoint(body, null, zero, zero, { rest: 1, mode }));
  let min = Infinity;
  let max = -Infinity;
  for (let s = 0; s < Math.round(seconds * 60); s += 1) {
    world.step(1 / 60);
    const len = Math.hypot(...body.x);
    min = Math.min(min, len);
    max = Math.max(max, len);
  }
  return {
    min,
    max,
    report: `${n}D ${mode} from [${position.map((p) => p.toFixed(3)).join(', ')}] v [${velocity.map((p) => p.toFixed(3)).join(', ')}]: length in [${min.toFixed(5)}, ${max.toFixed(5)}]`,
  };
}

describe('DistanceJoint: rope holds only the upper bound, strut only the lower, rod both (rest 1 m, tolerance 0.01 m)', () => {
  const rand = seeded(610);
  const side = uniform(rand, 1.5, 2.5);

  it('rope: a ball thrown up from the bottom (3 m/s) goes slack (length < 0.7) and, swinging, never stretches past 1 + 0.01', () => {
    const r = swing(3, 'rope', [0, -1, 0], [0.2 * side, 3, 0]);
    console.log(r.report);
    expect(r.max, r.report).toBeLessThanOrEqual(1 + TOL);
    expect(r.min, r.report).toBeLessThan(0.7);
  });

  it('rope: a ball dropped from 0.5 m above the anchor falls and is caught at 1 m (length ≤ 1.01)', () => {
    const r = swing(3, 'rope', [0.1, 0.5, 0], [0, 0, 0]);
    console.log(r.report);
    expect(r.max, r.report).toBeLessThanOrEqual(1 + TOL);
    expect(r.max, r.report).toBeGreaterThan(1 - TOL);
  });

  it('strut: a ball balanced 1 m above the anchor is held up (length ≥ 0.99); one hanging below falls away (length > 1.5)', () => {
    const up = swing(3, 'strut', [0, 1, 0], [0, 0, 0], 2);
    console.log(up.report);
    expect(up.min, up.report).toBeGreaterThanOrEqual(1 - TOL);
    const down = swing(3, 'strut', [0, -1, 0], [0, 0, 0], 1);
    console.log(down.report);
    expect(down.max, down.report).toBeGreaterThan(1.5);
    expect(down.min, down.report).toBeGreaterThanOrEqual(1 - TOL);
  });

  it('strut: a ball thrown sideways at the top swings down round the anchor without coming closer than 0.99', () => {
    const r = swing(3, 'strut', [0, 1, 0], [side, 0, 0], 1);
    console.log(r.report);
    expect(r.min, r.report).toBeGreaterThanOrEqual(1 - TOL);
  });

  it('rod: a ball thrown up from the bottom (3 m/s) and one swinging from the horizontal keep the length within 1 ± 0.01', () => {
    const thrown = swing(3, 'rod', [0, -1, 0], [0.3 * side, 3, 0]);
    console.log(thrown.report);
    expect(thrown.min, thrown.report).toBeGreaterThanOrEqual(1 - TOL);
    expect(thrown.max, thrown.report).toBeLessThanOrEqual(1 + TOL);
    const swung = swing(3, 'rod', [1, 0, 0], [0, 0, side]);
    console.log(swung.report);
    expect(swung.min, swung.report).toBeGreaterThanOrEqual(1 - TOL);
    expect(swung.max, swung.report).toBeLessThanOrEqual(1 + TOL);
  });

  it('4D: rope, strut and rod keep their bounds for a ball thrown with seeded speeds along w', () => {
    const vw = uniform(rand, 0.5, 1);
    const rope = swing(4, 'rope', [0, -1, 0, 0], [0, 3, 0, vw]);
    const strut = swing(4, 'strut', [0, 1, 0, 0], [0, 0, 0, vw], 1);
    const rod = swing(4, 'rod', [0, -1, 0, 0], [0, 3, 0, vw]);
    const report = [rope.report, strut.report, rod.report].join('\n');
    console.log(report);
    expect(rope.max, report).toBeLessThanOrEqual(1 + TOL);
    expect(rope.min, report).toBeLessThan(0.7);
    expect(strut.min, report).toBeGreaterThanOrEqual(1 - TOL);
    expect(rod.min, report).toBeGreaterThanOrEqual(1 - TOL);
    expect(rod.max, report).toBeLessThanOrEqual(1 + TOL);
  });
});
