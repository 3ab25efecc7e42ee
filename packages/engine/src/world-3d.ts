/**
 * The World of `@physin/engine/3d`: 3D alone, with the 3D rotor kernels alone, so a 3D app's
 * bundle carries no 4D or generic kernels.
 *
 * @module
 */
import { dims3 } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { boxBoxSat3Kernel } from './collision/box-box-sat3.js';
import { ContactSolver3 } from './solver/contact-solver-3d.js';
import { WorldBase } from './world.js';
import type { WorldOptions } from './world.js';

/** The tables of `@physin/engine/3d`: n = 3 only. */
function tables3(n: number): Dims {
  if (n !== 3)
    throw new RangeError(
      `new World: option 'dimensions' must be 3 in @physin/engine/3d, got ${n}; import @physin/engine for other dimensions`,
    );
  return dims3();
}

/**
 * A world of rigid bodies in 3D: the same world as `@physin/engine`'s, built for n = 3 only.
 *
 * @example
 * ```ts
 * import { World, Body, HyperBox, HalfSpace, dims } from '@physin/engine/3d';
 * const D = dims(3);
 * const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
 * ```
 */
export class World extends WorldBase {
  /**
   * @throws TypeError / RangeError for `dimensions` other than 3, a bad `gravity` (wrong length,
   *   non-finite) or bad `params` (unknown name, wrong type or range).
   */
  constructor(options: WorldOptions) {
    super(options, tables3, {
      contactSolver: (D, gravity) => new ContactSolver3(D, gravity),
      // n is 3 here: the world's tables are 3D.
      boxBoxSat: (_n, a, poseA, b, poseB, scratch) => boxBoxSat3Kernel(a, poseA, b, poseB, scratch),
    });
  }
}

/**
 * The tables of 3D (the same object as `dims(3)` of `@physin/algebra`), with the 3D kernels alone.
 *
 * @throws RangeError for any n but 3.
 */
export function dims(n: 3): Dims {
  if (n !== 3) throw new RangeError(`dims: argument 'n' must be 3 in @physin/engine/3d, got ${String(n)}`);
  return dims3();
}
