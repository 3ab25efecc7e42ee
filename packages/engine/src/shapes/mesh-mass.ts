import { checkIndex, checkPoints, checkPositive, checkTuples } from './checks.js';
import { addCone, centreMoments, createMoments, facetNormal, factorial } from './mesh-geometry.js';
import type { Moments } from './mesh-geometry.js';
import { checkClosedBoundary } from './mesh-topology.js';

/**
 * Mass properties of a solid of uniform density in its input coordinates.
 */
export interface SolidMassProperties {
  /** The n-volume (m^n), > 0. */
  readonly volume: number;
  /** density × volume (kg). */
  readonly mass: number;
  /** The centre of mass, n numbers (m). */
  readonly centroid: Float64Array;
  /**
   * The full mass-weighted covariance about the centroid, C = ∫ (x − c)(x − c)ᵀ dm, as an n×n
   * row-major symmetric matrix (kg·m²).
   */
  readonly covariance: Float64Array;
}

/** {@link SolidMassProperties} of a simplex, with the orientation of its vertex order. */
export interface SimplexMassProperties extends SolidMassProperties {
  /**
   * det[v_1 − v_0, …, v_n − v_0] / n!: the volume with the sign of the vertex order (negative
   * when the order is a mirror image of the axes' order).
   */
  readonly signedVolume: number;
}

function checkDimension(where: string, n: unknown): number {
  return checkIndex(where, n, 'n', 2, 8);
}

/**
 * Volume, centroid and covariance of a solid n-simplex of uniform density.
 *
 * Closed form: with vertices v_0..v_n, volume |det[v_1 − v_0, …, v_n − v_0]| / n!, centroid
 * (Σ v)/(n+1), and about the origin ∫ x xᵀ dm = m/((n+1)(n+2)) · (Σ v vᵀ + (Σ v)(Σ v)ᵀ); the
 * result is shifted to the centroid (parallel axis rule).
 *
 * @param n - count of dimensions, 2..8.
 * @param vertices - n + 1 points, as number[][] or flat (n(n+1) numbers).
 * @param density - kg/m^n, finite and > 0 (default 1: mass = volume).
 * @throws TypeError for wrong types or lengths; RangeError for non-finite numbers, a bad
 *   density or a degenerate (zero-volume) simplex.
 */
export function simplexMassProperties(n: number, vertices: unknown, density = 1): SimplexMassProperties {
  const where = 'simplexMassProperties';
  checkDimension(where, n);
  const v = checkPoints(where, vertices, 'vertices', n);
  if (v.length !== n * (n + 1)) {
    throw new TypeError(`${where}: argument 'vertices' must hold ${n + 1} points of ${n} numbers, got ${v.length / n} points`);
  }
  const rho = checkPositive(where, density, 'density');
  // the simplex is the cone from v_0 over the facet (v_1..v_n)
  const w = new Float64Array(n * n);
  for (let a = 0; a < n; a += 1) for (let c = 0; c < n; c += 1) w[a * n + c] = v[(a + 1) * n + c] - v[c];
  const facet = new Int32Array(n);
  for (let a = 0; a < n; a += 1) facet[a] = a;
  const normal = facetNormal(n, new Float64Array(n), w, facet, 0, new Float64Array(2 * n * n));
  let signedVolume = 0;
  for (let c = 0; c < n; c += 1) signedVolume += normal[c] * w[c];
  signedVolume /= factorial(n);
  if (!(Math.abs(signedVolume) > 0)) {
    throw new RangeError(`${where}: argument 'vertices' span no volume: the simplex is degenerate`);
  }
  const acc = createMoments(n);
  addCone(n, acc, w, signedVolume, new Float64Array(n));
  return { ...finish(n, acc, v.subarray(0, n), rho), signedVolume };
}

