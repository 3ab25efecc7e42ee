import type { Dims } from '@physin/algebra';
import { ballVolume } from './ball-volume.js';
import { checkDims, checkPositive } from './checks.js';
import { checkMassArguments, diagonalMassProperties } from './mass-properties.js';
import { checkMagnitude, inputLimits } from './limits.js';
import type { MassProperties, Shape } from './shape.js';
import { computeBoundsUnchecked } from '../collision/bounds.js';
import { capsuleColliders } from '../collision/capsule-colliders.js';
import { registerShapeFactory } from '../snapshot/registry.js';

/**
 * A solid capsule centred on its local origin: the points within `radius` of the core segment
 * from −halfHeight·e₁ to +halfHeight·e₁ (local axis 1, "y", as three.js's CapsuleGeometry and
 * Rapier's capsule). In 2D a stadium, in 3D the usual capsule, in 4D a 3-ball swept along a segment.
 */
export interface CapsuleShape extends Shape {
  readonly kind: 'capsule';
  readonly n: number;
  /** Half the length of the core segment (m), > 0: the capsule is 2·(halfHeight + radius) long. */
  readonly halfHeight: number;
  /** Radius of the ball swept along the segment (m), > 0. */
  readonly radius: number;
}

/**
 * The volume and the diagonal of the covariance per unit mass of an n-dimensional capsule
 * (half-height h of the core segment along axis 1, radius r), uniform density.
 *
 * Derivation (V_d(r) = volume of the d-ball, ∫ over a d-ball of x_j² = V_d(r) r² / (d + 2)):
 * - volume: the cylinder 2h·V_(n−1)(r) plus the two half-balls, one whole ball V_n(r);
 * - along axis 1: cylinder ∫y² = V_(n−1)(r)·2h³/3; caps: each half-ball sits at ±h, so
 *   ∫(h + y')² = h²V_n/2 + 2h∫y' + V_n r²/(2(n + 2)) per cap, with ∫_(half-ball) y' dV =
 *   V_(n−1)(r)·r²/(n + 1); both caps: h²V_n + 4h V_(n−1) r²/(n + 1) + V_n r²/(n + 2);
 * - across (every other axis): cylinder 2h·V_(n−1)(r)·r²/(n + 1); caps: V_n(r)·r²/(n + 2).
 *
 * Each second moment is divided by the volume. Checked against a Monte Carlo estimate in
 * tests/collision-capsule.test.ts for n = 2..5.
 *
 * @param n - count of dimensions (>= 2).
 * @param halfHeight - h (m), > 0.
 * @param radius - r (m), > 0.
 * @returns the volume (m^n), and the unit covariance along axis 1 and across it (m²).
 */
export function capsuleMoments(
  n: number,
  halfHeight: number,
  radius: number,
): { readonly volume: number; readonly along: number; readonly across: number } {
  const h = halfHeight;
  const r = radius;
  const disc = ballVolume(n - 1, r);
  const ball = ballVolume(n, r);
  const volume = 2 * h * disc + ball;
  const r2 = r * r;
  const alongCylinder = (disc * 2 * h * h * h) / 3;
  const alongCaps = h * h * ball + (4 * h * disc * r2) / (n + 1) + (ball * r2) / (n + 2);
  const acrossCylinder = (2 * h * disc * r2) / (n + 1);
  const acrossCaps = (ball * r2) / (n + 2);
  return { volume, along: (alongCylinder + alongCaps) / volume, across: (acrossCylinder + acrossCaps) / volume };
}

/**
 * Builds a solid capsule (a segment swept by a ball) in the dimensions of `D`: the points within
 * `radius` of the segment from −halfHeight·e₁ to +halfHeight·e₁ (local axis 1). Dimensions come
 * first, as in every shape factory.
 *
 * Mass properties in n dimensions (derived in `capsuleMoments`, shapes/capsule.ts): volume 2h·V_(n−1)(r) + V_n(r);
 * covariance along axis 1 m·[V_(n−1)·2h³/3 + h²V_n + 4hV_(n−1)r²/(n+1) + V_n r²/(n+2)]/V, across
 * it m·[2hV_(n−1)r²/(n+1) + V_n r²/(n+2)]/V.
 *
 * @param D - the dimensions (from `dims(n)`).
 * @param halfHeight - half the length of the core segment (m), within [1e-9, 1e9] (`Body.limits`).
 * @param radius - radius (m), within [1e-9, 1e9].
 * @throws TypeError when `D` is not a Dims or an argument is not a number; RangeError when a
 *   length is not finite, not > 0 or outside `Body.limits`.
 */
export function HyperCapsule(D: Dims, halfHeight: number, radius: number): CapsuleShape {
  const where = 'HyperCapsule';
  const n = checkDims(where, D).n;
  const h = checkPositive(where, halfHeight, 'halfHeight');
  const r = checkPositive(where, radius, 'radius');
  checkMagnitude(where, "argument 'halfHeight'", h, inputLimits.minLength, inputLimits.maxLength, 'm');
  checkMagnitude(where, "argument 'radius'", r, inputLimits.minLength, inputLimits.maxLength, 'm');
  const moments = capsuleMoments(n, h, r);
  const unitCovariance = new Float64Array(n).fill(moments.across);
  unitCovariance[1] = moments.along;
  return Object.freeze({
    // Collision pairs travel with the shape, so an unused shape leaves its collision code out of the bundle.
    colliders: capsuleColliders,
    // Its bounds too: a world of boxes, balls and half-spaces carries no code of other kinds.
    bounds: computeBoundsUnchecked,
    kind: 'capsule' as const,
    n,
    halfHeight: h,
    radius: r,
    massProperties(Dm: Dims, mass: number): MassProperties {
      const c = checkMassArguments('HyperCapsule.massProperties', Dm, mass, n);
      return diagonalMassProperties(c, moments.volume, unitCovariance, mass);
    },
  });
}

// World snapshots rebuild saved shapes of this kind with this factory (snapshot/registry.ts).
registerShapeFactory('capsule', HyperCapsule);
