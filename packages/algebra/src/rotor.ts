/**
 * Rotors: orientations in n dimensions.
 *
 * A rotor has r = 2^(n-1) components, the even blades ordered by grade then lexicographically
 * (3D: [1, e01, e02, e12]; 4D: [1, e01, e02, e03, e12, e13, e23, e0123]). It turns a vector by
 * x' = R x R~; doing R1 first and then R2 is the rotor R2 R1. The simple rotor of plane (i, j)
 * and angle θ (e_i toward e_j) is cos(θ/2) − sin(θ/2) e_ij. A body spinning with angular
 * velocity B obeys dR/dt = −½ B R.
 *
 * Each function validates its arguments (TypeError / RangeError naming the argument, nothing
 * written on failure) and then calls the unchecked kernel of its dimension, `D.kernels`.
 * Inputs may be any array-like of numbers; outputs are Float64Array.
 */
import type { Dims } from './tables.js';
import { matrixToRotor as matrixToRotorImpl } from './matrix-to-rotor.js';
import {
  checkBivector,
  checkDims,
  checkNumber,
  checkOutBivector,
  checkOutMatrix,
  checkOutRotor,
  checkOutVector,
  checkPlane,
  checkRotor,
  checkVector,
} from './validate.js';

// Kernels index their inputs only, so an array-like input can be handed to them as it is.
type F64 = Float64Array;

const planeScratch: (Float64Array | undefined)[] = [];

/** out = 1, the identity rotor. */
export function rotorIdentity(D: Dims, out: Float64Array): Float64Array {
  checkDims(D, 'rotorIdentity');
  checkOutRotor(D, 'out', out, 'rotorIdentity');
  out.fill(0);
  out[0] = 1;
  return out;
}

/** out = a b, the geometric product: the rotation b followed by a. `out` may alias a or b. */
export function rotorMul(D: Dims, out: Float64Array, a: ArrayLike<number>, b: ArrayLike<number>): Float64Array {
  const fn = 'rotorMul';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkRotor(D, 'a', a, fn);
  checkRotor(D, 'b', b, fn);
  return D.kernels.mul(out, a as F64, b as F64);
}

/** out = R~, the reverse (the inverse rotation for a unit rotor). `out` may alias R. */
export function rotorReverse(D: Dims, out: Float64Array, R: ArrayLike<number>): Float64Array {
  const fn = 'rotorReverse';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  const { r, reverseSign } = D;
  for (let a = 0; a < r; a += 1) out[a] = R[a]! * reverseSign[a]!;
  return out;
}

