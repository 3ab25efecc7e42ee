/**
 * Every tolerance and tuning number of the engine, in one place.
 *
 * The algebra has no tolerance of its own; whatever threshold a method needs is chosen here and
 * passed down. A world holds one frozen {@link Params} object; `World.setParams` replaces it with
 * a new frozen object after validating the whole change.
 *
 * @module
 */

/**
 * The engine's parameters. Units: seconds (s), metres (m), radians (rad), hertz (Hz); counts are
 * integers. Names and defaults follow the specification's tolerance table; `linearDamping` and
 * `angularDamping` are additions (default 0: no damping), and so are `manifoldReuseTolerance` and `solverTolerance`.
 */
export interface Params {
  /** Length of one step of a fixed-rate loop (s). A helper for callers: `World.step(dt)` takes its own dt. */
  readonly fixedTimeStep: number;
  /** Sub-steps per `World.step`: each integrates dt / subSteps (integer >= 1). */
  readonly subSteps: number;
  /** Velocity iterations of the contact and joint solver per sub-step (integer >= 1). */
  readonly iterations: number;
  /** Passes of shock propagation after the normal iterations (integer >= 0). */
  readonly shockIterations: number;
  /** Penetration the contact solver accepts without pushing back (m, >= 0). */
  readonly penetrationSlop: number;
  /** Baumgarte factor: fraction of the contact position error removed per sub-step (in [0, 1]). */
  readonly biasFactor: number;
  /** Separation below which a pair of shapes makes a contact (m, >= 0). */
  readonly contactMargin: number;
  /** Smallest approach speed that bounces; slower contacts are inelastic (m/s, >= 0). */
  readonly restitutionThreshold: number;
  /** Largest number of contact points kept per step; 0 = no limit (integer >= 0). */
  readonly maxContacts: number;
  /** Baumgarte factor of joints: fraction of a joint's position error removed per sub-step (in [0, 1]). */
  readonly constraintBias: number;
  /** Joint position error the solver accepts without correcting it (m or rad, >= 0). */
  readonly constraintSlop: number;
  /** Largest correction speed a joint's bias may ask for (m/s or rad/s, >= 0). */
  readonly constraintMaxBias: number;
  /** Shortest direction a joint accepts before it treats the direction as undefined (m, > 0). */
  readonly constraintTolerance: number;
  /**
   * Linear error of the rigid joints at which their position projection stops (m, >= 0): once
   * every linear row is within it (and every angular row at rounding), the projection ends after
   * a pass. From 0.01 × `constraintSlop` up, a sub-step that leaves the error within it is not
   * projected at all. The default, 0, projects to rounding (the accuracy the presets and
   * docs/trade.md state); 1e-9 keeps chains within a millionth of `constraintSlop` at about 0.85
   * of the time, and a scene that needs its joints to 1 mm can ask for 1e-3 at about 0.7
   * (docs/joints.md, "Where the projection stops").
   */
  readonly constraintProjectionTolerance: number;
  /** Default stiffness of a soft joint as a frequency (Hz, >= 0); 0 = rigid. */
  readonly constraintHertz: number;
  /** Default damping ratio of a soft joint (dimensionless, >= 0; 1 = critical). */
  readonly constraintDamping: number;
  /** Largest fraction of the sub-step rate a soft joint's frequency may use (in (0, 1]). */
  readonly constraintHertzRatio: number;
  /**
   * Largest rotor defect ‖R R~ − 1‖ left alone after a rotor step (dimensionless, >= 0). Above
   * it the rotor is corrected back onto the rotation group; 0 corrects whenever any defect shows.
   */
  readonly rotorTolerance: number;
  /**
   * Whether the rotor step follows the turning of the body's frame within the step. true: the
   * angular velocity that turns the rotor is the midpoint value, found by `gyroscopicIterations`
   * fixed-point iterations (second order). false: the rotor turns by the angular velocity at the
   * start of the step (first order). Either way L is held fixed in the world frame, so the
   * precession itself is never lost; only the accuracy of the turn changes. See docs/engine.md.
   */
  readonly gyroscopic: boolean;
  /**
   * Fixed-point iterations of the implicit midpoint angular velocity (integer >= 0). 1 is the
   * explicit midpoint rule (one extra inertia transform per body); each further iteration moves
   * the step closer to the symmetric implicit midpoint; 0 is the first-order step.
   */
  readonly gyroscopicIterations: number;
  /** Whether resting bodies may be put to sleep. */
  readonly allowSleep: boolean;
  /** Linear speed below which a body counts as resting (m/s, >= 0). */
  readonly sleepLinearVelocity: number;
  /** Angular speed (bivector norm) below which a body counts as resting (rad/s, >= 0). */
  readonly sleepAngularVelocity: number;
  /** Time a body must rest before it sleeps (s, >= 0). */
  readonly sleepTime: number;
  /** Whether the contact solver runs shock propagation (set false to compare). */
  readonly useShockPropagation: boolean;
  /** Whether the contact solver starts from last step's impulses (set false to compare). */
  readonly useWarmStart: boolean;
  /**
   * Linear damping rate (1/s, >= 0): each sub-step multiplies v by 1 / (1 + h·linearDamping).
   * 0 (the default) leaves v untouched.
   */
  readonly linearDamping: number;
  /**
   * Angular damping rate (1/s, >= 0): each sub-step multiplies L by 1 / (1 + h·angularDamping).
   * 0 (the default) leaves L untouched, so a torque-free body keeps L bit-exactly.
   */
  readonly angularDamping: number;
  /**
   * How far (m, >= 0) any point of one box may move relative to the other, since their manifold
   * was computed, before the narrowphase computes it again; meanwhile the manifold's points move
   * with the boxes and their separations are measured afresh (see docs/collision.md, "Manifold
   * reuse"). 0 computes every box–box manifold every sub-step.
   */
  readonly manifoldReuseTolerance: number;
  /**
   * Convergence tolerance of the contact solver (m/s, >= 0): when a whole pass changes no contact
   * row's velocity by more than this, the passes left of `iterations` (and of `shockIterations`)
   * are skipped, since they would change the velocities by less still; the inner sweeps of a
   * shock pass stop the same way. The joint passes of a sub-step without contacts stop the same
   * way when no joint row moves by more (m/s or rad/s). 0 skips only passes that would change
   * nothing at all. See docs/solver.md, "Early exit", and docs/joints.md.
   */
  readonly solverTolerance: number;
  /**
   * The length of one unit of the scene (m, > 0; default 1): every length tolerance of the engine
   * is multiplied by it — `penetrationSlop`, `contactMargin`, `constraintSlop`,
   * `constraintTolerance`, `manifoldReuseTolerance`, the broadphase margin and the narrowphase's
   * feature tie tolerance — and so is every speed threshold (`restitutionThreshold`,
   * `sleepLinearVelocity`, `solverTolerance`). A scene of 1 cm dice takes `lengthUnit: 0.01` and
   * then behaves as a scene of 1 m boxes does with 1 (docs/engine.md, "Scale"). The other
   * parameters keep their values as given. Set when the world is built (`new World`); `setParams`
   * refuses to change it, as the broadphase's boxes are grown by it.
   */
  readonly lengthUnit: number;
}

