/**
 * A dynamic bounding-volume tree of axis-aligned boxes in n dimensions.
 *
 * Leaves hold the boxes of user items; every inner node holds the union of its two children.
 * Insertion descends by the surface-area heuristic generalised to n dimensions (the box's
 * surface measure, {@link surfaceMeasure}) and the tree is kept balanced with AVL rotations, after
 * Box2D's b2DynamicTree. Storage is struct-of-arrays in typed arrays that grow by doubling, so
 * insert/remove/query allocate nothing once the tree has reached its size.
 *
 * This is an internal kernel of the broadphase: it does not validate its arguments.
 */

const NULL = -1;
/** The user id of a leaf marked to leave at the next rebuild (user ids are >= 0). */
const DEAD = -2;

/**
 * The (n−1)-dimensional measure of the boundary of a box with extents e: 2·Σ_k Π_{j≠k} e_j
 * (2D: the perimeter; 3D: the surface area). The cost the insertion heuristic minimises.
 */
export function surfaceMeasure(extents: ArrayLike<number>, n: number): number {
  let sum = 0;
  for (let k = 0; k < n; k += 1) {
    let p = 1;
    for (let j = 0; j < n; j += 1) if (j !== k) p *= extents[j]!;
    sum += p;
  }
  return 2 * sum;
}

import { TreeBuilder } from './broadphase-tree-build.js';

/** A dynamic AABB tree over n-dimensional boxes; leaves carry an integer user id. */
export class DynamicAabbTree {
  /** Count of dimensions. */
  readonly n: number;
  /** Root node index, or −1 when the tree is empty. */
  root = NULL;
  /** Lower corners of the node boxes, flat: node i is [i*n, i*n + n). */
  nodeMin: Float64Array;
  /** Upper corners of the node boxes, flat like {@link nodeMin}. */
  nodeMax: Float64Array;
  /** Parent of each node (−1 for the root); on free nodes, the next free node. */
  parent: Int32Array;
  /** First child of each inner node. */
  child1: Int32Array;
  /** Second child of each inner node. */
  child2: Int32Array;
  /** Leaf: 0; inner node: 1 + max(children's heights); free node: −1. */
  height: Int32Array;
  /** User id of a leaf (−1 on inner nodes). */
  userId: Int32Array;
  /** Node boxes tested by the last query or ray cast (the work it did). */
  nodesVisited = 0;
  /** Result list of {@link query}: user ids of the leaves found, [0, hitCount). */
  hits: Int32Array;
  /** Count of ids in {@link hits}. */
  hitCount = 0;

  private capacity: number;
  private freeList = NULL;
  private nodeCount = 0;
  /** Leaves linked into the tree (a leaf made by createLeaf counts once it is linked). */
  private linkedLeaves = 0;
  private stack: Int32Array;
  private readonly prefix: Float64Array;
  private readonly extents: Float64Array;
  private readonly measure = new Float64Array(6);
  /** The top-down build of {@link rebuild}, made by its first call. */
  private builder: TreeBuilder | null = null;
  /** The leaves a rebuild links (grown by it). */
  private leafScratch = new Int32Array(0);

  /** An empty tree for n dimensions with room for `initialCapacity` nodes (it grows by doubling). */
  constructor(n: number, initialCapacity = 16) {
    this.n = n;
    this.capacity = Math.max(2, initialCapacity);
    const c = this.capacity;
    this.nodeMin = new Float64Array(c * n);
    this.nodeMax = new Float64Array(c * n);
    this.parent = new Int32Array(c);
    this.child1 = new Int32Array(c);
    this.child2 = new Int32Array(c);
    this.height = new Int32Array(c);
    this.userId = new Int32Array(c);
    this.linkFree(0, c);
    this.hits = new Int32Array(16);
    this.stack = new Int32Array(64);
    this.prefix = new Float64Array(n);
    this.extents = new Float64Array(n);
  }

  /** Count of nodes in use (leaves and inner nodes). */
  get size(): number {
    return this.nodeCount;
  }

  /** Height of the tree (0 for a single leaf, −1 when empty). */
  get treeHeight(): number {
    return this.root === NULL ? -1 : this.height[this.root]!;
  }

  /**
   * Inserts a leaf for `user` with box [min, max) read from `min[off .. off+n)` and
   * `max[off .. off+n)`. Returns the leaf's node index.
   */
  insert(user: number, min: Float64Array, max: Float64Array, off: number): number {
    const leaf = this.allocateNode();
    const n = this.n;
    const b = leaf * n;
    for (let k = 0; k < n; k += 1) {
      this.nodeMin[b + k] = min[off + k]!;
      this.nodeMax[b + k] = max[off + k]!;
    }
    this.userId[leaf] = user;
    this.height[leaf] = 0;
    this.insertLeaf(leaf);
    return leaf;
  }

