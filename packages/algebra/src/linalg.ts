/**
 * Small dense linear algebra on row-major Float64Array matrices (`M[row * n + col]`).
 *
 * Sizes are small (n <= 8 for frames, k <= 28 for bivector operators). Every function keeps its
 * working storage in per-size scratch built on first use, so repeated calls allocate nothing.
 * Public functions validate their arguments; the `...Unchecked` variants are hot-path kernels
 * that trust their caller.
 */
import { checkArray, checkInteger, checkOut } from './validate.js';

/** Largest size accepted by the linear algebra (a k×k operator for n = 8 has k = 28). */
const MAX_SIZE = 64;

interface LinalgScratch {
  a: Float64Array;
  b: Float64Array;
  c: Float64Array;
  /** Private to determinantUnchecked, which the other routines call on their own scratch. */
  det: Float64Array;
}

const scratchBySize: (LinalgScratch | undefined)[] = [];

function scratchFor(n: number): LinalgScratch {
  let s = scratchBySize[n];
  if (s === undefined) {
    s = {
      a: new Float64Array(n * n),
      b: new Float64Array(n * n),
      c: new Float64Array(n * n),
      det: new Float64Array(n * n),
    };
    scratchBySize[n] = s;
  }
  return s;
}

function checkSize(n: unknown, fn: string): asserts n is number {
  checkInteger('n', n, 1, MAX_SIZE, fn);
}

/**
 * out = A B for n×n row-major matrices. `out` may alias `A` or `B`.
 * @throws TypeError/RangeError on a bad size, wrong lengths or non-finite entries.
 */
export function matMul(n: number, out: Float64Array, A: ArrayLike<number>, B: ArrayLike<number>): Float64Array {
  const fn = 'matMul';
  checkSize(n, fn);
  checkOut('out', out, n * n, `an ${n}x${n} matrix`, fn);
  checkArray('A', A, n * n, `an ${n}x${n} matrix`, fn);
  checkArray('B', B, n * n, `an ${n}x${n} matrix`, fn);
  return matMulUnchecked(n, out, A, B);
}

/** Unchecked hot-path form of {@link matMul}; `out` may alias `A` or `B`. Allocates nothing. */
export function matMulUnchecked(n: number, out: Float64Array, A: ArrayLike<number>, B: ArrayLike<number>): Float64Array {
  const t = scratchFor(n).c;
  for (let i = 0; i < n; i += 1) {
    for (let j = 0; j < n; j += 1) {
      let s = 0;
      for (let m = 0; m < n; m += 1) s += A[i * n + m]! * B[m * n + j]!;
      t[i * n + j] = s;
    }
  }
  out.set(t);
  return out;
}

/**
 * Determinant of an n×n matrix by LU decomposition with partial pivoting.
 * @throws TypeError/RangeError on a bad size, wrong length or non-finite entries.
 */
export function determinant(n: number, M: ArrayLike<number>): number {
  const fn = 'determinant';
  checkSize(n, fn);
  checkArray('M', M, n * n, `an ${n}x${n} matrix`, fn);
  return determinantUnchecked(n, M);
}

/** Unchecked form of {@link determinant}. Allocates nothing. */
export function determinantUnchecked(n: number, M: ArrayLike<number>): number {
  const a = scratchFor(n).det;
  for (let i = 0; i < n * n; i += 1) a[i] = M[i]!;
  let det = 1;
  for (let col = 0; col < n; col += 1) {
    let piv = col;
    let best = Math.abs(a[col * n + col]!);
    for (let row = col + 1; row < n; row += 1) {
      const v = Math.abs(a[row * n + col]!);
      if (v > best) {
        best = v;
        piv = row;
      }
    }
    if (best === 0) return 0;
    if (piv !== col) {
      for (let c = 0; c < n; c += 1) {
        const tmp = a[col * n + c]!;
        a[col * n + c] = a[piv * n + c]!;
        a[piv * n + c] = tmp;
      }
      det = -det;
    }
    const p = a[col * n + col]!;
    det *= p;
    for (let row = col + 1; row < n; row += 1) {
      const f = a[row * n + col]! / p;
      if (f === 0) continue;
      for (let c = col + 1; c < n; c += 1) a[row * n + c] = a[row * n + c]! - f * a[col * n + c]!;
    }
  }
  return det;
}

/** Most sweeps of the Jacobi method; it converges quadratically, so this is never reached in practice. */
const JACOBI_MAX_SWEEPS = 100;

/**
 * Eigen-decomposition of a real symmetric n×n matrix by the cyclic Jacobi method.
 *
 * Writes the eigenvalues, sorted in descending order, into `outValues` (n entries) and the unit
 * eigenvectors as the COLUMNS of `outVectors` (n×n row-major, `outVectors[i*n + c]` = component i
 * of eigenvector c), so A = V diag(values) Vᵀ. The columns are made a right-handed frame
 * (det V = +1) by flipping the sign of the last one when needed, which lets V be used directly as
 * a rotation. Only the symmetric part (A + Aᵀ)/2 is used. Iteration stops when the off-diagonal
 * mass is at the level of rounding (machine epsilon relative to the matrix norm): a property of
 * floating point, not a tolerance of the caller.
 * @throws TypeError/RangeError on a bad size, wrong lengths or non-finite entries.
 */
