/**
 * Adding and removing bodies at scale (issue 19: "add 32,000 bodies, then remove them all: ≤ 0.2 s,
 * linear"), by counts, not timings:
 * - addBody and removeBody do a fixed amount of work whatever the world holds: they leave the
 *   broadphase tree alone (a new leaf waits outside it, a dead one is only listed) and shift no
 *   other body;
 * - the step after a batch builds the tree once, top-down, and finds its pairs by one walk of
 *   the tree against itself, not one query per body; removing every body empties the tree in
 *   one pass, not one removal each;
 * - the tree broadphase finds the same pairs as sweep-and-prune through big batches of births,
 *   deaths and moves (the paths of the bulk build and the walk);
 * - a ball that touches nothing keeps no pose (the collision code's copy of x and R): it gets one
 *   when a pair, a joint or a query reads it, equal to its state.
 */
import { afterEach, describe, expect, it, vi } from 'vitest';
import { proxyBounds, validateTree } from '../packages/engine/src/collision/broadphase-queries.js';
import type { BroadphaseBase } from '../packages/engine/src/collision/broadphase-base.js';
import { queryParts } from '../packages/engine/src/queries.js';
import { Body, HyperSphere, World, dims, queryBox } from '@physin/engine';
import type { WorldBase } from '@physin/engine';
import { createBroadphase } from '../packages/engine/src/collision/broadphase.js';
import type { Broadphase } from '../packages/engine/src/collision/broadphase.js';
import { DynamicAabbTree } from '../packages/engine/src/collision/broadphase-aabb-tree.js';
import { TreeBroadphase } from '../packages/engine/src/collision/broadphase-tree.js';
import { TreeSelfPairs } from '../packages/engine/src/collision/broadphase-tree-pairs.js';
import { randomArray, seeded } from './support/random.js';

const D3 = dims(3);
const BALL = HyperSphere(D3, 0.2);

/** Ball i of a grid 1 m apart (no two touch), as in bench/scale.bench.mjs. */
function ball(i: number): Body {
  return new Body(D3, { shape: BALL, mass: 1, position: [i % 40, 1 + Math.floor(i / 1600), Math.floor(i / 40) % 40] });
}

/** The world's broadphase (a tree), through the internal accessor the queries use. */
function treeOf(world: WorldBase): TreeBroadphase {
  const bp = queryParts(world).broadphase;
  expect(bp).toBeInstanceOf(TreeBroadphase);
  return bp as TreeBroadphase;
}

/** Counts the calls of the tree's methods that change it or walk it, from now on. */
function countTreeCalls(): Record<string, { mock: { calls: unknown[] } }> {
  const names = ['insert', 'update', 'remove', 'query', 'createLeaf', 'linkLeaf', 'dropLeaf', 'markDead', 'rebuild'] as const;
  const spies: Record<string, { mock: { calls: unknown[] } }> = {};
  for (const name of names) spies[name] = vi.spyOn(DynamicAabbTree.prototype, name);
  spies.selfPairs = vi.spyOn(TreeSelfPairs.prototype, 'run');
  return spies;
}

const callCounts = (spies: Record<string, { mock: { calls: unknown[] } }>): Record<string, number> =>
  Object.fromEntries(Object.entries(spies).map(([name, spy]) => [name, spy.mock.calls.length]));

afterEach(() => {
  vi.restoreAllMocks();
});

