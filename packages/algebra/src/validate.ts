/**
 * Argument checks shared by every public function of PhysiN.
 *
 * Each check throws before anything is written: a `TypeError` when the argument has the wrong
 * type or length, a `RangeError` when it has the right shape but a bad value (NaN, an infinite
 * number, a plane index out of range, i == j, ...). Messages name the function (when given),
 * the argument and what was expected, e.g.
 * `rotorMul: argument 'a' must be a Float64Array-like of length 8 (a rotor for n = 4), got length 6`.
 *
 * The engine package imports these too, so its messages read the same way.
 */
import type { Dims } from './tables.js';

function prefix(fn: string | undefined): string {
  return fn ? `${fn}: ` : '';
}

function describe(value: unknown): string {
  if (value === null) return 'null';
  if (value === undefined) return 'undefined';
  if (typeof value !== 'object') return typeof value;
  const name = (value as { constructor?: { name?: string } }).constructor?.name ?? 'object';
  const len = (value as { length?: unknown }).length;
  return typeof len === 'number' ? `${name} of length ${len}` : name;
}

function isArrayLike(value: unknown): value is ArrayLike<number> {
  if (value === null || typeof value !== 'object') return false;
  const len = (value as { length?: unknown }).length;
  return typeof len === 'number' && Number.isInteger(len) && len >= 0;
}

/**
 * Checks that `value` is an array-like of numbers (a `number[]`, a `Float64Array`, any typed
 * array) of exactly `length` entries, all finite. `what` describes the expected object in the
 * message (e.g. `a rotor for n = 4`). TypeError for the wrong type or length, RangeError for a
 * non-finite entry.
 */
export function checkArray(
  name: string,
  value: unknown,
  length: number,
  what: string,
  fn?: string,
): asserts value is ArrayLike<number> {
  if (!isArrayLike(value) || value.length !== length) {
    const got = isArrayLike(value) ? `length ${value.length}` : describe(value);
    throw new TypeError(`${prefix(fn)}argument '${name}' must be a Float64Array-like of length ${length} (${what}), got ${got}`);
  }
  checkFinite(name, value, fn);
}

/**
 * Checks that `value` is a `Float64Array` of exactly `length` entries: the rule for every `out`
 * argument (results are always written into Float64Array storage). TypeError otherwise. The
 * contents are not checked: an output may hold anything before it is written.
 */
export function checkOut(name: string, value: unknown, length: number, what: string, fn?: string): asserts value is Float64Array {
  if (!(value instanceof Float64Array) || value.length !== length) {
    throw new TypeError(
      `${prefix(fn)}argument '${name}' must be a Float64Array of length ${length} (${what}), got ${describe(value)}`,
    );
  }
}

/**
 * Checks that every entry of `arr` is a finite number (no NaN, no ±Infinity). RangeError naming
 * the argument and the first bad index otherwise.
 */
export function checkFinite(name: string, arr: ArrayLike<number>, fn?: string): void {
  for (let i = 0; i < arr.length; i += 1) {
    const x = arr[i];
    if (typeof x !== 'number' || !Number.isFinite(x)) {
      throw new RangeError(`${prefix(fn)}argument '${name}' must contain only finite numbers, got ${String(x)} at index ${i}`);
    }
  }
}

/** Checks that `x` is a finite number: TypeError if it is not a number, RangeError if NaN or infinite. */
export function checkNumber(name: string, x: unknown, fn?: string): asserts x is number {
  if (typeof x !== 'number') {
    throw new TypeError(`${prefix(fn)}argument '${name}' must be a number, got ${describe(x)}`);
  }
  if (!Number.isFinite(x)) {
    throw new RangeError(`${prefix(fn)}argument '${name}' must be a finite number, got ${x}`);
  }
}

/**
 * Checks that `x` is an integer in [min, max]: TypeError if it is not a number, RangeError
 * otherwise.
 */
export function checkInteger(name: string, x: unknown, min: number, max: number, fn?: string): asserts x is number {
  if (typeof x !== 'number') {
    throw new TypeError(`${prefix(fn)}argument '${name}' must be an integer, got ${describe(x)}`);
  }
  if (!Number.isInteger(x) || x < min || x > max) {
    throw new RangeError(`${prefix(fn)}argument '${name}' must be an integer in [${min}, ${max}], got ${x}`);
  }
}

/**
 * Checks that `D` is the table object returned by `dims(n)` (TypeError otherwise), so a caller
 * who swapped arguments gets a clear message instead of a failure deep inside a kernel.
 */
