/**
 * Bivectors: angular velocity, torque and angular momentum in n dimensions.
 *
 * A bivector has k = n(n-1)/2 components, one per plane (i, j), i < j, in lexicographic order
 * (n = 4: xy, xz, xw, yz, yw, zw). A positive component ω_ij turns e_i toward e_j. The matching
 * antisymmetric matrix Ω has Ω[j][i] = +ω_ij and Ω[i][j] = −ω_ij, so the velocity of a body
 * point at arm r is Ω r. Units are those of the quantity stored (rad/s, N·m, kg·m²/s).
 */
import type { Dims } from './dims.js';
import {
  checkArray,
  checkBivector,
  checkDims,
  checkNumber,
  checkOut,
  checkOutBivector,
  checkOutMatrix,
  checkOutVector,
  checkMatrix,
  checkPlane,
  checkVector,
} from './validate.js';

const commutatorScratch: (Float64Array | undefined)[] = [];

/**
 * out = a ∧ b: (a ∧ b)_ij = a_i b_j − a_j b_i. The torque of a force F at arm r is r ∧ F.
 * `out` (k numbers) may not alias the vectors (it has another length anyway).
 */
export function wedge(D: Dims, out: Float64Array, a: ArrayLike<number>, b: ArrayLike<number>): Float64Array {
  const fn = 'wedge';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkVector(D, 'a', a, fn);
  checkVector(D, 'b', b, fn);
  const { k, planeI, planeJ } = D;
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    out[p] = a[i]! * b[j]! - a[j]! * b[i]!;
  }
  return out;
}

/**
 * out = scale · e_ij, the bivector of plane (i, j) turning e_i toward e_j. For i > j this is
 * −scale on the stored plane (j, i), since e_ij = −e_ji.
 * @throws RangeError for axes out of range or i == j, or a non-finite scale.
 */
export function planeBivector(D: Dims, out: Float64Array, i: number, j: number, scale = 1): Float64Array {
  const fn = 'planeBivector';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkPlane(D, 'i', i, 'j', j, fn);
  checkNumber('scale', scale, fn);
  out.fill(0);
  out[D.planeIndexOf[i * D.n + j]!] = i < j ? scale : -scale;
  return out;
}

/** out (n×n, row-major) = Ω, the antisymmetric matrix of B: Ω[j][i] = +B_ij, Ω[i][j] = −B_ij. */
export function bivectorToMatrix(D: Dims, out: Float64Array, B: ArrayLike<number>): Float64Array {
  const fn = 'bivectorToMatrix';
  checkDims(D, fn);
  checkOutMatrix(D, 'out', out, fn);
  checkBivector(D, 'B', B, fn);
  return bivectorToMatrixUnchecked(D, out, B);
}

/** Unchecked form of {@link bivectorToMatrix}. */
export function bivectorToMatrixUnchecked(D: Dims, out: Float64Array, B: ArrayLike<number>): Float64Array {
  const { n, k, planeI, planeJ } = D;
  out.fill(0);
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    out[j * n + i] = B[p]!;
    out[i * n + j] = -B[p]!;
  }
  return out;
}

/**
 * out = the bivector of the antisymmetric part of M: out_ij = (M[j][i] − M[i][j]) / 2. Inverse of
 * `bivectorToMatrix` on antisymmetric matrices; for a rotation matrix I + Ω + O(Ω²) it gives the
 * small turn Ω.
 */
export function matrixToBivector(D: Dims, out: Float64Array, M: ArrayLike<number>): Float64Array {
  const fn = 'matrixToBivector';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkMatrix(D, 'M', M, fn);
  const { n, k, planeI, planeJ } = D;
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    out[p] = 0.5 * (M[j * n + i]! - M[i * n + j]!);
  }
  return out;
}

/**
 * out = the bivector of the matrix commutator Ω_A Ω_B − Ω_B Ω_A (in 3D, with the dictionary
 * ω_yz = ω_x, ω_xz = −ω_y, ω_xy = ω_z, this is a cross product). `out` may alias A or B.
 */
export function bivectorCommutator(D: Dims, out: Float64Array, A: ArrayLike<number>, B: ArrayLike<number>): Float64Array {
  const fn = 'bivectorCommutator';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkBivector(D, 'A', A, fn);
  checkBivector(D, 'B', B, fn);
  const { n, k } = D;
  const s = commutatorScratch[n] ?? (commutatorScratch[n] = new Float64Array(2 * n * n + k));
  const res = s.subarray(2 * n * n);
  bivectorCommutatorUnchecked(D, res, A, B, s.subarray(0, n * n), s.subarray(n * n, 2 * n * n));
  out.set(res);
  return out;
}

/**
 * {@link bivectorCommutator} without checks or allocation, for hot loops: `a` and `b` are n×n
 * scratch; `out` must not alias A or B.
 */
export function bivectorCommutatorUnchecked(
  D: Dims,
  out: Float64Array,
  A: ArrayLike<number>,
  B: ArrayLike<number>,
  a: Float64Array,
  b: Float64Array,
): Float64Array {
  const { n, k, planeI, planeJ } = D;
  bivectorToMatrixUnchecked(D, a, A);
  bivectorToMatrixUnchecked(D, b, B);
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    // Entry [j][i] of the commutator (it is antisymmetric, so that entry is its component).
    let x = 0;
    for (let m = 0; m < n; m += 1) x += a[j * n + m]! * b[m * n + i]! - b[j * n + m]! * a[m * n + i]!;
    out[p] = x;
  }
  return out;
}

