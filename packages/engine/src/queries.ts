/**
 * Questions asked of a world between steps: the first body a ray hits, and the bodies in a box.
 * Functions, not World methods, so that a scene that asks none carries no ray code in its bundle
 * (docs/architecture.md).
 *
 * @module
 */
import { checkNumber, checkVector } from '@physin/algebra';
import type { Body } from './body.js';
import { createIdList, createRayCastResult, queryOverlap, rayCastClosest } from './collision/query.js';
import type { RayCastSource } from './collision/query.js';
import type { QueryShape } from './collision/query-shapes.js';
import { checkWorld } from './world.js';
import type { WorldBase } from './world.js';
import type { Broadphase } from './collision/broadphase.js';
import type { Pose } from './collision/manifold.js';
import type { ProxyTables } from './contacts/contact-set.js';
import type { AwakeSet } from './solver/islands.js';

/** The first hit of {@link castRay}. */
export interface WorldRayHit {
  /** The body hit. */
  readonly body: Body;
  /** Where the ray meets its surface (world, n numbers). */
  readonly point: Float64Array;
  /** The outward unit normal of the surface there (n numbers). */
  readonly normal: Float64Array;
  /** Distance from the origin along the normalised direction (m). */
  readonly distance: number;
  /** Which part of the body was hit: its index in the body's compound (`Compound`), 0 for a body of one shape. */
  readonly part: number;
}

/**
 * The first body of `world` hit by the ray origin + t·d̂, t in [0, maxDistance] (d̂ = direction
 * normalised), or null. Every shape counts as solid: a ray that starts inside a body hits it at
 * distance 0. Sleeping bodies are found and stay asleep. A user-level query: it allocates its
 * result.
 *
 * @example
 * ```ts
 * const hit = castRay(world, [0, 5, 0], [0, -1, 0], 10);
 * if (hit !== null) console.log(hit.body.label, hit.distance);
 * ```
 * @throws TypeError / RangeError for a world that is not a World, an origin or direction of the
 *   wrong length or non-finite, a zero direction, or a negative or non-finite maxDistance.
 */
export function castRay(
  world: WorldBase,
  origin: ArrayLike<number>,
  direction: ArrayLike<number>,
  maxDistance: number,
): WorldRayHit | null {
  const fn = 'castRay';
  const w = checkWorld(fn, world);
  checkVector(w.D, 'origin', origin, fn);
  checkVector(w.D, 'direction', direction, fn);
  let len = 0;
  for (let i = 0; i < w.n; i += 1) len += direction[i]! * direction[i]!;
  if (!(len > 0)) throw new RangeError(`${fn}: argument 'direction' must be a non-zero vector`);
  checkNumber('maxDistance', maxDistance, fn);
  if (!(maxDistance >= 0))
    throw new RangeError(`${fn}: argument 'maxDistance' must be a finite number >= 0 (m), got ${maxDistance}`);
  const { broadphase, bodyOfProxy, shapeOfProxy, poseOfProxy, partOfProxy } = queryParts(w);
  // Per proxy: a body's shape, or one part of a compound body, at its own pose.
  const source: RayCastSource = {
    shapeOf: (id) => shapeOfProxy[id] as unknown as QueryShape,
    positionOf: (id) => poseOfProxy[id]!.x,
    rotationOf: (id) => poseOfProxy[id]!.M,
  };
  const out = createRayCastResult(w.n);
  const id = rayCastClosest(broadphase, source, origin, direction, maxDistance, out);
  if (id < 0) return null;
  return { body: bodyOfProxy[id]!, point: out.point, normal: out.normal, distance: out.distance, part: partOfProxy[id]! };
}

/**
 * The bodies of `world` whose bounding boxes overlap the box [min, max] (closed intervals;
 * half-spaces when the box reaches their solid side), in the order they were added. Sleeping
 * bodies count.
 *
 * @throws TypeError / RangeError for a world that is not a World, bounds of the wrong length,
 *   non-finite, or min > max.
 */
export function queryBox(world: WorldBase, min: ArrayLike<number>, max: ArrayLike<number>): Body[] {
  const fn = 'queryBox';
  const w = checkWorld(fn, world);
  checkVector(w.D, 'min', min, fn);
  checkVector(w.D, 'max', max, fn);
  for (let i = 0; i < w.n; i += 1) {
    if (min[i]! > max[i]!)
      throw new RangeError(`${fn}: argument 'min' must be <= 'max' on every axis (axis ${i}: ${min[i]} > ${max[i]})`);
  }
  const { broadphase, bodyOfProxy } = queryParts(w);
  const list = createIdList();
  queryOverlap(broadphase, min, max, list);
  const found: Body[] = [];
  // A compound body is found once, however many of its parts' boxes meet the box.
  const seen = new Set<Body>();
  for (let i = 0; i < list.count; i += 1) {
    const body = bodyOfProxy[list.ids[i]!]!;
    if (seen.has(body)) continue;
    seen.add(body);
    found.push(body);
  }
  found.sort((a, b) => a.worldIndex - b.worldIndex);
  return found;
}

/** What the queries read of a world (its private parts; see queryParts). */
interface WorldQueryParts {
  readonly awake: AwakeSet;
  boundsStale: boolean;
  readonly reach: Float64Array;
  readonly broadphase: Broadphase;
  readonly bodyOfProxy: readonly (Body | null)[];
  readonly proxyTables: ProxyTables;
  compact(): void;
  lazyPoses: boolean;
  readonly bodyList: readonly Body[];
  ensurePose(body: Body): void;
  updatePose(body: Body): void;
  moveProxy(body: Body): void;
}

/**
 * @internal The broadphase of `world` with every box brought up to the bodies' poses (the step leaves the
 * boxes of the last sub-step), and the body, shape, pose and part of each proxy id. A function,
 * not a World method, so that a world without queries does not carry it.
 */
export function queryParts(world: WorldBase): {
  readonly broadphase: Broadphase;
  readonly bodyOfProxy: readonly (Body | null)[];
  readonly shapeOfProxy: ProxyTables['shape'];
  readonly poseOfProxy: readonly (Pose | null)[];
  readonly partOfProxy: readonly number[];
} {
  const w = world as unknown as WorldQueryParts;
  w.compact();
  const awake = w.awake;
  if (w.boundsStale || awake.movedCount !== 0) {
    awake.sort();
    for (let i = 0; i < awake.movedCount; i += 1) {
      const body = awake.moved[i]!;
      if (!body.poseDirty || body.worldIndex < 0) continue;
      w.updatePose(body);
      body.poseDirty = false;
      w.reach[body.worldIndex] = 0;
      w.moveProxy(body);
    }
    awake.clearMoved();
    if (w.boundsStale) {
      for (let b = 0; b < awake.count; b += 1) {
        const body = awake.list[b]!;
        if (body.poseDirty) {
          w.updatePose(body);
          body.poseDirty = false;
        }
        w.reach[body.worldIndex] = 0;
        w.moveProxy(body);
      }
    }
    w.boundsStale = false;
  }
  // Every body gets its pose: a query reads any proxy's (after the poses of bodies moved by hand
  // were refreshed above, so a pose made now is the record's).
  if (w.lazyPoses) for (const body of w.bodyList) w.ensurePose(body);
  w.lazyPoses = false;
  const t = w.proxyTables;
  return {
    broadphase: w.broadphase,
    bodyOfProxy: w.bodyOfProxy,
    shapeOfProxy: t.shape,
    poseOfProxy: t.pose,
    partOfProxy: t.part,
  };
}
