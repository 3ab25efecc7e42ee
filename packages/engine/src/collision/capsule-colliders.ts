/**
 * The pair colliders a capsule owns: capsule–half-space, capsule–ball, capsule–box,
 * capsule–convex mesh and capsule–capsule, with the capsule as shape A (`collide` swaps the
 * other order and flips the normal). A HyperCapsule factory attaches this table as
 * `shape.colliders`. Capsule–torus lives in the torus's table. Each entry carries its
 * allocation-free kernel (pair-kernel.ts).
 *
 * @module
 */
import { collideCapsuleCapsuleKernel, collideCapsuleHalfSpaceKernel, collideCapsuleSphereKernel } from './capsule-pairs.js';
import { collideCapsuleBoxKernel, collideCapsuleMeshKernel } from './capsule-polytope.js';
import type { ColliderTable } from './manifold.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';

/** Colliders of a capsule (shape A) against a half-space, a ball, a box, a convex mesh or a capsule (shape B). */
export const capsuleColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  halfspace: /* @__PURE__ */ pairCollider(collideCapsuleHalfSpaceKernel as unknown as PairKernel),
  sphere: /* @__PURE__ */ pairCollider(collideCapsuleSphereKernel as unknown as PairKernel),
  box: /* @__PURE__ */ pairCollider(collideCapsuleBoxKernel as unknown as PairKernel),
  mesh: /* @__PURE__ */ pairCollider(collideCapsuleMeshKernel as unknown as PairKernel),
  capsule: /* @__PURE__ */ pairCollider(collideCapsuleCapsuleKernel as unknown as PairKernel),
});
