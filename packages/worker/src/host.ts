/**
 * The world host: one interface whether the world lives in this thread or in a worker.
 *
 * - Main thread: every call runs on the world at once (the engine validates it and changes nothing
 *   on error); `step` steps and writes the report synchronously.
 * - Worker: every call runs first on a shadow world in this thread (never stepped), so a bad
 *   description or command throws here, with the engine's own error, and nothing is queued. Good
 *   ones are queued and travel with the next step request, in order: one message per step.
 *
 * Either way the operations reach the world in the same order, before the same step, through the
 * same code ({@link WorldCore}), so the two give the same bytes.
 *
 * @module
 */
import { transfer, wrap } from 'comlink';
import type { Remote } from 'comlink';
import { angularVelocityFromMomentum } from '@physin/engine';
import type { WorldOptions } from '@physin/engine';
import { errorFromData } from './errors.js';
import type { ErrorData } from './errors.js';
import { nodeEndpoint } from './node-endpoint.js';
import type { NodePort } from './node-endpoint.js';
import { ReportView } from './report.js';
import type { WorkerApi } from './worker-api.js';
import { WorldCore } from './world-core.js';
import type { Operation } from './world-core.js';
import type {
  BodyDescription,
  CommandMap,
  CommandName,
  HostDiedEvent,
  HostId,
  HostOptions,
  JointDescription,
  StepReport,
  ThreadKind,
  WorldHost,
} from './types.js';

/** Something that can be terminated: a browser Worker or a Node worker_threads Worker. */
interface Terminable {
  terminate(): unknown;
}

/** A started worker: the comlink proxy and how to stop and watch it. */
interface WorkerLink {
  readonly api: Remote<WorkerApi>;
  readonly handle: Terminable;
  /** Stops reporting death (we are ending it ourselves). */
  detach(): void;
}

const nodeProcess = (globalThis as { process?: { versions?: { node?: string } } }).process;
/** Node (worker_threads) rather than a browser (Web Workers). */
const isNode = nodeProcess?.versions?.node !== undefined && (globalThis as { window?: unknown }).window === undefined;

/** Starts the package's own worker, or the one the caller gave, and watches it for death. */
async function startWorker(given: unknown, onDeath: (error: Error | null) => void): Promise<WorkerLink> {
  let alive = true;
  const die = (error: Error | null): void => {
    if (!alive) return;
    alive = false;
    onDeath(error);
  };
  if (isNode && (given === undefined || given instanceof URL || typeof given === 'string')) {
    const name = 'node:worker_threads';
    const threads = (await import(/* @vite-ignore */ /* webpackIgnore: true */ name)) as {
      Worker: new (url: URL | string) => NodePort & Terminable & { on(type: string, fn: (value: unknown) => void): unknown };
    };
    const url = given === undefined ? new URL('./worker.js', import.meta.url) : given;
    const worker = new threads.Worker(url);
    worker.on('error', (e) => die(e instanceof Error ? e : new Error(String(e))));
    worker.on('exit', () => die(null));
    return { api: wrap<WorkerApi>(nodeEndpoint(worker)), handle: worker, detach: () => void (alive = false) };
  }
  let worker: Worker;
  if (given === undefined) {
    worker = new Worker(new URL('./worker.js', import.meta.url), { type: 'module' });
  } else if (given instanceof URL || typeof given === 'string') {
    worker = new Worker(given, { type: 'module' });
  } else if (typeof Worker !== 'undefined' && given instanceof Worker) {
    worker = given;
  } else {
    throw new TypeError(
      `openWorld: option 'worker' must be a Worker, a URL or a string, got ${given === null ? 'null' : typeof given}`,
    );
  }
  worker.addEventListener('error', (e) => die(new Error(e.message || 'the worker failed')));
  return { api: wrap<WorkerApi>(worker), handle: worker, detach: () => void (alive = false) };
}

