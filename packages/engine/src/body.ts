/**
 * Rigid bodies: state, mass properties and the calls that push them around.
 *
 * @module
 */
import {
  checkBivector,
  checkDims,
  checkNumber,
  checkPlane,
  checkRotor,
  checkVector,
  rotateInPlane as rotorRotateInPlane,
  rotorReverse,
} from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { angularVelocityFromMomentum, momentumFromAngularVelocity } from './inertia-world.js';
import { bodyDefaults, ROTOR_INPUT_TOLERANCE } from './params.js';
import type { Shape } from './shapes/shape.js';
import { checkComponents, formatBound, inputLimits } from './shapes/limits.js';
import type { InputLimits } from './shapes/limits.js';
import type { Pose } from './collision/manifold.js';
import type { QueryShape } from './collision/query-shapes.js';
import type { CollisionEvent, CollisionListener } from './contacts/contact-events.js';
import { Float64Slab } from './slab.js';

/**
 * @internal What a body needs from the world that owns it: a way to wake it (the world also puts
 * its broadphase proxy back among the awake ones) and to learn that it was moved by hand.
 */
export interface BodyOwner {
  /** The body's sleep state or pose changed outside the step. */
  onBodyChanged(body: Body): void;
  /** The body's friction or restitution changed. */
  onMaterialChanged(body: Body): void;
}

/**
 * How a body moves.
 * - `'dynamic'`: moved by forces, gravity, impulses and (later) contacts and joints; mass > 0.
 * - `'static'`: never moves; infinite mass. A body of mass 0 is static.
 * - `'kinematic'`: moves by its own linear and angular velocity exactly, ignoring forces,
 *   gravity and contacts (infinite mass for everything it touches).
 */
export type BodyType = 'dynamic' | 'static' | 'kinematic';

/** Surface properties used by the contact solver. */
export interface Material {
  /** Coulomb friction coefficient (dimensionless, >= 0). */
  readonly friction: number;
  /** Coefficient of restitution (dimensionless, in [0, 1]): 0 = no bounce, 1 = elastic. */
  readonly restitution: number;
}

/** Options of `new Body(D, options)`. Vectors are any array-like of numbers; they are copied. */
export interface BodyOptions {
  /** The collision and mass shape. Its n must equal D.n (a ball, n = null, fits any n). */
  readonly shape: Shape;
  /**
   * Mass (kg, finite, >= 0). 0 makes the body static (unless `type` says 'kinematic').
   * Default: 1 for a dynamic or kinematic body, 0 for a half-space (which can only be static).
   */
  readonly mass?: number;
  /** How the body moves; default 'dynamic', or 'static' when mass is 0 or the shape a half-space. */
  readonly type?: BodyType;
  /**
   * Position (m, n numbers) of the origin of the coordinates the shape was described in (for most
   * shapes the centre of mass). Default: the world origin.
   */
  readonly position?: ArrayLike<number>;
  /** Orientation rotor (r numbers, a unit rotor); default the identity. Corrected to an exact rotor. */
  readonly rotor?: ArrayLike<number>;
  /** Linear velocity of the centre of mass (m/s, n numbers); default 0. Not allowed on a static body. */
  readonly velocity?: ArrayLike<number>;
  /** World angular velocity bivector (rad/s, k numbers); default 0. Not allowed on a static body. */
  readonly angularVelocity?: ArrayLike<number>;
  /** Friction and restitution; missing entries take `bodyDefaults`. */
  readonly material?: Partial<Material>;
  /** An optional name, used in error messages. */
  readonly name?: string;
  /**
   * The collision groups the body belongs to: a 32-bit mask (an integer in 0..2³²−1); default 1
   * (group 0). Two bodies make contacts only when each one's group meets the other's mask.
   */
  readonly collisionGroup?: number;
  /** The groups the body collides with: a 32-bit mask; default 0xffffffff (every group). */
  readonly collisionMask?: number;
  /**
   * A sensor reports 'begin' and 'end' events while it overlaps other bodies and makes no contact
   * impulses (nothing pushes it and it pushes nothing); two sensors do not see each other.
   * Default false.
   */
  readonly sensor?: boolean;
}

/**
 * @internal Motion codes of a body (an integer compare is cheaper than a string compare on the hot
 * path): {@link MOTION_DYNAMIC}, {@link MOTION_KINEMATIC}, {@link MOTION_STATIC}.
 */
export type Motion = 0 | 1 | 2;
/** @internal Motion code of a dynamic body. */
export const MOTION_DYNAMIC = 0;
/** @internal Motion code of a kinematic body. */
export const MOTION_KINEMATIC = 1;
/** @internal Motion code of a static body. */
export const MOTION_STATIC = 2;

const motionOf: Record<BodyType, Motion> = { dynamic: MOTION_DYNAMIC, kinematic: MOTION_KINEMATIC, static: MOTION_STATIC };
const typeOf: readonly BodyType[] = ['dynamic', 'kinematic', 'static'];

const OPTION_NAMES = new Set([
  'shape',
  'mass',
  'type',
  'position',
  'rotor',
  'velocity',
  'angularVelocity',
  'material',
  'name',
  'collisionGroup',
  'collisionMask',
  'sensor',
]);

/** The largest 32-bit collision mask. */
const ALL_GROUPS = 0xffffffff;

/** Checks a 32-bit collision mask (an integer in 0..2³²−1) and returns it. */
function checkGroupBits(fn: string, label: string, value: unknown): number {
  if (typeof value !== 'number') throw new TypeError(`${fn}: ${label} must be a number (a 32-bit mask), got ${typeof value}`);
  if (!Number.isInteger(value) || value < 0 || value > ALL_GROUPS) {
    throw new RangeError(`${fn}: ${label} must be an integer in 0..0xffffffff (a 32-bit mask), got ${value}`);
  }
  return value;
}

/** Checks a sensor flag and returns it. */
function checkSensorFlag(fn: string, label: string, value: unknown): boolean {
  if (typeof value !== 'boolean') throw new TypeError(`${fn}: ${label} must be a boolean, got ${typeof value}`);
  return value;
}

let nextBodyId = 1;

/**
 * Where bodies' records and inertias are cut from (see slab.ts): a body's own ArrayBuffer cost
 * more to make and to collect than everything else its constructor did.
 */
const bodySlab = new Float64Slab();

/** The material of a body whose options give none: one frozen object shared by all of them. */
const DEFAULT_MATERIAL: Material = Object.freeze({ friction: bodyDefaults.friction, restitution: bodyDefaults.restitution });

/**
 * The principal inertia last computed for a (shape, D, mass), checked: bodies built in a loop
 * share a shape and a mass, and its mass properties (a Gamma function for a ball, a sum over the
 * faces of a mesh) were a tenth of the constructor's time. Only for frozen shapes (every factory
 * freezes its shapes): a shape that could change must be asked each time. The dynamic bodies of
 * that (shape, D, mass) share this array as their `inertia`, and `lastInverse` as `invInertia`
 * (two views fewer per body; a body copies them before it changes them, see ownInertia).
 */
