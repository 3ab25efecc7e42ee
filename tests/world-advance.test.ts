/**
 * `world.advance(elapsed, maxSteps)`: frame time in, fixed steps out (issue 17, point 8: a frame
 * loop that passes its own delta). A world advanced with frames of any length goes through the
 * same states as one stepped by `step()` alone, bit for bit: the varying frame time cannot change
 * the accuracy, because it never reaches the step.
 */
import { describe, expect, it } from 'vitest';
import { Body, HalfSpace, HyperBox, World, dims, restoreWorld, snapshotWorld } from '@physin/engine';

/** A column of `count` unit boxes on a floor, in n dimensions. */
function column(n: number, count: number, params: Record<string, number> = {}): World {
  const D = dims(n);
  const up = Array.from({ length: n }, (_, i) => (i === 1 ? 1 : 0));
  const world = new World({ dimensions: n, gravity: up.map((u) => -9.81 * u), params });
  world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
  for (let i = 0; i < count; i += 1) {
    const x = up.map((u, k) => u * (0.5 + i) + (k === 0 ? 0.01 * (i % 2) : 0));
    world.addBody(new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.5)), mass: 1, position: x }));
  }
  return world;
}

const state = (world: World): number[] => world.bodies.flatMap((b) => [...b.x, ...b.R, ...b.v, ...b.L]);

describe('world.advance', () => {
  for (const n of [3, 4]) {
    it(`${n}D: frames alternating 1/30 and 1/120 s give the states of fixed 1/120 s steps, bit for bit`, () => {
      const h = 1 / 120;
      const framed = column(n, 6, { fixedTimeStep: h });
      const fixed = column(n, 6, { fixedTimeStep: h });
      let steps = 0;
      for (let frame = 0; frame < 240; frame += 1) {
        const ran = framed.advance(frame % 2 === 0 ? 1 / 30 : 1 / 120);
        expect(ran).toBe(frame % 2 === 0 ? 4 : 1);
        steps += ran;
        for (let s = 0; s < ran; s += 1) fixed.step(h);
        expect(state(framed)).toEqual(state(fixed));
      }
      expect(steps).toBe(600);
      expect(framed.stepCount).toBe(600);
      expect(framed.time).toBe(fixed.time);
      // The stack drifts no more than under fixed steps (it is the same motion): the top box is
      // within a millimetre of its place after 5 s.
      const top = framed.bodies[6]!;
      expect(Math.abs(top.x[1]! - 5.5)).toBeLessThan(1e-3);
    });
  }

  it('carries the remainder: frames of 1/180 s make one 1/60 s step every third frame', () => {
    const world = column(3, 1);
    const ran = Array.from({ length: 9 }, () => world.advance(1 / 180));
    expect(ran).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1]);
    expect(world.alpha).toBeLessThan(1e-6);
    world.advance(1 / 120);
    expect(world.alpha).toBeCloseTo(0.5, 12);
  });

  it('runs at most maxSteps and drops the backlog beyond them, keeping the fraction', () => {
    const world = column(3, 1);
    expect(world.advance(1.0 + 0.25 / 60, 4)).toBe(4);
    expect(world.stepCount).toBe(4);
    expect(world.alpha).toBeCloseTo(0.25, 9);
    expect(world.advance(0)).toBe(0);
    expect(world.advance(0.75 / 60)).toBe(1);
  });

  it('a snapshot keeps the remainder: the restored world advances bit-identically', () => {
    const world = column(3, 4);
    world.advance(1 / 60 + 1 / 200);
    const copy = restoreWorld(snapshotWorld(world));
    expect(copy.alpha).toBe(world.alpha);
    for (let frame = 0; frame < 50; frame += 1) {
      const dt = frame % 3 === 0 ? 1 / 45 : 1 / 90;
      expect(copy.advance(dt)).toBe(world.advance(dt));
    }
    expect(state(copy)).toEqual(state(world));
  });

  it('refuses bad arguments before anything changes', () => {
    const world = column(3, 2);
    world.advance(1 / 100);
    const before = [...state(world), world.alpha, world.stepCount];
    expect(() => world.advance(-1)).toThrow(/'elapsed' must be a finite number >= 0/);
    expect(() => world.advance(Number.NaN)).toThrow(RangeError);
    expect(() => world.advance(Number.POSITIVE_INFINITY)).toThrow(RangeError);
    expect(() => world.advance('1' as unknown as number)).toThrow(TypeError);
    expect(() => world.advance(1 / 60, 0)).toThrow(/'maxSteps'/);
    expect(() => world.advance(1 / 60, 1.5)).toThrow(RangeError);
    expect([...state(world), world.alpha, world.stepCount]).toEqual(before);
  });
});
