/**
 * Joints: `angularError()` of FixedJoint and HingeJoint reads the angle of a known turn in a locked
 * plane to rounding, from a full turn down to 1e-12 rad (2·acos of the rotor's scalar, which they
 * read before, saw nothing below about 2e-8 rad), in n = 2..6.
 *
 * The rig: a static body and a body turned by θ in a locked plane (for the hinge, with a free turn
 * of 0.7 rad in its own plane besides, where that plane commutes with the locked one, n ≥ 4).
 * Bound: |angularError() − θ| ≤ 1e-12·θ, plus 1e-16 where the free turn is undone first (a rotor's
 * components carry roundings of about 1e-17; measured: 3e-20 at θ = 1e-12).
 */
import { describe, expect, it } from 'vitest';
import { rotorFromPlane } from '@physin/algebra';
import { Body, FixedJoint, HingeJoint, HyperBox, dims } from '@physin/engine';
import type { Dims } from '@physin/engine';

const ANGLES = [1e-12, 1e-9, 1e-7, 1e-4, 0.3, 2.5];

/** A body, and a function that turns it by the product of the given turns (i, j, angle). */
function turnable(D: Dims): { body: Body; turn: (planes: [number, number, number][]) => void } {
  const body = new Body(D, { shape: HyperBox(D, new Array<number>(D.n).fill(0.5)), mass: 1 });
  const turn = (planes: [number, number, number][]): void => {
    let R = rotorFromPlane(D, new Float64Array(D.r), 0, 1, 0);
    for (const [i, j, angle] of planes)
      R = D.kernels.mul(new Float64Array(D.r), rotorFromPlane(D, new Float64Array(D.r), i, j, angle), R);
    body.setRotor(R);
  };
  return { body, turn };
}

function base(D: Dims): Body {
  return new Body(D, { shape: HyperBox(D, new Array<number>(D.n).fill(0.5)), mass: 0 });
}

describe('angularError() reads small turns to rounding', () => {
  for (const n of [2, 3, 4, 5, 6]) {
    it(`n = ${n}: FixedJoint, a turn θ in plane (0, 1) and in plane (${n - 2}, ${n - 1})`, () => {
      const D = dims(n);
      const origin = new Array<number>(n).fill(0);
      for (const theta of ANGLES) {
        for (const [i, j] of [
          [0, 1],
          [n - 2, n - 1],
        ] as const) {
          const { body, turn } = turnable(D);
          const joint = new FixedJoint(base(D), body, origin, origin);
          turn([[i, j, theta]]);
          expect(Math.abs(joint.angularError() - theta)).toBeLessThanOrEqual(1e-12 * theta);
        }
      }
      const still = new FixedJoint(base(D), turnable(D).body, origin, origin);
      expect(still.angularError()).toBe(0);
    });
  }
  for (const n of [3, 4, 5, 6]) {
    it(`n = ${n}: HingeJoint turning in plane (0, 1), a turn θ in a locked plane${n >= 4 ? ' and a free turn of 0.7 rad' : ''}`, () => {
      const D = dims(n);
      const origin = new Array<number>(n).fill(0);
      for (const theta of ANGLES) {
        const planes: [number, number, number][] =
          n >= 4
            ? [
                [0, 1, 0.7],
                [2, 3, theta],
              ]
            : [[1, 2, theta]];
        const { body, turn } = turnable(D);
        const joint = new HingeJoint(base(D), body, origin, origin, { plane: D.planeIndexOf[1]! });
        turn(planes);
        expect(Math.abs(joint.angularError() - theta)).toBeLessThanOrEqual(1e-12 * theta + (n >= 4 ? 1e-16 : 0));
      }
      const { body, turn } = turnable(D);
      const free = new HingeJoint(base(D), body, origin, origin, { plane: D.planeIndexOf[1]! });
      turn([[0, 1, 0.7]]);
      expect(free.angularError()).toBeLessThan(1e-15);
    });
  }
});
