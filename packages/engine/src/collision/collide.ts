/**
 * Dispatch of a shape pair to its collider.
 *
 * Each shape kind owns a table of pair colliders (see ColliderTable and the *-colliders.ts
 * files) that its factory attaches as `shape.colliders`; the dispatch itself knows no pair, so a
 * scene bundles only the collision code of the shapes it builds.
 *
 * @module
 */
import type { CollidableShape, Manifold, Pose } from './manifold.js';
import { checkNarrowphaseDimension } from './manifold.js';
import { checkCollisionShape, checkFiniteNumber, checkManifold, checkPose, checkScratch } from './narrowphase-checks.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import type { KernelPairCollider } from './pair-kernel.js';
import { shapeColliders, shapeKind } from './shape-kind.js';
import { warnOnce } from './warn-once.js';

/**
 * Contacts between shape A at poseA and shape B at poseB, normal from A to B. Looks up
 * `A.colliders[B.kind]` and calls it; else `B.colliders[A.kind]` with the roles swapped, then
 * flips the normal (points, separations and ids do not depend on the order); else warns once
 * for the pair of kinds ({@link warnOnce}) and reports no contact. Returns whether any point has
 * separation < margin; `out.count` is 0 when not.
 *
 * Unchecked kernel (see PairCollider; {@link collidePair} validates). The margin is stored into
 * `scratch.scalars[NARROWPHASE_MARGIN]` and the pair is collided by {@link collideScratch}; a
 * caller that computes the margin in hot code should call that directly (a double argument of a
 * call V8 does not inline is boxed into a fresh heap number).
 */
export function collide(
  out: Manifold,
  n: number,
  shapeA: CollidableShape,
  poseA: Pose,
  shapeB: CollidableShape,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideScratch(out, n, shapeA, poseA, shapeB, poseB, scratch);
}

/**
 * The hot-path entry point of the narrowphase: {@link collide} with the margin (m, >= 0) read
 * from `scratch.scalars[NARROWPHASE_MARGIN]`, which the caller writes before each call:
 *
 *     scratch.scalars[NARROWPHASE_MARGIN] = margin;
 *     collideScratch(out, n, shapeA, poseA, shapeB, poseB, scratch);
 *
 * Every argument is an object or a small integer, so the call allocates nothing whether or not
 * V8 inlines it; the engine's pair colliders are reached through their kernels
 * (pair-kernel.ts), which pass their numbers through the scratch too. A custom collider in a
 * shape's table (one without a kernel) is called with the margin as an argument, which may
 * allocate a heap number. The kernels use the other slots of `scratch.scalars`; the margin slot
 * is only read. Unchecked; allocates nothing.
 */
export function collideScratch(
  out: Manifold,
  n: number,
  shapeA: CollidableShape,
  poseA: Pose,
  shapeB: CollidableShape,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  // kind and table read through shape-kind.ts, so the kernels' number fields load unboxed
  const kindB = shapeKind(shapeB);
  const direct = shapeColliders(shapeA)?.[kindB] as KernelPairCollider | undefined;
  if (direct) {
    const kernel = direct.kernel;
    if (kernel !== undefined) return kernel(out, n, shapeA, poseA, shapeB, poseB, scratch);
    return direct(out, n, shapeA, poseA, shapeB, poseB, scratch.scalars[NARROWPHASE_MARGIN], scratch);
  }
  const kindA = shapeKind(shapeA);
  const swapped = shapeColliders(shapeB)?.[kindA] as KernelPairCollider | undefined;
  if (swapped) {
    const kernel = swapped.kernel;
    const hit =
      kernel !== undefined
        ? kernel(out, n, shapeB, poseB, shapeA, poseA, scratch)
        : swapped(out, n, shapeB, poseB, shapeA, poseA, scratch.scalars[NARROWPHASE_MARGIN], scratch);
    if (hit) for (let i = 0; i < n; i += 1) out.normal[i] = -out.normal[i];
    return hit;
  }
  warnOnce(kindA, kindB);
  out.count = 0;
  return false;
}

/**
 * {@link collide} with every argument validated first (nothing is written before the checks
 * pass): n in 2..8, `out` a manifold for n, shapes with valid geometry for n, poses of n and n·n
 * finite numbers, margin finite and >= 0, `scratch` made for n.
 *
 * @throws TypeError for a wrong type or length; RangeError for a bad value.
 */
export function collidePair(
  out: Manifold,
  n: number,
  shapeA: CollidableShape,
  poseA: Pose,
  shapeB: CollidableShape,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  checkNarrowphaseDimension(n, 'n');
  checkManifold(out, n, 'out');
  checkCollisionShape(shapeA, n, 'shapeA');
  checkPose(poseA, n, 'poseA');
  checkCollisionShape(shapeB, n, 'shapeB');
  checkPose(poseB, n, 'poseB');
  checkFiniteNumber(margin, 'margin', 0);
  checkScratch(scratch, n, 'scratch');
  return collide(out, n, shapeA, poseA, shapeB, poseB, margin, scratch);
}
