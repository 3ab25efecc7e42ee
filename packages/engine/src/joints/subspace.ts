/**
 * The subspace joint: the axes and the planes that you name. Linear rows hold the anchor
 * separation at 0 along the locked axes; angular rows hold the relative rotor's components in the
 * locked planes at 0. Axes and planes are in a's frame, or in the world with `worldFrame`.
 * It replaces the velocity masks linearFactor / angularFactor, and it corrects drift.
 *
 * @module
 */
import type { Body } from '../body.js';
import { currentAnchors, currentRelative, identityRotor, referenceFrame } from './frames.js';
import { Joint } from './joint.js';
import type { JointOptions } from './joint.js';
import type { JointSolver } from './joint-solver.js';
import { KIND_LINEAR, ROW_EQUAL, SC_C } from './joint-solver.js';
import { readBoolean, readIndexList } from './options.js';
import { registerJointClass } from '../snapshot/registry.js';

/** Options of a {@link SubspaceJoint}. */
export interface SubspaceJointOptions extends JointOptions {
  /** The axes (indices 0..n−1) along which the anchors are held together. Not with `freeAxes`. */
  readonly lockAxes?: ArrayLike<number>;
  /** The axes left free; every other axis is locked. Not with `lockAxes`. */
  readonly freeAxes?: ArrayLike<number>;
  /** The rotation planes (indices 0..k−1, lexicographic) that are locked. Not with `freePlanes`. */
  readonly lockPlanes?: ArrayLike<number>;
  /** The planes left free; every other plane is locked. Not with `lockPlanes`. */
  readonly freePlanes?: ArrayLike<number>;
  /** Axes and planes in the world frame (true) or in a's frame, turning with it (false, default). */
  readonly worldFrame?: boolean;
  /** Anchor on a, in a's frame (n numbers); default the centre of mass. */
  readonly localA?: ArrayLike<number>;
  /** Anchor on b in b's frame, or a world point when b is null (n numbers); default zeros. */
  readonly localB?: ArrayLike<number>;
}

const NAMES = ['lockAxes', 'freeAxes', 'lockPlanes', 'freePlanes', 'worldFrame', 'localA', 'localB'];

function complement(list: Int32Array, count: number): Int32Array {
  const out: number[] = [];
  for (let i = 0; i < count; i += 1) if (!list.includes(i)) out.push(i);
  return Int32Array.from(out);
}

/**
 * Holds `a` (relative to `b`, or to the world when `b` is null) in a subspace: the locked axes
 * and planes. The rest orientation of the locked planes is the relative orientation at
 * construction.
 */
export class SubspaceJoint extends Joint {
  private readonly axes: Int32Array;
  private readonly planes: Int32Array;
  private readonly world1: number;
  private readonly frameA: Float64Array;
  private readonly frameB: Float64Array;

  /**
   * @param a the body to hold.
   * @param b the other body, or null for the world.
   * @param opts `lockAxes` | `freeAxes`, `lockPlanes` | `freePlanes`, `worldFrame`, `localA`,
   *   `localB` and the common options. At least one axis or plane must be locked.
   * @throws TypeError / RangeError for a bad argument: an unknown axis or plane, both lockAxes and
   *   freeAxes, nothing locked, ...
   */
  constructor(a: Body, b: Body | null, opts: SubspaceJointOptions) {
    const fn = 'new SubspaceJoint';
    if (opts === null || typeof opts !== 'object') {
      throw new TypeError(
        `${fn}: argument 'opts' must be an object { lockAxes | freeAxes, lockPlanes | freePlanes, worldFrame }`,
      );
    }
    const o = opts as Record<string, unknown>;
    const n = a instanceof Object && (a as { D?: { n: number } }).D ? (a as Body).D.n : 0;
    const zeros = new Array<number>(n).fill(0);
    super(fn, a, b, o.localA ?? zeros, o.localB ?? zeros, o, NAMES, 0, (D) => D.n + D.k);
    const D = this.D;
    if (o.lockAxes !== undefined && o.freeAxes !== undefined)
      throw new RangeError(`${fn}: give 'opts.lockAxes' or 'opts.freeAxes', not both`);
    if (o.lockPlanes !== undefined && o.freePlanes !== undefined)
      throw new RangeError(`${fn}: give 'opts.lockPlanes' or 'opts.freePlanes', not both`);
    let axes: Int32Array = new Int32Array(0);
    if (o.lockAxes !== undefined) axes = readIndexList(fn, 'opts.lockAxes', o.lockAxes, D.n, 'axis');
    else if (o.freeAxes !== undefined) axes = complement(readIndexList(fn, 'opts.freeAxes', o.freeAxes, D.n, 'axis'), D.n);
    let planes: Int32Array = new Int32Array(0);
    if (o.lockPlanes !== undefined) planes = readIndexList(fn, 'opts.lockPlanes', o.lockPlanes, D.k, 'plane');
    else if (o.freePlanes !== undefined)
      planes = complement(readIndexList(fn, 'opts.freePlanes', o.freePlanes, D.k, 'plane'), D.k);
    const worldFrame = o.worldFrame === undefined ? false : readBoolean(fn, 'opts.worldFrame', o.worldFrame);
    if (axes.length + planes.length === 0) {
      throw new RangeError(
        `${fn}: the joint locks nothing: give 'opts.lockAxes' / 'opts.freeAxes' or 'opts.lockPlanes' / 'opts.freePlanes' that lock at least one axis or plane`,
      );
    }
    this.axes = axes;
    this.planes = planes;
    this.world1 = worldFrame ? 1 : 0;
    this.frameA = identityRotor(D);
    this.frameB = referenceFrame(this, this.frameA);
  }

