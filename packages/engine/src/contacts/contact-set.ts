/**
 * The contacts of a world: one slot per pair of bodies whose broadphase boxes overlap, kept in the
 * order of the pair key so every pass over them is deterministic.
 *
 * A slot holds the pair's manifold (refreshed by the narrowphase every sub-step while one of the
 * two bodies is awake), the normal impulses of the last solve per manifold point (matched by
 * feature id, else by position, so the solver can warm-start them), the friction patch's impulses
 * per pair, the mixed material and the touching state that drives the
 * begin / end events. The set follows the broadphase: `applyPairChanges` merges its sorted lists
 * of added and removed pairs into the sorted key list, so no hashing is involved and nothing is
 * allocated once the arrays have grown to the scene.
 *
 * @module
 */
import type { Body } from '../body.js';
import { MOTION_DYNAMIC, MOTION_STATIC } from '../body.js';
import { collideScratch } from '../collision/collide.js';
import type { Manifold } from '../collision/manifold.js';
import type { Pose } from '../collision/manifold.js';
import { createManifold, createPose, manifoldBytes, manifoldIn, maxManifoldPoints } from '../collision/manifold.js';
import { NARROWPHASE_MARGIN, SAT_EDGE } from '../collision/narrowphase-scratch.js';
import type { NarrowphaseScratch } from '../collision/narrowphase-scratch.js';
import type { Params } from '../params.js';
import type { Shape } from '../shapes/shape.js';
import type { ContactEvents } from './contact-events.js';
import { CACHE_APART, CACHE_REUSE, ManifoldCache } from './manifold-cache.js';

export { growFloat64, growInt32 } from './grow.js';
import { growFloat64, growInt32 } from './grow.js';

/** Flag: the manifold has a point closer than the contact margin (the pair touches). */
export const CONTACT_TOUCHING = 1;
/** Flag: the pair touched at the end of the previous sub-step (for begin / end events). */
export const CONTACT_WAS_TOUCHING = 2;
/**
 * Flag: the manifold was refreshed in this sub-step (one of the bodies is awake) and holds points:
 * the slot gives the solver rows.
 */
export const CONTACT_ACTIVE = 4;
/**
 * Flag: one of the two bodies is a sensor. The slot tells overlap (CONTACT_TOUCHING: some point
 * with separation < 0) for the begin / end events and nothing else: no solver rows (it is never
 * CONTACT_ACTIVE), no island link, no waking.
 */
export const CONTACT_SENSOR = 8;
/**
 * Flag: the manifold may hold points though the slot is neither CONTACT_ACTIVE nor a sensor's (a
 * pair of two bodies that do not move, in a set used without a world). With those two it tells
 * `updateManifolds` whether a pair found apart must empty its manifold: most slots of a pile are
 * apart and already empty, and writing their manifolds cost a cache miss each.
 */
const CONTACT_POINTS = 16;

/**
 * A pair filter: called with the two bodies of a pair whose boxes overlap, each time the
 * narrowphase would collide them (once per sub-step while one of them moves); false means no
 * contact. It must not throw or change the world.
 */
export type PairFilter = (a: Body, b: Body) => boolean;

/**
 * What the world knows per broadphase proxy id, shared with its contact set: the body, the shape
 * the proxy holds (the body's shape, or one part of a compound body), that shape's world pose
 * (the body's pose, or the part's) and the part's index (0 for a body of one shape).
 */
export interface ProxyTables {
  readonly body: (Body | null)[];
  readonly shape: (Shape | null)[];
  readonly pose: (Pose | null)[];
  readonly part: number[];
}

/** Key of the pair of proxies (a, b), a < b: a·2²⁶ + b, exact in a double. */
export const PAIR_KEY_SCALE = 67_108_864;

/**
 * Whether the body moves in this sub-step: an awake dynamic body, or a kinematic body with a
 * velocity (a kinematic body at rest is as still as a static one and must not wake its neighbours).
 */
export function isMoving(body: Body): boolean {
  if (body.motion === MOTION_DYNAMIC) return !body.sleeping;
  if (body.motion === MOTION_STATIC) return false;
  const v = body.v;
  for (let i = 0; i < v.length; i += 1) if (v[i] !== 0) return true;
  const w = body.w;
  for (let i = 0; i < w.length; i += 1) if (w[i] !== 0) return true;
  return false;
}

/**
 * Scratch of the sweep that tells a real speculative contact from a ghost (`meetsInSubStep`), one
 * per count of dimensions, shared by the worlds of that n (the sweep runs within one call and
 * keeps nothing). Made by the ContactSet constructor, so a step allocates nothing.
 */
interface SweepScratch {
  /** The manifold of the pair at a time in the sub-step. */
  readonly manifold: Manifold;
  /** B's pose moved along the relative velocity (its M a copy of B's). */
  readonly pose: Pose;
  /** [sub-step h, tolerance, …] (an array: no boxed doubles). */
  readonly numbers: Float64Array;
}
const sweepScratch: (SweepScratch | undefined)[] = [];

/** Newton steps of the sweep (at most; it converges from below in a few). */
const SWEEP_STEPS = 24;
/** A gap the sweep closes to within this (m), plus the bodies' rotational reach, meets. */
const SWEEP_TOLERANCE = 1e-4;

/**
 * The contact list of every body, as doubly linked lists through the slots (Box2D's contact
 * edges): edge e = 2·slot + side (side 0: the slot's body A, 1: body B). Derived from the slots
 * (a restore rebuilds it), so waking an island, gathering the contacts of the awake bodies and
 * removing a body cost O(their contacts), not O(all contacts).
 */
