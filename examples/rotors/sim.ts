/**
 * The simulation behind the rotors page: a 4D rotor (the tesseract) and a 3D rotor (the cube)
 * advanced step by step under a constant angular velocity, with the diagnostics the page shows.
 *
 * The 4D angular velocity is a double rotation B = a e_P + b e_Q in two orthogonal planes P, Q.
 * The cube gets the part of B that lies in the planes of x, y, z (for xy and zw: a e_xy), so it
 * turns like the 3D shadow of the same motion and is integrated the same way.
 *
 * Why the defect grows under the `euler` update (brief §3.2): one step multiplies R by the even
 * element E = 1 − (h/2) B, and E E~ = 1 − h²B²/4 = (1 + h²|B|²/4) − (h² Pf(B)/2) I in 4D, where
 * Pf(B) = b_xy b_zw − b_xz b_yw + b_xw b_yz and I = e0123. Since R R~ = s + c I is central, the I
 * part compounds from step to step and normalising (which only fixes s) never removes it. For a
 * double rotation Pf(B) = ±a b ≠ 0; in 3D there is no I, so normalising is enough there.
 * The vector map of any 4D even element with R R~ = s + c I is √(s² − c²) times a rotation, so
 * the uncorrected frame shrinks: its columns keep their right angles but lose length.
 *
 * Pure (no DOM). `step` allocates nothing: all storage is made in the constructor.
 */
import {
  dims,
  planeIndex,
  rotorCorrect,
  rotorDefect,
  rotorExp,
  rotorIdentity,
  rotorMul,
  rotorNorm,
  rotorNormalize,
  rotorToMatrix,
} from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { DEFAULT_SETTINGS, planePairInfo } from './settings.js';
import type { RotorSettings } from './settings.js';

/**
 * max |MᵀM − I| over all entries, for an n×n row-major matrix M: 0 for a rotation (or any
 * orthogonal matrix). Entry (i, j) of MᵀM is the dot product of columns i and j.
 */
export function orthonormalityError(n: number, M: Float64Array): number {
  let worst = 0;
  for (let i = 0; i < n; i += 1) {
    for (let j = i; j < n; j += 1) {
      let s = 0;
      for (let r = 0; r < n; r += 1) s += M[r * n + i]! * M[r * n + j]!;
      const e = Math.abs(s - (i === j ? 1 : 0));
      if (e > worst) worst = e;
    }
  }
  return worst;
}

/** The mean length of the n columns of an n×n row-major matrix (1 for a rotation). */
export function meanColumnLength(n: number, M: Float64Array): number {
  let total = 0;
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let r = 0; r < n; r += 1) s += M[r * n + c]! * M[r * n + c]!;
    total += Math.sqrt(s);
  }
  return total / n;
}

/** The 4D Pfaffian b_xy b_zw − b_xz b_yw + b_xw b_yz of a 4D bivector (6 numbers, lexicographic planes). */
function pfaffian(B: Float64Array): number {
  return B[0]! * B[5]! - B[1]! * B[4]! + B[2]! * B[3]!;
}

/**
 * The defect |R R~ − 1| after `steps` uncorrected `euler` steps from the identity, in closed form
 * (4D, constant B): each step multiplies R R~ by α + β I with α = 1 + h²|B|²/4, β = −h² Pf(B)/2,
 * and normalising rescales it to 1 + c I, so c = tanh(steps · atanh(β/α)) in absolute value.
 * The tests compare the simulation with this; the page quotes the per-step growth.
 */
export function predictedEulerDefect(B: Float64Array, h: number, steps: number): number {
  let b2 = 0;
  for (let p = 0; p < 6; p += 1) b2 += B[p]! * B[p]!;
  const alpha = 1 + (h * h * b2) / 4;
  const beta = (-h * h * pfaffian(B)) / 2;
  return Math.abs(Math.tanh(steps * Math.atanh(beta / alpha)));
}

/** What the last step did, besides moving the rotors. */
export interface StepReport {
  /** The 4D defect right after the update and normalisation, before any correction. */
  updateDefect: number;
  /** Whether `rotorCorrect` was applied to the 4D rotor in this step. */
  corrected: boolean;
}

/**
 * A 4D and a 3D rotor turning at a constant angular velocity, with the page's diagnostics.
 * Read the public arrays and numbers after `step`; write only through `configure` and `reset`.
 */
