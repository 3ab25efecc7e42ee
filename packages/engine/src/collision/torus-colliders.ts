/**
 * The pair colliders a torus owns: torus–ball and torus–half-space. A HyperTorus factory attaches
 * this table as `shape.colliders`. Torus–box, torus–torus and torus–mesh have no collider (they
 * warn once and pass through, as the specification says). Each entry carries its
 * allocation-free kernel (pair-kernel.ts).
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';
import { collideTorusHalfSpaceKernel } from './torus-halfspace.js';
import { collideTorusSphereKernel } from './torus-sphere.js';

/** Colliders of a torus (shape A) against a ball or a half-space (shape B). */
export const torusColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: /* @__PURE__ */ pairCollider(collideTorusSphereKernel as unknown as PairKernel),
  halfspace: /* @__PURE__ */ pairCollider(collideTorusHalfSpaceKernel as unknown as PairKernel),
});
