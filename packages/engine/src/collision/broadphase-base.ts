/**
 * What every broadphase shares: proxy storage, fattening, moved/sleep/static flags, half-spaces
 * kept aside, and the sorted pair set with its allocation-free update. A subclass supplies the
 * box structure (the candidate search, box queries and ray walks).
 */
import type { Broadphase, BroadphaseOptions, BroadphaseStats } from './broadphase.js';
import { DEFAULT_BROADPHASE_MARGIN } from './broadphase-constants.js';
import { sortKeys } from './broadphase-sort.js';
import { checkDimension, checkDirection, checkFiniteArray, checkNumber } from './query-checks.js';

/** Proxy flag bit: the id is in use. */
export const ALIVE = 1;
/** Proxy flag bit: the proxy never moves by itself (static body or half-space). */
export const STATIC = 2;
/** Proxy flag bit: the proxy's body is awake. */
export const AWAKE = 4;
/** Proxy flag bit: the proxy is a half-space, kept outside the box structure. */
export const HALFSPACE = 8;
/** Proxy flag bit: the proxy's pairs must be recomputed at the next update. */
export const MOVED = 16;

/** Pair keys are a·2^26 + b in a double, exact for ids below 2^26. */
const KEY_SCALE = 67108864;
const ID_LIMIT = KEY_SCALE;

/**
 * The shared part of every broadphase (see `Broadphase` for the contract). Subclasses provide the
 * box structure through the protected hooks; everything public here validates its arguments.
 */
/** How many moves ahead a fattened box reaches along the last move (Box2D v2 uses 4). */
const PREDICTION = 4;

/**
 * @internal Everything that decides a broadphase's next updates, for world snapshots
 * (snapshot/broadphase.ts): the proxy arrays up to `highWater` (boxes n numbers per id), the
 * pending moved list, the half-space list, the free-id stack and the sorted pair keys, in their
 * order. The box structure (the tree) is not part of it: it is rebuilt from the fat boxes, and
 * the pairs it finds are sorted before use, so its shape never shows in the results.
 */
export interface BroadphaseState {
  readonly highWater: number;
  readonly liveCount: number;
  readonly flags: Uint8Array;
  readonly tightMin: Float64Array;
  readonly tightMax: Float64Array;
  readonly fatMin: Float64Array;
  readonly fatMax: Float64Array;
  readonly planeNormal: Float64Array;
  readonly planeOffset: Float64Array;
  readonly moved: Int32Array;
  readonly halfSpaces: Int32Array;
  readonly freeIds: Int32Array;
  readonly keys: Float64Array;
}

export abstract class BroadphaseBase implements Broadphase {
  readonly n: number;
  readonly margin: number;
  pairs: Int32Array;
  pairCount = 0;
  addedPairs: Int32Array;
  addedCount = 0;
  removedPairs: Int32Array;
  removedCount = 0;
  readonly stats: BroadphaseStats = { moved: 0, queries: 0, nodesVisited: 0, candidates: 0, pairs: 0 };

  /** Per-id storage; boxes are flat, id `i` at [i*n, i*n + n). */
  protected capacity: number;
  protected flags: Uint8Array;
  /** @internal Tight boxes per proxy id (n numbers each), as last given; read by the contact set. */
  tightMin: Float64Array;
  /** @internal See tightMin. */
  tightMax: Float64Array;
  protected fatMin: Float64Array;
  protected fatMax: Float64Array;
  /** Half-space planes (unit normal, offset), stored at the id's slot. */
  protected planeNormal: Float64Array;
  protected planeOffset: Float64Array;
  /** Ids ever handed out are < highWater. */
  protected highWater = 0;
  protected moved: Int32Array;
  protected movedCount = 0;
  /**
   * The reported pairs may differ from the last update's though no proxy moved (a proxy woke or
   * fell asleep, or a restore): the next update rewrites them. Derived, not state.
   */
  private reportStale = true;
  protected halfSpaces: Int32Array;
  protected halfSpaceCount = 0;

