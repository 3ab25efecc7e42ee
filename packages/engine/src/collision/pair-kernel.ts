/**
 * Pair kernels: the pair colliders' allocation-free form, with the margin read from
 * `scratch.scalars[NARROWPHASE_MARGIN]` instead of an argument.
 *
 * Why: in V8 a double passed as an argument to a call that is not inlined is boxed into a fresh
 * heap number. The dispatch calls through a table (a polymorphic site V8 does not inline), and
 * the colliders call large kernels, so the hot path passes its doubles through the scratch's
 * Float64Array slots and passes as arguments only objects and small integers.
 *
 * @module
 */
import type { CollidableShape, Manifold, PairCollider, Pose } from './manifold.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';

/**
 * A pair collider without its margin argument: reads the margin from
 * `scratch.scalars[NARROWPHASE_MARGIN]`, otherwise as {@link PairCollider}. Allocates nothing.
 */
export type PairKernel = (
  out: Manifold,
  n: number,
  shapeA: CollidableShape,
  poseA: Pose,
  shapeB: CollidableShape,
  poseB: Pose,
  scratch: NarrowphaseScratch,
) => boolean;

/** A pair collider that carries its kernel (the engine's tables hold these). */
export type KernelPairCollider = PairCollider & { readonly kernel?: PairKernel };

/**
 * The pair collider of a kernel: stores its margin into the scratch and calls the kernel, which
 * it also carries as `.kernel` for the dispatch (collideScratch in collide.ts) to call
 * directly.
 */
export function pairCollider(kernel: PairKernel): PairCollider {
  const collider = (
    out: Manifold,
    n: number,
    shapeA: CollidableShape,
    poseA: Pose,
    shapeB: CollidableShape,
    poseB: Pose,
    margin: number,
    scratch: NarrowphaseScratch,
  ): boolean => {
    scratch.scalars[NARROWPHASE_MARGIN] = margin;
    return kernel(out, n, shapeA, poseA, shapeB, poseB, scratch);
  };
  return Object.assign(collider, { kernel });
}
