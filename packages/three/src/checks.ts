/**
 * Argument checks of the adapter's public methods: a TypeError or RangeError that names the method,
 * the argument and what was expected, thrown before anything changes.
 *
 * @module
 */

/** Describes a value for an error message. */
export function describe(value: unknown): string {
  if (value === null) return 'null';
  if (Array.isArray(value)) return `an array of length ${value.length}`;
  if (ArrayBuffer.isView(value)) return `a ${value.constructor.name} of length ${(value as unknown as ArrayLike<number>).length}`;
  if (typeof value === 'number') return String(value);
  return typeof value;
}

/** True for an array or typed array of numbers. */
function isArrayLike(value: unknown): value is ArrayLike<unknown> {
  return Array.isArray(value) || (ArrayBuffer.isView(value) && !(value instanceof DataView));
}

/**
 * Checks an array of finite numbers of `length` (any length when null) and returns a Float64Array
 * copy, so that later changes to the caller's array do not reach a queued command.
 */
export function numbers(where: string, name: string, value: unknown, length: number | null, what = 'numbers'): Float64Array {
  if (!isArrayLike(value))
    throw new TypeError(`${where}: argument '${name}' must be an array of ${length ?? 'n'} ${what}, got ${describe(value)}`);
  if (length !== null && value.length !== length) {
    throw new RangeError(`${where}: argument '${name}' must have ${length} ${what}, got ${value.length}`);
  }
  const out = new Float64Array(value.length);
  for (let i = 0; i < value.length; i += 1) {
    const v = value[i];
    if (typeof v !== 'number' || !Number.isFinite(v)) {
      throw new RangeError(`${where}: argument '${name}' must hold finite numbers, got ${String(v)} at index ${i}`);
    }
    out[i] = v;
  }
  return out;
}

/** Checks a finite number (≥ `min` when given). */
export function finite(where: string, name: string, value: unknown, min?: number, what = 'number'): number {
  if (typeof value !== 'number') throw new TypeError(`${where}: argument '${name}' must be a ${what}, got ${describe(value)}`);
  if (!Number.isFinite(value)) throw new RangeError(`${where}: argument '${name}' must be a finite ${what}, got ${value}`);
  if (min !== undefined && value < min)
    throw new RangeError(`${where}: argument '${name}' must be a ${what} >= ${min}, got ${value}`);
  return value;
}

/** Checks a positive finite number. */
export function positive(where: string, name: string, value: unknown, what = 'number'): number {
  finite(where, name, value, undefined, what);
  if (!((value as number) > 0)) throw new RangeError(`${where}: argument '${name}' must be a ${what} > 0, got ${String(value)}`);
  return value as number;
}

/** Checks an integer in [min, max]. */
export function integer(where: string, name: string, value: unknown, min: number, max: number): number {
  if (typeof value !== 'number') throw new TypeError(`${where}: argument '${name}' must be an integer, got ${describe(value)}`);
  if (!Number.isInteger(value) || value < min || value > max) {
    throw new RangeError(`${where}: argument '${name}' must be an integer in [${min}, ${max}], got ${value}`);
  }
  return value;
}
