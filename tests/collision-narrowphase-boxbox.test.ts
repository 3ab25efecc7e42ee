import { describe, expect, it } from 'vitest';
import { collideBoxBox } from '../packages/engine/src/collision/box-box.js';
import { createManifold, createPose, maxManifoldPoints } from '../packages/engine/src/collision/manifold.js';
import type { Manifold, Pose } from '../packages/engine/src/collision/manifold.js';
import { SAT_EDGE, SAT_FACE_A } from '../packages/engine/src/collision/narrowphase-scratch.js';
import { createNarrowphaseScratch } from '../packages/engine/src/collision/narrowphase-scratch-nd.js';
import { seeded, uniform } from './support/random.js';
import { turn } from './support/poses.js';
import { box } from './support/shapes.js';

const DIMS = [2, 3, 4, 5, 6];
const TOL = 1e-12;
const MARGIN = 0.02;

function filled(n: number, v: number): Float64Array {
  return new Float64Array(n).fill(v);
}

function point(m: Manifold, p: number): number[] {
  return Array.from(m.points.subarray(p * m.n, p * m.n + m.n));
}

/** Sorted rows for set comparison, rounded to remove sign-of-zero and last-bit noise. */
function sortedRows(rows: number[][]): string[] {
  return rows.map((r) => r.map((v) => (Math.abs(v) < 1e-12 ? 0 : v).toFixed(9)).join(',')).sort();
}

/** All 2^m sign patterns of m coordinates. */
function corners(m: number): number[][] {
  const out: number[][] = [];
  for (let mask = 0; mask < 1 << m; mask += 1) {
    const row: number[] = [];
    for (let c = 0; c < m; c += 1) row.push(mask & (1 << c) ? 1 : -1);
    out.push(row);
  }
  return out;
}