/** The one implementation of {@link WorldHost}. */
class Host implements WorldHost {
  readonly dimensions: number;
  private mode: ThreadKind;
  /** Main thread: the world. Worker: the shadow that validates. */
  private core: WorldCore;
  private link: WorkerLink | null = null;
  private readonly queue: Operation[] = [];
  private nextBodyId = 0;
  private nextJointId = 0;
  private inFlight = false;
  private pendingReject: ((error: Error) => void) | null = null;
  private current: ReportView | null = null;
  /** The buffer the next step sends (worker) or fills (main). */
  private spare: ArrayBuffer | null = null;
  private lastSnapshot: Uint8Array | null = null;
  private disposed = false;
  private dead = false;
  private readonly options: WorldOptions;
  private readonly given: unknown;
  private readonly listeners = new Set<(event: HostDiedEvent) => void>();

  constructor(options: WorldOptions, core: WorldCore, mode: ThreadKind, given: unknown) {
    this.options = options;
    this.core = core;
    this.dimensions = core.D.n;
    this.mode = mode;
    this.given = given;
  }

  get thread(): ThreadKind {
    return this.mode;
  }

  get busy(): boolean {
    return this.inFlight || this.starting;
  }

  /** True while the first worker starts (steps are refused; descriptions and commands queue). */
  private starting = false;
  ready: Promise<void> = Promise.resolve();

  /** Starts the worker of a new world in the background; `ready` settles when it answers. */
  startInBackground(): void {
    this.starting = true;
    this.ready = this.attachWorker(null).then(
      () => {
        this.starting = false;
        if (this.disposed) this.endWorker();
      },
      (error: unknown) => {
        this.starting = false;
        const failure = error instanceof Error ? error : new Error(String(error));
        this.onDeath(failure);
        throw failure;
      },
    );
    // the `died` event reports a failure to whoever does not await `ready`
    this.ready.catch(() => undefined);
  }

  /** Runs `o` here (main) or on the shadow and queues it (worker). */
  private run(o: Operation): void {
    this.checkOpen();
    this.core.apply(o);
    if (this.mode === 'worker') this.queue.push(o);
  }

  private checkOpen(): void {
    if (this.disposed) throw new RangeError('WorldHost: this host was disposed');
  }

  addBody(description: BodyDescription): HostId {
    const id = this.nextBodyId;
    this.run({ op: 'addBody', id, description: this.mode === 'worker' ? structuredClone(description) : description });
    this.nextBodyId += 1;
    return id;
  }

  removeBody(id: HostId): void {
    this.run({ op: 'removeBody', id });
  }

  addJoint(description: JointDescription): HostId {
    const id = this.nextJointId;
    this.run({ op: 'addJoint', id, description: this.mode === 'worker' ? structuredClone(description) : description });
    this.nextJointId += 1;
    return id;
  }

  removeJoint(id: HostId): void {
    this.run({ op: 'removeJoint', id });
  }

  execute<C extends CommandName>(cmd: C, params: CommandMap[C]): void {
    this.run({
      op: 'execute',
      cmd,
      params: this.mode === 'worker' && params !== null && typeof params === 'object' ? structuredClone(params) : params,
    });
  }

  step(elapsed: number, maxSubSteps?: number): Promise<StepReport> | null {
    const where = 'WorldHost.step';
    this.checkOpen();
    if (typeof elapsed !== 'number')
      throw new TypeError(`${where}: argument 'elapsed' must be a number of seconds, got ${typeof elapsed}`);
    if (!(elapsed >= 0) || elapsed === Infinity)
      throw new RangeError(`${where}: argument 'elapsed' must be a finite number >= 0 (s), got ${elapsed}`);
    const fixed = this.core.world.params.fixedTimeStep;
    const max = maxSubSteps === undefined ? Math.max(1, Math.ceil(elapsed / fixed - 1e-9)) : maxSubSteps;
    if (typeof max !== 'number')
      throw new TypeError(`${where}: argument 'maxSubSteps' must be an integer >= 1, got ${typeof max}`);
    if (!Number.isInteger(max) || max < 1)
      throw new RangeError(`${where}: argument 'maxSubSteps' must be an integer >= 1, got ${max}`);
    if (this.inFlight || this.starting) return null;
    if (this.dead) return Promise.reject(new Error('WorldHost.step: the worker died; call restart()'));
    return this.mode === 'main' ? this.stepHere(elapsed, max) : this.stepThere(elapsed, max);
  }

