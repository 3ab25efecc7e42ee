/**
 * The rotor step of a free body: turn R over one sub-step h while the angular momentum L stays
 * fixed in the world frame.
 *
 * With L fixed, the angular velocity is a function of the orientation alone,
 * ω(R) = R·I⁻¹(R~ L R)·R~, and the motion is dR/dt = −½ ω(R) R. Two quantities are exact
 * invariants of that motion: L itself (never written here, so a torque-free body keeps it bit for
 * bit) and the kinetic energy E = ½ L·ω(R). The step (`iterations` ≥ 1, the gyroscopic step):
 *
 * 1. **Split**: the first midpoint evaluation ω(R_½) also measures how fast ω changes within the
 *    step; when h·|ω(R_½) − ω(R₀)| > ROTOR_SPLIT_ANGLE the sub-step is split into m equal rotor
 *    steps, m = ⌈√(h·|ω(R_½) − ω(R₀)| / ROTOR_SPLIT_ANGLE)⌉ ≤ 64 (that change falls as the square
 *    of the step). Ordinary spins, balls at any speed and steady spins about a principal plane
 *    take one step; boxes tumbling at 30–200 rad/s at 1/60 s take several.
 * 2. **Midpoint** on each: ω̄ = ω(exp(−(h/2m) ω̄/2) R), iterated from ω̄ = ω(R) at most
 *    `iterations` times and stopped early when |Δω̄| ≤ 1e-12 |ω̄|. One iteration is the explicit
 *    midpoint rule (second order); more converge to the symmetric implicit midpoint. Then
 *    R ← exp(−(h/m) ω̄/2) R.
 * 3. **Energy projection**: the turn conserves E only to O(h³) per step, and that error drifts
 *    (and, for h|ω| ≳ 0.5, explodes). The step restores E to its value at the start by Newton's
 *    method along the one direction that changes it: turning the body by ε G with G = [ω, L]
 *    changes 2E = L·ω at the rate dE₂/dε = 2|G|², so ε = −(L·ω − L·ω₀)/(2|G|²), at most 8
 *    times, only while |L·ω − L·ω₀| > 1e-12 L·ω₀ (each turn at most min(0.5, 0.01 h|ω|)): a step
 *    that already kept E to that tolerance (a ball, a steady spin) costs nothing more, and the
 *    decision, far above rounding, is the same for bodies that differ by rounding.
 *    G vanishes only when ω ∥ L (a steady spin about a principal plane), where E is stationary.
 *
 * `iterations` = 0 (first order, `gyroscopic: false`): one turn by ω̄ = ω(R₀), no split, no
 * projection (kept as the documented baseline).
 *
 * After every rotor step's turn the rotor is corrected back onto the rotation group when its
 * defect ‖R R~ − 1‖ exceeds `tolerance` (the projection's small turns are exact to rounding and
 * are checked after the next step's turn), and ω is rebuilt from L at the new orientation.
 *
 * @module
 */
import { bivectorCommutatorUnchecked } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { angularVelocityFromMomentum } from '../inertia-world.js';
import { STEP_H, STEP_ROTOR_ITERATIONS, STEP_ROTOR_TOLERANCE } from './step-constants.js';

/**
 * Largest h·|ω(R_½) − ω(R₀)| (rad: the change of ω over half a step, times the step) of one rotor
 * step before the sub-step is split.
 */
export const ROTOR_SPLIT_ANGLE = 0.01;
/** Most rotor steps one sub-step is split into. */
export const ROTOR_MAX_SPLIT = 64;
/** The midpoint iterations stop when |Δω̄| ≤ this × |ω̄|. */
export const ROTOR_MIDPOINT_TOLERANCE = 1e-12;
/** The energy projection stops when the relative energy error is at most this. */
export const ROTOR_ENERGY_TOLERANCE = 1e-12;
/** Most Newton steps of the energy projection. */
export const ROTOR_ENERGY_ITERATIONS = 8;
/** Largest turn of one Newton step of the energy projection, as a share of the step's turn h|ω|. */
export const ROTOR_ENERGY_TURN_SHARE = 0.01;
/** Largest turn of one Newton step of the energy projection (rad). */
export const ROTOR_ENERGY_MAX_TURN = 0.5;

/** Caller-owned scratch of one rotor step (allocate once per world and dimension). */
export interface RotorStepScratch {
  /** A turn rotor exp(−X/2) (r numbers). */
  readonly turn: Float64Array;
  /** The trial orientation at the middle of the step (r numbers). */
  readonly middle: Float64Array;
  /** The angular velocity that turns the rotor (k numbers). */
  readonly omega: Float64Array;
  /** The next midpoint iterate, then the energy gradient direction [ω, L] (k numbers). */
  readonly next: Float64Array;
  /** The turn bivector X = (time)·ω handed to the exponential (k numbers). */
  readonly turnBivector: Float64Array;
  /** Scratch of the inertia transform (k numbers). */
  readonly tmp: Float64Array;
  /** Two n×n matrices for the commutator [ω, L]. */
  readonly matA: Float64Array;
  readonly matB: Float64Array;
}

