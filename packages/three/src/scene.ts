/**
 * `Scene`: a `THREE.Scene` with a world. It talks to the engine only through `@physin/worker`'s
 * host, so the main thread and a worker give the same pictures.
 *
 * Each `simulate` sends the moves and commands of the frame with one step request; when the
 * report arrives every mesh is updated from it, collision and broken events fire, 4D bodies are
 * sliced again, and `update` fires once.
 *
 * @module
 */
import * as THREE from 'three';
import { dims } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import type { Params } from '@physin/engine';
import { createWorld } from '@physin/worker';
import type { CommandMap, CommandName, HostId, StepReport, WorldHost } from '@physin/worker';
import { finite, integer, numbers } from './checks.js';
import { HyperShapeMesh } from './hyper-meshes.js';
import { Joint } from './joints.js';
import { Mesh } from './mesh.js';
import type { SceneLink } from './mesh.js';

/** Options of a `Scene`. */
export interface SceneOptions {
  /** Count of dimensions, 2 to 8 (default 3). */
  readonly dimensions?: number;
  /** Gravity, n numbers (default: −9.81 along y). */
  readonly gravity?: ArrayLike<number>;
  /** Where the shown 3-flat crosses the w axis (n ≥ 4; default 0). */
  readonly sliceW?: number;
  /** For n ≥ 5: the values of coordinates 3..n−1 on the shown 3-flat (n − 3 numbers). */
  readonly slice?: ArrayLike<number>;
  /** The engine's parameters (see `Params`). */
  readonly params?: Partial<Params>;
  /**
   * false (default): the world steps in this thread. true: in the package's own worker. A
   * `Worker` or a URL: in that worker (it must run `@physin/worker/worker.js`).
   */
  readonly worker?: boolean | Worker | URL | string;
}

/** Events of a scene, on top of three's. */
export interface SceneEventMap extends THREE.Object3DEventMap {
  /** The world can step (at once in the main thread; when the worker answers otherwise). */
  ready: object;
  /** A report was applied: every mesh is up to date. */
  update: object;
  /** The worker died (an error, or it was ended); `scene.host.restart()` brings it back. */
  died: {
    /** The error the worker reported, if any. */
    readonly error: Error | null;
  };
  /** A step failed in the engine (for example a non-finite state); the world is as it left it. */
  error: {
    /** The engine's error. */
    readonly error: Error;
  };
}

/** A three.js scene whose PhysiN meshes are bodies of one world. */
export class Scene extends THREE.Scene<SceneEventMap> {
  /** Count of dimensions. */
  readonly dimensions: number;
  /** The world's host (`@physin/worker`): snapshots, moving between threads, restarts. */
  readonly host: WorldHost;
  /** Coordinates 3..n−1 of the shown 3-flat (n − 3 numbers; `sliceW` is the first). */
  readonly slice: Float64Array;
  private readonly D: Dims;
  private readonly link: SceneLink;
  private readonly bodies: Mesh[] = [];
  private readonly byId = new Map<HostId, Mesh>();
  private readonly joints = new Map<HostId, Joint>();
  /** Meshes to re-slice: the first `dirtyCount` slots (the array is reused, never emptied). */
  private readonly dirty: (HyperShapeMesh | null)[] = [];
  private dirtyCount = 0;
  private readonly newcomers: Mesh[] = [];
  private readonly lastSlice: Float64Array;
  private readonly M: Float64Array;
  private readonly updateEvent = { type: 'update' } as const;
  private lastTime = -1;
  private disposed = false;
  private readonly onReport = (report: StepReport): void => this.applyReport(report);
  private readonly onStepError = (error: unknown): void => {
    if (this.disposed) return;
    this.emit({ type: 'error', error: error instanceof Error ? error : new Error(String(error)) });
  };

