/**
 * What a world does with a compound body beyond what it does with any body: the poses of its
 * parts and one broadphase proxy per part. A Compound shape carries these functions
 * (`worldOps`, as a shape carries its pair colliders), so a world of other shapes carries none
 * of them (docs/architecture.md, What a scene pays for).
 *
 * @module
 */
import type { Broadphase } from '../collision/broadphase.js';
import { computeBoundsUnchecked } from '../collision/bounds.js';
import { createPose } from '../collision/manifold.js';
import type { Pose } from '../collision/manifold.js';
import type { QueryShape } from '../collision/query-shapes.js';
import type { CompoundShape } from './compound.js';
import type { Shape } from './shape.js';

/** @internal The world's handling of compound bodies (see the module). */
export interface CompoundWorldOps {
  /**
   * The world pose of part `i` into `out`: x_i = x + M·offset_i, M_i = M·rotation_i (the body's
   * pose composed with the part's place in the body).
   */
  partPose(n: number, pose: Pose, compound: CompoundShape, i: number, out: Pose): void;
  /** The poses of the parts (proxies `ids`, poses in `poses` by proxy id) from the body's pose. */
  updatePartPoses(n: number, pose: Pose, compound: CompoundShape, ids: Int32Array, poses: readonly (Pose | null)[]): void;
  /**
   * New poses of the parts into `out` (pushed), each part's bounds computed into min / max on the
   * way; returns the sum of 0·bound over every bound (0 when every box is finite).
   */
  newPartPoses(n: number, pose: Pose, compound: CompoundShape, min: Float64Array, max: Float64Array, out: Pose[]): number;
  /** One broadphase proxy per part at its pose (from newPartPoses); returns their ids. */
  createPartProxies(
    n: number,
    compound: CompoundShape,
    poses: readonly Pose[],
    broadphase: Broadphase,
    isStatic: boolean,
    min: Float64Array,
    max: Float64Array,
  ): Int32Array;
  /**
   * Moves the parts' proxies `ids` to their poses, each box grown by reach[index] (a box that
   * overflows keeps its last place). The reach is read here, not passed: a double argument of a
   * call that is not inlined is boxed.
   */
  moveParts(
    n: number,
    ids: Int32Array,
    shapes: readonly (Shape | null)[],
    poses: readonly (Pose | null)[],
    reach: Float64Array,
    index: number,
    min: Float64Array,
    max: Float64Array,
    broadphase: Broadphase,
  ): void;
}

function partPose(n: number, pose: Pose, compound: CompoundShape, i: number, out: Pose): void {
  const x = pose.x;
  const M = pose.M;
  const off = compound.partOffsets;
  const rot = compound.partRotations;
  const o = i * n;
  const q = i * n * n;
  for (let a = 0; a < n; a += 1) {
    let s = x[a]!;
    for (let c = 0; c < n; c += 1) s += M[a * n + c]! * off[o + c]!;
    out.x[a] = s;
    for (let b = 0; b < n; b += 1) {
      let t = 0;
      for (let c = 0; c < n; c += 1) t += M[a * n + c]! * rot[q + c * n + b]!;
      out.M[a * n + b] = t;
    }
  }
}

/** @internal See the module. */
export const compoundWorldOps: CompoundWorldOps = {
  partPose,

  updatePartPoses(n, pose, compound, ids, poses) {
    for (let i = 0; i < ids.length; i += 1) partPose(n, pose, compound, i, poses[ids[i]!]!);
  },

  newPartPoses(n, pose, compound, min, max, out) {
    let finite = 0;
    for (let i = 0; i < compound.partCount; i += 1) {
      const part = createPose(n);
      partPose(n, pose, compound, i, part);
      out.push(part);
      computeBoundsUnchecked(min, max, n, compound.parts[i] as unknown as QueryShape, part.x, part.M, 0);
      for (let c = 0; c < n; c += 1) finite += min[c]! * 0 + max[c]! * 0;
    }
    return finite;
  },

  createPartProxies(n, compound, poses, broadphase, isStatic, min, max) {
    const ids = new Int32Array(compound.partCount);
    for (let i = 0; i < ids.length; i += 1) {
      const pose = poses[i]!;
      computeBoundsUnchecked(min, max, n, compound.parts[i] as unknown as QueryShape, pose.x, pose.M, 0);
      ids[i] = broadphase.createProxy(min, max, isStatic);
    }
    return ids;
  },

  moveParts(n, ids, shapes, poses, reach, index, min, max, broadphase) {
    const grow = reach[index]!;
    for (let p = 0; p < ids.length; p += 1) {
      const id = ids[p]!;
      const pose = poses[id]!;
      computeBoundsUnchecked(min, max, n, shapes[id] as unknown as QueryShape, pose.x, pose.M, 0);
      let finite = 0;
      for (let i = 0; i < n; i += 1) {
        min[i] = min[i]! - grow;
        max[i] = max[i]! + grow;
        finite += min[i]! * 0 + max[i]! * 0;
      }
      if (finite === 0) broadphase.moveProxy(id, min, max);
    }
  },
};
