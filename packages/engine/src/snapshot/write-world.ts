/**
 * `snapshotWorld(world)`: the world's state in the order the reader rebuilds it.
 *
 * Payload, after the header of format.ts: n; the parameters by name; gravity; time and step
 * count; whether the broadphase boxes lag the poses; the shape table (each distinct shape object
 * once); the bodies in world order; the bodies that left the world but are still named by a
 * pending end event; the joints in world order; each body's reach of the last sub-step; the
 * broadphase; the contacts; the pending end events.
 *
 * Reads only: taking a snapshot changes nothing in the world (no pose refresh, no query).
 *
 * @module
 */
import type { Body } from '../body.js';
import type { Shape } from '../shapes/shape.js';
import type { WorldBase as World } from '../world.js';
import { writeBody } from './bodies.js';
import { writeBroadphase } from './broadphase.js';
import { writeContacts, writePendingEnds } from './contacts.js';
import { writeJoint } from './joints.js';
import { writeShape } from './shapes.js';
import type { WorldParts } from './world-parts.js';
import { SnapshotWriter } from './writer.js';

/** Param value tags. */
export const PARAM_NUMBER = 0;
export const PARAM_BOOLEAN = 1;

/** The bytes of `world` (see the module). */
export function writeWorldSnapshot(world: World, parts: WorldParts): Uint8Array {
  const D = world.D;
  const n = D.n;
  const bodies = world.bodies;
  const joints = world.constraints;
  const w = new SnapshotWriter(1024 + bodies.length * 64 * (n + D.r + 2 * D.k + n * n));
  w.u8(n);

  const params = world.params as unknown as Record<string, unknown>;
  const names = Object.keys(params);
  w.u32(names.length);
  for (const name of names) {
    const value = params[name];
    w.string(name);
    if (typeof value === 'boolean') {
      w.u8(PARAM_BOOLEAN);
      w.bool(value);
    } else if (typeof value === 'number') {
      w.u8(PARAM_NUMBER);
      w.f64(value);
    } else {
      throw new Error(
        `World.snapshot: parameter '${name}' is a ${typeof value}; snapshots store numbers and booleans (update packages/engine/src/snapshot/write-world.ts)`,
      );
    }
  }
  w.f64s(world.gravity, 0, n);
  w.f64(parts.clock[0]!);
  w.f64(parts.clock[1]!);
  w.f64(parts.clock[2]!);
  w.bool(parts.boundsStale);

  // Bodies that left the world but are still named by a pending end event.
  const pending = parts.events.pendingEnds();
  const departed: Body[] = [];
  const departedIndex = new Map<Body, number>();
  for (let i = 0; i < pending.count; i += 1) {
    for (const body of [pending.a[i]!, pending.b[i]!]) {
      if (bodies[body.worldIndex] === body || departedIndex.has(body)) continue;
      departedIndex.set(body, departed.length);
      departed.push(body);
    }
  }

  const shapes: Shape[] = [];
  const shapeIndex = new Map<Shape, number>();
  for (const body of [...bodies, ...departed]) {
    if (shapeIndex.has(body.shape)) continue;
    shapeIndex.set(body.shape, shapes.length);
    shapes.push(body.shape);
  }
  w.u32(shapes.length);
  for (const shape of shapes) writeShape(w, D, shape);

  w.u32(bodies.length);
  for (const body of bodies) writeBody(w, D, body, shapeIndex.get(body.shape)!);
  w.u32(departed.length);
  for (const body of departed) writeBody(w, D, body, shapeIndex.get(body.shape)!);

  const indexOf = (body: Body): number => {
    if (bodies[body.worldIndex] !== body) throw new Error(`World.snapshot: ${body.label} is referenced but not in the world`);
    return body.worldIndex;
  };
  w.u32(joints.length);
  for (const joint of joints) writeJoint(w, D, joint, indexOf);

  w.f64s(parts.reach, 0, bodies.length);
  writeBroadphase(w, parts.broadphase);
  // The proxy ids of each compound body's parts (the broadphase's ids, as they are).
  for (const body of bodies) {
    const ids = body.shape.kind === 'compound' ? parts.partProxies[body.proxyId] : null;
    if (ids === null || ids === undefined) continue;
    w.u32(ids.length);
    w.i32s(ids);
  }
  writeContacts(w, D, parts.contacts, indexOf);
  writePendingEnds(w, parts.events, (body) =>
    bodies[body.worldIndex] === body ? body.worldIndex : -1 - departedIndex.get(body)!,
  );
  return w.finish();
}