  private freeIds: Int32Array;
  private freeCount = 0;
  private liveCount = 0;
  private keys: Float64Array;
  private keyCount = 0;
  private keysNext: Float64Array;
  private cand: Float64Array;
  private candCount = 0;
  private dropped: Float64Array;
  private droppedCount = 0;
  /** Scratch for queries: a box and a unit direction. */
  protected readonly qMin: Float64Array;
  protected readonly qMax: Float64Array;
  protected readonly rayO: Float64Array;
  protected readonly rayD: Float64Array;
  /** Scratch of moveProxy: the move of the box per axis. */
  private readonly shift: Float64Array;

  constructor(n: number, options: BroadphaseOptions) {
    checkDimension(n);
    if (options === null || typeof options !== 'object') {
      throw new TypeError('options must be an object');
    }
    const margin = options.margin ?? DEFAULT_BROADPHASE_MARGIN;
    checkNumber(margin, 'options.margin', 0);
    const cap = options.initialCapacity ?? 64;
    if (!Number.isInteger(cap) || cap < 1) {
      throw new RangeError(`options.initialCapacity must be a positive integer, got ${cap}`);
    }
    this.n = n;
    this.margin = margin;
    this.capacity = cap;
    this.flags = new Uint8Array(cap);
    this.tightMin = new Float64Array(cap * n);
    this.tightMax = new Float64Array(cap * n);
    this.fatMin = new Float64Array(cap * n);
    this.fatMax = new Float64Array(cap * n);
    this.planeNormal = new Float64Array(cap * n);
    this.planeOffset = new Float64Array(cap);
    this.freeIds = new Int32Array(cap);
    this.moved = new Int32Array(cap);
    this.halfSpaces = new Int32Array(8);
    this.keys = new Float64Array(cap * 2);
    this.keysNext = new Float64Array(cap * 2);
    this.cand = new Float64Array(cap * 2);
    this.dropped = new Float64Array(cap * 2);
    this.pairs = new Int32Array(cap * 4);
    this.addedPairs = new Int32Array(cap * 4);
    this.removedPairs = new Int32Array(cap * 4);
    this.qMin = new Float64Array(n);
    this.qMax = new Float64Array(n);
    this.rayO = new Float64Array(n);
    this.rayD = new Float64Array(n);
    this.shift = new Float64Array(n);
  }

  // ---- the structure a subclass supplies ----

  /** True if pairs of proxies that did not move stay valid (the tree); false rebuilds all (SAP). */
  protected abstract readonly incremental: boolean;
  /** A box proxy was created (its fat box is set). */
  protected abstract onInsert(id: number): void;
  /** A box proxy is being destroyed. */
  protected abstract onRemove(id: number): void;
  /** A box proxy's fat box changed. */
  protected abstract onFatChanged(id: number): void;
  /** The per-id arrays grew to `capacity`. */
  protected abstract onCapacity(capacity: number): void;
  /** Adds the box–box candidate pairs of this update through {@link addCandidate}. */
  protected abstract collectBoxCandidates(): void;
  /**
   * Calls visit(id) for box proxies whose fat box overlaps [qMin, qMax]; false stops. Returns
   * false if stopped. (The ray walk over the fat boxes is `castFat` of broadphase-queries.ts.)
   */
  protected abstract visitFat(visit: (id: number) => boolean): boolean;

  // ---- proxies ----

  get proxyCount(): number {
    return this.liveCount;
  }

  get idBound(): number {
    return this.highWater;
  }

  createProxy(min: ArrayLike<number>, max: ArrayLike<number>, isStatic = false): number {
    this.checkBox(min, max, 'min', 'max');
    if (typeof isStatic !== 'boolean') throw new TypeError('isStatic must be a boolean');
    const id = this.allocateId();
    const n = this.n;
    const b = id * n;
    for (let k = 0; k < n; k += 1) {
      this.tightMin[b + k] = min[k]!;
      this.tightMax[b + k] = max[k]!;
    }
    this.fatten(id);
    this.flags[id] = ALIVE | AWAKE | (isStatic ? STATIC : 0);
    this.onInsert(id);
    this.markMoved(id);
    return id;
  }