/** Allocates the scratch of {@link advanceRotor} for dimension D. */
export function createRotorStepScratch(D: Dims): RotorStepScratch {
  return {
    turn: new Float64Array(D.r),
    middle: new Float64Array(D.r),
    omega: new Float64Array(D.k),
    next: new Float64Array(D.k),
    turnBivector: new Float64Array(D.k),
    tmp: new Float64Array(D.k),
    matA: new Float64Array(D.n * D.n),
    matB: new Float64Array(D.n * D.n),
  };
}

/**
 * Whether the defect ‖R R~ − 1‖ (largest component) exceeds the tolerance in `constants`.
 *
 * For n = 3 and n = 4 the defect is written out here (the same expressions as the 3D and 4D
 * kernels: R R~ = |R|² in 3D, and (s² + |B|² + p²) + 2(sp − Pf(B)) I in 4D) instead of calling
 * `D.kernels.defect`: V8 boxes a double returned by a call it does not inline, which would allocate
 * once per body and step. Other dimensions call the kernel.
 */
function defectExceeds(D: Dims, R: Float64Array, constants: Float64Array): boolean {
  const tolerance = constants[STEP_ROTOR_TOLERANCE]!;
  if (D.n === 3) {
    const a = R[0]! * R[0]! + R[1]! * R[1]! + R[2]! * R[2]! + R[3]! * R[3]!;
    return Math.abs(a - 1) > tolerance;
  }
  if (D.n === 4) {
    const s = R[0]!;
    const p = R[7]!;
    const b0 = R[1]!,
      b1 = R[2]!,
      b2 = R[3]!,
      b3 = R[4]!,
      b4 = R[5]!,
      b5 = R[6]!;
    const a = s * s + b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 + b4 * b4 + b5 * b5 + p * p;
    const c = 2 * (s * p - (b0 * b5 - b1 * b4 + b2 * b3));
    return Math.abs(a - 1) > tolerance || Math.abs(c) > tolerance;
  }
  return D.kernels.defect(R) > tolerance;
}

/**
 * Advances the rotor R of a body by one sub-step under a fixed world angular momentum L.
 *
 * Unchecked hot-path kernel: no validation, no allocation. On entry `w` must hold ω(R) (the
 * engine keeps that invariant); on return R is the new orientation and `w` = ω(R) at it.
 * The sub-step length, the iteration count and the tolerance are read from `constants`
 * (see `step-constants.ts`).
 *
 * @param R - rotor (r numbers), updated in place.
 * @param w - world angular velocity (k numbers, rad/s), updated in place.
 * @param L - world angular momentum (k numbers), read only.
 * @param invInertia - body-frame inverse principal inertia (k numbers).
 * @param constants - h (s), midpoint iterations (0 = first order), rotor tolerance.
 */
