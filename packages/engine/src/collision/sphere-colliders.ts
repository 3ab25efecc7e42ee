/**
 * The pair colliders a ball owns: ball–ball, ball–box and ball–half-space. A HyperSphere factory
 * attaches this table as `shape.colliders`. Ball–box is here rather than in the box's table so
 * that a box world, the common scene, carries no ball code (about 250 B gzip); ball–torus and
 * ball–mesh live in the tables of the torus and mesh. Each entry carries its allocation-free
 * kernel (pair-kernel.ts).
 *
 * @module
 */
import { collideSphereBoxKernel } from './box-sphere.js';
import type { ColliderTable } from './manifold.js';
import { pairCollider } from './pair-kernel.js';
import type { PairKernel } from './pair-kernel.js';
import { collideSphereHalfSpaceKernel } from './sphere-halfspace.js';
import { collideSphereSphereKernel } from './sphere-sphere.js';

/** Colliders of a ball (shape A) against a ball, a box or a half-space (shape B). */
export const sphereColliders: ColliderTable = /* @__PURE__ */ Object.freeze({
  sphere: /* @__PURE__ */ pairCollider(collideSphereSphereKernel as unknown as PairKernel),
  box: /* @__PURE__ */ pairCollider(collideSphereBoxKernel as unknown as PairKernel),
  halfspace: /* @__PURE__ */ pairCollider(collideSphereHalfSpaceKernel as unknown as PairKernel),
});