  constructor(options: SceneOptions = {}) {
    super();
    const where = 'Scene';
    if (options === null || typeof options !== 'object')
      throw new TypeError(`${where}: argument 'options' must be an object, got ${options === null ? 'null' : typeof options}`);
    const n = options.dimensions === undefined ? 3 : integer(where, 'options.dimensions', options.dimensions, 2, 8);
    const gravity = options.gravity === undefined ? defaultGravity(n) : numbers(where, 'options.gravity', options.gravity, n);
    const slice = new Float64Array(Math.max(0, n - 3));
    if (options.slice !== undefined) slice.set(numbers(where, 'options.slice', options.slice, n - 3));
    if (options.sliceW !== undefined) {
      finite(where, 'options.sliceW', options.sliceW, undefined, 'coordinate');
      if (n >= 4) slice[0] = options.sliceW;
    }
    const worker = options.worker ?? false;
    if (
      typeof worker !== 'boolean' &&
      typeof worker !== 'string' &&
      !(worker instanceof URL) &&
      (typeof worker !== 'object' || worker === null)
    ) {
      throw new TypeError(`${where}: option 'worker' must be false, true, a Worker or a URL, got ${typeof worker}`);
    }
    this.host = createWorld(
      { dimensions: n, gravity, ...(options.params === undefined ? {} : { params: options.params }) },
      worker === false ? { thread: 'main' } : worker === true ? { thread: 'worker' } : { thread: 'worker', worker },
    );
    this.dimensions = n;
    this.D = dims(n);
    this.slice = slice;
    this.lastSlice = slice.slice();
    this.M = new Float64Array(n * n);
    this.link = { host: this.host, D: this.D, markSliceDirty: (mesh) => this.markSliceDirty(mesh) };
    this.host.addEventListener('died', (event) => this.emit({ type: 'died', error: event.error }));
    this.host.ready.then(
      () => {
        if (!this.disposed) this.emit({ type: 'ready' });
      },
      () => undefined,
    );
  }

  /** Where the shown 3-flat crosses the w axis (n ≥ 4). Changing it re-slices at the next report or `refreshSlice`. */
  get sliceW(): number {
    return this.slice.length > 0 ? this.slice[0]! : 0;
  }

  /** Moves the shown 3-flat along w (a finite number; ignored for n < 4). */
  set sliceW(value: number) {
    finite('Scene.sliceW', 'value', value, undefined, 'coordinate');
    if (this.slice.length > 0) this.slice[0] = value;
  }

  /** True while a worker step is in flight (`simulate` then returns false). */
  get busy(): boolean {
    return this.host.busy;
  }

  // --- bodies -----------------------------------------------------------------------------------

  /** Adds objects; a PhysiN mesh gets its body (its commands called before `add` follow, in order). */
  override add(...objects: THREE.Object3D[]): this {
    for (const object of objects) {
      if (object instanceof Mesh && object._link !== this.link) this.addBody(object);
      super.add(object);
    }
    return this;
  }

  /** Removes objects; a PhysiN mesh loses its body and its joints. */
  override remove(...objects: THREE.Object3D[]): this {
    for (const object of objects) {
      if (object instanceof Mesh && object._link === this.link) this.removeBody(object);
      super.remove(object);
    }
    return this;
  }

  private addBody(mesh: Mesh): void {
    const where = 'Scene.add';
    this.checkOpen(where);
    const n = this.dimensions;
    if (mesh._link !== null)
      throw new RangeError(`${where}: this ${mesh.constructor.name} is in another scene; remove it there first`);
    if (mesh.dimensions === null) mesh.setDimensions(n, where);
    if (mesh.dimensions !== n)
      throw new RangeError(`${where}: the ${mesh.constructor.name} has ${mesh.dimensions} dimensions, the scene ${n}`);
    const id = this.host.addBody(mesh.describeBody(n));
    try {
      mesh.flushPending(this.host, id);
    } catch (error) {
      this.host.removeBody(id);
      throw error;
    }
    mesh.bindBody(this.link, id);
    this.byId.set(id, mesh);
    this.bodies.push(mesh);
    this.newcomers.push(mesh);
  }

  private removeBody(mesh: Mesh): void {
    const id = mesh._physiN.id!;
    for (const joint of this.joints.values()) {
      if (joint.a === mesh || joint.b === mesh) this.removeConstraint(joint);
    }
    if (!this.disposed) this.host.removeBody(id);
    this.byId.delete(id);
    removeItem(this.bodies, mesh);
    removeItem(this.newcomers, mesh);
    if (mesh instanceof HyperShapeMesh) mesh._sliceDirty = false;
    mesh.unbindBody();
  }

  /** Count of meshes with a body in this scene. */
  get bodyCount(): number {
    return this.bodies.length;
  }

  /** Count of joints in this scene. */
  get jointCount(): number {
    return this.joints.size;
  }

  // --- joints -----------------------------------------------------------------------------------

