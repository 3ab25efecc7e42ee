/**
 * The world: a set of bodies in n dimensions, gravity, parameters and the step.
 *
 * @module
 */
import { checkInteger, checkNumber, checkVector, MAX_DIMENSION, MIN_DIMENSION } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { Body, MOTION_DYNAMIC, MOTION_STATIC } from './body.js';
import type { BodyOwner } from './body.js';
import { computeBoundsCommon } from './collision/bounds.js';
import { TreeBroadphase } from './collision/broadphase-tree.js';
import type { Broadphase } from './collision/broadphase.js';
import type { BroadphaseBase } from './collision/broadphase-base.js';
import type { Pose } from './collision/manifold.js';
import {
  DEFAULT_AXIS_TOLERANCE,
  DEFAULT_CLIP_TOLERANCE,
  DEFAULT_FEATURE_TIE_TOLERANCE,
  DEFAULT_TORUS_RING_POINTS,
  narrowphaseScratchOf,
} from './collision/narrowphase-scratch.js';
import type { BoxBoxSatKernel } from './collision/narrowphase-scratch.js';
import { DEFAULT_BROADPHASE_MARGIN } from './collision/broadphase-constants.js';
import type { NarrowphaseScratch } from './collision/narrowphase-scratch.js';
import type { QueryShape } from './collision/query-shapes.js';
import { ContactEvents } from './contacts/contact-events.js';
import type { CollisionEvent } from './contacts/contact-events.js';
import { CONTACT_TOUCHING, CONTACT_WAS_TOUCHING, ContactSet, growFloat64 } from './contacts/contact-set.js';
import type { ProxyTables } from './contacts/contact-set.js';
import type { CompoundShape } from './shapes/compound.js';
import type { PairFilter } from './contacts/contact-set.js';
import type { ManifoldCache } from './contacts/manifold-cache.js';
import type { ContactSolver } from './solver/contact-solver.js';
import { AwakeSet, Islands } from './solver/islands.js';
import { SolverBodies } from './solver/solver-bodies.js';
import { NonFiniteStateError } from './errors.js';
import { integratePositions } from './integrator/positions.js';
import { createRotorStepScratch } from './integrator/rotor-step.js';
import type { RotorStepScratch } from './integrator/rotor-step.js';
import {
  createStepSnapshot,
  firstNonFiniteField,
  reserveStepSnapshot,
  restoreBodyStates,
  saveBodyState,
} from './integrator/step-state.js';
import type { StepSnapshot } from './integrator/step-state.js';
import {
  createStepConstants,
  STEP_ANGULAR_SCALE,
  STEP_H,
  STEP_LINEAR_SCALE,
  STEP_ROTOR_ITERATIONS,
  STEP_ROTOR_TOLERANCE,
} from './integrator/step-constants.js';
import { integrateVelocities } from './integrator/velocities.js';
import type { Joint, JointOwner } from './joints/joint.js';
import type { JointSolver } from './joints/joint-solver.js';
import type { WorldJoints } from './joints/world-joints.js';
import { defaultParams, mergeParams, scaledParams } from './params.js';
import { checkComponents, inputLimits } from './shapes/limits.js';
import type { Params } from './params.js';
import { Float64Slab, slabPose } from './slab.js';

/** Where the poses of bodies joining a world are cut from (see slab.ts: one buffer per pose cost more than the rest of addBody). */
const poseSlab = new Float64Slab();

/** What a world holds and what its last sub-step did, counted ({@link WorldBase.stats}). */
export interface WorldStats {
  /** Bodies in the world. */
  readonly bodies: number;
  /** Dynamic bodies that are awake (integrated and solved). */
  readonly awakeBodies: number;
  /**
   * Islands of the awake dynamic bodies: groups linked by touching contacts and joints (static
   * and kinematic bodies link nothing), as the island pass builds them, counted when read.
   * A sleeping island counts 0; two boxes on one floor, apart, count 2.
   */
  readonly islands: number;
  /**
   * Bodies the last sub-step visited (integrated and moved in the broadphase): the awake set,
   * awake dynamic and kinematic bodies. Sleeping and static bodies cost the step nothing.
   */
  readonly bodiesVisited: number;
  /**
   * Contact pairs the last sub-step's narrowphase visited: those with a moving body (awake
   * dynamic or moving kinematic). Pairs of sleeping or static bodies are not visited; the events,
   * the solver and the islands walk the same list.
   */
  readonly pairsVisited: number;
  /** Joints in the world. */
  readonly joints: number;
  /** Pairs of bodies whose grown boxes overlap (the broadphase's pair set, sleeping pairs included). */
  readonly pairs: number;
  /** Contact pairs the world keeps (touching or within the contact margin). */
  readonly contacts: number;
  /** Contact pairs whose manifold has a point closer than the contact margin. */
  readonly touching: number;
  /** Contact points the solver took in the last sub-step. */
  readonly contactPoints: number;
  /**
   * Passes of the velocity solve in the last sub-step: at most `params.iterations` (fewer when the
   * contacts, or the joints of a sub-step without contacts, converged early); 0 when there was
   * nothing to solve.
   */
  readonly solverPasses: number;
  /**
   * Joints that ended the last sub-step stretched: their error past 10 × `constraintSlop` (see
   * `Joint.stretched`). A joint solve that cannot hold its joints shows here, not silently.
   */
  readonly stretchedJoints: number;
}

/** Options of `new World(options)`. */
export interface WorldOptions {
  /** Number of dimensions n (integer, 2..8). */
  readonly dimensions: number;
  /** Acceleration of gravity (m/s², n numbers); default zero. */
  readonly gravity?: ArrayLike<number>;
  /** Parameters that differ from {@link defaultParams} (validated; unknown names are refused). */
  readonly params?: Partial<Params>;
}

/** Preallocated scratch of one world's step (nothing in the step allocates). */
interface WorldScratch {
  readonly rotor: RotorStepScratch;
  /** k numbers for the velocity stage. */
  readonly bivector: Float64Array;
  /** A bounding box (n numbers each). */
  readonly min: Float64Array;
  readonly max: Float64Array;
  /** A half-space's world normal (n numbers). */
  readonly normal: Float64Array;
  /** [0] |v| and [1] |ω| of the body the broadphase stage is on. */
  readonly speeds: Float64Array;
}

/**
 * The Euclidean norm of a[at .. at + len) into `out[slot]`, without overflow for huge finite entries (then
 * scaled by the largest); Infinity or NaN when an entry is not finite.
 *
 * Why an out-parameter: a double returned by a call V8 does not inline is boxed into a fresh heap
 * number, and whether this call is inlined depends on the compiler's budget and timing. Returned,
 * it cost two heap numbers per moving body per sub-step whenever it was not (the allocation test
 * caught it on a busy CI machine).
 */