/**
 * out = Ω_B v: the velocity of the body point at arm v under angular velocity B (equivalently
 * [v]*ᵀ B, the left contraction v ⌋ B). `out` may not alias `v`.
 */
export function bivectorApply(D: Dims, out: Float64Array, B: ArrayLike<number>, v: ArrayLike<number>): Float64Array {
  const fn = 'bivectorApply';
  checkDims(D, fn);
  checkOutVector(D, 'out', out, fn);
  checkBivector(D, 'B', B, fn);
  checkVector(D, 'v', v, fn);
  if (out === v) throw new RangeError(`${fn}: argument 'out' must not be the same array as 'v'`);
  const { k, planeI, planeJ } = D;
  out.fill(0);
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    const w = B[p]!;
    out[j] = out[j]! + w * v[i]!;
    out[i] = out[i]! - w * v[j]!;
  }
  return out;
}

/**
 * out (k×n, row-major) = [r]*, the matrix with r ∧ a = [r]* a: row (ij) has +r_i in column j and
 * −r_j in column i. Its transpose maps a bivector ω to the velocity [r]*ᵀ ω = Ω r, and
 * [r]* [r]*ᵀ summed over mass points is the inertia operator.
 */
export function wedgeMatrix(D: Dims, out: Float64Array, r: ArrayLike<number>): Float64Array {
  const fn = 'wedgeMatrix';
  checkDims(D, fn);
  checkOut('out', out, D.k * D.n, `a ${D.k}x${D.n} matrix for n = ${D.n}`, fn);
  checkVector(D, 'r', r, fn);
  const { n, k, planeI, planeJ } = D;
  out.fill(0);
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    out[p * n + j] = r[i]!;
    out[p * n + i] = -r[j]!;
  }
  return out;
}

/** Plain dot product over the k components (power = τ · ω; energy = ½ L · ω). */
export function bivectorDot(D: Dims, A: ArrayLike<number>, B: ArrayLike<number>): number {
  const fn = 'bivectorDot';
  checkDims(D, fn);
  checkBivector(D, 'A', A, fn);
  checkBivector(D, 'B', B, fn);
  let s = 0;
  for (let p = 0; p < D.k; p += 1) s += A[p]! * B[p]!;
  return s;
}

/** Euclidean norm over the k components (for a simple bivector: its angle or rate). */
export function bivectorNorm(D: Dims, B: ArrayLike<number>): number {
  const fn = 'bivectorNorm';
  checkDims(D, fn);
  checkBivector(D, 'B', B, fn);
  let s = 0;
  for (let p = 0; p < D.k; p += 1) s += B[p]! * B[p]!;
  return Math.sqrt(s);
}

/**
 * The Pfaffian of a 4D bivector, b_xy b_zw − b_xz b_yw + b_xw b_yz (B ∧ B = 2 Pf e0123).
 * Zero exactly when B is simple (a single plane). 4D only: B must have 6 components.
 */
export function pfaffian4(B: ArrayLike<number>): number {
  checkArray('B', B, 6, 'a bivector for n = 4', 'pfaffian4');
  return B[0]! * B[5]! - B[1]! * B[4]! + B[2]! * B[3]!;
}

/**
 * The Euclidean norm of the 4-vector B ∧ B, whose component on axes a < b < c < d is
 * 2 (B_ab B_cd − B_ac B_bd + B_ad B_bc). Zero exactly for a simple bivector; always 0 for n < 4.
 */
export function bivectorWedgeSelfNorm(D: Dims, B: ArrayLike<number>): number {
  const fn = 'bivectorWedgeSelfNorm';
  checkDims(D, fn);
  checkBivector(D, 'B', B, fn);
  return wedgeSelfNorm(D, B);
}

function wedgeSelfNorm(D: Dims, B: ArrayLike<number>): number {
  const { n, planeIndexOf: P } = D;
  let s = 0;
  for (let a = 0; a < n; a += 1) {
    for (let b = a + 1; b < n; b += 1) {
      for (let c = b + 1; c < n; c += 1) {
        for (let d = c + 1; d < n; d += 1) {
          const x =
            2 *
            (B[P[a * n + b]!]! * B[P[c * n + d]!]! -
              B[P[a * n + c]!]! * B[P[b * n + d]!]! +
              B[P[a * n + d]!]! * B[P[b * n + c]!]!);
          s += x * x;
        }
      }
    }
  }
  return Math.sqrt(s);
}

/**
 * Whether B is simple (one plane) to within a relative tolerance chosen by the caller:
 * |B ∧ B| <= tol · |B|². The zero bivector is simple.
 * @throws RangeError if tol is negative or not finite.
 */
export function isSimple(D: Dims, B: ArrayLike<number>, tol: number): boolean {
  const fn = 'isSimple';
  checkDims(D, fn);
  checkBivector(D, 'B', B, fn);
  checkNumber('tol', tol, fn);
  if (tol < 0) throw new RangeError(`${fn}: argument 'tol' must be >= 0, got ${tol}`);
  let b2 = 0;
  for (let p = 0; p < D.k; p += 1) b2 += B[p]! * B[p]!;
  return wedgeSelfNorm(D, B) <= tol * b2;
}