  /** Rows it takes away: the locked axes plus the locked planes. */
  get rowCount(): number {
    return this.axes.length + this.planes.length;
  }

  /** The locked axes (a sorted copy). */
  get lockedAxes(): number[] {
    return Array.from(this.axes);
  }

  /** The locked planes (a sorted copy). */
  get lockedPlanes(): number[] {
    return Array.from(this.planes);
  }

  /** Whether the axes and planes are in the world frame. */
  get worldFrame(): boolean {
    return this.world1 === 1;
  }

  /** The anchor separation along the locked axes now (m): sqrt(Σ ((p_B − p_A)·axis)²). */
  error(): number {
    const D = this.D;
    const { pA, pB } = currentAnchors(this);
    const M = D.kernels.toMatrix(new Float64Array(D.n * D.n), this.a.R);
    let s = 0;
    for (const axis of this.axes) {
      let c = 0;
      for (let i = 0; i < D.n; i += 1) c += (pB[i]! - pA[i]!) * (this.world1 === 1 ? (i === axis ? 1 : 0) : M[i * D.n + axis]!);
      s += c * c;
    }
    return Math.sqrt(s);
  }

  /** The angle (rad) in the locked planes now: 2·asin(|⟨Q⟩_locked|), Q the relative rotor. */
  override angularError(): number {
    if (this.planes.length === 0) return 0;
    const Q = currentRelative(this, this.frameA, this.frameB, this.world1 === 1);
    let s = 0;
    for (const p of this.planes) s += Q[1 + p]! * Q[1 + p]!;
    return 2 * Math.asin(Math.min(1, Math.sqrt(s)));
  }

  /** @internal */
  buildRows(js: JointSolver, j: number): void {
    const n = js.n;
    js.anchors(this);
    const axes = this.axes;
    if (axes.length > 0) {
      const M = this.a.pose!.M;
      const dir = js.dir;
      if (this.world1 === 0) {
        // An axis that turns with a: the arm of a reaches to p_B, so Ċ is the exact derivative.
        for (let i = 0; i < n; i += 1) js.armA[i] += js.pB[i] - js.pA[i];
      }
      for (let x = 0; x < axes.length; x += 1) {
        const axis = axes[x];
        let c = 0;
        for (let i = 0; i < n; i += 1) {
          const d = this.world1 === 1 ? (i === axis ? 1 : 0) : M[i * n + axis];
          dir[i] = d;
          c += (js.pB[i] - js.pA[i]) * d;
        }
        js.sc[SC_C] = c;
        js.addRow(j, x, KIND_LINEAR, ROW_EQUAL, 1);
      }
    }
    if (this.planes.length > 0) {
      js.frames(this, this.frameA, this.frameB);
      js.lockedPlaneRows(j, this.planes, this.world1, axes.length);
    }
  }
}

// World snapshots rebuild saved joints of this type with this class (snapshot/registry.ts).
registerJointClass('subspace', SubspaceJoint);