let lastMassShape: Shape | null = null;
let lastMassD: Dims | null = null;
let lastMass = 0;
let lastInertia: Float64Array | null = null;
let lastInverse: Float64Array | null = null;

/** Per-dimension scratch of the body methods (set-up calls, never the step). */
interface BodyScratch {
  readonly bivector: Float64Array;
  /** k numbers, the ω an impulse would give, checked before it is kept. */
  readonly omega: Float64Array;
  readonly tmp: Float64Array;
  readonly vector: Float64Array;
  /** k numbers, an angular acceleration I_world⁻¹ τ (the current one, beside `omega`'s new one). */
  readonly alpha: Float64Array;
  /** r numbers, for setRotor / getRotor. */
  readonly rotor: Float64Array;
  /** n numbers, the described origin kept by setRotor. */
  readonly origin: Float64Array;
}
const scratchByN: (BodyScratch | undefined)[] = [];
function scratchFor(D: Dims): BodyScratch {
  return (scratchByN[D.n] ??= {
    bivector: new Float64Array(D.k),
    omega: new Float64Array(D.k),
    alpha: new Float64Array(D.k),
    tmp: new Float64Array(D.k),
    vector: new Float64Array(D.n),
    rotor: new Float64Array(D.r),
    origin: new Float64Array(D.n),
  });
}

/** The largest distance of a point of the shape from its local origin (m); 0 for a half-space. */
function shapeBoundingRadius(n: number, shape: Shape): number {
  // a compound knows its own: the farthest point of any part from the centre of mass
  if (shape.kind === 'compound') return (shape as unknown as { readonly boundingRadius: number }).boundingRadius;
  const g = shape as unknown as QueryShape;
  switch (g.kind) {
    case 'box': {
      let s = 0;
      for (let i = 0; i < n; i += 1) s += g.halfExtents[i]! * g.halfExtents[i]!;
      return Math.sqrt(s);
    }
    case 'sphere':
      return g.radius;
    case 'torus':
      return g.majorRadius + g.minorRadius;
    case 'capsule':
      return g.halfHeight + g.radius;
    case 'mesh': {
      let best = 0;
      if (g.vertices === undefined) return 0; // a shape-like object without geometry (tests)
      for (let v = 0; v < g.vertices.length; v += n) {
        let s = 0;
        for (let i = 0; i < n; i += 1) s += g.vertices[v + i]! * g.vertices[v + i]!;
        if (s > best) best = s;
      }
      return Math.sqrt(best);
    }
    default:
      return 0;
  }
}

function isZero(a: ArrayLike<number>): boolean {
  for (let i = 0; i < a.length; i += 1) if (a[i] !== 0) return false;
  return true;
}

/**
 * Throws a RangeError naming `name` unless base + scale·add stays within ±`max` in every component
 * (or, for a component already beyond it, does not grow): a call must never put a non-finite
 * number into a body (two impulses of 1e308 would), nor a value whose next step could overflow.
 */
function checkSumBounded(
  fn: string,
  name: string,
  label: string,
  field: string,
  base: Float64Array,
  add: ArrayLike<number>,
  scale: number,
  max: number,
  unit: string,
): void {
  for (let i = 0; i < base.length; i += 1) {
    const next = base[i]! + add[i]! * scale;
    const a = Math.abs(next);
    if (!(a <= max || a <= Math.abs(base[i]!))) {
      const what = Number.isFinite(next) ? `${next}, beyond ±${formatBound(max)} ${unit} (Body.limits)` : 'non-finite';
      throw new RangeError(`${fn}: argument '${name}' would make ${label}'s ${field}[${i}] ${what}; nothing was changed`);
    }
  }
}

/**
 * Throws a RangeError unless the acceleration (base + add)·invMass stays within ±maxAcceleration in
 * every component (or, for one already beyond it, does not grow): a force on a light body must
 * not give a step a velocity or position that overflows.
 */
function checkAcceleration(
  fn: string,
  name: string,
  label: string,
  base: Float64Array,
  add: ArrayLike<number>,
  invMass: number,
): void {
  const max = inputLimits.maxAcceleration;
  for (let i = 0; i < base.length; i += 1) {
    const next = Math.abs((base[i]! + add[i]!) * invMass);
    if (!(next <= max || next <= Math.abs(base[i]! * invMass))) {
      throw new RangeError(
        `${fn}: argument '${name}' would give ${label} an acceleration[${i}] (force / mass) of ${formatBound(next)} m/s², beyond ±${formatBound(max)} m/s² (Body.limits); nothing was changed`,
      );
    }
  }
}

/** Throws unless every principal inertia is within [minInertia, maxInertia] (a body with mass). */
function checkInertia(fn: string, what: string, inertia: ArrayLike<number>, mass: number): void {
  const { minInertia, maxInertia } = inputLimits;
  for (let p = 0; p < inertia.length; p += 1) {
    const I = inertia[p]!;
    if (!(I >= minInertia && I <= maxInertia)) {
      throw new RangeError(
        `${fn}: ${what} gives principal inertia[${p}] = ${I} kg·m² for mass ${mass} kg, outside [${formatBound(minInertia)}, ${formatBound(maxInertia)}] (Body.limits); nothing was changed`,
      );
    }
  }
}

/** Throws unless m is 0 (static) or within [minMass, maxMass]. */
function checkMassValue(fn: string, what: string, m: number): void {
  if (m < 0) throw new RangeError(`${fn}: ${what} must be >= 0 (0 = static), got ${m}`);
  if (m !== 0 && !(m >= inputLimits.minMass && m <= inputLimits.maxMass)) {
    throw new RangeError(
      `${fn}: ${what} must be 0 (static) or within [${formatBound(inputLimits.minMass)}, ${formatBound(inputLimits.maxMass)}] kg (Body.limits), got ${m}`,
    );
  }
}

/** out = base + a ∧ b into `out` (k numbers), then true if every component is finite. */
function wedgeSumFinite(D: Dims, out: Float64Array, base: Float64Array, a: ArrayLike<number>, b: ArrayLike<number>): boolean {
  const { k, planeI, planeJ } = D;
  let finite = true;
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    out[p] = base[p]! + (a[i]! * b[j]! - a[j]! * b[i]!);
    if (!Number.isFinite(out[p]!)) finite = false;
  }
  return finite;
}

/**
 * A rigid body in n dimensions.
 *
 * **State** (SI units, world frame), all `Float64Array` views of the body's record (each made when first read):
 * - `x` (n): position of the centre of mass (m);
 * - `R` (r = 2^(n−1)): orientation rotor; a body point at ξ in the body frame is at x + R ξ R~;
 * - `v` (n): linear velocity of the centre of mass (m/s);
 * - `L` (k = n(n−1)/2): angular momentum bivector about the centre of mass (kg·m²/s) — the
 *   angular state: a torque-free dynamic body keeps it bit-exactly;
 * - `w` (k): angular velocity bivector (rad/s), derived: ω = I_world⁻¹ L, rebuilt whenever L or R
 *   changes (for a kinematic body ω is the given value and L is derived from it);
 * - `force` (n, N) and `torque` (k, N·m): accumulated since the last step, cleared by each step.
 *
 * The body frame is the principal frame of the shape, so the inertia is diagonal there
 * (`inertia`, k numbers, I_(ij) = C_ii + C_jj). Read the fields at any time; write them only through
 * the methods (they keep ω, L and the mass in agreement). The views may be rebound to other
 * storage when a world packs its bodies into flat arrays: read `body.x` anew rather than keeping
 * the array.
 */
