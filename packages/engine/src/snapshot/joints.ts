/**
 * Joints in a snapshot: one writer and one builder per joint type, plus what every joint has
 * (its bodies by world index, collideConnected, the anchors, the whole `state` array — softness,
 * break loads, the loads of the last sub-step, rest length, hinge angle, limits, motor — and the
 * accumulated impulses `lambda`).
 *
 * The rest frames of fixed, hinge and subspace joints were measured from the bodies' poses when
 * the joint was built; a joint built again on restore would measure them from the current poses.
 * So they are written raw and put back, as is everything else: the builder only makes an object
 * of the right type with the right options, and the saved numbers then replace its own.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import type { Body } from '../body.js';
import type { DistanceJoint, DistanceMode } from '../joints/distance.js';
import type { FixedJoint } from '../joints/fixed.js';
import type { HingeJoint } from '../joints/hinge.js';
import { JS_COMMON_COUNT } from '../joints/joint-slots.js';
import type { Joint } from '../joints/joint.js';
import type { PointJoint } from '../joints/point.js';
import type { SubspaceJoint } from '../joints/subspace.js';
import type { SnapshotReader } from './reader.js';
import { jointClass, jointTypeName } from './registry.js';
import type { SnapshotWriter } from './writer.js';

const KIND_POINT = 0;
const KIND_DISTANCE = 1;
const KIND_FIXED = 2;
const KIND_HINGE = 3;
const KIND_SUBSPACE = 4;

const MODES: readonly DistanceMode[] = ['rod', 'rope', 'strut'];

/** A joint's private fields, by name (the snapshot code reaches them through this view). */
type Internals = Record<string, unknown>;

function privateF64(joint: Joint, name: string): Float64Array {
  const v = (joint as unknown as Internals)[name];
  if (!(v instanceof Float64Array)) {
    throw new Error(
      `World.snapshot: ${joint.constructor.name} has no Float64Array field '${name}'; update packages/engine/src/snapshot/joints.ts`,
    );
  }
  return v;
}

function privateI32(joint: Joint, name: string): Int32Array {
  const v = (joint as unknown as Internals)[name];
  if (!(v instanceof Int32Array)) {
    throw new Error(
      `World.snapshot: ${joint.constructor.name} has no Int32Array field '${name}'; update packages/engine/src/snapshot/joints.ts`,
    );
  }
  return v;
}

function privateNumber(joint: Joint, name: string): number {
  const v = (joint as unknown as Internals)[name];
  if (typeof v !== 'number') {
    throw new Error(
      `World.snapshot: ${joint.constructor.name} has no number field '${name}'; update packages/engine/src/snapshot/joints.ts`,
    );
  }
  return v;
}

/** The private rest frames (and plane) of each joint type, written and put back raw. */
const FRAME_FIELDS: readonly (readonly string[])[] = [
  [],
  [],
  ['frameA', 'frameB'],
  ['planeValue', 'frameA', 'frameB'],
  ['frameA', 'frameB'],
];

/** Type names of the joint classes (registry.ts), by kind code. */
const NAMES = ['point', 'distance', 'fixed', 'hinge', 'subspace'];

function kindOf(joint: Joint): number {
  const kind = NAMES.indexOf(jointTypeName(joint.constructor) ?? '');
  if (kind < 0) {
    throw new Error(
      `World.snapshot: a joint of type ${joint.constructor.name} is not supported by snapshots (known: PointJoint, DistanceJoint, FixedJoint, HingeJoint, SubspaceJoint); add it to packages/engine/src/snapshot/joints.ts and register its class (registry.ts)`,
    );
  }
  return kind;
}

/** The registered class of a joint type (see registry.ts), typed as `C`. */
function classOf<C>(kind: number): C {
  const c = jointClass(NAMES[kind]!);
  if (typeof c !== 'function') {
    const name = `${NAMES[kind]![0]!.toUpperCase()}${NAMES[kind]!.slice(1)}Joint`;
    throw new Error(
      `restoreWorld: the snapshot holds a ${name}, and this program never loaded it; reference ${name} from @physin/engine before restoring`,
    );
  }
  return c as C;
}

