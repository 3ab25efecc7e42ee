/**
 * The public types of `@physin/worker`: what a caller gives a world host (plain, structured-cloneable
 * descriptions and commands) and what it gets back (one report per `step`).
 *
 * Every array here is a plain `number[]` or a typed array; every description can cross
 * `postMessage` as it is.
 *
 * @module
 */
import type { BodyType, DistanceMode, Material, Params, WorldOptions } from '@physin/engine';

/** Where the world lives: in this thread, or in a dedicated worker. */
export type ThreadKind = 'main' | 'worker';

/** How {@link openWorld} places the world. */
export interface HostOptions {
  /** 'main' (default) steps the world in this thread; 'worker' in a worker. */
  readonly thread?: ThreadKind;
  /**
   * With thread 'worker': a `Worker` the caller started (it must load this package's worker
   * entry), or the URL of that entry. Default: the package's own `worker.js`.
   */
  readonly worker?: unknown;
}

/** A host's id of a body or a joint: a non-negative integer assigned on the caller's side. */
export type HostId = number;

/** A shape, described by its kind and size (the engine's factories, as data). */
export type ShapeDescription =
  | { readonly kind: 'box'; readonly halfExtents: ArrayLike<number> }
  | { readonly kind: 'sphere'; readonly radius: number }
  | { readonly kind: 'halfspace'; readonly normal: ArrayLike<number>; readonly offset: number }
  | {
      readonly kind: 'torus';
      readonly majorRadius: number;
      readonly minorRadius: number;
      /** The two axes of the major circle, [i, j] with i < j. */
      readonly plane: readonly [number, number];
    }
  | {
      readonly kind: 'convex';
      /** Vertices, n numbers each, flat. */
      readonly vertices: ArrayLike<number>;
      /** Boundary facets: n vertex indices each, flat. */
      readonly facets: ArrayLike<number>;
    }
  | {
      /** A 3D convex mesh from triangles (repeated vertices are merged), as three.js gives them. */
      readonly kind: 'triangles';
      /** Positions, 3 numbers each, flat. */
      readonly positions: ArrayLike<number>;
      /** Triangle indices (3 each), or omitted for non-indexed positions. */
      readonly indices?: ArrayLike<number>;
    };

/** A body, as data: the engine's `BodyOptions` with a shape description in place of a shape. */
export interface BodyDescription {
  readonly shape: ShapeDescription;
  readonly mass?: number;
  readonly type?: BodyType;
  readonly position?: ArrayLike<number>;
  readonly rotor?: ArrayLike<number>;
  readonly velocity?: ArrayLike<number>;
  readonly angularVelocity?: ArrayLike<number>;
  readonly material?: Partial<Material>;
  readonly name?: string;
}

/** Options every joint takes (the engine's `JointOptions`). */
export interface JointDescriptionOptions {
  readonly hertz?: number;
  readonly damping?: number;
  readonly breakForce?: number;
  readonly breakTorque?: number;
  readonly collideConnected?: boolean;
  /** distance: */
  readonly rest?: number;
  readonly mode?: DistanceMode;
  /** hinge: */
  readonly plane?: number | ArrayLike<number>;
  readonly lowerAngle?: number;
  readonly upperAngle?: number;
  readonly motorSpeed?: number;
  readonly maxMotorTorque?: number;
  /** subspace: */
  readonly lockAxes?: ArrayLike<number>;
  readonly freeAxes?: ArrayLike<number>;
  readonly lockPlanes?: ArrayLike<number>;
  readonly freePlanes?: ArrayLike<number>;
  readonly worldFrame?: boolean;
}

/** A joint, as data. `b` null holds `a` to the world. Anchors are local to their body. */
export interface JointDescription {
  readonly kind: 'point' | 'distance' | 'fixed' | 'hinge' | 'subspace';
  readonly a: HostId;
  readonly b: HostId | null;
  /** Not used by 'subspace' (it takes them in options as the engine does). */
  readonly localA?: ArrayLike<number>;
  readonly localB?: ArrayLike<number>;
  readonly options?: JointDescriptionOptions;
}

/**
 * The commands of `execute(cmd, params)`. Body commands take `{ id, ... }`, joint commands
 * `{ joint, ... }`.
 */
export interface CommandMap {
  setGravity: { readonly gravity: ArrayLike<number> };
  setParams: { readonly params: Partial<Params> };
  setMass: { readonly id: HostId; readonly value: number };
  setMaterial: { readonly id: HostId; readonly friction?: number; readonly restitution?: number };
  wake: { readonly id: HostId };
  setPositionN: { readonly id: HostId; readonly position: ArrayLike<number> };
  setRotor: { readonly id: HostId; readonly rotor: ArrayLike<number> };
  rotateInPlane: { readonly id: HostId; readonly i: number; readonly j: number; readonly angle: number };
  setLinearVelocity: { readonly id: HostId; readonly velocity: ArrayLike<number> };
  setAngularVelocity: { readonly id: HostId; readonly angularVelocity: ArrayLike<number> };
  applyCentralImpulse: { readonly id: HostId; readonly impulse: ArrayLike<number> };
  applyImpulse: { readonly id: HostId; readonly impulse: ArrayLike<number>; readonly offset: ArrayLike<number> };
  applyCentralForce: { readonly id: HostId; readonly force: ArrayLike<number> };
  applyForce: { readonly id: HostId; readonly force: ArrayLike<number>; readonly offset: ArrayLike<number> };
  applyTorque: { readonly id: HostId; readonly torque: ArrayLike<number> };
  setSoftness: { readonly joint: HostId; readonly hertz: number; readonly damping: number };
  setBreak: { readonly joint: HostId; readonly force: number; readonly torque: number };
  setAnchors: { readonly joint: HostId; readonly localA: ArrayLike<number> | null; readonly localB: ArrayLike<number> | null };
  setLimits: { readonly joint: HostId; readonly lower: number; readonly upper: number };
  setMotor: { readonly joint: HostId; readonly speed: number; readonly maxTorque: number };
  setRest: { readonly joint: HostId; readonly rest: number };
  setMode: { readonly joint: HostId; readonly mode: DistanceMode };
}

