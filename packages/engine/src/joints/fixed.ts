/**
 * The fixed joint (a weld): the point and every rotation plane, n + k rows (3D: 6 of 6; 4D: 10 of
 * 10), solved as one block. The rest orientation is the relative orientation at construction.
 *
 * @module
 */
import type { Body } from '../body.js';
import { currentAnchors, currentRelative, distance, identityRotor, referenceFrame, turnAngle } from './frames.js';
import { Joint } from './joint.js';
import type { JointOptions } from './joint.js';
import type { JointSolver } from './joint-solver.js';
import { registerJointClass } from '../snapshot/registry.js';

/**
 * Welds `b` to `a` (or `a` to the world): the anchors held together and the relative rotor held
 * at its value at construction.
 */
export class FixedJoint extends Joint {
  private readonly frameA: Float64Array;
  private readonly frameB: Float64Array;
  private readonly planes: Int32Array;

  /**
   * @param a the first body.
   * @param b the second body, or null for the world.
   * @param localA anchor on a, in a's frame (n numbers).
   * @param localB anchor on b, in b's frame, or a world point when b is null (n numbers).
   * @param opts the common options ({@link JointOptions}).
   * @throws TypeError / RangeError for a bad argument; nothing is built.
   */
  constructor(a: Body, b: Body | null, localA: ArrayLike<number>, localB: ArrayLike<number>, opts?: JointOptions) {
    super('new FixedJoint', a, b, localA, localB, opts as Record<string, unknown> | undefined, [], 0, (D) => D.n + D.k);
    this.frameA = identityRotor(this.D);
    this.frameB = referenceFrame(this, this.frameA);
    this.planes = Int32Array.from({ length: this.D.k }, (_, p) => p);
  }

  /** Rows it takes away: n + k. */
  get rowCount(): number {
    return this.D.n + this.D.k;
  }

  /** The distance between the two anchors now (m). */
  error(): number {
    const { pA, pB } = currentAnchors(this);
    return distance(pA, pB);
  }

  /** The angle (rad) of the relative rotation away from the rest orientation: 2·acos(|⟨Q⟩₀|). */
  override angularError(): number {
    return turnAngle(currentRelative(this, this.frameA, this.frameB, false));
  }

  /** @internal */
  buildRows(js: JointSolver, j: number): void {
    js.anchors(this);
    js.pointRows(j, 0);
    js.frames(this, this.frameA, this.frameB);
    js.lockedPlaneRows(j, this.planes, 0, js.n);
  }
}

// World snapshots rebuild saved joints of this type with this class (snapshot/registry.ts).
registerJointClass('fixed', FixedJoint);
