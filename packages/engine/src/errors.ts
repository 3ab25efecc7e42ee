/**
 * Errors the engine throws besides argument errors (TypeError / RangeError).
 *
 * @module
 */
import type { Body } from './body.js';

/** The state fields a step checks for non-finite numbers. */
export type StateField = 'v' | 'L' | 'x' | 'R' | 'w';

/**
 * Thrown by `World.step` when a body's state became non-finite (NaN or ±Infinity) during the
 * step — typically a force, an impulse or a velocity so large that a product overflows.
 *
 * Policy: each body is checked right after its own integration in every sub-step; at the first
 * bad body the world stops and puts EVERY body back to its state at the start of the `step` call
 * (positions, rotors, velocities, momenta), leaves the forces and torques applied for that step in
 * place, does not advance its time, and throws this error. Nothing non-finite is ever left in the
 * world, so it cannot reach another body through a later contact or joint. Fix or remove the body
 * (`error.body`) and step again.
 */
export class NonFiniteStateError extends Error {
  /** The body whose state became non-finite. */
  readonly body: Body;
  /**
   * The first field found non-finite, checked in the order v, L, x, R, w: the velocities first,
   * because a bad velocity or momentum is usually the cause and the position or rotor its effect.
   */
  readonly field: StateField;
  /** The sub-step (0-based) in which it happened. */
  readonly subStep: number;

  constructor(body: Body, field: StateField, subStep: number, subSteps: number) {
    super(
      `World.step: ${body.label} got a non-finite ${field} in sub-step ${subStep + 1} of ${subSteps}; ` +
        `every body was restored to its state before this step (forces left in place)`,
    );
    this.name = 'NonFiniteStateError';
    this.body = body;
    this.field = field;
    this.subStep = subStep;
  }
}