function robustNormInto(out: Float64Array, slot: number, a: Float64Array, at: number, len: number): void {
  const end = at + len;
  let s = 0;
  for (let i = at; i < end; i += 1) s += a[i]! * a[i]!;
  if (s < Infinity) {
    out[slot] = Math.sqrt(s);
    return;
  }
  let big = 0;
  for (let i = at; i < end; i += 1) big = Math.max(big, Math.abs(a[i]!));
  if (!(big < Infinity)) {
    out[slot] = big;
    return;
  }
  s = 0;
  for (let i = at; i < end; i += 1) {
    const q = a[i]! / big;
    s += q * q;
  }
  out[slot] = big * Math.sqrt(s);
}

/** Passes of the joints' position projection per sub-step (see JointSolver.solvePositions). */
const JOINT_POSITION_ITERATIONS = 3;

const WORLD_OPTION_NAMES = new Set(['dimensions', 'gravity', 'params']);

/**
 * Checks a gravity vector: n finite numbers, each within the acceleration bound of
 * `Body.limits` (a larger gravity would overflow the next step's velocities).
 */
function checkGravity(D: Dims, name: string, g: unknown, fn: string): void {
  checkVector(D, name, g, fn);
  checkComponents(fn, `argument '${name}'`, g as ArrayLike<number>, inputLimits.maxAcceleration, 'm/s²');
}

/**
 * @internal `world` as a world of either entry, or a TypeError naming the argument: the check of
 * the functions that take a world (castRay, queryBox, snapshotWorld).
 */
export function checkWorld(fn: string, world: unknown): WorldBase {
  if (!(world instanceof WorldBase)) {
    throw new TypeError(`${fn}: argument 'world' must be a World, got ${world === null ? 'null' : typeof world}`);
  }
  return world;
}

/** Whether `value` is a joint (the world does not import the Joint class: see Joint.createSolver). */
function isJoint(value: unknown): value is Joint {
  return (
    typeof value === 'object' &&
    value !== null &&
    typeof (value as Joint).createSolver === 'function' &&
    typeof (value as Joint).buildRows === 'function'
  );
}

/** Throws the error of a bad `dt` (TypeError if not a number, RangeError otherwise). */
function throwBadTimeStep(dt: unknown): never {
  const fn = 'World.step';
  checkNumber('dt', dt, fn);
  throw new RangeError(`${fn}: argument 'dt' must be a finite number > 0 (s), got ${dt}`);
}

/**
 * The code chosen by dimension that an entry builds its worlds with, beside the tables. The root
 * entry gives the code of every n; the 3D entry gives the 3D code alone (the 3D rows of the
 * contact solver, the 3D box–box SAT), so a 3D app bundles no other dimension's kernels.
 * @internal
 */
export interface WorldKernels {
  /** Builds the contact solver for the world's tables; `gravity` is the world's own array. */
  readonly contactSolver: (D: Dims, gravity: Float64Array) => ContactSolver;
  /** The box–box separating-axis test for those tables. */
  readonly boxBoxSat: BoxBoxSatKernel;
  /** Builds the contact set's manifold cache (n, points per slot); the general one if absent. */
  readonly manifoldCache?: (n: number, pointsPerSlot: number) => ManifoldCache;
}

/**
 * A world of rigid bodies in n dimensions, whichever tables of dimensions it was built with: the
 * base of {@link World} (every n) and of the World of `@physin/engine/3d` (3D alone, a smaller
 * bundle). Use one of those to build a world; functions that take any world take a WorldBase.
 *
 * `step(dt)` advances it by dt seconds in `params.subSteps` equal sub-steps. Each sub-step reads
 * as the pipeline it is (see {@link WorldBase.step}). Bodies live in `bodies` in the order they
 * were added. Every public method validates its arguments and throws before changing anything.
 */
export class WorldBase {
  /** The tables of the world's dimension. */
  readonly D: Dims;
  /** Number of dimensions. */
  readonly n: number;

  private currentParams: Readonly<Params>;
  /** The parameters as the step reads them: lengths and speeds times `lengthUnit` (params.ts). */
  private stepParams: Readonly<Params>;
  private readonly gravityValue: Float64Array;
  /**
   * The bodies in the order they were added. `removeBody` leaves a hole (null) in O(1) instead of
   * shifting every later body; `compact()` closes the holes in one pass before anything iterates
   * the list (the step, queries, snapshots, `bodies`), so removing N bodies costs O(N), not O(N²).
   */
  private readonly bodyList: Body[] = [];
  /** Holes `removeBody` left in `bodyList` since the last `compact()`. */
  private holes = 0;
  /** The frozen copy `bodies` returns; null when the list changed since it was made. */
  private bodyView: readonly Body[] | null = null;
  private readonly stepState: StepSnapshot;
  private readonly scratch: WorldScratch;
  /** The scalars of the current sub-step, see `step-constants.ts`. */
  private readonly constants: Float64Array;
  /**
   * Simulated time (s), completed steps, and the time {@link WorldBase.advance} has not yet
   * stepped (s): in typed storage so step() boxes no double.
   */
  private readonly clock = new Float64Array(3);

