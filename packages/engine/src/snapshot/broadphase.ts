/**
 * The broadphase in a snapshot: its proxy ids and everything that decides which pairs it reports
 * and in what order.
 *
 * Why all of it: the contact set lists pairs by (lower proxy id, higher proxy id), and the lower
 * id's body is body A of the contact, whose normal points from A to B; the solver visits the pairs
 * in that order. So the ids must be the same after a restore, and so must the free-id stack (the
 * id a body added later gets), the pending moved list, the half-space list and the set of pairs
 * already found. The fat boxes are the boxes as last grown, with the margin and the prediction of
 * past moves: they decide when a box counts as moved and which pairs are candidates, and cannot
 * be recomputed from the poses. The dynamic tree itself is not saved: it is rebuilt from the fat
 * boxes, and only the set of leaves a query finds matters (candidates are sorted before use).
 * Dead ids have no boxes (zeros are written back): nothing reads them before an id is reused.
 *
 * @module
 */
import type { BroadphaseBase, BroadphaseState } from '../collision/broadphase-base.js';
import { ALIVE, HALFSPACE, growLength } from '../collision/broadphase-base.js';
import { PAIR_KEY_SCALE } from '../contacts/contact-set.js';
import type { SnapshotReader } from './reader.js';
import type { SnapshotWriter } from './writer.js';

/** Writes the broadphase's state (see the module). */
export function writeBroadphase(w: SnapshotWriter, bp: BroadphaseBase): void {
  const n = bp.n;
  const s = broadphaseState(bp);
  const hw = s.highWater;
  w.f64(bp.margin);
  w.u32(hw);
  w.u32(s.liveCount);
  w.u8s(s.flags, 0, hw);
  for (let id = 0; id < hw; id += 1) {
    const f = s.flags[id]!;
    if (!(f & ALIVE)) continue;
    if (f & HALFSPACE) {
      w.f64s(s.planeNormal, id * n, n);
      w.f64(s.planeOffset[id]!);
    } else {
      w.f64s(s.tightMin, id * n, n);
      w.f64s(s.tightMax, id * n, n);
      w.f64s(s.fatMin, id * n, n);
      w.f64s(s.fatMax, id * n, n);
    }
  }
  w.u32(s.moved.length);
  w.i32s(s.moved);
  w.u32(s.halfSpaces.length);
  w.i32s(s.halfSpaces);
  w.u32(s.freeIds.length);
  w.i32s(s.freeIds);
  w.u32(s.keys.length);
  w.f64s(s.keys);
}

function readIds(r: SnapshotReader, what: string, hw: number): Int32Array {
  const ids = r.i32s(r.count(`the ${what} count`, hw, 4));
  for (let i = 0; i < ids.length; i += 1)
    if (ids[i]! < 0 || ids[i]! >= hw) r.fail(`the ${what} list holds the id ${ids[i]} outside [0, ${hw})`);
  return ids;
}

/** Reads the broadphase state written by {@link writeBroadphase} into `bp` (a fresh world's). */
export function readBroadphase(r: SnapshotReader, bp: BroadphaseBase): void {
  const n = bp.n;
  const margin = r.f64();
  if (!Object.is(margin, bp.margin)) r.fail(`the broadphase margin ${margin} differs from this build's ${bp.margin}`);
  const hw = r.count('the broadphase id bound', 1 << 26, 1);
  const liveCount = r.count('the live proxy count', hw);
  const flags = r.u8s(hw);
  const tightMin = new Float64Array(hw * n);
  const tightMax = new Float64Array(hw * n);
  const fatMin = new Float64Array(hw * n);
  const fatMax = new Float64Array(hw * n);
  const planeNormal = new Float64Array(hw * n);
  const planeOffset = new Float64Array(hw);
  let alive = 0;
  for (let id = 0; id < hw; id += 1) {
    const f = flags[id]!;
    if (!(f & ALIVE)) continue;
    alive += 1;
    if (f & HALFSPACE) {
      r.f64s(n, planeNormal, id * n);
      planeOffset[id] = r.f64();
    } else {
      r.f64s(n, tightMin, id * n);
      r.f64s(n, tightMax, id * n);
      r.f64s(n, fatMin, id * n);
      r.f64s(n, fatMax, id * n);
    }
  }
  if (alive !== liveCount) r.fail(`the broadphase has ${alive} live proxies, not the ${liveCount} it claims`);
  const moved = readIds(r, 'moved proxy', hw);
  const halfSpaces = readIds(r, 'half-space', hw);
  const freeIds = readIds(r, 'free id', hw);
  const keys = r.f64s(r.count('the broadphase pair count', 1 << 30, 8));
  for (let i = 0; i < keys.length; i += 1) {
    const key = keys[i]!;
    const a = Math.floor(key / PAIR_KEY_SCALE);
    const b = key - a * PAIR_KEY_SCALE;
    if (!(a >= 0 && a < b && b < hw) || (i > 0 && !(keys[i - 1]! < key)))
      r.fail(`the broadphase pair key ${key} is not a sorted pair of ids`);
  }
  const state: BroadphaseState = {
    highWater: hw,
    liveCount,
    flags,
    tightMin,
    tightMax,
    fatMin,
    fatMax,
    planeNormal,
    planeOffset,
    moved,
    halfSpaces,
    freeIds,
    keys,
  };
  restoreBroadphaseState(bp, state);
}