/** The defaults of every parameter (frozen). */
export const defaultParams: Readonly<Params> = Object.freeze({
  fixedTimeStep: 1 / 60,
  subSteps: 1,
  iterations: 10,
  shockIterations: 2,
  penetrationSlop: 0.005,
  biasFactor: 0.2,
  contactMargin: 0.02,
  restitutionThreshold: 0.5,
  maxContacts: 0,
  constraintBias: 0.2,
  constraintSlop: 0.001,
  constraintMaxBias: 10,
  constraintTolerance: 1e-6,
  constraintProjectionTolerance: 0,
  constraintHertz: 0,
  constraintDamping: 1,
  constraintHertzRatio: 0.25,
  rotorTolerance: 1e-9,
  gyroscopic: true,
  gyroscopicIterations: 1,
  allowSleep: true,
  sleepLinearVelocity: 0.03,
  sleepAngularVelocity: 0.03,
  sleepTime: 0.6,
  useShockPropagation: true,
  useWarmStart: true,
  linearDamping: 0,
  angularDamping: 0,
  manifoldReuseTolerance: 1e-4,
  solverTolerance: 1e-9,
  lengthUnit: 1,
});

/** Upper bound of the integer counts (sub-steps, iterations): a guard against typos such as 1e9. */
export const MAX_PARAM_COUNT = 10_000;

