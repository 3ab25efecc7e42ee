import { isDims } from '@physin/algebra';
import type { Dims } from '@physin/algebra';

/**
 * Argument checks shared by the shape constructors. Each throws before anything is built:
 * a `TypeError` for a wrong type or length, a `RangeError` for a bad value, with a message that
 * names the function, the argument and what was expected.
 *
 * @module
 */

/** A sequence of numbers the shape constructors accept: a plain array or any typed array. */
export type NumberList = ArrayLike<number>;

function describe(value: unknown): string {
  if (value === null) return 'null';
  if (Array.isArray(value)) return `an array of length ${value.length}`;
  if (ArrayBuffer.isView(value)) return `a ${value.constructor.name}`;
  if (typeof value === 'number') return String(value);
  return typeof value;
}

/**
 * Checks that `D` is the table object that `dims(n)` returns (the cached one), and returns it.
 */
export function checkDims(where: string, D: unknown, name = 'D'): Dims {
  if (typeof D !== 'object' || D === null || typeof (D as { n?: unknown }).n !== 'number') {
    throw new TypeError(`${where}: argument '${name}' must be the tables returned by dims(n), got ${describe(D)}`);
  }
  const n = (D as { n: number }).n;
  if (!Number.isInteger(n) || n < 2 || n > 8 || !isDims(D)) {
    throw new TypeError(`${where}: argument '${name}' must be the tables returned by dims(n) (2 <= n <= 8)`);
  }
  return D as Dims;
}

/** Checks that `value` is a finite number and returns it. */
export function checkFinite(where: string, value: unknown, name: string): number {
  if (typeof value !== 'number') {
    throw new TypeError(`${where}: argument '${name}' must be a number, got ${describe(value)}`);
  }
  if (!Number.isFinite(value)) {
    throw new RangeError(`${where}: argument '${name}' must be finite, got ${value}`);
  }
  return value;
}

/** Checks that `value` is a finite number > 0 and returns it. */
export function checkPositive(where: string, value: unknown, name: string): number {
  const x = checkFinite(where, value, name);
  if (!(x > 0)) throw new RangeError(`${where}: argument '${name}' must be > 0, got ${x}`);
  return x;
}

/** Checks that `value` is an integer in [lo, hi] and returns it. */
export function checkIndex(where: string, value: unknown, name: string, lo: number, hi: number): number {
  if (typeof value !== 'number') {
    throw new TypeError(`${where}: argument '${name}' must be an integer, got ${describe(value)}`);
  }
  if (!Number.isInteger(value) || value < lo || value > hi) {
    throw new RangeError(`${where}: argument '${name}' must be an integer in [${lo}, ${hi}], got ${value}`);
  }
  return value;
}

/** True when `value` looks like an array of numbers (plain array or typed array). */
export function isNumberList(value: unknown): value is NumberList {
  return (
    (Array.isArray(value) || (ArrayBuffer.isView(value) && !(value instanceof DataView))) &&
    typeof (value as { length: unknown }).length === 'number'
  );
}

/**
 * Copies a list of `length` finite numbers into a new Float64Array (`length` = -1: any length).
 */
export function checkVector(where: string, value: unknown, name: string, length: number): Float64Array {
  if (!isNumberList(value)) {
    throw new TypeError(`${where}: argument '${name}' must be an array of numbers, got ${describe(value)}`);
  }
  if (length >= 0 && value.length !== length) {
    throw new TypeError(`${where}: argument '${name}' must have length ${length}, got ${value.length}`);
  }
  const out = new Float64Array(value.length);
  for (let i = 0; i < value.length; i += 1) {
    const x = value[i];
    if (typeof x !== 'number') {
      throw new TypeError(`${where}: argument '${name}'[${i}] must be a number, got ${describe(x)}`);
    }
    if (!Number.isFinite(x)) throw new RangeError(`${where}: argument '${name}'[${i}] must be finite, got ${x}`);
    out[i] = x;
  }
  return out;
}

