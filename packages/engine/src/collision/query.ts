/**
 * World-level spatial queries over a broadphase: overlap by bounding box, and the closest hit of
 * a ray against the posed shapes of the proxies. The world wraps these with its bodies.
 */
import type { Broadphase, ProxyVisitor } from './broadphase.js';
import type { BroadphaseBase } from './broadphase-base.js';
import { broadphaseQueryBox, broadphaseRayCast } from './broadphase-queries.js';
import { checkDirection, checkFiniteArray, checkNumber } from './query-checks.js';
import type { QueryShape } from './query-shapes.js';
import { DEFAULT_TORUS_RAY_STEPS, DEFAULT_TORUS_RAY_TOLERANCE, rayCastShapeUnchecked } from './raycast.js';
import type { RayHit, TorusRayOptions } from './raycast.js';

/** A growable list of proxy ids: ids[0 .. count). */
export interface IdList {
  ids: Int32Array;
  count: number;
}

/** A fresh, empty {@link IdList}. */
export function createIdList(capacity = 16): IdList {
  if (!Number.isInteger(capacity) || capacity < 1) {
    throw new RangeError(`capacity must be a positive integer, got ${capacity}`);
  }
  return { ids: new Int32Array(capacity), count: 0 };
}

/**
 * The proxies whose bounds overlap the box [min, max] (closed intervals): box proxies by their
 * tight bounds (the bounds last given to the broadphase), half-spaces when the box reaches their
 * solid side. With an {@link IdList}, fills it with the ids in ascending order; with a callback,
 * calls it per id in unspecified order (return false to stop). Returns the count found.
 */
export function queryOverlap(
  broadphase: Broadphase,
  min: ArrayLike<number>,
  max: ArrayLike<number>,
  out: IdList | ProxyVisitor,
): number {
  if (typeof out === 'function') {
    let count = 0;
    broadphaseQueryBox(broadphase as BroadphaseBase, min, max, (id) => {
      count += 1;
      return out(id);
    });
    return count;
  }
  if (out === null || typeof out !== 'object' || !(out.ids instanceof Int32Array)) {
    throw new TypeError('out must be an IdList or a callback');
  }
  out.count = 0;
  broadphaseQueryBox(broadphase as BroadphaseBase, min, max, (id) => {
    if (out.count === out.ids.length) {
      const grown = new Int32Array(out.ids.length * 2);
      grown.set(out.ids);
      out.ids = grown;
    }
    out.ids[out.count++] = id;
  });
  out.ids.subarray(0, out.count).sort();
  return out.count;
}

/** Where the shapes of the proxies are: the world supplies these per proxy id. */
export interface RayCastSource {
  /** The shape of proxy `id`. */
  shapeOf(id: number): QueryShape;
  /** World position of the shape's local origin (n numbers). */
  positionOf(id: number): ArrayLike<number>;
  /** World rotation of the shape, n*n row-major (world = x + M·local). */
  rotationOf(id: number): ArrayLike<number>;
}

/** A ray hit that also names the proxy hit. */
export interface RayCastResult extends RayHit {
  /** Proxy id of the shape hit, or −1 after a miss. */
  id: number;
}

/** A fresh {@link RayCastResult} for n dimensions (no hit). */
export function createRayCastResult(n: number): RayCastResult {
  return { id: -1, distance: -1, point: new Float64Array(n), normal: new Float64Array(n) };
}

/**
 * Casts the ray origin + t·d̂, t in [0, maxDistance], against every proxy's shape and keeps the
 * closest hit (ties go to the smaller id, so the answer does not depend on the tree's shape).
 * The broadphase prunes with the proxies' boxes; each candidate is cast exactly with
 * `rayCastShape`. Returns the id hit, or −1 (then out.id = −1 and out.distance = −1).
 * Shapes whose ray starts inside count as hit at distance 0. A user-level query: it allocates a
 * few small objects per call, so do not call it from the step.
 */
export function rayCastClosest(
  broadphase: Broadphase,
  source: RayCastSource,
  origin: ArrayLike<number>,
  direction: ArrayLike<number>,
  maxDistance: number,
  out: RayCastResult,
  torus: TorusRayOptions = {},
): number {
  const n = broadphase.n;
  checkFiniteArray(origin, n, 'origin');
  checkDirection(direction, n, 'direction');
  checkNumber(maxDistance, 'maxDistance', 0, true);
  if (
    out === null ||
    typeof out !== 'object' ||
    !(out.point instanceof Float64Array) ||
    out.point.length !== n ||
    !(out.normal instanceof Float64Array) ||
    out.normal.length !== n
  ) {
    throw new TypeError(`out must be a RayCastResult with point and normal of length ${n}`);
  }
  if (torus === null || typeof torus !== 'object') throw new TypeError('torus must be an options object');
  if (torus.tolerance !== undefined) {
    checkNumber(torus.tolerance, 'torus.tolerance', 0);
    if (!(torus.tolerance > 0)) throw new RangeError('torus.tolerance must be > 0');
  }
  const maxSteps = torus.maxSteps ?? DEFAULT_TORUS_RAY_STEPS;
  if (!Number.isInteger(maxSteps) || maxSteps < 1) {
    throw new RangeError(`torus.maxSteps must be a positive integer, got ${maxSteps}`);
  }
  let s = 0;
  for (let k = 0; k < n; k += 1) s += direction[k]! * direction[k]!;
  const inv = 1 / Math.sqrt(s);
  const d = new Float64Array(n);
  for (let k = 0; k < n; k += 1) d[k] = direction[k]! * inv;
  const scratch: RayHit = { distance: -1, point: new Float64Array(n), normal: new Float64Array(n) };
  out.id = -1;
  out.distance = -1;
  broadphaseRayCast(broadphase as BroadphaseBase, origin, d, maxDistance, (id, limit) => {
    const shape = source.shapeOf(id);
    const tol =
      torus.tolerance ?? (shape.kind === 'torus' ? DEFAULT_TORUS_RAY_TOLERANCE * (shape.majorRadius + shape.minorRadius) : 0);
    const t = rayCastShapeUnchecked(
      n,
      shape,
      source.positionOf(id),
      source.rotationOf(id),
      origin,
      d,
      limit,
      scratch,
      tol,
      maxSteps,
    );
    if (t < 0) return -1;
    if (out.id < 0 || t < out.distance || (t === out.distance && id < out.id)) {
      out.id = id;
      out.distance = t;
      out.point.set(scratch.point);
      out.normal.set(scratch.normal);
    }
    return t;
  });
  return out.id;
}