  /**
   * Makes a leaf for `user` with box [min, max) read as in {@link insert}, outside the tree: put
   * it in with {@link linkLeaf} or {@link rebuild}. Returns the leaf's node index.
   */
  createLeaf(user: number, min: Float64Array, max: Float64Array, off: number): number {
    const leaf = this.allocateNode();
    this.setLeafBox(leaf, min, max, off);
    this.userId[leaf] = user;
    return leaf;
  }

  /** Gives a leaf that is not in the tree yet (see {@link createLeaf}) a new box. */
  setLeafBox(leaf: number, min: Float64Array, max: Float64Array, off: number): void {
    const n = this.n;
    const b = leaf * n;
    for (let k = 0; k < n; k += 1) {
      this.nodeMin[b + k] = min[off + k]!;
      this.nodeMax[b + k] = max[off + k]!;
    }
  }

  /** Puts a leaf made by {@link createLeaf} into the tree (the incremental insertion). */
  linkLeaf(leaf: number): void {
    this.insertLeaf(leaf);
  }

  /** Frees a leaf made by {@link createLeaf} that was never put into the tree. */
  dropLeaf(leaf: number): void {
    this.freeNode(leaf);
  }

  /** Count of leaves in the tree (those made by createLeaf and not yet linked are not counted). */
  get leafCount(): number {
    return this.linkedLeaves;
  }

  /**
   * Marks a leaf of the tree to leave it at the next {@link rebuild} (which frees it). Until then
   * the tree must not be queried: the leaf is still in it.
   */
  markDead(leaf: number): void {
    this.userId[leaf] = DEAD;
  }

  /**
   * Builds the tree again, top-down, over its leaves and the new leaves `extra[0 .. count)` (made
   * by {@link createLeaf}); leaves marked by {@link markDead} are freed. The inner nodes are freed
   * and made anew, the other leaves keep their node indices. For many new or dead leaves at once,
   * where one insertion or removal each would cost more and give a worse tree (see
   * broadphase-tree-build.ts).
   */
  rebuild(extra: Int32Array, count: number): void {
    const total = this.linkedLeaves + count;
    if (this.leafScratch.length < total) this.leafScratch = new Int32Array(Math.max(total, 2 * this.leafScratch.length));
    const leaves = this.leafScratch;
    let m = 0;
    if (this.root !== NULL) {
      let top = 0;
      this.stack[top++] = this.root;
      while (top > 0) {
        const node = this.stack[--top]!;
        if (this.height[node] === 0) {
          if (this.userId[node] === DEAD) this.freeNode(node);
          else leaves[m++] = node;
          continue;
        }
        if (top + 2 > this.stack.length) this.stack = grow(this.stack, top);
        this.stack[top++] = this.child1[node]!;
        this.stack[top++] = this.child2[node]!;
        this.freeNode(node);
      }
    }
    for (let i = 0; i < count; i += 1) leaves[m++] = extra[i]!;
    this.reserveNodes(m - 1);
    this.builder ??= new TreeBuilder(this.n);
    this.root = this.builder.build(this, leaves, m);
    this.linkedLeaves = m;
  }

  /** @internal Makes sure `extra` more nodes can be allocated without the arrays growing. */
  reserveNodes(extra: number): void {
    while (this.capacity - this.nodeCount < extra) this.growNodes();
  }

  /** Removes a leaf and frees its node. */
  remove(leaf: number): void {
    this.removeLeaf(leaf);
    this.freeNode(leaf);
  }

  /** Gives a leaf a new box (remove and reinsert: the path to the root is refitted). */
  update(leaf: number, min: Float64Array, max: Float64Array, off: number): void {
    this.removeLeaf(leaf);
    const n = this.n;
    const b = leaf * n;
    for (let k = 0; k < n; k += 1) {
      this.nodeMin[b + k] = min[off + k]!;
      this.nodeMax[b + k] = max[off + k]!;
    }
    this.insertLeaf(leaf);
  }