  // ---- collision and contacts (see docs/solver.md) ----
  private readonly broadphase: Broadphase;
  private bodyOfProxy: (Body | null)[] = [];
  /**
   * Per proxy id: its body (the same array as bodyOfProxy), the shape the proxy holds (the body's
   * shape, or one part of a compound), that shape's pose (the body's pose, or the part's), and the
   * part's index (0 for a single shape). The contact set reads them per pair of proxies.
   */
  private readonly proxyTables: ProxyTables;
  /**
   * Per proxy id of a compound body (its `proxyId`, the first part's): the proxy ids of all its
   * parts, in part order; null (or absent) for a body of one shape.
   */
  private partProxies: (Int32Array | null)[] = [];
  private readonly narrowScratch: NarrowphaseScratch;
  private readonly contacts: ContactSet;
  private readonly solverBodies: SolverBodies;
  private readonly solver: ContactSolver;
  private readonly islands = new Islands();
  /** The bodies the step visits (neither static nor asleep), and the step's bookkeeping of them. */
  private readonly awake = new AwakeSet();
  /** Passes of the velocity solve in the last sub-step (a count for `stats`, not state). */
  private solverPasses = 0;
  // ---- joints (see docs/joints.md) ----
  private readonly jointList: Joint[] = [];
  private jointView: readonly Joint[] = Object.freeze([]);
  /** Made by the first joint added (Joint.createSolver), so a world without joints never loads it. */
  private jointSolver: JointSolver | null = null;
  /** @internal The joint bookkeeping, brought by the first joint added (Joint.worldJoints), like the solver. */
  private jointOps: WorldJoints | null = null;
  /** Joints that broke in this step, their events sent after it. */
  private readonly brokenJoints: Joint[] = [];
  private readonly jointOwner: JointOwner = {
    world: this,
    onJointChanged: (joint: Joint): void => {
      joint.a.wake();
      joint.b?.wake();
    },
  };
  /** Per body (world index): the distance it can close in one sub-step (m), for speculative contacts. */
  private reach = new Float64Array(16);
  /**
   * Where the bounds of a body without a pose are computed (see ensurePose); whether a body in
   * the proxy tables has no pose yet.
   */
  private readonly lazyPose: Pose;
  private lazyPoses = false;
  /** @internal Whether the broadphase boxes lag the poses (the queries and snapshots read it). */
  boundsStale = false;
  private readonly events: ContactEvents;
  private readonly collisionEvent: CollisionEvent;
  /** The pair filter (setPairFilter), or null. Not saved in snapshots: a function is code, not state. */
  private filterFn: PairFilter | null = null;
  private readonly setSleeping = (body: Body, asleep: boolean): void => {
    body.sleeping = asleep;
    if (asleep) {
      body.v.fill(0);
      body.L.fill(0);
      body.w.fill(0);
    }
    this.setProxiesAwake(body, !asleep);
    this.syncAwake(body);
  };
  /** The island walk of a wake: wakes `other` if it is a sleeping dynamic body (its timer kept). */
  private readonly wakeOther = (other: Body): void => {
    if (other.motion !== MOTION_DYNAMIC || !other.sleeping) return;
    other.sleeping = false;
    this.setProxiesAwake(other, true);
    this.syncAwake(other);
  };
  private readonly owner: BodyOwner = {
    onBodyChanged: (body: Body): void => {
      if (body.proxyId < 0) return;
      const ids = this.partProxies[body.proxyId];
      if (ids === undefined || ids === null) {
        this.broadphase.setStatic(body.proxyId, body.motion === MOTION_STATIC);
      } else for (let i = 0; i < ids.length; i += 1) this.broadphase.setStatic(ids[i]!, body.motion === MOTION_STATIC);
      this.setProxiesAwake(body, !body.sleeping);
      if (body.poseDirty) this.awake.queueMoved(body);
      this.syncAwake(body);
    },
    onMaterialChanged: (body: Body): void => {
      this.contacts.refreshMaterial(body);
    },
  };

  /**
   * @param tables - the tables of dimension n (the entry's `dims`), called once n is checked.
   * @throws TypeError / RangeError for a bad `dimensions` (not an integer in 2..8, or one the
   *   entry does not build), `gravity` (wrong length, non-finite) or `params` (unknown name,
   *   wrong type or range).
   */
  protected constructor(options: WorldOptions, tables: (n: number) => Dims);
  /**
   * The entries' form: with the code chosen by dimension (see {@link WorldKernels}), which the
   * world does not import, so that each entry bundles its own alone.
   * @internal
   */
  protected constructor(options: WorldOptions, tables: (n: number) => Dims, kernels: WorldKernels);
  protected constructor(options: WorldOptions, tables: (n: number) => Dims, kernels?: WorldKernels) {
    const fn = 'new World';
    // Only the World of an entry can build a world: it has the kernels.
    if (kernels === undefined) throw new TypeError(`${fn}: build the World of @physin/engine or @physin/engine/3d`);
    if (options === null || typeof options !== 'object') {
      throw new TypeError(`${fn}: argument 'options' must be an object { dimensions, gravity?, params? }`);
    }
    for (const key of Object.keys(options)) {
      if (!WORLD_OPTION_NAMES.has(key)) {
        throw new RangeError(`${fn}: unknown option '${key}' (known: dimensions, gravity, params)`);
      }
    }
    checkInteger('dimensions', options.dimensions, MIN_DIMENSION, MAX_DIMENSION, fn);
    const D = tables(options.dimensions);
    if (options.gravity !== undefined) checkGravity(D, 'gravity', options.gravity, fn);
    const params = mergeParams(defaultParams, options.params, fn);
    this.D = D;
    this.n = D.n;
    this.currentParams = params;
    this.stepParams = scaledParams(params);
    this.gravityValue = new Float64Array(D.n);
    if (options.gravity !== undefined) this.gravityValue.set(options.gravity);
    this.stepState = createStepSnapshot(Body.stateLength(D));
    this.scratch = {
      rotor: createRotorStepScratch(D),
      bivector: new Float64Array(D.k),
      min: new Float64Array(D.n),
      max: new Float64Array(D.n),
      normal: new Float64Array(D.n),
      speeds: new Float64Array(2),
    };
    this.constants = createStepConstants();
    this.lazyPose = slabPose(poseSlab, D.n);
    const unit = params.lengthUnit;
    this.broadphase = new TreeBroadphase(D.n, { margin: DEFAULT_BROADPHASE_MARGIN * unit });
    this.narrowScratch = narrowphaseScratchOf(
      kernels.boxBoxSat,
      D.n,
      DEFAULT_AXIS_TOLERANCE,
      DEFAULT_FEATURE_TIE_TOLERANCE * unit,
      DEFAULT_CLIP_TOLERANCE,
      DEFAULT_TORUS_RING_POINTS,
    );
    this.proxyTables = { body: this.bodyOfProxy, shape: [], pose: [], part: [] };
    this.contacts = new ContactSet(D.n, this.proxyTables, kernels.manifoldCache);
    this.solverBodies = new SolverBodies(D);
    this.solver = kernels.contactSolver(D, this.gravityValue);
    this.events = new ContactEvents(D.n);
    this.collisionEvent = {
      type: 'begin',
      body: null as unknown as Body,
      other: null as unknown as Body,
      part: 0,
      otherPart: 0,
      point: new Float64Array(D.n),
      normal: new Float64Array(D.n),
      impulse: 0,
    };
  }

  /**
   * The collision events of the last step (begin / end touching per pair of bodies), in flat
   * typed arrays that the step refills without allocating. See {@link ContactEvents}.
   */
  get contactEvents(): ContactEvents {
    return this.events;
  }

  /** Count of contact pairs the broadphase holds (touching or close). */
  get contactCount(): number {
    return this.contacts.count;
  }

  /** Count of touching contact pairs (a manifold point closer than `contactMargin`). */
  get touchingCount(): number {
    this.contacts.compactOrder();
    let c = 0;
    for (let i = 0; i < this.contacts.count; i += 1) {
      if (this.contacts.flags[this.contacts.order[i]!]! & CONTACT_TOUCHING) c += 1;
    }
    return c;
  }

  /** The current parameters (a frozen object; change them with {@link WorldBase.setParams}). */
  get params(): Readonly<Params> {
    return this.currentParams;
  }

  /**
   * Changes some parameters. All-or-nothing: the whole `partial` is validated first (unknown
   * names, types, ranges) and nothing changes if any entry is bad.
   */
  setParams(partial: Partial<Params>): this {
    const merged = mergeParams(this.currentParams, partial, 'World.setParams');
    if (merged.lengthUnit !== this.currentParams.lengthUnit) {
      throw new RangeError(
        `World.setParams: parameter 'lengthUnit' is set when the world is built (new World); got ${merged.lengthUnit}, the world has ${this.currentParams.lengthUnit}`,
      );
    }
    this.currentParams = merged;
    this.stepParams = scaledParams(merged);
    return this;
  }

