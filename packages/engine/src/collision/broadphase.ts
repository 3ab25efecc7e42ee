/**
 * The broadphase contract: which pairs of bodies might touch, from their bounding boxes.
 *
 * A broadphase holds proxies (integer ids): boxes, and half-spaces kept aside (infinite, never in
 * a box structure). Each proxy has a tight box (the bounds last given) and a fattened box (the
 * tight box grown by `margin` when it was last (re)inserted). A proxy counts as moved only when
 * its tight box leaves its fattened box; the pair set is the set of proxy pairs whose fattened
 * boxes overlap (closed intervals), and a box pairs with a half-space when its fattened box
 * reaches the solid side of the plane.
 *
 * `updatePairs()` brings the pair set up to date and writes the pairs to report into {@link
 * Broadphase.pairs}: sorted by (a, b) with a < b, so the output is bit-identical run to run. Pairs
 * where neither proxy is awake and dynamic (both asleep, both static, or one of each) are kept but
 * not reported. Half-spaces are static. Static–static pairs are not even kept.
 */
import { SweepAndPruneBroadphase } from './broadphase-sap.js';
import { TreeBroadphase } from './broadphase-tree.js';

/** Settings of a broadphase. */
export interface BroadphaseOptions {
  /**
   * Room added on every side of a proxy's box when it is (re)inserted (m, >= 0). Larger values
   * mean fewer reinsertions and more (false) candidate pairs. Default 0.1 (DEFAULT_BROADPHASE_MARGIN).
   */
  readonly margin?: number;
  /** Proxies to make room for up front (the arrays grow by doubling beyond it). Default 64. */
  readonly initialCapacity?: number;
}

export { DEFAULT_BROADPHASE_MARGIN } from './broadphase-constants.js';

/** What the last {@link Broadphase.updatePairs} did: counts, to measure the work. */
export interface BroadphaseStats {
  /** Proxies marked moved since the update before (created, destroyed, left their fat box, flag changed). */
  moved: number;
  /** Box-structure queries run (one per moved box proxy for the tree; 0 for a full sweep). */
  queries: number;
  /** Tree nodes (or sorted entries) visited by those queries. */
  nodesVisited: number;
  /** Candidate pairs produced (by queries, sweeps and half-space tests) before merging. */
  candidates: number;
  /** Pairs in the set, reported or not (sleeping pairs included). */
  pairs: number;
}

/** A callback for a box query: return `false` to stop the query early. */
export type ProxyVisitor = (id: number) => boolean | void;

/**
 * A callback for a ray query: cast the ray against proxy `id` and return the distance of the hit
 * (>= 0), or a negative number for a miss. `limit` is the closest distance found so far; a hit
 * beyond it is ignored. Returning a distance shrinks the limit for the rest of the walk.
 */
export type ProxyRayCast = (id: number, limit: number) => number;

/** An n-dimensional broadphase (see the module comment for the semantics). */
export interface Broadphase {
  /** Count of dimensions. */
  readonly n: number;
  /** Fattening margin (m). */
  readonly margin: number;
  /** Reported pairs of the last update, flat: pair p is (pairs[2p], pairs[2p+1]), a < b, sorted. May be reallocated by an update. */
  readonly pairs: Int32Array;
  /** Count of reported pairs. */
  readonly pairCount: number;
  /** Pairs that entered the set in the last update (reported or not), flat and sorted like {@link pairs}. */
  readonly addedPairs: Int32Array;
  /** Count of {@link addedPairs}. */
  readonly addedCount: number;
  /** Pairs that left the set in the last update (boxes separated or a proxy destroyed), flat and sorted. */
  readonly removedPairs: Int32Array;
  /** Count of {@link removedPairs}. */
  readonly removedCount: number;
  /** Work counters of the last update. */
  readonly stats: BroadphaseStats;
  /** Count of live proxies (boxes and half-spaces). */
  readonly proxyCount: number;
  /** Every live id is below this bound (ids are reused after an update). */
  readonly idBound: number;

  /** Adds a box proxy with bounds [min, max] (n numbers each, min <= max). Returns its id. */
  createProxy(min: ArrayLike<number>, max: ArrayLike<number>, isStatic?: boolean): number;
  /** Adds a half-space proxy: the solid side is { p : normal·p <= offset } in world coordinates. Returns its id. */
  createHalfSpaceProxy(normal: ArrayLike<number>, offset: number): number;
  /** Removes a proxy; its pairs leave the set at the next update, and its id is reused after that. */
  destroyProxy(id: number): void;
  /** Gives a box proxy new tight bounds; returns true if it left its fattened box (it counts as moved). */
  moveProxy(id: number, min: ArrayLike<number>, max: ArrayLike<number>): boolean;
  /** Gives a half-space proxy a new plane (it counts as moved). */
  moveHalfSpace(id: number, normal: ArrayLike<number>, offset: number): void;
  /** Marks a proxy awake (default at creation) or asleep. */
  setAwake(id: number, awake: boolean): void;
  /** Makes a box proxy static or dynamic (it counts as moved, so its pairs are rebuilt). */
  setStatic(id: number, isStatic: boolean): void;
  /** Brings the pair set up to date; returns {@link pairCount}. Allocates nothing in steady state. */
  updatePairs(): number;
}

/** Which structure a broadphase uses. */
export type BroadphaseKind = 'tree' | 'sap';

/**
 * Makes a broadphase for n dimensions. The default, `'tree'`, is the dynamic AABB tree (see
 * docs/collision.md for the measured comparison with `'sap'`, sweep-and-prune on the axis of
 * largest variance).
 */
export function createBroadphase(n: number, options: BroadphaseOptions = {}, kind: BroadphaseKind = 'tree'): Broadphase {
  if (kind === 'sap') return new SweepAndPruneBroadphase(n, options);
  if (kind !== 'tree') throw new RangeError(`kind must be 'tree' or 'sap', got ${String(kind)}`);
  return new TreeBroadphase(n, options);
}
