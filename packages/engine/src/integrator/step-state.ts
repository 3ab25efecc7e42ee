/**
 * The start-of-step copy of every body's state, and the finite check that decides whether it is
 * needed.
 *
 * The copy is taken once per `World.step` for the awake bodies (one typed-array copy per body, no
 * allocation; a body that wakes during the step is copied as it wakes, and a sleeping one does not
 * change) so that a step that produces a non-finite number can be undone completely; see
 * `NonFiniteStateError`.
 *
 * @module
 */
import type { Body } from '../body.js';
import type { StateField } from '../errors.js';

/** A growable flat array of body states: x, R, v, L, w per body, at the body's world index. */
export interface StepSnapshot {
  /** The stored states, `stride` numbers per body. */
  data: Float64Array;
  /** Numbers per body: Body.stateLength(D). */
  readonly stride: number;
}

/** Creates an empty snapshot store for bodies of `stride` state numbers. */
export function createStepSnapshot(stride: number, capacity = 16): StepSnapshot {
  return { data: new Float64Array(stride * Math.max(1, capacity)), stride };
}

/** Makes room for `count` bodies (allocates only when the capacity grows; never during a step). */
export function reserveStepSnapshot(snap: StepSnapshot, count: number): void {
  if (count * snap.stride <= snap.data.length) return;
  let capacity = snap.data.length / snap.stride;
  while (capacity < count) capacity *= 2;
  snap.data = new Float64Array(capacity * snap.stride);
}

/** Copies the state of one body into its place (its world index) in the snapshot. */
export function saveBodyState(snap: StepSnapshot, body: Body): void {
  const data = snap.data;
  const stride = snap.stride;
  const record = body.storage;
  const at = body.storageOffset;
  const base = body.worldIndex * stride;
  for (let i = 0; i < stride; i += 1) data[base + i] = record[at + i]!;
}

/** Puts bodies[0 .. count) back to the states saved by {@link saveBodyState}. */
export function restoreBodyStates(snap: StepSnapshot, bodies: readonly Body[], count: number): void {
  const data = snap.data;
  const stride = snap.stride;
  for (let b = 0; b < count; b += 1) {
    const record = bodies[b]!.storage;
    const at = bodies[b]!.storageOffset;
    const base = bodies[b]!.worldIndex * stride;
    for (let i = 0; i < stride; i += 1) record[at + i] = data[base + i]!;
  }
}

/**
 * True when every number of the body's state (x, R, v, L, w) is finite. A sum of x·0 terms is 0
 * when all are finite and NaN as soon as one is not (no false alarm from overflow of the sum).
 */
export function isStateFinite(body: Body): boolean {
  const s = body.storage;
  const at = body.storageOffset;
  const D = body.D;
  const end = at + 2 * D.n + D.r + 2 * D.k; // Body.stateLength
  let acc = 0;
  for (let i = at; i < end; i += 1) acc += s[i]! * 0;
  return acc === 0;
}

function hasNonFinite(a: Float64Array): boolean {
  for (let i = 0; i < a.length; i += 1) if (!Number.isFinite(a[i]!)) return true;
  return false;
}

/**
 * The first non-finite field of a body, or null; order v, L, x, R, w (causes before effects).
 * For the error path only.
 */
export function firstNonFiniteField(body: Body): StateField | null {
  if (hasNonFinite(body.v)) return 'v';
  if (hasNonFinite(body.L)) return 'L';
  if (hasNonFinite(body.x)) return 'x';
  if (hasNonFinite(body.R)) return 'R';
  if (hasNonFinite(body.w)) return 'w';
  return null;
}