export function checkDims(D: unknown, fn?: string): asserts D is Dims {
  const d = D as Partial<Dims> | null;
  if (
    d === null ||
    typeof d !== 'object' ||
    typeof d.n !== 'number' ||
    typeof d.k !== 'number' ||
    typeof d.r !== 'number' ||
    typeof d.kernels !== 'object'
  ) {
    throw new TypeError(`${prefix(fn)}argument 'D' must be the tables returned by dims(n), got ${describe(D)}`);
  }
}

/** Checks an input vector: n finite numbers (TypeError for a wrong length, RangeError for NaN/Infinity). */
export function checkVector(D: Dims, name: string, v: unknown, fn?: string): asserts v is ArrayLike<number> {
  // The description is built only for the error: made on every call, it cost more than the check.
  if (isArrayLike(v) && v.length === D.n) checkFinite(name, v, fn);
  else checkArray(name, v, D.n, `a vector for n = ${D.n}`, fn);
}

/** Checks an input bivector: k = n(n-1)/2 finite numbers. */
export function checkBivector(D: Dims, name: string, B: unknown, fn?: string): asserts B is ArrayLike<number> {
  if (isArrayLike(B) && B.length === D.k) checkFinite(name, B, fn);
  else checkArray(name, B, D.k, `a bivector for n = ${D.n}`, fn);
}

/** Checks an input rotor: r = 2^(n-1) finite numbers. */
export function checkRotor(D: Dims, name: string, R: unknown, fn?: string): asserts R is ArrayLike<number> {
  if (isArrayLike(R) && R.length === D.r) checkFinite(name, R, fn);
  else checkArray(name, R, D.r, `a rotor for n = ${D.n}`, fn);
}

/** Checks an input n×n matrix (row-major): n*n finite numbers. */
export function checkMatrix(D: Dims, name: string, M: unknown, fn?: string): asserts M is ArrayLike<number> {
  if (isArrayLike(M) && M.length === D.n * D.n) checkFinite(name, M, fn);
  else checkArray(name, M, D.n * D.n, `an ${D.n}x${D.n} matrix`, fn);
}

/** Checks an input k×k operator (row-major, e.g. an inertia operator): k*k finite numbers. */
export function checkOperator(D: Dims, name: string, M: unknown, fn?: string): asserts M is ArrayLike<number> {
  if (isArrayLike(M) && M.length === D.k * D.k) checkFinite(name, M, fn);
  else checkArray(name, M, D.k * D.k, `a ${D.k}x${D.k} bivector operator for n = ${D.n}`, fn);
}

/**
 * Checks the two axis indices of a plane: integers in [0, n-1] and different from each other
 * (RangeError; TypeError if not numbers).
 */
export function checkPlane(D: Dims, nameI: string, i: unknown, nameJ: string, j: unknown, fn?: string): void {
  checkInteger(nameI, i, 0, D.n - 1, fn);
  checkInteger(nameJ, j, 0, D.n - 1, fn);
  if (i === j) {
    throw new RangeError(
      `${prefix(fn)}arguments '${nameI}' and '${nameJ}' must name two different axes of a plane, got ${i} and ${j}`,
    );
  }
}

/** Output checks for the four shapes of the library: Float64Array of the exact length. */
export function checkOutVector(D: Dims, name: string, out: unknown, fn?: string): asserts out is Float64Array {
  checkOut(name, out, D.n, `a vector for n = ${D.n}`, fn);
}
/** Output check for a bivector (k entries). */
export function checkOutBivector(D: Dims, name: string, out: unknown, fn?: string): asserts out is Float64Array {
  checkOut(name, out, D.k, `a bivector for n = ${D.n}`, fn);
}
/** Output check for a rotor (r entries). */
export function checkOutRotor(D: Dims, name: string, out: unknown, fn?: string): asserts out is Float64Array {
  checkOut(name, out, D.r, `a rotor for n = ${D.n}`, fn);
}
/** Output check for an n×n matrix. */
export function checkOutMatrix(D: Dims, name: string, out: unknown, fn?: string): asserts out is Float64Array {
  checkOut(name, out, D.n * D.n, `an ${D.n}x${D.n} matrix`, fn);
}
/** Output check for a k×k operator. */
export function checkOutOperator(D: Dims, name: string, out: unknown, fn?: string): asserts out is Float64Array {
  checkOut(name, out, D.k * D.k, `a ${D.k}x${D.k} bivector operator for n = ${D.n}`, fn);
}
