/**
 * Stage 1 of a sub-step: external forces change the velocities.
 *
 * For every awake dynamic body: v += h (F/m + g), L += h τ (world frame), then the optional damping;
 * ω is rebuilt from L only when L changed, so a torque-free undamped body keeps L and ω untouched.
 * Static and kinematic bodies are skipped: forces do not move them.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { Body, MOTION_DYNAMIC } from '../body.js';
import { angularVelocityFromMomentum } from '../inertia-world.js';
import { STEP_ANGULAR_SCALE, STEP_H, STEP_LINEAR_SCALE } from './step-constants.js';

/**
 * Applies gravity, the accumulated forces and torques and the damping of one sub-step to the
 * velocities and momenta of the dynamic bodies. Unchecked hot-path stage; allocates nothing.
 *
 * @param bodies - the bodies to visit, bodies[0 .. count) (the world's awake set; static and
 *   sleeping ones among them are skipped).
 * @param gravity - acceleration of gravity (m/s², n numbers).
 * @param constants - the sub-step length h (s) and the damping factors (see `step-constants.ts`):
 *   v ← v · linearScale, L ← L · angularScale, each skipped when exactly 1.
 * @param tmp - scratch of k numbers.
 */
export function integrateVelocities(
  D: Dims,
  bodies: readonly Body[],
  count: number,
  gravity: Float64Array,
  constants: Float64Array,
  tmp: Float64Array,
): void {
  const { n, k } = D;
  // where v and the force start in a body record (see Body.storage: x, R, v, L, w, force, torque)
  const vAt = Body.velocityOffset(D);
  const forceAt = Body.stateLength(D);
  const h = constants[STEP_H]!;
  const linearScale = constants[STEP_LINEAR_SCALE]!;
  const angularScale = constants[STEP_ANGULAR_SCALE]!;
  for (let b = 0; b < count; b += 1) {
    const body = bodies[b]!;
    if (body.motion !== MOTION_DYNAMIC || body.sleeping) continue;
    // v and the force through the record (a body makes its views only when asked for them)
    const s = body.storage;
    const v = body.storageOffset + vAt;
    const f = body.storageOffset + forceAt;
    const im = body.invMass;
    for (let i = 0; i < n; i += 1) s[v + i] = s[v + i]! + h * (s[f + i]! * im + gravity[i]!);
    if (linearScale !== 1) for (let i = 0; i < n; i += 1) s[v + i] = s[v + i]! * linearScale;
    if (!body.hasTorque && angularScale === 1) continue;
    const L = body.L;
    if (body.hasTorque) {
      const t = body.torque;
      for (let p = 0; p < k; p += 1) L[p] = L[p]! + h * t[p]!;
    }
    if (angularScale !== 1) for (let p = 0; p < k; p += 1) L[p] = L[p]! * angularScale;
    angularVelocityFromMomentum(D, body.w, body.R, body.invInertia, L, tmp);
  }
}
