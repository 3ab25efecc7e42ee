/**
 * Joints between meshes (null: the world), added with `scene.addConstraint`. Their methods work
 * before and after: before, they change what `addConstraint` will build; after, they are commands
 * to the world, batched with the next step.
 *
 * @module
 */
import { EventDispatcher } from 'three';
import type { DistanceMode } from '@physin/engine';
import type { CommandMap, CommandName, HostId, JointDescription, JointDescriptionOptions, WorldHost } from '@physin/worker';
import { finite, numbers } from './checks.js';
import { Mesh } from './mesh.js';

/** Events of a joint. */
export interface JointEventMap {
  /** The joint broke (its load passed `breakForce` or `breakTorque`) and left the scene. */
  broken: object;
}

/** Options of every joint (see the engine's joints). */
export type JointOptions = JointDescriptionOptions;

/** @internal What a joint needs from the scene that holds it. */
export interface JointLink {
  readonly host: WorldHost;
}

/** The base of the five joint classes. */
export abstract class Joint extends EventDispatcher<JointEventMap> {
  /** The first mesh. */
  readonly a: Mesh;
  /** The second mesh, or null for the world. */
  readonly b: Mesh | null;
  /** @internal The host id, or null while not in a scene. */
  _id: HostId | null = null;
  /** @internal */
  _link: JointLink | null = null;
  /** The anchor on `a`, in a's frame (n numbers), or null for the default. */
  protected localA: Float64Array | null;
  /** The anchor on `b` in b's frame, or a world point when `b` is null; null for the default. */
  protected localB: Float64Array | null;
  /** The options given (a copy), sent with the joint's description when it is added. */
  protected readonly options: Record<string, unknown>;
  private readonly kind: JointDescription['kind'];

  protected constructor(
    kind: JointDescription['kind'],
    a: Mesh,
    b: Mesh | null,
    localA: ArrayLike<number> | null,
    localB: ArrayLike<number> | null,
    options: JointOptions | undefined,
  ) {
    super();
    const where = `${new.target.name}`;
    if (!(a instanceof Mesh)) throw new TypeError(`${where}: argument 'a' must be a PhysiN mesh`);
    if (b !== null && !(b instanceof Mesh))
      throw new TypeError(`${where}: argument 'b' must be a PhysiN mesh or null (the world)`);
    if (options !== undefined && (options === null || typeof options !== 'object'))
      throw new TypeError(`${where}: argument 'options' must be an object`);
    this.kind = kind;
    this.a = a;
    this.b = b;
    this.localA = localA === null ? null : numbers(where, 'localA', localA, a.dimensions);
    this.localB = localB === null ? null : numbers(where, 'localB', localB, b?.dimensions ?? a.dimensions);
    this.options = { ...(options ?? {}) };
  }

  /** The joint's id in the world (for `scene.execute`), or null while not in a scene. */
  get id(): HostId | null {
    return this._id;
  }

  /** @internal The description `addConstraint` sends. */
  describe(): JointDescription {
    const a = this.a._physiN.id;
    const b = this.b === null ? null : this.b._physiN.id;
    const where = 'Scene.addConstraint';
    if (a === null) throw new RangeError(`${where}: mesh 'a' of the ${this.constructor.name} is not in the scene; add it first`);
    if (this.b !== null && b === null)
      throw new RangeError(`${where}: mesh 'b' of the ${this.constructor.name} is not in the scene; add it first`);
    return {
      kind: this.kind,
      a,
      b,
      ...(this.localA === null ? {} : { localA: this.localA }),
      ...(this.localB === null ? {} : { localB: this.localB }),
      options: this.options as JointDescriptionOptions,
    };
  }

  /** A spring of `hertz` (0: rigid) with damping ratio `damping`. */
  setSoftness(hertz: number, damping: number): this {
    finite(`${this.constructor.name}.setSoftness`, 'hertz', hertz, 0, 'frequency in Hz');
    finite(`${this.constructor.name}.setSoftness`, 'damping', damping, 0, 'damping ratio');
    return this.change('setSoftness', { hertz, damping }, { hertz, damping });
  }

  /** Breaks the joint above `force` N or `torque` N·m (0: never). */
  setBreak(force: number, torque: number): this {
    finite(`${this.constructor.name}.setBreak`, 'force', force, 0, 'force in N');
    finite(`${this.constructor.name}.setBreak`, 'torque', torque, 0, 'torque in N·m');
    return this.change('setBreak', { force, torque }, { breakForce: force, breakTorque: torque });
  }

