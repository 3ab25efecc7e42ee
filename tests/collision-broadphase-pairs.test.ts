import { runInNewContext } from 'node:vm';
import { setFlagsFromString } from 'node:v8';
import { PerformanceObserver } from 'node:perf_hooks';
import { describe, expect, it } from 'vitest';
import {
  proxyBounds,
  proxyIsAlive,
  proxyIsAwake,
  proxyIsHalfSpace,
  proxyIsStatic,
  validateTree,
} from '../packages/engine/src/collision/broadphase-queries.js';
import type { BroadphaseBase } from '../packages/engine/src/collision/broadphase-base.js';
import { createBroadphase } from '../packages/engine/src/collision/broadphase.js';
import type { Broadphase, BroadphaseKind } from '../packages/engine/src/collision/broadphase.js';
import { TreeBroadphase } from '../packages/engine/src/collision/broadphase-tree.js';
import { randomArray, randomUnitVector, seeded, uniform } from './support/random.js';

const DIMS = [2, 3, 4, 5, 6];
const KINDS: BroadphaseKind[] = ['tree', 'sap'];

interface Plane {
  normal: Float64Array;
  offset: number;
}

/** What the test knows about the scene, independently of the broadphase. */
interface Scene {
  n: number;
  bp: Broadphase;
  planes: Map<number, Plane>;
  rand: () => number;
  spread: number;
}

const key = (a: number, b: number): string => (a < b ? `${a},${b}` : `${b},${a}`);

function randomBox(rand: () => number, n: number, spread: number): [Float64Array, Float64Array] {
  const c = randomArray(rand, n, -spread, spread);
  const h = randomArray(rand, n, 0.2, 1);
  return [c.map((v, k) => v - h[k]!), c.map((v, k) => v + h[k]!)];
}

function liveIds(bp: Broadphase): number[] {
  const ids: number[] = [];
  for (let id = 0; id < bp.idBound; id += 1) if (proxyIsAlive(bp as BroadphaseBase, id)) ids.push(id);
  return ids;
}

function reaches(lo: Float64Array, hi: Float64Array, p: Plane): boolean {
  let s = 0;
  for (let k = 0; k < lo.length; k += 1) s += p.normal[k]! * (p.normal[k]! > 0 ? lo[k]! : hi[k]!);
  return s <= p.offset + 1e-12;
}

function overlap(aLo: Float64Array, aHi: Float64Array, bLo: Float64Array, bHi: Float64Array): boolean {
  for (let k = 0; k < aLo.length; k += 1) if (aLo[k]! > bHi[k]! || bLo[k]! > aHi[k]!) return false;
  return true;
}

/** The brute-force pair set: every pair of live proxies, by fattened boxes (or tight ones). */
function bruteForce(s: Scene, which: 'fat' | 'tight' = 'fat'): { all: Set<string>; reported: Set<string> } {
  const { bp, n } = s;
  const ids = liveIds(bp);
  const lo = new Map<number, Float64Array>();
  const hi = new Map<number, Float64Array>();
  for (const id of ids) {
    if (proxyIsHalfSpace(bp as BroadphaseBase, id)) continue;
    const a = new Float64Array(n);
    const b = new Float64Array(n);
    if (which === 'fat') proxyBounds(bp as BroadphaseBase, id, a, b, true);
    else proxyBounds(bp as BroadphaseBase, id, a, b);
    lo.set(id, a);
    hi.set(id, b);
  }
  const active = (id: number): boolean => proxyIsAwake(bp as BroadphaseBase, id) && !proxyIsStatic(bp as BroadphaseBase, id);
  const all = new Set<string>();
  const reported = new Set<string>();
  for (let x = 0; x < ids.length; x += 1) {
    for (let y = x + 1; y < ids.length; y += 1) {
      const a = ids[x]!;
      const b = ids[y]!;
      if (proxyIsStatic(bp as BroadphaseBase, a) && proxyIsStatic(bp as BroadphaseBase, b)) continue;
      let hit: boolean;
      if (proxyIsHalfSpace(bp as BroadphaseBase, a)) hit = reaches(lo.get(b)!, hi.get(b)!, s.planes.get(a)!);
      else if (proxyIsHalfSpace(bp as BroadphaseBase, b)) hit = reaches(lo.get(a)!, hi.get(a)!, s.planes.get(b)!);
      else hit = overlap(lo.get(a)!, hi.get(a)!, lo.get(b)!, hi.get(b)!);
      if (!hit) continue;
      all.add(key(a, b));
      if (active(a) || active(b)) reported.add(key(a, b));
    }
  }
  return { all, reported };
}

