/**
 * @physin/engine/3d — the engine for 3D apps: the same interface as `@physin/engine`, with a
 * `World` and a `dims` built for n = 3 only, so the bundle carries no 4D or generic rotor kernels.
 *
 * @module
 */
export * from './index.js';
// Local exports take precedence over the names of `export *`.
export { World, dims } from './world-3d.js';
