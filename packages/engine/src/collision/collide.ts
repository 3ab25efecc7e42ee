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
import {
  checkCollisionShape,
  checkFiniteNumber,
  checkManifold,
  checkPose,
  checkScratch,
} from './narrowphase-checks.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { warnOnce } from './warn-once.js';

/**
 * Contacts between shape A at poseA and shape B at poseB, normal from A to B. Looks up
 * `A.colliders[B.kind]` and calls it; else `B.colliders[A.kind]` with the roles swapped, then
 * flips the normal (points, separations and ids do not depend on the order); else warns once
 * for the pair of kinds ({@link warnOnce}) and reports no contact. Returns whether any point has
 * separation < margin; `out.count` is 0 when not.
 *
 * Unchecked hot-path kernel (see PairCollider; {@link collidePair} validates); allocates nothing.
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
  const direct = shapeA.colliders?.[shapeB.kind];
  if (direct) return direct(out, n, shapeA, poseA, shapeB, poseB, margin, scratch);
  const swapped = shapeB.colliders?.[shapeA.kind];
  if (swapped) {
    const hit = swapped(out, n, shapeB, poseB, shapeA, poseA, margin, scratch);
    if (hit) for (let i = 0; i < n; i += 1) out.normal[i] = -out.normal[i];
    return hit;
  }
  warnOnce(shapeA.kind, shapeB.kind);
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
