/**
 * The report of one step, in one ArrayBuffer that travels between the threads and is reused:
 *
 * - bytes 0..63: a Float64 header — steps, time, body count, collision count, broken count,
 *   slept count, woke count, report buffers the writer has created so far;
 * - then Float32 body records `id | position (n) | rotor (r) | velocity (n) | momentum (k)`;
 * - then Float32 collision records `phase | idA | idB | impulse | point (n) | normal (n) | relative
 *   velocity (n)`;
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
const H_TIME = 1;
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

/** Numbers per collision record: 4 + 3n. */
export function collisionStride(D: Dims): number {
  return 4 + 3 * D.n;
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
    this.buffer = buffer;
    const h = new Float64Array(buffer, 0, 8);
    this.steps = h[H_STEPS]!;
    this.time = h[H_TIME]!;
    this.bodyCount = h[H_BODIES]!;
    this.collisionCount = h[H_COLLISIONS]!;
    this.brokenCount = h[H_BROKEN]!;
    this.sleptCount = h[H_SLEPT]!;
    this.wokeCount = h[H_WOKE]!;
    this.buffersCreated = h[H_BUFFERS]!;
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

/** Writes the header of a report. */
export function writeHeader(buffer: ArrayBuffer, steps: number, time: number, c: ReportCounts, buffersCreated: number): void {
  const h = new Float64Array(buffer, 0, 8);
  h[H_STEPS] = steps;
  h[H_TIME] = time;
  h[H_BODIES] = c.bodies;
  h[H_COLLISIONS] = c.collisions;
  h[H_BROKEN] = c.broken;
  h[H_SLEPT] = c.slept;
  h[H_WOKE] = c.woke;
  h[H_BUFFERS] = buffersCreated;
}
