/**
 * Descriptions → engine objects. The same functions run in the caller's thread (to validate, with
 * the engine's own errors) and in the thread that owns the world (to build), so a description that
 * passes here cannot fail there.
 *
 * @module
 */
import {
  Body,
  Compound,
  ConvexMesh,
  DistanceJoint,
  FixedJoint,
  HalfSpace,
  HingeJoint,
  HyperBox,
  HyperCapsule,
  HyperSphere,
  HyperTorus,
  PointJoint,
  SubspaceJoint,
} from '@physin/engine';
import type { Dims, Joint, Shape, SubspaceJointOptions } from '@physin/engine';
import type { BodyDescription, CompoundPartDescription, HostId, JointDescription, ShapeDescription } from './types.js';

const BODY_KEYS = new Set([
  'shape',
  'mass',
  'type',
  'position',
  'rotor',
  'velocity',
  'angularVelocity',
  'material',
  'name',
  'collisionGroup',
  'collisionMask',
  'sensor',
]);
const JOINT_KINDS = ['point', 'distance', 'fixed', 'hinge', 'subspace'] as const;

function isObject(value: unknown): value is Record<string, unknown> {
  return value !== null && typeof value === 'object';
}

function describeValue(value: unknown): string {
  return value === null ? 'null' : Array.isArray(value) ? 'an array' : typeof value;
}

/** Builds the shape of a description (the engine's factories validate it). */
export function buildShape(D: Dims, desc: ShapeDescription, where: string): Shape {
  if (!isObject(desc)) throw new TypeError(`${where}: 'shape' must be an object { kind, ... }, got ${describeValue(desc)}`);
  switch (desc.kind) {
    case 'box':
      return HyperBox(D, desc.halfExtents);
    case 'sphere':
      return HyperSphere(D, desc.radius);
    case 'halfspace':
      return HalfSpace(D, desc.normal, desc.offset);
    case 'torus':
      return HyperTorus(D, desc.majorRadius, desc.minorRadius, desc.plane);
    case 'capsule':
      return HyperCapsule(D, desc.halfHeight, desc.radius);
    case 'convex':
      return ConvexMesh(D, desc.vertices, desc.facets);
    case 'triangles':
      return ConvexMesh.fromTriangles(D, desc.positions, desc.indices);
    case 'compound':
      return buildCompound(D, desc.parts, where);
    default:
      throw new RangeError(
        `${where}: unknown shape kind '${String((desc as { kind?: unknown }).kind)}' (known: box, sphere, halfspace, torus, capsule, convex, triangles, compound)`,
      );
  }
}

/** Builds a compound from its part descriptions (the engine's `Compound` validates the placements). */
function buildCompound(D: Dims, parts: unknown, where: string): Shape {
  if (!Array.isArray(parts)) {
    throw new TypeError(
      `${where}: 'shape.parts' of a compound must be an array of { shape, position?, rotor? }, got ${describeValue(parts)}`,
    );
  }
  const built = parts.map((part: unknown, i) => {
    if (!isObject(part) || Array.isArray(part)) {
      throw new TypeError(
        `${where}: 'shape.parts'[${i}] must be an object { shape, position?, rotor? }, got ${describeValue(part)}`,
      );
    }
    const { shape, ...placement } = part as unknown as CompoundPartDescription;
    return { ...placement, shape: buildShape(D, shape, `${where} (shape.parts[${i}])`) };
  });
  return Compound(D, built);
}

/** Builds a body from its description. */
export function buildBody(D: Dims, desc: BodyDescription, where: string): Body {
  if (!isObject(desc))
    throw new TypeError(`${where}: argument 'description' must be an object { shape, mass?, ... }, got ${describeValue(desc)}`);
  for (const key of Object.keys(desc)) {
    if (!BODY_KEYS.has(key))
      throw new RangeError(`${where}: unknown body property '${key}' (known: ${[...BODY_KEYS].join(', ')})`);
  }
  const shape = buildShape(D, desc.shape, where);
  const { shape: _shape, ...rest } = desc;
  return new Body(D, { ...rest, shape });
}

/** Builds a joint from its description; `bodyOf` turns a host id into its body (throws if unknown). */
export function buildJoint(desc: JointDescription, bodyOf: (id: unknown, name: string) => Body, where: string): Joint {
  if (!isObject(desc))
    throw new TypeError(`${where}: argument 'description' must be an object { kind, a, b, ... }, got ${describeValue(desc)}`);
  const a = bodyOf(desc.a, 'a');
  const b = desc.b === null ? null : bodyOf(desc.b, 'b');
  const opts = desc.options as Record<string, unknown> | undefined;
  const localA = desc.localA ?? new Array<number>(a.D.n).fill(0);
  const localB = desc.localB ?? new Array<number>(a.D.n).fill(0);
  switch (desc.kind) {
    case 'point':
      return new PointJoint(a, b, localA, localB, opts);
    case 'distance':
      return new DistanceJoint(a, b, localA, localB, opts);
    case 'fixed':
      return new FixedJoint(a, b, localA, localB, opts);
    case 'hinge':
      return new HingeJoint(a, b, localA, localB, opts);
    case 'subspace':
      return new SubspaceJoint(a, b, (opts ?? {}) as SubspaceJointOptions);
    default:
      throw new RangeError(
        `${where}: unknown joint kind '${String((desc as { kind?: unknown }).kind)}' (known: ${JOINT_KINDS.join(', ')})`,
      );
  }
}

/** Checks a host id: a non-negative integer. */
export function checkHostId(where: string, name: string, id: unknown): HostId {
  if (typeof id !== 'number')
    throw new TypeError(`${where}: argument '${name}' must be an id (a non-negative integer), got ${describeValue(id)}`);
  if (!Number.isInteger(id) || id < 0)
    throw new RangeError(`${where}: argument '${name}' must be an id (a non-negative integer), got ${id}`);
  return id;
}
