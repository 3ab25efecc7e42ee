/**
 * Inertia in n dimensions: the k×k operator L = I(ω) from the body's mass-weighted second
 * moment (covariance) C = ∫ x xᵀ dm about its centre of mass (units kg·m²).
 *
 * I[(ij),(kl)] = δ_jl C_ik − δ_jk C_il − δ_il C_jk + δ_ik C_jl, which is ∫ [r]* [r]*ᵀ dm. In the
 * principal frame of C (C diagonal) the operator is diagonal with I_(ij) = C_ii + C_jj, which is
 * how bodies store it.
 */
import type { Dims } from './tables.js';
import {
  checkArray,
  checkBivector,
  checkDims,
  checkMatrix,
  checkNumber,
  checkOutBivector,
  checkOutMatrix,
  checkOutOperator,
  checkRotor,
  checkVector,
} from './validate.js';

/**
 * out (k×k, row-major) = the inertia operator of the covariance C (n×n, symmetric, about the
 * centre of mass). Only meaningful for symmetric C; the formula reads C as given.
 */
export function inertiaFromCovariance(D: Dims, out: Float64Array, C: ArrayLike<number>): Float64Array {
  const fn = 'inertiaFromCovariance';
  checkDims(D, fn);
  checkOutOperator(D, 'out', out, fn);
  checkMatrix(D, 'C', C, fn);
  const { n, k, planeI, planeJ } = D;
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    for (let q = 0; q < k; q += 1) {
      const a = planeI[q]!;
      const b = planeJ[q]!;
      let x = 0;
      if (j === b) x += C[i * n + a]!;
      if (j === a) x -= C[i * n + b]!;
      if (i === b) x -= C[j * n + a]!;
      if (i === a) x += C[j * n + b]!;
      out[p * k + q] = x;
    }
  }
  return out;
}

/**
 * out (k numbers) = the diagonal inertia of a body in its principal frame, from the n diagonal
 * covariances c_i = ∫ x_i² dm: I_(ij) = c_i + c_j.
 */
export function inertiaDiagonal(D: Dims, out: Float64Array, c: ArrayLike<number>): Float64Array {
  const fn = 'inertiaDiagonal';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkArray('c', c, D.n, `${D.n} principal covariances`, fn);
  const { k, planeI, planeJ } = D;
  for (let p = 0; p < k; p += 1) out[p] = c[planeI[p]!]! + c[planeJ[p]!]!;
  return out;
}

/**
 * out = C + mass · d dᵀ (n×n): the parallel-axis rule for covariances.
 *
 * Sign convention: d is the position of the centre of mass measured FROM the new reference point
 * p (d = c − p; the new point sits at −d from the centre of mass). With C the covariance about the
 * centre of mass, the result is the covariance about p. The rule also runs backwards: with C the
 * covariance about p and a NEGATIVE `mass` −m, the result C_p − m d dᵀ is the covariance about the
 * centre of mass (the mesh mass routines need this). `out` may alias C.
 * @throws RangeError for a non-finite mass.
 */
export function parallelAxisShift(
  D: Dims,
  out: Float64Array,
  C: ArrayLike<number>,
  mass: number,
  d: ArrayLike<number>,
): Float64Array {
  const fn = 'parallelAxisShift';
  checkDims(D, fn);
  checkOutMatrix(D, 'out', out, fn);
  checkMatrix(D, 'C', C, fn);
  checkNumber('mass', mass, fn);
  checkVector(D, 'd', d, fn);
  const n = D.n;
  for (let i = 0; i < n; i += 1) {
    for (let j = 0; j < n; j += 1) out[i * n + j] = C[i * n + j]! + mass * d[i]! * d[j]!;
  }
  return out;
}

const worldScratch: (Float64Array | undefined)[] = [];

/**
 * out = ω = R · I⁻¹(R~ L R) · R~: the world-frame angular velocity of a body with orientation R,
 * body-frame inverse principal inertia `invInertiaDiag` (k numbers, 1/(c_i + c_j)) and world
 * angular momentum L. Validates, then calls {@link inertiaWorldInverseUnchecked}. `out` may alias L.
 * `scratch` (k numbers) is optional; without it a per-dimension buffer is used. Allocates nothing.
 */
export function inertiaWorldInverse(
  D: Dims,
  out: Float64Array,
  R: ArrayLike<number>,
  invInertiaDiag: ArrayLike<number>,
  L: ArrayLike<number>,
  scratch?: Float64Array,
): Float64Array {
  const fn = 'inertiaWorldInverse';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  checkBivector(D, 'invInertiaDiag', invInertiaDiag, fn);
  checkBivector(D, 'L', L, fn);
  if (scratch !== undefined) checkOutBivector(D, 'scratch', scratch, fn);
  return inertiaWorldInverseUnchecked(D, out, R as Float64Array, invInertiaDiag, L as Float64Array, scratch);
}

/**
 * Unchecked hot-path form of {@link inertiaWorldInverse} (no validation: the engine calls it on
 * data checked when it entered the world). `out` may alias L. Allocates nothing.
 */
export function inertiaWorldInverseUnchecked(
  D: Dims,
  out: Float64Array,
  R: Float64Array,
  invInertiaDiag: ArrayLike<number>,
  L: Float64Array,
  scratch?: Float64Array,
): Float64Array {
  const s = scratch ?? worldScratch[D.n] ?? (worldScratch[D.n] = new Float64Array(D.k));
  D.kernels.applyBivectorInverse(s, R, L);
  for (let p = 0; p < D.k; p += 1) s[p] = s[p]! * invInertiaDiag[p]!;
  return D.kernels.applyBivector(out, R, s);
}
