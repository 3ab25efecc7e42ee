/**
 * Shapes and their mass properties: boxes, balls, half-spaces, tori, convex meshes and capsules in n
 * dimensions, plus the mesh integration helpers.
 *
 * @module
 */
export type { MassProperties, Shape, ShapeKind } from './shape.js';
export { HyperBox } from './box.js';
export type { BoxShape } from './box.js';
export { HyperSphere } from './sphere.js';
export type { SphereShape } from './sphere.js';
export { HalfSpace } from './half-space.js';
export type { HalfSpaceShape } from './half-space.js';
export { HyperTorus } from './torus.js';
export type { TorusShape } from './torus.js';
export { HyperCapsule } from './capsule.js';
export type { CapsuleShape } from './capsule.js';
export { ConvexMesh, DEFAULT_CONVEX_MESH_TOLERANCE } from './convex-mesh.js';
export type { ConvexMeshOptions, ConvexMeshShape, ConvexMeshTriangleOptions } from './convex-mesh.js';
export type { TriangleMergeOptions } from './triangle-merge.js';
export { Compound } from './compound.js';
export type { CompoundPart, CompoundShape } from './compound.js';
export { closedMeshMassProperties, simplexMassProperties } from './mesh-mass.js';
export type { SimplexMassProperties, SolidMassProperties } from './mesh-mass.js';
export { ballVolume, gammaHalfInteger } from './ball-volume.js';

import type { BoxShape } from './box.js';
import type { CapsuleShape } from './capsule.js';
import type { ConvexMeshShape } from './convex-mesh.js';
import type { HalfSpaceShape } from './half-space.js';
import type { SphereShape } from './sphere.js';
import type { TorusShape } from './torus.js';

/** Every concrete shape the engine builds; switch on `kind` to narrow it. */
export type AnyShape = BoxShape | SphereShape | HalfSpaceShape | TorusShape | ConvexMeshShape | CapsuleShape;
