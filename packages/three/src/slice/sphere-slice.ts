/**
 * The slice of a hypersphere: a 3-ball of radius √(r² − d²), d the distance from the centre to
 * the flat.
 *
 * @module
 */

/** d²: the squared distance from `x` to the flat whose coordinates 3..n−1 are `slice`. */
export function flatDistanceSquared(x: ArrayLike<number>, slice: ArrayLike<number>): number {
  let d2 = 0;
  for (let a = 3; a < x.length; a += 1) {
    const d = slice[a - 3]! - x[a]!;
    d2 += d * d;
  }
  return d2;
}

/** The radius of the slice of a ball of radius r at x, or 0 when the flat misses it. */
export function sphereSliceRadius(radius: number, x: ArrayLike<number>, slice: ArrayLike<number>): number {
  const s = radius * radius - flatDistanceSquared(x, slice);
  return s > 0 ? Math.sqrt(s) : 0;
}
