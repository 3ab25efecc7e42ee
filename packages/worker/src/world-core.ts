/**
 * The world and its host ids, in the thread that owns it: the same class runs in the main thread
 * and in a worker, so the two give the same bytes.
 *
 * It applies the batched operations in order, steps with the accumulator, and writes the report.
 *
 * @module
 */
import { World, restoreWorld, snapshotWorld } from '@physin/engine';
import type { Body, Joint } from '@physin/engine';
import type { Dims, WorldOptions } from '@physin/engine';
import { runCommand } from './commands.js';
import type { CommandTarget } from './commands.js';
import { buildBody, buildJoint, checkHostId } from './describe.js';
import { bodyStride, collisionStride, H_TIME, reportBytes, reportViews, writeHeaderInto } from './report.js';
import type { ReportViews } from './report.js';
import type { ReportCounts } from './report.js';
import type { BodyDescription, HostId, JointDescription } from './types.js';

/** One batched operation. */
export type Operation =
  | { readonly op: 'addBody'; readonly id: HostId; readonly description: BodyDescription }
  | { readonly op: 'removeBody'; readonly id: HostId }
  | { readonly op: 'addJoint'; readonly id: HostId; readonly description: JointDescription }
  | { readonly op: 'removeJoint'; readonly id: HostId }
  | { readonly op: 'execute'; readonly cmd: string; readonly params: object };

const SNAPSHOT_MAGIC = 0x53484e50; // 'PNHS'
const SNAPSHOT_VERSION = 1;

/**
 * A world with host ids. `apply` validates through the engine and changes nothing on error, so
 * the caller's thread can run the same operation on a shadow core to validate it before it is
 * queued for the real one.
 */
export class WorldCore implements CommandTarget {
  readonly world: World;
  readonly D: Dims;
  private readonly bodies = new Map<HostId, Body>();
  private readonly joints = new Map<HostId, Joint>();
  private readonly bodyIds = new Map<Body, HostId>();
  private readonly jointIds = new Map<Joint, HostId>();
  /** Ids of bodies removed since the last report (their end events name them). */
  private readonly departed = new Map<Body, HostId>();
  /** Time not yet stepped (s). */
  accumulator = 0;
  /** Report buffers this core has created (it stops growing in steady state). */
  buffersCreated = 0;
  // ---- the events of one report, gathered over its fixed steps ----
  private events = new Float64Array(64);
  private eventCount = 0;
  private broken: Int32Array<ArrayBuffer> = new Int32Array(8);
  private brokenCount = 0;
  /** Whether each body was asleep in the last report (1) or not (absent or 0). */
  private readonly reportedSleep = new Map<Body, number>();
  private readonly scratchX: Float64Array;
  private readonly scratchR: Float64Array;
  private readonly onBroken = (event: { joint: Joint }): void => {
    const id = this.jointIds.get(event.joint);
    if (id === undefined) return;
    if (this.brokenCount === this.broken.length) this.broken = growInt32(this.broken, this.brokenCount * 2);
    this.broken[this.brokenCount++] = id;
    this.joints.delete(id);
    this.jointIds.delete(event.joint);
  };

  constructor(world: World) {
    this.world = world;
    this.D = world.D;
    this.scratchX = new Float64Array(this.D.n);
    this.scratchR = new Float64Array(this.D.r);
  }

  /** A core around a new world. */
  static create(options: WorldOptions): WorldCore {
    return new WorldCore(new World(options));
  }

  get bodyCount(): number {
    return this.bodies.size;
  }

  get jointCount(): number {
    return this.joints.size;
  }

  bodyOf(id: unknown, name: string): Body {
    const body = typeof id === 'number' ? this.bodies.get(id) : undefined;
    if (body === undefined) {
      checkHostId('WorldHost', name, id);
      throw new RangeError(`WorldHost: argument '${name}' names no body (id ${String(id)})`);
    }
    return body;
  }

  jointOf(id: unknown, name: string): Joint {
    const joint = typeof id === 'number' ? this.joints.get(id) : undefined;
    if (joint === undefined) {
      checkHostId('WorldHost', name, id);
      throw new RangeError(`WorldHost: argument '${name}' names no joint (id ${String(id)})`);
    }
    return joint;
  }