/** How a parameter's value is checked. */
type Rule =
  | { readonly kind: 'boolean' }
  | { readonly kind: 'integer'; readonly min: number; readonly max: number }
  | { readonly kind: 'number'; readonly min: number; readonly max: number; readonly minOpen?: boolean };

const count = (min: number): Rule => ({ kind: 'integer', min, max: MAX_PARAM_COUNT });
const nonNegative: Rule = { kind: 'number', min: 0, max: Infinity };
const positive: Rule = { kind: 'number', min: 0, max: Infinity, minOpen: true };
const fraction: Rule = { kind: 'number', min: 0, max: 1 };
const flag: Rule = { kind: 'boolean' };

const rules: { readonly [K in keyof Params]: Rule } = {
  fixedTimeStep: positive,
  subSteps: count(1),
  iterations: count(1),
  shockIterations: count(0),
  penetrationSlop: nonNegative,
  biasFactor: fraction,
  contactMargin: nonNegative,
  restitutionThreshold: nonNegative,
  maxContacts: { kind: 'integer', min: 0, max: Number.MAX_SAFE_INTEGER },
  constraintBias: fraction,
  constraintSlop: nonNegative,
  constraintMaxBias: nonNegative,
  constraintTolerance: positive,
  constraintProjectionTolerance: nonNegative,
  constraintHertz: nonNegative,
  constraintDamping: nonNegative,
  constraintHertzRatio: { kind: 'number', min: 0, max: 1, minOpen: true },
  rotorTolerance: nonNegative,
  gyroscopic: flag,
  gyroscopicIterations: count(0),
  allowSleep: flag,
  sleepLinearVelocity: nonNegative,
  sleepAngularVelocity: nonNegative,
  sleepTime: nonNegative,
  useShockPropagation: flag,
  useWarmStart: flag,
  linearDamping: nonNegative,
  angularDamping: nonNegative,
  manifoldReuseTolerance: nonNegative,
  solverTolerance: nonNegative,
  lengthUnit: { kind: 'number', min: 1e-6, max: 1e6 },
};

/** The names of every parameter, in the order of the specification's table. */
export const paramNames: readonly (keyof Params)[] = Object.freeze(Object.keys(defaultParams) as (keyof Params)[]);

function describe(value: unknown): string {
  if (value === null) return 'null';
  if (typeof value === 'string') return `the string ${JSON.stringify(value)}`;
  if (typeof value === 'number' || typeof value === 'boolean') return String(value);
  return typeof value;
}

function checkOne(where: string, name: keyof Params, value: unknown): void {
  const rule = rules[name];
  const label = `${where}: parameter '${name}'`;
  if (rule.kind === 'boolean') {
    if (typeof value !== 'boolean') throw new TypeError(`${label} must be a boolean, got ${describe(value)}`);
    return;
  }
  if (typeof value !== 'number') {
    throw new TypeError(`${label} must be a number, got ${describe(value)}`);
  }
  if (rule.kind === 'integer') {
    if (!Number.isInteger(value) || value < rule.min || value > rule.max) {
      throw new RangeError(`${label} must be an integer in [${rule.min}, ${rule.max}], got ${value}`);
    }
    return;
  }
  const low = rule.minOpen ? value > rule.min : value >= rule.min;
  if (!Number.isFinite(value) || !low || value > rule.max) {
    const lo = rule.minOpen ? `> ${rule.min}` : `>= ${rule.min}`;
    const hi = rule.max === Infinity ? '' : ` and <= ${rule.max}`;
    throw new RangeError(`${label} must be a finite number ${lo}${hi}, got ${value}`);
  }
}

