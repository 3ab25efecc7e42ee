/**
 * Ray casts against single posed shapes in n dimensions.
 *
 * A ray is origin + t·d̂ for t in [0, maxDistance], d̂ the direction normalised: distances are in
 * metres along the ray whatever the direction's length. Shapes are solid: a ray that starts
 * inside (or on the boundary of) a shape hits it at distance 0, with point = origin and
 * normal = −d̂. Otherwise the hit is the first boundary point, with the outward unit normal there.
 *
 * Methods: sphere — the quadratic in t, solved without cancellation; box — slab test in the box's
 * frame, the normal from the last slab entered; half-space — one plane; convex mesh — the ray
 * clipped by every facet plane (Cyrus–Beck), the normal from the last facet entered; capsule —
 * the earliest of its cylinder's side and its two end balls (quadratics); torus —
 * sphere tracing of its exact distance function inside its bounding ball, then Newton steps.
 */
import {
  MAX_DIMENSIONS,
  checkDimension,
  checkDirection,
  checkFiniteArray,
  checkNumber,
  checkPose,
  checkShape,
} from './query-checks.js';
import type { CapsuleGeometry, ConvexMeshGeometry, QueryShape, TorusGeometry } from './query-shapes.js';
import { CAPSULE_RAY_INSIDE, capsuleRayLocal } from './raycast-capsule.js';
import { torusDistance, torusRayTrace } from './raycast-torus.js';

/** Where a ray met a shape. `point` and `normal` have n components. */
export interface RayHit {
  /** Distance along the ray (m), or −1 after a miss. */
  distance: number;
  /** World point of the hit. */
  readonly point: Float64Array;
  /** Outward unit normal of the shape at the hit (−d̂ when the ray starts inside). */
  readonly normal: Float64Array;
}

/** Settings of the torus ray cast (the other shapes are closed-form). */
export interface TorusRayOptions {
  /**
   * Distance (m) at which sphere tracing counts the surface as reached, before Newton refinement.
   * Default 1e-10·(R + r). A ray that passes closer than this to the torus counts as a hit.
   */
  readonly tolerance?: number;
  /** Largest count of sphere-tracing steps (a positive integer). Default 1000. */
  readonly maxSteps?: number;
}

/** Default largest count of sphere-tracing steps for a torus. */
export const DEFAULT_TORUS_RAY_STEPS = 1000;
/** Default torus tracing tolerance, as a fraction of R + r. */
export const DEFAULT_TORUS_RAY_TOLERANCE = 1e-10;

/** A fresh {@link RayHit} for n dimensions (distance −1). */
export function createRayHit(n: number): RayHit {
  checkDimension(n);
  return { distance: -1, point: new Float64Array(n), normal: new Float64Array(n) };
}

// Scratch shared by the ray casts (single-threaded, not re-entrant): the ray in the local frame.
const localO = new Float64Array(MAX_DIMENSIONS);
const localD = new Float64Array(MAX_DIMENSIONS);
const unitD = new Float64Array(MAX_DIMENSIONS);
const worldN = new Float64Array(MAX_DIMENSIONS);
/** Set by each cast: true when the hit at 0 is a start inside the solid. */
let insideStart = false;

/**
 * Casts the ray origin + t·d̂, t in [0, maxDistance], against `shape` at pose (x, M). Returns the
 * distance of the first hit or −1; on a hit writes outHit (distance, point, normal), on a miss
 * sets outHit.distance = −1 only. Validates every argument first.
 *
 * @param n count of dimensions (2..8).
 * @param shape geometry in its local frame.
 * @param x world position of the local origin (n numbers).
 * @param M rotation, n*n row-major: world = x + M·local (must be orthonormal).
 * @param origin ray start (n numbers, m).
 * @param direction ray direction (n numbers, nonzero; need not be unit).
 * @param maxDistance longest distance searched (m, >= 0; +Infinity allowed).
 * @param outHit receives the hit.
 * @param torus settings of the torus trace.
 */