/** Writes one joint; `indexOf` gives a body's index in the world's body list. */
export function writeJoint(w: SnapshotWriter, D: Dims, joint: Joint, indexOf: (body: Body) => number): void {
  const kind = kindOf(joint);
  w.u8(kind);
  w.u32(indexOf(joint.a));
  w.i32(joint.b === null ? -1 : indexOf(joint.b));
  w.bool(joint.collide);
  w.f64s(joint.anchorA, 0, D.n);
  w.f64s(joint.anchorB, 0, D.n);
  w.u32(joint.state.length);
  w.f64s(joint.state);
  w.u32(joint.lambda.length);
  w.f64s(joint.lambda);
  if (kind === KIND_DISTANCE) w.u8(privateNumber(joint, 'modeIndex'));
  if (kind === KIND_SUBSPACE) {
    const axes = privateI32(joint, 'axes');
    const planes = privateI32(joint, 'planes');
    w.u32(axes.length);
    w.i32s(axes);
    w.u32(planes.length);
    w.i32s(planes);
    w.u8(privateNumber(joint, 'world1'));
  }
  for (const name of FRAME_FIELDS[kind]!) {
    const a = privateF64(joint, name);
    w.u32(a.length);
    w.f64s(a);
  }
}

/** A joint read but not yet in the world: the reader adds it, then calls `finish`. */
export interface PendingJoint {
  readonly joint: Joint;
  /** Puts back the saved numbers (after World.addConstraint, which clears lambda). */
  finish(): void;
}

/** Reads one joint written by {@link writeJoint}; `bodies` are the restored world's bodies. */
export function readJoint(r: SnapshotReader, D: Dims, bodies: readonly Body[]): PendingJoint {
  const kind = r.u8();
  if (kind > KIND_SUBSPACE) r.fail(`a joint has the unknown type code ${kind}`);
  const ai = r.u32();
  const bi = r.i32();
  if (ai >= bodies.length || bi < -1 || bi >= bodies.length) r.fail(`a joint names body ${ai} or ${bi} of ${bodies.length}`);
  const a = bodies[ai]!;
  const b = bi < 0 ? null : bodies[bi]!;
  const collideConnected = r.bool();
  const anchorA = r.f64s(D.n);
  const anchorB = r.f64s(D.n);
  const state = r.f64s(r.count('a joint state length', 1024, 8));
  const lambda = r.f64s(r.count('a joint impulse count', 1024, 8));
  const modeIndex = kind === KIND_DISTANCE ? r.u8() : 0;
  if (modeIndex >= MODES.length) r.fail(`a distance joint has the unknown mode ${modeIndex}`);
  let axes: Int32Array | null = null;
  let planes: Int32Array | null = null;
  let world1 = 0;
  if (kind === KIND_SUBSPACE) {
    axes = r.i32s(r.count('a subspace joint axis count', D.n));
    planes = r.i32s(r.count('a subspace joint plane count', D.k));
    world1 = r.u8();
  }
  const frames = FRAME_FIELDS[kind]!.map(() => r.f64s(r.count('a joint frame length', 1024, 8)));
  let joint: Joint;
  try {
    const common = { collideConnected };
    switch (kind) {
      case KIND_POINT:
        joint = new (classOf<typeof PointJoint>(kind))(a, b, anchorA, anchorB, common);
        break;
      case KIND_DISTANCE:
        joint = new (classOf<typeof DistanceJoint>(kind))(a, b, anchorA, anchorB, {
          ...common,
          rest: state[JS_COMMON_COUNT]!,
          mode: MODES[modeIndex]!,
        });
        break;
      case KIND_FIXED:
        joint = new (classOf<typeof FixedJoint>(kind))(a, b, anchorA, anchorB, common);
        break;
      case KIND_HINGE:
        joint = new (classOf<typeof HingeJoint>(kind))(a, b, anchorA, anchorB, { ...common, plane: frames[0]! });
        break;
      default:
        joint = new (classOf<typeof SubspaceJoint>(kind))(a, b, {
          ...common,
          localA: anchorA,
          localB: anchorB,
          worldFrame: world1 === 1,
          ...(axes!.length > 0 ? { lockAxes: axes! } : {}),
          ...(planes!.length > 0 ? { lockPlanes: planes! } : {}),
        });
    }
  } catch (error) {
    if (error instanceof Error && error.message.startsWith('restoreWorld')) throw error;
    return r.fail(`a joint cannot be rebuilt (${(error as Error).message})`);
  }
  if (joint.state.length !== state.length || joint.lambda.length !== lambda.length)
    r.fail('a joint has arrays of the wrong length');
  const names = FRAME_FIELDS[kind]!;
  for (let i = 0; i < names.length; i += 1) {
    if (privateF64(joint, names[i]!).length !== frames[i]!.length) r.fail(`a joint's '${names[i]}' has the wrong length`);
  }
  return {
    joint,
    finish(): void {
      joint.anchorA.set(anchorA);
      joint.anchorB.set(anchorB);
      joint.state.set(state);
      joint.lambda.set(lambda);
      for (let i = 0; i < names.length; i += 1) privateF64(joint, names[i]!).set(frames[i]!);
    },
  };
}