function pairList(buf: Int32Array, count: number): string[] {
  const out: string[] = [];
  for (let p = 0; p < count; p += 1) out.push(`${buf[2 * p]},${buf[2 * p + 1]}`);
  return out;
}

/** Pairs must be a < b and strictly increasing in (a, b). */
function expectSorted(buf: Int32Array, count: number): void {
  for (let p = 0; p < count; p += 1) {
    expect(buf[2 * p]!).toBeLessThan(buf[2 * p + 1]!);
    if (p > 0) {
      const prev = buf[2 * p - 2]! * 1e8 + buf[2 * p - 1]!;
      expect(buf[2 * p]! * 1e8 + buf[2 * p + 1]!).toBeGreaterThan(prev);
    }
  }
}

function makeScene(kind: BroadphaseKind, n: number, seed: number, count: number): Scene {
  const rand = seeded(seed);
  const bp = createBroadphase(n, { margin: 0.1, initialCapacity: 4 }, kind);
  const spread = 0.9 * Math.pow(count, 1 / n);
  const s: Scene = { n, bp, planes: new Map(), rand, spread };
  for (let i = 0; i < count; i += 1) {
    const [lo, hi] = randomBox(rand, n, spread);
    bp.createProxy(lo, hi, rand() < 0.2);
  }
  for (let h = 0; h < 2; h += 1) addPlane(s);
  return s;
}

function addPlane(s: Scene): void {
  const normal = randomUnitVector(s.rand, s.n);
  const offset = -0.5 * s.spread;
  // A non-unit normal: the broadphase normalises it.
  const id = s.bp.createHalfSpaceProxy(
    normal.map((v) => v * 3),
    offset * 3,
  );
  s.planes.set(id, { normal, offset });
}

/** One round of random changes: small and large moves, births, deaths, sleep and static flips. */
function mutate(s: Scene): void {
  const { bp, rand, n } = s;
  const ids = liveIds(bp);
  const lo = new Float64Array(n);
  const hi = new Float64Array(n);
  for (const id of ids) {
    if (proxyIsHalfSpace(bp as BroadphaseBase, id)) {
      if (rand() < 0.1) {
        const normal = randomUnitVector(rand, n);
        const offset = uniform(rand, -s.spread, 0);
        bp.moveHalfSpace(id, normal, offset);
        s.planes.set(id, { normal, offset });
      }
      continue;
    }
    const r = rand();
    if (r < 0.3) {
      proxyBounds(bp as BroadphaseBase, id, lo, hi);
      const step = rand() < 0.5 ? 0.03 : 0.6;
      const d = randomArray(rand, n, -step, step);
      bp.moveProxy(
        id,
        lo.map((v, k) => v + d[k]!),
        hi.map((v, k) => v + d[k]!),
      );
    } else if (r < 0.33) {
      bp.destroyProxy(id);
    } else if (r < 0.4) {
      bp.setAwake(id, !proxyIsAwake(bp as BroadphaseBase, id));
    } else if (r < 0.41) {
      bp.setStatic(id, !proxyIsStatic(bp as BroadphaseBase, id));
    }
  }
  const births = Math.floor(rand() * 4);
  for (let b = 0; b < births; b += 1) {
    const [l, h] = randomBox(rand, n, s.spread);
    bp.createProxy(l, h, rand() < 0.2);
  }
  if (rand() < 0.1) addPlane(s);
  if (rand() < 0.1 && s.planes.size > 1) {
    const [first] = s.planes.keys();
    bp.destroyProxy(first!);
    s.planes.delete(first!);
  }
}

