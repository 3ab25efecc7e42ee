/**
 * @physin/engine/internal — the parts behind the public surface, for tools, tests and the
 * worker: collision kernels and pair functions, the broadphases, ray casts against one shape,
 * mesh mass integration, and the parameter helpers. Not covered by semantic versioning.
 *
 * @module
 */
export * from './index.js';
export { ContactEvents } from './contacts/contact-events.js';
export { mergeParams, paramNames, bodyDefaults, ROTOR_INPUT_TOLERANCE, MAX_PARAM_COUNT } from './params.js';
export { DEFAULT_CONVEX_MESH_TOLERANCE } from './shapes/convex-mesh.js';
export { closedMeshMassProperties, simplexMassProperties } from './shapes/mesh-mass.js';
export type { SimplexMassProperties, SolidMassProperties } from './shapes/mesh-mass.js';
export { ballVolume, gammaHalfInteger } from './shapes/ball-volume.js';
export * from './collision/index.js';
