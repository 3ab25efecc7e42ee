/**
 * Growth by doubling of the flat arrays the step keeps (contacts, solver rows, islands): they grow
 * to the scene once and then are reused, so a step in steady state allocates nothing.
 *
 * @module
 */

/** Grows a Float64Array to at least `need` entries, doubling, keeping the first `keep`. */
export function growFloat64(a: Float64Array, need: number, keep = a.length): Float64Array<ArrayBuffer> {
  if (need <= a.length) return a as Float64Array<ArrayBuffer>;
  let len = Math.max(1, a.length);
  while (len < need) len *= 2;
  const out = new Float64Array(len);
  out.set(a.subarray(0, Math.min(keep, a.length)));
  return out;
}

/** Grows an Int32Array to at least `need` entries, doubling, keeping the first `keep`. */
export function growInt32(a: Int32Array, need: number, keep = a.length): Int32Array<ArrayBuffer> {
  if (need <= a.length) return a as Int32Array<ArrayBuffer>;
  let len = Math.max(1, a.length);
  while (len < need) len *= 2;
  const out = new Int32Array(len);
  out.set(a.subarray(0, Math.min(keep, a.length)));
  return out;
}
