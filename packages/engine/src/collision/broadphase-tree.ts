/**
 * The default broadphase: a dynamic AABB tree of fattened boxes. Only proxies that left their
 * fattened box are reinserted and queried, so the cost of an update follows what moved.
 *
 * New proxies wait outside the tree, and destroyed ones stay in it, until it is next used (the
 * update, a query, a ray): a few changes are then made one by one, but a batch at least half the
 * size of the tree has the whole tree built again top-down (broadphase-tree-build.ts). Adding
 * 32,000 bodies before a step so costs one build of O(N log N) instead of 32,000 insertions with
 * their refits, and removing them all one walk of the tree (issue 19). The tree's shape never
 * shows in the results: pairs are sorted, and queries order their own results.
 */
import type { BroadphaseOptions } from './broadphase.js';
import { DynamicAabbTree } from './broadphase-aabb-tree.js';
import { TreeSelfPairs } from './broadphase-tree-pairs.js';
import { ALIVE, BroadphaseBase, HALFSPACE, MOVED } from './broadphase-base.js';

/**
 * Fewer waiting proxies than this are inserted one by one whatever the tree's size: the build's
 * fixed costs are not worth it for a handful.
 */
const BULK_MIN = 16;

/**
 * From this many moved proxies, and at least half the tree, the update walks the tree against
 * itself once (broadphase-tree-pairs.ts) instead of querying it once per moved proxy.
 */
const SELF_JOIN_MIN = 256;

/** A broadphase over a {@link DynamicAabbTree}; see `Broadphase` for the contract. */
export class TreeBroadphase extends BroadphaseBase {
  protected readonly incremental = true;
  private readonly boxTree: DynamicAabbTree;
  private leafOf: Int32Array;
  /** Per id: 1 while its leaf waits outside the tree. */
  private waiting: Uint8Array;
  /** Ids whose leaves wait, in the order they came (an id whose flag was cleared is skipped). */
  private pending: Int32Array;
  private pendingCount = 0;
  /** Leaves of destroyed proxies still in the tree, to leave it before it is next read. */
  private doomed: Int32Array;
  private doomedCount = 0;
  /** The walk of the tree against itself, made when first needed. */
  private selfPairs: TreeSelfPairs | null = null;

  /** An empty tree broadphase for n dimensions (2..8); throws on bad options. */
  constructor(n: number, options: BroadphaseOptions = {}) {
    super(n, options);
    this.boxTree = new DynamicAabbTree(n, 2 * this.capacity);
    this.leafOf = new Int32Array(this.capacity).fill(-1);
    this.waiting = new Uint8Array(this.capacity);
    this.pending = new Int32Array(16);
    this.doomed = new Int32Array(16);
  }

  /** The tree of fattened boxes, every proxy in it (exposed read-only for tests and diagnostics). */
  get tree(): DynamicAabbTree {
    this.flushPending();
    return this.boxTree;
  }

  protected onInsert(id: number): void {
    this.leafOf[id] = this.boxTree.createLeaf(id, this.fatMin, this.fatMax, id * this.n);
    this.waiting[id] = 1;
    if (this.pendingCount === this.pending.length) this.pending = grown(this.pending);
    this.pending[this.pendingCount++] = id;
  }

  protected onRemove(id: number): void {
    if (this.waiting[id] === 1) {
      this.waiting[id] = 0;
      this.boxTree.dropLeaf(this.leafOf[id]!);
    } else {
      // Out of the tree at the next flush: removing 32,000 leaves one by one refitted the path to
      // the root each time, where emptying the tree at once costs one walk of it.
      if (this.doomedCount === this.doomed.length) this.doomed = grown(this.doomed);
      this.doomed[this.doomedCount++] = this.leafOf[id]!;
    }
    this.leafOf[id] = -1;
  }

  protected onFatChanged(id: number): void {
    if (this.waiting[id] === 1) this.boxTree.setLeafBox(this.leafOf[id]!, this.fatMin, this.fatMax, id * this.n);
    else this.boxTree.update(this.leafOf[id]!, this.fatMin, this.fatMax, id * this.n);
  }

  protected onCapacity(capacity: number): void {
    const next = new Int32Array(capacity).fill(-1);
    next.set(this.leafOf);
    this.leafOf = next;
    const waiting = new Uint8Array(capacity);
    waiting.set(this.waiting);
    this.waiting = waiting;
  }

  /**
   * Takes the leaves of destroyed proxies out of the tree and puts the waiting leaves in: one by
   * one when they are few beside the tree, else by building the tree again over the leaves that
   * stay. Called before anything reads the tree.
   */
  private flushPending(): void {
    if (this.pendingCount === 0 && this.doomedCount === 0) return;
    const pending = this.pending;
    let count = 0;
    for (let i = 0; i < this.pendingCount; i += 1) {
      const id = pending[i]!;
      if (this.waiting[id] !== 1) continue;
      this.waiting[id] = 0;
      pending[count++] = this.leafOf[id]!;
    }
    this.pendingCount = 0;
    const tree = this.boxTree;
    const doomed = this.doomed;
    const dead = this.doomedCount;
    this.doomedCount = 0;
    const changes = count + dead;
    if (changes >= BULK_MIN && 2 * changes >= tree.leafCount) {
      for (let i = 0; i < dead; i += 1) tree.markDead(doomed[i]!);
      tree.rebuild(pending, count);
      return;
    }
    for (let i = 0; i < dead; i += 1) tree.remove(doomed[i]!);
    for (let i = 0; i < count; i += 1) tree.linkLeaf(pending[i]!);
  }

  protected collectBoxCandidates(): void {
    this.flushPending();
    const flags = this.flags;
    const tree = this.boxTree;
    const st = this.stats;
    if (this.movedCount >= SELF_JOIN_MIN && 2 * this.movedCount >= tree.leafCount) {
      this.collectAllPairs();
      return;
    }
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

  /**
   * The candidates of an update where most proxies moved: every overlapping pair of the tree,
   * kept when one side moved (the same set the queries give: a pair of two moved proxies once).
   */
  private collectAllPairs(): void {
    const walk = (this.selfPairs ??= new TreeSelfPairs());
    const count = walk.run(this.boxTree);
    const st = this.stats;
    st.queries += 1;
    st.nodesVisited += walk.nodesVisited;
    const flags = this.flags;
    const pairs = walk.pairs;
    for (let p = 0; p < count; p += 1) {
      const a = pairs[2 * p]!;
      const b = pairs[2 * p + 1]!;
      if (((flags[a]! | flags[b]!) & MOVED) === 0 || !this.pairable(a, b)) continue;
      this.addCandidate(a, b);
    }
  }

  protected visitFat(visit: (id: number) => boolean): boolean {
    this.flushPending();
    const count = this.boxTree.query(this.qMin, this.qMax, 0);
    const hits = this.boxTree.hits;
    for (let j = 0; j < count; j += 1) if (!visit(hits[j]!)) return false;
    return true;
  }
}

/** A copy of `a` twice as long. */
function grown(a: Int32Array): Int32Array {
  const next = new Int32Array(2 * a.length);
  next.set(a);
  return next;
}
