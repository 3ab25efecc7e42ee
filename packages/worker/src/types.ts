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

/**
 * One part of a compound description: a shape (not a half-space or a compound) placed at
 * `position` (n numbers, default the origin) and turned by `rotor` (r numbers, default identity)
 * in the coordinates of the compound's body.
 */
export interface CompoundPartDescription {
  /** The part's shape: any description but a half-space or a compound. */
  readonly shape: ShapeDescription;
  /** Where the part's origin sits in the body's coordinates (m, n numbers); default the origin. */
  readonly position?: ArrayLike<number>;
  /** The part's orientation in the body's coordinates (a unit rotor, r numbers); default identity. */
  readonly rotor?: ArrayLike<number>;
}

/** A shape, described by its kind and size (the engine's factories, as data). */
export type ShapeDescription =
  | {
      /**
       * One body of several shapes (the engine's `Compound`): mass properties summed with one
       * density; collision records name the part by its index in `parts`.
       */
      readonly kind: 'compound';
      /** At least one part. */
      readonly parts: readonly CompoundPartDescription[];
    }
  | {
      /** A hyperbox (the engine's `HyperBox`), centred on the body's position. */
      readonly kind: 'box';
      /** Half the side along each axis (m, n numbers, > 0). */
      readonly halfExtents: ArrayLike<number>;
    }
  | {
      /** A ball (the engine's `HyperSphere`), centred on the body's position. */
      readonly kind: 'sphere';
      /** Its radius (m, > 0). */
      readonly radius: number;
    }
  | {
      /** The half-space x · normal <= offset (the engine's `HalfSpace`); its body is static. */
      readonly kind: 'halfspace';
      /** Normal of the boundary, pointing out of the solid (n numbers, not all zero). */
      readonly normal: ArrayLike<number>;
      /** The boundary is the set x · normal = offset (m; both are divided by |normal|). */
      readonly offset: number;
    }
  | {
      /** A solid torus (the engine's `HyperTorus`): the points within `minorRadius` of a circle. */
      readonly kind: 'torus';
      /** Radius of the circle (m, > minorRadius). */
      readonly majorRadius: number;
      /** Distance from the circle (m, > 0). */
      readonly minorRadius: number;
      /** The two axes of the major circle, [i, j] with i < j. */
      readonly plane: readonly [number, number];
    }
  | {
      /**
       * A capsule (the engine's `HyperCapsule`): the points within `radius` of the segment from
       * −halfHeight to +halfHeight along local axis 1 ("y").
       */
      readonly kind: 'capsule';
      /** Half the length of the core segment (m, > 0). */
      readonly halfHeight: number;
      /** Radius (m, > 0). */
      readonly radius: number;
    }
  | {
      /** A convex polytope (the engine's `ConvexMesh`) from its vertices and boundary facets. */
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
  /** The collision and mass shape. */
  readonly shape: ShapeDescription;
  /** Mass (kg, >= 0); 0 makes the body static. Default 1 (0 for a half-space). */
  readonly mass?: number;
  /** How the body moves; default 'dynamic', or 'static' when the mass is 0 or the shape a half-space. */
  readonly type?: BodyType;
  /** Position of the shape's origin (m, n numbers); default the world origin. */
  readonly position?: ArrayLike<number>;
  /** Orientation rotor (r numbers, a unit rotor); default the identity. */
  readonly rotor?: ArrayLike<number>;
  /** Linear velocity (m/s, n numbers); default 0. Not on a static body. */
  readonly velocity?: ArrayLike<number>;
  /** World angular velocity bivector (rad/s, k numbers); default 0. Not on a static body. */
  readonly angularVelocity?: ArrayLike<number>;
  /** Friction and restitution; missing entries take the engine's `bodyDefaults`. */
  readonly material?: Partial<Material>;
  /** A name, used in error messages. */
  readonly name?: string;
  /** The collision groups the body belongs to (a 32-bit mask); default 1. */
  readonly collisionGroup?: number;
  /** The groups it collides with (a 32-bit mask); default 0xffffffff. */
  readonly collisionMask?: number;
  /** A sensor reports overlap events and makes no contact impulses; default false. */
  readonly sensor?: boolean;
}

