/**
 * The collision layer's public surface: bounds, broadphase, ray casts and overlap queries
 * (geometry and data structures with no body or world), and the narrowphase pair functions.
 * The world's step drives these; they are exported for tools, tests and custom pipelines.
 */
export { computeBounds, computeBoundsUnchecked } from './bounds.js';
export { createBroadphase, DEFAULT_BROADPHASE_MARGIN } from './broadphase.js';
export type { Broadphase, BroadphaseOptions, BroadphaseStats, BroadphaseKind, ProxyVisitor, ProxyRayCast } from './broadphase.js';
export { TreeBroadphase } from './broadphase-tree.js';
export { SweepAndPruneBroadphase } from './broadphase-sap.js';
export {
  broadphaseQueryBox,
  broadphaseRayCast,
  proxyBounds,
  proxyIsAlive,
  proxyIsAwake,
  proxyIsHalfSpace,
  proxyIsStatic,
  validateTree,
} from './broadphase-queries.js';
export {
  rayCastShape,
  rayCastShapeUnchecked,
  createRayHit,
  DEFAULT_TORUS_RAY_TOLERANCE,
  DEFAULT_TORUS_RAY_STEPS,
} from './raycast.js';
export type { RayHit, TorusRayOptions } from './raycast.js';
export { torusDistance } from './raycast-torus.js';
export { queryOverlap, rayCastClosest, createIdList, createRayCastResult } from './query.js';
export type { IdList, RayCastSource, RayCastResult } from './query.js';
export * from './narrowphase.js';
export { collideMeshBox, collideMeshMesh, polytopeSeparation } from './mesh-polytope.js';
