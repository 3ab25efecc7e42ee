/**
 * Argument checks of the narrowphase's validating entry points. Wrong type or length →
 * TypeError; a bad value (non-finite, out of range) → RangeError; every message names the
 * argument and what was expected. The checks only read.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';

/** Checks that `v` is a Float64Array of exactly `length` numbers (an output buffer). */
export function checkNarrowphaseOutput(v: unknown, length: number, name: string): asserts v is Float64Array {
  if (!(v instanceof Float64Array)) throw new TypeError(`'${name}' must be a Float64Array of length ${length}`);
  if (v.length !== length) throw new TypeError(`'${name}' must have length ${length}, got ${v.length}`);
}

/** Checks that `v` is an array-like of exactly `length` finite numbers. */
export function checkFiniteArray(v: unknown, length: number, name: string): asserts v is ArrayLike<number> {
  if (v === null || typeof v !== 'object' || typeof (v as ArrayLike<number>).length !== 'number') {
    throw new TypeError(`'${name}' must be an array of ${length} numbers`);
  }
  const a = v as ArrayLike<number>;
  if (a.length !== length) throw new TypeError(`'${name}' must have length ${length}, got ${a.length}`);
  for (let i = 0; i < length; i += 1) {
    const x = a[i];
    if (typeof x !== 'number') throw new TypeError(`'${name}'[${i}] must be a number, got ${typeof x}`);
    if (!Number.isFinite(x)) throw new RangeError(`'${name}'[${i}] must be finite, got ${x}`);
  }
}

/** Checks a finite number >= min. */
export function checkFiniteNumber(x: unknown, name: string, min = -Infinity): asserts x is number {
  if (typeof x !== 'number') throw new TypeError(`'${name}' must be a number, got ${typeof x}`);
  if (!Number.isFinite(x)) throw new RangeError(`'${name}' must be finite, got ${x}`);
  if (x < min) throw new RangeError(`'${name}' must be >= ${min}, got ${x}`);
}

/** Checks a manifold made for n dimensions. */
export function checkManifold(out: unknown, n: number, name: string): asserts out is Manifold {
  if (out === null || typeof out !== 'object') throw new TypeError(`'${name}' must be a Manifold (see createManifold)`);
  const m = out as Manifold;
  if (m.n !== n) throw new RangeError(`'${name}' must be a manifold for n = ${n}, got n = ${String(m.n)}`);
  const cap = m.capacity;
  if (!Number.isInteger(cap) || cap < 1) throw new TypeError(`'${name}.capacity' must be a positive integer`);
  checkNarrowphaseOutput(m.normal, n, `${name}.normal`);
  checkNarrowphaseOutput(m.points, cap * n, `${name}.points`);
  checkNarrowphaseOutput(m.separations, cap, `${name}.separations`);
  if (!(m.ids instanceof Uint32Array) || m.ids.length !== cap) {
    throw new TypeError(`'${name}.ids' must be a Uint32Array of length ${cap}`);
  }
}

/** Checks a pose: x of n finite numbers and M of n·n finite numbers, both Float64Array. */
export function checkPose(pose: unknown, n: number, name: string): asserts pose is Pose {
  if (pose === null || typeof pose !== 'object') throw new TypeError(`'${name}' must be a pose {x, M}`);
  const p = pose as Pose;
  checkNarrowphaseOutput(p.x, n, `${name}.x`);
  checkNarrowphaseOutput(p.M, n * n, `${name}.M`);
  checkFiniteArray(p.x, n, `${name}.x`);
  checkFiniteArray(p.M, n * n, `${name}.M`);
}

/** Checks a scratch made for n dimensions. */
export function checkScratch(scratch: unknown, n: number, name: string): asserts scratch is NarrowphaseScratch {
  if (scratch === null || typeof scratch !== 'object') {
    throw new TypeError(`'${name}' must be a NarrowphaseScratch (see createNarrowphaseScratch)`);
  }
  const s = scratch as NarrowphaseScratch;
  if (s.n !== n) throw new RangeError(`'${name}' must be a scratch for n = ${n}, got n = ${String(s.n)}`);
}

/**
 * Checks the geometry a narrowphase pair reads from `shape` (see narrowphase-shapes.ts) for n
 * dimensions. Unknown kinds are refused.
 */
