/**
 * Tall stacks (issue 17, point 5): a column of 30 unit boxes in 3D (and of squares in 2D) and of
 * 20 hypercubes in 4D stands 10 s at the defaults with allowSleep: false, dt = 1/60, one sub-step.
 * Boxes of half-extent 0.5 start exactly touching, one above the other, on the ground {x_1 <= 0}.
 *
 * What made them fall (docs/solver.md, "Shock propagation"): the impulses of the shock passes,
 * computed against an infinitely heavy lower body, were warm-started into the next sub-step as if
 * both bodies had received them; the column's corner loads and friction patches drifted into
 * balanced stresses until a patch slid (the 30-box column fell after about a second).
 *
 * Tall pyramids (issue 19): a pyramid of 40 rows (820 boxes, each resting on two) slid apart
 * sideways within a second while the shock passes took its manifolds one at a time: a box took the
 * velocity of the support visited last. They now settle the contacts of a box with the row below
 * together.
 */
import { describe, expect, it } from 'vitest';
import type { Body } from '@physin/engine';
import { addBox, addGround, addPyramid, horizontalDrift, makeWorld, run } from './support/scenes.js';

/** Largest sideways drift and rotation angle of any box, and the top's largest height error. */
function column(n: number, count: number) {
  const world = makeWorld(n);
  addGround(world);
  const boxes: Body[] = [];
  for (let i = 0; i < count; i += 1) {
    const p = new Array<number>(n).fill(0);
    p[1] = 0.5 + i;
    boxes.push(addBox(world, p, 0.5, { name: `box${i}` }));
  }
  const start = boxes.map((b) => Float64Array.from(b.x));
  let drift = 0;
  let tilt = 0;
  let topErr = 0;
  run(world, 600, 1 / 60, () => {
    boxes.forEach((b, i) => {
      drift = Math.max(drift, horizontalDrift(b.x, start[i]!));
      // rotation angle of the rotor (its scalar part is cos(θ/2)): tilt and turn together
      tilt = Math.max(tilt, 2 * Math.acos(Math.min(1, Math.abs(b.R[0]!))));
    });
    topErr = Math.max(topErr, Math.abs(boxes[count - 1]!.x[1]! - (count - 0.5)));
  });
  const report = `n = ${n}, ${count} boxes: drift ${drift.toExponential(2)}, tilt ${tilt.toExponential(2)}, top height error ${topErr.toExponential(2)}`;
  if (process.env.PHYSIN_VERBOSE) console.log(report);
  return { drift, tilt, topErr, report };
}

describe('tall columns stand 10 s at the defaults (sleep off)', () => {
  for (const [n, count] of [
    [3, 30],
    [4, 20],
    [2, 30],
  ] as const) {
    it(`n = ${n}: a column of ${count} boxes: every box within 5e-6 m sideways and turned < 1e-6 rad, top within 1e-7 m of ${count - 0.5}`, () => {
      const { drift, tilt, topErr, report } = column(n, count);
      // Measured: drift 6.5e-7 (3D), 6.1e-7 (4D), 8.5e-8 (2D); angle 0 in all three; top 6.3e-9,
      // 8.8e-9, 1.0e-8. With 8 shock sweeps instead of 16: drift 6.3e-4, 9.2e-4, 2.2e-4; angle
      // 4.6e-4, 1.6e-5, 1.9e-4; top 2.3e-4, 1.2e-5, 9.5e-5.
      expect(drift, report).toBeLessThan(5e-6);
      expect(tilt, report).toBeLessThan(1e-6);
      expect(topErr, report).toBeLessThan(1e-7);
    });
  }
});

describe('a pyramid of 40 rows stands at the defaults (sleep off)', () => {
  it('820 unit boxes, spacing 1.05, start touching: after 4 s every box within 1e-4 m of its start', () => {
    const world = makeWorld(3);
    addGround(world);
    const boxes = addPyramid(world, 40);
    const start = boxes.map((b) => Float64Array.from(b.x));
    let worst = 0;
    run(world, 240, 1 / 60, (s) => {
      if (s % 10 !== 0) return;
      boxes.forEach((b, i) => {
        let d = 0;
        for (let a = 0; a < 3; a += 1) d = Math.hypot(d, b.x[a]! - start[i]![a]!);
        worst = Math.max(worst, d);
      });
    });
    const report = `pyramid of 40 rows: largest displacement ${worst.toExponential(2)}`;
    if (process.env.PHYSIN_VERBOSE) console.log(report);
    // Measured: 3.4e-5. Manifold by manifold, the largest was 7.2 m (it fell).
    expect(worst, report).toBeLessThan(1e-4);
  });
});
