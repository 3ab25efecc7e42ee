/**
 * Box–sphere contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionBox, CollisionSphere } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { pointToLocal } from './manifold.js';

/**
 * One contact between a box (A) and a ball (B), normal from the box to the ball.
 *
 * The ball's centre c is taken into box coordinates and clamped into the box, q = clamp(c, ±a).
 * Centre outside the box: normal along c − q, separation |c − q| − ρ. Centre inside: the face of
 * least depth a_l − |c_l| pushes the ball out along ±axis l, separation −(a_l − |c_l|) − ρ.
 * The point is midway between the box surface point and the ball's surface point on the normal.
 *
 * Feature id: outside, the clamped feature of the box as base-3 digits per axis (0 inside the
 * slab, 1 clamped to −a, 2 clamped to +a); inside, 3ⁿ + 2l + (1 when the face is at +a_l).
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideBoxSphere(
  out: Manifold,
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideBoxSphereKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideBoxSphere} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideBoxSphereKernel(
  out: Manifold,
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const M = poseA.M;
  const xb = poseB.x;
  const half = a.halfExtents;
  const rho = b.radius;
  const local = scratch.v0;
  const d = scratch.v1;
  pointToLocal(local, n, poseA, poseB.x);
  let d2 = 0;
  let code = 0;
  let digit = 1;
  for (let c = 0; c < n; c += 1) {
    const v = local[c];
    const h = half[c];
    let delta = 0;
    if (v > h) {
      delta = v - h;
      code += 2 * digit;
    } else if (v < -h) {
      delta = v + h;
      code += digit;
    }
    d[c] = delta;
    d2 += delta * delta;
    digit *= 3;
  }
  const N = out.normal;
  let separation: number;
  let id: number;
  if (d2 > 0) {
    const reach = rho + margin;
    if (d2 >= reach * reach) {
      out.count = 0;
      return false;
    }
    const dist = Math.sqrt(d2);
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += M[i * n + c] * d[c];
      N[i] = s / dist;
    }
    separation = dist - rho;
    id = code;
  } else {
    let axis = 0;
    let depth = Infinity;
    for (let c = 0; c < n; c += 1) {
      const dc = half[c] - Math.abs(local[c]);
      if (dc < depth) {
        depth = dc;
        axis = c;
      }
    }
    const sign = local[axis] >= 0 ? 1 : -1;
    for (let i = 0; i < n; i += 1) N[i] = sign * M[i * n + axis];
    separation = -depth - rho;
    if (!(separation < margin)) {
      out.count = 0;
      return false;
    }
    id = digit + 2 * axis + (sign > 0 ? 1 : 0);
  }
  // midpoint of the ball's surface point x_B − ρN and the box's x_B − (separation + ρ)N
  const back = rho + separation / 2;
  for (let i = 0; i < n; i += 1) out.points[i] = xb[i] - back * N[i];
  out.separations[0] = separation;
  out.ids[0] = id;
  out.count = 1;
  return true;
}

/**
 * Ball (A) against box (B), for the ball's collider table: {@link collideBoxSphereKernel} with the
 * roles swapped and the normal turned to run from the ball to the box. The dispatch (collide.ts)
 * turns it back for a box–ball pair, so either order gives the bits the box–ball kernel gives.
 */
export function collideSphereBoxKernel(
  out: Manifold,
  n: number,
  a: CollisionSphere,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  if (!collideBoxSphereKernel(out, n, b, poseB, a, poseA, scratch)) return false;
  for (let i = 0; i < n; i += 1) out.normal[i] = -out.normal[i]!;
  return true;
}
