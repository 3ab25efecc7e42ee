/**
 * The base of every joint: the two bodies, the anchors, the common options (softness, breaking,
 * collideConnected), the accumulated impulses kept across steps, and the 'broken' event.
 *
 * A joint is plain data plus one method, `buildRows`, that the {@link JointSolver} calls once per
 * sub-step to write the joint's rows. Everything a step reads or writes lives in typed arrays
 * (`lambda`, `state`), so the step allocates nothing and boxes no double.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { Body, MOTION_STATIC } from '../body.js';
import { checkJointOptionNames, readBoolean, readNonNegative, readVector } from './options.js';
import { JointSolver } from './joint-solver.js';
import { worldJoints } from './world-joints.js';
import type { WorldJoints } from './world-joints.js';

/** The options every joint takes. */
export interface JointOptions {
  /**
   * Frequency of a soft joint (Hz, >= 0). 0 = rigid. Default: the world's `constraintHertz`
   * (read at every step). Capped at `constraintHertzRatio` × the sub-step rate.
   */
  readonly hertz?: number;
  /** Damping ratio of a soft joint (>= 0; 1 = critical). Default: the world's `constraintDamping`. */
  readonly damping?: number;
  /** The joint breaks when its linear load |λ_linear| / h exceeds this (N). 0 (default) = never. */
  readonly breakForce?: number;
  /**
   * The joint breaks when its angular load |λ_angular| / h exceeds this (N·m); a hinge limit
   * counts, a motor does not. 0 (default) = never.
   */
  readonly breakTorque?: number;
  /** Let the two bodies collide with each other (default false: their contacts are skipped). */
  readonly collideConnected?: boolean;
}

/** The event a joint sends when it breaks (after the step; the joint has left the world). */
export interface JointBrokenEvent {
  /** Always 'broken'. */
  readonly type: 'broken';
  /** The joint that broke. */
  readonly joint: Joint;
}

/** A listener of {@link JointBrokenEvent}. */
export type JointBrokenListener = (event: JointBrokenEvent) => void;

/** @internal What a joint needs from the world that owns it. */
export interface JointOwner {
  /** The world object (returned by `joint.world`). */
  readonly world: object;
  /** The joint's softness, anchors or limits changed: wake its bodies. */
  onJointChanged(joint: Joint): void;
}

import {
  JS_HERTZ,
  JS_DAMPING,
  JS_BREAK_FORCE,
  JS_BREAK_TORQUE,
  JS_FORCE,
  JS_TORQUE,
  JS_COMMON_COUNT,
  JS_ERROR,
  JS_STRETCH_COUNT,
  JS_STRETCH_LIMIT,
} from './joint-slots.js';

let nextJointId = 1;

/**
 * A joint between body `a` and body `b`, or between `a` and the world (`b` null). Use one of the
 * concrete classes: {@link PointJoint}, {@link DistanceJoint}, {@link FixedJoint},
 * {@link HingeJoint}, {@link SubspaceJoint}; add it with `world.addConstraint(joint)`.
 */
export abstract class Joint {
  /** A positive integer, unique in this process. */
  readonly id: number;
  /** @internal The dimension tables. */
  readonly D: Dims;
  /** The first body. */
  readonly a: Body;
  /** The second body, or null for the world. */
  readonly b: Body | null;
  /** @internal Anchor on a, in a's frame (n numbers). */
  readonly anchorA: Float64Array;
  /** @internal Anchor on b in b's frame, or a world point when b is null (n numbers). */
  readonly anchorB: Float64Array;
  /** @internal Per-joint doubles (JS_* indices, then the joint type's own). */
  readonly state: Float64Array;
  /** @internal Accumulated impulse of each row, by the row's fixed key (kept across steps). */
  readonly lambda: Float64Array;
  /** @internal The owner while the joint is in a world. */
  owner: JointOwner | null = null;
  /** @internal Set once when the joint breaks. */
  brokenFlag = false;
  /** @internal Whether the world must keep the two bodies from colliding. */
  readonly collide: boolean;
  private listeners: JointBrokenListener[] | null = null;