  createHalfSpaceProxy(normal: ArrayLike<number>, offset: number): number {
    checkDirection(normal, this.n, 'normal');
    checkNumber(offset, 'offset');
    const id = this.allocateId();
    this.setPlane(id, normal, offset);
    this.flags[id] = ALIVE | AWAKE | STATIC | HALFSPACE;
    if (this.halfSpaceCount === this.halfSpaces.length) {
      this.halfSpaces = growI32(this.halfSpaces, this.halfSpaceCount);
    }
    this.halfSpaces[this.halfSpaceCount++] = id;
    this.markMoved(id);
    return id;
  }

  destroyProxy(id: number): void {
    this.checkLive(id, 'id');
    const f = this.flags[id]!;
    if (f & HALFSPACE) {
      for (let i = 0; i < this.halfSpaceCount; i += 1) {
        if (this.halfSpaces[i] === id) {
          this.halfSpaces[i] = this.halfSpaces[--this.halfSpaceCount]!;
          break;
        }
      }
    } else {
      this.onRemove(id);
    }
    this.markMoved(id);
    // Dead but still MOVED: the next update drops its pairs, then frees the id.
    this.flags[id] = MOVED;
    this.liveCount -= 1;
  }

  moveProxy(id: number, min: ArrayLike<number>, max: ArrayLike<number>): boolean {
    this.checkBoxProxy(id);
    this.checkBox(min, max, 'min', 'max');
    const n = this.n;
    const b = id * n;
    let inside = true;
    const shift = this.shift;
    for (let k = 0; k < n; k += 1) {
      const lo = min[k]!;
      const hi = max[k]!;
      // How far the box moved along axis k since the last call (twice the centre's shift).
      shift[k] = lo + hi - this.tightMin[b + k]! - this.tightMax[b + k]!;
      this.tightMin[b + k] = lo;
      this.tightMax[b + k] = hi;
      if (lo < this.fatMin[b + k]! || hi > this.fatMax[b + k]!) inside = false;
    }
    if (inside) return false;
    this.fatten(id);
    // Predictive fattening (as Box2D v2): along an axis on which the box moved farther than half
    // the margin in one call, the fat box also reaches PREDICTION such moves ahead, so a moving
    // body leaves it every few steps instead of every one or two (the links of a whipping chain,
    // a few cm a step, left their boxes 3.2 times a step of 10 with the whole margin as the bar,
    // 2.0 with half). Smaller moves (a resting pile's jitter) keep the plain margin: prediction
    // there would only add pairs.
    const bar = 0.5 * this.margin;
    for (let k = 0; k < n; k += 1) {
      const move = 0.5 * shift[k]!;
      if (move < -bar) this.fatMin[b + k] = this.fatMin[b + k]! + PREDICTION * move;
      else if (move > bar) this.fatMax[b + k] = this.fatMax[b + k]! + PREDICTION * move;
    }
    this.onFatChanged(id);
    this.markMoved(id);
    return true;
  }

  moveHalfSpace(id: number, normal: ArrayLike<number>, offset: number): void {
    this.checkLive(id, 'id');
    if (!(this.flags[id]! & HALFSPACE)) throw new RangeError(`id ${id} is not a half-space proxy`);
    checkDirection(normal, this.n, 'normal');
    checkNumber(offset, 'offset');
    this.setPlane(id, normal, offset);
    this.markMoved(id);
  }

  setAwake(id: number, awake: boolean): void {
    this.checkLive(id, 'id');
    if (typeof awake !== 'boolean') throw new TypeError('awake must be a boolean');
    const was = (this.flags[id]! & AWAKE) !== 0;
    if (was === awake) return;
    if (awake) this.flags[id]! |= AWAKE;
    else this.flags[id]! &= ~AWAKE;
    this.reportStale = true;
  }

