/**
 * The pair colliders a box owns: box–ball, box–box and box–half-space. A HyperBox factory
 * attaches this table as `shape.colliders`. Box–torus and box–mesh have no collider (they warn
 * once and pass through).
 *
 * @module
 */
import { collideBoxBox } from './box-box.js';
import { collideBoxHalfSpace } from './box-halfspace.js';
import { collideBoxSphere } from './box-sphere.js';
import type { ColliderTable } from './manifold.js';
import type { CollisionBox, CollisionHalfSpace, CollisionSphere } from './narrowphase-shapes.js';

/** Colliders of a box (shape A) against a ball, a box or a half-space (shape B). */
export const boxColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: (out, n, a, pa, b, pb, margin, scratch) =>
    collideBoxSphere(out, n, a as unknown as CollisionBox, pa, b as unknown as CollisionSphere, pb, margin, scratch),
  box: (out, n, a, pa, b, pb, margin, scratch) =>
    collideBoxBox(out, n, a as unknown as CollisionBox, pa, b as unknown as CollisionBox, pb, margin, scratch),
  halfspace: (out, n, a, pa, b, pb, margin, scratch) =>
    collideBoxHalfSpace(out, n, a as unknown as CollisionBox, pa, b as unknown as CollisionHalfSpace, pb, margin, scratch),
});
