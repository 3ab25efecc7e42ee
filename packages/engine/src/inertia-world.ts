/**
 * World-frame inertia transforms of a body whose inertia is diagonal in its own (principal)
 * frame: ω = R·I⁻¹(R~ L R)·R~ and L = R·I(R~ ω R)·R~.
 *
 * These are unchecked hot-path kernels: the engine calls them every sub-step on data it validated
 * when the body was built, so they check nothing and allocate nothing. `tmp` is caller-owned
 * scratch of k numbers.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';

/**
 * out = I_world⁻¹ L = R·(invInertia ∘ (R~ L R))·R~: the world angular velocity (rad/s, bivector)
 * of a body with rotor R, body-frame inverse principal inertia `invInertia` (k numbers, 1/(kg·m²))
 * and world angular momentum L (kg·m²/s). Unchecked; `out` may alias L but not `tmp`.
 */
export function angularVelocityFromMomentum(
  D: Dims,
  out: Float64Array,
  R: Float64Array,
  invInertia: Float64Array,
  L: Float64Array,
  tmp: Float64Array,
): Float64Array {
  const K = D.kernels;
  K.applyBivectorInverse(tmp, R, L);
  for (let p = 0; p < D.k; p += 1) tmp[p] = tmp[p]! * invInertia[p]!;
  return K.applyBivector(out, R, tmp);
}

/**
 * out = I_world ω = R·(inertia ∘ (R~ ω R))·R~: the world angular momentum (kg·m²/s) of a body
 * with rotor R and body-frame principal inertia `inertia` (k numbers, kg·m²) turning at the world
 * angular velocity ω (rad/s). Unchecked; `out` may alias ω but not `tmp`.
 */
export function momentumFromAngularVelocity(
  D: Dims,
  out: Float64Array,
  R: Float64Array,
  inertia: Float64Array,
  omega: Float64Array,
  tmp: Float64Array,
): Float64Array {
  const K = D.kernels;
  K.applyBivectorInverse(tmp, R, omega);
  for (let p = 0; p < D.k; p += 1) tmp[p] = tmp[p]! * inertia[p]!;
  return K.applyBivector(out, R, tmp);
}
