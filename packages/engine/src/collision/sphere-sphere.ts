/**
 * Sphere–sphere contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionSphere } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';

/**
 * One contact between two balls: normal along the line of centres (A to B; the first axis when
 * the centres coincide), separation |x_B − x_A| − ρ_A − ρ_B, point midway between the two
 * surface points on that line, feature id 0.
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideSphereSphere(
  out: Manifold,
  n: number,
  a: CollisionSphere,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideSphereSphereKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideSphereSphere} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideSphereSphereKernel(
  out: Manifold,
  n: number,
  a: CollisionSphere,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const xa = poseA.x;
  const xb = poseB.x;
  const N = out.normal;
  let d2 = 0;
  for (let c = 0; c < n; c += 1) {
    const d = xb[c] - xa[c];
    N[c] = d;
    d2 += d * d;
  }
  const reach = a.radius + b.radius + margin;
  if (d2 >= reach * reach) {
    out.count = 0;
    return false;
  }
  const dist = Math.sqrt(d2);
  if (dist > 0) {
    for (let c = 0; c < n; c += 1) N[c] /= dist;
  } else {
    for (let c = 0; c < n; c += 1) N[c] = 0;
    N[0] = 1;
  }
  const separation = dist - a.radius - b.radius;
  // midpoint of x_A + ρ_A N and x_B − ρ_B N
  const along = a.radius + separation / 2;
  for (let c = 0; c < n; c += 1) out.points[c] = xa[c] + along * N[c];
  out.separations[0] = separation;
  out.ids[0] = 0;
  out.count = 1;
  return true;
}