  setStatic(id: number, isStatic: boolean): void {
    this.checkBoxProxy(id);
    if (typeof isStatic !== 'boolean') throw new TypeError('isStatic must be a boolean');
    const was = (this.flags[id]! & STATIC) !== 0;
    if (was === isStatic) return;
    if (isStatic) this.flags[id]! |= STATIC;
    else this.flags[id]! &= ~STATIC;
    this.markMoved(id);
  }

  // ---- the update ----

  updatePairs(): number {
    const st = this.stats;
    st.moved = this.movedCount;
    st.queries = 0;
    st.nodesVisited = 0;
    this.candCount = 0;
    this.droppedCount = 0;
    if (this.incremental && this.movedCount === 0 && !this.reportStale) {
      // Nothing moved, woke or fell asleep (a sleeping world): the pairs and the report stand.
      // O(1), where the passes below cost O(pairs).
      st.candidates = 0;
      st.pairs = this.keyCount;
      this.addedCount = 0;
      this.removedCount = 0;
      return this.pairCount;
    }
    this.reportStale = false;

    // Pairs with neither proxy moved keep their overlap status; the rest are recomputed.
    const flags = this.flags;
    const keys = this.keys;
    let kept = 0;
    for (let i = 0; i < this.keyCount; i += 1) {
      const key = keys[i]!;
      const a = Math.floor(key / KEY_SCALE);
      const b = key - a * KEY_SCALE;
      if (!this.incremental || ((flags[a]! | flags[b]!) & MOVED) !== 0) {
        this.pushDropped(keys, i);
      } else {
        keys[kept++] = key;
      }
    }

    this.collectBoxCandidates();
    this.collectHalfSpaceCandidates();
    st.candidates = this.candCount;
    sortKeys(this.cand, this.candCount);

    this.mergeInto(kept);
    this.diffChanges();
    this.writeReported();
    st.pairs = this.keyCount;

    for (let i = 0; i < this.movedCount; i += 1) {
      const id = this.moved[i]!;
      if (this.flags[id]! & ALIVE) {
        this.flags[id]! &= ~MOVED;
      } else {
        this.flags[id] = 0;
        this.freeIds[this.freeCount++] = id;
      }
    }
    this.movedCount = 0;
    return this.pairCount;
  }

  /** Adds the candidate pair (a, b), a != b, in either order. For subclasses. */
  protected addCandidate(a: number, b: number): void {
    if (this.candCount === this.cand.length) this.cand = growF64(this.cand, this.candCount);
    this.cand[this.candCount++] = a < b ? a * KEY_SCALE + b : b * KEY_SCALE + a;
  }

  /** True when the pair (a, b) is worth keeping: not both static. */
  protected pairable(a: number, b: number): boolean {
    return (this.flags[a]! & this.flags[b]! & STATIC) === 0;
  }

  /** True if the fat boxes of proxies a and b overlap (closed). */
  protected fatOverlap(a: number, b: number): boolean {
    const n = this.n;
    const ba = a * n;
    const bb = b * n;
    for (let k = 0; k < n; k += 1) {
      if (this.fatMin[ba + k]! > this.fatMax[bb + k]! || this.fatMin[bb + k]! > this.fatMax[ba + k]!) {
        return false;
      }
    }
    return true;
  }

  /** True if the box [lo, hi] of `base` in (lo, hi) reaches the solid side of half-space h. */
  protected boxReachesPlane(lo: Float64Array, hi: Float64Array, base: number, h: number): boolean {
    const n = this.n;
    const nb = h * n;
    let s = 0;
    for (let k = 0; k < n; k += 1) {
      const w = this.planeNormal[nb + k]!;
      s += w * (w > 0 ? lo[base + k]! : hi[base + k]!);
    }
    return s <= this.planeOffset[h]!;
  }

