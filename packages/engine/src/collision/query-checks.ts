/**
 * Argument checks shared by the spatial queries (bounds, broadphase, ray casts).
 *
 * Wrong type or length → TypeError; a bad value (non-finite, out of range) → RangeError. Every
 * message names the argument and says what was expected. The checks only read, so a public
 * function that runs them first throws before it writes anything.
 */
import type { QueryShape } from './query-shapes.js';

/** Largest count of dimensions the library supports. */
export const MAX_DIMENSIONS = 8;

/** Checks that `n` is an integer count of dimensions in 2..8. */
export function checkDimension(n: unknown, name = 'n'): asserts n is number {
  if (typeof n !== 'number' || !Number.isInteger(n)) {
    throw new TypeError(`${name} must be an integer count of dimensions, got ${String(n)}`);
  }
  if (n < 2 || n > MAX_DIMENSIONS) {
    throw new RangeError(`${name} must be between 2 and ${MAX_DIMENSIONS}, got ${n}`);
  }
}

/** Checks that `v` is a Float64Array of exactly `length` numbers (an output buffer). */
export function checkOutput(v: unknown, length: number, name: string): asserts v is Float64Array {
  if (!(v instanceof Float64Array)) {
    throw new TypeError(`${name} must be a Float64Array of length ${length}`);
  }
  if (v.length !== length) {
    throw new TypeError(`${name} must have length ${length}, got ${v.length}`);
  }
}

/** Checks that `v` is an array-like of exactly `length` finite numbers. */
export function checkFiniteArray(v: unknown, length: number, name: string): asserts v is ArrayLike<number> {
  if (v === null || typeof v !== 'object' || typeof (v as ArrayLike<number>).length !== 'number') {
    throw new TypeError(`${name} must be an array of ${length} numbers`);
  }
  const a = v as ArrayLike<number>;
  if (a.length !== length) {
    throw new TypeError(`${name} must have length ${length}, got ${a.length}`);
  }
  for (let i = 0; i < length; i += 1) {
    const x = a[i];
    if (typeof x !== 'number') throw new TypeError(`${name}[${i}] must be a number`);
    if (!Number.isFinite(x)) throw new RangeError(`${name}[${i}] must be finite, got ${x}`);
  }
}

/** Checks that `x` is a finite number (or, with `allowInfinity`, +Infinity) and >= `min`. */
export function checkNumber(x: unknown, name: string, min = -Infinity, allowInfinity = false): asserts x is number {
  if (typeof x !== 'number') throw new TypeError(`${name} must be a number`);
  if (Number.isNaN(x) || (!allowInfinity && !Number.isFinite(x)) || x === -Infinity) {
    throw new RangeError(`${name} must be ${allowInfinity ? 'a number or +Infinity' : 'finite'}, got ${x}`);
  }
  if (x < min) throw new RangeError(`${name} must be >= ${min}, got ${x}`);
}

/** Checks that `d` is a nonzero, finite direction of n components. */
export function checkDirection(d: unknown, n: number, name: string): asserts d is ArrayLike<number> {
  checkFiniteArray(d, n, name);
  let s = 0;
  for (let i = 0; i < n; i += 1) s += d[i]! * d[i]!;
  if (!(s > 0) || !Number.isFinite(s)) {
    throw new RangeError(`${name} must be a nonzero finite vector`);
  }
}

/** Checks a pose: position x (n finite numbers) and rotation M (n*n finite numbers, row-major). */
export function checkPose(n: number, x: unknown, M: unknown): void {
  checkFiniteArray(x, n, 'x');
  checkFiniteArray(M, n * n, 'M');
}

/** Checks that `shape` is one of the shapes the queries know, with data that fits n dimensions. */
export function checkShape(shape: unknown, n: number, name = 'shape'): asserts shape is QueryShape {
  if (shape === null || typeof shape !== 'object') {
    throw new TypeError(`${name} must be a shape object`);
  }
  const s = shape as QueryShape;
  switch (s.kind) {
    case 'box': {
      checkFiniteArray(s.halfExtents, n, `${name}.halfExtents`);
      for (let i = 0; i < n; i += 1) {
        if (!(s.halfExtents[i]! > 0)) {
          throw new RangeError(`${name}.halfExtents[${i}] must be > 0, got ${s.halfExtents[i]}`);
        }
      }
      return;
    }
    case 'sphere':
      checkNumber(s.radius, `${name}.radius`);
      if (!(s.radius > 0)) throw new RangeError(`${name}.radius must be > 0, got ${s.radius}`);
      return;
    case 'halfspace':
      checkDirection(s.normal, n, `${name}.normal`);
      checkNumber(s.offset, `${name}.offset`);
      return;
    case 'torus': {
      checkNumber(s.majorRadius, `${name}.majorRadius`);
      checkNumber(s.minorRadius, `${name}.minorRadius`);
      if (!(s.minorRadius > 0)) {
        throw new RangeError(`${name}.minorRadius must be > 0, got ${s.minorRadius}`);
      }
      if (!(s.majorRadius > s.minorRadius)) {
        throw new RangeError(`${name}.majorRadius must be > minorRadius (${s.minorRadius}), got ${s.majorRadius}`);
      }
      const { planeI, planeJ } = s;
      if (!Number.isInteger(planeI) || planeI < 0 || planeI >= n) {
        throw new RangeError(`${name}.planeI must be an axis index in 0..${n - 1}, got ${planeI}`);
      }
      if (!Number.isInteger(planeJ) || planeJ < 0 || planeJ >= n || planeJ === planeI) {
        throw new RangeError(`${name}.planeJ must be an axis index in 0..${n - 1} other than planeI, got ${planeJ}`);
      }
      return;
    }
    case 'mesh': {
      const v = s.vertices;
      if (v === null || typeof v !== 'object' || typeof v.length !== 'number') {
        throw new TypeError(`${name}.vertices must be a flat array of numbers`);
      }
      if (v.length === 0 || v.length % n !== 0) {
        throw new TypeError(`${name}.vertices must hold a nonzero multiple of ${n} numbers, got ${v.length}`);
      }
      checkFiniteArray(v, v.length, `${name}.vertices`);
      const offs = s.facetOffsets;
      if (offs === null || typeof offs !== 'object' || typeof offs.length !== 'number') {
        throw new TypeError(`${name}.facetOffsets must be an array of numbers`);
      }
      checkFiniteArray(offs, offs.length, `${name}.facetOffsets`);
      checkFiniteArray(s.facetNormals, offs.length * n, `${name}.facetNormals`);
      return;
    }
    case 'capsule':
      checkNumber(s.halfHeight, `${name}.halfHeight`);
      if (!(s.halfHeight > 0)) throw new RangeError(`${name}.halfHeight must be > 0, got ${s.halfHeight}`);
      checkNumber(s.radius, `${name}.radius`);
      if (!(s.radius > 0)) throw new RangeError(`${name}.radius must be > 0, got ${s.radius}`);
      return;
    default:
      throw new TypeError(
        `${name}.kind must be 'box', 'sphere', 'halfspace', 'torus', 'mesh' or 'capsule', got ${String((s as { kind?: unknown }).kind)}`,
      );
  }
}