export function advanceRotor(
  D: Dims,
  R: Float64Array,
  w: Float64Array,
  L: Float64Array,
  invInertia: Float64Array,
  constants: Float64Array,
  s: RotorStepScratch,
): void {
  const K = D.kernels;
  const k = D.k;
  const h = constants[STEP_H]!;
  const iterations = constants[STEP_ROTOR_ITERATIONS]!;
  const X = s.turnBivector;
  if (iterations <= 0) {
    for (let p = 0; p < k; p += 1) X[p] = h * w[p]!;
    K.exp(s.turn, X, 1);
    K.mul(R, s.turn, R);
    if (defectExceeds(D, R, constants)) K.correct(R, R);
    angularVelocityFromMomentum(D, w, R, invInertia, L, s.tmp);
    return;
  }
  let e0 = 0;
  for (let p = 0; p < k; p += 1) e0 += L[p]! * w[p]!;
  const omega = s.omega;
  const next = s.next;
  const tol2 = ROTOR_MIDPOINT_TOLERANCE * ROTOR_MIDPOINT_TOLERANCE;
  // The first midpoint evaluation, ω at R turned by h/2, also measures how fast ω changes: the
  // split count follows from h·|ω(R_½) − ω(R₀)|, which falls as the square of the step.
  for (let p = 0; p < k; p += 1) X[p] = 0.5 * h * w[p]!;
  K.exp(s.turn, X, 1);
  K.mul(s.middle, s.turn, R);
  angularVelocityFromMomentum(D, omega, s.middle, invInertia, L, s.tmp);
  let d2 = 0;
  let w2 = 0;
  for (let p = 0; p < k; p += 1) {
    const d = omega[p]! - w[p]!;
    d2 += d * d;
    w2 += omega[p]! * omega[p]!;
  }
  const change = h * Math.sqrt(d2);
  let split = 1;
  if (change > ROTOR_SPLIT_ANGLE) split = Math.min(Math.ceil(Math.sqrt(change / ROTOR_SPLIT_ANGLE)), ROTOR_MAX_SPLIT);
  const hs = h / split;
  const half = 0.5 * hs;
  for (let j = 0; j < split; j += 1) {
    // Unsplit, the first iteration is done above.
    let it = 0;
    if (split === 1) {
      it = 1;
      if (d2 <= tol2 * w2) it = iterations;
    } else {
      for (let p = 0; p < k; p += 1) omega[p] = w[p]!;
    }
    for (; it < iterations; it += 1) {
      for (let p = 0; p < k; p += 1) X[p] = half * omega[p]!;
      K.exp(s.turn, X, 1);
      K.mul(s.middle, s.turn, R);
      angularVelocityFromMomentum(D, next, s.middle, invInertia, L, s.tmp);
      d2 = 0;
      w2 = 0;
      for (let p = 0; p < k; p += 1) {
        const a = next[p]!;
        const d = a - omega[p]!;
        d2 += d * d;
        w2 += a * a;
        omega[p] = a;
      }
      if (d2 <= tol2 * w2) break;
    }
    for (let p = 0; p < k; p += 1) X[p] = hs * omega[p]!;
    K.exp(s.turn, X, 1);
    K.mul(R, s.turn, R);
    if (defectExceeds(D, R, constants)) K.correct(R, R);
    angularVelocityFromMomentum(D, w, R, invInertia, L, s.tmp);
  }
  // Energy projection: Newton on ε, turning the body by ε G, G = [ω, L].
  const G = s.next;
  // A correction turn never exceeds 1 % of the step's own turn h|ω| (nor ROTOR_ENERGY_MAX_TURN): a body
  // at rest, where de is rounding over a tiny |G|², is not thrown around.
  let wa2 = 0;
  for (let p = 0; p < k; p += 1) wa2 += w[p]! * w[p]!;
  const maxTurn = Math.min(ROTOR_ENERGY_MAX_TURN, ROTOR_ENERGY_TURN_SHARE * h * Math.sqrt(wa2));
  const maxTurn2 = maxTurn * maxTurn;
  for (let q = 0; q < ROTOR_ENERGY_ITERATIONS; q += 1) {
    let e = 0;
    for (let p = 0; p < k; p += 1) e += L[p]! * w[p]!;
    const de = e - e0;
    // Projected only while the relative error exceeds the tolerance: a decision far above the
    // rounding of L·ω, so bodies that differ by rounding (a 3D spin embedded in 4D) decide alike,
    // and a step that already kept E (a ball, a steady spin, a slow turn) costs nothing more.
    if (!(Math.abs(de) > ROTOR_ENERGY_TOLERANCE * e0)) return;
    bivectorCommutatorUnchecked(D, G, w, L, s.matA, s.matB);
    let g2 = 0;
    for (let p = 0; p < k; p += 1) g2 += G[p]! * G[p]!;
    if (!(g2 > 0)) return;
    let eps = -de / (2 * g2);
    // A turn of at most ROTOR_ENERGY_MAX_TURN (near ω ∥ L, where G is small).
    if (eps * eps * g2 > maxTurn2) eps = (eps > 0 ? maxTurn : -maxTurn) / Math.sqrt(g2);
    for (let p = 0; p < k; p += 1) X[p] = eps * G[p]!;
    K.exp(s.turn, X, 1);
    // The turn is exact to rounding: the defect it adds is checked after the next step's turn.
    K.mul(R, s.turn, R);
    angularVelocityFromMomentum(D, w, R, invInertia, L, s.tmp);
  }
}

/**
 * Turns the rotor R of a kinematic body by its fixed world angular velocity ω over one sub-step:
 * R ← exp(−h ω/2) R (exact for a constant ω), then corrects it above the tolerance. Unchecked.
 */
export function advanceRotorKinematic(
  D: Dims,
  R: Float64Array,
  w: Float64Array,
  constants: Float64Array,
  s: RotorStepScratch,
): void {
  const K = D.kernels;
  const h = constants[STEP_H]!;
  const X = s.turnBivector;
  for (let p = 0; p < D.k; p += 1) X[p] = h * w[p]!;
  K.exp(s.turn, X, 1);
  K.mul(R, s.turn, R);
  if (defectExceeds(D, R, constants)) K.correct(R, R);
}
