/**
 * The pair colliders a convex mesh owns: mesh–ball, mesh–half-space, mesh–box and mesh–mesh
 * (mesh is the last kind in the order halfspace, sphere, box, torus, mesh, so these pairs live
 * here, with the mesh as shape A; `collide` swaps a box–mesh pair and flips the normal). A
 * ConvexMesh factory attaches this table as `shape.colliders`. Mesh–torus has no collider (it
 * warns once and passes through). Each entry carries its allocation-free kernel (pair-kernel.ts).
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import { collideMeshHalfSpaceKernel } from './mesh-halfspace.js';
import { collideMeshSphereKernel } from './mesh-sphere.js';
import { collideMeshBoxKernel, collideMeshMeshKernel } from './mesh-polytope.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';

/** Colliders of a convex mesh (shape A) against a ball, a half-space, a box or a convex mesh (shape B). */
export const meshColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: /* @__PURE__ */ pairCollider(collideMeshSphereKernel as unknown as PairKernel),
  halfspace: /* @__PURE__ */ pairCollider(collideMeshHalfSpaceKernel as unknown as PairKernel),
  box: /* @__PURE__ */ pairCollider(collideMeshBoxKernel as unknown as PairKernel),
  mesh: /* @__PURE__ */ pairCollider(collideMeshMeshKernel as unknown as PairKernel),
});
