/**
 * @physin/engine — rigid body dynamics in n dimensions (n = 2..8): bodies, shapes and their mass
 * properties, collision and the contact solver, the world and its step, and every tolerance in
 * one place (`defaultParams`).
 *
 * @module
 */
export { World } from './world.js';
export type { WorldOptions, WorldRayHit } from './world.js';
export { ContactEvents } from './contacts/contact-events.js';
export type { CollisionEvent, CollisionListener } from './contacts/contact-events.js';
export { Body } from './body.js';
export type { BodyOptions, BodyType, Material } from './body.js';
export { defaultParams, validateParams, mergeParams, paramNames, bodyDefaults, ROTOR_INPUT_TOLERANCE, MAX_PARAM_COUNT } from './params.js';
export type { Params } from './params.js';
export { NonFiniteStateError } from './errors.js';
export type { StateField } from './errors.js';
export { angularVelocityFromMomentum, momentumFromAngularVelocity } from './inertia-world.js';
export * from './shapes/index.js';
export { dims } from '@physin/algebra';
export type { Dims } from '@physin/algebra';
export * from './collision/index.js';
export * from './joints/index.js';
