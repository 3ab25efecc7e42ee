/**
 * The default broadphase: a dynamic AABB tree of fattened boxes. Only proxies that left their
 * fattened box are reinserted and queried, so the cost of an update follows what moved.
 */
import type { BroadphaseOptions, ProxyRayCast } from './broadphase.js';
import { DynamicAabbTree } from './broadphase-aabb-tree.js';
import { ALIVE, BroadphaseBase, HALFSPACE, MOVED } from './broadphase-base.js';

/** A broadphase over a {@link DynamicAabbTree}; see `Broadphase` for the contract. */
export class TreeBroadphase extends BroadphaseBase {
  protected readonly incremental = true;
  /** The tree of fattened boxes (exposed read-only for tests and diagnostics). */
  readonly tree: DynamicAabbTree;
  private leafOf: Int32Array;

  /** An empty tree broadphase for n dimensions (2..8); throws on bad options. */
  constructor(n: number, options: BroadphaseOptions = {}) {
    super(n, options);
    this.tree = new DynamicAabbTree(n, 2 * this.capacity);
    this.leafOf = new Int32Array(this.capacity).fill(-1);
  }

  protected onInsert(id: number): void {
    this.leafOf[id] = this.tree.insert(id, this.fatMin, this.fatMax, id * this.n);
  }

  protected onRemove(id: number): void {
    this.tree.remove(this.leafOf[id]!);
    this.leafOf[id] = -1;
  }

  protected onFatChanged(id: number): void {
    this.tree.update(this.leafOf[id]!, this.fatMin, this.fatMax, id * this.n);
  }

  protected onCapacity(capacity: number): void {
    const next = new Int32Array(capacity).fill(-1);
    next.set(this.leafOf);
    this.leafOf = next;
  }

  protected collectBoxCandidates(): void {
    const flags = this.flags;
    const tree = this.tree;
    const st = this.stats;
    for (let i = 0; i < this.movedCount; i += 1) {
      const m = this.moved[i]!;
      if ((flags[m]! & (ALIVE | HALFSPACE)) !== ALIVE) continue;
      const count = tree.query(this.fatMin, this.fatMax, m * this.n);
      st.queries += 1;
      st.nodesVisited += tree.nodesVisited;
      const hits = tree.hits;
      for (let j = 0; j < count; j += 1) {
        const h = hits[j]!;
        if (h === m || !this.pairable(m, h)) continue;
        // Both moved: the smaller id's query adds the pair.
        if (flags[h]! & MOVED && h < m) continue;
        this.addCandidate(m, h);
      }
    }
  }

  protected visitFat(visit: (id: number) => boolean): boolean {
    const count = this.tree.query(this.qMin, this.qMax, 0);
    const hits = this.tree.hits;
    for (let j = 0; j < count; j += 1) if (!visit(hits[j]!)) return false;
    return true;
  }

  protected castFat(limit: number, cast: ProxyRayCast): number {
    return this.tree.rayCast(this.rayO, this.rayD, limit, cast);
  }
}