  /** The pair filter given to {@link WorldBase.setPairFilter}, or null. */
  get pairFilter(): PairFilter | null {
    return this.filterFn;
  }

  /**
   * Sets a pair filter, or removes it (null): a function of the two bodies of a pair whose boxes
   * overlap, asked each time the narrowphase would collide them (once per sub-step while one of
   * them moves); false means no contact, as if their groups and masks kept them apart
   * (`Body.collisionGroup`, `Body.collisionMask`). It must not throw or change the world, and it
   * should allocate nothing (it runs in the step). Every body wakes, so that resting pairs are
   * asked too. Snapshots do not hold it: set it again on a restored world.
   * @throws TypeError unless a function or null.
   */
  setPairFilter(filter: PairFilter | null): this {
    if (filter !== null && typeof filter !== 'function') {
      throw new TypeError(
        `World.setPairFilter: argument 'filter' must be a function (a, b) => boolean or null, got ${typeof filter}`,
      );
    }
    this.filterFn = filter;
    this.compact();
    for (const body of this.bodyList) body.wake();
    return this;
  }

  /** A copy of the gravity vector (m/s², n numbers). */
  get gravity(): Float64Array {
    return Float64Array.from(this.gravityValue);
  }

  /** Sets gravity (m/s², n finite numbers). */
  setGravity(g: ArrayLike<number>): this {
    checkGravity(this.D, 'g', g, 'World.setGravity');
    this.gravityValue.set(g);
    return this;
  }

  /** The bodies, in the order they were added (a frozen array, replaced when the list changes). */
  get bodies(): readonly Body[] {
    // Made when asked for, not on every add: adding N bodies copied the list N times (O(N²)).
    this.compact();
    return (this.bodyView ??= Object.freeze(this.bodyList.slice()));
  }

  /**
   * What the world holds and what its last sub-step did, counted: for profiling, and for tests
   * that would otherwise read private fields. A fresh object per call (not for the hot path).
   */
  get stats(): WorldStats {
    this.compact();
    const set = this.awake;
    set.sort();
    let awake = 0;
    for (let i = 0; i < set.count; i += 1) if (set.list[i]!.motion === MOTION_DYNAMIC) awake += 1;
    return Object.freeze({
      bodies: this.bodyList.length,
      awakeBodies: awake,
      islands: this.islands.count(set, this.contacts, this.jointList),
      bodiesVisited: set.visitedBodies,
      pairsVisited: set.visitedPairs,
      joints: this.jointList.length,
      pairs: this.broadphase.pairCount,
      contacts: this.contacts.count,
      touching: this.touchingCount,
      contactPoints: this.solver.pointCount,
      solverPasses: this.solverPasses,
      stretchedJoints: this.stretchedJointCount(),
    });
  }

  /** Simulated time (s): the sum of the dt of every completed step. */
  get time(): number {
    return this.clock[0]!;
  }

  /** Number of completed steps. */
  get stepCount(): number {
    return this.clock[1]!;
  }

  /**
   * How far the time given to {@link WorldBase.advance} has run into the next fixed step, in
   * [0, 1): draw bodies at `previous + alpha·(current − previous)` for motion without judder.
   */
  get alpha(): number {
    return Math.max(0, this.clock[2]! / this.currentParams.fixedTimeStep);
  }

  /**
   * Advances the world by `elapsed` seconds of frame time in fixed steps of
   * `params.fixedTimeStep`, as a frame loop should: the time left over carries into the next
   * call, and at most `maxSteps` steps run (the backlog beyond them is dropped, so a slow frame
   * cannot make the next one slower still). A world stepped this way with frames of any length
   * goes through exactly the states of one stepped by `step()` alone: the step is what sets the
   * accuracy, and a varying `dt` given to `step` would change it every frame (docs/engine.md,
   * "Fixed steps"). The three.js adapter's `scene.simulate` accumulates the same way in the host.
   *
   * @param elapsed - seconds since the last call (finite, >= 0).
   * @param maxSteps - most steps to run in this call (integer >= 1, default 4).
   * @returns the number of steps run.
   * @throws TypeError / RangeError for a bad `elapsed` or `maxSteps` (nothing changes);
   *   NonFiniteStateError as {@link WorldBase.step} (the steps completed before it stay).
   */
  advance(elapsed: number, maxSteps = 4): number {
    const fn = 'World.advance';
    checkNumber('elapsed', elapsed, fn);
    if (!(elapsed >= 0) || elapsed === Infinity)
      throw new RangeError(`${fn}: argument 'elapsed' must be a finite number >= 0 (s), got ${elapsed}`);
    checkInteger('maxSteps', maxSteps, 1, Number.MAX_SAFE_INTEGER, fn);
    const h = this.currentParams.fixedTimeStep;
    const c = this.clock;
    c[2] = c[2]! + elapsed;
    let steps = 0;
    // A step is due when the time left reaches h less rounding: three frames of 1/180 s make one
    // step of 1/60 s although their float sum falls short of 1/60 by an ulp.
    while (c[2]! >= h * (1 - 1e-9) && steps < maxSteps) {
      this.step(h);
      c[2] = c[2]! - h;
      steps += 1;
    }
    if (c[2]! >= h) c[2] = c[2]! % h;
    return steps;
  }

