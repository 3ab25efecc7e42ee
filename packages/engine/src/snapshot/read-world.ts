/**
 * `restoreWorld(bytes)`: a new world from the bytes of `snapshotWorld(world)`.
 *
 * The world is built through its public calls where they do exactly what the original did (the
 * constructor with the saved dimension, gravity and parameters; addBody in the saved order;
 * addConstraint in the saved order), then every number those calls set on their own (sleep
 * flags and timers, poses, proxy ids, the broadphase, the contacts, the joints' impulses, the
 * clock) is replaced by the saved one. Nothing is recomputed from the saved state, so nothing can
 * round differently: the restored world continues bit-identically.
 *
 * @module
 */
import type { Body } from '../body.js';
import { proxyIsAlive, proxyIsHalfSpace } from '../collision/broadphase-queries.js';
import type { Params } from '../params.js';
import type { Shape } from '../shapes/shape.js';
import type { WorldBase as World, WorldOptions } from '../world.js';
import { applyBodyFlags, readBody } from './bodies.js';
import type { BodyFlags } from './bodies.js';
import { readBroadphase } from './broadphase.js';
import { readContacts, readPendingEnds } from './contacts.js';
import { readJoint } from './joints.js';
import { SnapshotReader } from './reader.js';
import { readShape } from './shapes.js';
import { worldParts } from './world-parts.js';
import { PARAM_BOOLEAN, PARAM_NUMBER } from './write-world.js';

/** Reads a world; `create` is `new World(options)` (passed in so this module imports no World value). */
export function readWorldSnapshot(bytes: Uint8Array, create: (options: WorldOptions) => World): World {
  const r = new SnapshotReader(bytes);
  const n = r.u8();
  if (n < 2 || n > 8) r.fail(`the dimension is ${n}, not in 2..8`);

  const paramCount = r.count('the parameter count', 1024, 6);
  const entries: [string, number | boolean][] = [];
  for (let i = 0; i < paramCount; i += 1) {
    const name = r.string();
    const tag = r.u8();
    if (tag === PARAM_BOOLEAN) entries.push([name, r.bool()]);
    else if (tag === PARAM_NUMBER) entries.push([name, r.f64()]);
    else r.fail(`parameter '${name}' has the unknown tag ${tag}`);
  }
  const params = Object.fromEntries(entries); // own properties only, whatever the names
  const gravity = r.f64s(n);
  const time = r.f64();
  const steps = r.f64();
  const pending = r.f64();
  if (!Number.isFinite(time) || !(Number.isInteger(steps) && steps >= 0) || !Number.isFinite(pending)) {
    r.fail(
      `the clock (time ${time}, steps ${steps}, pending ${pending}) is not a finite time, a step count and a finite remainder`,
    );
  }
  const boundsStale = r.bool();

  let world: World;
  try {
    world = create({ dimensions: n, gravity, params: params as Partial<Params> });
  } catch (error) {
    return r.fail(`its parameters or gravity are refused (${(error as Error).message})`);
  }
  const D = world.D;

  const shapeCount = r.count('the shape count', 1 << 26, 10);
  const shapes: Shape[] = [];
  for (let i = 0; i < shapeCount; i += 1) shapes.push(readShape(r, D));

  const bodyCount = r.count('the body count', 1 << 26, 64);
  const flags: BodyFlags[] = [];
  for (let i = 0; i < bodyCount; i += 1) flags.push(readBody(r, D, shapes));
  const departedCount = r.count('the departed body count', 1 << 26, 64);
  const departed: Body[] = [];
  for (let i = 0; i < departedCount; i += 1) {
    const f = readBody(r, D, shapes);
    applyBodyFlags(D, f);
    departed.push(f.body);
  }
  for (const f of flags) {
    try {
      world.addBody(f.body);
    } catch (error) {
      r.fail(`a body cannot be added (${(error as Error).message})`);
    }
  }
  const bodies = world.bodies;

  const jointCount = r.count('the joint count', 1 << 26, 32);
  const joints = [];
  for (let i = 0; i < jointCount; i += 1) joints.push(readJoint(r, D, bodies));
  for (const p of joints) {
    try {
      world.addConstraint(p.joint);
    } catch (error) {
      r.fail(`a joint cannot be added (${(error as Error).message})`);
    }
    p.finish();
  }
  for (const f of flags) applyBodyFlags(D, f);

  const parts = worldParts(world);
  r.f64s(bodyCount, parts.reach);
  readBroadphase(r, parts.broadphase);
  const bp = parts.broadphase;
  const byProxy = parts.bodyOfProxy;
  parts.clearProxyTables();
  let proxies = 0;
  const partIds: (Int32Array | null)[] = [];
  for (const body of bodies) {
    const compound = body.shape.kind === 'compound';
    // A compound body has one proxy per part (its proxyId is the first part's).
    const ids = compound ? r.i32s(r.count('the part proxy count', 1 << 26, 4)) : null;
    if (ids !== null && (ids.length !== (body.shape as unknown as { partCount: number }).partCount || ids[0] !== body.proxyId))
      r.fail(`${body.label}'s part proxies do not match its compound`);
    partIds.push(ids);
    for (const id of ids ?? [body.proxyId]) {
      if (!proxyIsAlive(bp, id) || byProxy[id] !== undefined)
        r.fail(`${body.label} has the proxy id ${id}, not a live id of its own`);
      if (proxyIsHalfSpace(bp, id) !== (body.shape.kind === 'halfspace'))
        r.fail(`${body.label}'s proxy ${id} is of the wrong kind`);
      byProxy[id] = body;
      proxies += 1;
    }
  }
  bodies.forEach((body, i) => parts.setBodyProxies(body, partIds[i]!));
  for (let id = 0; id < bp.idBound; id += 1) if (byProxy[id] === undefined) byProxy[id] = null;
  if (bp.proxyCount !== proxies) r.fail(`the broadphase has ${bp.proxyCount} live proxies for ${proxies} bodies and parts`);
  readContacts(r, D, parts.contacts, bodies);
  readPendingEnds(r, parts.events, bodies, departed);
  if (!r.done) r.fail('bytes are left after the last field');
  parts.clock[0] = time;
  parts.clock[1] = steps;
  parts.clock[2] = pending;
  parts.setBoundsStale(boundsStale);
  return world;
}
