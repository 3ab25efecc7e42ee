/**
 * The pair colliders a torus owns: torus–ball and torus–half-space. A HyperTorus factory attaches
 * this table as `shape.colliders`. Torus–box, torus–torus and torus–mesh have no collider (they
 * warn once and pass through, as the specification says).
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import type { CollisionHalfSpace, CollisionSphere, CollisionTorus } from './narrowphase-shapes.js';
import { collideTorusHalfSpace } from './torus-halfspace.js';
import { collideTorusSphere } from './torus-sphere.js';

/** Colliders of a torus (shape A) against a ball or a half-space (shape B). */
export const torusColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: (out, n, a, pa, b, pb, margin, scratch) =>
    collideTorusSphere(out, n, a as unknown as CollisionTorus, pa, b as unknown as CollisionSphere, pb, margin, scratch),
  halfspace: (out, n, a, pa, b, pb, margin, scratch) =>
    collideTorusHalfSpace(out, n, a as unknown as CollisionTorus, pa, b as unknown as CollisionHalfSpace, pb, margin, scratch),
});
