/**
 * The narrowphase scratch of any n: {@link buildNarrowphaseScratch} with the general box–box SAT
 * (box-box-sat.ts). Kept apart from narrowphase-scratch.ts so that the 3D entry, which builds its
 * scratch with the 3D SAT alone, never bundles the general one.
 *
 * @module
 */
import { boxBoxSatKernel } from './box-box-sat.js';
import { buildNarrowphaseScratch } from './narrowphase-scratch.js';
import type { NarrowphaseOptions, NarrowphaseScratch } from './narrowphase-scratch.js';

/**
 * Builds the narrowphase scratch for n dimensions, with the box–box SAT of every n. Allocates
 * (a few kB; 1024·n numbers of candidates at n >= 5); call once per world and dimension.
 *
 * @param n - count of dimensions (2..8).
 * @param options - tolerances; see {@link NarrowphaseOptions}.
 * @throws TypeError for a non-integer n or a non-number option; RangeError for n out of range,
 *   a negative or non-finite tolerance, or a ring point count outside 3..32.
 */
export function createNarrowphaseScratch(n: number, options: NarrowphaseOptions = {}): NarrowphaseScratch {
  return buildNarrowphaseScratch(boxBoxSatKernel, n, options);
}
