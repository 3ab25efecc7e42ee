/**
 * The World of every dimension n = 2..8 (the root entry's): the world with `dims(n)` as its
 * tables, so every dimension's rotor kernels come with it.
 *
 * @module
 */
import { dims } from '@physin/algebra';
import { boxBoxSatKernel } from './collision/box-box-sat.js';
import { ManifoldCacheND } from './contacts/manifold-cache-nd.js';
import { ContactSolverND } from './solver/contact-solver-nd.js';
import { WorldBase } from './world.js';
import type { WorldOptions } from './world.js';

/**
 * A world of rigid bodies in n dimensions (n = 2..8).
 *
 * @example
 * ```ts
 * const D = dims(3);
 * const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
 * world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
 * const box = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 2, 0] }));
 * for (let i = 0; i < 60; i += 1) world.step(1 / 60);
 * ```
 */
export class World extends WorldBase {
  /**
   * @throws TypeError / RangeError for a bad `dimensions` (not an integer in 2..8), `gravity`
   *   (wrong length, non-finite) or `params` (unknown name, wrong type or range).
   */
  constructor(options: WorldOptions) {
    super(options, dims, {
      contactSolver: (D, gravity) => new ContactSolverND(D, gravity),
      boxBoxSat: boxBoxSatKernel,
      manifoldCache: (n, pointsPerSlot) => new ManifoldCacheND(n, pointsPerSlot),
    });
  }
}