  private stepHere(elapsed: number, max: number): Promise<StepReport> {
    const core = this.core;
    try {
      const steps = core.takeSteps(elapsed, max);
      const out = core.stepAndReport(steps, this.spare);
      this.spare = out;
      this.current = this.current === null ? new ReportView(core.D, out) : this.current.attach(out);
      return Promise.resolve(this.current);
    } catch (error) {
      return Promise.reject(error as Error);
    }
  }

  private stepThere(elapsed: number, max: number): Promise<StepReport> {
    const link = this.link!;
    const ops = this.queue.splice(0, this.queue.length);
    const send = this.spare;
    this.spare = null;
    this.inFlight = true;
    return new Promise<StepReport>((resolve, reject) => {
      this.pendingReject = reject;
      // the spare buffer travels as a transferable: moved, never copied
      const request =
        send === null ? link.api.step(ops, elapsed, max, null) : link.api.step(ops, elapsed, max, transfer(send, [send]));
      request.then(
        (answer) => {
          this.inFlight = false;
          this.pendingReject = null;
          if (answer.error !== null) {
            this.spare = answer.buffer;
            reject(errorFromData(answer.error));
            return;
          }
          const buffer = answer.buffer!;
          // The report of the last step is now free: it is the buffer the next step sends.
          this.spare = this.current === null ? null : this.current.buffer;
          this.current = this.current === null ? new ReportView(this.core.D, buffer) : this.current.attach(buffer);
          // Joints that broke there are gone there: forget them here too.
          for (let i = 0; i < this.current.brokenCount; i += 1) {
            try {
              this.core.apply({ op: 'removeJoint', id: this.current.broken[i]! });
            } catch {
              // already removed by the caller since
            }
          }
          resolve(this.current);
        },
        (error: unknown) => {
          this.inFlight = false;
          this.pendingReject = null;
          reject(error instanceof Error ? error : new Error(String(error)));
        },
      );
    });
  }

  angularVelocity(id: HostId, out: Float64Array = new Float64Array(this.core.D.k)): Float64Array {
    const where = 'WorldHost.angularVelocity';
    const D = this.core.D;
    if (!(out instanceof Float64Array) || out.length !== D.k)
      throw new TypeError(`${where}: argument 'out' must be a Float64Array of length ${D.k}`);
    const body = this.core.bodyOf(id, 'id');
    out.fill(0);
    const r = this.current;
    if (r === null || body.type === 'static') return out;
    const index = this.core.world.bodies.indexOf(body);
    let at = -1;
    if (index >= 0 && index < r.bodyCount && r.bodies[index * r.stride] === id) at = index * r.stride;
    else for (let i = 0; i < r.bodyCount && at < 0; i += 1) if (r.bodies[i * r.stride] === id) at = i * r.stride;
    if (at < 0) return out;
    const s =
      this.omegaScratch ??
      (this.omegaScratch = {
        R: new Float64Array(D.r),
        F: new Float64Array(D.r),
        L: new Float64Array(D.k),
        tmp: new Float64Array(D.k),
      });
    for (let i = 0; i < D.r; i += 1) s.R[i] = r.bodies[at + 1 + D.n + i]!;
    for (let i = 0; i < D.k; i += 1) s.L[i] = r.bodies[at + 1 + 2 * D.n + D.r + i]!;
    const frame = body.shape.frameRotor;
    if (frame !== undefined) {
      D.kernels.mul(s.F, s.R, frame);
      s.R.set(s.F);
    }
    return angularVelocityFromMomentum(D, out, s.R, body.invInertia, s.L, s.tmp);
  }

  private omegaScratch: { R: Float64Array; F: Float64Array; L: Float64Array; tmp: Float64Array } | null = null;

  async snapshot(): Promise<Uint8Array> {
    this.checkOpen();
    if (this.inFlight || this.starting)
      throw new RangeError('WorldHost.snapshot: a step is in flight or the worker is starting; wait for it');
    let bytes: Uint8Array;
    if (this.mode === 'main') {
      bytes = this.core.snapshot();
    } else {
      const ops = this.queue.splice(0, this.queue.length);
      const answer = await this.link!.api.snapshot(ops);
      if (!(answer instanceof Uint8Array)) throw errorFromData(answer as ErrorData);
      bytes = answer;
    }
    this.lastSnapshot = bytes;
    return bytes.slice();
  }

