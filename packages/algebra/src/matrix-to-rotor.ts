/**
 * Rebuilding a rotor from a rotation matrix as a product of reflections (Cartan–Dieudonné).
 *
 * The method works on a copy W of the matrix's columns and, one axis at a time, reflects the
 * whole frame so that the column that is furthest from its axis lands on it. Each reflection
 * vector u goes into the rotor product too, so the rotor always describes exactly the turns that
 * were applied to W, whatever rounding made u. What is left at the end is W ≈ 1 + A with A tiny
 * and antisymmetric, which a first-order rotor absorbs. No step divides by (1 + cos θ), so half
 * turns are ordinary inputs. See docs/nd-physics.md ("Matrix to rotor") for the half-turn rules.
 */
import type { Dims } from './tables.js';
import { determinantUnchecked } from './linalg.js';
import { checkDims, checkMatrix, checkOutRotor } from './validate.js';

/**
 * Below this distance between a column and its axis, no reflection is made: the column is left
 * for the first-order residual step. The rotor 1 - B/2 (normalised) of a residual of angle d
 * differs from the exact exp(-B/2) by about d³/24 and its matrix by about d³/6, which is below
 * 1e-18 at d = 1e-6, far under rounding; while a reflection built from a difference as small as
 * d would take its direction from rounding noise (0/0 at d = 0). A property of the method, not a
 * tolerance of physics.
 */
export const REFLECTION_THRESHOLD = 1e-6;

/**
 * Largest entry of |MᵀM − 1| accepted by the public `matrixToRotor`. The residual step is exact
 * only for rotations; a matrix further from orthogonal than this has no rotor worth returning.
 */
export const ORTHOGONALITY_LIMIT = 1e-6;

/** Working storage of the rebuild for one dimension (allocate once, reuse). */
export interface MatrixToRotorScratch {
  /** n×n row-major work copy of the matrix; its columns are reflected toward their axes. */
  readonly w: Float64Array;
  /** n flags: 1 once the column (and axis) of that index is in place. */
  readonly fixed: Uint8Array;
  /** n numbers: the unit normal of the current reflection. */
  readonly u: Float64Array;
  /** n numbers: the previous reflection normal, waiting to be paired with the next one. */
  readonly pending: Float64Array;
  /** r numbers: the rotor built so far from pairs of reflections. */
  readonly v: Float64Array;
  /** r numbers: product scratch. */
  readonly t: Float64Array;
  /** r numbers: a scalar-plus-bivector element (a pair of reflections, or the residual rotor). */
  readonly e: Float64Array;
}

/** Preallocated scratch for {@link matrixToRotorUnchecked} in dimension D.n. */
export function createMatrixToRotorScratch(D: Dims): MatrixToRotorScratch {
  return {
    w: new Float64Array(D.n * D.n),
    fixed: new Uint8Array(D.n),
    u: new Float64Array(D.n),
    pending: new Float64Array(D.n),
    v: new Float64Array(D.r),
    t: new Float64Array(D.r),
    e: new Float64Array(D.r),
  };
}

/** out = a b, with `a` given as a scalar plus bivector (only components 0..k are read). */
function mulScalarBivectorLeft(D: Dims, out: Float64Array, a: Float64Array, b: Float64Array): void {
  const { r, k, mulIndex, mulSign } = D;
  out.fill(0);
  for (let p = 0; p <= k; p += 1) {
    const ap = a[p]!;
    if (ap === 0) continue;
    const row = p * r;
    for (let c = 0; c < r; c += 1) out[mulIndex[row + c]!] += mulSign[row + c]! * ap * b[c]!;
  }
}

/**
 * Unchecked rebuild of the rotor of the rotation matrix M (n×n row-major, columns = images of
 * the axes). Writes the unit rotor into `out` and returns true; returns false, leaving `out`
 * untouched, when the reflection count is odd (det M = −1). The result's overall sign is
 * arbitrary (R and −R are the same rotation). `out` may not alias `M`. Allocates nothing.
 */
