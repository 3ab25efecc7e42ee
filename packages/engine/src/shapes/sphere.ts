import type { Dims } from '@physin/algebra';
import { ballVolume } from './ball-volume.js';
import { checkPositive } from './checks.js';
import { checkMassArguments, diagonalMassProperties } from './mass-properties.js';
import type { MassProperties, Shape } from './shape.js';
import { sphereColliders } from '../collision/sphere-colliders.js';
import { registerShapeFactory } from '../snapshot/registry.js';

/**
 * A solid ball centred on its local origin. It has no count of dimensions of its own (`n` is
 * null): it takes the n of the world or the Dims it is used with.
 */
export interface SphereShape extends Shape {
  readonly kind: 'sphere';
  readonly n: null;
  /** Radius (m), > 0. */
  readonly radius: number;
}

/**
 * Builds a solid ball (hypersphere) of the given radius, usable in any dimension.
 *
 * Mass properties in n dimensions: volume V_n(ρ) = π^(n/2) ρⁿ / Γ(n/2 + 1) (see {@link ballVolume});
 * covariance C_ii = m ρ² / (n + 2) on every axis.
 *
 * @param radius - radius (m), finite and > 0.
 * @throws TypeError when `radius` is not a number; RangeError when it is not finite or not > 0.
 */
export function HyperSphere(radius: number): SphereShape {
  const rho = checkPositive('HyperSphere', radius, 'radius');
  return Object.freeze({
    // Collision pairs travel with the shape, so an unused shape leaves its collision code out of the bundle.
    colliders: sphereColliders,
    kind: 'sphere' as const,
    n: null,
    radius: rho,
    massProperties(D: Dims, mass: number): MassProperties {
      const checked = checkMassArguments('HyperSphere.massProperties', D, mass, null);
      const n = checked.n;
      const c = (rho * rho) / (n + 2);
      const unitCovariance = new Float64Array(n).fill(c);
      return diagonalMassProperties(checked, ballVolume(n, rho), unitCovariance, mass);
    },
  });
}

// World snapshots rebuild saved shapes of this kind with this factory (snapshot/registry.ts).
registerShapeFactory('sphere', HyperSphere);