  /**
   * Adds a body and returns it.
   * @throws TypeError if `body` is not a Body; RangeError if its dimension differs from the
   *   world's, or it already belongs to this or another world.
   */
  addBody(body: Body): Body {
    const fn = 'World.addBody';
    if (!(body instanceof Body)) {
      throw new TypeError(`${fn}: argument 'body' must be a Body, got ${body === null ? 'null' : typeof body}`);
    }
    if (body.D.n !== this.n) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) has n = ${body.D.n} but the world has n = ${this.n}`);
    }
    if (body.owner === this.owner) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) is already in this world`);
    }
    if (body.owner !== null) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) already belongs to another world; remove it there first`);
    }
    // Bounds first: a body so far out that its box overflows is refused before anything changes.
    const sc = this.scratch;
    const isHalfSpace = body.shape.kind === 'halfspace';
    const compound = body.shape.kind === 'compound' ? (body.shape as unknown as CompoundShape) : null;
    // A plain body gets its pose when something reads it (ensurePose): 32,000 poses, about 280
    // bytes each, were half of what the collector moved when a world was built.
    if (body.pose?.x.length !== this.n) body.pose = isHalfSpace || compound !== null ? slabPose(poseSlab, this.n) : null;
    this.updatePose(body);
    const partPoses: Pose[] = [];
    let finite = 0;
    // One proxy per part: each part's box must be finite.
    if (compound !== null) finite = compound.worldOps.newPartPoses(this.n, body.pose!, compound, sc.min, sc.max, partPoses);
    else if (isHalfSpace) this.halfSpacePlane(body);
    else this.boundsOf(body);
    if (compound === null) finite = isHalfSpace ? sc.max[0]! * 0 : 0;
    for (let i = 0; i < this.n && compound === null; i += 1)
      finite += isHalfSpace ? sc.normal[i]! * 0 : sc.min[i]! * 0 + sc.max[i]! * 0;
    if (finite !== 0) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) is so far from the origin that its bounding box overflows`);
    }
    reserveStepSnapshot(this.stepState, this.bodyList.length + 1);
    this.reach = growFloat64(this.reach, this.bodyList.length + 1);
    body.owner = this.owner;
    body.worldIndex = this.bodyList.length;
    body.sleeping = false;
    body.sleepTimer = 0;
    body.poseDirty = false;
    this.bodyList.push(body);
    this.bodyView = null;
    this.reach[body.worldIndex] = 0;
    this.awake.reserve(this.bodyList.length);
    this.awake.sync(body);
    const bp = this.broadphase;
    if (compound !== null) {
      const isStatic = body.motion === MOTION_STATIC;
      const ids = compound.worldOps.createPartProxies(this.n, compound, partPoses, bp, isStatic, sc.min, sc.max);
      body.proxyId = ids[0]!;
      this.setBodyProxies(body, ids, partPoses);
      return body;
    }
    body.proxyId = isHalfSpace
      ? bp.createHalfSpaceProxy(sc.normal, sc.max[0]!)
      : bp.createProxy(sc.min, sc.max, body.motion === MOTION_STATIC);
    this.setBodyProxies(body, null, null);
    return body;
  }

  /**
   * Removes a body (its state is kept; it may be added again, here or to another world). The
   * bodies it touched wake (what rested on it falls), and each touching pair ends with an 'end'
   * event in the events of the next step.
   * @throws TypeError if `body` is not a Body; RangeError if it is not in this world.
   */
  removeBody(body: Body): this {
    const fn = 'World.removeBody';
    if (!(body instanceof Body)) {
      throw new TypeError(`${fn}: argument 'body' must be a Body, got ${body === null ? 'null' : typeof body}`);
    }
    const index = body.owner === this.owner ? body.worldIndex : -1;
    if (index < 0) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) is not in this world`);
    }
    if (body.jointCount > 0) {
      throw new RangeError(
        `${fn}: argument 'body' (${body.label}) is held by ${body.jointCount} joint(s) of this world; remove them first (World.removeConstraint)`,
      );
    }
    // A hole, closed by compact() before the list is next iterated (the type says Body: no code
    // reads the list between here and there).
    this.bodyList[index] = null as unknown as Body;
    this.holes += 1;
    // Out of the awake set before anything wakes (compact() rebuilds the set after the holes).
    body.sleeping = true;
    this.awake.sync(body);
    this.contacts.removeBody(body, this.events);
    const ids = this.partProxies[body.proxyId];
    if (ids !== undefined && ids !== null) {
      this.partProxies[body.proxyId] = null;
      for (let i = 0; i < ids.length; i += 1) this.clearProxy(ids[i]!);
    } else this.clearProxy(body.proxyId);
    body.proxyId = -1;
    body.worldIndex = -1;
    body.sleeping = false;
    body.owner = null;
    this.bodyView = null;
    return this;
  }

  /**
   * How many times a joint of this world ended a sub-step stretched (its error past
   * 10 × `constraintSlop`; `Joint.stretched`), summed over the joints now in the world: a counter
   * to watch (or test) that joints hold. Kept by the joints, so a snapshot keeps it.
   */
  get jointErrorCount(): number {
    let sum = 0;
    for (const joint of this.jointList) sum += joint.stretchCount;
    return sum;
  }

  private stretchedJointCount(): number {
    let count = 0;
    for (const joint of this.jointList) if (joint.stretched) count += 1;
    return count;
  }

  /** The joints of the world, in the order they were added (a frozen array, replaced when the list changes). */
  get constraints(): readonly Joint[] {
    return this.jointView;
  }

  /**
   * Adds a joint (see docs/joints.md) and returns it. Its bodies wake. With collideConnected
   * false (the default) the two bodies stop colliding with each other.
   * @throws TypeError if `joint` is not a Joint; RangeError if its dimension differs, a body of it
   *   is not in this world, it is already in this or another world, or it broke. Nothing changes.
   */
  addConstraint<J extends Joint>(joint: J): J {
    if (!isJoint(joint)) {
      throw new TypeError(
        `World.addConstraint: argument 'joint' must be a joint (PointJoint, DistanceJoint, FixedJoint, HingeJoint, SubspaceJoint), got ${joint === null ? 'null' : typeof joint}`,
      );
    }
    (this.jointOps ??= joint.worldJoints).add(this, joint);
    // The joint solver reads its bodies' poses.
    this.ensurePose(joint.a);
    this.ensurePose(joint.b);
    return joint;
  }

  /**
   * Removes a joint; its bodies wake (and may collide with each other again).
   * @throws TypeError if `joint` is not a Joint; RangeError if it is not in this world.
   */
  removeConstraint(joint: Joint): this {
    const fn = 'World.removeConstraint';
    if (!isJoint(joint)) {
      throw new TypeError(`${fn}: argument 'joint' must be a joint, got ${joint === null ? 'null' : typeof joint}`);
    }
    if (joint.owner !== this.jointOwner) throw new RangeError(`${fn}: argument 'joint' is not in this world`);
    this.jointOps!.remove(this, joint);
    return this;
  }

  /**
   * Advances the world by `dt` seconds (default `params.fixedTimeStep`) in `params.subSteps` equal
   * sub-steps h = dt / subSteps. Each sub-step, top to bottom:
   *
   * 1. forces → velocities: v += h (F/m + g), L += h τ, damping (awake dynamic bodies);
   * 2. broadphase: the boxes of the bodies that move, grown by the distance each can close in
   *    this sub-step, then the pairs that start or stop overlapping;
   * 3. narrowphase: the manifold of every pair with an awake body, impulses matched by feature id;
   * 4. contact and joint solver on v and L (prepare, warm start, iterations — joints then contacts
   *    in each — shock propagation, restitution, joint impulses stored and breaking checked);
   * 5. velocities → positions: x += h v, the midpoint rotor step under fixed L, rotor correction,
   *    ω rebuilt from L; kinematic bodies move by their own v and ω; each body is then checked for
   *    non-finite numbers;
   * 6. events (begin / end touching) and islands: sleep timers, whole islands sleep or wake.
   *
   * After the last sub-step the accumulated forces and torques are cleared and the body
   * listeners are called.
   *
   * @param timeStep seconds; default `params.fixedTimeStep`
   * @throws TypeError / RangeError if timeStep is not a finite number > 0 (nothing changes).
   * @throws NonFiniteStateError if a body's state became non-finite: every body is restored to
   *   its state before this call and the error names the body and the field.
   */
  step(timeStep?: number): this {
    // A local, not a default parameter: `dt = default` would merge the tagged argument with the
    // double read from params and box it, 16 bytes a step for every caller that passes nothing.
    // Checked in place (not through a shared helper) so the hot call boxes nothing.
    if (timeStep !== undefined && typeof timeStep !== 'number') throwBadTimeStep(timeStep);
    const dt = timeStep === undefined ? this.currentParams.fixedTimeStep : +timeStep;
    if (!(dt > 0) || dt === Infinity) throwBadTimeStep(dt);
    this.compact();
    const D = this.D;
    const p = this.stepParams;
    const awake = this.awake;
    const subSteps = p.subSteps;
    const h = dt / subSteps;
    const c = this.constants;
    c[STEP_H] = h;
    c[STEP_ROTOR_TOLERANCE] = p.rotorTolerance;
    c[STEP_ROTOR_ITERATIONS] = p.gyroscopic ? p.gyroscopicIterations : 0;
    c[STEP_LINEAR_SCALE] = p.linearDamping > 0 ? 1 / (1 + h * p.linearDamping) : 1;
    c[STEP_ANGULAR_SCALE] = p.angularDamping > 0 ? 1 / (1 + h * p.angularDamping) : 1;
    // Only the awake bodies are saved (a sleeping body does not change in a step; one that wakes
    // during it is saved as it wakes, see syncAwake).
    awake.sort();
    awake.beginStep();
    awake.inStep = true;
    for (let b = 0; b < awake.count; b += 1) {
      const body = awake.list[b]!;
      awake.markSaved(body);
      saveBodyState(this.stepState, body);
    }
    this.events.clear();
    for (let s = 0; s < subSteps; s += 1) {
      awake.sort();
      integrateVelocities(D, awake.list, awake.count, this.gravityValue, c, this.scratch.bivector);
      const unbounded = this.updateBroadphase();
      if (unbounded !== null) this.failStep(unbounded, s, subSteps);
      const bp = this.broadphase as BroadphaseBase;
      this.contacts.gatherActive(awake.list, awake.count);
      awake.visitedPairs = this.contacts.activeCount;
      this.contacts.updateManifolds(p, this.reach, this.narrowScratch, bp.tightMin, bp.tightMax, this.filterFn);
      this.solveContacts(p);
      const js = this.jointSolver;
      if (js !== null && js.brokenCount > 0) this.jointOps!.breakJoints(this, js);
      // (with the bodies the solver woke)
      awake.sort();
      awake.visitedBodies = awake.count;
      const bad = integratePositions(D, awake.list, awake.count, c, this.scratch.rotor);
      if (bad >= 0) this.failStep(awake.list[bad]!, s, subSteps);
      if (js !== null && js.count > 0) js.solvePositions(this.solverBodies, JOINT_POSITION_ITERATIONS);
      for (let b = 0; b < awake.count; b += 1) {
        const body = awake.list[b]!;
        if (body.motion !== MOTION_STATIC && !body.sleeping) this.updatePose(body);
      }
      this.recordEvents();
      if (p.allowSleep) {
        this.islands.update(awake, this.contacts, c, p, this.setSleeping, this.jointList);
      }
    }
    this.boundsStale = true;
    awake.inStep = false;
    // Forces wake a body: every body with a force was awake during the step, hence saved.
    for (let b = 0; b < awake.savedCount; b += 1) awake.saved[b]!.clearForces();
    this.clock[0] = this.clock[0]! + dt;
    this.clock[1] = this.clock[1]! + 1;
    if (this.events.beginCount > 0 || this.events.endCount > 0) this.dispatchEvents();
    if (this.brokenJoints.length > 0) this.jointOps!.dispatchBroken(this);
    return this;
  }

  // ---- the stages behind step() ----

  /**
   * Closes the holes of `bodyList` in one pass, keeping the order; renumbers the bodies and moves
   * their reach along. O(bodies) once after any number of removals.
   */
  private compact(): void {
    this.contacts.compactOrder();
    if (this.holes === 0) {
      if (this.awake.stale) {
        this.awake.stale = false;
        this.awake.rebuild(this.bodyList);
      }
      return;
    }
    const list = this.bodyList;
    const reach = this.reach;
    let o = 0;
    for (let i = 0; i < list.length; i += 1) {
      const body = list[i];
      if (body === null || body === undefined) continue;
      body.worldIndex = o;
      reach[o] = reach[i]!;
      list[o] = body;
      o += 1;
    }
    list.length = o;
    this.holes = 0;
    this.awake.stale = false;
    this.awake.rebuild(list);
  }

  /**
   * Puts `body` in the awake set or takes it out, after its sleep state or motion changed. A body
   * that joins during a step has its state saved first (the step may be undone); a dynamic body
   * that wakes wakes its island, by a walk over touching contacts and joints: O(island).
   */
  private syncAwake(body: Body): void {
    const awake = this.awake;
    if (awake.stale || body.worldIndex < 0) return; // (rebuilt before the next use)
    if (!awake.sync(body)) return;
    if (!awake.has(body)) {
      this.reach[body.worldIndex] = 0;
      return;
    }
    if (awake.inStep && awake.markSaved(body)) saveBodyState(this.stepState, body);
    if (body.motion !== MOTION_DYNAMIC) return;
    const pending = awake.pending;
    pending.push(body);
    if (awake.waking) return; // the walk under way takes it
    awake.waking = true;
    while (pending.length > 0) {
      const b = pending.pop()!;
      this.contacts.forEachTouching(b, this.wakeOther);
      if (b.jointCount === 0) continue;
      const joints = this.jointList;
      for (let j = 0; j < joints.length; j += 1) {
        const joint = joints[j]!;
        if (joint.a === b && joint.b !== null) this.wakeOther(joint.b);
        else if (joint.b === b) this.wakeOther(joint.a);
      }
    }
    awake.waking = false;
  }

  /** pose.x = body.x, pose.M = the matrix of body.R (nothing for a body without a pose). */
  private updatePose(body: Body): void {
    const pose = body.pose;
    if (pose === null) return;
    this.fillPose(body, pose);
    // (addBody reads the pose before the body has a proxy: partProxies[-1] is a slow lookup by name)
    const id = body.proxyId;
    if (id < 0) return;
    const ids = this.partProxies[id];
    if (ids !== undefined && ids !== null) {
      const compound = body.shape as unknown as CompoundShape;
      compound.worldOps.updatePartPoses(this.n, pose, compound, ids, this.proxyTables.pose);
    }
  }

  /**
   * Gives a body of this world without a pose its own, from its record. A pose always equals the
   * record when it is read (the step and the queries refresh the poses of bodies moved by hand
   * first), so a pose made late holds what one kept since addBody would.
   */
  private ensurePose(body: Body | null | undefined): void {
    if (body?.pose === null) this.fillPose(body, (this.proxyTables.pose[body.proxyId] = body.pose = slabPose(poseSlab, this.n)));
  }

  /** The record's x and the matrix of its R into `pose`. */
  private fillPose(body: Body, pose: Pose): void {
    // A loop, not pose.x.set(): a builtin call costs more than copying n numbers.
    // Read from the record: the body's views are made only when something asks for them.
    const px = pose.x;
    const s = body.storage;
    const at = body.storageOffset;
    const n = px.length;
    for (let i = 0; i < n; i += 1) px[i] = s[at + i]!;
    const R = this.scratch.rotor.turn; // (scratch of the rotor step, free here: r numbers)
    for (let i = 0; i < R.length; i += 1) R[i] = s[at + n + i]!;
    this.D.kernels.toMatrix(pose.M, R);
  }

  /**
   * Fills the proxy tables of `body`: one proxy (`ids` null: its `proxyId`, its shape and pose),
   * or one per part of a compound (`ids`, with the parts' poses).
   */
  private setBodyProxies(body: Body, ids: Int32Array | null, poses: Pose[] | null): void {
    const t = this.proxyTables;
    if (ids === null) {
      const id = body.proxyId;
      this.bodyOfProxy[id] = body;
      t.shape[id] = body.shape;
      t.pose[id] = body.pose;
      if (body.pose === null) this.lazyPoses = true;
      t.part[id] = 0;
      this.partProxies[id] = null;
      return;
    }
    const compound = body.shape as unknown as CompoundShape;
    for (let i = 0; i < ids.length; i += 1) {
      const id = ids[i]!;
      this.bodyOfProxy[id] = body;
      t.shape[id] = compound.parts[i]!;
      t.pose[id] = poses![i]!;
      t.part[id] = i;
      this.partProxies[id] = null;
    }
    this.partProxies[ids[0]!] = ids;
  }

  /** Destroys proxy `id` and clears its entries of the proxy tables. */
  private clearProxy(id: number): void {
    this.broadphase.destroyProxy(id);
    this.bodyOfProxy[id] = null;
    this.proxyTables.shape[id] = null;
    this.proxyTables.pose[id] = null;
    this.proxyTables.part[id] = 0;
  }

  /** Marks every proxy of `body` (one, or one per part) awake or asleep in the broadphase. */
  private setProxiesAwake(body: Body, awake: boolean): void {
    const ids = this.partProxies[body.proxyId];
    if (ids === undefined || ids === null) this.broadphase.setAwake(body.proxyId, awake);
    else for (let i = 0; i < ids.length; i += 1) this.broadphase.setAwake(ids[i]!, awake);
  }

  /** The world plane of a half-space body into scratch: normal in `normal`, offset in max[0]. */
  private halfSpacePlane(body: Body): void {
    const shape = body.shape as unknown as { normal: Float64Array; offset: number };
    const n = this.n;
    const M = body.pose!.M;
    const N = this.scratch.normal;
    let off = shape.offset;
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      for (let c2 = 0; c2 < n; c2 += 1) s += M[i * n + c2]! * shape.normal[c2]!;
      N[i] = s;
      off += s * body.x[i]!;
    }
    this.scratch.max[0] = off;
  }

  /**
   * The body's bounding box grown by its reach (see updateBroadphase) into scratch min / max.
   * (The reach is added here rather than passed as the margin: a double argument to a call that
   * is not inlined is boxed, and this runs for every moving body in every sub-step.)
   */
  private bodyBounds(body: Body): void {
    this.boundsOf(body);
    const grow = this.reach[body.worldIndex]!;
    if (grow > 0) {
      const { min, max } = this.scratch;
      for (let i = 0; i < this.n; i += 1) {
        min[i] = min[i]! - grow;
        max[i] = max[i]! + grow;
      }
    }
  }

  /** The body's tight bounding box into scratch min / max. */
  private boundsOf(body: Body): void {
    let pose = body.pose;
    if (pose === null) this.fillPose(body, (pose = this.lazyPose));
    computeBoundsCommon(this.scratch.min, this.scratch.max, this.n, body.shape as unknown as QueryShape, pose.x, pose.M, 0);
  }

  /** Moves the proxy of a body to its current pose (a half-space by its plane). */
  private moveProxy(body: Body): void {
    const ids = this.partProxies[body.proxyId];
    if (ids !== undefined && ids !== null) {
      const { min, max } = this.scratch;
      const t = this.proxyTables;
      (body.shape as unknown as CompoundShape).worldOps.moveParts(
        this.n,
        ids,
        t.shape,
        t.pose,
        this.reach,
        body.worldIndex,
        min,
        max,
        this.broadphase,
      );
    } else if (body.shape.kind === 'halfspace') {
      this.halfSpacePlane(body);
      this.broadphase.moveHalfSpace(body.proxyId, this.scratch.normal, this.scratch.max[0]!);
    } else {
      this.bodyBounds(body);
      const { min, max } = this.scratch;
      let finite = 0;
      for (let i = 0; i < this.n; i += 1) finite += min[i]! * 0 + max[i]! * 0;
      // A body at the edge of overflow keeps its last box; its own step then fails by name.
      if (finite === 0) this.broadphase.moveProxy(body.proxyId, min, max);
    }
  }

  /**
   * Stage 2: every moving body's box, grown by its reach h·(|v| + |ω|·radius) (the most its
   * surface can travel in the sub-step), and bodies moved by hand; then the broadphase's pair
   * changes go to the contact set. Returns the index of a body whose velocity is not finite (the
   * step is then undone before anything reads it), or -1.
   */
  private updateBroadphase(): Body | null {
    const awake = this.awake;
    // Bodies moved by hand (static ones too); an awake one is moved below with the others.
    for (let i = 0; i < awake.movedCount; i += 1) {
      const body = awake.moved[i]!;
      if (!body.poseDirty || body.worldIndex < 0) continue;
      this.updatePose(body);
      body.poseDirty = false;
      if (!awake.has(body) && !this.reachAndMove(body)) return body;
    }
    awake.clearMoved();
    for (let b = 0; b < awake.count; b += 1) {
      const body = awake.list[b]!;
      if (body.poseDirty) {
        this.updatePose(body);
        body.poseDirty = false;
      }
      if (!this.reachAndMove(body)) return body;
    }
    const bp = this.broadphase;
    bp.updatePairs();
    // The narrowphase reads the poses of a new pair's bodies (fresh here: moved bodies were read above).
    for (let i = 0; this.lazyPoses && i < 2 * bp.addedCount; i += 1) this.ensurePose(this.bodyOfProxy[bp.addedPairs[i]!]);
    this.contacts.applyPairChanges(bp.removedPairs, bp.removedCount, bp.addedPairs, bp.addedCount, this.bodyOfProxy, this.events);
    return null;
  }

  /**
   * The body's reach h·(|v| + |ω|·radius) and its proxy moved to its pose, grown by it. False when
   * a velocity is not finite (the step is then undone).
   */
  private reachAndMove(body: Body): boolean {
    const speeds = this.scratch.speeds;
    const D = this.D;
    const v = body.storageOffset + Body.velocityOffset(D); // then L (k numbers), then w
    robustNormInto(speeds, 0, body.storage, v, D.n);
    robustNormInto(speeds, 1, body.storage, v + D.n + D.k, D.k);
    const speed = speeds[0]!;
    const spin = speeds[1]!;
    if (!(speed < Infinity) || !(spin < Infinity)) return false;
    const r = this.constants[STEP_H]! * (speed + spin * body.boundingRadius);
    if (!(r < Infinity)) return true; // finite but beyond reach of any box: nothing can meet it
    this.reach[body.worldIndex] = r;
    this.moveProxy(body);
    return true;
  }

  /**
   * Stage 4: the contact and joint solver of this sub-step. Contacts are prepared first, then the
   * joints (which give their bodies solver slots); with contacts and a joint tree, the contacts are
   * prepared again with the tree's stiffened inertia (JointSolver.stiffenInertia, restored before
   * the write-back); warm start joints then contacts; in each of the
   * `iterations` passes the joints, then the contacts; shock propagation and restitution (contacts
   * only); the impulses are stored (joints: loads and breaking) and v, L written back.
   */
  private solveContacts(p: Readonly<Params>): void {
    const sb = this.solverBodies;
    const solver = this.solver;
    const joints = this.jointSolver;
    sb.reset();
    // The solver sees the active slots alone (those with a moving body).
    const view = this.contacts.solverContacts();
    const points = solver.prepare(view, sb, this.constants, p);
    // With no joint left, nothing of the last prepare may be solved again (solvePositions reads
    // joints.count): a world whose last joint was removed hung in its next step.
    if (joints !== null && this.jointList.length === 0) joints.count = 0;
    const jointCount = joints !== null && this.jointList.length > 0 ? joints.prepare(this.jointList, sb, this.constants, p) : 0;
    // Contacts in the passes of a tree's joints: both solve with the tree's stiffened inertia.
    if (points > 0 && jointCount > 0 && joints!.stiffenInertia(sb) > 0) solver.prepare(view, sb, this.constants, p);
    this.solverPasses = 0;
    if (joints === null || jointCount === 0) {
      if (joints !== null) joints.brokenCount = 0;
      if (points === 0) return;
      if (p.useWarmStart) solver.warmStart(sb);
      solver.solve(sb, p.iterations);
      this.solverPasses = solver.passesRun;
    } else {
      this.solverPasses = p.iterations;
      if (p.useWarmStart) {
        joints.warmStart(sb);
        if (points > 0) solver.warmStart(sb);
      }
      for (let it = 0; it < p.iterations; it += 1) {
        joints.pass(sb);
        if (points > 0) solver.iterate(sb);
        else if (joints.treeOnly === 1 || joints.passChanged() === 0) {
          // No contact, and either the tree's rows alone (the first pass met them exactly; the rest
          // would find every velocity as it left them: the same bits) or no joint row moved by more
          // than `solverTolerance`: the passes left would not move them either.
          this.solverPasses = it + 1;
          break;
        }
      }
      joints.store();
    }
    if (points > 0) {
      if (p.useShockPropagation) solver.shockPropagate(sb, p.shockIterations);
      solver.restitution(sb);
      solver.store(view);
    }
    if (joints !== null) joints.restoreInertia(sb);
    sb.writeBack();
  }

  /** Stage 6a: begin / end events from the touching flags of this sub-step. */
  private recordEvents(): void {
    const contacts = this.contacts;
    // (a pair of sleeping or static bodies keeps its touching state: no event)
    for (let i = 0; i < contacts.activeCount; i += 1) {
      const slot = contacts.active[i]!;
      const f = contacts.flags[slot]!;
      const now = (f & CONTACT_TOUCHING) !== 0;
      const before = (f & CONTACT_WAS_TOUCHING) !== 0;
      if (now === before) continue;
      const A = contacts.bodyA[slot]!;
      const B = contacts.bodyB[slot]!;
      if (now) {
        this.events.pushBegin(contacts, slot);
      } else {
        this.events.pushEnd(A, B, contacts.partA[slot]!, contacts.partB[slot]!);
      }
    }
  }

  /** Calls the collision listeners of the bodies in this step's events (after the step). */
  private dispatchEvents(): void {
    const ev = this.events;
    const e = this.collisionEvent;
    const n = this.n;
    for (let i = 0; i < ev.beginCount; i += 1) {
      const A = ev.beginA[i]!;
      const B = ev.beginB[i]!;
      if (!A.hasListeners && !B.hasListeners) continue;
      e.type = 'begin';
      e.impulse = ev.beginImpulse[i]!;
      for (let side = 0; side < 2; side += 1) {
        e.body = side === 0 ? A : B;
        e.other = side === 0 ? B : A;
        e.part = side === 0 ? ev.beginPartA[i]! : ev.beginPartB[i]!;
        e.otherPart = side === 0 ? ev.beginPartB[i]! : ev.beginPartA[i]!;
        const sign = side === 0 ? 1 : -1;
        for (let d = 0; d < n; d += 1) {
          e.point[d] = ev.beginPoint[i * n + d]!;
          e.normal[d] = sign * ev.beginNormal[i * n + d]!;
        }
        e.body.emitCollision(e);
      }
    }
    for (let i = 0; i < ev.endCount; i += 1) {
      const A = ev.endA[i]!;
      const B = ev.endB[i]!;
      if (!A.hasListeners && !B.hasListeners) continue;
      e.type = 'end';
      e.impulse = 0;
      e.point.fill(0);
      e.normal.fill(0);
      for (let side = 0; side < 2; side += 1) {
        e.body = side === 0 ? A : B;
        e.other = side === 0 ? B : A;
        e.part = side === 0 ? ev.endPartA[i]! : ev.endPartB[i]!;
        e.otherPart = side === 0 ? ev.endPartB[i]! : ev.endPartA[i]!;
        e.body.emitCollision(e);
      }
    }
  }

  /** Undoes the current step and throws the error that names the body. */
  private failStep(body: Body, subStep: number, subSteps: number): never {
    const field = firstNonFiniteField(body) ?? 'x';
    const awake = this.awake;
    awake.inStep = false;
    restoreBodyStates(this.stepState, awake.saved, awake.savedCount);
    throw new NonFiniteStateError(body, field, subStep, subSteps);
  }
}
