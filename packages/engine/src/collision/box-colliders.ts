/**
 * The pair colliders a box owns: box–box and box–half-space. A HyperBox factory attaches this
 * table as `shape.colliders`. Ball–box lives in the ball's table, so a scene of boxes alone loads
 * none of the ball code. Box–torus and box–mesh have no collider (they warn once and pass
 * through). Each entry carries its allocation-free kernel (pair-kernel.ts).
 *
 * @module
 */
import { collideBoxBoxKernel } from './box-box.js';
import { collideBoxHalfSpaceKernel } from './box-halfspace.js';
import type { ColliderTable } from './manifold.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';

/** Colliders of a box (shape A) against a box or a half-space (shape B). */
export const boxColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  box: /* @__PURE__ */ pairCollider(collideBoxBoxKernel as unknown as PairKernel),
  halfspace: /* @__PURE__ */ pairCollider(collideBoxHalfSpaceKernel as unknown as PairKernel),
});