export class Body {
  /**
   * The bounds every call holds its numbers to (SI units, frozen): masses, inertias, sizes,
   * positions, velocities, impulses, forces and torques beyond them are refused with a RangeError
   * that names the argument and the bound, before anything changes (docs/engine.md, "Limits on
   * input"). The shape factories and the joints hold theirs to the same bounds.
   */
  static readonly limits: InputLimits = inputLimits;

  /** A positive integer, unique in this process. */
  readonly id: number;
  /** The optional name given in the options (for messages). */
  readonly name: string | undefined;
  /** The tables of the body's dimension. */
  readonly D: Dims;
  /** The shape (shared, immutable). */
  readonly shape: Shape;
  /** Surface properties (frozen; change them with {@link Body.setMaterial}). */
  get material(): Material {
    return this.materialValue;
  }
  private materialValue: Material;

  /**
   * The collision groups the body belongs to (a 32-bit mask; default 1). Two bodies make contacts
   * only when (a.collisionGroup & b.collisionMask) and (b.collisionGroup & a.collisionMask) are
   * both nonzero; `World.pairFilter` may refuse a pair besides. Setting it wakes the body.
   * @throws TypeError / RangeError unless an integer in 0..0xffffffff.
   */
  get collisionGroup(): number {
    return this.groupBits;
  }
  /** Sets the groups the body belongs to (see the getter); wakes the body. */
  set collisionGroup(value: number) {
    this.groupBits = checkGroupBits('Body.collisionGroup', "value 'collisionGroup'", value);
    this.wake();
  }
  /**
   * The groups the body collides with (a 32-bit mask; default 0xffffffff, every group). Setting
   * it wakes the body.
   * @throws TypeError / RangeError unless an integer in 0..0xffffffff.
   */
  get collisionMask(): number {
    return this.maskBits;
  }
  /** Sets the groups the body collides with (see the getter); wakes the body. */
  set collisionMask(value: number) {
    this.maskBits = checkGroupBits('Body.collisionMask', "value 'collisionMask'", value);
    this.wake();
  }
  /**
   * Whether the body is a sensor: it reports 'begin' / 'end' events while it overlaps another
   * body and makes no contact impulses (it falls through the floor if dynamic); two sensors do
   * not see each other. Setting it wakes the body.
   * @throws TypeError unless a boolean.
   */
  get sensor(): boolean {
    return this.sensorFlag;
  }
  /** Makes the body a sensor or a solid body again (see the getter); wakes the body. */
  set sensor(value: boolean) {
    this.sensorFlag = checkSensorFlag('Body.sensor', "value 'sensor'", value);
    this.wake();
  }
  /** @internal The collision group bits (see collisionGroup). */
  groupBits: number;
  /** @internal The collision mask bits (see collisionMask). */
  maskBits: number;
  /** @internal Whether the body is a sensor. */
  sensorFlag: boolean;

  /** @internal Motion code: MOTION_DYNAMIC, MOTION_KINEMATIC or MOTION_STATIC. */
  motion: Motion;
  /** @internal Mass (kg); 0 for static and massless kinematic bodies. */
  massValue: number;
  /** @internal 1/mass for dynamic bodies, 0 otherwise (infinite mass for the solver). */
  invMass: number;
  /**
   * Principal inertia in the body frame (k numbers, kg·m²); zeros when the body has no mass.
   * Read only: use `setMass` to change it (bodies of the same shape and mass may share the array).
   */
  readonly inertia: Float64Array;
  /**
   * Inverse principal inertia (k numbers, body frame); zeros for static and kinematic bodies. Read
   * only (shared like `inertia`).
   */
  readonly invInertia: Float64Array;
  /** Whether `inertia` and `invInertia` are this body's own, not the arrays its (shape, mass) shares. */
  private ownsInertia: boolean;
  /**
   * @internal The centre of mass seen from the origin of the coordinates the shape was described
   * in, in the body frame (n numbers): x = origin + R·comOffset. null when the two coincide.
   */
  readonly comOffset: Float64Array | null;

  /**
   * @internal The buffer holding x, R, v, L, w, force, torque (in this order) at `storageOffset`;
   * shared with other bodies (a block of records, see slab.ts).
   */
  storage: Float64Array;
  /** @internal Offset of this body's record in `storage`. */
  storageOffset: number;
  /** @internal Whether a torque was applied since the last step. */
  hasTorque = false;
  /** @internal The world this body belongs to, or null. */
  owner: BodyOwner | null = null;
  /** @internal The body's broadphase proxy in its world, or -1. */
  proxyId = -1;
  /** @internal The pose the collision code reads (x and rotation matrix), filled by the world. */
  pose: Pose | null = null;
  /** @internal Whether the body sleeps (dynamic bodies only): it is neither integrated nor solved. */
  sleeping = false;
  /** @internal Seconds the body has been slower than the sleep thresholds. */
  sleepTimer = 0;
  /** @internal The pose changed by hand since the world last read it (setPositionN, rotateInPlane). */
  poseDirty = true;
  /** @internal Index in the world's body list. */
  worldIndex = -1;
  /** @internal Solver slot of the current sub-step (0 = the immovable slot), or -1. */
  solverSlot = -1;
  /**
   * @internal The bodies this one must not collide with: the other bodies of its joints with
   * collideConnected false (one entry per joint), or null.
   */
  jointPeers: Body[] | null = null;
  /** @internal Count of joints of its world that hold this body. */
  jointCount = 0;
  private listeners: CollisionListener[] | null = null;
  /** @internal Largest distance of a shape point from the centre of mass (m); 0 for a half-space. */
  boundingRadius = 0;

  /**
   * The views of the record (x, R, v, L, w, force, torque), made together when one is first
   * asked for: a view is a heap object, and the step reads the record through `storage`, so the
   * 32,000 balls of a world built and stepped untouched never need theirs.
   */
  private views: Float64Array[] | null = null;