  /** @internal */
  protected constructor(
    fn: string,
    a: unknown,
    b: unknown,
    localA: unknown,
    localB: unknown,
    opts: Record<string, unknown> | undefined,
    extraNames: readonly string[],
    stateLength: number,
    lambdaLength: (D: Dims) => number,
  ) {
    if (!(a instanceof Body)) throw new TypeError(`${fn}: argument 'a' must be a Body, got ${describe(a)}`);
    if (b !== null && !(b instanceof Body)) {
      throw new TypeError(`${fn}: argument 'b' must be a Body or null (the world), got ${describe(b)}`);
    }
    if (b === a) throw new RangeError(`${fn}: arguments 'a' and 'b' must be two different bodies (use null for the world)`);
    const D = a.D;
    if (b !== null && b.D.n !== D.n) {
      throw new RangeError(`${fn}: bodies 'a' (n = ${D.n}) and 'b' (n = ${b.D.n}) must have the same dimension`);
    }
    if (a.motion === MOTION_STATIC && (b === null || b.motion === MOTION_STATIC)) {
      throw new RangeError(
        `${fn}: at least one body of a joint must be able to move (got two static bodies or a static body and the world)`,
      );
    }
    checkJointOptionNames(fn, opts, extraNames);
    const anchorA = readVector(D, fn, 'localA', localA);
    const anchorB = readVector(D, fn, 'localB', localB);
    const o = opts ?? {};
    const hertz = o.hertz === undefined ? NaN : readNonNegative(fn, 'opts.hertz', o.hertz);
    const damping = o.damping === undefined ? NaN : readNonNegative(fn, 'opts.damping', o.damping);
    const breakForce = o.breakForce === undefined ? 0 : readNonNegative(fn, 'opts.breakForce', o.breakForce);
    const breakTorque = o.breakTorque === undefined ? 0 : readNonNegative(fn, 'opts.breakTorque', o.breakTorque);
    const collide = o.collideConnected === undefined ? false : readBoolean(fn, 'opts.collideConnected', o.collideConnected);
    this.id = nextJointId++;
    this.D = D;
    this.a = a;
    this.b = b;
    this.anchorA = anchorA;
    this.anchorB = anchorB;
    this.state = new Float64Array(JS_COMMON_COUNT + stateLength);
    this.state[JS_HERTZ] = hertz;
    this.state[JS_DAMPING] = damping;
    this.state[JS_BREAK_FORCE] = breakForce;
    this.state[JS_BREAK_TORQUE] = breakTorque;
    this.lambda = new Float64Array(lambdaLength(D));
    this.collide = collide;
  }

  /** The first body. */
  get bodyA(): Body {
    return this.a;
  }

  /** The second body, or null when the joint holds `bodyA` to the world. */
  get bodyB(): Body | null {
    return this.b;
  }

  /** The world the joint is in, or null. */
  get world(): object | null {
    return this.owner === null ? null : this.owner.world;
  }

  /** Whether the joint broke (it then left its world for good). */
  get broken(): boolean {
    return this.brokenFlag;
  }

  /** The anchor on `bodyA` in its body frame (a copy). */
  get localA(): Float64Array {
    return Float64Array.from(this.anchorA);
  }

  /** The anchor on `bodyB` in its body frame, or the world point when `bodyB` is null (a copy). */
  get localB(): Float64Array {
    return Float64Array.from(this.anchorB);
  }

  /** The frequency given (Hz), or undefined when the joint follows the world's `constraintHertz`. */
  get hertz(): number | undefined {
    const h = this.state[JS_HERTZ]!;
    return Number.isNaN(h) ? undefined : h;
  }

  /** The damping ratio given, or undefined when the joint follows the world's `constraintDamping`. */
  get damping(): number | undefined {
    const d = this.state[JS_DAMPING]!;
    return Number.isNaN(d) ? undefined : d;
  }

  /** Break force (N); 0 = never. */
  get breakForce(): number {
    return this.state[JS_BREAK_FORCE]!;
  }

  /** Break torque (N·m); 0 = never. */
  get breakTorque(): number {
    return this.state[JS_BREAK_TORQUE]!;
  }

  /** Whether the two bodies may collide with each other. */
  get collideConnected(): boolean {
    return this.collide;
  }

  /** The linear load of the last sub-step the joint was solved in: |λ_linear| / h (N). */
  get force(): number {
    return this.state[JS_FORCE]!;
  }

  /** The angular load of the last sub-step: |λ_angular| / h (N·m), limits included, motor excluded. */
  get torque(): number {
    return this.state[JS_TORQUE]!;
  }

  /**
   * The largest error the solver left in this joint at the end of the last sub-step it was solved
   * in, at the final poses after the position projection: the largest of the linear error |C| of
   * its linear equality rows (m: {@link Joint.error} at that moment), the angular error of its
   * locked planes (rad) and the violation of a limit or a rope. 0 for a soft joint (its error is
   * its spring) and before the first step.
   */
  get lastError(): number {
    return this.state[JS_ERROR]!;
  }

  /**
   * Whether the joint ended the last sub-step it was solved in stretched: `lastError` past
   * 10 × `constraintSlop` (1 cm, or 0.01 rad, at the defaults). A rigid joint is never stretched
   * in a scene the solver can hold; a stretched joint says that this one cannot at these
   * settings (raise `subSteps` or lower the time step).
   */
  get stretched(): boolean {
    return this.state[JS_ERROR]! > this.state[JS_STRETCH_LIMIT]!;
  }

  /** How many sub-steps ended with the joint stretched (see {@link Joint.stretched}), since it was built. */
  get stretchCount(): number {
    return this.state[JS_STRETCH_COUNT]!;
  }