  /** Adds a joint; both meshes must be in this scene. Returns the joint. */
  addConstraint<J extends Joint>(joint: J): J {
    const where = 'Scene.addConstraint';
    this.checkOpen(where);
    if (!(joint instanceof Joint))
      throw new TypeError(`${where}: argument 'joint' must be a PhysiN joint (PointJoint, HingeJoint, …)`);
    if (joint._link !== null) throw new RangeError(`${where}: this ${joint.constructor.name} is already in a scene`);
    if (joint.a._link !== this.link)
      throw new RangeError(`${where}: mesh 'a' of the ${joint.constructor.name} is not in this scene; add it first`);
    if (joint.b !== null && joint.b._link !== this.link)
      throw new RangeError(`${where}: mesh 'b' of the ${joint.constructor.name} is not in this scene; add it first`);
    const id = this.host.addJoint(joint.describe());
    joint._id = id;
    joint._link = this.link;
    this.joints.set(id, joint);
    return joint;
  }

  /** Removes a joint of this scene. */
  removeConstraint(joint: Joint): void {
    const where = 'Scene.removeConstraint';
    if (!(joint instanceof Joint)) throw new TypeError(`${where}: argument 'joint' must be a PhysiN joint`);
    if (joint._link !== this.link) throw new RangeError(`${where}: this ${joint.constructor.name} is not in this scene`);
    if (!this.disposed) this.host.removeJoint(joint._id!);
    this.joints.delete(joint._id!);
    joint._link = null;
    joint._id = null;
  }

  // --- world ------------------------------------------------------------------------------------

  /** Sets gravity (n numbers). */
  setGravity(gravity: ArrayLike<number>): void {
    this.checkOpen('Scene.setGravity');
    this.host.execute('setGravity', { gravity: numbers('Scene.setGravity', 'gravity', gravity, this.dimensions) });
  }

  /** Sends a command to the engine, e.g. `execute('setMass', { id: mesh._physiN.id, value: 2 })`. */
  execute<C extends CommandName>(cmd: C, params: CommandMap[C]): void {
    this.checkOpen('Scene.execute');
    this.host.execute(cmd, params);
  }

  /**
   * Steps the world by `timeStep` seconds (default: the time since the last call) in fixed steps
   * of `params.fixedTimeStep`, at most `maxSubSteps` of them; the rest carries to the next call.
   * Returns false, doing nothing, while a worker step is in flight or the worker starts.
   */
  simulate(timeStep?: number, maxSubSteps?: number): boolean {
    const where = 'Scene.simulate';
    this.checkOpen(where);
    const now = typeof performance !== 'undefined' ? performance.now() : Date.now();
    let dt: number;
    if (timeStep === undefined) {
      dt = this.lastTime < 0 ? 1 / 60 : Math.min((now - this.lastTime) / 1000, 0.25);
    } else {
      dt = finite(where, 'timeStep', timeStep, 0, 'number of seconds');
    }
    if (maxSubSteps !== undefined) integer(where, 'maxSubSteps', maxSubSteps, 1, 1_000_000);
    if (this.host.busy) return false;
    const bodies = this.bodies;
    for (let i = 0; i < bodies.length; i += 1) bodies[i]!.sendMoves();
    const step = this.host.step(dt, maxSubSteps);
    if (step === null) return false;
    this.lastTime = now;
    step.then(this.onReport, this.onStepError);
    return true;
  }

  /** Slices every n-D mesh again by the flat `slice` (call it after changing `sliceW` while paused). */
  refreshSlice(): void {
    const bodies = this.bodies;
    for (let i = 0; i < bodies.length; i += 1) {
      const mesh = bodies[i]!;
      if (mesh instanceof HyperShapeMesh) this.sliceOne(mesh);
    }
    for (let i = 0; i < this.dirtyCount; i += 1) this.dirty[i] = null;
    this.dirtyCount = 0;
    this.lastSlice.set(this.slice);
  }