  /**
   * Builds a body. Every option is checked before anything is built (TypeError for a wrong type or
   * length, RangeError for a bad value, naming the option).
   *
   * For a shape that carries a principal frame (`frameOffset`, `frameRotor`: convex meshes), the
   * pose given is that of the coordinates the shape was described in, and the body's state is the
   * principal frame: x = position + R_given·frameOffset, R = R_given·frameRotor.
   */
  constructor(D: Dims, options: BodyOptions) {
    const fn = 'new Body';
    checkDims(D, fn);
    if (options === null || typeof options !== 'object') {
      throw new TypeError(
        `${fn}: argument 'options' must be an object with at least 'shape', got ${options === null ? 'null' : typeof options}`,
      );
    }
    for (const key of Object.keys(options)) {
      if (!OPTION_NAMES.has(key)) {
        throw new RangeError(`${fn}: unknown option '${key}' (known: ${[...OPTION_NAMES].join(', ')})`);
      }
    }
    const { n, k } = D;
    const shape = options.shape as Shape | undefined;
    if (
      shape === null ||
      typeof shape !== 'object' ||
      typeof (shape as { kind?: unknown }).kind !== 'string' ||
      typeof (shape as { massProperties?: unknown }).massProperties !== 'function'
    ) {
      throw new TypeError(
        `${fn}: option 'shape' must be a shape (HyperBox, HyperSphere, HalfSpace, ...), got ${shape === null ? 'null' : typeof shape}`,
      );
    }
    if (shape.n !== null && shape.n !== n) {
      throw new RangeError(`${fn}: option 'shape' was built for n = ${shape.n} but the body's D has n = ${n}`);
    }
    const name = options.name;
    if (name !== undefined && typeof name !== 'string') {
      throw new TypeError(`${fn}: option 'name' must be a string, got ${typeof name}`);
    }
    const isHalfSpace = shape.kind === 'halfspace';
    let mass: number;
    if (options.mass === undefined) {
      mass = options.type === 'static' || isHalfSpace ? 0 : bodyDefaults.mass;
    } else {
      checkNumber('mass', options.mass, fn);
      mass = options.mass;
      checkMassValue(fn, "option 'mass'", mass);
    }
    let type: BodyType;
    if (options.type === undefined) {
      type = mass === 0 ? 'static' : 'dynamic';
    } else {
      if (typeof options.type !== 'string') {
        throw new TypeError(`${fn}: option 'type' must be 'dynamic', 'static' or 'kinematic', got ${typeof options.type}`);
      }
      if (!(options.type in motionOf)) {
        throw new RangeError(`${fn}: option 'type' must be 'dynamic', 'static' or 'kinematic', got '${options.type}'`);
      }
      type = options.type;
    }
    if (type === 'dynamic' && mass === 0) {
      throw new RangeError(`${fn}: a dynamic body needs option 'mass' > 0 (mass 0 means static)`);
    }
    if (type === 'static') mass = 0;
    if (isHalfSpace && mass > 0) {
      throw new RangeError(
        `${fn}: option 'shape' is a half-space, which has no finite mass: give it mass 0 (static) or type 'kinematic' with mass 0`,
      );
    }
    const lim = inputLimits;
    if (options.position !== undefined) {
      checkVector(D, 'position', options.position, fn);
      checkComponents(fn, "option 'position'", options.position, lim.maxPosition, 'm');
    }
    if (options.rotor !== undefined) {
      checkRotor(D, 'rotor', options.rotor, fn);
      const defect = D.kernels.defect(Float64Array.from(options.rotor));
      if (!(defect <= ROTOR_INPUT_TOLERANCE)) {
        throw new RangeError(
          `${fn}: option 'rotor' must be a unit rotor (defect |R R~ - 1| <= ${ROTOR_INPUT_TOLERANCE}), got defect ${defect}`,
        );
      }
    }
    if (options.velocity !== undefined) {
      checkVector(D, 'velocity', options.velocity, fn);
      checkComponents(fn, "option 'velocity'", options.velocity, lim.maxVelocity, 'm/s');
    }
    if (options.angularVelocity !== undefined) {
      checkBivector(D, 'angularVelocity', options.angularVelocity, fn);
      checkComponents(fn, "option 'angularVelocity'", options.angularVelocity, lim.maxAngularVelocity, 'rad/s');
    }
    if (type === 'static') {
      if (
        (options.velocity !== undefined && !isZero(options.velocity)) ||
        (options.angularVelocity !== undefined && !isZero(options.angularVelocity))
      ) {
        throw new RangeError(
          `${fn}: a static body cannot have a velocity; use type 'kinematic' for a body that moves by its velocity`,
        );
      }
    }
    const material = checkMaterial(options.material, fn);
    const groupBits =
      options.collisionGroup === undefined ? 1 : checkGroupBits(fn, "option 'collisionGroup'", options.collisionGroup);
    const maskBits =
      options.collisionMask === undefined ? ALL_GROUPS : checkGroupBits(fn, "option 'collisionMask'", options.collisionMask);
    const sensorFlag = options.sensor === undefined ? false : checkSensorFlag(fn, "option 'sensor'", options.sensor);
    const frameOffset = shape.frameOffset;
    const frameRotor = shape.frameRotor;
    if (frameOffset !== undefined) {
      checkVector(D, 'shape.frameOffset', frameOffset, fn);
      checkComponents(fn, "option 'shape'.frameOffset", frameOffset, lim.maxPosition, 'm');
    }
    if (frameRotor !== undefined) checkRotor(D, 'shape.frameRotor', frameRotor, fn);
    let principal: Float64Array | null = null;
    if (mass > 0) {
      if (shape === lastMassShape && D === lastMassD && mass === lastMass) principal = lastInertia;
      else {
        const mp = shape.massProperties(D, mass);
        checkBivector(D, 'shape.massProperties(D, mass).inertia', mp.inertia, fn);
        checkInertia(fn, "option 'shape' with option 'mass'", mp.inertia, mass);
        principal = Float64Array.from(mp.inertia);
        const frozen = Object.isFrozen(shape);
        lastMassShape = frozen ? shape : null;
        lastMassD = frozen ? D : null;
        lastMass = mass;
        lastInertia = frozen ? principal : null;
        lastInverse = null;
      }
    }
    // All checks passed: build. One run of the slab holds the record, then (unless this dynamic
    // body shares the arrays of its shape and mass) inertia and its inverse.
    const shares = type === 'dynamic' && principal !== null && principal === lastInertia;
    const recordLength = Body.recordLength(D);
    const start = bodySlab.reserve(shares ? recordLength : recordLength + 2 * k);
    const block = bodySlab.current;
    let inertia: Float64Array;
    let invInertia: Float64Array;
    if (shares) {
      inertia = principal!;
      invInertia = lastInverse ??= inverseOf(principal!);
    } else {
      inertia = new Float64Array(block.buffer, block.byteOffset + (start + recordLength) * 8, k);
      invInertia = new Float64Array(block.buffer, block.byteOffset + (start + recordLength + k) * 8, k);
      if (principal !== null) inertia.set(principal);
    }
    this.id = nextBodyId;
    nextBodyId += 1;
    this.name = name;
    this.D = D;
    this.shape = shape;
    this.materialValue = material;
    this.groupBits = groupBits;
    this.maskBits = maskBits;
    this.sensorFlag = sensorFlag;
    this.motion = motionOf[type];
    this.massValue = mass;
    this.invMass = type === 'dynamic' ? 1 / mass : 0;
    this.inertia = inertia;
    this.invInertia = invInertia;
    this.ownsInertia = !shares;
    if (!shares) this.fillInverseInertia();
    this.storage = block;
    this.storageOffset = start;

    // The record is written through `block` (no view made): a ball or box placed by position alone
    // gets no view at all until something reads one.
    const K = D.kernels;
    block[start + n] = 1;
    if (options.rotor !== undefined) {
      const R = this.R;
      R.set(options.rotor);
      if (K.defect(R) > 0) K.correct(R, R);
    }
    let comOffset: Float64Array | null = null;
    if (frameOffset !== undefined && !isZero(frameOffset)) {
      // Centre of mass seen from the described origin, in the body (principal) frame.
      comOffset = new Float64Array(n);
      if (frameRotor !== undefined)
        K.applyVectorInverse(comOffset, Float64Array.from(frameRotor), Float64Array.from(frameOffset));
      else comOffset.set(frameOffset);
    }
    this.comOffset = comOffset;
    if (frameRotor !== undefined) {
      const R = this.R;
      K.mul(R, R, Float64Array.from(frameRotor));
      if (K.defect(R) > 0) K.correct(R, R);
    }
    if (options.position !== undefined) block.set(options.position, start);
    this.placeCentreOfMass();
    this.boundingRadius = shapeBoundingRadius(D.n, shape);
    if (options.velocity !== undefined) block.set(options.velocity, start + Body.velocityOffset(D));
    if (options.angularVelocity !== undefined) {
      this.w.set(options.angularVelocity);
      this.momentumFromOmega();
    }
  }

