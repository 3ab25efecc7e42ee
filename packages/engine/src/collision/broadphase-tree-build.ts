/**
 * The top-down build of a {@link DynamicAabbTree} over many leaves at once.
 *
 * Inserting leaves one at a time costs a descent and a refit to the root each. When a world adds
 * thousands of bodies before a step, the broadphase builds the tree for all of them in one pass
 * instead, as Box2D v3 rebuilds its static tree, with its default split: each range of leaves is
 * cut at the middle of the widest spread of their centres, and a range whose centres all
 * coincide is halved by count. The centres' bounds of the two halves are gathered while the range
 * is partitioned, so each level of the tree costs one pass over its leaves: O(leaves · depth).
 * (The binned surface-area split, tried first, gave no better trees on our scenes at five times
 * the cost.) No allocation once the scratch has grown; a pure function of the leaves and their
 * order.
 *
 * This is an internal kernel of the broadphase: it does not validate its arguments.
 */
import type { DynamicAabbTree } from './broadphase-aabb-tree.js';

const NULL = -1;

/** Scratch and the build itself; one per tree, grown with the count of leaves. */
export class TreeBuilder {
  private readonly n: number;
  /** Ranges still to split: (begin, end, parent, slot) per entry. */
  private stack = new Int32Array(64);
  /** Per stack entry: the bounds of its leaves' centres (min then max, n numbers each; sums min + max). */
  private bounds: Float64Array;
  /** The inner nodes made, parents before children (their boxes are filled in reverse). */
  private inner = new Int32Array(64);

  /** Scratch for n dimensions. */
  constructor(n: number) {
    this.n = n;
    this.bounds = new Float64Array(16 * 2 * n);
  }

  /**
   * Links the free leaves `leaves[0 .. count)` (nodes of `tree` with their boxes set, parent and
   * children unset) into one subtree of new inner nodes and returns its root (−1 when count is 0).
   * Reorders `leaves`. The tree must have room for count − 1 more nodes (`tree.reserveNodes`).
   */
  build(tree: DynamicAabbTree, leaves: Int32Array, count: number): number {
    if (count === 0) return NULL;
    if (this.inner.length < count) this.inner = new Int32Array(Math.max(count, 2 * this.inner.length));
    const n = this.n;
    const lo = tree.nodeMin;
    const hi = tree.nodeMax;
    let innerCount = 0;
    let root = NULL;
    this.setEntry(0, 0, count, NULL, 0);
    let top = 1;
    this.centreBounds(tree, leaves, 0, count, 0);
    while (top > 0) {
      top -= 1;
      const begin = this.stack[4 * top]!;
      const end = this.stack[4 * top + 1]!;
      const parent = this.stack[4 * top + 2]!;
      const slot = this.stack[4 * top + 3]!;
      let node: number;
      if (end - begin === 1) {
        node = leaves[begin]!;
      } else {
        node = tree.allocateNode();
        this.inner[innerCount++] = node;
        // Entry `top` is free now: the partition writes the first half's bounds there and the
        // second half's into the entry above it, and both are pushed in those places.
        const mid = this.partition(tree, leaves, begin, end, top);
        this.setEntry(top + 1, mid, end, node, 2);
        this.setEntry(top, begin, mid, node, 1);
        top += 2;
      }
      tree.parent[node] = parent;
      if (parent === NULL) root = node;
      else if (slot === 1) tree.child1[parent] = node;
      else tree.child2[parent] = node;
    }
    // Children were made after their parents: in reverse, every node's children are done.
    const height = tree.height;
    for (let i = innerCount - 1; i >= 0; i -= 1) {
      const node = this.inner[i]!;
      const a = tree.child1[node]!;
      const b = tree.child2[node]!;
      for (let k = 0; k < n; k += 1) {
        lo[node * n + k] = Math.min(lo[a * n + k]!, lo[b * n + k]!);
        hi[node * n + k] = Math.max(hi[a * n + k]!, hi[b * n + k]!);
      }
      height[node] = 1 + Math.max(height[a]!, height[b]!);
    }
    return root;
  }

