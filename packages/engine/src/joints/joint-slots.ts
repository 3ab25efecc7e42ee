/**
 * The common slots of `Joint.state`, the per-joint doubles the step reads and writes. A file of
 * their own so that the solver and the joint classes share them without importing each other.
 *
 * @module
 */
/** @internal Indices of `Joint.state` (per-joint doubles the step reads and writes). */
export const JS_HERTZ = 0;
/** @internal Damping ratio, or NaN for the world's default. */
export const JS_DAMPING = 1;
/** @internal Break force (N), 0 = never. */
export const JS_BREAK_FORCE = 2;
/** @internal Break torque (N·m), 0 = never. */
export const JS_BREAK_TORQUE = 3;
/** @internal |λ_linear| / h of the last sub-step (N). */
export const JS_FORCE = 4;
/** @internal |λ_angular (no motor)| / h of the last sub-step (N·m). */
export const JS_TORQUE = 5;
/** @internal The sub-step h of the last solve (s). */
export const JS_H = 6;
/**
 * @internal The largest row error the solver left at the end of the last sub-step (m for linear
 * rows, rad for angular ones; 0 for a soft joint): see `Joint.lastError`.
 */
export const JS_ERROR = 7;
/** @internal Sub-steps that ended with the error past the stretch threshold (see `Joint.stretchCount`). */
export const JS_STRETCH_COUNT = 8;
/** @internal The stretch threshold of the last sub-step (m or rad): 10 × constraintSlop. */
export const JS_STRETCH_LIMIT = 9;
/** @internal First index free for the joint types. */
export const JS_COMMON_COUNT = 10;