  /** Number of Float64 entries of one body record: x, R, v, L, w (the state), then force, torque. */
  static recordLength(D: Dims): number {
    return Body.stateLength(D) + D.n + D.k;
  }

  /** Number of Float64 entries of the state part of a record: x (n), R (r), v (n), L (k), w (k). */
  static stateLength(D: Dims): number {
    return 2 * D.n + D.r + 2 * D.k;
  }

  /**
   * @internal Where v starts in a record (after x and R); L follows v, w follows L, and the force
   * starts at {@link Body.stateLength}. For the step's loops, which read the record, not the views.
   */
  static velocityOffset(D: Dims): number {
    return D.n + D.r;
  }

  /** How the body moves: 'dynamic', 'static' or 'kinematic'. */
  get type(): BodyType {
    return typeOf[this.motion]!;
  }

  /** Mass (kg); 0 for a static body. */
  get mass(): number {
    return this.massValue;
  }

  /** Position of the centre of mass (m, n numbers). */
  get x(): Float64Array {
    return (this.views ??= this.bindViews())[0]!;
  }
  /** Orientation rotor (r numbers). */
  get R(): Float64Array {
    return (this.views ??= this.bindViews())[1]!;
  }
  /** Linear velocity (m/s, n numbers). */
  get v(): Float64Array {
    return (this.views ??= this.bindViews())[2]!;
  }
  /** Angular momentum about the centre of mass, world frame (kg·m²/s, k numbers). */
  get L(): Float64Array {
    return (this.views ??= this.bindViews())[3]!;
  }
  /** Angular velocity, world frame (rad/s, k numbers): I_world⁻¹ L. */
  get w(): Float64Array {
    return (this.views ??= this.bindViews())[4]!;
  }
  /** Force accumulated since the last step (N, n numbers). */
  get force(): Float64Array {
    return (this.views ??= this.bindViews())[5]!;
  }
  /** Torque accumulated since the last step (N·m, bivector, k numbers). */
  get torque(): Float64Array {
    return (this.views ??= this.bindViews())[6]!;
  }

  /** A short description for messages: `body 7 ('crate')`. */
  get label(): string {
    return this.name === undefined ? `body ${this.id}` : `body ${this.id} ('${this.name}')`;
  }

  /**
   * Adds a listener of collision events: `'collision'` is called after each step in which this
   * body begins or ends touching another (see CollisionEvent; the event object is reused).
   * @throws TypeError if `type` is not 'collision' or `listener` is not a function.
   */
  addEventListener(type: 'collision', listener: CollisionListener): this {
    checkListener('Body.addEventListener', type, listener);
    (this.listeners ??= []).push(listener);
    return this;
  }

  /** Removes a listener added with {@link Body.addEventListener} (no effect if it is not there). */
  removeEventListener(type: 'collision', listener: CollisionListener): this {
    checkListener('Body.removeEventListener', type, listener);
    const list = this.listeners;
    if (list) {
      const i = list.indexOf(listener);
      if (i >= 0) list.splice(i, 1);
    }
    return this;
  }

  /** @internal Whether any collision listener is registered. */
  get hasListeners(): boolean {
    return this.listeners !== null && this.listeners.length > 0;
  }

  /** @internal Calls the collision listeners with `event`. */
  emitCollision(event: CollisionEvent): void {
    const list = this.listeners;
    if (list === null) return;
    for (let i = 0; i < list.length; i += 1) list[i]!(event);
  }

  /** Whether the body sleeps: it stays where it is, unmoved, until something touches or pushes it. */
  get isSleeping(): boolean {
    return this.sleeping;
  }

  /**
   * Wakes the body (and, at the next step, every body resting on it or under it). Every call that
   * changes a velocity, pushes, or moves the body wakes it by itself; call this after writing to
   * a field directly.
   */
  wake(): this {
    this.sleepTimer = 0;
    if (this.sleeping) {
      this.sleeping = false;
      this.owner?.onBodyChanged(this);
    }
    return this;
  }

  /** The pose was changed by hand: the world must read it again, and the body wakes. */
  private movedByHand(): void {
    this.poseDirty = true;
    this.sleepTimer = 0;
    this.sleeping = false;
    this.owner?.onBodyChanged(this);
  }

  /**
   * @internal A view of x, R, v, L, w as one record (a new view per call: for tests and error
   * paths; the step reads `storage` at `storageOffset`).
   */
  get stateView(): Float64Array {
    return this.storage.subarray(this.storageOffset, this.storageOffset + Body.stateLength(this.D));
  }

  /** The views of x, R, v, L, w, force and torque, made straight on the buffer (subarray() looks up the species constructor). */
  private bindViews(): Float64Array[] {
    const { n, r, k } = this.D;
    const s = this.storage;
    let at = s.byteOffset + this.storageOffset * 8;
    const views: Float64Array[] = [];
    for (const len of [n, r, n, k, k, n, k]) {
      views.push(new Float64Array(s.buffer, at, len));
      at += len * 8;
    }
    return views;
  }

  /**
   * @internal Gives the body inertia arrays of its own (copies of the ones its shape and mass
   * share) before anything writes into them: setMass, a snapshot's restore.
   */
  ownInertia(): void {
    if (this.ownsInertia) return;
    const k = this.D.k;
    const inertia = bodySlab.take(k);
    const invInertia = bodySlab.take(k);
    inertia.set(this.inertia);
    invInertia.set(this.invInertia);
    const self = this as unknown as { inertia: Float64Array; invInertia: Float64Array };
    self.inertia = inertia;
    self.invInertia = invInertia;
    this.ownsInertia = true;
  }

  private fillInverseInertia(): void {
    const dynamic = this.motion === MOTION_DYNAMIC;
    for (let p = 0; p < this.D.k; p += 1) {
      const I = this.inertia[p]!;
      this.invInertia[p] = dynamic && I > 0 ? 1 / I : 0;
    }
  }

  /** L = I_world ω from the current w (massless: L = 0). */
  private momentumFromOmega(): void {
    if (this.massValue > 0) {
      momentumFromAngularVelocity(this.D, this.L, this.R, this.inertia, this.w, scratchFor(this.D).tmp);
    } else {
      this.L.fill(0);
    }
  }

