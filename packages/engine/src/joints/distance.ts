/**
 * The distance joint: the length between two anchor points. It takes away one degree of freedom
 * in any n (1 of 6 in 3D, 1 of 10 in 4D). A rod holds the length both ways, a rope only stops it
 * from growing (it pulls), a strut only stops it from shrinking (it pushes).
 *
 * @module
 */
import type { Body } from '../body.js';
import { currentAnchors, distance } from './frames.js';
import { Joint } from './joint.js';
import { JS_COMMON_COUNT } from './joint-slots.js';
import type { JointOptions } from './joint.js';
import type { JointSolver } from './joint-solver.js';
import { KIND_LINEAR, ROW_EQUAL, ROW_INEQUAL, SC_C, SC_TOL } from './joint-solver.js';
import { readNonNegative } from './options.js';
import { registerJointClass } from '../snapshot/registry.js';

/** How a {@link DistanceJoint} holds its length. */
export type DistanceMode = 'rod' | 'rope' | 'strut';

/** Options of a {@link DistanceJoint}. */
export interface DistanceJointOptions extends JointOptions {
  /** The length to hold (m, >= 0); default: the distance of the anchors at construction. */
  readonly rest?: number;
  /** 'rod' (default): the length both ways; 'rope': at most `rest`; 'strut': at least `rest`. */
  readonly mode?: DistanceMode;
}

const MODES: readonly DistanceMode[] = ['rod', 'rope', 'strut'];
const JS_REST = JS_COMMON_COUNT;

function readMode(fn: string, name: string, mode: unknown): number {
  if (typeof mode !== 'string')
    throw new TypeError(`${fn}: argument '${name}' must be a string ('rod', 'rope' or 'strut'), got ${typeof mode}`);
  const m = MODES.indexOf(mode as DistanceMode);
  if (m < 0) throw new RangeError(`${fn}: argument '${name}' must be 'rod', 'rope' or 'strut', got '${mode}'`);
  return m;
}

/**
 * Holds the distance between the point `localA` of `a` and the point `localB` of `b` (a world
 * point when `b` is null): one row along the unit vector between the anchors.
 */
export class DistanceJoint extends Joint {
  private modeIndex: number;

  /**
   * @param a the first body.
   * @param b the second body, or null for the world.
   * @param localA anchor on a, in a's frame (n numbers).
   * @param localB anchor on b, in b's frame, or a world point when b is null (n numbers).
   * @param opts `rest`, `mode` and the common options.
   * @throws TypeError / RangeError for a bad argument (an unknown mode, a negative rest, ...).
   */
  constructor(a: Body, b: Body | null, localA: ArrayLike<number>, localB: ArrayLike<number>, opts?: DistanceJointOptions) {
    super('new DistanceJoint', a, b, localA, localB, opts as Record<string, unknown> | undefined, ['rest', 'mode'], 1, () => 1);
    const fn = 'new DistanceJoint';
    const o = (opts ?? {}) as Record<string, unknown>;
    this.modeIndex = o.mode === undefined ? 0 : readMode(fn, 'opts.mode', o.mode);
    this.state[JS_REST] = o.rest === undefined ? this.length : readNonNegative(fn, 'opts.rest', o.rest);
  }

  /** Rows it takes away: 1. */
  get rowCount(): number {
    return 1;
  }

  /** The length it holds (m). */
  get rest(): number {
    return this.state[JS_REST]!;
  }

  /** 'rod', 'rope' or 'strut'. */
  get mode(): DistanceMode {
    return MODES[this.modeIndex]!;
  }

  /** The current distance of the anchors (m). */
  get length(): number {
    const { pA, pB } = currentAnchors(this);
    return distance(pA, pB);
  }

  /**
   * Sets the length to hold (m, >= 0). The bodies move there at most at `constraintMaxBias`.
   * @throws TypeError / RangeError if `rest` is not a finite number >= 0.
   */
  setRest(rest: number): this {
    this.state[JS_REST] = readNonNegative('DistanceJoint.setRest', 'rest', rest);
    this.lambda[0] = 0;
    this.changed();
    return this;
  }

  /**
   * Sets the mode: 'rod', 'rope' or 'strut'.
   * @throws TypeError / RangeError for anything else.
   */
  setMode(mode: DistanceMode): this {
    this.modeIndex = readMode('DistanceJoint.setMode', 'mode', mode);
    this.lambda[0] = 0;
    this.changed();
    return this;
  }

  /** The violation now (m): rod |length − rest|, rope max(0, length − rest), strut max(0, rest − length). */
  error(): number {
    const d = this.length - this.rest;
    if (this.modeIndex === 0) return Math.abs(d);
    return this.modeIndex === 1 ? Math.max(0, d) : Math.max(0, -d);
  }

  /** @internal */
  buildRows(js: JointSolver, j: number): void {
    js.anchors(this);
    const n = js.n;
    const dir = js.dir;
    let len2 = 0;
    for (let i = 0; i < n; i += 1) {
      const d = js.pB[i] - js.pA[i];
      dir[i] = d;
      len2 += d * d;
    }
    const len = Math.sqrt(len2);
    // Anchors on top of each other: no direction to hold along (the impulse is kept).
    if (!(len > js.sc[SC_TOL])) return;
    const sign = this.modeIndex === 1 ? -1 : 1;
    for (let i = 0; i < n; i += 1) dir[i] = (sign * dir[i]) / len;
    js.sc[SC_C] = sign * (len - this.state[JS_REST]);
    js.addRow(j, 0, KIND_LINEAR, this.modeIndex === 0 ? ROW_EQUAL : ROW_INEQUAL, 1);
  }
}

// World snapshots rebuild saved joints of this type with this class (snapshot/registry.ts).
registerJointClass('distance', DistanceJoint);