class SlotLinks {
  /** Per edge: the next edge of the same body's list, plus one (0: the end). */
  next = new Int32Array(32);
  /** Per edge: the previous edge of the same body's list, plus one (0: the first). */
  prev = new Int32Array(32);
  /** Per proxy id of a body (`Body.proxyId`): its first edge plus one (0: no contact). */
  head = new Int32Array(16);
  /** Per slot: the pass of `gatherActive` that last took it. */
  mark = new Int32Array(16);
  /** The current pass of `gatherActive`. */
  epoch = 0;
  /** True when the lists do not match the slots (a snapshot filled them): rebuilt before use. */
  stale = false;
}

/**
 * The slots, fields and order the contact solver reads (`ContactSolver.prepare` / `store`): the
 * set's own arrays, with `order` / `count` the active slots alone (see ContactSet.solverContacts).
 */
interface SolverContacts {
  order: Int32Array;
  count: number;
  pointCapacity: number;
  flags: Uint8Array;
  manifolds: Manifold[];
  bodyA: (Body | null)[];
  bodyB: (Body | null)[];
  normalImpulse: Float64Array;
  approachSpeed: Float64Array;
  patchTangent: Float64Array;
  patchTwist: Float64Array;
  friction: Float64Array;
  restitution: Float64Array;
}

/**
 * Sorts `list[0 .. count)` (slots) by ascending `keys[slot]` in place (heap sort: no recursion,
 * no allocation). Keys are unique, so the result is the same whatever the input order.
 */
function sortSlotsByKey(list: Int32Array, count: number, keys: Float64Array): void {
  for (let start = (count >> 1) - 1; start >= 0; start -= 1) siftSlot(list, keys, start, count);
  for (let end = count - 1; end > 0; end -= 1) {
    const t = list[0];
    list[0] = list[end];
    list[end] = t;
    siftSlot(list, keys, 0, end);
  }
}

/** The sift-down of sortSlotsByKey's heap over list[0 .. end). */
function siftSlot(list: Int32Array, keys: Float64Array, root: number, end: number): void {
  for (;;) {
    let child = 2 * root + 1;
    if (child >= end) return;
    if (child + 1 < end && keys[list[child + 1]] > keys[list[child]]) child += 1;
    if (keys[list[root]] >= keys[list[child]]) return;
    const t = list[root];
    list[root] = list[child];
    list[child] = t;
    root = child;
  }
}

/**
 * The contact slots of one world (n dimensions). All arrays are indexed by slot; `order` lists
 * the live slots in ascending pair key.
 */
export class ContactSet {
  /** Count of dimensions. */
  readonly n: number;
  /** Most points a manifold keeps in n dimensions. */
  readonly pointCapacity: number;

  /**
   * Live slots in ascending key order: order[0 .. count) once `compactOrder()` ran (`removeBody`
   * leaves holes that it closes; every pass of the set closes them first).
   */
  order: Int32Array = new Int32Array(16);
  /** Count of live contacts. */
  count = 0;
  /**
   * The slots with a moving body (an awake dynamic or a moving kinematic one) in ascending key
   * order: active[0 .. activeCount). The narrowphase, the solver, the events and the islands of a
   * sub-step walk this list alone, so that sleeping piles cost nothing. The world gathers it from
   * its awake bodies (`gatherActive`); without that, `updateManifolds` finds it by a pass over
   * every slot.
   */
  active: Int32Array = new Int32Array(16);
  /** Count of active slots. */
  activeCount = 0;
  /** Whether `gatherActive` ran since the last `updateManifolds`. */
  private gathered = false;
  /** The contact list of every body (derived from the slots). */
  private readonly links = new SlotLinks();
  /** Slots `removeBody` freed that `order` still lists (see compactOrder). */
  private orderHoles = 0;
  /** The view of the active slots handed to the contact solver (see solverContacts). */
  private readonly solverSet: SolverContacts;

  /** Pair key of each slot. */
  keys: Float64Array = new Float64Array(16);
  /** Bodies of each slot (A owns the lower proxy id); null for a free slot. */
  bodyA: (Body | null)[] = [];
  /** Second body of each slot. */
  bodyB: (Body | null)[] = [];
  /** The shape of each slot's first proxy: body A's shape, or the part of A's compound it holds. */
  shapeA: (Shape | null)[] = [];
  /** The shape of each slot's second proxy. */
  shapeB: (Shape | null)[] = [];
  /** The world pose of shapeA (body A's pose, or its part's). */
  poseA: (Pose | null)[] = [];
  /** The world pose of shapeB. */
  poseB: (Pose | null)[] = [];
  /** The index of shapeA among the parts of A's compound (0 for a body of one shape). */
  partA: Int32Array = new Int32Array(16);
  /** The index of shapeB among the parts of B's compound. */
  partB: Int32Array = new Int32Array(16);
  /** The world's tables per proxy id (see ProxyTables). */
  readonly proxies: ProxyTables;
  /** The manifold of each slot (normal from A to B). */
  manifolds: Manifold[] = [];
  /** Accumulated normal impulse per manifold point (N·s), pointCapacity per slot. */
  normalImpulse: Float64Array;
  /**
   * Per manifold point: the normal velocity (m/s, negative = approaching) at which a speculative
   * contact stopped the bodies at the surface in the last sub-step, else 0. The next sub-step
   * bounces from that speed: the stop itself leaves almost no approach speed to bounce from.
   */
  approachSpeed: Float64Array;
  /**
   * Accumulated friction impulse of each slot's patch (see ContactSolver) as a world vector (N·s),
   * n per slot; it survives a change of tangent basis and of the manifold's points.
   */
  patchTangent: Float64Array;
  /** Accumulated twist friction impulse of each slot's patch as a world bivector (N·m·s), k per slot. */
  patchTwist: Float64Array;
  /** Bivector components per slot: n(n−1)/2. */
  private readonly k: number;
  /** Mixed friction coefficient of each slot. */
  friction: Float64Array = new Float64Array(16);
  /** Mixed restitution of each slot. */
  restitution: Float64Array = new Float64Array(16);
  /** CONTACT_* flags of each slot. */
  flags: Uint8Array = new Uint8Array(16);