/** Options every joint takes (the engine's `JointOptions`). */
export interface JointDescriptionOptions {
  /** Frequency of a soft joint (Hz, >= 0; 0 = rigid). Default: the world's `constraintHertz`. */
  readonly hertz?: number;
  /** Damping ratio of a soft joint (>= 0; 1 = critical). Default: the world's `constraintDamping`. */
  readonly damping?: number;
  /** The joint breaks when its linear load exceeds this (N). 0 (default) = never. */
  readonly breakForce?: number;
  /** The joint breaks when its angular load exceeds this (N·m). 0 (default) = never. */
  readonly breakTorque?: number;
  /** Let the two bodies collide with each other (default false). */
  readonly collideConnected?: boolean;
  /** distance: the length to hold (m, >= 0); default the distance of the anchors when added. */
  readonly rest?: number;
  /** distance: 'rod' (default, both ways), 'rope' (at most `rest`) or 'strut' (at least `rest`). */
  readonly mode?: DistanceMode;
  /** hinge: the free plane in a's frame, a plane index or a simple bivector (k numbers); default 0. */
  readonly plane?: number | ArrayLike<number>;
  /** hinge: lower limit of the angle (rad); default −Infinity (none). */
  readonly lowerAngle?: number;
  /** hinge: upper limit of the angle (rad); default +Infinity (none). */
  readonly upperAngle?: number;
  /** hinge: target speed of the motor (rad/s); default 0. */
  readonly motorSpeed?: number;
  /** hinge: largest torque of the motor (N·m, >= 0); default 0 = no motor. */
  readonly maxMotorTorque?: number;
  /** subspace: the axes (0..n−1) along which the anchors are held together. Not with `freeAxes`. */
  readonly lockAxes?: ArrayLike<number>;
  /** subspace: the axes left free; every other axis is locked. Not with `lockAxes`. */
  readonly freeAxes?: ArrayLike<number>;
  /** subspace: the rotation planes (0..k−1, lexicographic) that are locked. Not with `freePlanes`. */
  readonly lockPlanes?: ArrayLike<number>;
  /** subspace: the planes left free; every other plane is locked. Not with `lockPlanes`. */
  readonly freePlanes?: ArrayLike<number>;
  /** subspace: axes and planes in the world frame (true) or in a's frame (false, default). */
  readonly worldFrame?: boolean;
}

/** A joint, as data. `b` null holds `a` to the world. Anchors are local to their body. */
export interface JointDescription {
  /** Which of the engine's joints: `PointJoint`, `DistanceJoint`, `FixedJoint`, `HingeJoint`, `SubspaceJoint`. */
  readonly kind: 'point' | 'distance' | 'fixed' | 'hinge' | 'subspace';
  /** The first body. */
  readonly a: HostId;
  /** The second body, or null for the world. */
  readonly b: HostId | null;
  /**
   * Anchor on a, in a's frame (n numbers; default zeros). Not used by 'subspace' (it takes them
   * in options as the engine does).
   */
  readonly localA?: ArrayLike<number>;
  /** Anchor on b in b's frame, or a world point when b is null (n numbers; default zeros). Not used by 'subspace'. */
  readonly localB?: ArrayLike<number>;
  /** The common options and those of the kind. */
  readonly options?: JointDescriptionOptions;
}

/**
 * The commands of `execute(cmd, params)`. Body commands take `{ id, ... }`, joint commands
 * `{ joint, ... }`.
 */
