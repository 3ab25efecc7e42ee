/**
 * The last stage of a sub-step: velocities move the bodies.
 *
 * - dynamic: x += h v (semi-implicit Euler: the velocity of the end of the step), then the rotor
 *   step of `rotor-step.ts` under the fixed world L (midpoint rule, correction, ω rebuilt);
 * - kinematic: x += h v and R ← exp(−h ω/2) R with its own fixed ω (exact for constant
 *   velocities); L follows as I_world ω when it has a mass;
 * - static and sleeping: nothing.
 *
 * Each body is checked for non-finite numbers right after its own update; the stage stops at the
 * first bad one and returns its index, so the world can undo the step before anything reads it.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { Body, MOTION_DYNAMIC, MOTION_STATIC } from '../body.js';
import { momentumFromAngularVelocity } from '../inertia-world.js';
import { advanceRotor, advanceRotorKinematic } from './rotor-step.js';
import type { RotorStepScratch } from './rotor-step.js';
import { STEP_H } from './step-constants.js';
import { isStateFinite } from './step-state.js';

/** Whether a[at .. at + len) is all zeros. */
function isZeroRun(a: Float64Array, at: number, len: number): boolean {
  for (let i = at; i < at + len; i += 1) if (a[i] !== 0) return false;
  return true;
}

/**
 * Moves the non-static, awake bodies of bodies[0 .. count) (the world's awake set) by one
 * sub-step. Unchecked hot-path stage; allocates nothing.
 *
 * @param constants - h (s), the rotor iterations and tolerance (see `step-constants.ts`).
 * @returns the index in `bodies` of the first body whose state became non-finite, or -1.
 */
export function integratePositions(
  D: Dims,
  bodies: readonly Body[],
  count: number,
  constants: Float64Array,
  scratch: RotorStepScratch,
): number {
  const { n, k } = D;
  // where v, L and w start in a body record (see Body.storage: x, R, v, L, w, force, torque)
  const vAt = Body.velocityOffset(D);
  const lAt = vAt + n;
  const h = constants[STEP_H]!;
  for (let b = 0; b < count; b += 1) {
    const body = bodies[b]!;
    const motion = body.motion;
    if (motion === MOTION_STATIC || body.sleeping) continue;
    // x, v and L through the record (a body makes its views only when asked for them)
    const s = body.storage;
    const at = body.storageOffset;
    const v = at + vAt;
    for (let i = 0; i < n; i += 1) s[at + i] = s[at + i]! + h * s[v + i]!;
    if (motion === MOTION_DYNAMIC) {
      // A body with no angular momentum has ω = 0 and keeps its rotor.
      if (!isZeroRun(s, at + lAt, k)) {
        advanceRotor(D, body.R, body.w, body.L, body.invInertia, constants, scratch);
      }
    } else if (!isZeroRun(s, at + lAt + k, k)) {
      advanceRotorKinematic(D, body.R, body.w, constants, scratch);
      if (body.massValue > 0) momentumFromAngularVelocity(D, body.L, body.R, body.inertia, body.w, scratch.tmp);
    }
    if (!isStateFinite(body)) return b;
  }
  return -1;
}