  /** @internal ω = I_world⁻¹ L for a dynamic body (call after any change of L or R). */
  omegaFromMomentum(): void {
    if (this.motion === MOTION_DYNAMIC) {
      angularVelocityFromMomentum(this.D, this.w, this.R, this.invInertia, this.L, scratchFor(this.D).tmp);
    }
  }

  /** Moves x so the described origin (see `setPositionN`) is at `p`: x = p + R·comOffset. */
  private placeCentreOfMass(): void {
    const off = this.comOffset;
    if (off === null) return;
    const c = scratchFor(this.D).vector;
    this.D.kernels.applyVector(c, this.R, off);
    for (let i = 0; i < this.D.n; i += 1) this.x[i] = this.x[i]! + c[i]!;
  }

  /**
   * Kinetic energy (J): ½ m |v|² + ½ L·ω. 0 for a static body; for a kinematic body, the energy of
   * its given mass moving at its given velocity.
   */
  kineticEnergy(): number {
    if (this.massValue === 0) return 0;
    let lin = 0;
    for (let i = 0; i < this.D.n; i += 1) lin += this.v[i]! * this.v[i]!;
    let ang = 0;
    for (let p = 0; p < this.D.k; p += 1) ang += this.L[p]! * this.w[p]!;
    return 0.5 * (this.massValue * lin + ang);
  }

  /**
   * Writes the position (m, n numbers) of the origin of the coordinates the shape was described in
   * (the centre of mass for every shape without a `frameOffset`) into `out` and returns it.
   */
  getPositionN(out: Float64Array = new Float64Array(this.D.n)): Float64Array {
    const { n } = this.D;
    if (!(out instanceof Float64Array) || out.length !== n) {
      throw new TypeError(`Body.getPositionN: argument 'out' must be a Float64Array of length ${n}`);
    }
    out.set(this.x);
    const off = this.comOffset;
    if (off !== null) {
      const c = scratchFor(this.D).vector;
      this.D.kernels.applyVector(c, this.R, off);
      for (let i = 0; i < n; i += 1) out[i] = out[i]! - c[i]!;
    }
    return out;
  }

  /**
   * Moves the body (a teleport; velocities are kept) so that the origin of the coordinates its shape
   * was described in is at `p` (m, n numbers) — the centre of mass for every shape without a
   * `frameOffset`. Allowed on every type of body.
   */
  setPositionN(p: ArrayLike<number>): this {
    checkVector(this.D, 'p', p, 'Body.setPositionN');
    checkComponents('Body.setPositionN', "argument 'p'", p, inputLimits.maxPosition, 'm');
    this.x.set(p);
    this.placeCentreOfMass();
    this.movedByHand();
    return this;
  }

  /**
   * Turns the body by `angle` (rad) in the world plane (i, j), e_i toward e_j, about the origin of
   * the coordinates its shape was described in (which stays in place). The world angular velocity
   * is kept; L is recomputed for the new orientation.
   */
  rotateInPlane(i: number, j: number, angle: number): this {
    const fn = 'Body.rotateInPlane';
    checkPlane(this.D, 'i', i, 'j', j, fn);
    checkNumber('angle', angle, fn);
    const origin = this.comOffset === null ? null : this.getPositionN();
    rotorRotateInPlane(this.D, this.R, this.R, i, j, angle);
    if (origin !== null) {
      this.x.set(origin);
      this.placeCentreOfMass();
    }
    if (this.motion !== MOTION_STATIC) this.momentumFromOmega();
    this.movedByHand();
    return this;
  }

  /** Sets the linear velocity (m/s, n numbers). A static body accepts only zero. */
  setLinearVelocity(v: ArrayLike<number>): this {
    const fn = 'Body.setLinearVelocity';
    checkVector(this.D, 'v', v, fn);
    checkComponents(fn, "argument 'v'", v, inputLimits.maxVelocity, 'm/s');
    if (this.motion === MOTION_STATIC && !isZero(v)) {
      throw new RangeError(`${fn}: ${this.label} is static and cannot move (argument 'v' must be zero)`);
    }
    this.v.set(v);
    this.wake();
    return this;
  }

  /**
   * Sets the world angular velocity bivector ω (rad/s, k numbers) and the angular momentum that
   * goes with it, L = I_world ω. A static body accepts only zero.
   */
  setAngularVelocity(w: ArrayLike<number>): this {
    const fn = 'Body.setAngularVelocity';
    checkBivector(this.D, 'w', w, fn);
    checkComponents(fn, "argument 'w'", w, inputLimits.maxAngularVelocity, 'rad/s');
    if (this.motion === MOTION_STATIC && !isZero(w)) {
      throw new RangeError(`${fn}: ${this.label} is static and cannot turn (argument 'w' must be zero)`);
    }
    this.w.set(w);
    this.momentumFromOmega();
    this.wake();
    return this;
  }

  /**
   * Applies an impulse j (N·s, n numbers) at the centre of mass: v += j/m. No effect on static and
   * kinematic bodies (infinite mass).
   */
  applyCentralImpulse(j: ArrayLike<number>): this {
    const fn = 'Body.applyCentralImpulse';
    checkVector(this.D, 'j', j, fn);
    checkComponents(fn, "argument 'j'", j, inputLimits.maxImpulse, 'N·s');
    if (this.motion !== MOTION_DYNAMIC) return this;
    const im = this.invMass;
    checkSumBounded(fn, 'j', this.label, 'velocity', this.v, j, im, inputLimits.maxVelocity, 'm/s');
    for (let i = 0; i < this.D.n; i += 1) this.v[i] = this.v[i]! + j[i]! * im;
    this.wake();
    return this;
  }

  /**
   * Applies an impulse j (N·s, n numbers) at the arm r (m, n numbers: the point of application minus
   * the centre of mass, world frame): v += j/m, L += r ∧ j, then ω = I_world⁻¹ L. No effect on static
   * and kinematic bodies.
   */
  applyImpulse(j: ArrayLike<number>, r: ArrayLike<number>): this {
    const fn = 'Body.applyImpulse';
    checkVector(this.D, 'j', j, fn);
    checkVector(this.D, 'r', r, fn);
    checkComponents(fn, "argument 'j'", j, inputLimits.maxImpulse, 'N·s');
    checkComponents(fn, "argument 'r'", r, inputLimits.maxPosition, 'm');
    if (this.motion !== MOTION_DYNAMIC) return this;
    const im = this.invMass;
    checkSumBounded(fn, 'j', this.label, 'velocity', this.v, j, im, inputLimits.maxVelocity, 'm/s');
    // the new L and its ω first, into scratch: committed only if both are finite
    const scratch = scratchFor(this.D);
    const L = scratch.bivector;
    const w = scratch.omega;
    let finite = wedgeSumFinite(this.D, L, this.L, r, j);
    if (finite) {
      angularVelocityFromMomentum(this.D, w, this.R, this.invInertia, L, scratch.tmp);
      for (let p = 0; p < this.D.k; p += 1) if (!Number.isFinite(w[p]!)) finite = false;
    }
    if (!finite)
      throw new RangeError(
        `${fn}: arguments 'j' and 'r' would make ${this.label}'s angular momentum non-finite; nothing was changed`,
      );
    const maxW = inputLimits.maxAngularVelocity;
    for (let p = 0; p < this.D.k; p += 1) {
      const a = Math.abs(w[p]!);
      if (!(a <= maxW || a <= Math.abs(this.w[p]!))) {
        throw new RangeError(
          `${fn}: arguments 'j' and 'r' would make ${this.label}'s angular velocity[${p}] ${w[p]}, beyond ±${formatBound(maxW)} rad/s (Body.limits); nothing was changed`,
        );
      }
    }
    for (let i = 0; i < this.D.n; i += 1) this.v[i] = this.v[i]! + j[i]! * im;
    this.L.set(L);
    this.w.set(w);
    this.wake();
    return this;
  }

