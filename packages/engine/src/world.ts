/**
 * The world: a set of bodies in n dimensions, gravity, parameters and the step.
 *
 * @module
 */
import { checkInteger, checkNumber, checkVector, dims, MAX_DIMENSION, MIN_DIMENSION } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { Body } from './body.js';
import { NonFiniteStateError } from './errors.js';
import { integratePositions } from './integrator/positions.js';
import { createRotorStepScratch } from './integrator/rotor-step.js';
import type { RotorStepScratch } from './integrator/rotor-step.js';
import {
  createStepSnapshot,
  firstNonFiniteField,
  reserveStepSnapshot,
  restoreStepState,
  saveStepState,
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
import { defaultParams, mergeParams } from './params.js';
import type { Params } from './params.js';

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
}

const WORLD_OPTION_NAMES = new Set(['dimensions', 'gravity', 'params']);

/** Throws the error of a bad `dt` (TypeError if not a number, RangeError otherwise). */
function throwBadTimeStep(dt: unknown): never {
  const fn = 'World.step';
  checkNumber('dt', dt, fn);
  throw new RangeError(`${fn}: argument 'dt' must be a finite number > 0 (s), got ${dt}`);
}

/**
 * A world of rigid bodies in n dimensions.
 *
 * `step(dt)` advances it by dt seconds in `params.subSteps` equal sub-steps. Each sub-step reads
 * as the pipeline it is (see {@link World.step}). Bodies live in `bodies` in the order they were
 * added. Every public method validates its arguments and throws before changing anything.
 */
export class World {
  /** The tables of the world's dimension. */
  readonly D: Dims;
  /** Number of dimensions. */
  readonly n: number;

  private currentParams: Readonly<Params>;
  private readonly gravityValue: Float64Array;
  private readonly bodyList: Body[] = [];
  private bodyView: readonly Body[] = Object.freeze([]);
  private readonly snapshot: StepSnapshot;
  private readonly scratch: WorldScratch;
  /** The scalars of the current sub-step, see `step-constants.ts`. */
  private readonly constants: Float64Array;
  /** [simulated time (s), completed steps]: kept in typed storage so step() boxes no double. */
  private readonly clock = new Float64Array(2);

  /**
   * @throws TypeError / RangeError for a bad `dimensions` (not an integer in 2..8), `gravity`
   *   (wrong length, non-finite) or `params` (unknown name, wrong type or range).
   */
  constructor(options: WorldOptions) {
    const fn = 'new World';
    if (options === null || typeof options !== 'object') {
      throw new TypeError(`${fn}: argument 'options' must be an object { dimensions, gravity?, params? }`);
    }
    for (const key of Object.keys(options)) {
      if (!WORLD_OPTION_NAMES.has(key)) {
        throw new RangeError(`${fn}: unknown option '${key}' (known: dimensions, gravity, params)`);
      }
    }
    checkInteger('dimensions', options.dimensions, MIN_DIMENSION, MAX_DIMENSION, fn);
    const D = dims(options.dimensions);
    if (options.gravity !== undefined) checkVector(D, 'gravity', options.gravity, fn);
    const params = mergeParams(defaultParams, options.params, fn);
    this.D = D;
    this.n = D.n;
    this.currentParams = params;
    this.gravityValue = new Float64Array(D.n);
    if (options.gravity !== undefined) this.gravityValue.set(options.gravity);
    this.snapshot = createStepSnapshot(Body.stateLength(D));
    this.scratch = { rotor: createRotorStepScratch(D), bivector: new Float64Array(D.k) };
    this.constants = createStepConstants();
  }

  /** The current parameters (a frozen object; change them with {@link World.setParams}). */
  get params(): Readonly<Params> {
    return this.currentParams;
  }

  /**
   * Changes some parameters. All-or-nothing: the whole `partial` is validated first (unknown
   * names, types, ranges) and nothing changes if any entry is bad.
   */
  setParams(partial: Partial<Params>): this {
    this.currentParams = mergeParams(this.currentParams, partial, 'World.setParams');
    return this;
  }

  /** A copy of the gravity vector (m/s², n numbers). */
  get gravity(): Float64Array {
    return Float64Array.from(this.gravityValue);
  }

