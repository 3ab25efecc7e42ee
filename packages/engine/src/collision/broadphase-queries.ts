/**
 * The broadphase's box query and ray walk, and the reading of a proxy's flags and boxes, as
 * functions rather than methods: a class's methods cannot be dropped by a bundler, and a world
 * that never queries, casts a ray or restores a snapshot should not carry them
 * (docs/architecture.md, What a scene pays for). The query code of collision/query.ts and the
 * snapshot code call them; they read the broadphase's and the tree's storage directly.
 *
 * @module
 */
import type { ProxyRayCast, ProxyVisitor } from './broadphase.js';
import type { BroadphaseBase } from './broadphase-base.js';
import type { DynamicAabbTree } from './broadphase-aabb-tree.js';
import { TreeBroadphase } from './broadphase-tree.js';
import { ALIVE, AWAKE, HALFSPACE, STATIC } from './broadphase-base.js';
import { checkDirection, checkFiniteArray, checkNumber, checkOutput } from './query-checks.js';

/** What these functions read of a broadphase (its protected and private parts). */
interface BaseParts {
  readonly n: number;
  readonly highWater: number;
  readonly flags: Uint8Array;
  readonly fatMin: Float64Array;
  readonly fatMax: Float64Array;
  checkLive(id: number, name: string): void;
  checkBoxProxy(id: number): void;
  readonly tightMin: Float64Array;
  readonly tightMax: Float64Array;
  readonly qMin: Float64Array;
  readonly qMax: Float64Array;
  readonly rayO: Float64Array;
  readonly rayD: Float64Array;
  readonly halfSpaces: Int32Array;
  readonly halfSpaceCount: number;
  checkBox(min: ArrayLike<number>, max: ArrayLike<number>, minName: string, maxName: string): void;
  boxReachesPlane(lo: Float64Array, hi: Float64Array, base: number, h: number): boolean;
  visitFat(visit: (id: number) => boolean): boolean;
  /** The ray walk of a broadphase other than the tree (the sweep-and-prune's). */
  castFat(limit: number, cast: ProxyRayCast): number;
}

/** What the ray walk reads of the tree (its private stack among it). */
interface TreeParts {
  readonly n: number;
  readonly root: number;
  readonly nodeMin: Float64Array;
  readonly nodeMax: Float64Array;
  readonly height: Int32Array;
  readonly userId: Int32Array;
  readonly child1: Int32Array;
  readonly child2: Int32Array;
  nodesVisited: number;
  stack: Int32Array;
}

/** True if `id` is a live proxy of `broadphase`. */
export function proxyIsAlive(broadphase: BroadphaseBase, id: number): boolean {
  const bp = broadphase as unknown as BaseParts;
  return Number.isInteger(id) && id >= 0 && id < bp.highWater && (bp.flags[id]! & ALIVE) !== 0;
}

/** The flag `bit` of the live proxy `id` (throws for an id that is not live). */
function flag(broadphase: BroadphaseBase, id: number, bit: number): boolean {
  const bp = broadphase as unknown as BaseParts;
  bp.checkLive(id, 'id');
  return (bp.flags[id]! & bit) !== 0;
}

/** True if the live proxy `id` is awake. */
export function proxyIsAwake(broadphase: BroadphaseBase, id: number): boolean {
  return flag(broadphase, id, AWAKE);
}

/** True if the live proxy `id` is static (half-spaces are). */
export function proxyIsStatic(broadphase: BroadphaseBase, id: number): boolean {
  return flag(broadphase, id, STATIC);
}

/** True if the live proxy `id` is a half-space. */
export function proxyIsHalfSpace(broadphase: BroadphaseBase, id: number): boolean {
  return flag(broadphase, id, HALFSPACE);
}

/**
 * Copies the tight box (the bounds last given; `fat` false) or the fattened box (`fat` true) of
 * the box proxy `id` into outMin/outMax (n numbers each).
 */