describe.each(KINDS)('%s broadphase', (kind) => {
  describe.each(DIMS)('in %iD', (n) => {
    it('reports exactly the brute-force pairs through moves, births, deaths, sleep and half-spaces', () => {
      const s = makeScene(kind, n, 1000 * n + (kind === 'tree' ? 1 : 2), 80);
      let prevAll = new Set<string>();
      let reportedTotal = 0;
      let asleepSkipped = 0;
      for (let round = 0; round < 25; round += 1) {
        if (round > 0) mutate(s);
        const count = s.bp.updatePairs();
        expect(count).toBe(s.bp.pairCount);
        expectSorted(s.bp.pairs, count);
        const brute = bruteForce(s);
        const reported = pairList(s.bp.pairs, count);
        expect(new Set(reported)).toEqual(brute.reported);
        expect(reported.length).toBe(brute.reported.size);
        // The set's changes: previous + added − removed = current.
        const added = pairList(s.bp.addedPairs, s.bp.addedCount);
        const removed = pairList(s.bp.removedPairs, s.bp.removedCount);
        expectSorted(s.bp.addedPairs, s.bp.addedCount);
        expectSorted(s.bp.removedPairs, s.bp.removedCount);
        for (const p of added) expect(prevAll.has(p)).toBe(false);
        for (const p of removed) expect(prevAll.has(p)).toBe(true);
        const next = new Set(prevAll);
        for (const p of removed) next.delete(p);
        for (const p of added) next.add(p);
        expect(next).toEqual(brute.all);
        expect(s.bp.stats.pairs).toBe(brute.all.size);
        // Fat boxes contain the tight ones: every truly overlapping pair is among them.
        for (const p of bruteForce(s, 'tight').reported) expect(brute.reported.has(p)).toBe(true);
        if (s.bp instanceof TreeBroadphase) expect(validateTree(s.bp.tree)).toBeNull();
        prevAll = brute.all;
        reportedTotal += count;
        asleepSkipped += brute.all.size - brute.reported.size;
      }
      // The scenes are busy enough to mean something.
      expect(reportedTotal).toBeGreaterThan(25 * 20);
      expect(asleepSkipped).toBeGreaterThan(0);
    });
  });

  it('is deterministic: the same scenario gives bit-identical pair arrays', () => {
    for (const n of [3, 4]) {
      const runs = [0, 1].map(() => {
        const s = makeScene(kind, n, 77, 120);
        const out: number[][] = [];
        for (let round = 0; round < 15; round += 1) {
          if (round > 0) mutate(s);
          const c = s.bp.updatePairs();
          out.push(Array.from(s.bp.pairs.subarray(0, 2 * c)));
        }
        return out;
      });
      expect(runs[0]).toEqual(runs[1]);
      expect(runs[0]!.flat().length).toBeGreaterThan(100);
    }
  });
});

describe('tree and sweep-and-prune agree pair for pair', () => {
  it.each([2, 3, 4, 5, 6])('%iD', (n) => {
    const a = makeScene('tree', n, 4242 + n, 100);
    const b = makeScene('sap', n, 4242 + n, 100);
    for (let round = 0; round < 10; round += 1) {
      if (round > 0) {
        mutate(a);
        mutate(b);
      }
      const ca = a.bp.updatePairs();
      const cb = b.bp.updatePairs();
      expect(Array.from(a.bp.pairs.subarray(0, 2 * ca))).toEqual(Array.from(b.bp.pairs.subarray(0, 2 * cb)));
    }
  });
});