export function checkCollisionShape(shape: unknown, n: number, name: string): void {
  if (shape === null || typeof shape !== 'object') throw new TypeError(`'${name}' must be a shape object`);
  const s = shape as Record<string, unknown>;
  switch (s.kind) {
    case 'box': {
      checkFiniteArray(s.halfExtents, n, `${name}.halfExtents`);
      const h = s.halfExtents as ArrayLike<number>;
      for (let i = 0; i < n; i += 1) {
        if (!(h[i] > 0)) throw new RangeError(`'${name}.halfExtents'[${i}] must be > 0, got ${h[i]}`);
      }
      return;
    }
    case 'sphere':
      checkFiniteNumber(s.radius, `${name}.radius`);
      if (!((s.radius as number) > 0)) throw new RangeError(`'${name}.radius' must be > 0, got ${String(s.radius)}`);
      return;
    case 'halfspace': {
      checkFiniteArray(s.normal, n, `${name}.normal`);
      const v = s.normal as ArrayLike<number>;
      let len2 = 0;
      for (let i = 0; i < n; i += 1) len2 += v[i] * v[i];
      if (!(len2 > 0) || !Number.isFinite(len2)) throw new RangeError(`'${name}.normal' must be a nonzero vector`);
      checkFiniteNumber(s.offset, `${name}.offset`);
      return;
    }
    case 'torus': {
      checkFiniteNumber(s.minorRadius, `${name}.minorRadius`);
      checkFiniteNumber(s.majorRadius, `${name}.majorRadius`);
      const r = s.minorRadius as number;
      const R = s.majorRadius as number;
      if (!(r > 0)) throw new RangeError(`'${name}.minorRadius' must be > 0, got ${r}`);
      if (!(R > r)) throw new RangeError(`'${name}.majorRadius' must be > minorRadius (${r}), got ${R}`);
      const { planeI, planeJ } = s;
      if (typeof planeI !== 'number' || !Number.isInteger(planeI) || planeI < 0 || planeI >= n) {
        throw new RangeError(`'${name}.planeI' must be an axis index in 0..${n - 1}, got ${String(planeI)}`);
      }
      if (typeof planeJ !== 'number' || !Number.isInteger(planeJ) || planeJ < 0 || planeJ >= n || planeJ === planeI) {
        throw new RangeError(`'${name}.planeJ' must be an axis index in 0..${n - 1} other than planeI, got ${String(planeJ)}`);
      }
      return;
    }
    case 'mesh': {
      const v = s.vertices as ArrayLike<number>;
      if (v === null || typeof v !== 'object' || typeof v.length !== 'number' || v.length === 0 || v.length % n !== 0) {
        throw new TypeError(`'${name}.vertices' must be a flat array of a nonzero multiple of ${n} numbers`);
      }
      checkFiniteArray(v, v.length, `${name}.vertices`);
      const offsets = s.facetOffsets as ArrayLike<number>;
      if (offsets === null || typeof offsets !== 'object' || typeof offsets.length !== 'number' || offsets.length === 0) {
        throw new TypeError(`'${name}.facetOffsets' must be a non-empty array of numbers`);
      }
      const facets = offsets.length;
      checkFiniteArray(offsets, facets, `${name}.facetOffsets`);
      checkFiniteArray(s.facetNormals, facets * n, `${name}.facetNormals`);
      checkFiniteArray(s.facets, facets * n, `${name}.facets`);
      const f = s.facets as ArrayLike<number>;
      const count = v.length / n;
      for (let i = 0; i < f.length; i += 1) {
        if (!Number.isInteger(f[i]) || f[i] < 0 || f[i] >= count) {
          throw new RangeError(`'${name}.facets'[${i}] must be a vertex index in 0..${count - 1}, got ${f[i]}`);
        }
      }
      return;
    }
    case 'capsule': {
      checkFiniteNumber(s.halfHeight, `${name}.halfHeight`);
      checkFiniteNumber(s.radius, `${name}.radius`);
      if (!((s.halfHeight as number) > 0)) throw new RangeError(`'${name}.halfHeight' must be > 0, got ${String(s.halfHeight)}`);
      if (!((s.radius as number) > 0)) throw new RangeError(`'${name}.radius' must be > 0, got ${String(s.radius)}`);
      return;
    }
    default:
      throw new TypeError(
        `'${name}.kind' must be 'box', 'sphere', 'halfspace', 'torus', 'mesh' or 'capsule', got ${String(s.kind)}`,
      );
  }
}