  /**
   * Finds every leaf whose box overlaps [min, max] (closed intervals on every axis) and writes
   * their user ids into {@link hits}[0 .. hitCount). Returns hitCount.
   */
  query(min: Float64Array, max: Float64Array, off: number): number {
    this.hitCount = 0;
    this.nodesVisited = 0;
    if (this.root === NULL) return 0;
    const n = this.n;
    const nodeMin = this.nodeMin;
    const nodeMax = this.nodeMax;
    let top = 0;
    this.stack[top++] = this.root;
    while (top > 0) {
      const node = this.stack[--top]!;
      this.nodesVisited += 1;
      const b = node * n;
      let overlap = true;
      for (let k = 0; k < n; k += 1) {
        if (nodeMin[b + k]! > max[off + k]! || min[off + k]! > nodeMax[b + k]!) {
          overlap = false;
          break;
        }
      }
      if (!overlap) continue;
      if (this.height[node] === 0) {
        if (this.hitCount === this.hits.length) this.hits = grow(this.hits, this.hitCount);
        this.hits[this.hitCount++] = this.userId[node]!;
      } else {
        if (top + 2 > this.stack.length) this.stack = grow(this.stack, top);
        this.stack[top++] = this.child1[node]!;
        this.stack[top++] = this.child2[node]!;
      }
    }
    return this.hitCount;
  }

  private linkFree(from: number, to: number): void {
    for (let i = from; i < to - 1; i += 1) {
      this.parent[i] = i + 1;
      this.height[i] = -1;
    }
    this.parent[to - 1] = this.freeList;
    this.height[to - 1] = -1;
    this.freeList = from;
  }

  /** @internal A free node (grows the arrays when none is left), reset to an unlinked leaf. */
  allocateNode(): number {
    if (this.freeList === NULL) this.growNodes();
    const node = this.freeList;
    this.freeList = this.parent[node]!;
    this.parent[node] = NULL;
    this.child1[node] = NULL;
    this.child2[node] = NULL;
    this.height[node] = 0;
    this.userId[node] = NULL;
    this.nodeCount += 1;
    return node;
  }

  private freeNode(node: number): void {
    this.parent[node] = this.freeList;
    this.height[node] = -1;
    this.freeList = node;
    this.nodeCount -= 1;
  }

  private growNodes(): void {
    const old = this.capacity;
    const c = old * 2;
    const n = this.n;
    this.nodeMin = resizeF64(this.nodeMin, c * n);
    this.nodeMax = resizeF64(this.nodeMax, c * n);
    this.parent = resizeI32(this.parent, c);
    this.child1 = resizeI32(this.child1, c);
    this.child2 = resizeI32(this.child2, c);
    this.height = resizeI32(this.height, c);
    this.userId = resizeI32(this.userId, c);
    this.capacity = c;
    this.linkFree(old, c);
  }

  /**
   * Surface measure of the union of the boxes of nodes a and b (b = −1: a alone), written to
   * measure[slot]. Results go through a typed array, not a return value: a returned double is
   * boxed on the heap when the call is not inlined, and insertion makes many of these calls.
   */
  private measureInto(slot: number, a: number, b: number): void {
    const n = this.n;
    const e = this.extents;
    const lo = this.nodeMin;
    const hi = this.nodeMax;
    if (b < 0) {
      for (let k = 0; k < n; k += 1) e[k] = hi[a * n + k]! - lo[a * n + k]!;
    } else {
      for (let k = 0; k < n; k += 1) {
        e[k] = Math.max(hi[a * n + k]!, hi[b * n + k]!) - Math.min(lo[a * n + k]!, lo[b * n + k]!);
      }
    }
    // 2·Σ_k Π_{j≠k} e_j in O(n) with prefix and suffix products (exact with zero extents).
    const pre = this.prefix;
    let p = 1;
    for (let k = 0; k < n; k += 1) {
      pre[k] = p;
      p *= e[k]!;
    }
    let suffix = 1;
    let sum = 0;
    for (let k = n - 1; k >= 0; k -= 1) {
      sum += pre[k]! * suffix;
      suffix *= e[k]!;
    }
    this.measure[slot] = 2 * sum;
  }

  private setUnion(node: number, a: number, b: number): void {
    const n = this.n;
    for (let k = 0; k < n; k += 1) {
      this.nodeMin[node * n + k] = Math.min(this.nodeMin[a * n + k]!, this.nodeMin[b * n + k]!);
      this.nodeMax[node * n + k] = Math.max(this.nodeMax[a * n + k]!, this.nodeMax[b * n + k]!);
    }
  }

