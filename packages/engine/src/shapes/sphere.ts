import type { Dims } from '@physin/algebra';
import { ballVolume } from './ball-volume.js';
import { checkDims, checkPositive } from './checks.js';
import { checkMassArguments, diagonalMassProperties } from './mass-properties.js';
import { checkMagnitude, inputLimits } from './limits.js';
import type { MassProperties, Shape } from './shape.js';
import { sphereColliders } from '../collision/sphere-colliders.js';
import { registerShapeFactory } from '../snapshot/registry.js';

/** A solid ball centred on its local origin, in the n dimensions of the `D` it was built with. */
export interface SphereShape extends Shape {
  readonly kind: 'sphere';
  readonly n: number;
  /** Radius (m), > 0. */
  readonly radius: number;
}

/**
 * Builds a solid ball (hypersphere) of the given radius in the dimensions of `D`. Every shape
 * factory takes the dimensions first, so a call reads the same for every shape.
 *
 * Mass properties in n dimensions: volume V_n(ρ) = π^(n/2) ρⁿ / Γ(n/2 + 1) (the engine's `ballVolume`);
 * covariance C_ii = m ρ² / (n + 2) on every axis.
 *
 * @param D - the dimensions (from `dims(n)`).
 * @param radius - radius (m), within [1e-9, 1e9] (`Body.limits`).
 * @throws TypeError when `D` is not a Dims or `radius` is not a number; RangeError when the
 *   radius is not finite or not > 0.
 */
export function HyperSphere(D: Dims, radius: number): SphereShape {
  const dimensions = checkDims('HyperSphere', D).n;
  const rho = checkPositive('HyperSphere', radius, 'radius');
  checkMagnitude('HyperSphere', "argument 'radius'", rho, inputLimits.minLength, inputLimits.maxLength, 'm');
  return Object.freeze({
    // Collision pairs travel with the shape, so an unused shape leaves its collision code out of the bundle.
    colliders: sphereColliders,
    kind: 'sphere' as const,
    n: dimensions,
    radius: rho,
    massProperties(D: Dims, mass: number): MassProperties {
      const checked = checkMassArguments('HyperSphere.massProperties', D, mass, dimensions);
      const n = checked.n;
      const c = (rho * rho) / (n + 2);
      const unitCovariance = new Float64Array(n).fill(c);
      return diagonalMassProperties(checked, ballVolume(n, rho), unitCovariance, mass);
    },
  });
}

// World snapshots rebuild saved shapes of this kind with this factory (snapshot/registry.ts).
registerShapeFactory('sphere', HyperSphere);
