/**
 * @physin/three — the three.js adapter of PhysiN: Physijs's interface in n dimensions. A `Scene`
 * whose meshes are rigid bodies, stepped in this thread or in a worker through `@physin/worker`;
 * bodies of 4 and more dimensions are shown by their cut with the 3-flat of `scene.slice`.
 *
 * @module
 */
export { Scene } from './scene.js';
export type { SceneOptions, SceneEventMap } from './scene.js';
export { Mesh } from './mesh.js';
export type { CollisionEvent, MeshEventMap, MeshPhysics, VectorInput, BivectorInput } from './mesh.js';
export { BoxMesh, SphereMesh, PlaneMesh, TorusMesh, CapsuleMesh, ConvexMesh } from './meshes.js';
export { HyperShapeMesh, HyperBoxMesh, HyperSphereMesh, HyperPlaneMesh, HyperTorusMesh, HyperMesh } from './hyper-meshes.js';
export type { HyperTorusOptions } from './hyper-meshes.js';
export { Joint, PointJoint, DistanceJoint, FixedJoint, HingeJoint, SubspaceJoint } from './joints.js';
export type { JointOptions, JointEventMap } from './joints.js';
export { createMaterial } from './material.js';
export type { PhysinMaterialValues } from './material.js';
