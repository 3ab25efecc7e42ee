/**
 * No call may put a non-finite number into a body: an impulse, force or torque that would
 * overflow the state (two of 1e308 in a row) throws a RangeError naming the argument, and nothing
 * changes; the world then steps on. n = 2, 3, 4 and 5.
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
  return [...body.x, ...body.R, ...body.v, ...body.L, ...body.w];
}

describe('calls that would overflow the state are refused', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: impulses, forces and torques of 1e308, twice, throw the second time and leave the body as it was`, () => {
      const { world, body, k } = setup(n);
      const big = new Array(n).fill(0);
      big[0] = 1e308;
      const arm = new Array(n).fill(0);
      arm[1] = 1e10;
      const bigTorque = new Array(k).fill(0);
      bigTorque[0] = 1e308;

      body.applyCentralImpulse(big);
      let before = state(body);
      expect(() => body.applyCentralImpulse(big)).toThrow(/argument 'j' would make .* velocity non-finite/);
      expect(state(body)).toEqual(before);

      body.setLinearVelocity(new Array(n).fill(0));
      before = state(body);
      expect(() => body.applyImpulse(big, arm)).toThrow(/angular momentum non-finite/);
      expect(state(body)).toEqual(before);

      body.applyCentralForce(big);
      expect(() => body.applyCentralForce(big)).toThrow(/argument 'f' would make .* force non-finite/);
      expect(() => body.applyForce(big, new Array(n).fill(0))).toThrow(/force non-finite/);
      body.applyTorque(bigTorque);
      expect(() => body.applyTorque(bigTorque)).toThrow(/argument 't' would make .* torque non-finite/);

      // the refused calls left a body the world can step (the forces it did accept are huge but finite)
      body.setMass(1);
      const fresh = setup(n);
      fresh.body.applyCentralImpulse([1, ...new Array(n - 1).fill(0)]);
      expect(() => fresh.world.step(1 / 60)).not.toThrow();
      expect(fresh.body.x[0]).toBeCloseTo(1 / 60, 12);
      void world;
    });
  }
});
