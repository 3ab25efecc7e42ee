/**
 * The pair colliders a ball owns: ball–ball and ball–half-space. A HyperSphere factory attaches
 * this table as `shape.colliders`. (Ball–box, ball–torus and ball–mesh live in the tables of the
 * box, torus and mesh, so a scene of balls alone loads none of their code.)
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import type { CollisionHalfSpace, CollisionSphere } from './narrowphase-shapes.js';
import { collideSphereHalfSpace } from './sphere-halfspace.js';
import { collideSphereSphere } from './sphere-sphere.js';

/** Colliders of a ball (shape A) against a ball or a half-space (shape B). */
export const sphereColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: (out, n, a, pa, b, pb, margin, scratch) =>
    collideSphereSphere(out, n, a as unknown as CollisionSphere, pa, b as unknown as CollisionSphere, pb, margin, scratch),
  halfspace: (out, n, a, pa, b, pb, margin, scratch) =>
    collideSphereHalfSpace(out, n, a as unknown as CollisionSphere, pa, b as unknown as CollisionHalfSpace, pb, margin, scratch),
});
