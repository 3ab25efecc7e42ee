import type { Dims } from '@physin/algebra';
import { ballVolume } from './ball-volume.js';
import { checkDims, checkIndex, checkPositive, isNumberList } from './checks.js';
import { checkMassArguments, diagonalMassProperties } from './mass-properties.js';
import { checkMagnitude, inputLimits } from './limits.js';
import type { MassProperties, Shape } from './shape.js';
import { computeBoundsUnchecked } from '../collision/bounds.js';
import { torusColliders } from '../collision/torus-colliders.js';
import { registerShapeFactory } from '../snapshot/registry.js';

/**
 * A solid n-torus centred on its local origin: the points at distance <= `minorRadius` from the
 * core circle of radius `majorRadius` that lies in the plane of axes (`planeI`, `planeJ`):
 * (√(x_i² + x_j²) − R)² + Σ_(other k) x_k² <= r².
 * In 3D the usual ring torus; in 4D its cross-section is a 3-ball; in 2D an annulus.
 */
export interface TorusShape extends Shape {
  readonly kind: 'torus';
  readonly n: number;
  /** Radius R of the core circle (m), > minorRadius. */
  readonly majorRadius: number;
  /** Radius r of the tube round the core circle (m), 0 < r < R. */
  readonly minorRadius: number;
  /** First axis of the core circle's plane (planeI < planeJ). */
  readonly planeI: number;
  /** Second axis of the core circle's plane. */
  readonly planeJ: number;
  /** Index of the plane (planeI, planeJ) in lexicographic bivector order. */
  readonly plane: number;
}

/**
 * Builds a solid n-torus.
 *
 * Mass properties (uniform density): volume 2πR · V_(n−1)(r) (V_d = volume of the d-ball);
 * covariance C_ii = C_jj = m (R² + 3r²/(n+1)) / 2 on the two axes of the core plane and
 * C_kk = m r²/(n+1) on every other axis. In 3D this gives the classical inertia m(R² + 3r²/4)
 * about the symmetry axis and m(4R² + 5r²)/8 about a diameter.
 *
 * @param D - the tables of the dimension.
 * @param majorRadius - R (m), > minorRadius, within [1e-9, 1e9] (`Body.limits`).
 * @param minorRadius - r (m), within [1e-9, 1e9].
 * @param plane - the plane of the core circle: either its index in lexicographic order
 *   (0 ..< k; n = 3: 0 = xy, 1 = xz, 2 = yz) or a pair of distinct axes [i, j] (either order).
 * @throws TypeError for a wrong type; RangeError for radii out of range (including r >= R) or a
 *   bad plane.
 */
export function HyperTorus(
  D: Dims,
  majorRadius: number,
  minorRadius: number,
  plane: number | readonly [number, number] | ArrayLike<number>,
): TorusShape {
  const where = 'HyperTorus';
  const checked = checkDims(where, D);
  const { n, k } = checked;
  const R = checkPositive(where, majorRadius, 'majorRadius');
  const r = checkPositive(where, minorRadius, 'minorRadius');
  checkMagnitude(where, "argument 'majorRadius'", R, inputLimits.minLength, inputLimits.maxLength, 'm');
  checkMagnitude(where, "argument 'minorRadius'", r, inputLimits.minLength, inputLimits.maxLength, 'm');
  if (!(r < R)) {
    throw new RangeError(`${where}: argument 'minorRadius' must be < 'majorRadius' (a ring torus), got r = ${r} >= R = ${R}`);
  }
  let planeI: number;
  let planeJ: number;
  if (typeof plane === 'number') {
    const p = checkIndex(where, plane, 'plane', 0, k - 1);
    planeI = checked.planeI[p];
    planeJ = checked.planeJ[p];
  } else if (isNumberList(plane)) {
    if (plane.length !== 2)
      throw new TypeError(`${where}: argument 'plane' as a pair of axes must have length 2, got ${plane.length}`);
    const a = checkIndex(where, plane[0], 'plane[0]', 0, n - 1);
    const b = checkIndex(where, plane[1], 'plane[1]', 0, n - 1);
    if (a === b) throw new RangeError(`${where}: argument 'plane' must name two different axes, got [${a}, ${b}]`);
    planeI = Math.min(a, b);
    planeJ = Math.max(a, b);
  } else {
    throw new TypeError(`${where}: argument 'plane' must be a plane index or a pair of axes [i, j], got ${typeof plane}`);
  }
  const planeIndex = checked.planeIndexOf[planeI * n + planeJ];
  const volume = 2 * Math.PI * R * ballVolume(n - 1, r);
  const unitCovariance = new Float64Array(n).fill((r * r) / (n + 1));
  const inPlane = (R * R + (3 * r * r) / (n + 1)) / 2;
  unitCovariance[planeI] = inPlane;
  unitCovariance[planeJ] = inPlane;
  return Object.freeze({
    // Collision pairs travel with the shape, so an unused shape leaves its collision code out of the bundle.
    colliders: torusColliders,
    // Its bounds too: a world of boxes, balls and half-spaces carries no code of other kinds.
    bounds: computeBoundsUnchecked,
    kind: 'torus' as const,
    n,
    majorRadius: R,
    minorRadius: r,
    planeI,
    planeJ,
    plane: planeIndex,
    massProperties(Dm: Dims, mass: number): MassProperties {
      const c = checkMassArguments('HyperTorus.massProperties', Dm, mass, n);
      return diagonalMassProperties(c, volume, unitCovariance, mass);
    },
  });
}

// World snapshots rebuild saved shapes of this kind with this factory (snapshot/registry.ts).
registerShapeFactory('torus', HyperTorus);