describe('addBody and removeBody cost the same in a small world and a large one', () => {
  it('64 adds and 64 removals make the same calls into the tree with 500 bodies and with 8000, and shift no body', () => {
    const seen: Record<string, number>[] = [];
    for (const size of [500, 8000]) {
      const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
      const bodies = Array.from({ length: size }, (_, i) => world.addBody(ball(i)));
      world.step(1 / 60);
      const spies = countTreeCalls();
      const added = Array.from({ length: 64 }, (_, i) => world.addBody(ball(size + i)));
      // Every third body from the first quarter on: holes, not shifts; no other body is renumbered.
      const removed = Array.from({ length: 64 }, (_, i) => bodies[(size >> 2) + 3 * i]!);
      const before = bodies.map((b) => b.worldIndex);
      for (const body of removed) world.removeBody(body);
      const gone = new Set(removed);
      bodies.forEach((b, i) => {
        if (!gone.has(b)) expect(b.worldIndex).toBe(before[i]);
      });
      seen.push(callCounts(spies));
      vi.restoreAllMocks();
      // The world is whole after the next step: the survivors in order, the new ones last.
      world.step(1 / 60);
      expect(world.bodies).toEqual([...bodies.filter((b) => !gone.has(b)), ...added]);
      expect(world.stats.bodies).toBe(size);
    }
    // One new leaf per add, made outside the tree; nothing else walks or changes the tree.
    expect(seen[0]).toEqual({
      insert: 0,
      update: 0,
      remove: 0,
      query: 0,
      createLeaf: 64,
      linkLeaf: 0,
      dropLeaf: 0,
      markDead: 0,
      rebuild: 0,
      selfPairs: 0,
    });
    expect(seen[1]).toEqual(seen[0]);
  });
});

describe('the step after a batch', () => {
  it('builds the tree of 4000 new bodies once and walks it once for their pairs; removing all empties it at once', () => {
    const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
    const bodies = Array.from({ length: 4000 }, (_, i) => world.addBody(ball(i)));
    let spies = countTreeCalls();
    world.step(1 / 60);
    expect(callCounts(spies)).toMatchObject({ insert: 0, linkLeaf: 0, query: 0, rebuild: 1, selfPairs: 1 });
    vi.restoreAllMocks();
    const bp = treeOf(world);
    expect(validateTree(bp.tree)).toBeNull();
    expect(bp.tree.leafCount).toBe(4000);
    expect(bp.tree.size).toBe(2 * 4000 - 1);
    // Shallow: the middle splits of a 40 × 40 grid leave it within a quarter of a balanced tree's 12.
    expect(bp.tree.treeHeight).toBeLessThanOrEqual(Math.ceil(1.25 * Math.log2(4000)));
    expect(world.stats.pairs).toBe(0);

    // A few bodies more are put in one by one, each found by one query.
    for (let i = 0; i < 5; i += 1) world.addBody(ball(4000 + i));
    spies = countTreeCalls();
    world.step(1 / 60);
    expect(callCounts(spies)).toMatchObject({ linkLeaf: 5, rebuild: 0, selfPairs: 0, query: 5 });
    vi.restoreAllMocks();
    expect(validateTree(treeOf(world).tree)).toBeNull();

    for (const body of bodies) world.removeBody(body);
    for (const body of world.bodies.slice()) world.removeBody(body);
    spies = countTreeCalls();
    world.step(1 / 60);
    expect(callCounts(spies)).toMatchObject({ remove: 0, markDead: 4005, rebuild: 1 });
    vi.restoreAllMocks();
    expect(treeOf(world).tree.size).toBe(0);
    expect(world.stats.bodies).toBe(0);
  });

  it('finds the same contacts whether the bodies came in one batch or one by one', () => {
    // A pile of touching balls: built in one batch (bulk build, walk) and one ball per step.
    const place = (i: number): number[] => [(i % 10) * 0.35, 0.2 + Math.floor(i / 100) * 0.35, (Math.floor(i / 10) % 10) * 0.35];
    const batch = new World({ dimensions: 3 });
    for (let i = 0; i < 300; i += 1) batch.addBody(new Body(D3, { shape: BALL, mass: 1, position: place(i) }));
    batch.step(1 / 60);
    const single = new World({ dimensions: 3 });
    for (let i = 0; i < 300; i += 1) {
      single.addBody(new Body(D3, { shape: BALL, mass: 1, position: place(i) }));
      // A query between adds puts each new leaf into the tree at once, by the one-by-one insertion.
      expect(queryBox(single, [-1, -1, -1], [-0.9, -0.9, -0.9])).toEqual([]);
    }
    single.step(1 / 60);
    expect(single.stats.pairs).toBe(batch.stats.pairs);
    expect(single.stats.contacts).toBe(batch.stats.contacts);
    expect(batch.stats.pairs).toBeGreaterThan(600);
    const a = batch.bodies.flatMap((b) => [...b.x, ...b.v]);
    const b = single.bodies.flatMap((b) => [...b.x, ...b.v]);
    expect(a).toEqual(b);
  });
});

