import { describe, expect, it } from 'vitest';
import { createBroadphase } from '../packages/engine/src/collision/broadphase.js';
import type { BroadphaseKind } from '../packages/engine/src/collision/broadphase.js';
import { createIdList, queryOverlap } from '../packages/engine/src/collision/query.js';
import { randomArray, randomUnitVector, seeded } from './support/random.js';

const DIMS = [2, 3, 4, 5, 6];
const KINDS: BroadphaseKind[] = ['tree', 'sap'];

describe.each(KINDS)('queryOverlap (%s)', (kind) => {
  it.each(DIMS)('%iD: equals brute force over tight boxes and half-spaces, after moves', (n) => {
    const rand = seeded(700 + n + (kind === 'sap' ? 50 : 0));
    const bp = createBroadphase(n, { margin: 0.2 }, kind);
    const spread = Math.pow(200, 1 / n);
    const boxes = new Map<number, [Float64Array, Float64Array]>();
    const planes = new Map<number, [Float64Array, number]>();
    const add = (): void => {
      const c = randomArray(rand, n, -spread, spread);
      const h = randomArray(rand, n, 0.1, 0.8);
      const lo = c.map((v, k) => v - h[k]!);
      const hi = c.map((v, k) => v + h[k]!);
      boxes.set(bp.createProxy(lo, hi, rand() < 0.3), [lo, hi]);
    };
    for (let i = 0; i < 200; i += 1) add();
    for (let p = 0; p < 2; p += 1) {
      const normal = randomUnitVector(rand, n);
      const offset = -0.7 * spread;
      planes.set(bp.createHalfSpaceProxy(normal, offset), [normal, offset]);
    }
    const list = createIdList(2);
    let found = 0;
    for (let round = 0; round < 6; round += 1) {
      // Move a third of the boxes (some only within their fat box: the query uses the tight one).
      for (const [id, [lo, hi]] of boxes) {
        if (rand() < 0.33) {
          const d = randomArray(rand, n, -0.5, 0.5).map((v) => (rand() < 0.5 ? v * 0.1 : v));
          lo.forEach((v, k) => (lo[k] = v + d[k]!));
          hi.forEach((v, k) => (hi[k] = v + d[k]!));
          bp.moveProxy(id, lo, hi);
        }
      }
      bp.updatePairs();
      for (let q = 0; q < 20; q += 1) {
        const c = randomArray(rand, n, -spread, spread);
        const h = randomArray(rand, n, 0.1, 2);
        const qlo = c.map((v, k) => v - h[k]!);
        const qhi = c.map((v, k) => v + h[k]!);
        const expected: number[] = [];
        for (const [id, [lo, hi]] of boxes) {
          let hit = true;
          for (let k = 0; k < n; k += 1) if (lo[k]! > qhi[k]! || qlo[k]! > hi[k]!) hit = false;
          if (hit) expected.push(id);
        }
        for (const [id, [normal, offset]] of planes) {
          let s = 0;
          for (let k = 0; k < n; k += 1) s += normal[k]! * (normal[k]! > 0 ? qlo[k]! : qhi[k]!);
          if (s <= offset) expected.push(id);
        }
        expected.sort((a, b) => a - b);
        const count = queryOverlap(bp, qlo, qhi, list);
        expect(Array.from(list.ids.subarray(0, count))).toEqual(expected);
        found += count;
        // The callback form visits the same set, and stops when told to.
        const visited: number[] = [];
        expect(queryOverlap(bp, qlo, qhi, (id) => void visited.push(id))).toBe(expected.length);
        expect(visited.sort((a, b) => a - b)).toEqual(expected);
        if (expected.length > 1) {
          let calls = 0;
          queryOverlap(bp, qlo, qhi, () => {
            calls += 1;
            return false;
          });
          expect(calls).toBe(1);
        }
      }
    }
    expect(found).toBeGreaterThan(100);
  });
});

describe('queryOverlap argument checks', () => {
  it('rejects bad boxes and outputs', () => {
    const bp = createBroadphase(3);
    bp.createProxy([0, 0, 0], [1, 1, 1]);
    expect(() => queryOverlap(bp, [0, 0], [1, 1, 1], createIdList())).toThrow(/min must have length 3/);
    expect(() => queryOverlap(bp, [2, 0, 0], [1, 1, 1], createIdList())).toThrow(RangeError);
    expect(() => queryOverlap(bp, [0, 0, 0], [1, 1, 1], {} as never)).toThrow(TypeError);
    expect(() => createIdList(0)).toThrow(RangeError);
  });
});
