/**
 * Small Float64Array views cut from shared blocks: the storage of bodies and poses.
 *
 * A `new Float64Array(len)` of its own costs an ArrayBuffer, its backing store and the collector's
 * record of it, besides the view; 32,000 bodies made 32,000 of them, and the collector's copying
 * of them was a fifth of the time to build a world (issue 19). Views of one block of many records
 * cost the view alone. A block stays alive while any view of it does: a few kilobytes at most
 * for one body kept alone.
 *
 * @module
 */

import type { Pose } from './collision/manifold.js';

/** Records per block: large enough that the blocks' own cost vanishes, small enough to waste little. */
const BLOCK_NUMBERS = 4096;

/** @internal Hands out zeroed views of `len` numbers from shared blocks. */
export class Float64Slab {
  private block = new Float64Array(0);
  private used = 0;

  /** A zeroed view of `len` numbers (len <= 4096), cut from the current block or a new one. */
  take(len: number): Float64Array {
    const start = this.reserve(len);
    return new Float64Array(this.block.buffer, start * 8, len);
  }

  /**
   * The start (in numbers) of a run of `len` zeroed numbers in the current block (or a new one)
   * that the caller cuts its own views from; read the block with {@link Float64Slab.current}.
   */
  reserve(len: number): number {
    if (this.used + len > this.block.length) {
      this.block = new Float64Array(Math.max(BLOCK_NUMBERS, len));
      this.used = 0;
    }
    const start = this.used;
    this.used += len;
    return start;
  }

  /** The block the last {@link Float64Slab.reserve} cut from. */
  get current(): Float64Array {
    return this.block;
  }
}

/**
 * @internal A pose at the origin with the identity rotation (as `createPose` makes), its x and M
 * cut from `slab`: the pose every body gets when it joins a world.
 */
export function slabPose(slab: Float64Slab, n: number): Pose {
  const x = slab.take(n);
  const M = slab.take(n * n);
  for (let i = 0; i < n; i += 1) M[i * n + i] = 1;
  return { x, M };
}
