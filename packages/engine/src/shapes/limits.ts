/**
 * The bounds every public entry holds its numbers to, so that no derived quantity (1/m, the
 * inverse inertia, L = I ω, the kinetic energy, the next step's x + h v, a contact's effective
 * mass) can overflow or underflow to a value the step cannot use. Values beyond a bound are
 * refused with a RangeError that names the argument and the bound, before anything changes.
 *
 * The bounds are wide (a 1e-6 kg bead, a 1e6 kg ship, a 1000 m/s bullet, a 1 cm cube and a
 * 6400 km planet all fit, each by orders of magnitude), and narrow enough that the largest
 * product a step forms from them stays below 1e120, far from the largest double (1.8e308):
 * see docs/engine.md, "Limits on input".
 *
 * @module
 */

/** The bounds on input (SI units). Read them as `Body.limits`. */
export interface InputLimits {
  /** Smallest mass of a body with mass (kg); 0 still means static. */
  readonly minMass: number;
  /** Largest mass (kg). */
  readonly maxMass: number;
  /** Smallest size of a shape (m): a half extent, a radius, a mesh's extent. */
  readonly minLength: number;
  /** Largest size of a shape (m). */
  readonly maxLength: number;
  /** Largest coordinate of a position, an arm, an anchor, a mesh vertex or a plane offset (m). */
  readonly maxPosition: number;
  /** Smallest principal inertia of a body with mass (kg·m²). */
  readonly minInertia: number;
  /** Largest principal inertia (kg·m²). */
  readonly maxInertia: number;
  /** Largest component of a linear velocity a call sets or leaves (m/s). */
  readonly maxVelocity: number;
  /** Largest component of an angular velocity a call sets or leaves (rad/s). */
  readonly maxAngularVelocity: number;
  /** Largest component of an impulse argument (N·s). */
  readonly maxImpulse: number;
  /** Largest component of a force argument, and of the force accumulated for a step (N). */
  readonly maxForce: number;
  /** Largest component of a torque argument, and of the torque accumulated for a step (N·m). */
  readonly maxTorque: number;
  /** Largest component of the acceleration force / mass a body's accumulated force gives (m/s²). */
  readonly maxAcceleration: number;
  /** Largest component of the angular acceleration I⁻¹ τ a body's accumulated torque gives (rad/s²). */
  readonly maxAngularAcceleration: number;
  /** Largest joint frequency (Hz) and damping ratio. */
  readonly maxJointStiffness: number;
}

/** The bounds on input; see {@link InputLimits}. Frozen. */
export const inputLimits: InputLimits = Object.freeze({
  minMass: 1e-12,
  maxMass: 1e12,
  minLength: 1e-9,
  maxLength: 1e9,
  maxPosition: 1e12,
  minInertia: 1e-40,
  maxInertia: 1e40,
  maxVelocity: 1e8,
  maxAngularVelocity: 1e6,
  maxImpulse: 1e20,
  maxForce: 1e20,
  maxTorque: 1e32,
  maxAcceleration: 1e12,
  maxAngularAcceleration: 1e12,
  maxJointStiffness: 1e12,
});

/** A bound as a message prints it: 1e20, 1e-12, 100 (not 100000000000000000000). */
export function formatBound(x: number): string {
  const a = Math.abs(x);
  return a !== 0 && (a >= 1e5 || a < 1e-3) ? x.toExponential().replace('e+', 'e') : String(x);
}

/**
 * Throws a RangeError unless lo <= |x| <= hi (lo = 0: only the upper bound). `what` is the
 * argument as the message names it, e.g. `argument 'halfExtents'[2]` or `option 'mass'`.
 */
export function checkMagnitude(where: string, what: string, x: number, lo: number, hi: number, unit: string): void {
  const a = Math.abs(x);
  if (!(a <= hi) || a < lo) {
    const range = lo > 0 ? `within [${formatBound(lo)}, ${formatBound(hi)}] ${unit}` : `within ±${formatBound(hi)} ${unit}`;
    throw new RangeError(`${where}: ${what} must be ${range} (Body.limits), got ${x}`);
  }
}

/** Throws a RangeError unless every |x[i]| <= hi, naming the component. */
export function checkComponents(where: string, what: string, x: ArrayLike<number>, hi: number, unit: string): void {
  for (let i = 0; i < x.length; i += 1) {
    const a = Math.abs(x[i]!);
    if (!(a <= hi)) {
      throw new RangeError(`${where}: ${what}[${i}] must be within ±${formatBound(hi)} ${unit} (Body.limits), got ${x[i]}`);
    }
  }
}
