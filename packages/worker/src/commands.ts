/**
 * The commands of `execute(cmd, params)`: each is one call of the engine, so the engine's own
 * checks validate it and its own errors name what was wrong.
 *
 * @module
 */
import { DistanceJoint, HingeJoint } from '@physin/engine';
import type { Body, Joint, World } from '@physin/engine';
import type { CommandMap, CommandName } from './types.js';

/** What a command needs: the world, and the bodies and joints by host id. */
export interface CommandTarget {
  readonly world: World;
  /** The body of a host id; throws a RangeError naming `name` if there is none. */
  bodyOf(id: unknown, name: string): Body;
  /** The joint of a host id; throws a RangeError naming `name` if there is none. */
  jointOf(id: unknown, name: string): Joint;
}

type Handler<C extends CommandName> = (t: CommandTarget, p: CommandMap[C], where: string) => void;

function hinge(t: CommandTarget, id: unknown, where: string): HingeJoint {
  const joint = t.jointOf(id, 'joint');
  if (!(joint instanceof HingeJoint)) throw new RangeError(`${where}: joint ${String(id)} is not a hinge`);
  return joint;
}

function distance(t: CommandTarget, id: unknown, where: string): DistanceJoint {
  const joint = t.jointOf(id, 'joint');
  if (!(joint instanceof DistanceJoint)) throw new RangeError(`${where}: joint ${String(id)} is not a distance joint`);
  return joint;
}

const handlers: { readonly [C in CommandName]: Handler<C> } = {
  setGravity: (t, p) => void t.world.setGravity(p.gravity),
  setParams: (t, p) => void t.world.setParams(p.params),
  setMass: (t, p) => void t.bodyOf(p.id, 'id').setMass(p.value),
  setMaterial: (t, p) => {
    const material: { friction?: number; restitution?: number } = {};
    if (p.friction !== undefined) material.friction = p.friction;
    if (p.restitution !== undefined) material.restitution = p.restitution;
    t.bodyOf(p.id, 'id').setMaterial(material);
  },
  setCollisionFilter: (t, p) => {
    const { id: _id, ...filter } = p;
    t.bodyOf(p.id, 'id').setCollisionFilter(filter);
  },
  wake: (t, p) => void t.bodyOf(p.id, 'id').wake(),
  setPositionN: (t, p) => void t.bodyOf(p.id, 'id').setPositionN(p.position),
  setRotor: (t, p) => void t.bodyOf(p.id, 'id').setRotor(p.rotor),
  rotateInPlane: (t, p) => void t.bodyOf(p.id, 'id').rotateInPlane(p.i, p.j, p.angle),
  setLinearVelocity: (t, p) => void t.bodyOf(p.id, 'id').setLinearVelocity(p.velocity),
  setAngularVelocity: (t, p) => void t.bodyOf(p.id, 'id').setAngularVelocity(p.angularVelocity),
  applyCentralImpulse: (t, p) => void t.bodyOf(p.id, 'id').applyCentralImpulse(p.impulse),
  applyImpulse: (t, p) => void t.bodyOf(p.id, 'id').applyImpulse(p.impulse, p.offset),
  applyCentralForce: (t, p) => void t.bodyOf(p.id, 'id').applyCentralForce(p.force),
  applyForce: (t, p) => void t.bodyOf(p.id, 'id').applyForce(p.force, p.offset),
  applyTorque: (t, p) => void t.bodyOf(p.id, 'id').applyTorque(p.torque),
  setSoftness: (t, p) => void t.jointOf(p.joint, 'joint').setSoftness(p.hertz, p.damping),
  setBreak: (t, p) => void t.jointOf(p.joint, 'joint').setBreak(p.force, p.torque),
  setAnchors: (t, p) => void t.jointOf(p.joint, 'joint').setAnchors(p.localA, p.localB),
  setLimits: (t, p, where) => void hinge(t, p.joint, where).setLimits(p.lower, p.upper),
  setMotor: (t, p, where) => void hinge(t, p.joint, where).setMotor(p.speed, p.maxTorque),
  setRest: (t, p, where) => void distance(t, p.joint, where).setRest(p.rest),
  setMode: (t, p, where) => void distance(t, p.joint, where).setMode(p.mode),
};

/** The names of every command, for messages and tests. */
export const COMMAND_NAMES: readonly CommandName[] = Object.freeze(Object.keys(handlers) as CommandName[]);

/**
 * Runs command `cmd` on `t`. Throws a RangeError naming the known commands for an unknown one, a
 * TypeError for params that are not an object, and the engine's errors for bad values.
 */
export function runCommand(t: CommandTarget, cmd: unknown, params: unknown, where: string): void {
  if (typeof cmd !== 'string' || !Object.hasOwn(handlers, cmd)) {
    throw new RangeError(`${where}: unknown command '${String(cmd)}' (known: ${COMMAND_NAMES.join(', ')})`);
  }
  if (params === null || typeof params !== 'object') {
    throw new TypeError(
      `${where}: argument 'params' of '${cmd}' must be an object, got ${params === null ? 'null' : typeof params}`,
    );
  }
  (handlers[cmd as CommandName] as Handler<CommandName>)(t, params as never, `${where} '${cmd}'`);
}