export function rayCastShape(
  n: number,
  shape: QueryShape,
  x: ArrayLike<number>,
  M: ArrayLike<number>,
  origin: ArrayLike<number>,
  direction: ArrayLike<number>,
  maxDistance: number,
  outHit: RayHit,
  torus: TorusRayOptions = {},
): number {
  checkDimension(n);
  checkShape(shape, n);
  checkPose(n, x, M);
  checkFiniteArray(origin, n, 'origin');
  checkDirection(direction, n, 'direction');
  checkNumber(maxDistance, 'maxDistance', 0, true);
  checkRayHit(outHit, n);
  if (torus === null || typeof torus !== 'object') throw new TypeError('torus must be an options object');
  const tolerance =
    torus.tolerance ?? (shape.kind === 'torus' ? DEFAULT_TORUS_RAY_TOLERANCE * (shape.majorRadius + shape.minorRadius) : 0);
  checkNumber(tolerance, 'torus.tolerance', 0);
  if (shape.kind === 'torus' && !(tolerance > 0)) throw new RangeError('torus.tolerance must be > 0');
  const maxSteps = torus.maxSteps ?? DEFAULT_TORUS_RAY_STEPS;
  if (!Number.isInteger(maxSteps) || maxSteps < 1) {
    throw new RangeError(`torus.maxSteps must be a positive integer, got ${maxSteps}`);
  }
  let s = 0;
  for (let k = 0; k < n; k += 1) s += direction[k]! * direction[k]!;
  const inv = 1 / Math.sqrt(s);
  for (let k = 0; k < n; k += 1) unitD[k] = direction[k]! * inv;
  return rayCastShapeUnchecked(n, shape, x, M, origin, unitD, maxDistance, outHit, tolerance, maxSteps);
}

/**
 * {@link rayCastShape} without argument checks, for data already validated. `unitDirection` must
 * have length 1; `tolerance` and `maxSteps` are the torus settings (absolute, m). Works in
 * module-level scratch arrays and creates no arrays or objects.
 */
export function rayCastShapeUnchecked(
  n: number,
  shape: QueryShape,
  x: ArrayLike<number>,
  M: ArrayLike<number>,
  origin: ArrayLike<number>,
  unitDirection: ArrayLike<number>,
  maxDistance: number,
  outHit: RayHit,
  tolerance: number,
  maxSteps: number,
): number {
  let t: number;
  switch (shape.kind) {
    case 'sphere':
      t = raySphere(n, shape.radius, x, origin, unitDirection, maxDistance, outHit);
      break;
    case 'halfspace':
      t = rayHalfSpace(n, shape.normal, shape.offset, x, M, origin, unitDirection, maxDistance, outHit);
      break;
    case 'box':
      toLocal(n, x, M, origin, unitDirection);
      t = rayBoxLocal(n, shape.halfExtents, M, maxDistance, outHit);
      break;
    case 'mesh':
      toLocal(n, x, M, origin, unitDirection);
      t = rayMeshLocal(n, shape, M, maxDistance, outHit);
      break;
    case 'torus':
      toLocal(n, x, M, origin, unitDirection);
      t = rayTorusLocal(n, shape, M, maxDistance, outHit, tolerance, maxSteps);
      break;
    case 'capsule':
      toLocal(n, x, M, origin, unitDirection);
      t = rayCapsuleLocal(n, shape, M, maxDistance, outHit);
      break;
    default:
      t = -1; // no other kind reaches here
  }
  outHit.distance = t;
  if (t < 0) return -1;
  const p = outHit.point;
  for (let k = 0; k < n; k += 1) p[k] = origin[k]! + t * unitDirection[k]!;
  if (t === 0 && insideStart) {
    for (let k = 0; k < n; k += 1) outHit.normal[k] = -unitDirection[k]!;
  }
  return t;
}