describe('box–box face manifolds', () => {
  it('a small box on a large one: the 2^(n−1) corners of its face, separation = overlap (1e-12)', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 1 << (n - 1));
      const delta = 0.013;
      const pa = createPose(n);
      const pb = createPose(n);
      pb.x[1] = 2 + 0.5 - delta;
      for (let c = 0; c < n; c += 1) if (c !== 1) pb.x[c] = 0.1 * (c + 1);
      expect(collideBoxBox(all, n, box(filled(n, 2)), pa, box(filled(n, 0.5)), pb, MARGIN, scratch)).toBe(true);
      expect(scratch.sat.kind).toBe(SAT_FACE_A);
      expect(all.count).toBe(1 << (n - 1));
      for (let c = 0; c < n; c += 1) expect(all.normal[c]).toBe(c === 1 ? 1 : 0);
      const expected = corners(n - 1).map((s) => {
        const row: number[] = [];
        for (let c = 0, k = 0; c < n; c += 1) row.push(c === 1 ? 2 - delta / 2 : pb.x[c] + 0.5 * s[k++]);
        return row;
      });
      const got: number[][] = [];
      for (let p = 0; p < all.count; p += 1) {
        expect(Math.abs(all.separations[p] + delta)).toBeLessThanOrEqual(TOL);
        got.push(point(all, p));
      }
      expect(sortedRows(got)).toEqual(sortedRows(expected));
      expect(new Set(all.ids.subarray(0, all.count)).size).toBe(all.count);
      // the default bound keeps min(2^(n−1), bound) of them, the deepest first
      const out = createManifold(n);
      collideBoxBox(out, n, box(filled(n, 2)), pa, box(filled(n, 0.5)), pb, MARGIN, scratch);
      expect(out.count).toBe(Math.min(1 << (n - 1), maxManifoldPoints(n)));
    }
  });

  it('offset equal boxes: the corners of the overlap region (crossings included), any n', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 1 << (n - 1));
      const delta = 0.007;
      const pa = createPose(n);
      const pb = createPose(n);
      const shift: number[] = [];
      pb.x[1] = 2 - delta;
      for (let c = 0; c < n; c += 1) {
        if (c === 1) continue;
        const s = 0.3 + 0.2 * c;
        pb.x[c] = c % 2 ? -s : s;
        shift.push(pb.x[c]);
      }
      expect(collideBoxBox(all, n, box(filled(n, 1)), pa, box(filled(n, 1)), pb, MARGIN, scratch)).toBe(true);
      expect(all.count).toBe(1 << (n - 1));
      // overlap of [−1, 1] and [s − 1, s + 1] on every tangent axis
      const lo = shift.map((s) => Math.max(-1, s - 1));
      const hi = shift.map((s) => Math.min(1, s + 1));
      const expected = corners(n - 1).map((sg) => {
        const row: number[] = [];
        for (let c = 0, k = 0; c < n; c += 1) {
          if (c === 1) row.push(1 - delta / 2);
          else {
            row.push(sg[k] > 0 ? hi[k] : lo[k]);
            k += 1;
          }
        }
        return row;
      });
      const got: number[][] = [];
      for (let p = 0; p < all.count; p += 1) {
        expect(Math.abs(all.separations[p] + delta)).toBeLessThanOrEqual(TOL);
        got.push(point(all, p));
      }
      expect(sortedRows(got)).toEqual(sortedRows(expected));
    }
  });

  it('coincident faces of equal boxes give each corner once', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 64);
      const pb = createPose(n);
      pb.x[1] = 2 - 0.01;
      collideBoxBox(all, n, box(filled(n, 1)), createPose(n), box(filled(n, 1)), pb, MARGIN, scratch);
      expect(all.count).toBe(1 << (n - 1));
    }
  });

  it('a box turned 45° resting edge-down: the 2^(n−2) ridge corners at the analytic depth', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 64);
      const delta = 0.004;
      const pb = createPose(n);
      turn(n, pb.M, 0, 1, Math.PI / 4);
      pb.x[1] = 2 + 0.5 * Math.SQRT2 - delta;
      expect(collideBoxBox(all, n, box(filled(n, 2)), createPose(n), box(filled(n, 0.5)), pb, MARGIN, scratch)).toBe(true);
      expect(scratch.sat.kind).toBe(SAT_FACE_A);
      expect(all.count).toBe(1 << Math.max(0, n - 2));
      for (let c = 0; c < n; c += 1) expect(all.normal[c]).toBe(c === 1 ? 1 : 0);
      const expected = corners(n - 2).map((s) => [0, 2 - delta / 2, ...s.map((v) => 0.5 * v)]);
      const got: number[][] = [];
      for (let p = 0; p < all.count; p += 1) {
        expect(Math.abs(all.separations[p] + delta)).toBeLessThanOrEqual(TOL);
        got.push(point(all, p));
      }
      expect(sortedRows(got)).toEqual(sortedRows(expected));
    }
  });

  it('B as reference: a large box on a small one flips the roles and keeps the normal from A to B', () => {
    for (const n of [2, 3, 4]) {
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 64);
      const delta = 0.01;
      const pb = createPose(n);
      pb.x[1] = 0.5 + 2 - delta; // B (large) above A (small)
      expect(collideBoxBox(all, n, box(filled(n, 0.5)), createPose(n), box(filled(n, 2)), pb, MARGIN, scratch)).toBe(true);
      expect(all.count).toBe(Math.min(1 << (n - 1), 64));
      for (let c = 0; c < n; c += 1) expect(all.normal[c]).toBe(c === 1 ? 1 : 0);
      for (let p = 0; p < all.count; p += 1) {
        expect(Math.abs(all.separations[p] + delta)).toBeLessThanOrEqual(TOL);
        expect(Math.abs(all.points[p * n + 1] - (0.5 - delta / 2))).toBeLessThanOrEqual(TOL);
      }
    }
  });

  it('the reduction keeps the deepest point first and surrounds the face centre (n = 4..6)', () => {
    const rand = seeded(77);
    for (const n of [4, 5, 6]) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const pb = createPose(n);
      turn(n, pb.M, 1, 2, 0.004); // a slight tilt: one side deeper
      pb.x[1] = 2.5 - 0.01;
      collideBoxBox(out, n, box(filled(n, 2)), createPose(n), box(filled(n, 0.5)), pb, MARGIN, scratch);
      expect(out.count).toBe(maxManifoldPoints(n));
      let deepest = Infinity;
      for (let p = 0; p < out.count; p += 1) deepest = Math.min(deepest, out.separations[p]);
      expect(out.separations[0]).toBe(deepest);
      for (let c = 0; c < n; c += 1) {
        if (c === 1) continue;
        let minC = Infinity;
        let maxC = -Infinity;
        for (let p = 0; p < out.count; p += 1) {
          minC = Math.min(minC, out.points[p * n + c]);
          maxC = Math.max(maxC, out.points[p * n + c]);
        }
        expect(minC).toBeLessThan(-0.49);
        expect(maxC).toBeGreaterThan(0.49);
      }
      // the centre lies strictly inside the hull of the kept points: in every tangent direction u
      // some kept point reaches beyond it, by at least 0.1 of the half extent (0.5)
      for (let trial = 0; trial < 500; trial += 1) {
        const u = new Float64Array(n);
        for (let c = 0; c < n; c += 1) u[c] = c === 1 ? 0 : uniform(rand, -1, 1);
        const len = Math.hypot(...u);
        let support = -Infinity;
        for (let p = 0; p < out.count; p += 1) {
          let s = 0;
          for (let c = 0; c < n; c += 1) s += (u[c] / len) * (out.points[p * n + c] - pb.x[c]);
          support = Math.max(support, s);
        }
        expect(support).toBeGreaterThan(0.05);
      }
    }
  });
});