  /** Adds a force f (N, n numbers) at the centre of mass, for the next step. Ignored by static and kinematic bodies. */
  applyCentralForce(f: ArrayLike<number>): this {
    const fn = 'Body.applyCentralForce';
    checkVector(this.D, 'f', f, fn);
    checkComponents(fn, "argument 'f'", f, inputLimits.maxForce, 'N');
    if (this.motion !== MOTION_DYNAMIC) return this;
    checkSumBounded(fn, 'f', this.label, 'force', this.force, f, 1, inputLimits.maxForce, 'N');
    checkAcceleration(fn, 'f', this.label, this.force, f, this.invMass);
    for (let i = 0; i < this.D.n; i += 1) this.force[i] = this.force[i]! + f[i]!;
    this.wake();
    return this;
  }

  /**
   * Adds a force f (N) at the arm r (m, world frame, from the centre of mass) for the next step:
   * force += f, torque += r ∧ f. Ignored by static and kinematic bodies.
   */
  applyForce(f: ArrayLike<number>, r: ArrayLike<number>): this {
    const fn = 'Body.applyForce';
    checkVector(this.D, 'f', f, fn);
    checkVector(this.D, 'r', r, fn);
    checkComponents(fn, "argument 'f'", f, inputLimits.maxForce, 'N');
    checkComponents(fn, "argument 'r'", r, inputLimits.maxPosition, 'm');
    if (this.motion !== MOTION_DYNAMIC) return this;
    checkSumBounded(fn, 'f', this.label, 'force', this.force, f, 1, inputLimits.maxForce, 'N');
    checkAcceleration(fn, 'f', this.label, this.force, f, this.invMass);
    const torque = scratchFor(this.D).bivector;
    if (!wedgeSumFinite(this.D, torque, this.torque, r, f)) {
      throw new RangeError(`${fn}: arguments 'f' and 'r' would make ${this.label}'s torque non-finite; nothing was changed`);
    }
    const maxT = inputLimits.maxTorque;
    for (let p = 0; p < this.D.k; p += 1) {
      const a = Math.abs(torque[p]!);
      if (!(a <= maxT || a <= Math.abs(this.torque[p]!))) {
        throw new RangeError(
          `${fn}: arguments 'f' and 'r' would make ${this.label}'s torque[${p}] ${torque[p]}, beyond ±${formatBound(maxT)} N·m (Body.limits); nothing was changed`,
        );
      }
    }
    this.checkAngularAcceleration(fn, "arguments 'f' and 'r'", torque);
    for (let i = 0; i < this.D.n; i += 1) this.force[i] = this.force[i]! + f[i]!;
    this.torque.set(torque);
    this.hasTorque = true;
    this.wake();
    return this;
  }

  /** Adds a torque bivector t (N·m, k numbers, world frame) for the next step. Ignored by static and kinematic bodies. */
  applyTorque(t: ArrayLike<number>): this {
    const fn = 'Body.applyTorque';
    checkBivector(this.D, 't', t, fn);
    checkComponents(fn, "argument 't'", t, inputLimits.maxTorque, 'N·m');
    if (this.motion !== MOTION_DYNAMIC) return this;
    checkSumBounded(fn, 't', this.label, 'torque', this.torque, t, 1, inputLimits.maxTorque, 'N·m');
    const torque = scratchFor(this.D).bivector;
    for (let p = 0; p < this.D.k; p += 1) torque[p] = this.torque[p]! + t[p]!;
    this.checkAngularAcceleration(fn, "argument 't'", torque);
    this.torque.set(torque);
    this.hasTorque = true;
    this.wake();
    return this;
  }

  /**
   * Writes the orientation of the coordinates the shape was described in (r numbers) into `out`
   * and returns it: `R` itself for every shape without a `frameRotor`, else R·frameRotor~.
   */
  getRotor(out: Float64Array = new Float64Array(this.D.r)): Float64Array {
    const { r } = this.D;
    if (!(out instanceof Float64Array) || out.length !== r) {
      throw new TypeError(`Body.getRotor: argument 'out' must be a Float64Array of length ${r}`);
    }
    const frame = this.shape.frameRotor;
    if (frame === undefined) {
      out.set(this.R);
      return out;
    }
    const inv = scratchFor(this.D).rotor;
    rotorReverse(this.D, inv, frame);
    this.D.kernels.mul(out, this.R, inv);
    return out;
  }

  /**
   * Turns the body (a teleport; the world angular velocity is kept) so that the coordinates its
   * shape was described in have the orientation `R` (a unit rotor, r numbers), about the origin of
   * those coordinates (which stays in place). The inverse of {@link Body.getRotor}.
   */
  setRotor(R: ArrayLike<number>): this {
    const fn = 'Body.setRotor';
    checkRotor(this.D, 'R', R, fn);
    const K = this.D.kernels;
    const next = scratchFor(this.D).rotor;
    next.set(R);
    const defect = K.defect(next);
    if (!(defect <= ROTOR_INPUT_TOLERANCE)) {
      throw new RangeError(
        `${fn}: argument 'R' must be a unit rotor (defect |R R~ - 1| <= ${ROTOR_INPUT_TOLERANCE}), got defect ${defect}`,
      );
    }
    const origin = this.comOffset === null ? null : this.getPositionN(scratchFor(this.D).origin);
    const frame = this.shape.frameRotor;
    if (frame !== undefined) K.mul(this.R, next, frame);
    else this.R.set(next);
    if (K.defect(this.R) > 0) K.correct(this.R, this.R);
    if (origin !== null) {
      this.x.set(origin);
      this.placeCentreOfMass();
    }
    if (this.motion !== MOTION_STATIC) this.momentumFromOmega();
    this.movedByHand();
    return this;
  }

  /**
   * Changes friction and/or restitution (entries left out keep their value). The contacts this
   * body is in take the new mix from the next step on.
   */
  setMaterial(material: Partial<Material>): this {
    const fn = 'Body.setMaterial';
    if (material === null || typeof material !== 'object') {
      throw new TypeError(
        `${fn}: argument 'material' must be an object { friction?, restitution? }, got ${material === null ? 'null' : typeof material}`,
      );
    }
    this.materialValue = checkMaterial({ ...this.materialValue, ...material }, fn);
    this.owner?.onMaterialChanged(this);
    return this;
  }