describe('work follows what moved (tree)', () => {
  it.each([2, 3, 4, 5, 6])('%iD: no move → no query; one move → one query and only its pairs', (n) => {
    const s = makeScene('tree', n, 555 + n, 150);
    const bp = s.bp as TreeBroadphase;
    bp.updatePairs();
    expect(bp.stats.queries).toBe(150);
    const before = Array.from(bp.pairs.subarray(0, 2 * bp.pairCount));

    bp.updatePairs();
    expect(bp.stats.moved).toBe(0);
    expect(bp.stats.queries).toBe(0);
    expect(bp.stats.candidates).toBe(0);
    expect(bp.addedCount + bp.removedCount).toBe(0);
    expect(Array.from(bp.pairs.subarray(0, 2 * bp.pairCount))).toEqual(before);

    // Moves inside the fattened box are not moves.
    const lo = new Float64Array(n);
    const hi = new Float64Array(n);
    let dynamicId = -1;
    for (let id = 0; id < bp.idBound; id += 1) {
      if (!proxyIsHalfSpace(bp as BroadphaseBase, id) && !proxyIsStatic(bp as BroadphaseBase, id)) {
        dynamicId = id;
        break;
      }
    }
    proxyBounds(bp as BroadphaseBase, dynamicId, lo, hi);
    expect(
      bp.moveProxy(
        dynamicId,
        lo.map((v) => v + 0.05),
        hi.map((v) => v + 0.05),
      ),
    ).toBe(false);
    bp.updatePairs();
    expect(bp.stats.queries).toBe(0);

    // A jump out of it: exactly one tree query, and every pair that changed involves that proxy.
    expect(
      bp.moveProxy(
        dynamicId,
        lo.map((v) => v + 1.5),
        hi.map((v) => v + 1.5),
      ),
    ).toBe(true);
    bp.updatePairs();
    expect(bp.stats.moved).toBe(1);
    expect(bp.stats.queries).toBe(1);
    const own = [...bruteForce(s).all].filter((p) => p.split(',').map(Number).includes(dynamicId));
    expect(bp.stats.candidates).toBe(own.length);
    for (const p of [...pairList(bp.addedPairs, bp.addedCount), ...pairList(bp.removedPairs, bp.removedCount)]) {
      expect(p.split(',').map(Number)).toContain(dynamicId);
    }
    // A query visits a small part of the tree, not all of it.
    expect(bp.stats.nodesVisited).toBeLessThan(bp.tree.size / 2);
  });

  it('keeps the tree shallow: height <= 3·log2(leaves) after 2000 random reinsertions', () => {
    const s = makeScene('tree', 4, 99, 300);
    const bp = s.bp as TreeBroadphase;
    for (let round = 0; round < 10; round += 1) {
      mutate(s);
      bp.updatePairs();
    }
    const leaves = liveIds(bp).filter((id) => !proxyIsHalfSpace(bp as BroadphaseBase, id)).length;
    expect(bp.tree.treeHeight).toBeLessThanOrEqual(3 * Math.log2(leaves));
    expect(validateTree(bp.tree)).toBeNull();
  });
});

describe('sleeping and static pairs', () => {
  it('are kept but not reported, and come back when a proxy wakes', () => {
    const n = 3;
    const bp = createBroadphase(n, { margin: 0.1 });
    const box = (c: number[]): [number[], number[]] => [c.map((v) => v - 0.5), c.map((v) => v + 0.5)];
    const a = bp.createProxy(...box([0, 0, 0]));
    const b = bp.createProxy(...box([0.8, 0, 0]));
    const ground = bp.createProxy(...box([0, -0.9, 0]), true);
    const wall = bp.createProxy(...box([0.4, 0, 0.9]), true); // static–static with ground: never a pair
    const plane = bp.createHalfSpaceProxy([0, 1, 0], -0.4);
    bp.updatePairs();
    const all = (): string[] => pairList(bp.pairs, bp.pairCount);
    expect(all()).toEqual([
      `${a},${b}`,
      `${a},${ground}`,
      `${a},${wall}`,
      `${a},${plane}`,
      `${b},${ground}`,
      `${b},${wall}`,
      `${b},${plane}`,
    ]);
    bp.setAwake(a, false);
    bp.updatePairs();
    // a asleep: a–b still reported (b awake); a–static pairs are not.
    expect(all()).toEqual([`${a},${b}`, `${b},${ground}`, `${b},${wall}`, `${b},${plane}`]);
    bp.setAwake(b, false);
    bp.updatePairs();
    expect(all()).toEqual([]);
    expect(bp.stats.pairs).toBe(7);
    expect(bp.stats.queries).toBe(0);
    bp.setAwake(b, true);
    bp.updatePairs();
    expect(all()).toEqual([`${a},${b}`, `${b},${ground}`, `${b},${wall}`, `${b},${plane}`]);
  });
});