/** Centroid (shifted back by the reference point) and mass-weighted covariance; V ≠ 0. */
function finish(n: number, acc: Moments, reference: ArrayLike<number>, density: number): SolidMassProperties {
  const centroid = new Float64Array(n);
  const covariance = new Float64Array(n * n);
  centreMoments(n, acc, centroid, covariance);
  // |V|: an inward-oriented mesh gives V < 0, and every moment flips sign with it
  const scale = density * Math.sign(acc.volume);
  for (let i = 0; i < n * n; i += 1) covariance[i] *= scale;
  for (let c = 0; c < n; c += 1) centroid[c] += reference[c];
  const volume = Math.abs(acc.volume);
  return { volume, mass: density * volume, centroid, covariance };
}

/**
 * Adds the cones from `p` over every facet to `acc`. Unchecked; `p` has n numbers.
 * @returns acc
 */
export function accumulateMeshMoments(
  n: number,
  vertices: ArrayLike<number>,
  facets: ArrayLike<number>,
  p: ArrayLike<number>,
  acc: Moments,
): Moments {
  const facetCount = facets.length / n;
  const w = new Float64Array(n * n);
  const normal = new Float64Array(n);
  const scratch = new Float64Array(2 * n * n);
  const sum = new Float64Array(n);
  const nFactorial = factorial(n);
  for (let f = 0; f < facetCount; f += 1) {
    for (let a = 0; a < n; a += 1) {
      const v = facets[f * n + a] * n;
      for (let c = 0; c < n; c += 1) w[a * n + c] = vertices[v + c] - p[c];
    }
    facetNormal(n, normal, vertices, facets, f, scratch);
    let det = 0;
    for (let c = 0; c < n; c += 1) det += normal[c] * w[c];
    addCone(n, acc, w, det / nFactorial, sum);
  }
  return acc;
}

/**
 * Volume, centroid and covariance of the solid bounded by a closed mesh of (n−1)-simplices,
 * convex or not (a tessellated torus works), with uniform density.
 *
 * Method: the sum over facets of the signed cones from a reference point p (the mean of the
 * vertices, for accuracy; any point gives the same result for a closed mesh), each with the
 * simplex formulas of {@link simplexMassProperties}; then the parallel axis rule to the centroid.
 *
 * The facets must be consistently oriented, all outward or all inward (the sign of the total
 * tells which); a facet (a_0..a_(n−1)) is outward when det[a_0 − p, …, a_(n−1) − p] > 0 for p
 * inside (3D: counter-clockwise seen from outside). The mesh is checked to be closed and
 * consistently oriented.
 *
 * @param n - count of dimensions, 2..8.
 * @param vertices - points as number[][] or flat (n per point).
 * @param facets - n vertex indices per facet, as number[][] or flat.
 * @param density - kg/m^n, finite and > 0 (default 1: mass = volume).
 * @throws TypeError for wrong types or lengths; RangeError for non-finite numbers, indices out
 *   of range, repeated indices in a facet, an open or inconsistently oriented mesh, or zero volume.
 */
export function closedMeshMassProperties(n: number, vertices: unknown, facets: unknown, density = 1): SolidMassProperties {
  const where = 'closedMeshMassProperties';
  checkDimension(where, n);
  const v = checkPoints(where, vertices, 'vertices', n);
  const count = v.length / n;
  const f = checkTuples(where, facets, 'facets', n, count);
  const rho = checkPositive(where, density, 'density');
  if (f.length === 0) throw new RangeError(`${where}: argument 'facets' is empty`);
  checkClosedBoundary(n, f, { where, facets: 'facets' });
  const p = new Float64Array(n);
  for (let i = 0; i < count; i += 1) for (let c = 0; c < n; c += 1) p[c] += v[i * n + c];
  for (let c = 0; c < n; c += 1) p[c] /= count;
  const acc = accumulateMeshMoments(n, v, f, p, createMoments(n));
  if (!(Math.abs(acc.volume) > 0)) throw new RangeError(`${where}: the mesh encloses no volume`);
  return finish(n, acc, p, rho);
}
