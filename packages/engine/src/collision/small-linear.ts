/**
 * Tiny dense solvers for the narrowphase (systems of at most 9×9). Unchecked, allocation-free.
 * Matrices are row-major with row stride m. One code for both forms (a matrix alone, or one of
 * several side by side): the offsets add integers, so the results are the same bits.
 *
 * @module
 */

/**
 * LU factorisation with partial pivoting of the m×m matrix `a`, in place; `piv` receives the row
 * order. Returns false (the matrix counts as singular) when a pivot is <= `tolerance` × the
 * largest absolute entry, or the matrix is zero.
 */
export function luFactor(m: number, a: Float64Array, piv: Int32Array, tolerance: number): boolean {
  return luFactorAt(m, a, 0, piv, 0, tolerance);
}

/** Solves a x = b with the factors of {@link luFactor}; `b` is read, `x` written (distinct arrays). */
export function luSolve(m: number, a: Float64Array, piv: Int32Array, b: ArrayLike<number>, x: Float64Array): Float64Array {
  return luSolveAt(m, a, 0, piv, 0, b, x);
}

/**
 * {@link luFactor} on the m×m matrix stored at a[o ..], with the row order at piv[po ..]
 * (several factorisations side by side in one buffer).
 */
export function luFactorAt(m: number, a: Float64Array, o: number, piv: Int32Array, po: number, tolerance: number): boolean {
  let scale = 0;
  for (let i = 0; i < m * m; i += 1) scale = Math.max(scale, Math.abs(a[o + i]));
  if (!(scale > 0)) return m === 0;
  const limit = tolerance * scale;
  for (let i = 0; i < m; i += 1) piv[po + i] = i;
  for (let col = 0; col < m; col += 1) {
    let p = col;
    let best = Math.abs(a[o + col * m + col]);
    for (let row = col + 1; row < m; row += 1) {
      const v = Math.abs(a[o + row * m + col]);
      if (v > best) {
        best = v;
        p = row;
      }
    }
    if (!(best > limit)) return false;
    if (p !== col) {
      for (let c = 0; c < m; c += 1) {
        const t = a[o + col * m + c];
        a[o + col * m + c] = a[o + p * m + c];
        a[o + p * m + c] = t;
      }
      const t = piv[po + col];
      piv[po + col] = piv[po + p];
      piv[po + p] = t;
    }
    const d = a[o + col * m + col];
    for (let row = col + 1; row < m; row += 1) {
      const f = a[o + row * m + col] / d;
      a[o + row * m + col] = f;
      if (f === 0) continue;
      for (let c = col + 1; c < m; c += 1) a[o + row * m + c] -= f * a[o + col * m + c];
    }
  }
  return true;
}

/** {@link luSolve} with the factors of {@link luFactorAt} at a[o ..], piv[po ..]. */
export function luSolveAt(
  m: number,
  a: Float64Array,
  o: number,
  piv: Int32Array,
  po: number,
  b: ArrayLike<number>,
  x: Float64Array,
): Float64Array {
  for (let i = 0; i < m; i += 1) {
    let s = b[piv[po + i]];
    for (let c = 0; c < i; c += 1) s -= a[o + i * m + c] * x[c];
    x[i] = s;
  }
  for (let i = m - 1; i >= 0; i -= 1) {
    let s = x[i];
    for (let c = i + 1; c < m; c += 1) s -= a[o + i * m + c] * x[c];
    x[i] = s / a[o + i * m + i];
  }
  return x;
}