  private collectHalfSpaceCandidates(): void {
    const flags = this.flags;
    const n = this.n;
    if (this.halfSpaceCount === 0) return;
    if (!this.incremental) {
      for (let i = 0; i < this.halfSpaceCount; i += 1) {
        const h = this.halfSpaces[i]!;
        for (let id = 0; id < this.highWater; id += 1) {
          if ((flags[id]! & (ALIVE | STATIC)) !== ALIVE) continue;
          if (this.boxReachesPlane(this.fatMin, this.fatMax, id * n, h) === false) continue;
          this.addCandidate(h, id);
        }
      }
      return;
    }
    for (let i = 0; i < this.movedCount; i += 1) {
      const m = this.moved[i]!;
      const f = flags[m]!;
      if (!(f & ALIVE)) continue;
      if (f & HALFSPACE) {
        for (let id = 0; id < this.highWater; id += 1) {
          if ((flags[id]! & (ALIVE | STATIC)) !== ALIVE) continue;
          if (this.boxReachesPlane(this.fatMin, this.fatMax, id * n, m)) this.addCandidate(m, id);
        }
      } else if (!(f & STATIC)) {
        for (let j = 0; j < this.halfSpaceCount; j += 1) {
          const h = this.halfSpaces[j]!;
          // A moved half-space finds this proxy itself (above).
          if (flags[h]! & MOVED) continue;
          if (this.boxReachesPlane(this.fatMin, this.fatMax, m * n, h)) this.addCandidate(h, m);
        }
      }
    }
  }

  /** keys[0..kept) and cand[0..candCount) are sorted and disjoint: merge them into the set. */
  private mergeInto(kept: number): void {
    const total = kept + this.candCount;
    if (total > this.keysNext.length) this.keysNext = new Float64Array(growLength(this.keysNext.length, total));
    const out = this.keysNext;
    const a = this.keys;
    const c = this.cand;
    let i = 0;
    let j = 0;
    let o = 0;
    while (i < kept && j < this.candCount) {
      if (a[i]! < c[j]!) out[o++] = a[i++]!;
      else out[o++] = c[j++]!;
    }
    while (i < kept) out[o++] = a[i++]!;
    while (j < this.candCount) out[o++] = c[j++]!;
    this.keysNext = this.keys;
    this.keys = out;
    this.keyCount = o;
    if (this.keysNext.length < this.keys.length) this.keysNext = new Float64Array(this.keys.length);
  }

  /** added = cand \ dropped, removed = dropped \ cand (both lists sorted). */
  private diffChanges(): void {
    const c = this.cand;
    const d = this.dropped;
    const nc = this.candCount;
    const nd = this.droppedCount;
    this.addedCount = 0;
    this.removedCount = 0;
    let i = 0;
    let j = 0;
    while (i < nc || j < nd) {
      if (j >= nd || (i < nc && c[i]! < d[j]!)) {
        this.addedPairs = this.pushPair(this.addedPairs, this.addedCount++, c, i++);
      } else if (i >= nc || d[j]! < c[i]!) {
        this.removedPairs = this.pushPair(this.removedPairs, this.removedCount++, d, j++);
      } else {
        i += 1;
        j += 1;
      }
    }
  }

  private writeReported(): void {
    const flags = this.flags;
    let count = 0;
    for (let i = 0; i < this.keyCount; i += 1) {
      const key = this.keys[i]!;
      const a = Math.floor(key / KEY_SCALE);
      const b = key - a * KEY_SCALE;
      // Reported when at least one side is awake and dynamic.
      if ((flags[a]! & (AWAKE | STATIC)) === AWAKE || (flags[b]! & (AWAKE | STATIC)) === AWAKE) {
        this.pairs = this.pushPair(this.pairs, count++, this.keys, i);
      }
    }
    this.pairCount = count;
  }

  /**
   * Writes the pair of key src[at] as pair `index` of buf (grown by doubling if needed). Keys are
   * passed by position, never as arguments: a double argument is boxed when a call is not inlined.
   */
  private pushPair(buf: Int32Array, index: number, src: Float64Array, at: number): Int32Array {
    const key = src[at]!;
    let out = buf;
    if (2 * index + 2 > out.length) {
      out = new Int32Array(growLength(out.length, 2 * index + 2));
      out.set(buf.subarray(0, 2 * index));
    }
    const a = Math.floor(key / KEY_SCALE);
    out[2 * index] = a;
    out[2 * index + 1] = key - a * KEY_SCALE;
    return out;
  }

