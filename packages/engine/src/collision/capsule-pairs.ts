/**
 * Capsule–half-space, capsule–ball and capsule–capsule contacts, any n. A capsule is the set of
 * points within radius r of its core segment x ± s·a, s in [−h, h], where a is the world image
 * of local axis 1 (column 1 of the pose's M); every pair reduces to closest points of segments.
 *
 * - **Half-space:** one point per end of the segment whose ball comes within the margin of the
 *   plane (ids 0 and 1): a capsule lying on its side gets both, so it rests without rolling.
 * - **Ball:** the closest point of the segment to the centre, then as two balls (id 0).
 * - **Capsule:** the closest points of the two segments (clamped line–line, as Ericson's
 *   *Real-Time Collision Detection* §5.1.9, written with unit axes so it holds in any n), normal
 *   along them; when they coincide (the segments cross), n ≥ 3 escapes along a direction normal
 *   to both axes (depth rA + rB), n = 2 by the better of the two axes normal to a segment (the
 *   separating-axis test of two crossing segments). When the axes are parallel within
 *   {@link CAPSULE_PARALLEL_SIN2} and their projections overlap, two points at the ends of the
 *   overlap (ids 1 and 2) with the separation measured along the normal, so two capsules lying
 *   side by side rest; else one point (id 0).
 *
 * Unchecked hot-path kernels (see PairCollider): they read the margin from
 * `scratch.scalars[NARROWPHASE_MARGIN]` and allocate nothing.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionCapsule, CollisionHalfSpace, CollisionSphere } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { worldPlane } from './world-plane.js';

/**
 * Two capsule axes count as parallel when sin²θ of their angle is below this (θ < 0.01 rad):
 * then two contact points span their overlap.
 */
export const CAPSULE_PARALLEL_SIN2 = 1e-4;

/** Contacts between a capsule (A) and a half-space (B): one per segment end within the margin. */
export function collideCapsuleHalfSpaceKernel(
  out: Manifold,
  n: number,
  a: CollisionCapsule,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const N = scratch.v0;
  worldPlane(N, n, b, poseB, scratch.scalars, 2);
  const x = poseA.x;
  const M = poseA.M;
  const h = a.halfHeight;
  const r = a.radius;
  let centre = -scratch.scalars[2];
  let along = 0;
  for (let c = 0; c < n; c += 1) {
    centre += N[c] * x[c];
    along += N[c] * M[c * n + 1];
  }
  let count = 0;
  for (let k = 0; k < 2; k += 1) {
    const s = k === 0 ? -h : h;
    const height = centre + s * along;
    const separation = height - r;
    if (!(separation < margin)) continue;
    // midpoint of the end's lowest point (height − r above the plane) and the plane
    const down = (r + height) / 2;
    for (let c = 0; c < n; c += 1) out.points[count * n + c] = x[c] + s * M[c * n + 1] - down * N[c];
    out.separations[count] = separation;
    out.ids[count] = k;
    count += 1;
  }
  out.count = count;
  if (count === 0) return false;
  for (let c = 0; c < n; c += 1) out.normal[c] = -N[c];
  return true;
}

/** Contact between a capsule (A) and a ball (B): the segment's closest point to the centre, then as two balls. */
export function collideCapsuleSphereKernel(
  out: Manifold,
  n: number,
  a: CollisionCapsule,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const xa = poseA.x;
  const xb = poseB.x;
  const M = poseA.M;
  const h = a.halfHeight;
  let s = 0;
  for (let c = 0; c < n; c += 1) s += M[c * n + 1] * (xb[c] - xa[c]);
  s = s < -h ? -h : s > h ? h : s;
  const p = scratch.v1;
  const N = out.normal;
  let d2 = 0;
  for (let c = 0; c < n; c += 1) {
    p[c] = xa[c] + s * M[c * n + 1];
    const d = xb[c] - p[c];
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
    // the centre is on the segment: escape along local axis 0, normal to the axis
    for (let c = 0; c < n; c += 1) N[c] = M[c * n];
  }
  const separation = dist - a.radius - b.radius;
  const along = a.radius + separation / 2;
  for (let c = 0; c < n; c += 1) out.points[c] = p[c] + along * N[c];
  out.separations[0] = separation;
  out.ids[0] = 0;
  out.count = 1;
  return true;
}

/**
 * Writes into `u` a unit vector normal to the unit vector `a` and to `b` (unit; may be parallel
 * to a): the world axis with the largest part normal to both, made unit. n >= 3, or n = 2 with
 * b parallel to a. Uses `w` as scratch.
 */
function normalToBoth(n: number, u: Float64Array, a: Float64Array, b: Float64Array, w: Float64Array): void {
  // w = the part of b normal to a, unit (or zero when b is parallel to a)
  let ab = 0;
  for (let c = 0; c < n; c += 1) ab += a[c] * b[c];
  let w2 = 0;
  for (let c = 0; c < n; c += 1) {
    w[c] = b[c] - ab * a[c];
    w2 += w[c] * w[c];
  }
  const wl = w2 > 1e-20 ? 1 / Math.sqrt(w2) : 0;
  for (let c = 0; c < n; c += 1) w[c] *= wl;
  let best = -1;
  let bestLen = -1;
  for (let k = 0; k < n; k += 1) {
    // |e_k − (e_k·a)a − (e_k·w)w|² = 1 − a_k² − w_k²
    const len = 1 - a[k] * a[k] - w[k] * w[k];
    if (len > bestLen + 1e-12) {
      bestLen = len;
      best = k;
    }
  }
  let u2 = 0;
  for (let c = 0; c < n; c += 1) {
    u[c] = (c === best ? 1 : 0) - a[best] * a[c] - w[best] * w[c];
    u2 += u[c] * u[c];
  }
  const ul = 1 / Math.sqrt(u2);
  for (let c = 0; c < n; c += 1) u[c] *= ul;
}