describe('steady-state allocation', () => {
  it('a 4D pile of 300 moving boxes updates without growing the heap or reallocating buffers', async () => {
    setFlagsFromString('--expose-gc');
    const gc = runInNewContext('gc') as () => void;
    const n = 4;
    const rand = seeded(31337);
    const bp = createBroadphase(n, { margin: 0.1 });
    const count = 300;
    const centres = Array.from({ length: count }, () => randomArray(rand, n, -3, 3));
    const half = 0.5;
    const lo = new Float64Array(n);
    const hi = new Float64Array(n);
    const ids = centres.map((c) =>
      bp.createProxy(
        c.map((v) => v - half),
        c.map((v) => v + half),
      ),
    );
    bp.createHalfSpaceProxy([0, 1, 0, 0], -2);
    const velocity = centres.map(() => randomArray(rand, n, -0.02, 0.02));
    const step = (): void => {
      for (let i = 0; i < count; i += 1) {
        const c = centres[i]!;
        const v = velocity[i]!;
        for (let k = 0; k < n; k += 1) {
          c[k] += v[k]!;
          // Bounce inside the box [-3, 3]^n so the scene stays a pile.
          if (c[k]! > 3 || c[k]! < -3) v[k] = -v[k]!;
          lo[k] = c[k]! - half;
          hi[k] = c[k]! + half;
        }
        bp.moveProxy(ids[i]!, lo, hi);
      }
      bp.updatePairs();
    };
    // Warm up; then measure windows of 1000 steps. The JIT's own code and feedback count as heap
    // too and may still be settling in the first window, so the best of five windows is judged:
    // code that allocates per step grows the heap (or triggers collections) in every window.
    for (let w = 0; w < 1500; w += 1) step();
    const pairs = bp.pairs;
    let collections = 0;
    const observer = new PerformanceObserver((list) => {
      collections += list.getEntries().length;
    });
    observer.observe({ entryTypes: ['gc'] });
    const settle = (): Promise<void> => new Promise((resolve) => setTimeout(resolve, 20));
    let steady = false;
    let smallest = Infinity;
    let moves = 0;
    for (let window = 0; window < 5 && !steady; window += 1) {
      gc();
      await settle();
      collections = 0;
      const before = process.memoryUsage().heapUsed;
      moves = 0;
      for (let w = 0; w < 1000; w += 1) {
        step();
        moves += bp.stats.moved;
      }
      const grown = process.memoryUsage().heapUsed - before;
      await settle();
      // 1000 steps × 300 proxies: one 16-byte object per proxy per step would be 4.8 MB.
      steady = collections === 0 && grown < 256 * 1024;
      smallest = Math.min(smallest, grown);
    }
    observer.disconnect();
    expect(steady, `heap grew by at least ${smallest} bytes per 1000 steps`).toBe(true);
    expect(moves).toBeGreaterThan(1000 * 10);
    expect(bp.pairCount).toBeGreaterThan(100);
    expect(bp.pairs).toBe(pairs);
  });
});

describe('broadphase argument checks', () => {
  it('validates before changing anything', () => {
    const bp = createBroadphase(3);
    expect(() => createBroadphase(1)).toThrow(RangeError);
    expect(() => createBroadphase(3, { margin: -1 })).toThrow(/margin/);
    expect(() => bp.createProxy([0, 0], [1, 1, 1])).toThrow(/min must have length 3/);
    expect(() => bp.createProxy([0, 2, 0], [1, 1, 1])).toThrow(/min\[1\]/);
    expect(() => bp.createProxy([0, NaN, 0], [1, 1, 1])).toThrow(RangeError);
    expect(() => bp.createHalfSpaceProxy([0, 0, 0], 1)).toThrow(/normal/);
    expect(bp.proxyCount).toBe(0);
    const id = bp.createProxy([0, 0, 0], [1, 1, 1]);
    expect(() => bp.moveProxy(id + 1, [0, 0, 0], [1, 1, 1])).toThrow(/not a live proxy/);
    expect(() => bp.moveProxy(1.5, [0, 0, 0], [1, 1, 1])).toThrow(TypeError);
    const plane = bp.createHalfSpaceProxy([0, 1, 0], 0);
    expect(() => bp.moveProxy(plane, [0, 0, 0], [1, 1, 1])).toThrow(/half-space/);
    expect(() => bp.moveHalfSpace(id, [0, 1, 0], 0)).toThrow(/not a half-space/);
    bp.destroyProxy(id);
    expect(() => bp.destroyProxy(id)).toThrow(/not a live proxy/);
    expect(() => bp.setAwake(plane, 1 as unknown as boolean)).toThrow(TypeError);
  });
});
