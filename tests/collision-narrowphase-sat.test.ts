import { describe, expect, it } from 'vitest';
import { boxBoxSat3 } from '../packages/engine/src/collision/box-box-sat3.js';
import { boxBoxSatGeneral, satAxisCount, satAxisTable } from '../packages/engine/src/collision/box-box-sat.js';
import { collideBoxBox } from '../packages/engine/src/collision/box-box.js';
import { createManifold, createPose } from '../packages/engine/src/collision/manifold.js';
import { createNarrowphaseScratch } from '../packages/engine/src/collision/narrowphase-scratch-nd.js';
import { SAT_EDGE, SAT_FACE_A, SAT_FACE_B, SAT_SEPARATED } from '../packages/engine/src/collision/narrowphase-scratch.js';
import { randomArray, seeded, uniform } from './support/random.js';
import { randomPose } from './support/poses.js';
import { box } from './support/shapes.js';

const DIMS = [2, 3, 4, 5, 6];

function binomial(a: number, b: number): number {
  let r = 1;
  for (let i = 1; i <= b; i += 1) r = (r * (a - b + i)) / i;
  return Math.round(r);
}

describe('box–box SAT candidate axes (identity 16)', () => {
  it('counts C(2n, n−1) = 4, 15, 56, 210, 792 for n = 2..6', () => {
    expect(DIMS.map(satAxisCount)).toEqual([4, 15, 56, 210, 792]);
    expect(DIMS.map((n) => satAxisTable(n).count)).toEqual([4, 15, 56, 210, 792]);
    expect(satAxisCount(7)).toBe(binomial(14, 6));
    expect(satAxisCount(8)).toBe(binomial(16, 7));
  });

  it('enumerates every (S_A, S_B) with |S_A| + |S_B| = n − 1 exactly once, faces first', () => {
    for (const n of DIMS) {
      const table = satAxisTable(n);
      const seen = new Set<number>();
      const perP = new Array<number>(n).fill(0);
      for (let e = 0; e < table.count; e += 1) {
        const a = table.maskA[e];
        const b = table.maskB[e];
        const p = popcount(a);
        expect(p + popcount(b)).toBe(n - 1);
        seen.add(a * 256 + b);
        perP[p] += 1;
      }
      expect(seen.size).toBe(table.count);
      // p face directions of A and n−1−p of B: C(n, p)·C(n, n−1−p) axes
      for (let p = 0; p < n; p += 1) expect(perP[p]).toBe(binomial(n, p) * binomial(n, n - 1 - p));
      // the first n are A's faces (q = 0), the next n B's faces (p = 0)
      for (let i = 0; i < n; i += 1) {
        expect(table.maskB[i]).toBe(0);
        expect(table.maskA[n + i]).toBe(0);
      }
    }
  });

  it('throws RangeError / TypeError for a bad n', () => {
    expect(() => satAxisCount(1)).toThrow(RangeError);
    expect(() => satAxisCount(9)).toThrow(RangeError);
    expect(() => satAxisCount(2.5)).toThrow(TypeError);
  });
});

function popcount(x: number): number {
  let c = 0;
  for (let v = x; v; v &= v - 1) c += 1;
  return c;
}

describe('box–box SAT', () => {
  it('the 3D closed form agrees with the general-n path on seeded random poses (±1e-12)', () => {
    const rand = seeded(1601);
    const scratch = createNarrowphaseScratch(3);
    const kinds = new Set<number>();
    for (let trial = 0; trial < 400; trial += 1) {
      const a = box(randomArray(rand, 3, 0.2, 1.5));
      const b = box(randomArray(rand, 3, 0.2, 1.5));
      const pa = randomPose(rand, 3, 1);
      const pb = randomPose(rand, 3, 1);
      const margin = 0.02;
      const hitG = boxBoxSatGeneral(3, a, pa, b, pb, margin, scratch);
      const g = { ...scratch.sat, normal: Float64Array.from(scratch.sat.normal) };
      const hit3 = boxBoxSat3(a, pa, b, pb, margin, scratch);
      const f = scratch.sat;
      expect(hit3).toBe(hitG);
      expect(f.kind).toBe(g.kind);
      expect(Math.abs(f.separation - g.separation)).toBeLessThanOrEqual(1e-12);
      kinds.add(f.kind);
      if (hit3) {
        expect(f.axis).toBe(g.axis);
        expect(f.maskA).toBe(g.maskA);
        expect(f.maskB).toBe(g.maskB);
        for (let i = 0; i < 3; i += 1) expect(Math.abs(f.normal[i] - g.normal[i])).toBeLessThanOrEqual(1e-12);
      }
    }
    // the seeded set exercises every outcome
    expect([...kinds].sort()).toEqual([SAT_SEPARATED, SAT_FACE_A, SAT_FACE_B, SAT_EDGE].sort());
  });

  it('the chosen axis gives the exact gap of boxes separated along a face normal, any n', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const rand = seeded(20 + n);
      for (let trial = 0; trial < 20; trial += 1) {
        const ha = randomArray(rand, n, 0.3, 1);
        const hb = randomArray(rand, n, 0.3, 1);
        const gap = uniform(rand, -0.2, 0.2);
        const axis = trial % n;
        const pa = createPose(n);
        const pb = createPose(n);
        // B sits on A's +axis face, shifted sideways by less than the faces' overlap
        pb.x[axis] = ha[axis] + hb[axis] + gap;
        for (let c = 0; c < n; c += 1) if (c !== axis) pb.x[c] = uniform(rand, -0.2, 0.2);
        const hit = boxBoxSatGeneral(n, box(ha), pa, box(hb), pb, 0.25, scratch);
        expect(hit).toBe(true);
        expect(Math.abs(scratch.sat.separation - gap)).toBeLessThanOrEqual(1e-12);
        expect(scratch.sat.normal[axis]).toBeCloseTo(1, 12);
      }
    }
  });

  it('separated boxes give no contact beyond the margin and a speculative one within it, any n', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const pa = createPose(n);
      const rand = seeded(7 + n);
      const pb = randomPose(rand, n, 0);
      const hb = randomArray(rand, n, 0.2, 0.6);
      // B's support along −e_0 reaches Σ |M[0][c]| b_c below its centre
      let reach = 0;
      for (let c = 0; c < n; c += 1) reach += Math.abs(pb.M[c]) * hb[c];
      const margin = 0.02;
      pb.x[0] = 1 + reach + margin + 1e-3;
      expect(collideBoxBox(out, n, box(new Float64Array(n).fill(1)), pa, box(hb), pb, margin, scratch)).toBe(false);
      expect(out.count).toBe(0);
      expect(scratch.sat.kind).toBe(SAT_SEPARATED);
      pb.x[0] = 1 + reach + margin / 2;
      expect(collideBoxBox(out, n, box(new Float64Array(n).fill(1)), pa, box(hb), pb, margin, scratch)).toBe(true);
      // the gap is margin/2 along e_0 (B's lowest corner over A's top face)
      expect(out.count).toBeGreaterThan(0);
      let deepest = Infinity;
      for (let p = 0; p < out.count; p += 1) deepest = Math.min(deepest, out.separations[p]);
      expect(Math.abs(deepest - margin / 2)).toBeLessThanOrEqual(1e-12);
    }
  });
});
