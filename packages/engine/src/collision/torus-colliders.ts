/**
 * The pair colliders a torus owns: torus–ball, torus–half-space, torus–box, torus–capsule,
 * torus–torus and torus–convex mesh (mesh–torus lives here too, with the torus as shape A;
 * `collide` swaps the other order and flips the normal). A HyperTorus factory attaches this table
 * as `shape.colliders`, so a scene without tori carries none of this code. Each entry carries
 * its allocation-free kernel (pair-kernel.ts); the method is in torus-pairs.ts.
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';
import { collideTorusHalfSpaceKernel } from './torus-halfspace.js';
import {
  collideTorusBoxKernel,
  collideTorusCapsuleKernel,
  collideTorusMeshKernel,
  collideTorusTorusKernel,
} from './torus-pairs.js';
import { collideTorusSphereKernel } from './torus-sphere.js';

/** Colliders of a torus (shape A) against a ball, a half-space, a box, a capsule, a torus or a convex mesh (shape B). */
export const torusColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: /* @__PURE__ */ pairCollider(collideTorusSphereKernel as unknown as PairKernel),
  halfspace: /* @__PURE__ */ pairCollider(collideTorusHalfSpaceKernel as unknown as PairKernel),
  box: /* @__PURE__ */ pairCollider(collideTorusBoxKernel as unknown as PairKernel),
  capsule: /* @__PURE__ */ pairCollider(collideTorusCapsuleKernel as unknown as PairKernel),
  torus: /* @__PURE__ */ pairCollider(collideTorusTorusKernel as unknown as PairKernel),
  mesh: /* @__PURE__ */ pairCollider(collideTorusMeshKernel as unknown as PairKernel),
});
