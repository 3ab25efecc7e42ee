/**
 * Slices of n-dimensional bodies (n ≥ 4) by the 3-flat the viewer shows.
 *
 * @module
 */
export { BoxSlicer } from './box-slice.js';
export { PolytopeCut } from './polytope-cut.js';
export { sphereSliceRadius, flatDistanceSquared } from './sphere-slice.js';
export { TorusSlicer } from './torus-slice.js';