describe('poses made on demand', () => {
  it('a ball alone has no pose until it meets another or a query reads it; the pose is then its state', () => {
    const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
    const a = world.addBody(ball(0));
    const b = world.addBody(ball(1));
    for (let s = 0; s < 3; s += 1) world.step(1 / 60);
    expect([a.pose, b.pose]).toEqual([null, null]);
    // moved by hand onto a: the step's new pair gives both their poses
    b.setPositionN([a.x[0]! + 0.3, a.x[1]!, a.x[2]!]);
    world.step(1 / 60);
    for (const body of [a, b]) {
      expect(Array.from(body.pose!.x)).toEqual(Array.from(body.x));
      expect(Array.from(body.pose!.M, (v) => v + 0)).toEqual([1, 0, 0, 0, 1, 0, 0, 0, 1]); // (+ 0: -0 is 0 here)
    }
    const c = world.addBody(ball(5));
    expect(c.pose).toBeNull();
    expect(queryBox(world, [4.5, 0.5, -0.5], [5.5, 1.5, 0.5])).toEqual([c]);
    expect(Array.from(c.pose!.x)).toEqual(Array.from(c.x));
  });
});

describe('the tree broadphase through big batches agrees with sweep-and-prune', () => {
  /** Random boxes: centres in a cube that makes about `count` overlaps; 1 in 5 static. */
  function populate(bp: Broadphase, rand: () => number, n: number, count: number, spread: number, into: number[]): void {
    for (let i = 0; i < count; i += 1) {
      const c = randomArray(rand, n, -spread, spread);
      const h = randomArray(rand, n, 0.2, 1);
      into.push(
        bp.createProxy(
          c.map((v, k) => v - h[k]!),
          c.map((v, k) => v + h[k]!),
          rand() < 0.2,
        ),
      );
    }
  }

  it.each([2, 3, 4, 6])('%iD: 600 born at once, then 400 die, 300 are born and 100 move, twice', (n) => {
    const lanes = (['tree', 'sap'] as const).map((kind) => {
      const rand = seeded(7100 + n);
      const bp = createBroadphase(n, { margin: 0.1 }, kind);
      return { bp, rand, ids: [] as number[] };
    });
    const spread = 1.2 * Math.pow(600, 1 / n);
    const pairsOf = (bp: Broadphase): number[] => Array.from(bp.pairs.subarray(0, 2 * bp.pairCount));
    for (const lane of lanes) {
      populate(lane.bp, lane.rand, n, 600, spread, lane.ids);
      lane.bp.createHalfSpaceProxy([1, ...new Array<number>(n - 1).fill(0)], -0.5 * spread);
      lane.bp.updatePairs();
    }
    expect(pairsOf(lanes[0]!.bp)).toEqual(pairsOf(lanes[1]!.bp));
    expect(lanes[0]!.bp.pairCount).toBeGreaterThan(300);
    for (let round = 0; round < 2; round += 1) {
      for (const lane of lanes) {
        const { bp, rand, ids } = lane;
        for (let i = 0; i < 400; i += 1) bp.destroyProxy(ids.splice(Math.floor(rand() * ids.length), 1)[0]!);
        populate(bp, rand, n, 300, spread, ids);
        const lo = new Float64Array(n);
        const hi = new Float64Array(n);
        for (let i = 0; i < 100; i += 1) {
          const id = ids[Math.floor(rand() * ids.length)]!;
          proxyBounds(bp as BroadphaseBase, id, lo, hi);
          const d = randomArray(rand, n, -1, 1);
          bp.moveProxy(
            id,
            lo.map((v, k) => v + d[k]!),
            hi.map((v, k) => v + d[k]!),
          );
        }
        bp.updatePairs();
      }
      expect(pairsOf(lanes[0]!.bp)).toEqual(pairsOf(lanes[1]!.bp));
      const tree = lanes[0]!.bp as TreeBroadphase;
      expect(validateTree(tree.tree)).toBeNull();
      expect(tree.tree.leafCount).toBe(lanes[0]!.ids.length);
    }
  });
});
