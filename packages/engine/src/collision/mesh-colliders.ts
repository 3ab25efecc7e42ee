/**
 * The pair colliders a convex mesh owns: mesh–ball and mesh–half-space. A ConvexMesh factory
 * attaches this table as `shape.colliders`. Mesh–box, mesh–torus and mesh–mesh have no collider
 * (they warn once and pass through, as the specification says). Each entry carries its
 * allocation-free kernel (pair-kernel.ts).
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import { collideMeshHalfSpaceKernel } from './mesh-halfspace.js';
import { collideMeshSphereKernel } from './mesh-sphere.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';

/** Colliders of a convex mesh (shape A) against a ball or a half-space (shape B). */
export const meshColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: /* @__PURE__ */ pairCollider(collideMeshSphereKernel as unknown as PairKernel),
  halfspace: /* @__PURE__ */ pairCollider(collideMeshHalfSpaceKernel as unknown as PairKernel),
});
