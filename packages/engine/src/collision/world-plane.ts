/**
 * The world plane of a posed half-space. Unchecked, allocation-free.
 *
 * @module
 */
import type { Pose } from './manifold.js';
import type { CollisionHalfSpace } from './narrowphase-shapes.js';

/**
 * Writes the unit outward world normal N of half-space `h` at `pose` into `outNormal` and the
 * plane height into `outHeight[slot]`: the world solid is {x : N·x <= height}. The local normal
 * need not be unit.
 */
export function worldPlane(
  outNormal: Float64Array,
  n: number,
  h: CollisionHalfSpace,
  pose: Pose,
  outHeight: Float64Array,
  slot: number,
): void {
  const local = h.normal;
  let len2 = 0;
  for (let c = 0; c < n; c += 1) len2 += local[c] * local[c];
  const inv = 1 / Math.sqrt(len2);
  const M = pose.M;
  const x = pose.x;
  let height = h.offset * inv;
  for (let i = 0; i < n; i += 1) {
    let s = 0;
    for (let c = 0; c < n; c += 1) s += M[i * n + c] * local[c];
    s *= inv;
    outNormal[i] = s;
    height += s * x[i];
  }
  outHeight[slot] = height;
}