describe('box–box mixed axes', () => {
  it('3D edge–edge: one point midway between the crossing edges', () => {
    const n = 3;
    const scratch = createNarrowphaseScratch(n);
    const out = createManifold(n);
    const delta = 0.006;
    const pa = createPose(n);
    turn(n, pa.M, 1, 2, Math.PI / 4); // A's top edge runs along x at y = √2
    const pb = createPose(n);
    turn(n, pb.M, 0, 1, Math.PI / 4); // B's bottom edge runs along z
    pb.x[1] = 2 * Math.SQRT2 - delta;
    expect(collideBoxBox(out, n, box([1, 1, 1]), pa, box([1, 1, 1]), pb, MARGIN, scratch)).toBe(true);
    expect(scratch.sat.kind).toBe(SAT_EDGE);
    expect(out.count).toBe(1);
    expect(Math.abs(out.separations[0] + delta)).toBeLessThanOrEqual(TOL);
    const p = point(out, 0);
    expect(Math.abs(p[0])).toBeLessThanOrEqual(TOL);
    expect(Math.abs(p[1] - (Math.SQRT2 - delta / 2))).toBeLessThanOrEqual(TOL);
    expect(Math.abs(p[2])).toBeLessThanOrEqual(TOL);
    expect(Math.abs(out.normal[1] - 1)).toBeLessThanOrEqual(TOL);
  });

  it('3D edge–edge off-centre: the point is at the crossing of the two edges', () => {
    const n = 3;
    const scratch = createNarrowphaseScratch(n);
    const out = createManifold(n);
    const delta = 0.01;
    const pa = createPose(n);
    turn(n, pa.M, 1, 2, Math.PI / 4);
    const pb = createPose(n);
    turn(n, pb.M, 0, 1, Math.PI / 4);
    pb.x[0] = 0.3; // B's edge crosses A's at x = 0.3
    pb.x[2] = -0.2; // and A's edge is at z = 0, inside B's edge span
    pb.x[1] = 2 * Math.SQRT2 - delta;
    collideBoxBox(out, n, box([1, 1, 1]), pa, box([1, 1, 1]), pb, MARGIN, scratch);
    expect(scratch.sat.kind).toBe(SAT_EDGE);
    const p = point(out, 0);
    expect(Math.abs(p[0] - 0.3)).toBeLessThanOrEqual(TOL);
    expect(Math.abs(p[1] - (Math.SQRT2 - delta / 2))).toBeLessThanOrEqual(TOL);
    expect(Math.abs(p[2])).toBeLessThanOrEqual(TOL);
  });

  it('4D ridge across ridge (p = 1, q = 2): one point on the contact segment at the analytic depth', () => {
    const n = 4;
    const scratch = createNarrowphaseScratch(n);
    const out = createManifold(n);
    const delta = 0.005;
    const pa = createPose(n);
    turn(n, pa.M, 1, 2, Math.PI / 4);
    const pb = createPose(n);
    turn(n, pb.M, 0, 1, Math.PI / 4);
    pb.x[1] = 2 * Math.SQRT2 - delta;
    expect(collideBoxBox(out, n, box(filled(n, 1)), pa, box(filled(n, 1)), pb, MARGIN, scratch)).toBe(true);
    expect(scratch.sat.kind).toBe(SAT_EDGE);
    expect(out.count).toBe(1);
    expect(Math.abs(out.separations[0] + delta)).toBeLessThanOrEqual(TOL);
    const p = point(out, 0);
    expect(Math.abs(p[0])).toBeLessThanOrEqual(TOL);
    expect(Math.abs(p[1] - (Math.SQRT2 - delta / 2))).toBeLessThanOrEqual(TOL);
    expect(Math.abs(p[2])).toBeLessThanOrEqual(TOL);
    expect(Math.abs(p[3])).toBeLessThanOrEqual(1 + TOL);
  });
});

