/**
 * The report of one step, in one ArrayBuffer that travels between the threads and is reused:
 *
 * - bytes 0..63: a Float64 header — steps, time, body count, collision count, broken count,
 *   slept count, woke count, report buffers the writer has created so far;
 * - then Float32 body records `id | position (n) | rotor (r) | velocity (n) | momentum (k)`;
 * - then Float32 collision records `phase | idA | idB | impulse | point (n) | normal (n) | relative
 *   velocity (n) | partA | partB` (the parts of compound bodies that touched; 0 for one shape);
 * - then Int32 ids: the joints broken, the bodies that fell asleep, the bodies that woke.
 *
 * The writer grows the buffer only when a step needs more room than it has (a larger world, a
 * burst of events); otherwise the same bytes are written over and over.
 *
 * @module
 */
import type { Dims } from '@physin/engine';
import type { StepReport } from './types.js';

/** Bytes of the Float64 header. */
export const HEADER_BYTES = 64;
const H_STEPS = 0;
export const H_TIME = 1;
const H_BODIES = 2;
const H_COLLISIONS = 3;
const H_BROKEN = 4;
const H_SLEPT = 5;
const H_WOKE = 6;
const H_BUFFERS = 7;

/** Numbers per body record: 1 + 2n + r + k. */
export function bodyStride(D: Dims): number {
  return 1 + 2 * D.n + D.r + D.k;
}

/** Numbers per collision record: 6 + 3n. */
export function collisionStride(D: Dims): number {
  return 6 + 3 * D.n;
}

/** The counts of one report. */
export interface ReportCounts {
  bodies: number;
  collisions: number;
  broken: number;
  slept: number;
  woke: number;
}

/** Bytes a report with these counts takes. */
export function reportBytes(D: Dims, c: ReportCounts): number {
  return HEADER_BYTES + 4 * (c.bodies * bodyStride(D) + c.collisions * collisionStride(D) + c.broken + c.slept + c.woke);
}

/**
 * Typed views over a report buffer, laid out for the given counts. Rebuilt for each buffer that
 * arrives (a transferred ArrayBuffer is a new object on the receiving side); the buffer itself is
 * never copied.
 */
export class ReportView implements StepReport {
  steps = 0;
  time = 0;
  bodyCount = 0;
  readonly stride: number;
  bodies: Float32Array;
  collisionCount = 0;
  readonly collisionStride: number;
  collisions: Float32Array;
  broken: Int32Array;
  brokenCount = 0;
  slept: Int32Array;
  sleptCount = 0;
  woke: Int32Array;
  wokeCount = 0;
  buffersCreated = 0;
  /** The buffer the views look at. */
  buffer: ArrayBuffer;
  private header: Float64Array | null = null;

  constructor(D: Dims, buffer: ArrayBuffer) {
    this.stride = bodyStride(D);
    this.collisionStride = collisionStride(D);
    this.buffer = buffer;
    this.bodies = new Float32Array(0);
    this.collisions = new Float32Array(0);
    this.broken = new Int32Array(0);
    this.slept = new Int32Array(0);
    this.woke = new Int32Array(0);
    this.attach(buffer);
  }

  /** Points the views at `buffer`, reading the counts from its header. */
  attach(buffer: ArrayBuffer): this {
    const same = buffer === this.buffer && this.header !== null;
    this.buffer = buffer;
    if (!same) this.header = new Float64Array(buffer, 0, 8);
    const h = this.header!;
    const layout =
      h[H_BODIES]! !== this.bodyCount ||
      h[H_COLLISIONS]! !== this.collisionCount ||
      h[H_BROKEN]! !== this.brokenCount ||
      h[H_SLEPT]! !== this.sleptCount ||
      h[H_WOKE]! !== this.wokeCount;
    this.steps = h[H_STEPS]!;
    this.time = h[H_TIME]!;
    this.bodyCount = h[H_BODIES]!;
    this.collisionCount = h[H_COLLISIONS]!;
    this.brokenCount = h[H_BROKEN]!;
    this.sleptCount = h[H_SLEPT]!;
    this.wokeCount = h[H_WOKE]!;
    this.buffersCreated = h[H_BUFFERS]!;
    // the same buffer with the same counts (a main-thread world at rest): the views still fit
    if (same && !layout) return this;
    let at = HEADER_BYTES;
    this.bodies = new Float32Array(buffer, at, this.bodyCount * this.stride);
    at += this.bodies.byteLength;
    this.collisions = new Float32Array(buffer, at, this.collisionCount * this.collisionStride);
    at += this.collisions.byteLength;
    this.broken = new Int32Array(buffer, at, this.brokenCount);
    at += this.broken.byteLength;
    this.slept = new Int32Array(buffer, at, this.sleptCount);
    at += this.slept.byteLength;
    this.woke = new Int32Array(buffer, at, this.wokeCount);
    return this;
  }
}

/** Views over a whole report buffer: the header, and the records and id lists after it. */
export interface ReportViews {
  readonly buffer: ArrayBuffer;
  readonly header: Float64Array;
  /** Float32 records from the end of the header to the end of the buffer. */
  readonly floats: Float32Array;
  /** The same bytes as Int32 (the id lists), indexed like `floats`. */
  readonly ints: Int32Array;
}

/** Makes the views of a report buffer (once per buffer object). */
export function reportViews(buffer: ArrayBuffer): ReportViews {
  return {
    buffer,
    header: new Float64Array(buffer, 0, 8),
    floats: new Float32Array(buffer, HEADER_BYTES),
    ints: new Int32Array(buffer, HEADER_BYTES),
  };
}

/**
 * Writes the header of a report into its header view, but for the time (`h[H_TIME]`), which the
 * caller writes itself: a double passed as an argument may be boxed.
 */
export function writeHeaderInto(h: Float64Array, steps: number, c: ReportCounts, buffersCreated: number): void {
  h[H_STEPS] = steps;
  h[H_BODIES] = c.bodies;
  h[H_COLLISIONS] = c.collisions;
  h[H_BROKEN] = c.broken;
  h[H_SLEPT] = c.slept;
  h[H_WOKE] = c.woke;
  h[H_BUFFERS] = buffersCreated;
}
