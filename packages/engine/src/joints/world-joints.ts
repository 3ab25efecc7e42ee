/**
 * The world's bookkeeping of its joints: adding, removing and breaking them. Functions the world
 * reaches through its joints (`Joint.worldJoints`, like the solver through `Joint.createSolver`),
 * so a world without joints carries none of it (docs/architecture.md, What a scene pays for).
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import type { BodyOwner } from '../body.js';
import type { WorldBase } from '../world.js';
import type { Joint, JointOwner } from './joint.js';
import type { JointSolver } from './joint-solver.js';

/** What these functions read and change of a world (its private parts). */
interface WorldJointParts {
  readonly D: Dims;
  readonly n: number;
  readonly owner: BodyOwner;
  readonly jointList: Joint[];
  jointView: readonly Joint[];
  jointSolver: JointSolver | null;
  readonly brokenJoints: Joint[];
  readonly jointOwner: JointOwner;
}

/** @internal The world's joint operations (see the module). */
export interface WorldJoints {
  /** The checks and the work of `World.addConstraint` once `joint` is known to be a joint. */
  add<J extends Joint>(world: WorldBase, joint: J): J;
  /** The work of `World.removeConstraint` for a joint of this world. */
  remove(world: WorldBase, joint: Joint): void;
  /** Takes the joints the solver broke out of the world (their events wait for the step's end). */
  breakJoints(world: WorldBase, js: JointSolver): void;
  /** Sends the events of the joints that broke in the step. */
  dispatchBroken(world: WorldBase): void;
}

/** @internal See the module. */
export const worldJoints: WorldJoints = {
  add<J extends Joint>(world: WorldBase, joint: J): J {
    const w = world as unknown as WorldJointParts;
    const fn = 'World.addConstraint';
    if (joint.D.n !== w.n) {
      throw new RangeError(`${fn}: argument 'joint' has n = ${joint.D.n} but the world has n = ${w.n}`);
    }
    if (joint.brokenFlag) throw new RangeError(`${fn}: argument 'joint' broke; build a new joint`);
    if (joint.owner === w.jointOwner) throw new RangeError(`${fn}: argument 'joint' is already in this world`);
    if (joint.owner !== null)
      throw new RangeError(`${fn}: argument 'joint' already belongs to another world; remove it there first`);
    if (joint.a.owner !== w.owner) {
      throw new RangeError(`${fn}: body 'a' (${joint.a.label}) of the joint is not in this world; add it first (World.addBody)`);
    }
    if (joint.b !== null && joint.b.owner !== w.owner) {
      throw new RangeError(`${fn}: body 'b' (${joint.b.label}) of the joint is not in this world; add it first (World.addBody)`);
    }
    w.jointSolver ??= joint.createSolver(w.D);
    joint.owner = w.jointOwner;
    joint.lambda.fill(0);
    w.jointList.push(joint);
    w.jointView = Object.freeze(w.jointList.slice());
    linkBodies(joint, 1);
    joint.a.wake();
    joint.b?.wake();
    return joint;
  },

  remove(world: WorldBase, joint: Joint): void {
    const w = world as unknown as WorldJointParts;
    const index = w.jointList.indexOf(joint);
    if (index < 0) throw new RangeError(`World.removeConstraint: argument 'joint' is not in this world`);
    detachJoint(w, joint, index);
    joint.a.wake();
    joint.b?.wake();
  },

  breakJoints(world: WorldBase, js: JointSolver): void {
    const w = world as unknown as WorldJointParts;
    for (let i = 0; i < js.brokenCount; i += 1) {
      const joint = js.broken[i]!;
      const index = w.jointList.indexOf(joint);
      if (index < 0) continue;
      joint.brokenFlag = true;
      detachJoint(w, joint, index);
      joint.a.wake();
      joint.b?.wake();
      w.brokenJoints.push(joint);
    }
    js.brokenCount = 0;
  },

  dispatchBroken(world: WorldBase): void {
    const w = world as unknown as WorldJointParts;
    const list = w.brokenJoints.splice(0, w.brokenJoints.length);
    for (const joint of list) joint.emitBroken();
  },
};

/** Takes a joint out of the list (it is known to be at `index`). */
function detachJoint(w: WorldJointParts, joint: Joint, index: number): void {
  w.jointList.splice(index, 1);
  w.jointView = Object.freeze(w.jointList.slice());
  linkBodies(joint, -1);
  joint.owner = null;
}

/** Counts the joint on its bodies (+1 or −1) and keeps their collision filter. */
function linkBodies(joint: Joint, sign: number): void {
  const A = joint.a;
  const B = joint.b;
  A.jointCount += sign;
  if (B === null) return;
  B.jointCount += sign;
  if (joint.collideConnected) return;
  if (sign > 0) {
    (A.jointPeers ??= []).push(B);
    (B.jointPeers ??= []).push(A);
  } else {
    A.jointPeers!.splice(A.jointPeers!.indexOf(B), 1);
    B.jointPeers!.splice(B.jointPeers!.indexOf(A), 1);
    if (A.jointPeers!.length === 0) A.jointPeers = null;
    if (B.jointPeers!.length === 0) B.jointPeers = null;
  }
}
