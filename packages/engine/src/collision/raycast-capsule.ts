/**
 * The ray cast against a capsule in its local frame (the capsule: the points within r of the
 * segment ±h·e₁). Pure arithmetic on the caller's arrays; allocates nothing.
 *
 * @module
 */

/** Returned by {@link capsuleRayLocal} when the ray starts inside the capsule (or on it). */
export const CAPSULE_RAY_INSIDE = -2;

/**
 * The first hit of the ray o + t·d (d unit, local frame) on the capsule of half-height `h` and
 * radius `r`, for t in [0, maxDistance]: the capsule is the union of the finite cylinder round
 * the segment and the balls at its ends, so its first boundary point is the earliest of the
 * cylinder's side (entered where |y| <= h) and the two balls (each a quadratic in t, solved
 * without cancellation). Writes the outward unit normal at the hit into `outNormal` (local).
 *
 * @returns the distance t, −1 for a miss, or {@link CAPSULE_RAY_INSIDE} when o lies in the
 *   closed capsule.
 */
export function capsuleRayLocal(
  n: number,
  h: number,
  r: number,
  o: ArrayLike<number>,
  d: ArrayLike<number>,
  maxDistance: number,
  outNormal: Float64Array,
): number {
  const r2 = r * r;
  const y0 = o[1]!;
  const yc = y0 < -h ? -h : y0 > h ? h : y0;
  let perp2 = 0;
  let a = 0;
  let b = 0;
  for (let k = 0; k < n; k += 1) {
    if (k === 1) continue;
    perp2 += o[k]! * o[k]!;
    a += d[k]! * d[k]!;
    b += o[k]! * d[k]!;
  }
  if (perp2 + (y0 - yc) * (y0 - yc) <= r2) return CAPSULE_RAY_INSIDE;
  let best = Infinity;
  let which = 0; // 1: the side, 2: the ball at −h, 3: the ball at +h
  const c = perp2 - r2;
  if (c > 0 && b < 0 && a > 0) {
    const disc = b * b - a * c;
    if (disc >= 0) {
      const t = c / (-b + Math.sqrt(disc));
      const y = y0 + t * d[1]!;
      if (y >= -h && y <= h) {
        best = t;
        which = 1;
      }
    }
  }
  for (let end = 0; end < 2; end += 1) {
    const yEnd = end === 0 ? -h : h;
    const wy = y0 - yEnd;
    const bb = b + wy * d[1]!;
    const cc = perp2 + wy * wy - r2;
    if (!(bb < 0)) continue;
    const disc = bb * bb - cc;
    if (disc < 0) continue;
    const t = cc / (-bb + Math.sqrt(disc));
    if (t < best) {
      best = t;
      which = end + 2;
    }
  }
  if (which === 0 || best > maxDistance) return -1;
  const yCentre = which === 1 ? y0 + best * d[1]! : which === 2 ? -h : h;
  let s = 0;
  for (let k = 0; k < n; k += 1) {
    const v = k === 1 ? y0 + best * d[1]! - yCentre : o[k]! + best * d[k]!;
    outNormal[k] = v;
    s += v * v;
  }
  const inv = 1 / Math.sqrt(s);
  for (let k = 0; k < n; k += 1) outNormal[k] *= inv;
  return best;
}
