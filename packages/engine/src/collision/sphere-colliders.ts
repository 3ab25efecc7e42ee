/**
 * The pair colliders a ball owns: ball–ball and ball–half-space. A HyperSphere factory attaches
 * this table as `shape.colliders`. (Ball–box, ball–torus and ball–mesh live in the tables of the
 * box, torus and mesh, so a scene of balls alone loads none of their code.) Each entry carries
 * its allocation-free kernel (pair-kernel.ts).
 *
 * @module
 */
import type { ColliderTable } from './manifold.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';
import { collideSphereHalfSpaceKernel } from './sphere-halfspace.js';
import { collideSphereSphereKernel } from './sphere-sphere.js';

/** Colliders of a ball (shape A) against a ball or a half-space (shape B). */
export const sphereColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: /* @__PURE__ */ pairCollider(collideSphereSphereKernel as unknown as PairKernel),
  halfspace: /* @__PURE__ */ pairCollider(collideSphereHalfSpaceKernel as unknown as PairKernel),
});