function raySphere(
  n: number,
  radius: number,
  x: ArrayLike<number>,
  o: ArrayLike<number>,
  d: ArrayLike<number>,
  maxDistance: number,
  hit: RayHit,
): number {
  insideStart = false;
  let b = 0;
  let c = 0;
  for (let k = 0; k < n; k += 1) {
    const w = o[k]! - x[k]!;
    b += w * d[k]!;
    c += w * w;
  }
  c -= radius * radius;
  if (c <= 0) {
    insideStart = true;
    return 0;
  }
  // Outside and moving away: both roots are behind.
  if (b >= 0) return -1;
  const disc = b * b - c;
  if (disc < 0) return -1;
  // t = −b − √disc written as c / (−b + √disc): no cancellation when the ray grazes.
  const t = c / (-b + Math.sqrt(disc));
  if (t > maxDistance) return -1;
  const nrm = hit.normal;
  for (let k = 0; k < n; k += 1) nrm[k] = (o[k]! + t * d[k]! - x[k]!) / radius;
  normalize(n, nrm);
  return t;
}

function rayHalfSpace(
  n: number,
  normal: ArrayLike<number>,
  offset: number,
  x: ArrayLike<number>,
  M: ArrayLike<number>,
  o: ArrayLike<number>,
  d: ArrayLike<number>,
  maxDistance: number,
  hit: RayHit,
): number {
  insideStart = false;
  const N = worldN;
  let len = 0;
  for (let k = 0; k < n; k += 1) {
    let w = 0;
    for (let c = 0; c < n; c += 1) w += M[k * n + c]! * normal[c]!;
    N[k] = w;
  }
  for (let c = 0; c < n; c += 1) len += normal[c]! * normal[c]!;
  len = Math.sqrt(len);
  // World plane: N·p <= offset + N·x (N = M·normal), divided through by |normal|.
  let s = -offset;
  let den = 0;
  for (let k = 0; k < n; k += 1) {
    s += N[k]! * (o[k]! - x[k]!);
    den += N[k]! * d[k]!;
  }
  s /= len;
  den /= len;
  if (s <= 0) {
    insideStart = true;
    return 0;
  }
  if (den >= 0) return -1;
  const t = -s / den;
  if (t > maxDistance) return -1;
  for (let k = 0; k < n; k += 1) hit.normal[k] = N[k]! / len;
  return t;
}

/** Writes the ray in the shape's local frame into localO / localD: Mᵀ(o − x), Mᵀd. */
function toLocal(n: number, x: ArrayLike<number>, M: ArrayLike<number>, o: ArrayLike<number>, d: ArrayLike<number>): void {
  for (let c = 0; c < n; c += 1) {
    let po = 0;
    let pd = 0;
    for (let k = 0; k < n; k += 1) {
      const m = M[k * n + c]!;
      po += m * (o[k]! - x[k]!);
      pd += m * d[k]!;
    }
    localO[c] = po;
    localD[c] = pd;
  }
}

/** hit.normal = M · (local vector v), normalised. */
function normalToWorld(n: number, M: ArrayLike<number>, v: ArrayLike<number>, vOff: number, scale: number, hit: RayHit): void {
  const out = hit.normal;
  for (let k = 0; k < n; k += 1) {
    let w = 0;
    for (let c = 0; c < n; c += 1) w += M[k * n + c]! * v[vOff + c]!;
    out[k] = w * scale;
  }
  normalize(n, out);
}

function rayBoxLocal(n: number, a: ArrayLike<number>, M: ArrayLike<number>, maxDistance: number, hit: RayHit): number {
  insideStart = false;
  let tEnter = -Infinity;
  let tExit = Infinity;
  let axis = -1;
  let side = 0;
  for (let k = 0; k < n; k += 1) {
    const o = localO[k]!;
    const d = localD[k]!;
    const h = a[k]!;
    if (d === 0) {
      if (o < -h || o > h) return -1;
      continue;
    }
    const t1 = (-h - o) / d;
    const t2 = (h - o) / d;
    const near = t1 < t2 ? t1 : t2;
    const far = t1 < t2 ? t2 : t1;
    if (near > tEnter) {
      tEnter = near;
      axis = k;
      // Entering through the face the ray points into: −e_k face when d > 0.
      side = d > 0 ? -1 : 1;
    }
    if (far < tExit) tExit = far;
    if (tEnter > tExit) return -1;
  }
  if (tExit < 0) return -1;
  if (tEnter <= 0) {
    insideStart = true;
    return 0;
  }
  if (tEnter > maxDistance) return -1;
  const out = hit.normal;
  for (let k = 0; k < n; k += 1) out[k] = side * M[k * n + axis]!;
  return tEnter;
}

