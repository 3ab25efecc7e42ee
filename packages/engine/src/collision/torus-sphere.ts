/**
 * Torus–sphere contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionSphere, CollisionTorus } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { pointToLocal } from './manifold.js';

/**
 * One contact between a torus (A; core circle of radius R in its local plane (i, j), tube
 * radius r) and a ball (B, radius ρ). The ball's centre s, in the torus frame, is projected onto
 * the major plane; the nearest core point is q = R·proj/|proj| (q = R e_i when the centre is on
 * the axis, where every core point is equally near); normal (s − q)/|s − q| (the radial direction
 * q/R when s is on the core circle), separation |s − q| − r − ρ, point midway between the two
 * surface points on that line, id 0. A ball through the hole, ρ < R − r, centred on the axis,
 * is at |s − q| = R and does not touch.
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideTorusSphere(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideTorusSphereKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideTorusSphere} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideTorusSphereKernel(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const M = poseA.M;
  const xb = poseB.x;
  const s = scratch.v0;
  const R = a.majorRadius;
  const pi = a.planeI;
  const pj = a.planeJ;
  pointToLocal(s, n, poseA, poseB.x);
  const rho = Math.sqrt(s[pi] * s[pi] + s[pj] * s[pj]);
  const qi = rho > 0 ? (R * s[pi]) / rho : R;
  const qj = rho > 0 ? (R * s[pj]) / rho : 0;
  // s − q, in place
  s[pi] -= qi;
  s[pj] -= qj;
  let d2 = 0;
  for (let c = 0; c < n; c += 1) d2 += s[c] * s[c];
  const reach = a.minorRadius + b.radius + margin;
  if (d2 >= reach * reach) {
    out.count = 0;
    return false;
  }
  const dist = Math.sqrt(d2);
  if (dist > 0) {
    for (let c = 0; c < n; c += 1) s[c] /= dist;
  } else {
    s[pi] = qi / R;
    s[pj] = qj / R;
  }
  const N = out.normal;
  for (let i = 0; i < n; i += 1) {
    let v = 0;
    for (let c = 0; c < n; c += 1) v += M[i * n + c] * s[c];
    N[i] = v;
  }
  const separation = dist - a.minorRadius - b.radius;
  const back = b.radius + separation / 2;
  for (let i = 0; i < n; i += 1) out.points[i] = xb[i] - back * N[i];
  out.separations[0] = separation;
  out.ids[0] = 0;
  out.count = 1;
  return true;
}
