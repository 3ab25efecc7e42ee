import type { Dims } from '@physin/algebra';
import { checkDims, checkFinite, checkVector } from './checks.js';
import type { MassProperties, Shape } from './shape.js';
import { checkMagnitude, inputLimits } from './limits.js';
import { registerShapeFactory } from '../snapshot/registry.js';

/**
 * A solid half-space: the points x with normal · x <= offset, bounded by the hyperplane
 * normal · x = offset. It is static only: it has no finite mass.
 */
export interface HalfSpaceShape extends Shape {
  readonly kind: 'halfspace';
  readonly n: number;
  /** Unit outward normal (n numbers): it points out of the solid. Read only: do not write. */
  readonly normal: Float64Array;
  /** Signed distance of the boundary plane from the local origin along `normal` (m). */
  readonly offset: number;
}

/**
 * Builds a static half-space {x : normal · x <= offset}.
 *
 * A `normal` that is not of unit length is normalised, and `offset` is divided by the same
 * length, so the plane given (the set normal · x = offset) is the plane stored.
 *
 * `massProperties` throws: a half-space has no mass; give its body mass 0 (static).
 *
 * @param D - the tables of the dimension; its n must equal `normal.length`.
 * @param normal - n numbers, finite, not all zero; points out of the solid.
 * @param offset - finite (m); offset / |normal| within ±1e12 (`Body.limits.maxPosition`).
 * @throws TypeError for a wrong type or length; RangeError for non-finite numbers or a zero normal.
 */
export function HalfSpace(D: Dims, normal: ArrayLike<number>, offset: number): HalfSpaceShape {
  const where = 'HalfSpace';
  const n = checkDims(where, D).n;
  const unit = checkVector(where, normal, 'normal', n);
  const d = checkFinite(where, offset, 'offset');
  let length = 0;
  for (let i = 0; i < n; i += 1) length = Math.hypot(length, unit[i]);
  if (!(length > 0) || !Number.isFinite(length)) {
    throw new RangeError(`${where}: argument 'normal' must be a non-zero vector, got length ${length}`);
  }
  for (let i = 0; i < n; i += 1) unit[i] /= length;
  const stored = d / length;
  checkMagnitude(where, "argument 'offset' / |normal|", stored, 0, inputLimits.maxPosition, 'm');
  return Object.freeze({
    kind: 'halfspace' as const,
    n,
    normal: unit,
    offset: stored,
    massProperties(_D: Dims, _mass: number): MassProperties {
      throw new RangeError('HalfSpace.massProperties: a half-space has no mass; it is static only (give its body mass 0)');
    },
  });
}

// World snapshots rebuild saved shapes of this kind with this factory (snapshot/registry.ts).
registerShapeFactory('halfspace', HalfSpace);
