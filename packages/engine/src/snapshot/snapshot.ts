/**
 * Snapshots of a world as functions, not World methods: a scene that never saves carries none of
 * this code in its bundle (docs/architecture.md).
 *
 * @module
 */
import { checkWorld } from '../world.js';
import type { WorldBase } from '../world.js';
import { World } from '../world-nd.js';
import { readWorldSnapshot } from './read-world.js';
import { writeWorldSnapshot } from './write-world.js';
import { worldParts } from './world-parts.js';

/**
 * The whole state a step reads, as bytes: dimension, parameters, gravity, time and step count,
 * the shapes, every body (its full state, mass, material, sleep state), every joint (options,
 * anchors, accumulated impulses), the contacts with their warm-start impulses and cached
 * manifolds, the broadphase's pair bookkeeping and the end events pending for the next step.
 * {@link restoreWorld} rebuilds a world from it that continues bit-identically: every Float64 of
 * every body after any number of steps is the same as the original's. Taking a snapshot changes
 * nothing in the world. The array owns its whole buffer (byteOffset 0, exact length), so it can
 * be transferred to a worker as it is.
 *
 * Not saved: listeners (functions), and the events of the last step (`contactEvents` of a
 * restored world is empty until its first step).
 *
 * @example
 * ```ts
 * const bytes = snapshotWorld(world);
 * const copy = restoreWorld(bytes); // steps exactly as `world` does from here
 * ```
 * @throws TypeError if `world` is not a World; Error if a body has a shape kind the snapshot code
 *   does not know (it names the kind).
 */
export function snapshotWorld(world: WorldBase): Uint8Array {
  const w = checkWorld('snapshotWorld', world);
  return writeWorldSnapshot(w, worldParts(w));
}

/**
 * Rebuilds a world from the bytes of {@link snapshotWorld}. Its bodies and joints are new
 * objects, in the same order as in the original: `restored.bodies[i]` is the copy of
 * `original.bodies[i]`, `restored.constraints[j]` of `original.constraints[j]` (ids differ: they
 * are unique per process).
 *
 * @throws TypeError if `bytes` is not a Uint8Array; RangeError, naming 'bytes', if it is
 *   truncated, foreign, of another format version, damaged, or inconsistent.
 */
export function restoreWorld(bytes: Uint8Array): World {
  return readWorldSnapshot(bytes, (options) => new World(options));
}