export function proxyBounds(
  broadphase: BroadphaseBase,
  id: number,
  outMin: Float64Array,
  outMax: Float64Array,
  fat = false,
): void {
  const bp = broadphase as unknown as BaseParts;
  const n = bp.n;
  bp.checkBoxProxy(id);
  checkOutput(outMin, n, 'outMin');
  checkOutput(outMax, n, 'outMax');
  const b = id * n;
  outMin.set((fat ? bp.fatMin : bp.tightMin).subarray(b, b + n));
  outMax.set((fat ? bp.fatMax : bp.tightMax).subarray(b, b + n));
}

/**
 * Visits every proxy of `broadphase` whose tight box overlaps [min, max] (closed), and every
 * half-space whose solid side the box reaches. Order is unspecified; `visit` returning false
 * stops; do not call the broadphase from `visit`.
 */
export function broadphaseQueryBox(
  broadphase: BroadphaseBase,
  min: ArrayLike<number>,
  max: ArrayLike<number>,
  visit: ProxyVisitor,
): void {
  const bp = broadphase as unknown as BaseParts;
  bp.checkBox(min, max, 'min', 'max');
  if (typeof visit !== 'function') throw new TypeError('visit must be a function');
  const n = bp.n;
  for (let k = 0; k < n; k += 1) {
    bp.qMin[k] = min[k]!;
    bp.qMax[k] = max[k]!;
  }
  for (let i = 0; i < bp.halfSpaceCount; i += 1) {
    const h = bp.halfSpaces[i]!;
    if (bp.boxReachesPlane(bp.qMin, bp.qMax, 0, h) && visit(h) === false) return;
  }
  bp.visitFat((id) => {
    const b = id * n;
    for (let k = 0; k < n; k += 1) {
      if (bp.tightMin[b + k]! > bp.qMax[k]! || bp.qMin[k]! > bp.tightMax[b + k]!) return true;
    }
    return visit(id) !== false;
  });
}

/**
 * Walks the proxies of `broadphase` whose tight box the ray origin + t·d̂ meets, t in
 * [0, maxDistance] (d̂ = direction normalised), half-spaces first, pruning with the closest hit
 * so far. Returns the closest distance reported by `cast`, or −1.
 */
export function broadphaseRayCast(
  broadphase: BroadphaseBase,
  origin: ArrayLike<number>,
  direction: ArrayLike<number>,
  maxDistance: number,
  cast: ProxyRayCast,
): number {
  const bp = broadphase as unknown as BaseParts;
  const n = bp.n;
  checkFiniteArray(origin, n, 'origin');
  checkDirection(direction, n, 'direction');
  checkNumber(maxDistance, 'maxDistance', 0, true);
  if (typeof cast !== 'function') throw new TypeError('cast must be a function');
  let s = 0;
  for (let k = 0; k < n; k += 1) s += direction[k]! * direction[k]!;
  const inv = 1 / Math.sqrt(s);
  for (let k = 0; k < n; k += 1) {
    bp.rayO[k] = origin[k]!;
    bp.rayD[k] = direction[k]! * inv;
  }
  let limit = maxDistance;
  let best = -1;
  for (let i = 0; i < bp.halfSpaceCount; i += 1) {
    const t = cast(bp.halfSpaces[i]!, limit);
    if (t >= 0 && t <= limit) {
      limit = t;
      best = t;
    }
  }
  const boxCast = (id: number, lim: number): number =>
    rayHitsBox(n, bp.rayO, bp.rayD, lim, bp.tightMin, bp.tightMax, id * n) ? cast(id, lim) : -1;
  // The tree's walk (its `tree` getter first puts waiting proxies in), or the other structure's.
  const t =
    broadphase instanceof TreeBroadphase
      ? treeRayCast(broadphase.tree, bp.rayO, bp.rayD, limit, boxCast)
      : bp.castFat(limit, boxCast);
  return t >= 0 ? t : best;
}

/**
 * Walks the leaves of `tree` whose box the ray o + t·d meets for t in [0, limit], shrinking the
 * limit as hits come in: `cast(user, limit)` returns the distance of its own hit (>= 0, used as
 * the new limit) or a negative number for none. Returns the smallest hit distance, or −1.
 */