  private capacity = 0;
  private freeSlots: Int32Array = new Int32Array(16);
  private freeCount = 0;
  private orderNext: Int32Array = new Int32Array(16);
  /** Scratch of the id matching: the previous ids, impulses and friction vectors of one manifold. */
  private readonly oldIds: Uint32Array;
  private readonly oldNormal: Float64Array;
  private readonly oldApproach: Float64Array;
  private readonly oldPoints: Float64Array;
  /** Per old point: 1 once a new point took its impulses. */
  private readonly oldTaken: Uint8Array;
  /** Per new point: 1 once it took an old point's impulses by id. */
  private readonly newMatched: Uint8Array;
  /** Box–box manifolds kept while the two boxes hardly move relative to each other. */
  private readonly cache: ManifoldCache;
  /**
   * [the reuse tolerance, the radii of the pair's second and first bodies, the pair's margin]
   * (arrays: no boxed doubles).
   */
  private readonly reuseNumbers = new Float64Array(4);

  /**
   * `cache` builds the manifold cache (n, points per slot): the root entry's worlds give one with
   * the 4D reuse written out (manifold-cache-nd.ts); by default the general one.
   */
  constructor(
    n: number,
    proxies: ProxyTables = { body: [], shape: [], pose: [], part: [] },
    cache?: (n: number, pointsPerSlot: number) => ManifoldCache,
  ) {
    this.n = n;
    this.proxies = proxies;
    this.pointCapacity = maxManifoldPoints(n);
    this.normalImpulse = new Float64Array(16 * this.pointCapacity);
    this.approachSpeed = new Float64Array(16 * this.pointCapacity);
    this.k = (n * (n - 1)) / 2;
    this.patchTangent = new Float64Array(16 * n);
    this.patchTwist = new Float64Array(16 * this.k);
    this.oldIds = new Uint32Array(this.pointCapacity);
    this.oldNormal = new Float64Array(this.pointCapacity);
    this.oldApproach = new Float64Array(this.pointCapacity);
    this.oldPoints = new Float64Array(this.pointCapacity * n);
    this.oldTaken = new Uint8Array(this.pointCapacity);
    this.newMatched = new Uint8Array(this.pointCapacity);
    this.cache = cache !== undefined ? cache(n, this.pointCapacity) : new ManifoldCache(n, this.pointCapacity);
    this.solverSet = {
      order: this.active,
      count: 0,
      pointCapacity: this.pointCapacity,
      flags: this.flags,
      manifolds: this.manifolds,
      bodyA: this.bodyA,
      bodyB: this.bodyB,
      normalImpulse: this.normalImpulse,
      approachSpeed: this.approachSpeed,
      patchTangent: this.patchTangent,
      patchTwist: this.patchTwist,
      friction: this.friction,
      restitution: this.restitution,
    };
    if (sweepScratch[n] === undefined) {
      sweepScratch[n] = { manifold: createManifold(n, this.pointCapacity), pose: createPose(n), numbers: new Float64Array(4) };
    }
    this.ensureSlots(16);
  }

  private ensureSlots(need: number): void {
    if (need <= this.capacity) return;
    let cap = Math.max(16, this.capacity);
    while (cap < need) cap *= 2;
    const P = this.pointCapacity;
    this.keys = growFloat64(this.keys, cap);
    this.friction = growFloat64(this.friction, cap);
    this.restitution = growFloat64(this.restitution, cap);
    this.normalImpulse = growFloat64(this.normalImpulse, cap * P);
    this.approachSpeed = growFloat64(this.approachSpeed, cap * P);
    this.patchTangent = growFloat64(this.patchTangent, cap * this.n);
    this.patchTwist = growFloat64(this.patchTwist, cap * this.k);
    const flags = new Uint8Array(cap);
    flags.set(this.flags.subarray(0, Math.min(this.flags.length, cap)));
    this.flags = flags;
    this.freeSlots = growInt32(this.freeSlots, cap);
    this.order = growInt32(this.order, cap);
    this.orderNext = growInt32(this.orderNext, cap);
    this.partA = growInt32(this.partA, cap);
    this.partB = growInt32(this.partB, cap);
    this.active = growInt32(this.active, cap);
    const links = this.links;
    links.next = growInt32(links.next, 2 * cap);
    links.prev = growInt32(links.prev, 2 * cap);
    links.mark = growInt32(links.mark, cap);
    // The new slots' manifolds are views of one buffer, each slot's numbers side by side (normal,
    // separations, points, ids): the solver's prepare and the narrowphase then read a slot from
    // adjacent cache lines, where arrays of their own lay scattered, a cache miss each. (Filled
    // upwards: the slot lists stay packed arrays.)
    const stride = manifoldBytes(this.n, P);
    const slab = new ArrayBuffer((cap - this.capacity) * stride);
    for (let s = this.capacity, at = 0; s < cap; s += 1, at += stride) {
      this.bodyA[s] = null;
      this.bodyB[s] = null;
      this.shapeA[s] = null;
      this.shapeB[s] = null;
      this.poseA[s] = null;
      this.poseB[s] = null;
      this.manifolds[s] = manifoldIn(this.n, P, slab, at);
    }
    // New slots are handed out lowest first.
    for (let s = cap - 1; s >= this.capacity; s -= 1) this.freeSlots[this.freeCount++] = s;
    this.cache.ensureSlots(cap);
    this.capacity = cap;
  }

