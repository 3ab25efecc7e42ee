/**
 * The argument checks of the joints: each throws a TypeError (wrong type or length) or a
 * RangeError (bad value) naming the function and the argument, before anything changes.
 *
 * @module
 */
import { checkVector } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { formatBound, inputLimits } from '../shapes/limits.js';

/**
 * The bound (and unit) of each joint number that feeds the state, by argument name (without
 * 'opts.'): beyond it, the joint's impulses or soft-step coefficients could overflow. Break loads
 * and angle limits are only compared, so any finite value (or ±Infinity for limits) is allowed.
 */
const JOINT_BOUNDS: Readonly<Record<string, readonly [number, string]>> = {
  motorSpeed: [inputLimits.maxAngularVelocity, 'rad/s'],
  speed: [inputLimits.maxAngularVelocity, 'rad/s'],
  maxMotorTorque: [inputLimits.maxTorque, 'N·m'],
  maxTorque: [inputLimits.maxTorque, 'N·m'],
  rest: [inputLimits.maxPosition, 'm'],
  hertz: [inputLimits.maxJointStiffness, 'Hz'],
  damping: [inputLimits.maxJointStiffness, '(damping ratio)'],
};

/** Throws a RangeError when |v| is beyond the bound of `name` in JOINT_BOUNDS (if it has one). */
function checkJointBound(fn: string, name: string, v: number): void {
  const bound = JOINT_BOUNDS[name.startsWith('opts.') ? name.slice(5) : name];
  if (bound !== undefined && !(Math.abs(v) <= bound[0])) {
    throw new RangeError(
      `${fn}: argument '${name}' must be within ±${formatBound(bound[0])} ${bound[1]} (Body.limits), got ${v}`,
    );
  }
}

/** The options every joint takes. */
export const COMMON_OPTION_NAMES: readonly string[] = ['hertz', 'damping', 'breakForce', 'breakTorque', 'collideConnected'];

/** @internal Refuses an options argument that is not an object, and unknown option names. */
export function checkJointOptionNames(fn: string, opts: unknown, extra: readonly string[]): void {
  if (opts === undefined) return;
  if (opts === null || typeof opts !== 'object' || Array.isArray(opts)) {
    throw new TypeError(`${fn}: argument 'opts' must be an object or undefined, got ${opts === null ? 'null' : typeof opts}`);
  }
  for (const key of Object.keys(opts)) {
    if (!COMMON_OPTION_NAMES.includes(key) && !extra.includes(key)) {
      throw new RangeError(`${fn}: unknown option '${key}' (known: ${[...COMMON_OPTION_NAMES, ...extra].join(', ')})`);
    }
  }
}

/** @internal A finite number (TypeError if not a number, RangeError if NaN or infinite). */
export function readFinite(fn: string, name: string, x: unknown): number {
  if (typeof x !== 'number') throw new TypeError(`${fn}: argument '${name}' must be a number, got ${typeof x}`);
  if (!Number.isFinite(x)) throw new RangeError(`${fn}: argument '${name}' must be a finite number, got ${x}`);
  checkJointBound(fn, name, x);
  return x;
}

/** @internal A finite number >= 0. */
export function readNonNegative(fn: string, name: string, x: unknown): number {
  const v = readFinite(fn, name, x);
  if (v < 0) throw new RangeError(`${fn}: argument '${name}' must be >= 0, got ${v}`);
  return v;
}

/** @internal A number that is not NaN (±Infinity allowed: "no limit"). */
export function readLimit(fn: string, name: string, x: unknown): number {
  if (typeof x !== 'number') throw new TypeError(`${fn}: argument '${name}' must be a number, got ${typeof x}`);
  if (Number.isNaN(x)) throw new RangeError(`${fn}: argument '${name}' must not be NaN`);
  return x;
}

/** @internal A boolean. */
export function readBoolean(fn: string, name: string, x: unknown): boolean {
  if (typeof x !== 'boolean') throw new TypeError(`${fn}: argument '${name}' must be a boolean, got ${typeof x}`);
  return x;
}

/** @internal A vector of n finite numbers (a point: each within ±maxPosition), copied into a new Float64Array. */
export function readVector(D: Dims, fn: string, name: string, v: unknown): Float64Array {
  checkVector(D, name, v, fn);
  const max = inputLimits.maxPosition;
  for (let i = 0; i < D.n; i += 1) {
    if (!(Math.abs(v[i]!) <= max)) {
      throw new RangeError(`${fn}: argument '${name}'[${i}] must be within ±${formatBound(max)} m (Body.limits), got ${v[i]}`);
    }
  }
  return Float64Array.from(v);
}

/**
 * @internal A list of distinct integer indices in [0, count) (axes or planes), sorted.
 * `what` names the kind in messages ('axis', 'plane').
 */
export function readIndexList(fn: string, name: string, x: unknown, count: number, what: string): Int32Array {
  if (!Array.isArray(x) && !(ArrayBuffer.isView(x) && !(x instanceof DataView))) {
    throw new TypeError(`${fn}: argument '${name}' must be an array of ${what} indices, got ${x === null ? 'null' : typeof x}`);
  }
  const list = x as ArrayLike<unknown>;
  const out = new Int32Array(list.length);
  const seen = new Set<number>();
  for (let i = 0; i < list.length; i += 1) {
    const v = list[i];
    if (typeof v !== 'number') throw new TypeError(`${fn}: argument '${name}[${i}]' must be a number, got ${typeof v}`);
    if (!Number.isInteger(v) || v < 0 || v >= count) {
      throw new RangeError(`${fn}: argument '${name}[${i}]' must be an ${what} index, an integer in [0, ${count - 1}], got ${v}`);
    }
    if (seen.has(v)) throw new RangeError(`${fn}: argument '${name}' names ${what} ${v} twice`);
    seen.add(v);
    out[i] = v;
  }
  out.sort();
  return out;
}
