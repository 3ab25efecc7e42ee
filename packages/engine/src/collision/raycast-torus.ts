/**
 * The solid n-torus for ray casts: its exact signed distance and a sphere-traced ray hit.
 *
 * The distance from a local point p to the tube surface is
 *   f(p) = √((ρ − R)² + Σ_{k ∉ {i,j}} p_k²) − r,   ρ = √(p_i² + p_j²),
 * exact (not a bound) outside and inside, so a step of f along a ray never passes the surface.
 * Unchecked kernels: the caller validates.
 */
import { MAX_DIMENSIONS } from './query-checks.js';
import type { TorusGeometry } from './query-shapes.js';

const point = new Float64Array(MAX_DIMENSIONS);

/**
 * Newton refinement stops where the ray meets the surface at a slope |∇f·d̂| below this: one
 * step then moves at most tolerance / MIN_REFINE_SLOPE, so it cannot leap past a thin feature.
 */
const MIN_REFINE_SLOPE = 1e-4;
/** Newton evaluations after the trace: quadratic convergence needs 2–3 from the trace's tolerance. */
const REFINE_STEPS = 6;

/**
 * Signed distance (m) from local point q to the torus surface, negative inside. With `outGrad`,
 * also writes the gradient of the distance (the outward unit normal of the nearest surface point;
 * zero on the core circle, and without its in-plane part on the axis ρ = 0, where it is undefined).
 */
export function torusDistance(n: number, torus: TorusGeometry, q: ArrayLike<number>, outGrad: Float64Array | null): number {
  const pi = torus.planeI;
  const pj = torus.planeJ;
  let s = 0;
  for (let k = 0; k < n; k += 1) if (k !== pi && k !== pj) s += q[k]! * q[k]!;
  const qi = q[pi]!;
  const qj = q[pj]!;
  const rho = Math.sqrt(qi * qi + qj * qj);
  const a = rho - torus.majorRadius;
  const w = Math.sqrt(a * a + s);
  if (outGrad !== null) {
    const inv = w > 0 ? 1 / w : 0;
    for (let k = 0; k < n; k += 1) outGrad[k] = q[k]! * inv;
    const radial = rho > 0 ? (a * inv) / rho : 0;
    outGrad[pi] = qi * radial;
    outGrad[pj] = qj * radial;
  }
  return w - torus.minorRadius;
}

/**
 * First hit of the ray o + t·d (local frame, d unit, o outside the torus) for t in
 * [0, maxDistance]: sphere tracing inside the bounding ball |p| <= R + r until the distance is
 * at most `tolerance` (at most `maxSteps` steps; a ray still farther than that after the last
 * step counts as a miss), then Newton steps on f along the ray where the ray is not grazing.
 * Returns t or −1; on a hit writes the local outward unit normal into outNormal.
 */
export function torusRayTrace(
  n: number,
  torus: TorusGeometry,
  o: ArrayLike<number>,
  d: ArrayLike<number>,
  maxDistance: number,
  tolerance: number,
  maxSteps: number,
  outNormal: Float64Array,
): number {
  const bound = torus.majorRadius + torus.minorRadius;
  let b = 0;
  let c = 0;
  for (let k = 0; k < n; k += 1) {
    b += o[k]! * d[k]!;
    c += o[k]! * o[k]!;
  }
  c -= bound * bound;
  const disc = b * b - c;
  if (disc < 0) return -1;
  const sq = Math.sqrt(disc);
  const tFar = -b + sq;
  if (tFar < 0) return -1;
  const tNear = c > 0 ? c / (-b + sq) : 0;
  const end = Math.min(maxDistance, tFar);
  let t = tNear > 0 ? tNear : 0;
  let f = Infinity;
  for (let step = 0; step < maxSteps; step += 1) {
    if (t > end) return -1;
    at(n, o, d, t);
    f = torusDistance(n, torus, point, null);
    if (f <= tolerance) break;
    t += f;
  }
  if (!(f <= tolerance)) return -1;

  // Newton on f(t): keep the iterate with the smallest |f| among those still approaching the
  // surface (slope < 0), so a step that lands past a grazing chord cannot pick the exit point.
  let best = t;
  let bestF = f;
  for (let it = 0; it < REFINE_STEPS; it += 1) {
    at(n, o, d, t);
    const g = torusDistance(n, torus, point, outNormal);
    let slope = 0;
    for (let k = 0; k < n; k += 1) slope += outNormal[k]! * d[k]!;
    if (slope >= 0) break;
    if (Math.abs(g) < bestF) {
      best = t;
      bestF = Math.abs(g);
    }
    if (slope > -MIN_REFINE_SLOPE || it === REFINE_STEPS - 1) break;
    const dt = -g / slope;
    if (Math.abs(dt) <= 1e-16 * (1 + Math.abs(t))) break;
    t += dt;
  }
  t = best;
  if (t < 0) t = 0;
  if (t > maxDistance) return -1;
  at(n, o, d, t);
  torusDistance(n, torus, point, outNormal);
  return t;
}

function at(n: number, o: ArrayLike<number>, d: ArrayLike<number>, t: number): void {
  for (let k = 0; k < n; k += 1) point[k] = o[k]! + t * d[k]!;
}