export class RotorDemo {
  /** Tables of n = 4. */
  readonly D4: Dims;
  /** Tables of n = 3. */
  readonly D3: Dims;
  /** Orientation of the tesseract (8 numbers). */
  readonly rotor4: Float64Array;
  /** Orientation of the cube (4 numbers). */
  readonly rotor3: Float64Array;
  /** Matrix of `rotor4` (4×4 row-major), refreshed by every step. */
  readonly matrix4: Float64Array;
  /** Matrix of `rotor3` (3×3 row-major), refreshed by every step. */
  readonly matrix3: Float64Array;
  /** The 4D angular velocity bivector B (rad/s, 6 numbers). */
  readonly omega4: Float64Array;
  /** The cube's angular velocity: the part of B in the planes of x, y, z (3 numbers). */
  readonly omega3: Float64Array;
  /** The current settings (a private copy; change them with `configure`). */
  readonly settings: RotorSettings;

  /** Simulated time (s) since the last reset. */
  time = 0;
  /** Steps since the last reset. */
  steps = 0;
  /** Times `rotorCorrect` was applied to the 4D rotor since the last reset. */
  corrections = 0;
  /** Times the 4D rotor had collapsed too far for `rotorCorrect` and was restarted at the identity. */
  restarts = 0;
  /** |R R~ − 1| of the 4D rotor, largest component (`rotorDefect`). */
  defect4 = 0;
  /** |R|, the Euclidean norm of the 4D rotor's 8 numbers. */
  norm4 = 1;
  /** max |MᵀM − I| of the 4D rotor's matrix. */
  orthoError4 = 0;
  /** Mean column length of the 4D rotor's matrix (how much the frame has shrunk). */
  frameScale4 = 1;
  /** The 4D defect right after the last update, before the correction (see `StepReport`). */
  updateDefect4 = 0;
  /** |R R~ − 1| of the 3D rotor. */
  defect3 = 0;
  /** max |MᵀM − I| of the 3D rotor's matrix. */
  orthoError3 = 0;

  // B embedded as an even element (scalar 0, bivector in components 1..k) so rotorMul can form B R.
  private readonly even4: Float64Array;
  private readonly even3: Float64Array;
  private readonly tmp4: Float64Array;
  private readonly tmp3: Float64Array;
  private readonly report: StepReport = { updateDefect: 0, corrected: false };

  constructor(settings: Partial<RotorSettings> = {}) {
    this.D4 = dims(4);
    this.D3 = dims(3);
    this.rotor4 = new Float64Array(this.D4.r);
    this.rotor3 = new Float64Array(this.D3.r);
    this.matrix4 = new Float64Array(16);
    this.matrix3 = new Float64Array(9);
    this.omega4 = new Float64Array(this.D4.k);
    this.omega3 = new Float64Array(this.D3.k);
    this.even4 = new Float64Array(this.D4.r);
    this.even3 = new Float64Array(this.D3.r);
    this.tmp4 = new Float64Array(this.D4.r);
    this.tmp3 = new Float64Array(this.D3.r);
    this.settings = { ...DEFAULT_SETTINGS, ...settings };
    this.configure({});
    this.reset();
  }

  /**
   * Changes some settings. The rotors keep their current orientation, so a change of rate,
   * step or correction takes effect from the next step on.
   */
  configure(change: Partial<RotorSettings>): void {
    Object.assign(this.settings, change);
    const s = this.settings;
    const pair = planePairInfo(s.pair);
    this.omega4.fill(0);
    this.omega4[planeIndex(this.D4, pair.a[0], pair.a[1])] = s.rateA;
    this.omega4[planeIndex(this.D4, pair.b[0], pair.b[1])] = s.rateB;
    this.omega3.fill(0);
    for (let p = 0; p < this.D4.k; p += 1) {
      const i = this.D4.planeI[p]!;
      const j = this.D4.planeJ[p]!;
      if (j < 3) this.omega3[planeIndex(this.D3, i, j)] = this.omega4[p]!;
    }
    this.even4.fill(0);
    this.even4.set(this.omega4, 1);
    this.even3.fill(0);
    this.even3.set(this.omega3, 1);
  }

