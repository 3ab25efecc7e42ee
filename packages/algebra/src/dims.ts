/**
 * `dims(n)`: the tables of any dimension n = 2..8, with the rotor kernels chosen for n (closed
 * forms in 3D and 4D, table-driven elsewhere). Built the first time n is asked for and cached,
 * so a program that only uses 3D never builds the 6D tables. Everything else in the library takes
 * the result as its first argument `D`.
 *
 * @module
 */
import { createFast3Kernels } from './kernels/fast3.js';
import { createFast4Kernels } from './kernels/fast4.js';
import { createGenericKernels } from './kernels/generic.js';
import type { RotorKernels } from './kernels/types.js';
import { MAX_DIMENSION, MIN_DIMENSION, tablesWith } from './tables.js';
import type { Dims } from './tables.js';
import { checkDims, checkInteger, checkPlane } from './validate.js';

export { MIN_DIMENSION, MAX_DIMENSION, bladeProductSign, popcount, isDims } from './tables.js';
export type { Dims } from './tables.js';

/** Closed forms where they exist (quaternions in 3D, the P± split in 4D), tables elsewhere. */
function kernelsFor(D: Dims): RotorKernels {
  return D.n === 3 ? createFast3Kernels(D) : D.n === 4 ? createFast4Kernels(D) : createGenericKernels(D);
}

/**
 * The tables of dimension n, built on the first call for that n and cached.
 * @param n the dimension, an integer in [2, 8].
 * @throws TypeError if n is not a number, RangeError if it is not an integer in [2, 8].
 */
export function dims(n: number): Dims {
  checkInteger('n', n, MIN_DIMENSION, MAX_DIMENSION, 'dims');
  return tablesWith(n, kernelsFor);
}

/**
 * Index of the plane of axes i and j in bivector order (the order of i and j does not matter;
 * note that e_ji = -e_ij, see `planeBivector` for a signed unit bivector).
 * @throws RangeError if i or j is out of [0, n-1], not an integer, or i == j.
 */
export function planeIndex(D: Dims, i: number, j: number): number {
  checkDims(D, 'planeIndex');
  checkPlane(D, 'i', i, 'j', j, 'planeIndex');
  return D.planeIndexOf[i * D.n + j]!;
}