  /** Runs one operation; throws (changing nothing) if the engine refuses it. */
  apply(o: Operation): void {
    switch (o.op) {
      case 'addBody': {
        const where = 'WorldHost.addBody';
        checkHostId(where, 'id', o.id);
        if (this.bodies.has(o.id)) throw new RangeError(`${where}: id ${o.id} is taken`);
        const body = this.world.addBody(buildBody(this.D, o.description, where));
        this.bodies.set(o.id, body);
        this.bodyIds.set(body, o.id);
        return;
      }
      case 'removeBody': {
        const body = this.bodyOf(o.id, 'id');
        // The joints that hold it go first (the engine refuses to remove a held body).
        for (const joint of [...this.world.constraints]) {
          if (joint.a === body || joint.b === body) this.removeJointObject(joint);
        }
        this.world.removeBody(body);
        this.bodies.delete(o.id);
        this.bodyIds.delete(body);
        this.reportedSleep.delete(body);
        this.departed.set(body, o.id);
        return;
      }
      case 'addJoint': {
        const where = 'WorldHost.addJoint';
        checkHostId(where, 'id', o.id);
        if (this.joints.has(o.id)) throw new RangeError(`${where}: id ${o.id} is taken`);
        const joint = this.world.addConstraint(buildJoint(o.description, (id, name) => this.bodyOf(id, name), where));
        joint.addEventListener('broken', this.onBroken);
        this.joints.set(o.id, joint);
        this.jointIds.set(joint, o.id);
        return;
      }
      case 'removeJoint':
        this.removeJointObject(this.jointOf(o.id, 'id'));
        return;
      case 'execute':
        runCommand(this, o.cmd, o.params, 'WorldHost.execute');
        return;
      default:
        throw new RangeError(`WorldHost: unknown operation '${String((o as { op?: unknown }).op)}'`);
    }
  }

  private removeJointObject(joint: Joint): void {
    this.world.removeConstraint(joint);
    joint.removeEventListener('broken', this.onBroken);
    const id = this.jointIds.get(joint)!;
    this.joints.delete(id);
    this.jointIds.delete(joint);
  }

  /** How many fixed steps `elapsed` (plus the carried time) makes, at most `maxSubSteps`; the rest carries. */
  takeSteps(elapsed: number, maxSubSteps: number): number {
    const fixed = this.world.params.fixedTimeStep;
    const total = this.accumulator + elapsed;
    // The tiny slack keeps 2 × (1/60) from rounding down to one step.
    const whole = Math.floor(total / fixed + 1e-9);
    const steps = Math.min(whole, maxSubSteps);
    this.accumulator = Math.max(0, total - whole * fixed);
    return steps;
  }

  /**
   * Steps `steps` fixed steps and writes the report into `buffer`, or into a larger new buffer if
   * it does not fit; returns the buffer written. On an engine error the world is as the engine
   * left it and the error is thrown.
   */
  stepAndReport(steps: number, buffer: ArrayBuffer | null): ArrayBuffer {
    const world = this.world;
    const list = world.bodies;
    const count = list.length;
    this.eventCount = 0;
    this.brokenCount = 0;
    for (let s = 0; s < steps; s += 1) {
      // no argument: the step's default is params.fixedTimeStep, and a double read from an
      // object and passed to a call is boxed (16 bytes a step)
      world.step();
      this.gatherCollisions();
    }
    this.departed.clear();
    let slept = 0;
    let woke = 0;
    for (let i = 0; i < count; i += 1) {
      const body = list[i]!;
      const now = body.isSleeping ? 1 : 0;
      const before = this.reportedSleep.get(body) ?? 0;
      if (now > before) slept += 1;
      else if (now < before) woke += 1;
    }
    // one counts object and one set of views per buffer, reused: writing a report allocates nothing
    const counts = this.counts;
    counts.bodies = count;
    counts.collisions = this.eventCount;
    counts.broken = this.brokenCount;
    counts.slept = slept;
    counts.woke = woke;
    const need = reportBytes(this.D, counts);
    let out = buffer;
    if (out === null || out.byteLength < need) {
      out = new ArrayBuffer(Math.max(need, out === null ? 0 : 2 * out.byteLength));
      this.buffersCreated += 1;
    }
    const views = this.viewsOf(out);
    writeHeaderInto(views.header, steps, counts, this.buffersCreated);
    views.header[H_TIME] = world.time;
    this.writeRecords(views, counts);
    return out;
  }