/** What the snapshot reads and writes of a broadphase (its protected and private parts). */
interface BaseParts {
  readonly n: number;
  highWater: number;
  liveCount: number;
  capacity: number;
  flags: Uint8Array;
  tightMin: Float64Array;
  tightMax: Float64Array;
  fatMin: Float64Array;
  fatMax: Float64Array;
  planeNormal: Float64Array;
  planeOffset: Float64Array;
  moved: Int32Array;
  movedCount: number;
  halfSpaces: Int32Array;
  halfSpaceCount: number;
  freeIds: Int32Array;
  freeCount: number;
  keys: Float64Array;
  keysNext: Float64Array;
  keyCount: number;
  pairCount: number;
  addedCount: number;
  removedCount: number;
  reportStale: boolean;
  onInsert(id: number): void;
  onRemove(id: number): void;
  grow(): void;
}

/** The state of `bp` that decides the next updates (views of the live parts, not copies). */
function broadphaseState(bp: BroadphaseBase): BroadphaseState {
  const b = bp as unknown as BaseParts;
  const hw = b.highWater;
  const n = b.n;
  return {
    highWater: hw,
    liveCount: b.liveCount,
    flags: b.flags.subarray(0, hw),
    tightMin: b.tightMin.subarray(0, hw * n),
    tightMax: b.tightMax.subarray(0, hw * n),
    fatMin: b.fatMin.subarray(0, hw * n),
    fatMax: b.fatMax.subarray(0, hw * n),
    planeNormal: b.planeNormal.subarray(0, hw * n),
    planeOffset: b.planeOffset.subarray(0, hw),
    moved: b.moved.subarray(0, b.movedCount),
    halfSpaces: b.halfSpaces.subarray(0, b.halfSpaceCount),
    freeIds: b.freeIds.subarray(0, b.freeCount),
    keys: b.keys.subarray(0, b.keyCount),
  };
}

/**
 * Replaces the whole state of `bp` by `s` (as {@link broadphaseState} gives it; the caller
 * checked its consistency) and rebuilds the box structure from the fat boxes. Copies.
 */
function restoreBroadphaseState(bp: BroadphaseBase, s: BroadphaseState): void {
  const b = bp as unknown as BaseParts;
  for (let id = 0; id < b.highWater; id += 1) {
    if ((b.flags[id]! & (ALIVE | HALFSPACE)) === ALIVE) b.onRemove(id);
  }
  while (b.capacity < s.highWater) b.grow();
  b.flags.fill(0);
  b.flags.set(s.flags);
  b.tightMin.set(s.tightMin);
  b.tightMax.set(s.tightMax);
  b.fatMin.set(s.fatMin);
  b.fatMax.set(s.fatMax);
  b.planeNormal.set(s.planeNormal);
  b.planeOffset.set(s.planeOffset);
  b.highWater = s.highWater;
  b.liveCount = s.liveCount;
  if (b.moved.length < s.moved.length) b.moved = new Int32Array(growLength(b.moved.length, s.moved.length));
  b.moved.set(s.moved);
  b.movedCount = s.moved.length;
  if (b.halfSpaces.length < s.halfSpaces.length)
    b.halfSpaces = new Int32Array(growLength(b.halfSpaces.length, s.halfSpaces.length));
  b.halfSpaces.set(s.halfSpaces);
  b.halfSpaceCount = s.halfSpaces.length;
  b.freeIds.set(s.freeIds);
  b.freeCount = s.freeIds.length;
  if (b.keys.length < s.keys.length) {
    b.keys = new Float64Array(growLength(b.keys.length, s.keys.length));
    b.keysNext = new Float64Array(b.keys.length);
  }
  b.keys.set(s.keys);
  b.keyCount = s.keys.length;
  b.pairCount = 0;
  b.addedCount = 0;
  b.removedCount = 0;
  b.reportStale = true;
  for (let id = 0; id < s.highWater; id += 1) {
    if ((b.flags[id]! & (ALIVE | HALFSPACE)) === ALIVE) b.onInsert(id);
  }
}