  private pushDropped(src: Float64Array, at: number): void {
    if (this.droppedCount === this.dropped.length) this.dropped = growF64(this.dropped, this.droppedCount);
    this.dropped[this.droppedCount++] = src[at]!;
  }

  // ---- internals ----

  private fatten(id: number): void {
    const n = this.n;
    const b = id * n;
    const m = this.margin;
    for (let k = 0; k < n; k += 1) {
      this.fatMin[b + k] = this.tightMin[b + k]! - m;
      this.fatMax[b + k] = this.tightMax[b + k]! + m;
    }
  }

  private setPlane(id: number, normal: ArrayLike<number>, offset: number): void {
    const n = this.n;
    let s = 0;
    for (let k = 0; k < n; k += 1) s += normal[k]! * normal[k]!;
    const inv = 1 / Math.sqrt(s);
    for (let k = 0; k < n; k += 1) this.planeNormal[id * n + k] = normal[k]! * inv;
    this.planeOffset[id] = offset * inv;
  }

  protected markMoved(id: number): void {
    if (this.flags[id]! & MOVED) return;
    this.flags[id]! |= MOVED;
    if (this.movedCount === this.moved.length) this.moved = growI32(this.moved, this.movedCount);
    this.moved[this.movedCount++] = id;
  }

  private allocateId(): number {
    let id: number;
    if (this.freeCount > 0) {
      id = this.freeIds[--this.freeCount]!;
    } else {
      if (this.highWater >= ID_LIMIT) throw new RangeError(`a broadphase holds at most ${ID_LIMIT} proxies`);
      if (this.highWater === this.capacity) this.grow();
      id = this.highWater++;
    }
    this.liveCount += 1;
    return id;
  }

  private grow(): void {
    const c = this.capacity * 2;
    const n = this.n;
    this.flags = resizeU8(this.flags, c);
    this.tightMin = resizeF64(this.tightMin, c * n);
    this.tightMax = resizeF64(this.tightMax, c * n);
    this.fatMin = resizeF64(this.fatMin, c * n);
    this.fatMax = resizeF64(this.fatMax, c * n);
    this.planeNormal = resizeF64(this.planeNormal, c * n);
    this.planeOffset = resizeF64(this.planeOffset, c);
    this.freeIds = resizeI32(this.freeIds, c);
    this.capacity = c;
    this.onCapacity(c);
  }

  private checkBox(min: ArrayLike<number>, max: ArrayLike<number>, minName: string, maxName: string): void {
    const n = this.n;
    checkFiniteArray(min, n, minName);
    checkFiniteArray(max, n, maxName);
    for (let k = 0; k < n; k += 1) {
      if (min[k]! > max[k]!) {
        throw new RangeError(`${minName}[${k}] (${min[k]}) must be <= ${maxName}[${k}] (${max[k]})`);
      }
    }
  }

  protected checkLive(id: number, name: string): void {
    if (typeof id !== 'number' || !Number.isInteger(id)) throw new TypeError(`${name} must be an integer proxy id`);
    if (id < 0 || id >= this.highWater || !(this.flags[id]! & ALIVE)) {
      throw new RangeError(`${name} ${id} is not a live proxy`);
    }
  }

  private checkBoxProxy(id: number): void {
    this.checkLive(id, 'id');
    if (this.flags[id]! & HALFSPACE) throw new RangeError(`id ${id} is a half-space proxy, not a box`);
  }
}

/** A length at least `needed`, doubling from `current`. */
export function growLength(current: number, needed: number): number {
  let c = Math.max(current, 8);
  while (c < needed) c *= 2;
  return c;
}

function growI32(a: Int32Array, used: number): Int32Array {
  const b = new Int32Array(growLength(a.length, a.length + 1));
  b.set(a.subarray(0, used));
  return b;
}

function growF64(a: Float64Array, used: number): Float64Array {
  const b = new Float64Array(growLength(a.length, a.length + 1));
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

function resizeU8(a: Uint8Array, length: number): Uint8Array {
  const b = new Uint8Array(length);
  b.set(a);
  return b;
}
