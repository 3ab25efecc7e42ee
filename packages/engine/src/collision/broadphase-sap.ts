/**
 * Sweep-and-prune on the axis of largest variance, kept as the measured alternative to the tree.
 *
 * Every update sorts the box proxies by the lower end of their fattened box on the axis where the
 * box centres spread most (insertion sort: the order of the last step is nearly right), sweeps
 * the sorted list and tests the other axes of each overlapping interval pair. Its cost follows
 * the whole scene each step, not what moved.
 */
import type { BroadphaseOptions, ProxyRayCast } from './broadphase.js';
import { rayHitsBox } from './broadphase-queries.js';
import { ALIVE, BroadphaseBase, HALFSPACE } from './broadphase-base.js';
import { heapSortIdsByKey, insertionSortIdsByKey } from './broadphase-sort.js';

/** A sweep-and-prune broadphase; see `Broadphase` for the contract. */
export class SweepAndPruneBroadphase extends BroadphaseBase {
  protected readonly incremental = false;
  /** Box proxy ids sorted by fat lower bound on {@link axis}. */
  private order: Int32Array;
  private orderCount = 0;
  private orderDirty = false;
  /** The sweep axis of the last update (−1 before the first). */
  axis = -1;
  private readonly mean: Float64Array;
  private readonly square: Float64Array;

  /** An empty sweep-and-prune broadphase for n dimensions (2..8); throws on bad options. */
  constructor(n: number, options: BroadphaseOptions = {}) {
    super(n, options);
    this.order = new Int32Array(this.capacity);
    this.mean = new Float64Array(n);
    this.square = new Float64Array(n);
  }

  protected onInsert(id: number): void {
    this.order[this.orderCount++] = id;
  }

  protected onRemove(): void {
    // Dead ids are compacted out of the order at the next update.
    this.orderDirty = true;
  }

  protected onFatChanged(): void {}

  protected onCapacity(capacity: number): void {
    const next = new Int32Array(capacity);
    next.set(this.order.subarray(0, this.orderCount));
    this.order = next;
  }

  protected collectBoxCandidates(): void {
    const n = this.n;
    const flags = this.flags;
    const order = this.order;
    if (this.orderDirty) {
      let w = 0;
      for (let i = 0; i < this.orderCount; i += 1) {
        const id = order[i]!;
        if ((flags[id]! & (ALIVE | HALFSPACE)) === ALIVE) order[w++] = id;
      }
      this.orderCount = w;
      this.orderDirty = false;
    }
    const count = this.orderCount;
    if (count === 0) return;
    // Axis of largest variance of the fat box centres.
    const mean = this.mean.fill(0);
    const square = this.square.fill(0);
    for (let i = 0; i < count; i += 1) {
      const b = order[i]! * n;
      for (let k = 0; k < n; k += 1) {
        const c = 0.5 * (this.fatMin[b + k]! + this.fatMax[b + k]!);
        mean[k] += c;
        square[k] += c * c;
      }
    }
    let axis = 0;
    let best = -Infinity;
    for (let k = 0; k < n; k += 1) {
      const m = mean[k]! / count;
      const v = square[k]! / count - m * m;
      if (v > best) {
        best = v;
        axis = k;
      }
    }
    if (axis === this.axis) insertionSortIdsByKey(order, count, this.fatMin, n, axis);
    else heapSortIdsByKey(order, count, this.fatMin, n, axis);
    this.axis = axis;

    let visited = 0;
    for (let i = 0; i < count; i += 1) {
      const a = order[i]!;
      const hi = this.fatMax[a * n + axis]!;
      for (let j = i + 1; j < count; j += 1) {
        const b = order[j]!;
        visited += 1;
        if (this.fatMin[b * n + axis]! > hi) break;
        if (!this.pairable(a, b)) continue;
        if (this.fatOverlap(a, b)) this.addCandidate(a, b);
      }
    }
    this.stats.nodesVisited = visited;
  }

  protected visitFat(visit: (id: number) => boolean): boolean {
    const n = this.n;
    const flags = this.flags;
    for (let i = 0; i < this.orderCount; i += 1) {
      const id = this.order[i]!;
      if ((flags[id]! & (ALIVE | HALFSPACE)) !== ALIVE) continue;
      const b = id * n;
      let overlap = true;
      for (let k = 0; k < n; k += 1) {
        if (this.fatMin[b + k]! > this.qMax[k]! || this.qMin[k]! > this.fatMax[b + k]!) {
          overlap = false;
          break;
        }
      }
      if (overlap && !visit(id)) return false;
    }
    return true;
  }

  protected castFat(limit: number, cast: ProxyRayCast): number {
    const n = this.n;
    const flags = this.flags;
    let lim = limit;
    let best = -1;
    for (let i = 0; i < this.orderCount; i += 1) {
      const id = this.order[i]!;
      if ((flags[id]! & (ALIVE | HALFSPACE)) !== ALIVE) continue;
      if (!rayHitsBox(n, this.rayO, this.rayD, lim, this.fatMin, this.fatMax, id * n)) continue;
      const t = cast(id, lim);
      if (t >= 0 && t <= lim) {
        lim = t;
        best = t;
      }
    }
    return best;
  }
}