export function symmetricEigen(n: number, outValues: Float64Array, outVectors: Float64Array, A: ArrayLike<number>): Float64Array {
  const fn = 'symmetricEigen';
  checkSize(n, fn);
  checkOut('outValues', outValues, n, `${n} eigenvalues`, fn);
  checkOut('outVectors', outVectors, n * n, `an ${n}x${n} matrix`, fn);
  checkArray('A', A, n * n, `a symmetric ${n}x${n} matrix`, fn);
  if (outValues === outVectors) {
    throw new RangeError(`${fn}: arguments 'outValues' and 'outVectors' must be different arrays`);
  }
  return symmetricEigenUnchecked(n, outValues, outVectors, A);
}

/** Unchecked form of {@link symmetricEigen}; `outVectors` may alias `A`. Allocates nothing. Returns `outValues`. */
export function symmetricEigenUnchecked(
  n: number,
  outValues: Float64Array,
  outVectors: Float64Array,
  A: ArrayLike<number>,
): Float64Array {
  const { a, b: v } = scratchFor(n);
  let norm2 = 0;
  for (let i = 0; i < n; i += 1) {
    for (let j = 0; j < n; j += 1) {
      const x = 0.5 * (A[i * n + j]! + A[j * n + i]!);
      a[i * n + j] = x;
      norm2 += x * x;
      v[i * n + j] = i === j ? 1 : 0;
    }
  }
  const stop = norm2 * Number.EPSILON * Number.EPSILON;
  for (let sweep = 0; sweep < JACOBI_MAX_SWEEPS; sweep += 1) {
    let off = 0;
    for (let p = 0; p < n; p += 1) for (let q = p + 1; q < n; q += 1) off += 2 * a[p * n + q]! ** 2;
    if (off <= stop) break;
    for (let p = 0; p < n - 1; p += 1) {
      for (let q = p + 1; q < n; q += 1) {
        const apq = a[p * n + q]!;
        if (apq === 0) continue;
        const theta = (a[q * n + q]! - a[p * n + p]!) / (2 * apq);
        // t = tan of the rotation angle, the smaller root (stable); 1/(2θ) when θ² would overflow.
        const t =
          Math.abs(theta) > 1e150 ? 1 / (2 * theta) : (theta >= 0 ? 1 : -1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
        const c = 1 / Math.sqrt(t * t + 1);
        const s = t * c;
        for (let r = 0; r < n; r += 1) {
          const x = a[r * n + p]!;
          const y = a[r * n + q]!;
          a[r * n + p] = c * x - s * y;
          a[r * n + q] = s * x + c * y;
        }
        for (let r = 0; r < n; r += 1) {
          const x = a[p * n + r]!;
          const y = a[q * n + r]!;
          a[p * n + r] = c * x - s * y;
          a[q * n + r] = s * x + c * y;
        }
        a[p * n + q] = 0;
        a[q * n + p] = 0;
        for (let r = 0; r < n; r += 1) {
          const x = v[r * n + p]!;
          const y = v[r * n + q]!;
          v[r * n + p] = c * x - s * y;
          v[r * n + q] = s * x + c * y;
        }
      }
    }
  }
  // Selection sort, descending, moving eigenvector columns along with their values.
  for (let i = 0; i < n; i += 1) outValues[i] = a[i * n + i]!;
  for (let i = 0; i < n - 1; i += 1) {
    let m = i;
    for (let j = i + 1; j < n; j += 1) if (outValues[j]! > outValues[m]!) m = j;
    if (m !== i) {
      const tv = outValues[i]!;
      outValues[i] = outValues[m]!;
      outValues[m] = tv;
      for (let r = 0; r < n; r += 1) {
        const tmp = v[r * n + i]!;
        v[r * n + i] = v[r * n + m]!;
        v[r * n + m] = tmp;
      }
    }
  }
  if (determinantUnchecked(n, v) < 0) {
    for (let r = 0; r < n; r += 1) v[r * n + n - 1] = -v[r * n + n - 1]!;
  }
  outVectors.set(v);
  return outValues;
}

/**
 * Largest number of Newton–Schulz steps; from the start the method guarantees (residual < 1) it
 * needs about 6 to reach rounding level, so this bound only guards against a non-terminating loop.
 */
const POLAR_MAX_STEPS = 60;

/**
 * out = an orthogonal matrix close to M (n×n, row-major).
 *
 * After scaling M so that its Frobenius norm is √n (the polar factor does not depend on a positive
 * scale), if ‖MᵀM − 1‖_F < 1 the result is the NEAREST orthogonal matrix (the polar factor of M, by
 * Newton–Schulz iteration X ← X (3 − XᵀX)/2, quadratically convergent there): the case of a
 * rotation matrix that has drifted, as in rotor correction. Otherwise M is too far from a rotation
 * for "nearest" to be cheap, and the columns are made orthonormal by modified Gram–Schmidt (done
 * twice for accuracy; a column that depends on the previous ones is replaced by the basis
 * direction most orthogonal to them). The sign of the determinant is kept (det M > 0 gives a
 * rotation). `out` may alias `M`.
 * @throws TypeError/RangeError on a bad size, wrong lengths or non-finite entries.
 */
export function orthonormalize(n: number, out: Float64Array, M: ArrayLike<number>): Float64Array {
  const fn = 'orthonormalize';
  checkSize(n, fn);
  checkOut('out', out, n * n, `an ${n}x${n} matrix`, fn);
  checkArray('M', M, n * n, `an ${n}x${n} matrix`, fn);
  return orthonormalizeUnchecked(n, out, M);
}

function gramResidual(n: number, X: Float64Array): number {
  let r = 0;
  for (let i = 0; i < n; i += 1) {
    for (let j = 0; j < n; j += 1) {
      let s = 0;
      for (let m = 0; m < n; m += 1) s += X[m * n + i]! * X[m * n + j]!;
      const d = s - (i === j ? 1 : 0);
      r += d * d;
    }
  }
  return Math.sqrt(r);
}

/** Unchecked form of {@link orthonormalize}; `out` may alias `M`. Allocates nothing. */
export function orthonormalizeUnchecked(n: number, out: Float64Array, M: ArrayLike<number>): Float64Array {
  const { a: x, b: g, c: y } = scratchFor(n);
  let f2 = 0;
  for (let i = 0; i < n * n; i += 1) f2 += M[i]! * M[i]!;
  const scale = f2 > 0 ? Math.sqrt(n / f2) : 1;
  for (let i = 0; i < n * n; i += 1) x[i] = M[i]! * scale;
  let res = gramResidual(n, x);
  if (res < 1) {
    for (let step = 0; step < POLAR_MAX_STEPS && res > 0; step += 1) {
      // g = (3 - XᵀX)/2, then X ← X g
      for (let i = 0; i < n; i += 1) {
        for (let j = 0; j < n; j += 1) {
          let s = 0;
          for (let m = 0; m < n; m += 1) s += x[m * n + i]! * x[m * n + j]!;
          g[i * n + j] = ((i === j ? 3 : 0) - s) * 0.5;
        }
      }
      for (let i = 0; i < n; i += 1) {
        for (let j = 0; j < n; j += 1) {
          let s = 0;
          for (let m = 0; m < n; m += 1) s += x[i * n + m]! * g[m * n + j]!;
          y[i * n + j] = s;
        }
      }
      const next = gramResidual(n, y);
      if (next < res) x.set(y);
      // Convergence is quadratic, so a step that no longer halves the residual means rounding level.
      if (next >= 0.5 * res) break;
      res = next;
    }
    out.set(x);
    return out;
  }
  const detSign = determinantUnchecked(n, x) < 0 ? -1 : 1;
  for (let pass = 0; pass < 2; pass += 1) {
    for (let c = 0; c < n; c += 1) {
      let before = 0;
      for (let i = 0; i < n; i += 1) before += x[i * n + c]! ** 2;
      for (let p = 0; p < c; p += 1) {
        let d = 0;
        for (let i = 0; i < n; i += 1) d += x[i * n + p]! * x[i * n + c]!;
        for (let i = 0; i < n; i += 1) x[i * n + c] = x[i * n + c]! - d * x[i * n + p]!;
      }
      let len = 0;
      for (let i = 0; i < n; i += 1) len += x[i * n + c]! ** 2;
      // Relative size below which a column is taken as dependent on the previous ones (rounding level).
      if (len <= 1e-28 * before || len === 0) {
        let bestAxis = 0;
        let bestRest = -1;
        for (let e = 0; e < n; e += 1) {
          let rest = 1;
          for (let p = 0; p < c; p += 1) rest -= x[e * n + p]! ** 2;
          if (rest > bestRest) {
            bestRest = rest;
            bestAxis = e;
          }
        }
        for (let i = 0; i < n; i += 1) x[i * n + c] = i === bestAxis ? 1 : 0;
        for (let p = 0; p < c; p += 1) {
          const d = x[bestAxis * n + p]!;
          for (let i = 0; i < n; i += 1) x[i * n + c] = x[i * n + c]! - d * x[i * n + p]!;
        }
        len = 0;
        for (let i = 0; i < n; i += 1) len += x[i * n + c]! ** 2;
      }
      const inv = 1 / Math.sqrt(len);
      for (let i = 0; i < n; i += 1) x[i * n + c] = x[i * n + c]! * inv;
    }
  }
  // A replaced column has an arbitrary orientation: restore the sign of the input's determinant.
  if ((determinantUnchecked(n, x) < 0 ? -1 : 1) !== detSign) {
    for (let i = 0; i < n; i += 1) x[i * n + n - 1] = -x[i * n + n - 1]!;
  }
  out.set(x);
  return out;
}
