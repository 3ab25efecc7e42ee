/**
 * Patch friction (ContactSolver): one tangent block at the centroid of a manifold's points,
 * clamped to μΣλ_n, and one twist block, one row per plane of the tangent space, clamped to
 * μΣλ_n·R with R the mean distance of the points from the centroid. Analytic checks in n = 3..6
 * (in 2D the tangent space is a line and has no plane to twist in).
 */
import { describe, expect, it } from 'vitest';
import { rotorToMatrix } from '@physin/algebra';
import { addBall, addBox, addGround, axis, makeWorld, run } from './support/scenes.js';

const G = 9.81;
const HALF = 0.5;

/** Index of the plane (i, j), i < j, in the order of the bivector basis (e01, e02, …, e12, …). */
function planeIndex(n: number, i: number, j: number): number {
  let p = 0;
  for (let a = 0; a < n; a += 1) {
    for (let b = a + 1; b < n; b += 1) {
      if (a === i && b === j) return p;
      p += 1;
    }
  }
  throw new RangeError('no such plane');
}

describe('twist friction of a face resting flat', () => {
  for (const n of [3, 4, 5, 6]) {
    it(`n = ${n}: a hypercube spinning in a horizontal plane slows at μ m g R / I, R the mean corner distance (2 %)`, () => {
      const mu = 0.5;
      const world = makeWorld(n, { allowSleep: false });
      addGround(world, { friction: mu });
      const box = addBox(world, axis(n, 1, HALF - 0.002), HALF, { material: { friction: mu } });
      run(world, 20); // settle onto the ground, no spin yet
      // Spin in the plane (x, z): horizontal, since y is up.
      const plane = planeIndex(n, 0, 2);
      const w = new Array<number>((n * (n - 1)) / 2).fill(0);
      w[plane] = 10;
      box.setAngularVelocity(w);
      const h = 1 / 60;
      run(world, 6, h);
      const w1 = box.w[plane]!;
      run(world, 6, h);
      const w2 = box.w[plane]!;
      // The face is a cube of n − 1 dimensions, side 1: its 2^(n−1) corners lie √(n−1)/2 from
      // its centre. A hypercube of side 1 has the moment (1 + 1)/12 = 1/6 in every plane.
      const R = Math.sqrt(n - 1) / 2;
      const alpha = (mu * G * R) / (1 / 6);
      const measured = (w1 - w2) / (6 * h);
      expect(w2).toBeGreaterThan(0.5); // still spinning: the measure is of the sliding phase
      expect(Math.abs(measured - alpha) / alpha).toBeLessThan(0.02);
    });
  }

  it('n = 3: a ball (one point, R = 0) gets no twist friction: its spin about the normal is kept', () => {
    const world = makeWorld(3, { allowSleep: false });
    addGround(world, { friction: 0.8 });
    const ball = addBall(world, axis(3, 1, 0.5), 0.5, { material: { friction: 0.8 }, angularVelocity: [0, 0, 0] });
    run(world, 20);
    const w = [0, 0, 0];
    w[planeIndex(3, 0, 2)] = 4;
    ball.setAngularVelocity(w);
    run(world, 60);
    expect(ball.w[planeIndex(3, 0, 2)]!).toBeCloseTo(4, 9);
  });

  it('n = 3: a spinning box set down on one corner (R = 0) keeps no twist impulse from its face', () => {
    const world = makeWorld(3, { allowSleep: false });
    addGround(world, { friction: 0.5 });
    const box = addBox(world, axis(3, 1, HALF - 0.002), HALF, { material: { friction: 0.5 } });
    run(world, 20);
    const xz = planeIndex(3, 0, 2);
    const w = [0, 0, 0];
    w[xz] = 6;
    box.setAngularVelocity(w);
    run(world, 5); // the face slides round: the patch holds a twist impulse at its limit
    // Turn it onto its lowest corner (a body diagonal vertical), at rest, that corner just in
    // contact; the corner keeps its feature id, so the manifold's points carry over.
    box.setAngularVelocity([0, 0, 0]);
    box.rotateInPlane(0, 1, Math.PI / 4);
    box.rotateInPlane(1, 2, Math.atan(Math.SQRT1_2));
    const M = rotorToMatrix(world.D, new Float64Array(9), box.R);
    const corners: number[] = [];
    for (let c = 0; c < 8; c += 1) {
      let y = 0;
      for (let j = 0; j < 3; j += 1) y += M[3 + j]! * (c & (1 << j) ? HALF : -HALF);
      corners.push(y);
    }
    const lowest = Math.min(...corners);
    const x = Array.from(box.x);
    x[1] = -lowest - 0.001;
    box.setPositionN(x);
    expect(corners.filter((y) => y - lowest < 0.05).length).toBe(1); // one point of contact
    world.step(1 / 60);
    // The normal force acts through the corner straight below the centre, friction at the
    // corner turns the box only in vertical planes: nothing turns it in the horizontal plane
    // (up to rounding of the diagonal: 6e-9 rad/s; a twist impulse left from the face gave 0.32).
    expect(Math.abs(box.w[xz]!)).toBeLessThan(1e-6);
  });
});
