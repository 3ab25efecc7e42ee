/**
 * The narrowphase contract: poses, contact manifolds and the pair-collider signature.
 *
 * Everything here is pure geometry on primitive inputs. Nothing depends on a body or a world:
 * the solver computes a pose per body per step and calls the pair functions.
 *
 * **Pose.** A shape is placed by a pose (x, M): world = x + M·local, where M is an n×n
 * row-major rotation and `M[i*n + c]` is component i of the image of local axis c. The local
 * frame is the shape's own frame (for a convex mesh: its principal frame, the one its
 * `vertices` are stored in).
 *
 * **Manifold.** One normal for the whole manifold, unit length, pointing from shape A to shape
 * B. Each point lies on the midpoint between the two surfaces (halfway along the normal between
 * the surface point of A and the surface point of B), so the arms from both bodies are treated
 * alike. Separation is the signed gap along the normal: negative means overlap (the depth),
 * positive a speculative contact closer than the margin. Feature ids name the pair of features
 * that made each point (faces, corners, clip features…) so the solver can match points from one
 * step to the next and warm-start them.
 *
 * @module
 */
import type { ShapeKind } from '../shapes/shape.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';

/** Largest count of dimensions the narrowphase supports. */
export const NARROWPHASE_MAX_DIMENSIONS = 8;

/**
 * Where a shape sits in the world: world = x + M·local.
 * The caller builds M once per body per step (from the rotor) and reuses it for every pair.
 */
export interface Pose {
  /** World position of the shape's local origin (n numbers, m). */
  readonly x: Float64Array;
  /** Rotation, n×n row-major: `M[i*n + c]` = component i of the image of local axis c. Orthonormal, det +1. */
  readonly M: Float64Array;
}

/** A fresh pose at the origin with the identity rotation. Allocates; call at set-up. */
export function createPose(n: number): Pose {
  checkNarrowphaseDimension(n, 'n');
  const M = new Float64Array(n * n);
  for (let i = 0; i < n; i += 1) M[i * n + i] = 1;
  return { x: new Float64Array(n), M };
}

/**
 * out = Mᵀ (p − x): the world point `p` in the local frame of `pose` (unchecked, no allocation).
 * `out` must not alias `p` or the pose's arrays.
 */
export function pointToLocal(out: Float64Array, n: number, pose: Pose, p: Float64Array): Float64Array {
  const M = pose.M;
  const x = pose.x;
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let i = 0; i < n; i += 1) s += M[i * n + c] * (p[i] - x[i]);
    out[c] = s;
  }
  return out;
}

/**
 * A contact manifold between two shapes, preallocated and reused: the pair functions overwrite
 * it and allocate nothing. Only the first `count` entries of the per-point arrays are meaningful.
 */
export interface Manifold {
  /** Count of dimensions. */
  readonly n: number;
  /** Most points this manifold can hold. */
  readonly capacity: number;
  /** Count of valid points (0..capacity). */
  count: number;
  /** Unit normal from A to B (n numbers). Valid when count > 0. */
  readonly normal: Float64Array;
  /** Points, flat: point p is points[p*n .. p*n + n), world coordinates (m), midway between the surfaces. */
  readonly points: Float64Array;
  /** Signed gap of each point along the normal (m): negative = overlap. */
  readonly separations: Float64Array;
  /** Feature id of each point, stable from step to step while the same features touch. */
  readonly ids: Uint32Array;
}

/**
 * The bound on the points a pair manifold keeps in n dimensions:
 * n = 2: 2 (a segment of contact needs its two ends); n = 3: 4 (as Box2D, Bullet and Rapier: a
 * quadrilateral spans a resting face); n >= 4: 2^(n−1), at most 32 — every corner of a box face
 * (8 in 4D, 16 in 5D, 32 in 6D).
 *
 * Why whole faces: a face resting on a face needs at least n affinely independent points to
 * support it, and a reduced set (first tried: max(8, 2(n − 1)), 10 of the 32 corners in 6D)
 * does support it but unevenly, so the solver's impulses rock the box and the rocking changes
 * which corners the reduction keeps: a 6D box never came to rest (|v| ~ 2e-3 after 5 s) and a
 * 6D stack of 5 drifted 2 cm. With the whole face it rests (|v| < 1e-15) and the stack stands
 * (3e-4 m in 10 s), at about 1.5× the 6D cost. The reduction (deepest, then farthest points) still
 * applies past 32 points (n = 7, 8) and to the clipper's larger candidate sets.
 */
