/**
 * The numbers one sub-step needs, kept in a Float64Array the world owns.
 *
 * Why an array and not arguments: in V8 a double handed to a function that is not inlined, or
 * returned from one, is boxed into a fresh heap object. The step runs for every body many times a
 * second and must allocate nothing, so its scalars travel in this array (read into locals by each
 * stage) and the rotor kernels are called with scale 1 on pre-scaled bivectors.
 *
 * @module
 */

/** Index of the sub-step length h (s). */
export const STEP_H = 0;
/** Index of the rotor defect above which the rotor is corrected. */
export const STEP_ROTOR_TOLERANCE = 1;
/** Index of the count of midpoint iterations of the rotor step (0 = first order). */
export const STEP_ROTOR_ITERATIONS = 2;
/** Index of the factor applied to v each sub-step by linear damping (1 = none). */
export const STEP_LINEAR_SCALE = 3;
/** Index of the factor applied to L each sub-step by angular damping (1 = none). */
export const STEP_ANGULAR_SCALE = 4;
/** Number of entries. */
export const STEP_CONSTANT_COUNT = 5;

/** Allocates the array of step constants (once per world). */
export function createStepConstants(): Float64Array {
  return new Float64Array(STEP_CONSTANT_COUNT);
}
