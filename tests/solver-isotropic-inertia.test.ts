/**
 * The isotropic fast path of the solver bodies (SolverBodies.isoInvInertia): a body whose inertia
 * is the same in every plane (a hypercube, a hypersphere) has I_world⁻¹ = s·identity whatever its
 * rotation, and the contact rows take I⁻¹J = s·J. The path must give the physics of the full
 * k×k product: a tumbling cube lands as a box a hair away from a cube (which takes the full
 * product) does. n = 3..6 (in 2D there is one plane, so every body's I⁻¹ is a scalar and takes
 * the path).
 */
import { describe, expect, it } from 'vitest';
import type { Body, World } from '@physin/engine';
import type { SolverBodies } from '../packages/engine/src/solver/solver-bodies.js';
import { addBox, addGround, axis, makeWorld, run } from './support/scenes.js';

const DIMS = [3, 4, 5, 6];

function solverBodies(world: World): SolverBodies {
  return (world as unknown as { solverBodies: SolverBodies }).solverBodies;
}

/** A box dropped turned in two planes and spinning, onto the ground (friction 0.5). */
function drop(n: number, half: number[]): [World, Body] {
  const world = makeWorld(n);
  addGround(world, { friction: 0.5 });
  const k = (n * (n - 1)) / 2;
  const angularVelocity = new Array<number>(k).fill(0).map((_, i) => 0.7 - 0.3 * i);
  const box = addBox(world, axis(n, 1, 1.2), half, { material: { friction: 0.5 } });
  box.rotateInPlane(0, 1, 0.4);
  if (n >= 3) box.rotateInPlane(1, 2, 0.3);
  box.setAngularVelocity(angularVelocity);
  return [world, box];
}

describe('isotropic inertia: I⁻¹J = s·J', () => {
  for (const n of DIMS) {
    it(`n = ${n}: a tumbling cube lands as a near-cube on the full k×k product does (1e-6 over 90 steps)`, () => {
      const [cubeWorld, cube] = drop(n, new Array<number>(n).fill(0.5));
      // 1e-12 longer on one axis: the inertia differs per plane, so the general product is used.
      const near = new Array<number>(n).fill(0.5);
      near[n - 1] = 0.5 * (1 + 1e-12);
      const [nearWorld, nearCube] = drop(n, near);
      let isoSeen = 0;
      let fullSeen = 0;
      run(cubeWorld, 90, 1 / 60, () => {
        const sb = solverBodies(cubeWorld);
        if (sb.count > 1) isoSeen += sb.isoInvInertia[1]! > 0 ? 1 : 0;
      });
      run(nearWorld, 90, 1 / 60, () => {
        const sb = solverBodies(nearWorld);
        if (sb.count > 1) fullSeen += sb.isoInvInertia[1]! === -1 ? 1 : 0;
      });
      expect(isoSeen).toBeGreaterThan(10); // the cube took the fast path while in contact ...
      expect(fullSeen).toBeGreaterThan(10); // ... and the near-cube the full product
      expect(cube.x[1]!).toBeLessThan(0.9); // it landed
      for (let d = 0; d < n; d += 1) expect(Math.abs(cube.x[d]! - nearCube.x[d]!)).toBeLessThan(1e-6);
      for (let p = 0; p < cube.w.length; p += 1) expect(Math.abs(cube.w[p]! - nearCube.w[p]!)).toBeLessThan(1e-6);
    });
  }
});