/** Contacts between two capsules (see the module comment). */
export function collideCapsuleCapsuleKernel(
  out: Manifold,
  n: number,
  a: CollisionCapsule,
  poseA: Pose,
  b: CollisionCapsule,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const xa = poseA.x;
  const xb = poseB.x;
  const MA = poseA.M;
  const MB = poseB.M;
  const ha = a.halfHeight;
  const hb = b.halfHeight;
  const rr = a.radius + b.radius;
  const ua = scratch.v0;
  const ub = scratch.v1;
  const N = out.normal;
  let aw = 0;
  let bw = 0;
  let cos = 0;
  for (let c = 0; c < n; c += 1) {
    ua[c] = MA[c * n + 1];
    ub[c] = MB[c * n + 1];
    const w = xa[c] - xb[c];
    aw += ua[c] * w;
    bw += ub[c] * w;
    cos += ua[c] * ub[c];
  }
  // |w + s·a − t·b|² is least where s = t·cos − a·w and t = s·cos + b·w
  const sin2 = 1 - cos * cos;
  let s = sin2 > 1e-14 ? (bw * cos - aw) / sin2 : 0;
  s = s < -ha ? -ha : s > ha ? ha : s;
  let t = s * cos + bw;
  if (t < -hb) {
    t = -hb;
    s = t * cos - aw;
    s = s < -ha ? -ha : s > ha ? ha : s;
  } else if (t > hb) {
    t = hb;
    s = t * cos - aw;
    s = s < -ha ? -ha : s > ha ? ha : s;
  }
  let d2 = 0;
  for (let c = 0; c < n; c += 1) {
    const d = xb[c] + t * ub[c] - xa[c] - s * ua[c];
    N[c] = d;
    d2 += d * d;
  }
  const reach = rr + margin;
  if (d2 >= reach * reach) {
    out.count = 0;
    return false;
  }
  const dist = Math.sqrt(d2);
  const size = ha + hb + rr;
  let segmentSeparation = dist;
  if (dist > 1e-12 * size) {
    for (let c = 0; c < n; c += 1) N[c] /= dist;
  } else if (n > 2 || sin2 <= 1e-14) {
    normalToBoth(n, N, ua, ub, scratch.v2);
    segmentSeparation = 0;
  } else {
    // n = 2, crossing segments: the better of ±(a's normal) and ±(b's normal)
    let best = -Infinity;
    for (let axis = 0; axis < 2; axis += 1) {
      const u = axis === 0 ? ua : ub;
      const nx = -u[1];
      const ny = u[0];
      // the other segment's half-extent along this normal, and the offset of the centres
      const other = axis === 0 ? hb * Math.abs(nx * ub[0] + ny * ub[1]) : ha * Math.abs(nx * ua[0] + ny * ua[1]);
      const offset = nx * (xb[0] - xa[0]) + ny * (xb[1] - xa[1]);
      for (let sign = -1; sign <= 1; sign += 2) {
        const sep = sign * offset - other;
        if (sep > best) {
          best = sep;
          N[0] = sign * nx;
          N[1] = sign * ny;
        }
      }
    }
    segmentSeparation = best;
  }
  const separation = segmentSeparation - rr;
  if (!(separation < margin)) {
    out.count = 0;
    return false;
  }
  // parallel axes: two points at the ends of the overlap of B's segment projected on A's axis
  if (sin2 < CAPSULE_PARALLEL_SIN2) {
    const e0 = -aw - hb * cos;
    const e1 = -aw + hb * cos;
    const lo = Math.max(-ha, Math.min(e0, e1));
    const hi = Math.min(ha, Math.max(e0, e1));
    if (hi - lo > 1e-9 * size) {
      let count = 0;
      for (let k = 0; k < 2; k += 1) {
        const sk = k === 0 ? lo : hi;
        // closest point of B's segment to A's point at sk, and their gap along the normal
        let tk = sk * cos + bw;
        tk = tk < -hb ? -hb : tk > hb ? hb : tk;
        let gap = 0;
        for (let c = 0; c < n; c += 1) gap += N[c] * (xb[c] + tk * ub[c] - xa[c] - sk * ua[c]);
        const sep = gap - rr;
        if (!(sep < margin)) continue;
        for (let c = 0; c < n; c += 1) {
          const pa = xa[c] + sk * ua[c];
          const pb = xb[c] + tk * ub[c];
          out.points[count * n + c] = (pa + pb) / 2 + ((a.radius - b.radius) / 2) * N[c];
        }
        out.separations[count] = sep;
        out.ids[count] = k + 1;
        count += 1;
      }
      if (count > 0) {
        out.count = count;
        return true;
      }
    }
  }
  // one point, midway between the surfaces along the normal
  const along = a.radius + separation / 2;
  for (let c = 0; c < n; c += 1) out.points[c] = xa[c] + s * ua[c] + along * N[c];
  out.separations[0] = separation;
  out.ids[0] = 0;
  out.count = 1;
  return true;
}
