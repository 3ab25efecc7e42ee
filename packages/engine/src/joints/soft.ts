/**
 * The soft step of Box2D v3 (Erin Catto, "Solver2D", 2024) for joints: a constraint that behaves
 * as a spring of frequency f (Hz) and damping ratio ζ, whatever the sub-step h.
 *
 * With ω₀ = 2πf:
 * ```
 * a1 = 2ζ + h ω₀ ; a2 = h ω₀ a1 ; a3 = 1 / (1 + a2)
 * biasRate = ω₀ / a1 ; massScale = a2 a3 ; impulseScale = a3
 * Δλ = −m_eff · massScale · (Ċ + biasRate · C) − impulseScale · λ
 * ```
 * f = 0 means rigid (biasRate 0, massScale 1, impulseScale 0; the caller then adds its own
 * Baumgarte bias). A mass m held by such a joint under gravity g settles where the accumulated
 * impulse λ = m g h balances −m h ω₀² C: C = −g / ω₀² (5 Hz: 9.94 mm), independent of h.
 *
 * The numbers travel in a Float64Array (a double argument to a call that is not inlined is boxed).
 *
 * @module
 */

/** Index of the input frequency (Hz, already capped). */
export const SOFT_HERTZ = 0;
/** Index of the input damping ratio. */
export const SOFT_DAMPING = 1;
/** Index of the input sub-step (s). */
export const SOFT_H = 2;
/** Index of the output bias rate (1/s). */
export const SOFT_BIAS_RATE = 3;
/** Index of the output mass scale. */
export const SOFT_MASS_SCALE = 4;
/** Index of the output impulse scale. */
export const SOFT_IMPULSE_SCALE = 5;
/** Count of entries. */
export const SOFT_COUNT = 6;

/** Fills the outputs of `io` from its inputs (see the module). */
export function softStep(io: Float64Array): void {
  const hz = io[SOFT_HERTZ];
  if (!(hz > 0)) {
    io[SOFT_BIAS_RATE] = 0;
    io[SOFT_MASS_SCALE] = 1;
    io[SOFT_IMPULSE_SCALE] = 0;
    return;
  }
  const omega = 2 * Math.PI * hz;
  const zeta = io[SOFT_DAMPING];
  const h = io[SOFT_H];
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  io[SOFT_BIAS_RATE] = omega / a1;
  io[SOFT_MASS_SCALE] = a2 * a3;
  io[SOFT_IMPULSE_SCALE] = a3;
}
