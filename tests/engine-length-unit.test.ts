/**
 * `params.lengthUnit` (issue 17, point 6): one parameter scales every length and speed tolerance
 * together. The check is similarity: a scene built at scale s (lengths × s, gravity × s, the same
 * time step) with `lengthUnit: s` is the scene at scale 1 shrunk by s, step for step — any length
 * tolerance left unscaled would break that. And 1 cm cubes under real gravity stand with
 * `lengthUnit: 0.01` as 1 m cubes stand with 1.
 */
import { describe, expect, it } from 'vitest';
import { Body, HalfSpace, HyperBox, HyperSphere, World, dims } from '@physin/engine';

/** A column of boxes (slightly offset) and a ball thrown at it, at scale `s`, in n dimensions. */
function scene(n: number, s: number, lengthUnit: number, gravity = 9.81 * s): World {
  const D = dims(n);
  const at = (y: number, x = 0): number[] => Array.from({ length: n }, (_, i) => (i === 1 ? y : i === 0 ? x : 0) * s);
  const world = new World({ dimensions: n, gravity: at(-gravity / s), params: { lengthUnit } });
  world.addBody(
    new Body(D, {
      shape: HalfSpace(
        D,
        at(1).map((v) => v / s),
        0,
      ),
      mass: 0,
    }),
  );
  for (let i = 0; i < 5; i += 1) {
    world.addBody(
      new Body(D, {
        shape: HyperBox(D, new Array<number>(n).fill(0.5 * s)),
        mass: 1,
        position: at(0.5 + 1.001 * i, 0.02 * (i % 2)),
      }),
    );
  }
  world.addBody(new Body(D, { shape: HyperSphere(D, 0.3 * s), mass: 0.5, position: at(3, -4), velocity: at(1, 6) }));
  return world;
}

describe('lengthUnit', () => {
  for (const n of [3, 4]) {
    it(`${n}D: a scene at scale 0.01 with lengthUnit 0.01 is the scene at scale 1, shrunk (3 s)`, () => {
      const big = scene(n, 1, 1);
      const small = scene(n, 0.01, 0.01);
      let worst = 0;
      for (let step = 0; step < 180; step += 1) {
        big.step(1 / 60);
        small.step(1 / 60);
        for (let b = 0; b < big.bodies.length; b += 1) {
          const A = big.bodies[b]!;
          const B = small.bodies[b]!;
          for (let i = 0; i < n; i += 1) worst = Math.max(worst, Math.abs(B.x[i]! / 0.01 - A.x[i]!));
          for (let i = 0; i < A.R.length; i += 1) worst = Math.max(worst, Math.abs(B.R[i]! - A.R[i]!));
        }
      }
      // Measured: 3.7e-12 (3D) and 5.0e-12 (4D): rounding of the scaled arithmetic.
      expect(worst).toBeLessThan(2e-11);
      // The ball did hit the column: the test is not of bodies in free fall.
      expect(big.touchingCount).toBeGreaterThan(5);
    });
  }

  it('1 cm cubes under real gravity stand with lengthUnit 0.01 (and fall without it)', () => {
    const top = (lengthUnit: number): number => {
      const world = scene(3, 0.01, lengthUnit, 9.81);
      world.removeBody(world.bodies[6]!);
      for (let step = 0; step < 300; step += 1) world.step(1 / 60);
      return world.bodies[5]!.x[1]!;
    };
    // The top cube's centre starts at 4.504 cm: with the unit it stays within 0.1 mm of its rest
    // height (4.5 cm less the slop); with the 2 cm margin of 1 m scenes it does not.
    expect(Math.abs(top(0.01) - 0.045)).toBeLessThan(1e-4);
    expect(Math.abs(top(1) - 0.045)).toBeGreaterThan(1e-3);
  });

  it('is set when the world is built: setParams refuses to change it; bad values are refused', () => {
    const world = new World({ dimensions: 3, params: { lengthUnit: 0.01 } });
    expect(world.params.lengthUnit).toBe(0.01);
    expect(() => world.setParams({ lengthUnit: 1 })).toThrow(/'lengthUnit' is set when the world is built/);
    expect(world.params.lengthUnit).toBe(0.01);
    world.setParams({ iterations: 12, lengthUnit: 0.01 });
    expect(world.params.iterations).toBe(12);
    expect(() => new World({ dimensions: 3, params: { lengthUnit: 0 } })).toThrow(/'lengthUnit'/);
    expect(() => new World({ dimensions: 3, params: { lengthUnit: Number.NaN } })).toThrow(RangeError);
    expect(() => new World({ dimensions: 3, params: { lengthUnit: '1' as unknown as number } })).toThrow(TypeError);
  });
});