  private insertLeaf(leaf: number): void {
    this.linkedLeaves += 1;
    if (this.root === NULL) {
      this.root = leaf;
      this.parent[leaf] = NULL;
      return;
    }
    // Descend toward the sibling that grows the total surface measure the least.
    let index = this.root;
    const m = this.measure;
    while (this.height[index] !== 0) {
      const c1 = this.child1[index]!;
      const c2 = this.child2[index]!;
      this.measureInto(0, index, -1);
      this.measureInto(1, index, leaf);
      this.measureInto(2, leaf, c1);
      this.measureInto(3, leaf, c2);
      if (this.height[c1] !== 0) this.measureInto(4, c1, -1);
      else m[4] = 0;
      if (this.height[c2] !== 0) this.measureInto(5, c2, -1);
      else m[5] = 0;
      const cost = 2 * m[1]!;
      const inheritance = 2 * (m[1]! - m[0]!);
      const cost1 = m[2]! - m[4]! + inheritance;
      const cost2 = m[3]! - m[5]! + inheritance;
      if (cost < cost1 && cost < cost2) break;
      index = cost1 < cost2 ? c1 : c2;
    }
    const sibling = index;
    const oldParent = this.parent[sibling]!;
    const newParent = this.allocateNode();
    this.parent[newParent] = oldParent;
    this.setUnion(newParent, leaf, sibling);
    this.height[newParent] = this.height[sibling]! + 1;
    if (oldParent !== NULL) {
      if (this.child1[oldParent] === sibling) this.child1[oldParent] = newParent;
      else this.child2[oldParent] = newParent;
    } else {
      this.root = newParent;
    }
    this.child1[newParent] = sibling;
    this.child2[newParent] = leaf;
    this.parent[sibling] = newParent;
    this.parent[leaf] = newParent;
    this.refitUpward(this.parent[leaf]!);
  }

  private removeLeaf(leaf: number): void {
    this.linkedLeaves -= 1;
    if (leaf === this.root) {
      this.root = NULL;
      return;
    }
    const parent = this.parent[leaf]!;
    const grandParent = this.parent[parent]!;
    const sibling = this.child1[parent] === leaf ? this.child2[parent]! : this.child1[parent]!;
    if (grandParent !== NULL) {
      if (this.child1[grandParent] === parent) this.child1[grandParent] = sibling;
      else this.child2[grandParent] = sibling;
      this.parent[sibling] = grandParent;
      this.freeNode(parent);
      this.refitUpward(grandParent);
    } else {
      this.root = sibling;
      this.parent[sibling] = NULL;
      this.freeNode(parent);
    }
  }

  /** Rebalances and refits every node from `index` to the root. */
  private refitUpward(start: number): void {
    let index = start;
    while (index !== NULL) {
      index = this.balance(index);
      const c1 = this.child1[index]!;
      const c2 = this.child2[index]!;
      this.height[index] = 1 + Math.max(this.height[c1]!, this.height[c2]!);
      this.setUnion(index, c1, c2);
      index = this.parent[index]!;
    }
  }

  /** One AVL rotation at node a if its children's heights differ by more than 1. */
  private balance(iA: number): number {
    if (this.height[iA] === 0 || this.height[iA]! < 2) return iA;
    const iB = this.child1[iA]!;
    const iC = this.child2[iA]!;
    const diff = this.height[iC]! - this.height[iB]!;
    if (diff > 1) return this.rotateUp(iA, iC, iB, true);
    if (diff < -1) return this.rotateUp(iA, iB, iC, false);
    return iA;
  }

  /**
   * Lifts the taller child `up` of `a` into a's place. `other` is a's other child, `upIsChild2`
   * says which slot `up` occupied. The lower of up's children moves under a.
   */
  private rotateUp(iA: number, up: number, other: number, upIsChild2: boolean): number {
    const iF = this.child1[up]!;
    const iG = this.child2[up]!;
    this.child1[up] = iA;
    this.parent[up] = this.parent[iA]!;
    this.parent[iA] = up;
    const p = this.parent[up]!;
    if (p !== NULL) {
      if (this.child1[p] === iA) this.child1[p] = up;
      else this.child2[p] = up;
    } else {
      this.root = up;
    }
    // Keep the taller grandchild under `up`, give the shorter one to a.
    const keep = this.height[iF]! > this.height[iG]! ? iF : iG;
    const give = keep === iF ? iG : iF;
    this.child2[up] = keep;
    if (upIsChild2) this.child2[iA] = give;
    else this.child1[iA] = give;
    this.parent[give] = iA;
    this.setUnion(iA, other, give);
    this.setUnion(up, iA, keep);
    this.height[iA] = 1 + Math.max(this.height[other]!, this.height[give]!);
    this.height[up] = 1 + Math.max(this.height[iA]!, this.height[keep]!);
    return up;
  }
}

function grow(a: Int32Array, used: number): Int32Array {
  const b = new Int32Array(a.length * 2);
  b.set(a.subarray(0, used));
  return b;
}

function resizeF64(a: Float64Array, length: number): Float64Array {
  const b = new Float64Array(length);
  b.set(a);
  return b;
}

function resizeI32(a: Int32Array, length: number): Int32Array {
  const b = new Int32Array(length);
  b.set(a);
  return b;
}