  private readonly counts: ReportCounts = { bodies: 0, collisions: 0, broken: 0, slept: 0, woke: 0 };
  private views: ReportViews | null = null;

  /** Views over the whole of `buffer`, made again only when the buffer is another object. */
  private viewsOf(buffer: ArrayBuffer): ReportViews {
    if (this.views === null || this.views.buffer !== buffer) this.views = reportViews(buffer);
    return this.views;
  }

  private idOf(body: Body): number {
    return this.bodyIds.get(body) ?? this.departed.get(body) ?? -1;
  }

  /** Appends the begin and end events of the last fixed step. */
  private gatherCollisions(): void {
    const ev = this.world.contactEvents;
    const n = this.D.n;
    const stride = collisionStride(this.D);
    const total = this.eventCount + ev.beginCount + ev.endCount;
    if (total * stride > this.events.length) {
      const next = new Float64Array(Math.max(total * stride, 2 * this.events.length));
      next.set(this.events);
      this.events = next;
    }
    const e = this.events;
    for (let i = 0; i < ev.beginCount; i += 1) {
      const A = ev.beginA[i]!;
      const B = ev.beginB[i]!;
      const at = this.eventCount++ * stride;
      e[at] = 0;
      e[at + 1] = this.idOf(A);
      e[at + 2] = this.idOf(B);
      e[at + 3] = ev.beginImpulse[i]!;
      for (let c = 0; c < n; c += 1) {
        e[at + 4 + c] = ev.beginPoint[i * n + c]!;
        e[at + 4 + n + c] = ev.beginNormal[i * n + c]!;
      }
      this.relativeVelocity(e, at + 4 + 2 * n, A, B, at + 4);
      e[at + 4 + 3 * n] = ev.beginPartA[i]!;
      e[at + 5 + 3 * n] = ev.beginPartB[i]!;
    }
    for (let i = 0; i < ev.endCount; i += 1) {
      const at = this.eventCount++ * stride;
      e.fill(0, at, at + stride);
      e[at] = 1;
      e[at + 1] = this.idOf(ev.endA[i]!);
      e[at + 2] = this.idOf(ev.endB[i]!);
      e[at + 4 + 3 * n] = ev.endPartA[i]!;
      e[at + 5 + 3 * n] = ev.endPartB[i]!;
    }
  }

  /** Velocity of B's material point at p minus A's (after the step), into e[out ..]. */
  private relativeVelocity(e: Float64Array, out: number, A: Body, B: Body, p: number): void {
    const n = this.D.n;
    for (let c = 0; c < n; c += 1) e[out + c] = B.v[c]! - A.v[c]!;
    // v += ω ⌋ (p − x): row (i, j) of ω turns e_i toward e_j.
    let q = 0;
    for (let i = 0; i < n; i += 1) {
      for (let j = i + 1; j < n; j += 1, q += 1) {
        const wb = B.w[q]!;
        const wa = A.w[q]!;
        const rbi = e[p + i]! - B.x[i]!;
        const rbj = e[p + j]! - B.x[j]!;
        const rai = e[p + i]! - A.x[i]!;
        const raj = e[p + j]! - A.x[j]!;
        e[out + j] = e[out + j]! + wb * rbi - wa * rai;
        e[out + i] = e[out + i]! - wb * rbj + wa * raj;
      }
    }
  }