  private allocSlot(): number {
    if (this.freeCount === 0) this.ensureSlots(this.capacity + 1);
    return this.freeSlots[--this.freeCount];
  }

  private freeSlot(slot: number): void {
    if (!this.links.stale) this.unlink(slot);
    this.bodyA[slot] = null;
    this.bodyB[slot] = null;
    this.shapeA[slot] = null;
    this.shapeB[slot] = null;
    this.poseA[slot] = null;
    this.poseB[slot] = null;
    this.manifolds[slot].count = 0;
    this.flags[slot] = 0;
    this.cache.forget(slot);
    this.freeSlots[this.freeCount++] = slot;
  }

  /** Puts `slot` at the head of the contact lists of its two bodies (a body outside a world has none). */
  private link(slot: number): void {
    const L = this.links;
    for (let side = 0; side < 2; side += 1) {
      const id = (side === 0 ? this.bodyA[slot]! : this.bodyB[slot]!).proxyId;
      if (id < 0) continue;
      if (id >= L.head.length) L.head = growInt32(L.head, id + 1);
      const e = 2 * slot + side;
      const first = L.head[id];
      L.next[e] = first;
      L.prev[e] = 0;
      if (first !== 0) L.prev[first - 1] = e + 1;
      L.head[id] = e + 1;
    }
  }

  /** Takes `slot` out of the contact lists of its two bodies. */
  private unlink(slot: number): void {
    const L = this.links;
    for (let side = 0; side < 2; side += 1) {
      const body = side === 0 ? this.bodyA[slot] : this.bodyB[slot];
      if (body === null || body === undefined) continue;
      const id = body.proxyId;
      if (id < 0 || id >= L.head.length) continue;
      const e = 2 * slot + side;
      const nx = L.next[e];
      const pv = L.prev[e];
      if (pv !== 0) L.next[pv - 1] = nx;
      else if (L.head[id] === e + 1) L.head[id] = nx;
      else continue; // never linked
      if (nx !== 0) L.prev[nx - 1] = pv;
      L.next[e] = 0;
      L.prev[e] = 0;
    }
  }

  /** Rebuilds the contact lists from the slots if a snapshot restore left them stale. */
  private ensureLinks(): void {
    const L = this.links;
    if (!L.stale) return;
    this.compactOrder();
    L.head.fill(0);
    L.next.fill(0);
    L.prev.fill(0);
    L.stale = false;
    for (let i = 0; i < this.count; i += 1) this.link(this.order[i]);
  }

  /** Closes the holes `removeBody` left in `order`, keeping the key order. O(count) once per batch of removals. */
  compactOrder(): void {
    if (this.orderHoles === 0) return;
    const order = this.order;
    const total = this.count + this.orderHoles;
    let o = 0;
    for (let i = 0; i < total; i += 1) {
      const slot = order[i];
      if (this.bodyA[slot] !== null) order[o++] = slot;
    }
    this.orderHoles = 0;
  }

  /**
   * Gathers the active slots (see `active`) from the contact lists of `bodies[0 .. count)` (the
   * world's awake bodies; those that do not move are skipped), sorted by key: O(their contacts ·
   * log), or one pass over `order` when most slots are active. Allocates nothing.
   */
  gatherActive(bodies: readonly Body[], count: number): void {
    this.ensureLinks();
    this.compactOrder();
    const L = this.links;
    const head = L.head;
    const next = L.next;
    const mark = L.mark;
    L.epoch = (L.epoch + 1) | 0;
    if (L.epoch === 0) {
      mark.fill(0);
      L.epoch = 1;
    }
    const epoch = L.epoch;
    const active = this.active;
    let a = 0;
    for (let b = 0; b < count; b += 1) {
      const body = bodies[b];
      if (!isMoving(body)) continue;
      const id = body.proxyId;
      if (id < 0 || id >= head.length) continue;
      for (let e = head[id]; e !== 0; e = next[e - 1]) {
        const slot = (e - 1) >> 1;
        if (mark[slot] === epoch) continue;
        mark[slot] = epoch;
        active[a++] = slot;
      }
    }
    if (a > 1 && a * (32 - Math.clz32(a)) > this.count) {
      // Most slots are active: one pass over `order` lists them in key order.
      a = 0;
      for (let i = 0; i < this.count; i += 1) {
        const slot = this.order[i];
        if (mark[slot] === epoch) active[a++] = slot;
      }
    } else sortSlotsByKey(active, a, this.keys);
    this.activeCount = a;
    this.gathered = true;
  }

  /**
   * The active slots by a pass over every slot (a set used without a world): pairs of two bodies
   * that do not move keep their manifold and touching state.
   */
  private gatherAllActive(): void {
    this.compactOrder();
    let a = 0;
    for (let i = 0; i < this.count; i += 1) {
      const slot = this.order[i];
      if (isMoving(this.bodyA[slot]!) || isMoving(this.bodyB[slot]!)) {
        this.active[a++] = slot;
        continue;
      }
      const f = this.flags[slot];
      this.flags[slot] =
        (f & CONTACT_TOUCHING ? CONTACT_WAS_TOUCHING : 0) |
        (f & (CONTACT_TOUCHING | CONTACT_SENSOR)) |
        (f & (CONTACT_ACTIVE | CONTACT_POINTS) ? CONTACT_POINTS : 0);
    }
    this.activeCount = a;
  }

