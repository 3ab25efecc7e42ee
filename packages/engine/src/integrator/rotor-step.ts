/**
 * The rotor step of a free body: turn R over one sub-step h while the angular momentum L stays
 * fixed in the world frame.
 *
 * With L fixed, the angular velocity is a function of the orientation alone,
 * ω(R) = R·I⁻¹(R~ L R)·R~, and the motion is dR/dt = −½ ω(R) R. The step turns R by
 * exp(−h ω̄/2) for one angular velocity ω̄ chosen as follows:
 *
 * - `iterations` = 0 (first order): ω̄ = ω(R₀), the velocity at the start of the step.
 * - `iterations` = m ≥ 1: m fixed-point iterations of the implicit midpoint equation
 *   ω̄ = ω(exp(−(h/2) ω̄/2) R₀), starting from ω(R₀). One iteration is the explicit midpoint rule
 *   (ω taken at R turned by h/2 — second order); every further iteration multiplies the distance to
 *   the implicit solution by about h|ω|, and the implicit solution is a symmetric (time-reversible)
 *   method: its energy error stays bounded without drift.
 *
 * The iterations are the engine's "implicit gyroscopic step": they find the angular velocity that
 * turns the rotor and write no field of the body. L is never touched, so a torque-free body keeps
 * it bit-exactly whatever the settings; only the accuracy of the turn changes.
 *
 * After the turn the rotor is corrected back onto the rotation group when its defect
 * ‖R R~ − 1‖ exceeds `tolerance`, and ω is rebuilt from L at the new orientation.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { angularVelocityFromMomentum } from '../inertia-world.js';
import { STEP_H, STEP_ROTOR_ITERATIONS, STEP_ROTOR_TOLERANCE } from './step-constants.js';

/** Caller-owned scratch of one rotor step (allocate once per world and dimension). */
export interface RotorStepScratch {
  /** A turn rotor exp(−X/2) (r numbers). */
  readonly turn: Float64Array;
  /** The trial orientation at the middle of the step (r numbers). */
  readonly middle: Float64Array;
  /** The angular velocity that turns the rotor (k numbers). */
  readonly omega: Float64Array;
  /** The turn bivector X = (time)·ω handed to the exponential (k numbers). */
  readonly turnBivector: Float64Array;
  /** Scratch of the inertia transform (k numbers). */
  readonly tmp: Float64Array;
}

/** Allocates the scratch of {@link advanceRotor} for dimension D. */
export function createRotorStepScratch(D: Dims): RotorStepScratch {
  return {
    turn: new Float64Array(D.r),
    middle: new Float64Array(D.r),
    omega: new Float64Array(D.k),
    turnBivector: new Float64Array(D.k),
    tmp: new Float64Array(D.k),
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
    const b0 = R[1]!, b1 = R[2]!, b2 = R[3]!, b3 = R[4]!, b4 = R[5]!, b5 = R[6]!;
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
  let omega = w;
  if (iterations > 0) {
    omega = s.omega;
    omega.set(w);
  }
  // Passes 0..iterations-1 turn R by h/2 to the trial middle and take ω there; the last pass
  // turns R by h with that ω, corrects it and rebuilds ω = ω(R) into w. One call site per kernel
  // keeps V8's inlining budget small, and the exponential gets scale 1 on a pre-scaled bivector:
  // a double crossing a call boundary that is not inlined is boxed on the heap.
  for (let it = 0; ; it += 1) {
    const last = it >= iterations;
    const t = last ? h : 0.5 * h;
    for (let p = 0; p < k; p += 1) X[p] = t * omega[p]!;
    K.exp(s.turn, X, 1);
    const target = last ? R : s.middle;
    K.mul(target, s.turn, R);
    if (last && defectExceeds(D, R, constants)) K.correct(R, R);
    angularVelocityFromMomentum(D, last ? w : omega, target, invInertia, L, s.tmp);
    if (last) return;
  }
}

/**
 * Turns the rotor R of a kinematic body by its fixed world angular velocity ω over one sub-step:
 * R ← exp(−h ω/2) R (exact for a constant ω), then corrects it above the tolerance. Unchecked.
 */
export function advanceRotorKinematic(D: Dims, R: Float64Array, w: Float64Array, constants: Float64Array, s: RotorStepScratch): void {
  const K = D.kernels;
  const h = constants[STEP_H]!;
  const X = s.turnBivector;
  for (let p = 0; p < D.k; p += 1) X[p] = h * w[p]!;
  K.exp(s.turn, X, 1);
  K.mul(R, s.turn, R);
  if (defectExceeds(D, R, constants)) K.correct(R, R);
}