/**
 * Checks a partial set of parameters: every name known, every value of the right type and
 * range. Throws before returning anything: a TypeError for a wrong type (or a `partial` that is
 * not a plain object), a RangeError for a value out of range or an unknown name. The message
 * names the parameter.
 *
 * @param partial - the parameters to check (any subset of {@link Params}).
 * @param where - the caller's name for the message (e.g. `'World.setParams'`).
 */
export function validateParams(partial: unknown, where = 'validateParams'): asserts partial is Partial<Params> {
  if (partial === null || typeof partial !== 'object' || Array.isArray(partial)) {
    throw new TypeError(`${where}: argument 'params' must be an object of parameters, got ${describe(partial)}`);
  }
  for (const name of Object.keys(partial)) {
    if (!Object.prototype.hasOwnProperty.call(rules, name)) {
      throw new RangeError(`${where}: unknown parameter '${name}' (known: ${paramNames.join(', ')})`);
    }
    checkOne(where, name as keyof Params, (partial as Record<string, unknown>)[name]);
  }
}

/**
 * Returns a new frozen parameter object: `base` with the entries of `partial` over it, after
 * checking `partial` with {@link validateParams} (nothing is built if a check fails).
 *
 * @param base - a complete, already valid parameter set (e.g. {@link defaultParams}).
 * @param partial - the changes; `undefined` returns a frozen copy of `base`.
 */
export function mergeParams(base: Readonly<Params>, partial?: unknown, where = 'mergeParams'): Readonly<Params> {
  if (partial === undefined) return Object.freeze({ ...base });
  validateParams(partial, where);
  return Object.freeze({ ...base, ...partial });
}

/** The parameters that are lengths (m) or speeds (m/s): {@link Params.lengthUnit} scales them. */
const LENGTH_PARAMS = [
  'penetrationSlop',
  'contactMargin',
  'constraintSlop',
  'constraintTolerance',
  'constraintProjectionTolerance',
  'manifoldReuseTolerance',
  'restitutionThreshold',
  'sleepLinearVelocity',
  'solverTolerance',
] as const;

/**
 * @internal The parameters as the step reads them: every length and speed tolerance multiplied by
 * `lengthUnit` (the same object back when the unit is 1).
 */
export function scaledParams(p: Readonly<Params>): Readonly<Params> {
  const unit = p.lengthUnit;
  if (unit === 1) return p;
  const out: Record<string, number | boolean> = { ...p };
  for (const name of LENGTH_PARAMS) out[name] = p[name] * unit;
  return Object.freeze(out) as unknown as Readonly<Params>;
}

/**
 * Defaults of a body's options (see `BodyOptions`): mass 1 kg for a dynamic or kinematic body,
 * friction coefficient 0.5 and restitution 0 (no bounce).
 */
export const bodyDefaults = Object.freeze({
  /** Mass of a body whose options give none (kg). */
  mass: 1,
  /** Coulomb friction coefficient (dimensionless, >= 0). */
  friction: 0.5,
  /** Coefficient of restitution (dimensionless, in [0, 1]). */
  restitution: 0,
});

/**
 * Largest rotor defect ‖R R~ − 1‖ accepted in a rotor given by the caller (a body's `rotor`
 * option). Such input is then corrected to an exact rotor; this bound only catches arrays that are
 * not rotors at all (zeros, a matrix, the wrong convention), while it accepts rotors stored in
 * single precision or typed with six digits.
 */
export const ROTOR_INPUT_TOLERANCE = 1e-4;