  /**
   * Sets the collision group, mask and sensor flag together (entries left out keep their value;
   * see {@link Body.collisionGroup}, {@link Body.collisionMask}, {@link Body.sensor}). All are
   * checked before any changes. Wakes the body.
   * @throws TypeError / RangeError naming the bad entry.
   */
  setCollisionFilter(filter: { readonly group?: number; readonly mask?: number; readonly sensor?: boolean }): this {
    const fn = 'Body.setCollisionFilter';
    if (filter === null || typeof filter !== 'object') {
      throw new TypeError(
        `${fn}: argument 'filter' must be an object { group?, mask?, sensor? }, got ${filter === null ? 'null' : typeof filter}`,
      );
    }
    for (const key of Object.keys(filter)) {
      if (key !== 'group' && key !== 'mask' && key !== 'sensor') {
        throw new RangeError(`${fn}: unknown entry '${key}' of argument 'filter' (known: group, mask, sensor)`);
      }
    }
    const group = filter.group === undefined ? this.groupBits : checkGroupBits(fn, "entry 'filter.group'", filter.group);
    const mask = filter.mask === undefined ? this.maskBits : checkGroupBits(fn, "entry 'filter.mask'", filter.mask);
    const sensor = filter.sensor === undefined ? this.sensorFlag : checkSensorFlag(fn, "entry 'filter.sensor'", filter.sensor);
    this.groupBits = group;
    this.maskBits = mask;
    this.sensorFlag = sensor;
    return this.wake();
  }

  /**
   * Changes the mass (kg, finite, >= 0); the inertia scales with it. 0 makes the body static (its
   * velocities and pending forces are cleared); a positive mass makes a static body dynamic. A
   * moving body keeps v and ω, and L is rescaled to I_world ω.
   */
  setMass(m: number): this {
    const fn = 'Body.setMass';
    checkNumber('m', m, fn);
    checkMassValue(fn, "argument 'm'", m);
    if (m > 0 && this.shape.kind === 'halfspace') {
      throw new RangeError(`${fn}: ${this.label} is a half-space, which has no finite mass (argument 'm' must be 0)`);
    }
    if (m === 0) {
      this.motion = MOTION_STATIC;
      this.massValue = 0;
      this.invMass = 0;
      this.ownInertia();
      this.inertia.fill(0);
      this.fillInverseInertia();
      this.v.fill(0);
      this.L.fill(0);
      this.w.fill(0);
      this.clearForces();
      this.sleeping = false;
      this.owner?.onBodyChanged(this);
      return this;
    }
    const mp = this.shape.massProperties(this.D, m);
    checkBivector(this.D, 'shape.massProperties(D, m).inertia', mp.inertia, fn);
    checkInertia(fn, "argument 'm'", mp.inertia, m);
    // L = I_world ω with the new inertia, into scratch: committed only if finite
    const scratch = scratchFor(this.D);
    const L = scratch.bivector;
    momentumFromAngularVelocity(this.D, L, this.R, mp.inertia, this.w, scratch.tmp);
    for (let p = 0; p < this.D.k; p += 1) {
      if (!Number.isFinite(L[p]!)) {
        throw new RangeError(
          `${fn}: argument 'm' would make ${this.label}'s angular momentum non-finite (L = I ω); nothing was changed`,
        );
      }
    }
    if (this.motion === MOTION_STATIC) this.motion = MOTION_DYNAMIC;
    this.massValue = m;
    this.invMass = this.motion === MOTION_DYNAMIC ? 1 / m : 0;
    this.ownInertia();
    this.inertia.set(mp.inertia);
    this.fillInverseInertia();
    this.L.set(L);
    this.sleeping = false;
    this.sleepTimer = 0;
    this.owner?.onBodyChanged(this);
    return this;
  }

  /**
   * Throws a RangeError unless the angular acceleration I_world⁻¹ τ of the torque `torque` (k
   * numbers) stays within ±maxAngularAcceleration (or is no larger than the current torque's).
   */
  private checkAngularAcceleration(fn: string, what: string, torque: Float64Array): void {
    const scratch = scratchFor(this.D);
    const max = inputLimits.maxAngularAcceleration;
    angularVelocityFromMomentum(this.D, scratch.omega, this.R, this.invInertia, torque, scratch.tmp);
    let next = 0;
    for (let p = 0; p < this.D.k; p += 1) next = Math.max(next, Math.abs(scratch.omega[p]!));
    if (next <= max) return;
    angularVelocityFromMomentum(this.D, scratch.alpha, this.R, this.invInertia, this.torque, scratch.tmp);
    let now = 0;
    for (let p = 0; p < this.D.k; p += 1) now = Math.max(now, Math.abs(scratch.alpha[p]!));
    if (next <= now) return;
    throw new RangeError(
      `${fn}: ${what} would give ${this.label} an angular acceleration (I⁻¹ τ) of ${formatBound(next)} rad/s², beyond ±${formatBound(max)} rad/s² (Body.limits); nothing was changed`,
    );
  }

  /** @internal Clears the accumulated force and torque. */
  clearForces(): void {
    const at = this.storageOffset + Body.stateLength(this.D); // (the force follows the state)
    this.storage.fill(0, at, at + this.D.n);
    if (this.hasTorque) {
      this.torque.fill(0);
      this.hasTorque = false;
    }
  }
}

/** The inverse inertia of a dynamic body of principal inertia `I` (as fillInverseInertia writes it). */
function inverseOf(I: Float64Array): Float64Array {
  const inv = new Float64Array(I.length);
  for (let p = 0; p < I.length; p += 1) inv[p] = I[p]! > 0 ? 1 / I[p]! : 0;
  return inv;
}

function checkListener(fn: string, type: unknown, listener: unknown): void {
  if (type !== 'collision') throw new TypeError(`${fn}: argument 'type' must be 'collision', got ${String(type)}`);
  if (typeof listener !== 'function') throw new TypeError(`${fn}: argument 'listener' must be a function`);
}

function checkMaterial(material: unknown, fn: string): Material {
  if (material === undefined) return DEFAULT_MATERIAL;
  if (material === null || typeof material !== 'object') {
    throw new TypeError(
      `${fn}: option 'material' must be an object { friction, restitution }, got ${material === null ? 'null' : typeof material}`,
    );
  }
  const m = material as Record<string, unknown>;
  for (const key of Object.keys(m)) {
    if (key !== 'friction' && key !== 'restitution') {
      throw new RangeError(`${fn}: unknown material property '${key}' (known: friction, restitution)`);
    }
  }
  const friction = m.friction === undefined ? bodyDefaults.friction : m.friction;
  const restitution = m.restitution === undefined ? bodyDefaults.restitution : m.restitution;
  checkNumber('material.friction', friction, fn);
  checkNumber('material.restitution', restitution, fn);
  if (friction < 0) throw new RangeError(`${fn}: option 'material.friction' must be >= 0, got ${friction}`);
  if (restitution < 0 || restitution > 1) {
    throw new RangeError(`${fn}: option 'material.restitution' must be in [0, 1], got ${restitution}`);
  }
  return Object.freeze({ friction, restitution });
}