export function matrixToRotorUnchecked(D: Dims, out: Float64Array, M: ArrayLike<number>, s: MatrixToRotorScratch): boolean {
  const { n, r, k, planeI, planeJ, reverseSign } = D;
  const { w, fixed, u, pending, v, t, e } = s;
  for (let i = 0; i < n * n; i += 1) w[i] = M[i]!;
  fixed.fill(0);
  v.fill(0);
  v[0] = 1;
  let hasPending = false;
  for (let step = 0; step < n; step += 1) {
    // Rule 1: take the unfixed column furthest from its axis; on a tie (an exact half turn) the
    // first in axis order wins, so the plane of the next axis is the one that is used.
    // Rule 2: measure (and later reflect) only in the components of the axes not yet fixed, so
    // rounding in the columns that are already in place cannot tilt the reflection plane.
    let best = -1;
    let bestD2 = -1;
    for (let c = 0; c < n; c += 1) {
      if (fixed[c]) continue;
      let d2 = 0;
      for (let i = 0; i < n; i += 1) {
        if (fixed[i]) continue;
        const x = w[i * n + c]! - (i === c ? 1 : 0);
        d2 += x * x;
      }
      if (d2 > bestD2) {
        bestD2 = d2;
        best = c;
      }
    }
    const d = Math.sqrt(bestD2);
    // Rule 3: leave tiny residuals to the first-order step at the end.
    if (d < REFLECTION_THRESHOLD) {
      fixed[best] = 1;
      continue;
    }
    for (let i = 0; i < n; i += 1) u[i] = fixed[i] ? 0 : (w[i * n + best]! - (i === best ? 1 : 0)) / d;
    fixed[best] = 1;
    for (let c = 0; c < n; c += 1) {
      let dot = 0;
      for (let i = 0; i < n; i += 1) dot += u[i]! * w[i * n + c]!;
      if (dot === 0) continue;
      const f = 2 * dot;
      for (let i = 0; i < n; i += 1) w[i * n + c] = w[i * n + c]! - f * u[i]!;
    }
    if (!hasPending) {
      pending.set(u);
      hasPending = true;
    } else {
      // V ← (u · p + u ∧ p) V: the two latest reflections as one even element.
      e.fill(0);
      let dot = 0;
      for (let i = 0; i < n; i += 1) dot += u[i]! * pending[i]!;
      e[0] = dot;
      for (let p = 0; p < k; p += 1) {
        const i = planeI[p]!;
        const j = planeJ[p]!;
        e[1 + p] = u[i]! * pending[j]! - u[j]! * pending[i]!;
      }
      mulScalarBivectorLeft(D, t, e, v);
      v.set(t);
      hasPending = false;
    }
  }
  if (hasPending) return false;
  // Residual W ≈ 1 + Ω_A: its rotor to first order is 1 − B_A/2 with ω_ij = (W[j][i] − W[i][j])/2.
  e.fill(0);
  e[0] = 1;
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    e[1 + p] = -0.25 * (w[j * n + i]! - w[i * n + j]!);
  }
  // R = V~ R_res: reverse V in place, then multiply by the residual rotor on the right.
  for (let a = 0; a < r; a += 1) v[a] = v[a]! * reverseSign[a]!;
  // Right multiplication by a scalar + bivector element: (V~ R_res) = Σ V~_a e_p (blade a · blade p).
  const { mulIndex, mulSign } = D;
  t.fill(0);
  for (let a = 0; a < r; a += 1) {
    const va = v[a]!;
    if (va === 0) continue;
    const row = a * r;
    for (let p = 0; p <= k; p += 1) {
      const ep = e[p]!;
      if (ep === 0) continue;
      t[mulIndex[row + p]!] += mulSign[row + p]! * va * ep;
    }
  }
  let norm = 0;
  for (let a = 0; a < r; a += 1) norm += t[a]! * t[a]!;
  const inv = 1 / Math.sqrt(norm);
  for (let a = 0; a < r; a += 1) out[a] = t[a]! * inv;
  return true;
}

const publicScratch: (MatrixToRotorScratch | undefined)[] = [];

/**
 * out = the unit rotor of the rotation matrix M (n×n, row-major, `M[i*n + c]` = component i of
 * the image of e_c), rebuilt by reflections (robust at half turns, see the module comment). The
 * overall sign of the rotor is not specified (R and −R give the same rotation).
 * @throws TypeError on wrong lengths; RangeError for non-finite entries, for a matrix that is not
 * orthogonal to within 1e-6 (largest entry of |MᵀM − 1|), and for a reflection (det M = −1), which
 * has no rotor. `out` is untouched when it throws.
 */
export function matrixToRotor(D: Dims, out: Float64Array, M: ArrayLike<number>): Float64Array {
  const fn = 'matrixToRotor';
  checkDims(D, fn);
  checkOutRotor(D, 'out', out, fn);
  checkMatrix(D, 'M', M, fn);
  const n = D.n;
  let worst = 0;
  for (let i = 0; i < n; i += 1) {
    for (let j = 0; j < n; j += 1) {
      let s = 0;
      for (let m = 0; m < n; m += 1) s += M[m * n + i]! * M[m * n + j]!;
      worst = Math.max(worst, Math.abs(s - (i === j ? 1 : 0)));
    }
  }
  if (worst > ORTHOGONALITY_LIMIT) {
    throw new RangeError(
      `${fn}: argument 'M' is not orthogonal to within ${ORTHOGONALITY_LIMIT.toExponential()} ` +
        `(largest entry of |MᵀM - 1| is ${worst.toExponential(3)}), so it is not a rotation matrix`,
    );
  }
  if (determinantUnchecked(n, M) < 0) {
    throw new RangeError(`${fn}: argument 'M' has determinant -1 (a reflection), which has no rotor`);
  }
  const s = publicScratch[n] ?? (publicScratch[n] = createMatrixToRotorScratch(D));
  if (!matrixToRotorUnchecked(D, out, M, s)) {
    throw new RangeError(`${fn}: argument 'M' has determinant -1 (a reflection), which has no rotor`);
  }
  return out;
}
