/**
 * Sphere–half-space contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionHalfSpace, CollisionSphere } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { worldPlane } from './world-plane.js';

/**
 * One contact between a ball (A) and a half-space (B): the half-space's world plane N·x = h
 * (N outward, out of the solid); normal from the ball into the half-space, −N; separation
 * N·x_A − h − ρ; point midway between the ball's lowest point x_A − ρN and the plane; id 0.
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideSphereHalfSpace(
  out: Manifold,
  n: number,
  a: CollisionSphere,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideSphereHalfSpaceKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideSphereHalfSpace} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideSphereHalfSpaceKernel(
  out: Manifold,
  n: number,
  a: CollisionSphere,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const N = scratch.v0;
  worldPlane(N, n, b, poseB, scratch.scalars, 2);
  const h = scratch.scalars[2];
  const xa = poseA.x;
  let height = -h;
  for (let c = 0; c < n; c += 1) height += N[c] * xa[c];
  const separation = height - a.radius;
  if (!(separation < margin)) {
    out.count = 0;
    return false;
  }
  // midpoint of x_A − ρN (ball) and x_A − height·N (plane)
  const down = (a.radius + height) / 2;
  for (let c = 0; c < n; c += 1) {
    out.normal[c] = -N[c];
    out.points[c] = xa[c] - down * N[c];
  }
  out.separations[0] = separation;
  out.ids[0] = 0;
  out.count = 1;
  return true;
}