  /** New anchors in the frames of their bodies (null keeps one as it is). */
  setAnchors(localA: ArrayLike<number> | null, localB: ArrayLike<number> | null): this {
    const where = `${this.constructor.name}.setAnchors`;
    const A = localA === null ? null : numbers(where, 'localA', localA, this.a.dimensions);
    const B = localB === null ? null : numbers(where, 'localB', localB, this.b?.dimensions ?? this.a.dimensions);
    if (this._link !== null) {
      this._link.host.execute('setAnchors', { joint: this._id!, localA: A, localB: B });
    } else {
      if (A !== null) this.localA = A;
      if (B !== null) this.localB = B;
    }
    return this;
  }

  /** Sends `cmd` when in a scene, else records the options for `addConstraint`. */
  protected change<C extends CommandName>(cmd: C, params: Record<string, unknown>, options: Record<string, unknown>): this {
    if (this._link !== null) this._link.host.execute(cmd, { ...params, joint: this._id! } as unknown as CommandMap[C]);
    else Object.assign(this.options, options);
    return this;
  }
}

/** Holds a point of `a` on a point of `b` (anchors in their bodies' frames). */
export class PointJoint extends Joint {
  constructor(a: Mesh, b: Mesh | null, localA?: ArrayLike<number>, localB?: ArrayLike<number>, options?: JointOptions) {
    super('point', a, b, localA ?? null, localB ?? null, options);
  }
}

/** Holds the distance between two points: `options.rest` (default: the distance at the start), `options.mode` rod, rope or strut. */
export class DistanceJoint extends Joint {
  constructor(a: Mesh, b: Mesh | null, localA?: ArrayLike<number>, localB?: ArrayLike<number>, options?: JointOptions) {
    super('distance', a, b, localA ?? null, localB ?? null, options);
  }

  /** A new rest length. */
  setRest(rest: number): this {
    finite('DistanceJoint.setRest', 'rest', rest, 0, 'length in m');
    return this.change('setRest', { rest }, { rest });
  }

  /** 'rod', 'rope' or 'strut'. */
  setMode(mode: DistanceMode): this {
    if (mode !== 'rod' && mode !== 'rope' && mode !== 'strut')
      throw new RangeError(`DistanceJoint.setMode: argument 'mode' must be 'rod', 'rope' or 'strut', got ${String(mode)}`);
    return this.change('setMode', { mode }, { mode });
  }
}

/** Holds the point and every plane: the two bodies move as one. */
export class FixedJoint extends Joint {
  constructor(a: Mesh, b: Mesh | null, localA?: ArrayLike<number>, localB?: ArrayLike<number>, options?: JointOptions) {
    super('fixed', a, b, localA ?? null, localB ?? null, options);
  }
}

/**
 * Holds the point and every rotation plane but one: `options.plane` (an index of the
 * lexicographic order, or a simple bivector, in the frame of `a`), with limits and a motor.
 */
export class HingeJoint extends Joint {
  constructor(a: Mesh, b: Mesh | null, localA?: ArrayLike<number>, localB?: ArrayLike<number>, options?: JointOptions) {
    super('hinge', a, b, localA ?? null, localB ?? null, options);
  }

  /** The angle limits in radians (within (−π, π)). */
  setLimits(lower: number, upper: number): this {
    finite('HingeJoint.setLimits', 'lower', lower, undefined, 'angle in rad');
    finite('HingeJoint.setLimits', 'upper', upper, undefined, 'angle in rad');
    return this.change('setLimits', { lower, upper }, { lowerAngle: lower, upperAngle: upper });
  }

  /** The motor: `speed` rad/s with at most `maxTorque` N·m (0: off). */
  setMotor(speed: number, maxTorque: number): this {
    finite('HingeJoint.setMotor', 'speed', speed, undefined, 'speed in rad/s');
    finite('HingeJoint.setMotor', 'maxTorque', maxTorque, 0, 'torque in N·m');
    return this.change('setMotor', { speed, maxTorque }, { motorSpeed: speed, maxMotorTorque: maxTorque });
  }
}

/** Holds a body in a subspace: `lockAxes`/`freeAxes` for the position, `lockPlanes`/`freePlanes` for the turn. */
export class SubspaceJoint extends Joint {
  constructor(a: Mesh, b: Mesh | null, options?: JointOptions) {
    super('subspace', a, b, null, null, options);
  }
}