  async moveTo(thread: ThreadKind): Promise<void> {
    this.checkOpen();
    if (thread !== 'main' && thread !== 'worker')
      throw new RangeError(`WorldHost.moveTo: argument 'thread' must be 'main' or 'worker', got ${String(thread)}`);
    if (thread === this.mode) return;
    const bytes = await this.snapshot();
    if (thread === 'worker') {
      await this.attachWorker(bytes);
      this.core = WorldCore.restore(bytes);
      this.mode = 'worker';
    } else {
      this.endWorker();
      this.core = WorldCore.restore(bytes);
      this.mode = 'main';
    }
    this.spare = null;
    this.current = null;
  }

  async restart(): Promise<void> {
    this.checkOpen();
    if (this.mode !== 'worker') throw new RangeError('WorldHost.restart: the world is in the main thread');
    const bytes = this.lastSnapshot ?? this.core.snapshot();
    this.endWorker();
    this.queue.length = 0;
    await this.attachWorker(bytes);
    this.core = WorldCore.restore(bytes);
    this.spare = null;
    this.current = null;
    this.dead = false;
  }

  /** Starts a worker and opens the world there (a new world when `bytes` is null). */
  async attachWorker(bytes: Uint8Array | null): Promise<void> {
    const link = await startWorker(this.given, (error) => this.onDeath(error));
    const failure = await link.api.open(this.options, bytes);
    if (failure !== null) {
      link.detach();
      void link.handle.terminate();
      throw errorFromData(failure);
    }
    this.link = link;
  }

  private endWorker(): void {
    if (this.link === null) return;
    this.link.detach();
    void this.link.handle.terminate();
    this.link = null;
  }

  private onDeath(error: Error | null): void {
    this.dead = true;
    this.inFlight = false;
    const reject = this.pendingReject;
    this.pendingReject = null;
    reject?.(error ?? new Error('WorldHost: the worker ended'));
    const event: HostDiedEvent = { type: 'died', error };
    for (const fn of [...this.listeners]) fn(event);
  }

  addEventListener(type: 'died', listener: (event: HostDiedEvent) => void): void {
    if (type !== 'died') throw new RangeError(`WorldHost.addEventListener: unknown event '${String(type)}' (known: died)`);
    if (typeof listener !== 'function') throw new TypeError("WorldHost.addEventListener: argument 'listener' must be a function");
    this.listeners.add(listener);
  }

  removeEventListener(type: 'died', listener: (event: HostDiedEvent) => void): void {
    if (type !== 'died') throw new RangeError(`WorldHost.removeEventListener: unknown event '${String(type)}' (known: died)`);
    this.listeners.delete(listener);
  }

  /** Ends the worker of someone else's making without telling us (for tests of death). */
  terminateWorker(): void {
    void this.link?.handle.terminate();
  }

  dispose(): void {
    if (this.disposed) return;
    this.endWorker();
    this.disposed = true;
    this.queue.length = 0;
    this.listeners.clear();
  }
}

/**
 * Opens a world in this thread (`thread: 'main'`, the default) or in a worker, and resolves to
 * its host. `options` are `new World`'s; they are checked here, in the caller's thread.
 */
export async function openWorld(options: WorldOptions, hostOptions: HostOptions = {}): Promise<WorldHost> {
  const host = createWorld(options, hostOptions);
  await host.ready;
  return host;
}

/**
 * Like `openWorld`, but returns the host at once: in worker mode the worker starts in the
 * background (`host.ready` settles when it answers; until then `step` returns null and everything
 * else is validated here and queued). Bad options throw here, synchronously.
 */
export function createWorld(options: WorldOptions, hostOptions: HostOptions = {}): WorldHost {
  if (hostOptions === null || typeof hostOptions !== 'object') {
    throw new TypeError(
      `createWorld: argument 'hostOptions' must be an object { thread?, worker? }, got ${hostOptions === null ? 'null' : typeof hostOptions}`,
    );
  }
  const thread = hostOptions.thread ?? (hostOptions.worker !== undefined ? 'worker' : 'main');
  if (thread !== 'main' && thread !== 'worker')
    throw new RangeError(`createWorld: option 'thread' must be 'main' or 'worker', got ${String(thread)}`);
  const core = WorldCore.create(options);
  const host = new Host(options, core, thread, hostOptions.worker);
  if (thread === 'worker') host.startInBackground();
  return host;
}