  /**
   * @internal The active slots as the contact solver reads a set (`order` / `count` are the
   * active list; every other field is the set's own array, current as of this call).
   */
  solverContacts(): ContactSet {
    const v = this.solverSet;
    v.order = this.active;
    v.count = this.activeCount;
    v.flags = this.flags;
    v.manifolds = this.manifolds;
    v.bodyA = this.bodyA;
    v.bodyB = this.bodyB;
    v.normalImpulse = this.normalImpulse;
    v.approachSpeed = this.approachSpeed;
    v.patchTangent = this.patchTangent;
    v.patchTwist = this.patchTwist;
    v.friction = this.friction;
    v.restitution = this.restitution;
    return v as unknown as ContactSet;
  }

  /**
   * Merges the broadphase's changes into the set: `removed` and `added` are flat sorted pair
   * lists [a0, b0, a1, b1, …] of proxy ids (a < b). `bodyOfProxy` maps a proxy id to its body.
   * A pair of two bodies that cannot push each other (neither dynamic) gets no slot. Removing a
   * pair without a slot is a no-op; removing a touching pair records an end event.
   */
  applyPairChanges(
    removed: Int32Array,
    removedCount: number,
    added: Int32Array,
    addedCount: number,
    bodyOfProxy: readonly (Body | null)[],
    events: ContactEvents,
  ): void {
    if (removedCount === 0 && addedCount === 0) return;
    this.compactOrder();
    this.ensureSlots(this.count + addedCount);
    const out = this.orderNext;
    const order = this.order;
    const keys = this.keys;
    let o = 0;
    let i = 0;
    let r = 0;
    let a = 0;
    // Three sorted streams: live slots, removals, additions.
    while (i < this.count || a < addedCount) {
      const liveKey = i < this.count ? keys[order[i]] : Infinity;
      const addKey = a < addedCount ? added[2 * a] * PAIR_KEY_SCALE + added[2 * a + 1] : Infinity;
      if (liveKey <= addKey) {
        // Skip removals below this key, then drop the live slot if it is removed.
        while (r < removedCount && removed[2 * r] * PAIR_KEY_SCALE + removed[2 * r + 1] < liveKey) r += 1;
        const slot = order[i];
        i += 1;
        if (r < removedCount && removed[2 * r] * PAIR_KEY_SCALE + removed[2 * r + 1] === liveKey) {
          r += 1;
          if (this.flags[slot] & CONTACT_TOUCHING)
            events.pushEnd(this.bodyA[slot]!, this.bodyB[slot]!, this.partA[slot]!, this.partB[slot]!);
          this.freeSlot(slot);
          continue;
        }
        if (liveKey === addKey) a += 1; // already live (cannot happen with a consistent broadphase)
        out[o++] = slot;
      } else {
        const pa = added[2 * a];
        const pb = added[2 * a + 1];
        a += 1;
        const A = bodyOfProxy[pa];
        const B = bodyOfProxy[pb];
        if (A === B) continue; // two parts of one compound body never pair
        if (!A || !B || (A.motion !== MOTION_DYNAMIC && B.motion !== MOTION_DYNAMIC)) continue;
        const slot = this.allocSlot();
        keys[slot] = addKey;
        this.bodyA[slot] = A;
        this.bodyB[slot] = B;
        this.setSlotProxies(slot, pa, pb);
        this.manifolds[slot].count = 0;
        this.flags[slot] = 0;
        this.normalImpulse.fill(0, slot * this.pointCapacity, (slot + 1) * this.pointCapacity);
        this.approachSpeed.fill(0, slot * this.pointCapacity, (slot + 1) * this.pointCapacity);
        this.clearPatch(slot);
        this.mixMaterial(slot, A, B);
        if (!this.links.stale) this.link(slot);
        out[o++] = slot;
      }
    }
    this.orderNext = order;
    this.order = out;
    this.count = o;
  }

  /**
   * @internal Gives `slot` the shapes, poses and part indices of proxies pa (A) and pb (B) from
   * the world's proxy tables.
   */
  setSlotProxies(slot: number, pa: number, pb: number): void {
    const t = this.proxies;
    this.shapeA[slot] = t.shape[pa]!;
    this.shapeB[slot] = t.shape[pb]!;
    this.poseA[slot] = t.pose[pa]!;
    this.poseB[slot] = t.pose[pb]!;
    this.partA[slot] = t.part[pa]!;
    this.partB[slot] = t.part[pb]!;
  }

  /** Friction and restitution of a pair: geometric mean of friction, the larger restitution (Box2D's rules). */
  private mixMaterial(slot: number, A: Body, B: Body): void {
    this.friction[slot] = Math.sqrt(A.material.friction * B.material.friction);
    this.restitution[slot] = Math.max(A.material.restitution, B.material.restitution);
  }

  /** Mixes the material of every pair of `body` again (its friction or restitution changed). */
  refreshMaterial(body: Body): void {
    this.compactOrder();
    for (let i = 0; i < this.count; i += 1) {
      const slot = this.order[i]!;
      const A = this.bodyA[slot]!;
      const B = this.bodyB[slot]!;
      if (A === body || B === body) this.mixMaterial(slot, A, B);
    }
  }

  /**
   * Calls `visit(other, slot)` for every touching, non-sensor contact of `body` (O(its contacts)):
   * the links of an island, for waking it.
   */
  forEachTouching(body: Body, visit: (other: Body, slot: number) => void): void {
    this.ensureLinks();
    const L = this.links;
    const id = body.proxyId;
    if (id < 0 || id >= L.head.length) return;
    for (let e = L.head[id]; e !== 0; e = L.next[e - 1]) {
      const slot = (e - 1) >> 1;
      if ((this.flags[slot] & (CONTACT_TOUCHING | CONTACT_SENSOR)) !== CONTACT_TOUCHING) continue;
      visit(this.bodyA[slot] === body ? this.bodyB[slot]! : this.bodyA[slot]!, slot);
    }
  }