  /** Ends the worker, frees the geometries the adapter made, and detaches every mesh. */
  override dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.host.dispose();
    for (const mesh of [...this.bodies]) {
      if (mesh instanceof HyperShapeMesh && mesh.ownsGeometry) mesh.geometry.dispose();
      this.removeBody(mesh);
    }
    super.dispose();
  }

  // --- reports ----------------------------------------------------------------------------------

  private applyReport(report: StepReport): void {
    if (this.disposed) return;
    const { n, r } = this.D;
    const { bodies, stride } = report;
    for (let i = 0; i < report.bodyCount; i += 1) {
      const at = i * stride;
      // `| 0`: an integer key, not a boxed double from the Float32Array
      const mesh = this.byId.get(bodies[at]! | 0);
      if (mesh !== undefined) mesh.readRecord(bodies, at, n, r);
    }
    this.fireCollisions(report);
    for (let i = 0; i < report.brokenCount; i += 1) {
      const joint = this.joints.get(report.broken[i]!);
      if (joint === undefined) continue;
      this.joints.delete(joint._id!);
      joint._link = null;
      joint._id = null;
      joint.dispatchEvent({ type: 'broken' });
    }
    this.sliceChanged();
    if (this.newcomers.length > 0) {
      for (let i = 0; i < this.newcomers.length; i += 1) this.newcomers[i]!.dispatchEvent({ type: 'ready' });
      this.newcomers.length = 0;
    }
    this.emit(this.updateEvent);
  }

  private fireCollisions(report: StepReport): void {
    const n = this.dimensions;
    const c = report.collisions;
    for (let i = 0; i < report.collisionCount; i += 1) {
      const at = i * report.collisionStride;
      const a = this.byId.get(c[at + 1]! | 0);
      const b = this.byId.get(c[at + 2]! | 0);
      if (a === undefined || b === undefined) continue;
      const phase = c[at] === 0 ? 'begin' : 'end';
      const impulse = c[at + 3]!;
      const point = Float64Array.from(c.subarray(at + 4, at + 4 + n));
      const normal = Float64Array.from(c.subarray(at + 4 + n, at + 4 + 2 * n));
      const relative = Float64Array.from(c.subarray(at + 4 + 2 * n, at + 4 + 3 * n));
      // the meshes of the parts that touched (a compound body's child meshes), else the bodies'
      const partA = a._parts?.[c[at + 4 + 3 * n]! | 0] ?? a;
      const partB = b._parts?.[c[at + 5 + 3 * n]! | 0] ?? b;
      a.dispatchEvent({
        type: 'collision',
        phase,
        other: b,
        point,
        normal,
        relativeVelocity: relative,
        impulse,
        part: partA,
        otherPart: partB,
      });
      b.dispatchEvent({
        type: 'collision',
        phase,
        other: a,
        point: point.slice(),
        normal: negate(normal),
        relativeVelocity: negate(relative),
        impulse,
        part: partB,
        otherPart: partA,
      });
    }
  }

  private markSliceDirty(mesh: Mesh): void {
    if (!(mesh instanceof HyperShapeMesh) || this.dimensions < 4 || mesh._sliceDirty) return;
    mesh._sliceDirty = true;
    if (this.dirtyCount < this.dirty.length) this.dirty[this.dirtyCount] = mesh;
    else this.dirty.push(mesh);
    this.dirtyCount += 1;
  }

  /** Re-slices the meshes that moved, or all of them when the flat moved. */
  private sliceChanged(): void {
    if (this.dimensions < 4) return;
    let flatMoved = false;
    for (let a = 0; a < this.slice.length; a += 1) if (this.slice[a] !== this.lastSlice[a]) flatMoved = true;
    if (flatMoved) {
      this.refreshSlice();
      return;
    }
    const dirty = this.dirty;
    for (let i = 0; i < this.dirtyCount; i += 1) {
      const mesh = dirty[i]!;
      dirty[i] = null;
      // a mesh removed since it was marked is no longer dirty
      if (mesh._sliceDirty) this.sliceOne(mesh);
    }
    this.dirtyCount = 0;
  }

  private sliceOne(mesh: HyperShapeMesh): void {
    mesh._sliceDirty = false;
    if (mesh._R === null || mesh._R.length !== this.D.r) return;
    this.D.kernels.toMatrix(this.M, mesh._R);
    mesh.updateSlice(this.slice, this.M);
  }

  private checkOpen(where: string): void {
    if (this.disposed) throw new RangeError(`${where}: this scene was disposed`);
  }

  private emit(event: { type: keyof SceneEventMap } & Record<string, unknown>): void {
    this.dispatchEvent(event as never);
  }
}

function defaultGravity(n: number): Float64Array {
  const g = new Float64Array(n);
  g[1] = -9.81;
  return g;
}

function negate(v: Float64Array): Float64Array {
  const out = new Float64Array(v.length);
  for (let i = 0; i < v.length; i += 1) out[i] = v[i] === 0 ? 0 : -v[i]!;
  return out;
}

function removeItem<T>(list: T[], item: T): void {
  const i = list.indexOf(item);
  if (i >= 0) list.splice(i, 1);
}