  private writeRecords(views: ReportViews, c: ReportCounts): void {
    const D = this.D;
    const { n, r, k } = D;
    const stride = bodyStride(D);
    const f = views.floats;
    const list = this.world.bodies;
    const x = this.scratchX;
    const R = this.scratchR;
    for (let i = 0; i < c.bodies; i += 1) {
      const body = list[i]!;
      let at = i * stride;
      f[at++] = this.bodyIds.get(body)!;
      body.getPositionN(x);
      for (let a = 0; a < n; a += 1) f[at++] = x[a]!;
      body.getRotor(R);
      for (let a = 0; a < r; a += 1) f[at++] = R[a]!;
      const v = body.v;
      for (let a = 0; a < n; a += 1) f[at++] = v[a]!;
      const L = body.L;
      for (let a = 0; a < k; a += 1) f[at++] = L[a]!;
    }
    const base = c.bodies * stride;
    const len = c.collisions * collisionStride(D);
    for (let i = 0; i < len; i += 1) f[base + i] = this.events[i]!;
    // the id lists follow the records, in the same 4-byte index space
    const ints = views.ints;
    const first = base + len;
    for (let i = 0; i < c.broken; i += 1) ints[first + i] = this.broken[i]!;
    let s = first + c.broken;
    let w = first + c.broken + c.slept;
    for (let i = 0; i < c.bodies; i += 1) {
      const body = list[i]!;
      const now = body.isSleeping ? 1 : 0;
      const before = this.reportedSleep.get(body) ?? 0;
      if (now === before) continue;
      if (now > before) ints[s++] = this.bodyIds.get(body)!;
      else ints[w++] = this.bodyIds.get(body)!;
      this.reportedSleep.set(body, now);
    }
  }

  /** The world and its ids as bytes: a small header, the ids in world order, then `snapshotWorld(world)`. */
  snapshot(): Uint8Array {
    const world = snapshotWorld(this.world);
    const bodies = this.world.bodies;
    const joints = this.world.constraints;
    const head = 24 + 4 * (bodies.length + joints.length);
    const out = new Uint8Array(head + world.length);
    const view = new DataView(out.buffer);
    view.setUint32(0, SNAPSHOT_MAGIC, true);
    view.setUint32(4, SNAPSHOT_VERSION, true);
    view.setFloat64(8, this.accumulator, true);
    view.setUint32(16, bodies.length, true);
    view.setUint32(20, joints.length, true);
    let at = 24;
    for (const b of bodies) {
      view.setInt32(at, this.bodyIds.get(b)!, true);
      at += 4;
    }
    for (const j of joints) {
      view.setInt32(at, this.jointIds.get(j)!, true);
      at += 4;
    }
    out.set(world, head);
    return out;
  }

  /** A core rebuilt from {@link WorldCore.snapshot}'s bytes. */
  static restore(bytes: Uint8Array): WorldCore {
    const where = 'WorldHost.restore';
    if (!(bytes instanceof Uint8Array)) throw new TypeError(`${where}: argument 'bytes' must be a Uint8Array`);
    if (bytes.length < 24) throw new RangeError(`${where}: argument 'bytes' is too short to be a host snapshot`);
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    if (view.getUint32(0, true) !== SNAPSHOT_MAGIC) throw new RangeError(`${where}: argument 'bytes' is not a host snapshot`);
    const version = view.getUint32(4, true);
    if (version !== SNAPSHOT_VERSION)
      throw new RangeError(`${where}: argument 'bytes' has version ${version}; this build reads ${SNAPSHOT_VERSION}`);
    const nb = view.getUint32(16, true);
    const nj = view.getUint32(20, true);
    const head = 24 + 4 * (nb + nj);
    if (bytes.length < head) throw new RangeError(`${where}: argument 'bytes' is truncated`);
    const core = new WorldCore(restoreWorld(bytes.subarray(head)));
    core.accumulator = view.getFloat64(8, true);
    const bodies = core.world.bodies;
    const joints = core.world.constraints;
    if (bodies.length !== nb || joints.length !== nj)
      throw new RangeError(`${where}: argument 'bytes' holds inconsistent counts`);
    let at = 24;
    for (const b of bodies) {
      const id = view.getInt32(at, true);
      at += 4;
      core.bodies.set(id, b);
      core.bodyIds.set(b, id);
      if (b.isSleeping) core.reportedSleep.set(b, 1);
    }
    for (const j of joints) {
      const id = view.getInt32(at, true);
      at += 4;
      core.joints.set(id, j);
      core.jointIds.set(j, id);
      j.addEventListener('broken', core.onBroken);
    }
    return core;
  }
}

function growInt32(a: Int32Array, size: number): Int32Array<ArrayBuffer> {
  const next = new Int32Array(Math.max(size, 8));
  next.set(a);
  return next;
}