  /**
   * Removes every contact of `body` (when it leaves the world). Not for the step. Each pair that
   * was touching records an end event for the next step, and the other body wakes: what rested
   * on the body must fall (its island wakes with it). O(contacts of the body): the holes it leaves
   * in `order` are closed by the next pass over the set (compactOrder).
   */
  removeBody(body: Body, events: ContactEvents): void {
    this.ensureLinks();
    const L = this.links;
    const id = body.proxyId;
    if (id < 0 || id >= L.head.length) return;
    let e = L.head[id];
    while (e !== 0) {
      const slot = (e - 1) >> 1;
      e = L.next[e - 1];
      const A = this.bodyA[slot]!;
      const B = this.bodyB[slot]!;
      const touching = (this.flags[slot] & CONTACT_TOUCHING) !== 0;
      if (touching) events.pushEndLater(A, B, this.partA[slot]!, this.partB[slot]!);
      this.freeSlot(slot);
      this.count -= 1;
      this.orderHoles += 1;
      // (after the slot is freed: waking walks the other body's contacts)
      if (touching) (A === body ? B : A).wake();
    }
  }

  /** @internal The manifold cache of the slots, for world snapshots (snapshot/contacts.ts). */
  get manifoldCache(): ManifoldCache {
    return this.cache;
  }

  /**
   * @internal For restoring a snapshot into an empty set: makes `count` live slots, handed out
   * as a new set hands them out (0, 1, 2, …), listed in `order` in that order. The caller then
   * fills every per-slot field.
   */
  takeSlots(count: number): void {
    if (this.count !== 0) throw new Error('ContactSet.takeSlots: the set must be empty');
    this.compactOrder();
    this.links.stale = true;
    this.ensureSlots(count);
    for (let i = 0; i < count; i += 1) this.order[i] = this.allocSlot();
    this.count = count;
  }

  /**
   * Whether the speculative manifold `m` of A and B (every point apart) can close in this
   * sub-step. A manifold with a point that touches, or whose gap the relative velocity along its
   * normal does not close within the sub-step, is left as it is (true): its rows push only if the
   * solve makes the bodies approach. Otherwise B is swept along the relative velocity v_B − v_A
   * (A held still) by Newton steps on the gap d(t), which for convex shapes under a translation is
   * convex in t, so the steps t += d / (−d′) approach the first contact from below: the pair meets
   * when the gap falls below SWEEP_TOLERANCE plus the distance the rotations can move the surfaces
   * in a sub-step, and does not when the gap stops closing or the time passes the sub-step. Only
   * spheres and boxes are swept (a torus is not convex); other pairs, and a sweep that has not
   * settled, keep the manifold. The sub-step h is read from the reaches, h·(|v| + |ω|·ρ).
   */
  private meetsInSubStep(m: Manifold, A: Body, B: Body, slot: number, reach: Float64Array, scratch: NarrowphaseScratch): boolean {
    // The slot's shapes (a compound body's part): the bodies' speeds and bounding radii still
    // bound how far any point of the part moves, so the sweep below holds for parts too.
    const sA = this.shapeA[slot]!;
    const sB = this.shapeB[slot]!;
    const kA = sA.kind;
    const kB = sB.kind;
    if ((kA !== 'sphere' && kA !== 'box') || (kB !== 'sphere' && kB !== 'box')) return true;
    const n = this.n;
    let gap = Infinity;
    for (let p = 0; p < m.count; p += 1) if (m.separations[p] < gap) gap = m.separations[p];
    if (!(gap > 0)) return true;
    // h from the reach of the faster body: reach = h·(|v| + |ω|·ρ).
    const sw = sweepScratch[n]!;
    const num = sw.numbers;
    num[0] = 0; // speed + spin·ρ of A, then of B
    num[1] = 0;
    let rot = 0;
    for (let side = 0; side < 2; side += 1) {
      const body = side === 0 ? A : B;
      if (body.motion === MOTION_STATIC) continue;
      let v2 = 0;
      for (let c = 0; c < n; c += 1) v2 += body.v[c] * body.v[c];
      let w2 = 0;
      const w = body.w;
      for (let c = 0; c < w.length; c += 1) w2 += w[c] * w[c];
      const spin = Math.sqrt(w2) * body.boundingRadius;
      num[side] = Math.sqrt(v2) + spin;
      rot += spin;
    }
    const useB = num[1] * reach[A.worldIndex] >= num[0] * reach[B.worldIndex] ? 1 : 0;
    const rate = num[useB];
    const r = reach[useB === 1 ? B.worldIndex : A.worldIndex];
    if (!(rate > 0) || !(r > 0)) return true;
    const h = r / rate;
    const tolerance = SWEEP_TOLERANCE + h * rot;
    if (gap <= tolerance) return true;
    // The relative velocity, and whether the linear view closes the gap in the sub-step at all.
    const vA = A.v;
    const vB = B.v;
    let closing = 0;
    for (let c = 0; c < n; c += 1) closing -= m.normal[c] * (vB[c] - vA[c]);
    if (gap - h * closing > tolerance) return true;
    const pose = sw.pose;
    const poseB = this.poseB[slot]!;
    pose.M.set(poseB.M);
    const out = sw.manifold;
    let t = 0;
    let d = gap;
    let rateNow = closing;
    for (let it = 0; it < SWEEP_STEPS; it += 1) {
      if (d <= tolerance) return true;
      if (!(rateNow > 0)) return false;
      t += d / rateNow;
      if (t > h) return false;
      for (let c = 0; c < n; c += 1) pose.x[c] = poseB.x[c] + t * (vB[c] - vA[c]);
      // (The narrowphase margin is still the pair's, set for the manifold being checked.)
      collideScratch(out, n, sA as never, this.poseA[slot]!, sB as never, pose, scratch);
      if (out.count === 0) return false; // farther apart than the margin: moving away
      d = Infinity;
      for (let p = 0; p < out.count; p += 1) if (out.separations[p] < d) d = out.separations[p];
      rateNow = 0;
      for (let c = 0; c < n; c += 1) rateNow -= out.normal[c] * (vB[c] - vA[c]);
    }
    return true;
  }