function rayMeshLocal(n: number, mesh: ConvexMeshGeometry, M: ArrayLike<number>, maxDistance: number, hit: RayHit): number {
  insideStart = false;
  const normals = mesh.facetNormals;
  const offsets = mesh.facetOffsets;
  const count = offsets.length;
  let tEnter = -Infinity;
  let tExit = Infinity;
  let facet = -1;
  for (let f = 0; f < count; f += 1) {
    let no = 0;
    let nd = 0;
    const b = f * n;
    for (let k = 0; k < n; k += 1) {
      no += normals[b + k]! * localO[k]!;
      nd += normals[b + k]! * localD[k]!;
    }
    const gap = offsets[f]! - no; // >= 0: origin on the inner side of this facet
    if (nd === 0) {
      if (gap < 0) return -1;
      continue;
    }
    const t = gap / nd;
    if (nd < 0) {
      if (t > tEnter) {
        tEnter = t;
        facet = f;
      }
    } else if (t < tExit) {
      tExit = t;
    }
    if (tEnter > tExit) return -1;
  }
  if (tExit < 0) return -1;
  if (tEnter <= 0 || facet < 0) {
    insideStart = true;
    return 0;
  }
  if (tEnter > maxDistance) return -1;
  normalToWorld(n, M, normals, facet * n, 1, hit);
  return tEnter;
}

function rayTorusLocal(
  n: number,
  torus: TorusGeometry,
  M: ArrayLike<number>,
  maxDistance: number,
  hit: RayHit,
  tolerance: number,
  maxSteps: number,
): number {
  insideStart = false;
  if (torusDistance(n, torus, localO, null) <= 0) {
    insideStart = true;
    return 0;
  }
  const t = torusRayTrace(n, torus, localO, localD, maxDistance, tolerance, maxSteps, localN);
  if (t < 0) return -1;
  normalToWorld(n, M, localN, 0, 1, hit);
  return t;
}

const localN = new Float64Array(MAX_DIMENSIONS);

function rayCapsuleLocal(n: number, capsule: CapsuleGeometry, M: ArrayLike<number>, maxDistance: number, hit: RayHit): number {
  insideStart = false;
  const t = capsuleRayLocal(n, capsule.halfHeight, capsule.radius, localO, localD, maxDistance, localN);
  if (t === CAPSULE_RAY_INSIDE) {
    insideStart = true;
    return 0;
  }
  if (t < 0) return -1;
  normalToWorld(n, M, localN, 0, 1, hit);
  return t;
}

function normalize(n: number, v: Float64Array): void {
  let s = 0;
  for (let k = 0; k < n; k += 1) s += v[k]! * v[k]!;
  if (s === 0) return;
  const inv = 1 / Math.sqrt(s);
  for (let k = 0; k < n; k += 1) v[k] = v[k]! * inv;
}

function checkRayHit(hit: unknown, n: number): void {
  if (hit === null || typeof hit !== 'object') throw new TypeError('outHit must be a RayHit object');
  const h = hit as RayHit;
  if (!(h.point instanceof Float64Array) || h.point.length !== n) {
    throw new TypeError(`outHit.point must be a Float64Array of length ${n}`);
  }
  if (!(h.normal instanceof Float64Array) || h.normal.length !== n) {
    throw new TypeError(`outHit.normal must be a Float64Array of length ${n}`);
  }
}
