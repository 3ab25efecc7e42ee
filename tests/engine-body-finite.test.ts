/**
 * No call may put a non-finite number into a body: an impulse, force or torque that would
 * overflow the state (two of 1e308 in a row once did) throws a RangeError naming the argument,
 * and nothing changes; the world then steps on. n = 2, 3, 4 and 5. Since the input bounds
 * (Body.limits, tests/engine-input-limits.test.ts) a single 1e308 is refused at the argument; a
 * state already beyond a bound (written by hand, or grown by the step) refuses a call that would
 * make it larger and accepts one that brings it back.
 */
import { describe, expect, it } from 'vitest';
import { Body, HyperBox, World, dims } from '@physin/engine';

function setup(n: number): { world: World; body: Body; k: number } {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: new Array(n).fill(0) });
  const body = new Body(D, { shape: HyperBox(D, new Array(n).fill(0.5)), mass: 1 });
  world.addBody(body);
  return { world, body, k: D.k };
}

function state(body: Body): number[] {
  return [...body.x, ...body.R, ...body.v, ...body.L, ...body.w, ...body.force, ...body.torque];
}

describe('calls that would overflow the state are refused', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: impulses, forces and torques of 1e308 throw and leave the body as it was`, () => {
      const { world, body, k } = setup(n);
      const big = new Array(n).fill(0);
      big[0] = 1e308;
      const arm = new Array(n).fill(0);
      arm[1] = 1e10;
      const bigTorque = new Array(k).fill(0);
      bigTorque[0] = 1e308;

      const before = state(body);
      expect(() => body.applyCentralImpulse(big)).toThrow(/argument 'j'\[0\] must be within ±1e20 N·s/);
      expect(() => body.applyImpulse(big, arm)).toThrow(/argument 'j'\[0\]/);
      expect(() => body.applyCentralForce(big)).toThrow(/argument 'f'\[0\] must be within/);
      expect(() => body.applyForce(big, new Array(n).fill(0))).toThrow(/argument 'f'\[0\]/);
      expect(() => body.applyTorque(bigTorque)).toThrow(/argument 't'\[0\] must be within/);
      expect(state(body)).toEqual(before);

      // a velocity beyond the bound (written by hand): a push that grows it is refused, one that
      // brings it back is accepted
      body.v[0] = 1e10;
      const push = new Array(n).fill(0);
      push[0] = 1;
      const withHugeV = state(body);
      expect(() => body.applyCentralImpulse(push)).toThrow(/would make .*'s velocity\[0\] 10000000001, beyond ±1e8 m\/s/);
      expect(state(body)).toEqual(withHugeV);
      push[0] = -1;
      body.applyCentralImpulse(push);
      expect(body.v[0]).toBe(1e10 - 1);

      // the refused calls left a body the world can step
      body.setLinearVelocity([1, ...new Array(n - 1).fill(0)]);
      const x0 = body.x[0]!;
      world.step(1 / 60);
      expect(body.x[0]! - x0).toBeCloseTo(1 / 60, 12);
    });
  }
});