export function maxManifoldPoints(n: number): number {
  checkNarrowphaseDimension(n, 'n');
  return n === 2 ? 2 : n === 3 ? 4 : Math.min(32, 2 ** (n - 1));
}

/**
 * A fresh manifold for n dimensions holding at most `capacity` points
 * (default {@link maxManifoldPoints}(n)). Allocates; call once per contact pair slot.
 *
 * @throws TypeError when n or capacity is not an integer; RangeError when n is outside 2..8 or
 *   capacity < 1.
 */
export function createManifold(n: number, capacity?: number): Manifold {
  checkNarrowphaseDimension(n, 'n');
  const cap = capacity === undefined ? maxManifoldPoints(n) : capacity;
  if (typeof cap !== 'number' || !Number.isInteger(cap)) {
    throw new TypeError(`createManifold: 'capacity' must be an integer count of points, got ${String(cap)}`);
  }
  if (cap < 1) throw new RangeError(`createManifold: 'capacity' must be >= 1, got ${cap}`);
  return manifoldIn(n, cap, new ArrayBuffer(manifoldBytes(n, cap)), 0);
}

/**
 * @internal Bytes of one manifold's numbers side by side (normal, separations, points, ids),
 * padded to 8 so that manifolds laid one after another stay aligned.
 */
export function manifoldBytes(n: number, capacity: number): number {
  return (n + capacity + capacity * n) * 8 + capacity * 4 + 4 * (capacity & 1);
}

/**
 * @internal A manifold whose numbers are views of `buffer` from byte `at` (see manifoldBytes):
 * the contact set lays a block of slots' manifolds in one buffer, so a slot's numbers share cache
 * lines. No checks: the callers pass what they computed.
 */
export function manifoldIn(n: number, capacity: number, buffer: ArrayBuffer, at: number): Manifold {
  return {
    n,
    capacity,
    count: 0,
    normal: new Float64Array(buffer, at, n),
    points: new Float64Array(buffer, at + (n + capacity) * 8, capacity * n),
    separations: new Float64Array(buffer, at + n * 8, capacity),
    ids: new Uint32Array(buffer, at + (n + capacity + capacity * n) * 8, capacity),
  };
}

/**
 * Anything the dispatch can collide: a shape of a known kind that may carry its table of pair
 * colliders. The engine's shapes satisfy this; the geometry each collider reads is described in
 * narrowphase-shapes.ts.
 */
export interface CollidableShape {
  readonly kind: ShapeKind;
  readonly colliders?: ColliderTable;
}

/**
 * A pair collider: fills `out` with the contacts between `shapeA` at `poseA` and `shapeB` at
 * `poseB` (normal from A to B) and returns whether any point has separation < `margin`.
 * On false, `out.count` is 0. `margin` (m, >= 0) is the speculative contact distance (the
 * engine's contactMargin). Unchecked hot-path kernel: the caller guarantees that the shapes are
 * of the kinds the table promises, that poses and `out` have n-sized data and that `scratch`
 * was made for n. Allocates nothing.
 */
export type PairCollider = (
  out: Manifold,
  n: number,
  shapeA: CollidableShape,
  poseA: Pose,
  shapeB: CollidableShape,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
) => boolean;

/**
 * The pair colliders a shape kind owns, keyed by the other shape's kind. The entry under kind K
 * of shape S's table is called with S as shape A and the K-shape as shape B.
 * Each pair lives in the table of only one of its two kinds (the later one in the order
 * halfspace, sphere, box, torus, mesh), so a scene that never builds a torus never loads torus
 * collision code.
 */
export type ColliderTable = Readonly<Partial<Record<ShapeKind, PairCollider>>>;

/**
 * Checks that `n` is an integer count of dimensions the narrowphase supports (2..8).
 * @throws TypeError when not an integer; RangeError when out of range.
 */
export function checkNarrowphaseDimension(n: unknown, name: string): asserts n is number {
  if (typeof n !== 'number' || !Number.isInteger(n)) {
    throw new TypeError(`'${name}' must be an integer count of dimensions, got ${String(n)}`);
  }
  if (n < 2 || n > NARROWPHASE_MAX_DIMENSIONS) {
    throw new RangeError(`'${name}' must be between 2 and ${NARROWPHASE_MAX_DIMENSIONS}, got ${n}`);
  }
}
