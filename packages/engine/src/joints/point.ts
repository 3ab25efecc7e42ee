/**
 * The point joint (ball joint in 3D): one point of a held on one point of b. It takes away the n
 * translations and leaves every one of the k rotation planes free (3D: 3 of 6; 4D: 4 of 10).
 *
 * @module
 */
import type { Body } from '../body.js';
import { currentAnchors, distance } from './frames.js';
import { Joint } from './joint.js';
import type { JointOptions } from './joint.js';
import type { JointSolver } from './joint-solver.js';
import { usePoint3Path } from './joint-space-point.js';
import { registerJointClass } from '../snapshot/registry.js';

/**
 * Holds the point `localA` of `a` on the point `localB` of `b` (or on the world point `localB`
 * when `b` is null): n equality rows C = p_B − p_A, solved as one n×n block.
 */
export class PointJoint extends Joint {
  /**
   * @param a the first body.
   * @param b the second body, or null for the world.
   * @param localA anchor on a, in a's frame (n numbers).
   * @param localB anchor on b, in b's frame, or a world point when b is null (n numbers).
   * @param opts the common options ({@link JointOptions}).
   * @throws TypeError / RangeError for a bad argument (see docs/joints.md); nothing is built.
   */
  constructor(a: Body, b: Body | null, localA: ArrayLike<number>, localB: ArrayLike<number>, opts?: JointOptions) {
    super('new PointJoint', a, b, localA, localB, opts as Record<string, unknown> | undefined, [], 0, (D) => D.n);
  }

  /** Rows it takes away: n. */
  get rowCount(): number {
    return this.D.n;
  }

  /** The distance between the two anchors now (m). */
  error(): number {
    const { pA, pB } = currentAnchors(this);
    return distance(pA, pB);
  }

  /** @internal */
  buildRows(js: JointSolver, j: number): void {
    js.anchors(this);
    js.pointRows(j, 0);
  }
}

// World snapshots rebuild saved joints of this type with this class (snapshot/registry.ts).
registerJointClass('point', PointJoint);
// The joint-space trees of point joints in 3D take the written-out path; a scene without point
// joints does not carry it (tests/bundle-size.test.ts).
usePoint3Path();
