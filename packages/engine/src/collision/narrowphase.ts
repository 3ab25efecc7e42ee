/**
 * The narrowphase: contact manifolds between pairs of posed shapes, in n dimensions.
 *
 * Contract: manifold.ts (poses, manifolds, the pair-collider signature). Per-kind collider
 * tables (sphere-, box-, torus-, mesh-colliders.ts) are attached to the shapes by their
 * factories; `collide` dispatches through them. Every pair function is also exported for direct
 * use. Docs: docs/collision.md (narrowphase section).
 *
 * @module
 */
export type { CollidableShape, ColliderTable, Manifold, PairCollider, Pose } from './manifold.js';
export { createManifold, createPose, maxManifoldPoints, NARROWPHASE_MAX_DIMENSIONS } from './manifold.js';
export type { CollisionBox, CollisionHalfSpace, CollisionMesh, CollisionSphere, CollisionTorus } from './narrowphase-shapes.js';
export type { BoxBoxSatKernel, NarrowphaseOptions, NarrowphaseScratch, SatResult } from './narrowphase-scratch.js';
export { createNarrowphaseScratch } from './narrowphase-scratch-nd.js';
export {
  buildNarrowphaseScratch,
  DEFAULT_AXIS_TOLERANCE,
  DEFAULT_CLIP_TOLERANCE,
  DEFAULT_FEATURE_TIE_TOLERANCE,
  DEFAULT_TORUS_RING_POINTS,
  SAT_EDGE,
  SAT_FACE_A,
  SAT_FACE_B,
  SAT_SEPARATED,
} from './narrowphase-scratch.js';
export { collide, collidePair } from './collide.js';
export { resetCollisionWarnings, warnOnce } from './warn-once.js';
export { boxBoxSat, boxBoxSatGeneral, satAxisCount, satAxisTable } from './box-box-sat.js';
export type { SatAxisTable } from './box-box-sat.js';
export { boxBoxSat3 } from './box-box-sat3.js';
export { collideBoxBox } from './box-box.js';
export { collideBoxHalfSpace } from './box-halfspace.js';
export { collideBoxSphere } from './box-sphere.js';
export { collideSphereHalfSpace } from './sphere-halfspace.js';
export { collideSphereSphere } from './sphere-sphere.js';
export { collideTorusHalfSpace } from './torus-halfspace.js';
export { collideTorusSphere } from './torus-sphere.js';
export { collideTorusOther } from './torus-pairs.js';
export { collideMeshHalfSpace } from './mesh-halfspace.js';
export { collideMeshSphere, MESH_INSIDE_ID } from './mesh-sphere.js';
export { closestPointOnSimplex } from './simplex-closest.js';
export { sphereColliders } from './sphere-colliders.js';
export { boxColliders } from './box-colliders.js';
export { torusColliders } from './torus-colliders.js';
export { meshColliders } from './mesh-colliders.js';