describe('box–box feature ids', () => {
  it('are stable under a small motion and follow their points (n = 2..5)', () => {
    for (const n of [2, 3, 4, 5]) {
      const rand = seeded(300 + n);
      const scratch = createNarrowphaseScratch(n);
      const first = createManifold(n, 64);
      const second = createManifold(n, 64);
      const pb: Pose = createPose(n);
      // a slightly tilted box hanging over A's edge, so the manifold has crossings too
      for (let i = 0; i < n; i += 1) for (let j = i + 1; j < n; j += 1) turn(n, pb.M, i, j, uniform(rand, -0.004, 0.004));
      pb.x[0] = 0.8;
      pb.x[1] = 1 + 0.5 - 0.01;
      for (let c = 2; c < n; c += 1) pb.x[c] = uniform(rand, -0.3, 0.3);
      const A = box(filled(n, 1));
      const B = box(filled(n, 0.5));
      const pa = createPose(n);
      expect(collideBoxBox(first, n, A, pa, B, pb, MARGIN, scratch)).toBe(true);
      // move B by 1e-5 and turn it by 1e-5
      for (let c = 0; c < n; c += 1) pb.x[c] += 1e-5 * (c % 2 ? 1 : -1);
      turn(n, pb.M, 0, n - 1, 1e-5);
      expect(collideBoxBox(second, n, A, pa, B, pb, MARGIN, scratch)).toBe(true);
      expect(second.count).toBe(first.count);
      expect(first.count).toBe(1 << (n - 1));
      for (let p = 0; p < first.count; p += 1) {
        const q = Array.from(second.ids.subarray(0, second.count)).indexOf(first.ids[p]);
        expect(q).toBeGreaterThanOrEqual(0);
        let moved = 0;
        for (let c = 0; c < n; c += 1) moved = Math.max(moved, Math.abs(first.points[p * n + c] - second.points[q * n + c]));
        expect(moved).toBeLessThan(1e-4);
      }
    }
  });
});