  /** Sets gravity (m/s², n finite numbers). */
  setGravity(g: ArrayLike<number>): this {
    checkVector(this.D, 'g', g, 'World.setGravity');
    this.gravityValue.set(g);
    return this;
  }

  /** The bodies, in the order they were added (a frozen array, replaced when the list changes). */
  get bodies(): readonly Body[] {
    return this.bodyView;
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
    if (body.owner === this) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) is already in this world`);
    }
    if (body.owner !== null) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) already belongs to another world; remove it there first`);
    }
    reserveStepSnapshot(this.snapshot, this.bodyList.length + 1);
    body.owner = this;
    this.bodyList.push(body);
    this.bodyView = Object.freeze(this.bodyList.slice());
    return body;
  }

  /**
   * Removes a body (its state is kept; it may be added again, here or to another world).
   * @throws TypeError if `body` is not a Body; RangeError if it is not in this world.
   */
  removeBody(body: Body): this {
    const fn = 'World.removeBody';
    if (!(body instanceof Body)) {
      throw new TypeError(`${fn}: argument 'body' must be a Body, got ${body === null ? 'null' : typeof body}`);
    }
    const index = body.owner === this ? this.bodyList.indexOf(body) : -1;
    if (index < 0) {
      throw new RangeError(`${fn}: argument 'body' (${body.label}) is not in this world`);
    }
    this.bodyList.splice(index, 1);
    body.owner = null;
    this.bodyView = Object.freeze(this.bodyList.slice());
    return this;
  }

  /**
   * Advances the world by `dt` seconds (default `params.fixedTimeStep`) in `params.subSteps` equal
   * sub-steps h = dt / subSteps. Each sub-step, top to bottom:
   *
   * 1. forces → velocities: v += h (F/m + g), L += h τ, damping (dynamic bodies);
   * 2. (next issues: broadphase, narrowphase, islands, contact and joint solver on v and L);
   * 3. velocities → positions: x += h v, the midpoint rotor step under fixed L, rotor correction,
   *    ω rebuilt from L; kinematic bodies move by their own v and ω; each body is then checked for
   *    non-finite numbers.
   *
   * After the last sub-step the accumulated forces and torques are cleared.
   *
   * @throws TypeError / RangeError if dt is not a finite number > 0 (nothing changes).
   * @throws NonFiniteStateError if a body's state became non-finite: every body is restored to
   *   its state before this call and the error names the body and the field.
   */
  step(dt: number = this.currentParams.fixedTimeStep): this {
    // Checked in place (not through a shared helper) so the hot call boxes nothing.
    if (typeof dt !== 'number' || !(dt > 0) || dt === Infinity) throwBadTimeStep(dt);
    const D = this.D;
    const p = this.currentParams;
    const bodies = this.bodyList;
    const subSteps = p.subSteps;
    const h = dt / subSteps;
    const c = this.constants;
    c[STEP_H] = h;
    c[STEP_ROTOR_TOLERANCE] = p.rotorTolerance;
    c[STEP_ROTOR_ITERATIONS] = p.gyroscopic ? p.gyroscopicIterations : 0;
    c[STEP_LINEAR_SCALE] = p.linearDamping > 0 ? 1 / (1 + h * p.linearDamping) : 1;
    c[STEP_ANGULAR_SCALE] = p.angularDamping > 0 ? 1 / (1 + h * p.angularDamping) : 1;
    saveStepState(this.snapshot, bodies);
    for (let s = 0; s < subSteps; s += 1) {
      integrateVelocities(D, bodies, this.gravityValue, c, this.scratch.bivector);
      // Collision detection and the constraint solver slot in here (they act on v and L).
      const bad = integratePositions(D, bodies, c, this.scratch.rotor);
      if (bad >= 0) this.failStep(bodies[bad]!, s, subSteps);
    }
    for (let b = 0; b < bodies.length; b += 1) bodies[b]!.clearForces();
    this.clock[0] = this.clock[0]! + dt;
    this.clock[1] = this.clock[1]! + 1;
    return this;
  }

  /** Undoes the current step and throws the error that names the body. */
  private failStep(body: Body, subStep: number, subSteps: number): never {
    const field = firstNonFiniteField(body) ?? 'x';
    restoreStepState(this.snapshot, this.bodyList);
    throw new NonFiniteStateError(body, field, subStep, subSteps);
  }
}
