/**
 * `dims3()` and `dims4()`: the tables of one dimension, with its closed-form kernels alone. A
 * program that calls only these carries no other dimension's kernels in its bundle (`dims(n)`
 * references all of them). They return the same object as `dims(3)` and `dims(4)`.
 *
 * @module
 */
import { createFast3Kernels } from './kernels/fast3.js';
import { createFast4Kernels } from './kernels/fast4.js';
import { tablesWith } from './tables.js';
import type { Dims } from './tables.js';

/** The tables of 3D, the same object as `dims(3)`; only the 3D kernels come with it. */
export function dims3(): Dims {
  return tablesWith(3, createFast3Kernels);
}

/** The tables of 4D, the same object as `dims(4)`; only the 4D kernels come with it. */
export function dims4(): Dims {
  return tablesWith(4, createFast4Kernels);
}