  /** Forgets the friction patch of `slot` (a new contact, or one whose points all changed). */
  private clearPatch(slot: number): void {
    this.patchTangent.fill(0, slot * this.n, (slot + 1) * this.n);
    this.patchTwist.fill(0, slot * this.k, (slot + 1) * this.k);
  }

  /** Gives point index `ni` (slot·P + p) the impulses of old point `q`, which is then taken. */
  private carryImpulses(ni: number, q: number): void {
    this.oldTaken[q] = 1;
    this.normalImpulse[ni] = this.oldNormal[q];
    this.approachSpeed[ni] = this.oldApproach[q];
  }

  /**
   * Refreshes the manifold of every contact with a moving body (awake dynamic or kinematic) and
   * carries the impulses of points whose feature id survived; a point with a new id takes those of
   * the nearest unclaimed old point within `params.contactMargin`. `params.contactMargin` is the margin;
   * `reach` adds the distance each body can close in one sub-step (speculative contacts), per
   * world index; `tightMin` / `tightMax` are the broadphase's tight boxes per proxy id. Sets CONTACT_ACTIVE (on slots whose manifold holds
   * points) and CONTACT_TOUCHING, and keeps the previous touching state in CONTACT_WAS_TOUCHING.
   * Allocates nothing.
   */
  updateManifolds(
    params: Readonly<Params>,
    reach: Float64Array,
    scratch: NarrowphaseScratch,
    tightMin: Float64Array,
    tightMax: Float64Array,
    filter: PairFilter | null,
  ): void {
    const margin = params.contactMargin;
    const n = this.n;
    const P = this.pointCapacity;
    const oldIds = this.oldIds;
    const oldNormal = this.oldNormal;
    const oldApproach = this.oldApproach;
    const oldPoints = this.oldPoints;
    const oldTaken = this.oldTaken;
    const reuseTolerance = params.manifoldReuseTolerance;
    const reuseNumbers = this.reuseNumbers;
    reuseNumbers[0] = reuseTolerance;
    if (!this.gathered) this.gatherAllActive();
    this.gathered = false;
    for (let i = 0; i < this.activeCount; i += 1) {
      const slot = this.active[i];
      const A = this.bodyA[slot]!;
      const B = this.bodyB[slot]!;
      // The shapes and poses of the slot's two proxies: the bodies', or parts of compounds.
      const sA = this.shapeA[slot]!;
      const sB = this.shapeB[slot]!;
      const pA = this.poseA[slot]!;
      const pB = this.poseB[slot]!;
      let flags = this.flags[slot] & CONTACT_TOUCHING ? CONTACT_WAS_TOUCHING : 0;
      if (
        (A.jointPeers !== null && A.jointPeers.indexOf(B) >= 0) ||
        (A.groupBits & B.maskBits) === 0 ||
        (B.groupBits & A.maskBits) === 0 ||
        (A.sensorFlag && B.sensorFlag) ||
        (filter !== null && !filter(A, B))
      ) {
        // A joint with collideConnected false holds the two, their groups and masks keep them
        // apart, both are sensors, or the world's pair filter refuses them: no contact.
        this.manifolds[slot].count = 0;
        this.cache.forget(slot);
        this.flags[slot] = flags;
        continue;
      }
      const m = this.manifolds[slot];
      const pairMargin = margin + reach[A.worldIndex] + reach[B.worldIndex];
      // The broadphase pairs fattened boxes; most such pairs in a pile are farther apart than the
      // margin. Their tight boxes (already grown by the reaches) then miss each other by more
      // than `margin` on some axis, and the narrowphase is skipped.
      if (sA.kind !== 'halfspace' && sB.kind !== 'halfspace') {
        const key = this.keys[slot];
        const proxyA = Math.floor(key / PAIR_KEY_SCALE);
        const pa = proxyA * n;
        const pb = (key - proxyA * PAIR_KEY_SCALE) * n;
        let apart = false;
        for (let c = 0; c < n; c += 1) {
          if (tightMin[pa + c] - tightMax[pb + c] > margin || tightMin[pb + c] - tightMax[pa + c] > margin) {
            apart = true;
            break;
          }
        }
        if (apart) {
          if (this.flags[slot] & (CONTACT_ACTIVE | CONTACT_SENSOR | CONTACT_POINTS)) m.count = 0;
          this.cache.forget(slot);
          // Not CONTACT_ACTIVE: no points, so the solver's prepare skips the slot without
          // reading its manifold (most slots of a pile: a cache miss each).
          this.flags[slot] = flags;
          continue;
        }
      }
      // Polytope pairs (box–box, convex mesh–box, convex mesh–mesh): reuse the manifold while the
      // two have hardly moved relative to each other (manifold-cache.ts); its points, ids and
      // impulses stay where they are.
      const sensor = A.sensorFlag || B.sensorFlag;
      const reusable =
        !sensor && reuseTolerance > 0 && (sA.kind === 'box' || sA.kind === 'mesh') && (sB.kind === 'box' || sB.kind === 'mesh');
      if (reusable) {
        // ρ_B: the body's bounding radius, kept since it was built (for a compound's part, the
        // whole body's: larger than the part's own, so the check errs toward a fresh manifold)
        reuseNumbers[1] = B.boundingRadius;
        reuseNumbers[2] = A.boundingRadius;
        reuseNumbers[3] = pairMargin;
        const cache = this.cache;
        const cached = cache.check(slot, pA, pB, reuseNumbers);
        if (cached === CACHE_REUSE) {
          cache.reuse(slot, m, pA, pB);
          let touching = false;
          for (let p = 0; p < m.count; p += 1) if (m.separations[p] < margin) touching = true;
          this.flags[slot] = flags | (m.count > 0 ? CONTACT_ACTIVE : 0) | (touching ? CONTACT_TOUCHING : 0);
          continue;
        }
        if (cached === CACHE_APART) {
          // Two boxes still apart by the separation the narrowphase last found (most near pairs
          // of a resting pile): it would give the same empty manifold; the rest is what the
          // narrowphase path does with one (m.count is 0 since).
          this.clearPatch(slot);
          this.flags[slot] = flags;
          continue;
        }
      }
      // The impulses of the old points, to be matched by id once the narrowphase has run (only
      // here: a pair found apart or a reused manifold needs none).
      const oldCount = m.count;
      const ni = slot * P;
      for (let p = 0; p < oldCount; p += 1) {
        oldIds[p] = m.ids[p];
        oldNormal[p] = this.normalImpulse[ni + p];
        oldApproach[p] = this.approachSpeed[ni + p];
        for (let c = 0; c < n; c += 1) oldPoints[p * n + c] = m.points[p * n + c];
      }
      scratch.scalars[NARROWPHASE_MARGIN] = pairMargin; // through the scratch: no boxed double
      // (a collider other than the box–box tests leaves it so: no separation kept)
      scratch.sat.kind = SAT_EDGE;
      collideScratch(m, n, sA as never, pA, sB as never, pB, scratch);
      // A pose at the edge of overflow can give a manifold of NaN: drop it rather than let it
      // carry non-finite impulses into the other body (the world then names the culprit).
      let finite = 0;
      for (let c = 0; c < n; c += 1) finite += m.normal[c] * 0;
      for (let p = 0; p < m.count; p += 1) finite += m.separations[p] * 0 + m.points[p * n] * 0;
      if (finite !== 0) m.count = 0;
      // (Not reusable, e.g. the tolerance set to 0 for a while: forget, so that a later reuse
      // never pairs this manifold's ids with points cached before it.)
      if (reusable) {
        if (m.count === 0 && sA.kind === 'box' && sB.kind === 'box') this.cache.storeApart(slot, scratch.sat);
        else this.cache.store(slot, m, pA, pB);
      } else this.cache.forget(slot);
      if (sensor) {
        // A sensor's slot tells overlap alone: no impulses, no friction patch, no sweep.
        let overlap = false;
        for (let p = 0; p < m.count; p += 1) {
          if (m.separations[p] < 0) overlap = true;
          this.normalImpulse[ni + p] = 0;
          this.approachSpeed[ni + p] = 0;
        }
        this.clearPatch(slot);
        this.flags[slot] = flags | CONTACT_SENSOR | (overlap ? CONTACT_TOUCHING : 0);
        continue;
      }
      // A speculative manifold whose gap the velocities would close only along its normal (the
      // row's linear view) but that the bodies never reach in this sub-step is a ghost: it would
      // push a body flying past an edge. Swept, it is dropped (docs/solver.md, Speculative contacts).
      if (
        m.count > 0 &&
        sA.kind !== 'halfspace' &&
        sB.kind !== 'halfspace' &&
        !this.meetsInSubStep(m, A, B, slot, reach, scratch)
      ) {
        m.count = 0;
        if (reusable) this.cache.forget(slot);
      }
      let touching = false;
      oldTaken.fill(0, 0, oldCount);
      const newMatched = this.newMatched;
      let unmatched = 0;
      for (let p = 0; p < m.count; p += 1) {
        if (m.separations[p] < margin) touching = true;
        const id = m.ids[p];
        let q = 0;
        while (q < oldCount && oldIds[q] !== id) q += 1;
        newMatched[p] = q < oldCount ? 1 : 0;
        if (q < oldCount) this.carryImpulses(ni + p, q);
        else unmatched += 1;
      }
      if (unmatched > 0) {
        // A point whose id is new takes the impulses of the nearest unclaimed old point within
        // the margin: where two edges coincide (boxes flush side by side, as in a pyramid) the
        // same corner of the contact region is named by one feature pair or another from one
        // sub-step to the next, and without this its load would restart from zero.
        const reach2 = margin * margin;
        const pts = m.points;
        for (let p = 0; p < m.count; p += 1) {
          if (newMatched[p]) continue;
          let best = -1;
          let bestD2 = reach2;
          for (let q = 0; q < oldCount; q += 1) {
            if (oldTaken[q]) continue;
            let d2 = 0;
            for (let c = 0; c < n; c += 1) {
              const dc = pts[p * n + c] - oldPoints[q * n + c];
              d2 += dc * dc;
            }
            if (d2 <= bestD2) {
              bestD2 = d2;
              best = q;
            }
          }
          if (best >= 0) this.carryImpulses(ni + p, best);
          else {
            this.normalImpulse[ni + p] = 0;
            this.approachSpeed[ni + p] = 0;
          }
        }
      }
      // The friction patch belongs to the pair, not to a point: it stays while any point carried
      // over, and starts from zero when none did (a new contact, or a jump to another face).
      let carried = false;
      for (let q = 0; q < oldCount; q += 1) if (oldTaken[q]) carried = true;
      if (!carried) this.clearPatch(slot);
      if (m.count > 0) flags |= CONTACT_ACTIVE;
      if (touching) flags |= CONTACT_TOUCHING;
      this.flags[slot] = flags;
    }
  }
}
