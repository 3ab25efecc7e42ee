/**
 * Every pair of overlapping leaves of a {@link DynamicAabbTree}, by one walk of the tree against
 * itself.
 *
 * The broadphase finds the pairs of a proxy that moved by a query from the root, O(log N) each.
 * When most proxies moved at once (the first step after thousands of bodies were added), N
 * queries walk the top of the tree N times; walking the tree against itself visits each pair of
 * overlapping nodes once instead: O(N + overlapping pairs). A node is paired with itself (its two
 * children, each with itself and with the other); two different nodes that overlap are split,
 * the taller one first, down to pairs of leaves. Each unordered pair of overlapping leaves comes
 * out exactly once, in an order that depends on the tree's shape (the broadphase sorts it).
 *
 * This is an internal kernel of the broadphase: it does not validate its arguments.
 */
import type { DynamicAabbTree } from './broadphase-aabb-tree.js';

/** The self-join's scratch and results; allocates only to grow. */
export class TreeSelfPairs {
  /** The pairs found: user ids, flat, pair p at [2p, 2p + 1). */
  pairs: Int32Array = new Int32Array(64);
  /** Count of pairs in {@link pairs}. */
  count = 0;
  /** Pairs of nodes whose boxes the last walk tested (the work it did). */
  nodesVisited = 0;
  /** Node pairs still to visit (a, b); a === b means the node against itself. */
  private stack: Int32Array = new Int32Array(128);

  /** Finds every pair of leaves of `tree` whose boxes overlap (closed intervals); returns the count. */
  run(tree: DynamicAabbTree): number {
    this.count = 0;
    this.nodesVisited = 0;
    if (tree.root < 0) return 0;
    const n = tree.n;
    const lo = tree.nodeMin;
    const hi = tree.nodeMax;
    const child1 = tree.child1;
    const child2 = tree.child2;
    const height = tree.height;
    let stack = this.stack;
    let top = 0;
    stack[top++] = tree.root;
    stack[top++] = tree.root;
    while (top > 0) {
      const b = stack[--top]!;
      const a = stack[--top]!;
      if (top + 6 > stack.length) stack = this.growStack(top);
      if (a === b) {
        if (height[a] === 0) continue;
        const c1 = child1[a]!;
        const c2 = child2[a]!;
        stack[top++] = c1;
        stack[top++] = c2;
        stack[top++] = c2;
        stack[top++] = c2;
        stack[top++] = c1;
        stack[top++] = c1;
        continue;
      }
      this.nodesVisited += 1;
      let overlap = true;
      for (let k = 0; k < n; k += 1) {
        if (lo[a * n + k]! > hi[b * n + k]! || lo[b * n + k]! > hi[a * n + k]!) {
          overlap = false;
          break;
        }
      }
      if (!overlap) continue;
      const ha = height[a]!;
      const hb = height[b]!;
      if (ha === 0 && hb === 0) {
        this.push(tree.userId[a]!, tree.userId[b]!);
      } else if (hb > ha) {
        stack[top++] = a;
        stack[top++] = child1[b]!;
        stack[top++] = a;
        stack[top++] = child2[b]!;
      } else {
        stack[top++] = child1[a]!;
        stack[top++] = b;
        stack[top++] = child2[a]!;
        stack[top++] = b;
      }
    }
    return this.count;
  }

  private push(a: number, b: number): void {
    if (2 * this.count + 2 > this.pairs.length) {
      const next = new Int32Array(2 * this.pairs.length);
      next.set(this.pairs);
      this.pairs = next;
    }
    this.pairs[2 * this.count] = a;
    this.pairs[2 * this.count + 1] = b;
    this.count += 1;
  }

  private growStack(used: number): Int32Array {
    const next = new Int32Array(2 * this.stack.length);
    next.set(this.stack.subarray(0, used));
    this.stack = next;
    return next;
  }
}
