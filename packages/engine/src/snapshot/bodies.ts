/**
 * Bodies in a snapshot: everything the step reads of a body, written raw (mass, inverse mass,
 * both inertias, the centre-of-mass offset and the whole state record x, R, v, L, w, force,
 * torque as stored), so nothing is recomputed on restore and nothing can round differently.
 *
 * A body is rebuilt with `new Body` (shape, type, mass, material, name) and then given the saved
 * numbers. The flags the world itself sets when a body or joint is added (sleeping, sleep timer,
 * pose, proxy id) are returned apart, for the world reader to put back once the body and its
 * joints are in the world.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { Body, MOTION_DYNAMIC, MOTION_KINEMATIC, MOTION_STATIC } from '../body.js';
import type { BodyType } from '../body.js';
import { createPose } from '../collision/manifold.js';
import type { Shape } from '../shapes/shape.js';
import type { SnapshotReader } from './reader.js';
import type { SnapshotWriter } from './writer.js';

/** What the world sets on addBody / addConstraint and the reader puts back afterwards. */
export interface BodyFlags {
  readonly body: Body;
  readonly hasTorque: boolean;
  readonly sleeping: boolean;
  readonly sleepTimer: number;
  readonly poseDirty: boolean;
  /** The collision pose (x, then the n×n matrix), or null when the body never had one. */
  readonly pose: Float64Array | null;
  readonly proxyId: number;
}

const TYPES: readonly BodyType[] = ['dynamic', 'kinematic', 'static'];

/** Writes one body; `shapeIndex` is its shape's index in the snapshot's shape table. */
export function writeBody(w: SnapshotWriter, D: Dims, body: Body, shapeIndex: number): void {
  const { n, k } = D;
  w.u32(shapeIndex);
  w.bool(body.name !== undefined);
  if (body.name !== undefined) w.string(body.name);
  w.u8(body.motion);
  w.f64(body.massValue);
  w.f64(body.invMass);
  w.f64(body.material.friction);
  w.f64(body.material.restitution);
  w.u32(body.groupBits);
  w.u32(body.maskBits);
  w.bool(body.sensorFlag);
  w.f64s(body.inertia, 0, k);
  w.f64s(body.invInertia, 0, k);
  w.bool(body.comOffset !== null);
  if (body.comOffset !== null) w.f64s(body.comOffset, 0, n);
  w.f64(body.boundingRadius);
  w.f64s(body.storage, body.storageOffset, Body.recordLength(D));
  w.bool(body.hasTorque);
  w.bool(body.sleeping);
  w.f64(body.sleepTimer);
  w.bool(body.poseDirty);
  w.bool(body.pose !== null);
  if (body.pose !== null) {
    w.f64s(body.pose.x, 0, n);
    w.f64s(body.pose.M, 0, n * n);
  }
  w.i32(body.proxyId);
}

/** Reads one body written by {@link writeBody}; `shapes` is the snapshot's shape table. */
export function readBody(r: SnapshotReader, D: Dims, shapes: readonly Shape[]): BodyFlags {
  const { n, k } = D;
  const shapeIndex = r.u32();
  if (shapeIndex >= shapes.length) r.fail(`a body's shape index ${shapeIndex} is past the ${shapes.length} shapes`);
  const shape = shapes[shapeIndex]!;
  const name = r.bool() ? r.string() : undefined;
  const motion = r.u8();
  if (motion !== MOTION_DYNAMIC && motion !== MOTION_KINEMATIC && motion !== MOTION_STATIC)
    r.fail(`a body has the unknown motion code ${motion}`);
  const mass = r.f64();
  const invMass = r.f64();
  const friction = r.f64();
  const restitution = r.f64();
  const collisionGroup = r.u32();
  const collisionMask = r.u32();
  const sensor = r.bool();
  const inertia = r.f64s(k);
  const invInertia = r.f64s(k);
  const comOffset = r.bool() ? r.f64s(n) : null;
  const boundingRadius = r.f64();
  const record = r.f64s(Body.recordLength(D));
  const hasTorque = r.bool();
  const sleeping = r.bool();
  const sleepTimer = r.f64();
  const poseDirty = r.bool();
  const pose = r.bool() ? r.f64s(n + n * n) : null;
  const proxyId = r.i32();
  for (let i = 0; i < record.length; i += 1)
    if (!Number.isFinite(record[i])) r.fail(`a body's state holds the non-finite number ${record[i]}`);
  if (!Number.isFinite(invMass) || !Number.isFinite(sleepTimer) || !Number.isFinite(boundingRadius))
    r.fail('a body holds a non-finite number');
  let body: Body;
  try {
    body = new Body(D, {
      shape,
      type: TYPES[motion]!,
      mass,
      material: { friction, restitution },
      collisionGroup,
      collisionMask,
      sensor,
      ...(name === undefined ? {} : { name }),
    });
  } catch (error) {
    return r.fail(`a body cannot be rebuilt (${(error as Error).message})`);
  }
  if ((body.comOffset === null) !== (comOffset === null)) r.fail("a body's centre-of-mass offset does not match its shape");
  if (comOffset !== null) body.comOffset!.set(comOffset);
  body.massValue = mass;
  body.invMass = invMass;
  body.ownInertia(); // (its arrays may be shared with bodies of the same shape and mass)
  body.inertia.set(inertia);
  body.invInertia.set(invInertia);
  body.boundingRadius = boundingRadius;
  body.storage.set(record, body.storageOffset);
  return { body, hasTorque, sleeping, sleepTimer, poseDirty, pose, proxyId };
}

/** Puts back what the world set on addBody and addConstraint (see {@link BodyFlags}). */
export function applyBodyFlags(D: Dims, f: BodyFlags): void {
  const body = f.body;
  const n = D.n;
  body.hasTorque = f.hasTorque;
  body.sleeping = f.sleeping;
  body.sleepTimer = f.sleepTimer;
  body.poseDirty = f.poseDirty;
  if (f.pose !== null) {
    body.pose ??= createPose(n); // a body that left the world keeps the pose it had there
    body.pose.x.set(f.pose.subarray(0, n));
    body.pose.M.set(f.pose.subarray(n, n + n * n));
  } else body.pose = null; // (made from the record when read, see World.ensurePose)
  body.proxyId = f.proxyId;
}