/** out = R v R~, the vector v turned by R. `out` may alias v. */
export function rotorApplyVector(D: Dims, out: Float64Array, R: ArrayLike<number>, v: ArrayLike<number>): Float64Array {
  const fn = 'rotorApplyVector';
  checkDims(D, fn);
  checkOutVector(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  checkVector(D, 'v', v, fn);
  return D.kernels.applyVector(out, R as F64, v as F64);
}

/** out = R~ v R, the vector v turned by the inverse of R (world → body frame). `out` may alias v. */
export function rotorApplyVectorInverse(D: Dims, out: Float64Array, R: ArrayLike<number>, v: ArrayLike<number>): Float64Array {
  const fn = 'rotorApplyVectorInverse';
  checkDims(D, fn);
  checkOutVector(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  checkVector(D, 'v', v, fn);
  return D.kernels.applyVectorInverse(out, R as F64, v as F64);
}

/** out = R B R~, the bivector B turned by R (body → world frame). `out` may alias B. */
export function rotorApplyBivector(D: Dims, out: Float64Array, R: ArrayLike<number>, B: ArrayLike<number>): Float64Array {
  const fn = 'rotorApplyBivector';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  checkBivector(D, 'B', B, fn);
  return D.kernels.applyBivector(out, R as F64, B as F64);
}

/** out = R~ B R, the bivector B turned by the inverse of R (world → body frame). `out` may alias B. */
export function rotorApplyBivectorInverse(D: Dims, out: Float64Array, R: ArrayLike<number>, B: ArrayLike<number>): Float64Array {
  const fn = 'rotorApplyBivectorInverse';
  checkDims(D, fn);
  checkOutBivector(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  checkBivector(D, 'B', B, fn);
  return D.kernels.applyBivectorInverse(out, R as F64, B as F64);
}

/**
 * out (n×n, row-major) = the rotation matrix of R: column c is R e_c R~, so
 * `out[i*n + c]` is component i of the image of e_c. For a non-unit R the matrix is scaled by |R|².
 */
export function rotorToMatrix(D: Dims, out: Float64Array, R: ArrayLike<number>): Float64Array {
  const fn = 'rotorToMatrix';
  checkDims(D, fn);
  checkOutMatrix(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  return D.kernels.toMatrix(out, R as F64);
}

/**
 * out = the unit rotor of a rotation matrix, rebuilt by reflections (robust at half turns).
 * Its overall sign is unspecified (R and −R are the same rotation).
 * @throws RangeError for a matrix that is not orthogonal to within 1e-6, or has det −1.
 */
export function matrixToRotor(D: Dims, out: Float64Array, M: ArrayLike<number>): Float64Array {
  return matrixToRotorImpl(D, out, M);
}

/** out = the simple rotor turning e_i toward e_j by `angle` radians: cos(θ/2) − sin(θ/2) e_ij. */
export function rotorFromPlane(D: Dims, out: Float64Array, i: number, j: number, angle: number): Float64Array {
  const fn = 'rotorFromPlane';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkPlane(D, 'i', i, 'j', j, fn);
  checkNumber('angle', angle, fn);
  writePlaneRotor(D, out, i, j, angle);
  return out;
}

function writePlaneRotor(D: Dims, out: Float64Array, i: number, j: number, angle: number): void {
  const s = Math.sin(0.5 * angle);
  out.fill(0);
  out[0] = Math.cos(0.5 * angle);
  // e_ji = −e_ij: the stored blade of the plane is (min, max).
  out[1 + D.planeIndexOf[i * D.n + j]!] = i < j ? -s : s;
}

/**
 * out = P R where P turns e_i toward e_j by `angle`: the orientation R followed by a turn in the
 * plane (i, j) of the world frame. `out` may alias R.
 */
export function rotateInPlane(
  D: Dims,
  out: Float64Array,
  R: ArrayLike<number>,
  i: number,
  j: number,
  angle: number,
): Float64Array {
  const fn = 'rotateInPlane';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  checkPlane(D, 'i', i, 'j', j, fn);
  checkNumber('angle', angle, fn);
  const P = planeScratch[D.n] ?? (planeScratch[D.n] = new Float64Array(D.r));
  writePlaneRotor(D, P, i, j, angle);
  return D.kernels.mul(out, P, R as F64);
}

/**
 * out = exp(−scale · B / 2): the rotor of a body turning with angular velocity B (rad/s) for
 * `scale` seconds (or, with scale = 1, the turn by the bivector angle B). A step of the motion
 * dR/dt = −½ B R is R ← rotorExp(D, tmp, B, h) R.
 */
export function rotorExp(D: Dims, out: Float64Array, B: ArrayLike<number>, scale = 1): Float64Array {
  const fn = 'rotorExp';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkBivector(D, 'B', B, fn);
  checkNumber('scale', scale, fn);
  return D.kernels.exp(out, B as F64, scale);
}

/** The defect of R: the largest absolute component of R R~ − 1 (0 for an exact unit rotor). */
export function rotorDefect(D: Dims, R: ArrayLike<number>): number {
  const fn = 'rotorDefect';
  checkDims(D, fn);
  checkRotor(D, 'R', R, fn);
  return D.kernels.defect(R as F64);
}

/**
 * out = the exact unit rotor nearest to R (same sign as R). Use it when the defect has grown:
 * normalising is not enough for n >= 4, where |R| = 1 does not make R a rotation.
 * `out` may alias R.
 * @throws RangeError if R is zero or so far from a rotor that its frame is a reflection.
 */
export function rotorCorrect(D: Dims, out: Float64Array, R: ArrayLike<number>): Float64Array {
  const fn = 'rotorCorrect';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  if (normOf(D, R) === 0) throw new RangeError(`${fn}: argument 'R' is zero, which is no rotation`);
  return D.kernels.correct(out, R as F64);
}

/** out = R / |R| (Euclidean norm over the r components). `out` may alias R. */
export function rotorNormalize(D: Dims, out: Float64Array, R: ArrayLike<number>): Float64Array {
  const fn = 'rotorNormalize';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkRotor(D, 'R', R, fn);
  const norm = normOf(D, R);
  if (norm === 0) throw new RangeError(`${fn}: argument 'R' is zero and cannot be normalised`);
  const inv = 1 / norm;
  for (let a = 0; a < D.r; a += 1) out[a] = R[a]! * inv;
  return out;
}

/** |R|, the Euclidean norm over the r components (1 for a unit rotor; not a test of being a rotor). */
export function rotorNorm(D: Dims, R: ArrayLike<number>): number {
  checkDims(D, 'rotorNorm');
  checkRotor(D, 'R', R, 'rotorNorm');
  return normOf(D, R);
}

function normOf(D: Dims, R: ArrayLike<number>): number {
  let s = 0;
  for (let a = 0; a < D.r; a += 1) s += R[a]! * R[a]!;
  return Math.sqrt(s);
}