  /** Back to the identity orientation at time 0, counters cleared. */
  reset(): void {
    rotorIdentity(this.D4, this.rotor4);
    rotorIdentity(this.D3, this.rotor3);
    this.time = 0;
    this.steps = 0;
    this.corrections = 0;
    this.restarts = 0;
    this.updateDefect4 = 0;
    this.refreshDiagnostics();
  }

  /** The 4D Pfaffian of the angular velocity, Pf(B): zero for a simple rotation, a·b for a double one. */
  pfaffian(): number {
    return pfaffian(this.omega4);
  }

  /**
   * One step of length `settings.step`: both rotors are advanced by the chosen integrator, the 4D
   * one is corrected when correction is on and its defect exceeds the tolerance, and every
   * diagnostic is refreshed. Returns a report object that is reused by the next call.
   */
  step(): StepReport {
    const s = this.settings;
    const h = s.step;
    this.advance(this.D4, this.rotor4, this.even4, this.omega4, this.tmp4, h);
    this.advance(this.D3, this.rotor3, this.even3, this.omega3, this.tmp3, h);
    const updateDefect = rotorDefect(this.D4, this.rotor4);
    let corrected = false;
    if (s.correct) {
      if (updateDefect > s.tolerance) {
        corrected = true;
        this.corrections += 1;
        if (!this.tryCorrect()) {
          this.restarts += 1;
          rotorIdentity(this.D4, this.rotor4);
        }
      }
      // In 3D the correction is plain normalisation, already done by the update.
      if (rotorDefect(this.D3, this.rotor3) > s.tolerance) rotorCorrect(this.D3, this.rotor3, this.rotor3);
    }
    this.time += h;
    this.steps += 1;
    this.updateDefect4 = updateDefect;
    this.refreshDiagnostics();
    this.report.updateDefect = updateDefect;
    this.report.corrected = corrected;
    return this.report;
  }

  /** Runs `count` steps (for warming up before the first frame, and for tests). */
  run(count: number): void {
    for (let i = 0; i < count; i += 1) this.step();
  }

  /**
   * out (4×4) = the matrix of the nearest true rotation to the current 4D rotor (`rotorCorrect`
   * of a copy): what the tesseract would look like if the frame were still a rotation. Returns
   * false, leaving `out` unchanged, when the frame has collapsed too far to say.
   */
  nearestRotationMatrix(out: Float64Array): boolean {
    try {
      rotorCorrect(this.D4, this.tmp4, this.rotor4);
    } catch (err) {
      if (err instanceof RangeError) return false;
      throw err;
    }
    for (let a = 0; a < this.D4.r; a += 1) if (!Number.isFinite(this.tmp4[a]!)) return false;
    rotorToMatrix(this.D4, out, this.tmp4);
    return true;
  }

  private advance(D: Dims, R: Float64Array, even: Float64Array, omega: Float64Array, tmp: Float64Array, h: number): void {
    if (this.settings.integrator === 'exp') {
      rotorExp(D, tmp, omega, h);
      rotorMul(D, R, tmp, R);
      return;
    }
    // First order in h, as a naive engine would write dR/dt = −½ B R.
    rotorMul(D, tmp, even, R);
    const f = -0.5 * h;
    for (let a = 0; a < D.r; a += 1) R[a] = R[a]! + f * tmp[a]!;
    rotorNormalize(D, R, R);
  }

  // A frame that has shrunk to (nearly) nothing cannot be orthonormalised back into a rotation.
  private tryCorrect(): boolean {
    try {
      rotorCorrect(this.D4, this.tmp4, this.rotor4);
    } catch (err) {
      if (err instanceof RangeError) return false;
      throw err;
    }
    for (let a = 0; a < this.D4.r; a += 1) if (!Number.isFinite(this.tmp4[a]!)) return false;
    this.rotor4.set(this.tmp4);
    return true;
  }

  private refreshDiagnostics(): void {
    this.defect4 = rotorDefect(this.D4, this.rotor4);
    this.norm4 = rotorNorm(this.D4, this.rotor4);
    rotorToMatrix(this.D4, this.matrix4, this.rotor4);
    this.orthoError4 = orthonormalityError(4, this.matrix4);
    this.frameScale4 = meanColumnLength(4, this.matrix4);
    this.defect3 = rotorDefect(this.D3, this.rotor3);
    rotorToMatrix(this.D3, this.matrix3, this.rotor3);
    this.orthoError3 = orthonormalityError(3, this.matrix3);
  }
}
