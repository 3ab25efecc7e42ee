/**
 * The pair colliders a convex mesh owns: mesh–ball and mesh–half-space. A ConvexMesh factory
 * attaches this table as `shape.colliders`. Mesh–box, mesh–torus and mesh–mesh have no collider
 * (they warn once and pass through, as the specification says).
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import { collideMeshHalfSpace } from './mesh-halfspace.js';
import { collideMeshSphere } from './mesh-sphere.js';
import type { CollisionHalfSpace, CollisionMesh, CollisionSphere } from './narrowphase-shapes.js';

/** Colliders of a convex mesh (shape A) against a ball or a half-space (shape B). */
export const meshColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: (out, n, a, pa, b, pb, margin, scratch) =>
    collideMeshSphere(out, n, a as unknown as CollisionMesh, pa, b as unknown as CollisionSphere, pb, margin, scratch),
  halfspace: (out, n, a, pa, b, pb, margin, scratch) =>
    collideMeshHalfSpace(out, n, a as unknown as CollisionMesh, pa, b as unknown as CollisionHalfSpace, pb, margin, scratch),
});
