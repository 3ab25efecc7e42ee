/**
 * @physin/engine — rigid body dynamics in n dimensions (n = 2..8): the world and its step,
 * bodies, shapes and their mass properties, joints, queries and snapshots, and every tolerance
 * in one place (`defaultParams`).
 *
 * Only what a user calls is exported here; collision kernels, the broadphase and the solver's
 * parts live behind `@physin/engine/internal` (for tools, tests and the worker). Queries and
 * snapshots are functions, and joints bring their solver with them, so a scene pays in its bundle
 * only for what it uses (docs/architecture.md).
 *
 * @module
 */
export { World } from './world-nd.js';
export { WorldBase } from './world.js';
export type { WorldOptions, WorldStats } from './world.js';
export { castRay, queryBox } from './queries.js';
export type { WorldRayHit } from './queries.js';
export { snapshotWorld, restoreWorld } from './snapshot/snapshot.js';
export type { ContactEvents } from './contacts/contact-events.js';
export type { CollisionEvent, CollisionListener } from './contacts/contact-events.js';
export type { PairFilter } from './contacts/contact-set.js';
export { Body } from './body.js';
export type { BodyOptions, BodyType, Material } from './body.js';
export type { InputLimits } from './shapes/limits.js';
export { defaultParams, validateParams } from './params.js';
export type { Params } from './params.js';
export { presets } from './presets.js';
export type { Preset, Presets } from './presets.js';
export { NonFiniteStateError } from './errors.js';
export type { StateField } from './errors.js';
export { angularVelocityFromMomentum, momentumFromAngularVelocity } from './inertia-world.js';
export { HyperBox } from './shapes/box.js';
export { HyperSphere } from './shapes/sphere.js';
export { HalfSpace } from './shapes/half-space.js';
export { HyperTorus } from './shapes/torus.js';
export { HyperCapsule } from './shapes/capsule.js';
export { ConvexMesh } from './shapes/convex-mesh.js';
export { Compound } from './shapes/compound.js';
export type {
  AnyShape,
  BoxShape,
  SphereShape,
  HalfSpaceShape,
  TorusShape,
  ConvexMeshShape,
  CapsuleShape,
  CompoundShape,
  CompoundPart,
  ConvexMeshOptions,
  ConvexMeshTriangleOptions,
  TriangleMergeOptions,
  MassProperties,
  Shape,
  ShapeKind,
} from './shapes/index.js';
export { dims } from '@physin/algebra';
export type { Dims } from '@physin/algebra';
export { Joint, PointJoint, DistanceJoint, FixedJoint, HingeJoint, SubspaceJoint } from './joints/index.js';
export type {
  JointOptions,
  JointBrokenEvent,
  JointBrokenListener,
  DistanceJointOptions,
  DistanceMode,
  HingeJointOptions,
  SubspaceJointOptions,
} from './joints/index.js';