  /** Writes stack entry `at`, growing the stack and the bounds with it. */
  private setEntry(at: number, begin: number, end: number, parent: number, slot: number): void {
    if (4 * at + 4 > this.stack.length) {
      const next = new Int32Array(2 * this.stack.length);
      next.set(this.stack);
      this.stack = next;
    }
    if (2 * this.n * (at + 1) > this.bounds.length) {
      const next = new Float64Array(2 * this.bounds.length);
      next.set(this.bounds);
      this.bounds = next;
    }
    this.stack[4 * at] = begin;
    this.stack[4 * at + 1] = end;
    this.stack[4 * at + 2] = parent;
    this.stack[4 * at + 3] = slot;
  }

  /** The bounds of the centres of leaves[begin .. end) into bounds entry `at`. */
  private centreBounds(tree: DynamicAabbTree, leaves: Int32Array, begin: number, end: number, at: number): void {
    const n = this.n;
    const lo = tree.nodeMin;
    const hi = tree.nodeMax;
    const bounds = this.bounds;
    const o = 2 * n * at;
    for (let k = 0; k < n; k += 1) {
      bounds[o + k] = Infinity;
      bounds[o + n + k] = -Infinity;
    }
    for (let i = begin; i < end; i += 1) {
      const b = leaves[i]! * n;
      for (let k = 0; k < n; k += 1) {
        const c = lo[b + k]! + hi[b + k]!;
        if (c < bounds[o + k]!) bounds[o + k] = c;
        if (c > bounds[o + n + k]!) bounds[o + n + k] = c;
      }
    }
  }

  /**
   * Reorders leaves[begin .. end) (at least two, their centres' bounds in entry `at`) into two
   * non-empty runs, those below the middle of the widest axis first, and returns where the second
   * starts; the bounds of the first run's centres go to entry `at`, the second's to `at + 1`.
   */
  private partition(tree: DynamicAabbTree, leaves: Int32Array, begin: number, end: number, at: number): number {
    const n = this.n;
    const lo = tree.nodeMin;
    const hi = tree.nodeMax;
    this.setEntry(at + 1, 0, 0, NULL, 0); // (room for the second run's bounds)
    const bounds = this.bounds;
    const o = 2 * n * at;
    let axis = 0;
    for (let k = 1; k < n; k += 1) {
      if (bounds[o + n + k]! - bounds[o + k]! > bounds[o + n + axis]! - bounds[o + axis]!) axis = k;
    }
    const low = bounds[o + axis]!;
    const high = bounds[o + n + axis]!;
    // Identical centres (a stack of equal boxes): no axis tells them apart; halve the range.
    if (!(high > low)) {
      const mid = begin + ((end - begin) >> 1);
      bounds.copyWithin(o + 2 * n, o, o + 2 * n);
      return mid;
    }
    const pivot = 0.5 * (low + high);
    let i = begin;
    let j = end - 1;
    for (;;) {
      while (i <= j && lo[leaves[i]! * n + axis]! + hi[leaves[i]! * n + axis]! < pivot) i += 1;
      while (i <= j && lo[leaves[j]! * n + axis]! + hi[leaves[j]! * n + axis]! >= pivot) j -= 1;
      if (i >= j) break;
      const t = leaves[i]!;
      leaves[i] = leaves[j]!;
      leaves[j] = t;
      i += 1;
      j -= 1;
    }
    // The lowest centre is below the pivot and the highest is not, unless the two are neighbouring
    // floats (then the pivot rounds onto the lowest): halve the range by count.
    if (i === begin || i === end) i = begin + ((end - begin) >> 1);
    this.centreBounds(tree, leaves, begin, i, at);
    this.centreBounds(tree, leaves, i, end, at + 1);
    return i;
  }
}