export interface CommandMap {
  /** `World.setGravity`. */
  setGravity: {
    /** The gravity vector (m/s², n numbers). */
    readonly gravity: ArrayLike<number>;
  };
  /** `World.setParams`: changes some of the world's tolerances (the others keep their value). */
  setParams: {
    /** The tolerances to change (see the engine's `defaultParams`). */
    readonly params: Partial<Params>;
  };
  /** `Body.setMass`. */
  setMass: {
    /** The body. */
    readonly id: HostId;
    /** The new mass (kg, >= 0). */
    readonly value: number;
  };
  /** `Body.setMaterial`: entries left out keep their value. */
  setMaterial: {
    /** The body. */
    readonly id: HostId;
    /** Friction coefficient (>= 0). */
    readonly friction?: number;
    /** Restitution (0..1). */
    readonly restitution?: number;
  };
  /** `Body.collisionGroup`, `Body.collisionMask`, `Body.sensor`: entries left out keep their value. */
  setCollisionFilter: {
    /** The body. */
    readonly id: HostId;
    /** The groups the body belongs to (a 32-bit mask). */
    readonly group?: number;
    /** The groups it collides with (a 32-bit mask). */
    readonly mask?: number;
    /** Whether it is a sensor. */
    readonly sensor?: boolean;
  };
  /** `Body.wake`: wakes a sleeping body. */
  wake: {
    /** The body. */
    readonly id: HostId;
  };
  /** `Body.setPositionN`: moves the body (a teleport: velocities are kept). */
  setPositionN: {
    /** The body. */
    readonly id: HostId;
    /** The new position (m, n numbers). */
    readonly position: ArrayLike<number>;
  };
  /** `Body.setRotor`: sets the orientation. */
  setRotor: {
    /** The body. */
    readonly id: HostId;
    /** The new orientation (r numbers, a unit rotor). */
    readonly rotor: ArrayLike<number>;
  };
  /** `Body.rotateInPlane`: turns the body by `angle` in the plane of the axes i and j. */
  rotateInPlane: {
    /** The body. */
    readonly id: HostId;
    /** The first axis of the plane (0..n−1). */
    readonly i: number;
    /** The second axis of the plane (0..n−1, not i). */
    readonly j: number;
    /** The angle (rad), from axis i towards axis j. */
    readonly angle: number;
  };
  /** `Body.setLinearVelocity`. */
  setLinearVelocity: {
    /** The body. */
    readonly id: HostId;
    /** The velocity of the centre of mass (m/s, n numbers). */
    readonly velocity: ArrayLike<number>;
  };
  /** `Body.setAngularVelocity`. */
  setAngularVelocity: {
    /** The body. */
    readonly id: HostId;
    /** The world angular velocity bivector (rad/s, k numbers). */
    readonly angularVelocity: ArrayLike<number>;
  };
  /** `Body.applyCentralImpulse`: an impulse at the centre of mass. */
  applyCentralImpulse: {
    /** The body. */
    readonly id: HostId;
    /** The impulse (N·s, n numbers). */
    readonly impulse: ArrayLike<number>;
  };
  /** `Body.applyImpulse`: an impulse at a point of the body. */
  applyImpulse: {
    /** The body. */
    readonly id: HostId;
    /** The impulse (N·s, n numbers). */
    readonly impulse: ArrayLike<number>;
    /** The point of application minus the centre of mass (m, n numbers, world frame). */
    readonly offset: ArrayLike<number>;
  };
  /** `Body.applyCentralForce`: a force at the centre of mass, for the next step. */
  applyCentralForce: {
    /** The body. */
    readonly id: HostId;
    /** The force (N, n numbers). */
    readonly force: ArrayLike<number>;
  };
  /** `Body.applyForce`: a force at a point of the body, for the next step. */
  applyForce: {
    /** The body. */
    readonly id: HostId;
    /** The force (N, n numbers). */
    readonly force: ArrayLike<number>;
    /** The point of application minus the centre of mass (m, n numbers, world frame). */
    readonly offset: ArrayLike<number>;
  };
  /** `Body.applyTorque`: a torque for the next step. */
  applyTorque: {
    /** The body. */
    readonly id: HostId;
    /** The torque bivector (N·m, k numbers, world frame). */
    readonly torque: ArrayLike<number>;
  };
  /** `Joint.setSoftness`. */
  setSoftness: {
    /** The joint. */
    readonly joint: HostId;
    /** Frequency (Hz, >= 0; 0 = rigid). */
    readonly hertz: number;
    /** Damping ratio (>= 0; 1 = critical). */
    readonly damping: number;
  };
  /** `Joint.setBreak`: the loads at which the joint breaks (0 = never). */
  setBreak: {
    /** The joint. */
    readonly joint: HostId;
    /** Break force (N, >= 0). */
    readonly force: number;
    /** Break torque (N·m, >= 0). */
    readonly torque: number;
  };
  /** `Joint.setAnchors`: moves the anchors (null keeps one). */
  setAnchors: {
    /** The joint. */
    readonly joint: HostId;
    /** The anchor on a, in a's frame (n numbers), or null to keep it. */
    readonly localA: ArrayLike<number> | null;
    /** The anchor on b (a world point when b is null), or null to keep it. */
    readonly localB: ArrayLike<number> | null;
  };
  /** `HingeJoint.setLimits` (a hinge only). */
  setLimits: {
    /** The joint. */
    readonly joint: HostId;
    /** Lower limit of the angle (rad; −Infinity = none). */
    readonly lower: number;
    /** Upper limit of the angle (rad; +Infinity = none). */
    readonly upper: number;
  };
  /** `HingeJoint.setMotor` (a hinge only). */
  setMotor: {
    /** The joint. */
    readonly joint: HostId;
    /** Target speed (rad/s). */
    readonly speed: number;
    /** Largest torque (N·m, >= 0; 0 = off). */
    readonly maxTorque: number;
  };
  /** `DistanceJoint.setRest` (a distance joint only). */
  setRest: {
    /** The joint. */
    readonly joint: HostId;
    /** The length to hold (m, >= 0). */
    readonly rest: number;
  };
  /** `DistanceJoint.setMode` (a distance joint only). */
  setMode: {
    /** The joint. */
    readonly joint: HostId;
    /** 'rod', 'rope' or 'strut'. */
    readonly mode: DistanceMode;
  };
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
 * velocity of B's point to A's (n) | partA | partB`; impulse, point, normal and velocity are zeros
 * for an end. partA and partB name the parts that touched of compound bodies (their index in the
 * description's `parts`; 0 for a body of one shape): two compounds report one record per pair
 * of parts.
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
  /** Numbers per collision record: 6 + 3n. */
  readonly collisionStride: number;
  /** The collision records. */
  readonly collisions: Float32Array;
  /** Ids of the joints that broke in this step (they left the world). */
  readonly broken: Int32Array;
  /** Count of ids in `broken` (its length). */
  readonly brokenCount: number;
  /** Ids of the bodies that fell asleep in this step. */
  readonly slept: Int32Array;
  /** Count of ids in `slept` (its length). */
  readonly sleptCount: number;
  /** Ids of the bodies that woke in this step. */
  readonly woke: Int32Array;
  /** Count of ids in `woke` (its length). */
  readonly wokeCount: number;
  /**
   * Report buffers the world's thread has created so far: two at the start (the reports travel
   * back and forth), more only when a report outgrows them. Constant in steady state.
   */
  readonly buffersCreated: number;
}

/** A host event: the worker died (an error, or `terminate()` by someone else). */
export interface HostDiedEvent {
  /** Always 'died'. */
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
  /** Calls `listener` when the worker dies (see {@link HostDiedEvent}). */
  addEventListener(type: 'died', listener: (event: HostDiedEvent) => void): void;
  /** Stops calling a listener added by `addEventListener`. */
  removeEventListener(type: 'died', listener: (event: HostDiedEvent) => void): void;
  /** Ends the worker (if any) and frees the world. */
  dispose(): void;
}

/** The options of `new World` that a host takes. */
export type HostWorldOptions = WorldOptions;