/**
 * Reads a list of points of `n` coordinates each, given either as an array of points
 * (`number[][]`) or flat (`n * count` numbers), into a flat Float64Array.
 */
export function checkPoints(where: string, value: unknown, name: string, n: number): Float64Array {
  if (!Array.isArray(value) && !isNumberList(value)) {
    throw new TypeError(
      `${where}: argument '${name}' must be an array of points or a flat array of numbers, got ${describe(value)}`,
    );
  }
  const list = value as ArrayLike<unknown>;
  if (list.length > 0 && typeof list[0] !== 'number') {
    const out = new Float64Array(list.length * n);
    for (let p = 0; p < list.length; p += 1) {
      const point = list[p];
      if (!isNumberList(point)) {
        throw new TypeError(`${where}: argument '${name}'[${p}] must be an array of ${n} numbers, got ${describe(point)}`);
      }
      if (point.length !== n) {
        throw new TypeError(`${where}: argument '${name}'[${p}] must have length ${n}, got ${point.length}`);
      }
      for (let c = 0; c < n; c += 1) {
        const x = point[c];
        if (typeof x !== 'number') {
          throw new TypeError(`${where}: argument '${name}'[${p}][${c}] must be a number, got ${describe(x)}`);
        }
        if (!Number.isFinite(x)) throw new RangeError(`${where}: argument '${name}'[${p}][${c}] must be finite, got ${x}`);
        out[p * n + c] = x;
      }
    }
    return out;
  }
  if (list.length % n !== 0) {
    throw new TypeError(`${where}: flat '${name}' must hold a multiple of ${n} numbers, got ${list.length}`);
  }
  return checkVector(where, list, name, -1);
}

/**
 * Reads a list of index tuples of `width` entries each (`number[][]` or flat), every index an
 * integer in [0, count), into a flat Int32Array. Repeated indices inside one tuple are refused
 * (a facet that repeats a vertex is degenerate) unless `allowRepeats`.
 */
export function checkTuples(
  where: string,
  value: unknown,
  name: string,
  width: number,
  count: number,
  allowRepeats = false,
): Int32Array {
  if (!Array.isArray(value) && !isNumberList(value)) {
    throw new TypeError(
      `${where}: argument '${name}' must be an array of index tuples or a flat array of indices, got ${describe(value)}`,
    );
  }
  const list = value as ArrayLike<unknown>;
  const nested = list.length > 0 && typeof list[0] !== 'number';
  if (!nested && list.length % width !== 0) {
    throw new TypeError(`${where}: flat '${name}' must hold a multiple of ${width} indices, got ${list.length}`);
  }
  const tuples = nested ? list.length : list.length / width;
  const out = new Int32Array(tuples * width);
  for (let t = 0; t < tuples; t += 1) {
    let tuple: ArrayLike<unknown> = list;
    let base = t * width;
    let label = (c: number): string => `'${name}'[${t * width + c}]`;
    if (nested) {
      const item = list[t];
      if (!isNumberList(item)) {
        throw new TypeError(`${where}: argument '${name}'[${t}] must be an array of ${width} indices, got ${describe(item)}`);
      }
      if (item.length !== width) {
        throw new TypeError(`${where}: argument '${name}'[${t}] must have length ${width}, got ${item.length}`);
      }
      tuple = item;
      base = 0;
      label = (c) => `'${name}'[${t}][${c}]`;
    }
    for (let c = 0; c < width; c += 1) {
      const x = tuple[base + c];
      if (typeof x !== 'number') throw new TypeError(`${where}: ${label(c)} must be an integer, got ${describe(x)}`);
      if (!Number.isInteger(x) || x < 0 || x >= count) {
        throw new RangeError(`${where}: ${label(c)} must be a vertex index in [0, ${count - 1}], got ${x}`);
      }
      for (let b = 0; b < c && !allowRepeats; b += 1) {
        if (out[t * width + b] === x) {
          throw new RangeError(`${where}: argument '${name}'[${t}] repeats vertex ${x}: the facet is degenerate`);
        }
      }
      out[t * width + c] = x;
    }
  }
  return out;
}