  /** The count of degrees of freedom the joint takes away (rows of equality, plus limits). */
  abstract get rowCount(): number;

  /**
   * Makes the joint a spring of `hertz` Hz (0 = rigid) and damping ratio `damping`.
   * @throws TypeError / RangeError for a value that is not a finite number >= 0.
   */
  setSoftness(hertz: number, damping: number): this {
    const fn = `${this.constructor.name}.setSoftness`;
    const h = readNonNegative(fn, 'hertz', hertz);
    const d = readNonNegative(fn, 'damping', damping);
    this.state[JS_HERTZ] = h;
    this.state[JS_DAMPING] = d;
    this.changed();
    return this;
  }

  /**
   * Sets the loads that break the joint: `force` (N) and `torque` (N·m); 0 = never.
   * @throws TypeError / RangeError for a value that is not a finite number >= 0.
   */
  setBreak(force: number, torque: number): this {
    const fn = `${this.constructor.name}.setBreak`;
    const f = readNonNegative(fn, 'force', force);
    const t = readNonNegative(fn, 'torque', torque);
    this.state[JS_BREAK_FORCE] = f;
    this.state[JS_BREAK_TORQUE] = t;
    this.changed();
    return this;
  }

  /**
   * Moves the anchors (null keeps one). The accumulated impulses are kept, so the bodies slide to
   * the new place at a speed bounded by `constraintMaxBias` rather than jump.
   * @throws TypeError / RangeError for an anchor of the wrong length or with a non-finite number.
   */
  setAnchors(localA: ArrayLike<number> | null, localB: ArrayLike<number> | null): this {
    const fn = `${this.constructor.name}.setAnchors`;
    const A = localA === null ? null : readVector(this.D, fn, 'localA', localA);
    const B = localB === null ? null : readVector(this.D, fn, 'localB', localB);
    if (A !== null) this.anchorA.set(A);
    if (B !== null) this.anchorB.set(B);
    this.anchorsChanged();
    this.changed();
    return this;
  }

  /**
   * Adds a listener of the 'broken' event (called once, after the step in which the joint broke).
   * @throws TypeError if `type` is not 'broken' or `listener` is not a function.
   */
  addEventListener(type: 'broken', listener: JointBrokenListener): this {
    checkListener(`${this.constructor.name}.addEventListener`, type, listener);
    (this.listeners ??= []).push(listener);
    return this;
  }

  /** Removes a listener added with {@link Joint.addEventListener} (no effect if it is not there). */
  removeEventListener(type: 'broken', listener: JointBrokenListener): this {
    checkListener(`${this.constructor.name}.removeEventListener`, type, listener);
    const list = this.listeners;
    if (list) {
      const i = list.indexOf(listener);
      if (i >= 0) list.splice(i, 1);
    }
    return this;
  }

  /** @internal Calls the 'broken' listeners (after the step). */
  emitBroken(): void {
    const list = this.listeners;
    if (list === null || list.length === 0) return;
    const event: JointBrokenEvent = { type: 'broken', joint: this };
    for (const fn of list.slice()) fn(event);
  }

  /**
   * The current linear position error (m), from the bodies' current poses: see each joint.
   * Not for the step (it may allocate).
   */
  abstract error(): number;

  /** The current angular error (rad) of the locked planes; 0 for joints without angular rows. */
  angularError(): number {
    return 0;
  }

  /** @internal Writes the rows of this sub-step (see {@link JointSolver}); `j` is the solver index. */
  abstract buildRows(js: JointSolver, j: number): void;

  /**
   * @internal The joint solver of a world, made when the world's first joint is added. The world
   * reaches the solver through its joints and never imports it, so a scene without joints does
   * not carry the solver in its bundle (docs/architecture.md).
   */
  createSolver(D: Dims): JointSolver {
    return new JointSolver(D);
  }

  /**
   * @internal The world's bookkeeping of its joints (adding, removing, breaking), reached through
   * the joints as the solver is, so a scene without joints does not carry it either.
   */
  get worldJoints(): WorldJoints {
    return worldJoints;
  }

  /** @internal Hook: the anchors changed (setAnchors). */
  protected anchorsChanged(): void {}

  /** @internal Wakes the bodies after a change. */
  protected changed(): void {
    this.owner?.onJointChanged(this);
  }
}

function describe(value: unknown): string {
  if (value === null) return 'null';
  if (typeof value !== 'object') return typeof value;
  return (value as { constructor?: { name?: string } }).constructor?.name ?? 'object';
}

function checkListener(fn: string, type: unknown, listener: unknown): void {
  if (type !== 'broken') throw new TypeError(`${fn}: argument 'type' must be 'broken', got ${String(type)}`);
  if (typeof listener !== 'function') throw new TypeError(`${fn}: argument 'listener' must be a function`);
}