/** The name of a command. */
export type CommandName = keyof CommandMap;

/**
 * One step's report. Valid until the next `step` call: its buffers then go back to the world to
 * be refilled (no report is allocated in steady state). Copy what you keep.
 *
 * Body record i (of `bodyCount`) starts at `i * stride` in `bodies`:
 * `id | position (n) | rotor (r) | linear velocity (n) | angular momentum (k)` — the
 * specification's record. Ids are the host ids, exact in a Float32 up to 2^24.
 *
 * Collision record c (of `collisionCount`) starts at `c * collisionStride` in `collisions`:
 * `phase (0 begin, 1 end) | idA | idB | impulse | point (n) | normal from A to B (n) | relative
 * velocity of B's point to A's (n)`; the numbers after idB are zeros for an end.
 */
export interface StepReport {
  /** Fixed steps the world took for this report (0 for `step(0)`). */
  readonly steps: number;
  /** Simulated time after the step (s). */
  readonly time: number;
  /** Count of body records. */
  readonly bodyCount: number;
  /** Numbers per body record: 1 + 2n + r + k. */
  readonly stride: number;
  /** The body records. */
  readonly bodies: Float32Array;
  /** Count of collision records. */
  readonly collisionCount: number;
  /** Numbers per collision record: 4 + 3n. */
  readonly collisionStride: number;
  /** The collision records. */
  readonly collisions: Float32Array;
  /** Ids of the joints that broke in this step (they left the world). */
  readonly broken: Int32Array;
  readonly brokenCount: number;
  /** Ids of the bodies that fell asleep in this step. */
  readonly slept: Int32Array;
  readonly sleptCount: number;
  /** Ids of the bodies that woke in this step. */
  readonly woke: Int32Array;
  readonly wokeCount: number;
  /**
   * Report buffers the world's thread has created so far: two at the start (the reports travel
   * back and forth), more only when a report outgrows them. Constant in steady state.
   */
  readonly buffersCreated: number;
}

/** A host event: the worker died (an error, or `terminate()` by someone else). */
export interface HostDiedEvent {
  readonly type: 'died';
  /** The error the worker reported, if any. */
  readonly error: Error | null;
}

/** The world behind a host: the same interface in either thread. */
export interface WorldHost {
  /** Where the world lives now. */
  readonly thread: ThreadKind;
  /** Count of dimensions n. */
  readonly dimensions: number;
  /** True while a step is in flight or the worker starts (then `step` returns null). */
  readonly busy: boolean;
  /**
   * Settles when the world can step: at once in the main thread, when the worker answers
   * otherwise (it rejects, and `died` fires, if the worker cannot start).
   */
  readonly ready: Promise<void>;
  /** Adds a body; the id is assigned here and returned at once. Throws on bad input (nothing queued). */
  addBody(description: BodyDescription): HostId;
  /** Removes a body (and the joints that hold it). */
  removeBody(id: HostId): void;
  /** Adds a joint; returns its id at once. Throws on bad input (nothing queued). */
  addJoint(description: JointDescription): HostId;
  /** Removes a joint. */
  removeJoint(id: HostId): void;
  /** Queues a command for the next step; validated here, throws on bad input (nothing queued). */
  execute<C extends CommandName>(cmd: C, params: CommandMap[C]): void;
  /**
   * Takes at most `maxSubSteps` fixed steps of `params.fixedTimeStep` for `elapsed` seconds plus
   * the carried remainder (the rest carries; beyond `maxSubSteps` it is dropped). Returns null,
   * doing nothing, while a step is in flight.
   */
  step(elapsed: number, maxSubSteps?: number): Promise<StepReport> | null;
  /**
   * The angular velocity bivector (k numbers) of body `id` in the last report, ω = I⁻¹ L from the
   * reported rotor and momentum (the record carries L, as the specification says). Zeros before the
   * first report.
   */
  angularVelocity(id: HostId, out?: Float64Array): Float64Array;
  /** The world's state as bytes (see `World.snapshot`). */
  snapshot(): Promise<Uint8Array>;
  /** Moves the running world to the other thread, through a snapshot, without a jump. */
  moveTo(thread: ThreadKind): Promise<void>;
  /** Starts a new worker from the last snapshot after the worker died. */
  restart(): Promise<void>;
  addEventListener(type: 'died', listener: (event: HostDiedEvent) => void): void;
  removeEventListener(type: 'died', listener: (event: HostDiedEvent) => void): void;
  /** Ends the worker (if any) and frees the world. */
  dispose(): void;
}

/** The options of `new World` that a host takes. */
export type HostWorldOptions = WorldOptions;
