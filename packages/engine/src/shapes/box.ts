import type { Dims } from '@physin/algebra';
import { checkDims, checkVector } from './checks.js';
import { checkMassArguments, diagonalMassProperties } from './mass-properties.js';
import { checkMagnitude, inputLimits } from './limits.js';
import type { MassProperties, Shape } from './shape.js';
import { boxColliders } from '../collision/box-colliders.js';
import { registerShapeFactory } from '../snapshot/registry.js';

/**
 * A solid n-dimensional box centred on its local origin with its edges along the local axes:
 * the points with |x_i| <= halfExtents[i] for every i.
 */
export interface BoxShape extends Shape {
  readonly kind: 'box';
  readonly n: number;
  /** Half the edge length along each local axis (m), n numbers, all > 0. Read only: do not write. */
  readonly halfExtents: Float64Array;
}

/**
 * Builds a solid box (hyperbox) with the given half extents.
 *
 * Mass properties: volume ∏ 2a_i; covariance C_ii = m a_i² / 3 (uniform density).
 *
 * @param D - the tables of the dimension; its n must equal `halfExtents.length`.
 * @param halfExtents - n half edge lengths (m), each within [1e-9, 1e9] (`Body.limits`; copied).
 * @throws TypeError when `D` is not a Dims or `halfExtents` has the wrong length;
 *   RangeError for a non-finite, zero or negative half extent, or one beyond the length bounds.
 */
export function HyperBox(D: Dims, halfExtents: ArrayLike<number>): BoxShape {
  const where = 'HyperBox';
  const dimsChecked = checkDims(where, D);
  const n = dimsChecked.n;
  const a = checkVector(where, halfExtents, 'halfExtents', n);
  let volume = 1;
  const unitCovariance = new Float64Array(n);
  for (let i = 0; i < n; i += 1) {
    if (!(a[i] > 0)) throw new RangeError(`${where}: argument 'halfExtents'[${i}] must be > 0, got ${a[i]}`);
    checkMagnitude(where, `argument 'halfExtents'[${i}]`, a[i], inputLimits.minLength, inputLimits.maxLength, 'm');
    volume *= 2 * a[i];
    unitCovariance[i] = (a[i] * a[i]) / 3;
  }
  return Object.freeze({
    // Collision pairs travel with the shape, so an unused shape leaves its collision code out of the bundle.
    colliders: boxColliders,
    kind: 'box' as const,
    n,
    halfExtents: a,
    massProperties(Dm: Dims, mass: number): MassProperties {
      const checked = checkMassArguments('HyperBox.massProperties', Dm, mass, n);
      return diagonalMassProperties(checked, volume, unitCovariance, mass);
    },
  });
}

// World snapshots rebuild saved shapes of this kind with this factory (snapshot/registry.ts).
registerShapeFactory('box', HyperBox);
