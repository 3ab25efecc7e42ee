import { inertiaDiagonal } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { checkDims, checkFinite } from './checks.js';
import type { MassProperties } from './shape.js';
import { formatBound, inputLimits } from './limits.js';

/**
 * Checks the arguments of a `massProperties(D, mass)` call: `D` a Dims whose n equals the
 * shape's n (when the shape has one), `mass` within [minMass, maxMass] (`Body.limits`).
 *
 * @returns the checked Dims.
 */
export function checkMassArguments(where: string, D: unknown, mass: unknown, shapeN: number | null): Dims {
  const dimsChecked = checkDims(where, D);
  if (shapeN !== null && dimsChecked.n !== shapeN) {
    throw new RangeError(`${where}: argument 'D' has n = ${dimsChecked.n} but the shape was built for n = ${shapeN}`);
  }
  const m = checkFinite(where, mass, 'mass');
  if (!(m > 0)) {
    throw new RangeError(`${where}: argument 'mass' must be > 0 (a static body has no mass properties), got ${m}`);
  }
  if (!(m >= inputLimits.minMass && m <= inputLimits.maxMass)) {
    throw new RangeError(
      `${where}: argument 'mass' must be within [${formatBound(inputLimits.minMass)}, ${formatBound(inputLimits.maxMass)}] kg (Body.limits), got ${m}`,
    );
  }
  return dimsChecked;
}

/**
 * Builds the mass properties of a shape whose covariance is diagonal in its own frame.
 *
 * @param D - the tables of the dimension.
 * @param volume - the n-volume of the shape (m^n).
 * @param unitCovariance - the n diagonal entries of the covariance per unit mass (m²), i.e.
 *   ∫ x_i² dV / V about the centre of mass.
 * @param mass - total mass (kg); the covariance and inertia scale linearly with it.
 */
export function diagonalMassProperties(D: Dims, volume: number, unitCovariance: ArrayLike<number>, mass: number): MassProperties {
  const covariance = new Float64Array(D.n);
  for (let i = 0; i < D.n; i += 1) {
    covariance[i] = mass * unitCovariance[i];
    // every shape factory bounds its sizes, so this holds for them; it guards against a new one
    if (!(covariance[i] > 0 && covariance[i] < Infinity)) {
      throw new RangeError(
        `massProperties: the covariance[${i}] of mass ${mass} kg is ${covariance[i]}: the shape is too small or too large`,
      );
    }
  }
  if (!(volume > 0 && volume < Infinity))
    throw new RangeError(`massProperties: the shape's volume is ${volume}: too small or too large`);
  const inertia = inertiaDiagonal(D, new Float64Array(D.k), covariance);
  return Object.freeze({ volume, covariance, inertia });
}