export function treeRayCast(
  tree: DynamicAabbTree,
  o: ArrayLike<number>,
  d: ArrayLike<number>,
  maxDistance: number,
  cast: (user: number, limit: number) => number,
): number {
  const t = tree as unknown as TreeParts;
  t.nodesVisited = 0;
  if (t.root === -1) return -1;
  const n = t.n;
  let limit = maxDistance;
  let best = -1;
  let top = 0;
  t.stack[top++] = t.root;
  while (top > 0) {
    const node = t.stack[--top]!;
    t.nodesVisited += 1;
    if (!rayHitsBox(n, o, d, limit, t.nodeMin, t.nodeMax, node * n)) continue;
    if (t.height[node] === 0) {
      const hit = cast(t.userId[node]!, limit);
      if (hit >= 0 && hit <= limit) {
        limit = hit;
        best = hit;
      }
    } else {
      if (top + 2 > t.stack.length) t.stack = grow(t.stack, top);
      t.stack[top++] = t.child1[node]!;
      t.stack[top++] = t.child2[node]!;
    }
  }
  return best;
}

/**
 * Slab test: does the ray o + t·d, t in [0, limit], meet the box at `base` of (boxMin, boxMax)?
 * Closed intervals; an axis with d = 0 needs o inside the slab.
 */
export function rayHitsBox(
  n: number,
  o: ArrayLike<number>,
  d: ArrayLike<number>,
  limit: number,
  boxMin: Float64Array,
  boxMax: Float64Array,
  base: number,
): boolean {
  let t0 = 0;
  let t1 = limit;
  for (let k = 0; k < n; k += 1) {
    const dk = d[k]!;
    const ok = o[k]!;
    const lo = boxMin[base + k]!;
    const hi = boxMax[base + k]!;
    if (dk === 0) {
      if (ok < lo || ok > hi) return false;
      continue;
    }
    let a = (lo - ok) / dk;
    let b = (hi - ok) / dk;
    if (a > b) {
      const s = a;
      a = b;
      b = s;
    }
    if (a > t0) t0 = a;
    if (b < t1) t1 = b;
    if (t0 > t1) return false;
  }
  return true;
}

/**
 * Checks the tree's invariants (parents, heights, boxes containing children); for tests. Returns
 * null, or what is wrong.
 */
export function validateTree(tree: DynamicAabbTree): string | null {
  const t = tree as unknown as TreeParts & { readonly parent: Int32Array; readonly nodeCount: number };
  if (t.root === -1) return null;
  if (t.parent[t.root] !== -1) return 'root has a parent';
  const n = t.n;
  let count = 0;
  let top = 0;
  t.stack[top++] = t.root;
  while (top > 0) {
    const node = t.stack[--top]!;
    count += 1;
    if (t.height[node] === 0) continue;
    const c1 = t.child1[node]!;
    const c2 = t.child2[node]!;
    if (t.parent[c1] !== node || t.parent[c2] !== node) return `bad parent link at ${node}`;
    const h = 1 + Math.max(t.height[c1]!, t.height[c2]!);
    if (t.height[node] !== h) return `bad height at ${node}`;
    for (let k = 0; k < n; k += 1) {
      const lo = Math.min(t.nodeMin[c1 * n + k]!, t.nodeMin[c2 * n + k]!);
      const hi = Math.max(t.nodeMax[c1 * n + k]!, t.nodeMax[c2 * n + k]!);
      if (t.nodeMin[node * n + k] !== lo || t.nodeMax[node * n + k] !== hi) {
        return `box of ${node} is not the union of its children`;
      }
    }
    if (top + 2 > t.stack.length) t.stack = grow(t.stack, top);
    t.stack[top++] = c1;
    t.stack[top++] = c2;
  }
  if (count !== t.nodeCount) return `reachable ${count} != allocated ${t.nodeCount}`;
  return null;
}

function grow(a: Int32Array, used: number): Int32Array {
  const b = new Int32Array(a.length * 2);
  b.set(a.subarray(0, used));
  return b;
}
