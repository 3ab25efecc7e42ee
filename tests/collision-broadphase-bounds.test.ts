import { describe, expect, it } from 'vitest';
import { computeBounds } from '../packages/engine/src/collision/bounds.js';
import type {
  BoxGeometry,
  ConvexMeshGeometry,
  HalfSpaceGeometry,
  SphereGeometry,
  TorusGeometry,
} from '../packages/engine/src/collision/query-shapes.js';
import { randomArray, randomUnitVector, seeded, uniform } from './support/random.js';
import { randomRotation, toWorld } from './support/poses.js';

const DIMS = [2, 3, 4, 5, 6];
/** Containment and tightness are exact up to rounding of a few products: 1e-12 absolute. */
const TOL = 1e-12;

/** Every sample lies in [min − tol, max + tol]. */
function expectInside(points: Float64Array[], min: Float64Array, max: Float64Array): void {
  for (const p of points) {
    for (let k = 0; k < p.length; k += 1) {
      expect(p[k]!).toBeGreaterThanOrEqual(min[k]! - TOL);
      expect(p[k]!).toBeLessThanOrEqual(max[k]! + TOL);
    }
  }
}

/** For each axis k, some point of the (closed) shape reaches max[k] − margin and another min[k] + margin. */
function expectTouches(
  support: (k: number, sign: number) => Float64Array,
  min: Float64Array,
  max: Float64Array,
  margin: number,
): void {
  for (let k = 0; k < min.length; k += 1) {
    expect(Math.abs(support(k, 1)[k]! - (max[k]! - margin))).toBeLessThanOrEqual(TOL);
    expect(Math.abs(support(k, -1)[k]! - (min[k]! + margin))).toBeLessThanOrEqual(TOL);
  }
}

function bounds(
  n: number,
  shape: Parameters<typeof computeBounds>[3],
  x: Float64Array,
  M: Float64Array,
  margin: number,
): [Float64Array, Float64Array] {
  const lo = new Float64Array(n);
  const hi = new Float64Array(n);
  expect(computeBounds(lo, hi, n, shape, x, M, margin)).toBe(lo);
  return [lo, hi];
}

describe.each(DIMS)('computeBounds in %iD', (n) => {
  it('box: every corner inside, the extreme corner touches each face', () => {
    const rand = seeded(10 + n);
    for (let trial = 0; trial < 20; trial += 1) {
      const a = randomArray(rand, n, 0.1, 3);
      const shape: BoxGeometry = { kind: 'box', halfExtents: a };
      const x = randomArray(rand, n, -10, 10);
      const M = randomRotation(rand, n);
      const margin = trial % 2 === 0 ? 0 : 0.05;
      const [lo, hi] = bounds(n, shape, x, M, margin);
      const corners: Float64Array[] = [];
      for (let mask = 0; mask < 1 << n; mask += 1) {
        corners.push(
          toWorld(
            n,
            x,
            M,
            a.map((h, c) => ((mask >> c) & 1 ? h : -h)),
          ),
        );
      }
      expectInside(corners, lo, hi);
      // The corner with signs sign(M[k][c])·sign along e_k is the support point.
      expectTouches(
        (k, s) =>
          toWorld(
            n,
            x,
            M,
            a.map((h, c) => (s * M[k * n + c]! >= 0 ? h : -h)),
          ),
        lo,
        hi,
        margin,
      );
    }
  });

  it('sphere: surface samples inside, the poles touch each face', () => {
    const rand = seeded(20 + n);
    for (let trial = 0; trial < 20; trial += 1) {
      const radius = uniform(rand, 0.1, 3);
      const shape: SphereGeometry = { kind: 'sphere', radius };
      const x = randomArray(rand, n, -10, 10);
      const M = randomRotation(rand, n);
      const margin = trial % 2 === 0 ? 0 : 0.05;
      const [lo, hi] = bounds(n, shape, x, M, margin);
      const samples = Array.from({ length: 50 }, () =>
        toWorld(
          n,
          x,
          M,
          randomUnitVector(rand, n).map((v) => v * radius),
        ),
      );
      expectInside(samples, lo, hi);
      expectTouches((k, s) => x.map((c, i) => c + (i === k ? s * radius : 0)), lo, hi, margin);
    }
  });

  it('torus: surface samples inside, the exact support point (on the torus) touches each face', () => {
    const rand = seeded(30 + n);
    for (let trial = 0; trial < 20; trial += 1) {
      const R = uniform(rand, 0.5, 3);
      const r = uniform(rand, 0.05, 0.95) * R;
      const i = Math.floor(rand() * n);
      const j = (i + 1 + Math.floor(rand() * (n - 1))) % n;
      const shape: TorusGeometry = { kind: 'torus', majorRadius: R, minorRadius: r, planeI: i, planeJ: j };
      const x = randomArray(rand, n, -10, 10);
      const M = randomRotation(rand, n);
      const margin = trial % 2 === 0 ? 0 : 0.05;
      const [lo, hi] = bounds(n, shape, x, M, margin);
      /** Local (ρ − R)² + Σ others − r² of a world point: <= 0 on the closed solid. */
      const implicit = (p: Float64Array): number => {
        const w = p.map((v, c) => v - x[c]!);
        const q = new Float64Array(n);
        for (let c = 0; c < n; c += 1) for (let k = 0; k < n; k += 1) q[c] += M[k * n + c]! * w[k]!;
        let s = 0;
        for (let c = 0; c < n; c += 1) if (c !== i && c !== j) s += q[c]! ** 2;
        return (Math.hypot(q[i]!, q[j]!) - R) ** 2 + s - r * r;
      };
      const samples = Array.from({ length: 80 }, () => {
        // A surface point: circle angle φ, then r along a unit vector of the tube's normal space.
        const phi = uniform(rand, 0, 2 * Math.PI);
        const u = randomUnitVector(rand, n - 1);
        const q = new Float64Array(n);
        let m = 1;
        q[i] = (R + r * u[0]!) * Math.cos(phi);
        q[j] = (R + r * u[0]!) * Math.sin(phi);
        for (let c = 0; c < n; c += 1) if (c !== i && c !== j) q[c] = r * u[m++]!;
        return toWorld(n, x, M, q);
      });
      for (const p of samples) expect(Math.abs(implicit(p))).toBeLessThanOrEqual(1e-11);
      expectInside(samples, lo, hi);
      // Support along s·e_k: the core circle's point farthest along e_k, plus r·s·e_k.
      const support = (k: number, s: number): Float64Array => {
        const u = M[k * n + i]!;
        const v = M[k * n + j]!;
        const len = Math.hypot(u, v);
        const q = new Float64Array(n);
        if (len > 0) {
          q[i] = (s * R * u) / len;
          q[j] = (s * R * v) / len;
        }
        const p = toWorld(n, x, M, q);
        p[k] += s * r;
        expect(implicit(p)).toBeLessThanOrEqual(1e-11);
        return p;
      };
      expectTouches(support, lo, hi, margin);
    }
  });

  it('convex mesh: vertices and mixtures inside, the extreme vertex touches each face', () => {
    const rand = seeded(40 + n);
    for (let trial = 0; trial < 20; trial += 1) {
      const count = n + 1 + Math.floor(rand() * 10);
      const verts = Array.from({ length: count }, () => randomArray(rand, n, -2, 2));
      const flat = new Float64Array(count * n);
      verts.forEach((v, idx) => flat.set(v, idx * n));
      // Bounds read only the vertices; the facets are not needed here.
      const shape: ConvexMeshGeometry = { kind: 'mesh', vertices: flat, facetNormals: [], facetOffsets: [] };
      const x = randomArray(rand, n, -10, 10);
      const M = randomRotation(rand, n);
      const margin = trial % 2 === 0 ? 0 : 0.05;
      const [lo, hi] = bounds(n, shape, x, M, margin);
      const world = verts.map((v) => toWorld(n, x, M, v));
      const mixtures = Array.from({ length: 30 }, () => {
        const w = verts.map(() => rand());
        const sum = w.reduce((p, q) => p + q, 0);
        const local = new Float64Array(n);
        verts.forEach((v, idx) => v.forEach((c, k) => (local[k] += (c * w[idx]!) / sum)));
        return toWorld(n, x, M, local);
      });
      expectInside([...world, ...mixtures], lo, hi);
      expectTouches((k, s) => world.reduce((best, p) => (s * p[k]! > s * best[k]! ? p : best)), lo, hi, margin);
    }
  });

  it('half-space: infinite, except the one axis an axis-aligned normal bounds', () => {
    const rand = seeded(50 + n);
    const x = randomArray(rand, n, -3, 3);
    const M = randomRotation(rand, n);
    const general: HalfSpaceGeometry = { kind: 'halfspace', normal: randomUnitVector(rand, n), offset: 0.3 };
    const [lo, hi] = bounds(n, general, x, M, 0.1);
    for (let k = 0; k < n; k += 1) {
      expect(lo[k]).toBe(-Infinity);
      expect(hi[k]).toBe(Infinity);
    }
    // Identity pose, normal (0, 2, 0, ...), offset 1: the solid is y <= 0.5 (+ x_y) → max y = 0.5 + x_y + margin.
    const I = new Float64Array(n * n);
    for (let k = 0; k < n; k += 1) I[k * n + k] = 1;
    const up: HalfSpaceGeometry = {
      kind: 'halfspace',
      normal: Float64Array.from({ length: n }, (_, k) => (k === 1 ? 2 : 0)),
      offset: 1,
    };
    const [lo2, hi2] = bounds(n, up, x, I, 0.1);
    for (let k = 0; k < n; k += 1) {
      expect(lo2[k]).toBe(-Infinity);
      if (k === 1) expect(Math.abs(hi2[k]! - (0.5 + x[1]! + 0.1))).toBeLessThanOrEqual(TOL);
      else expect(hi2[k]).toBe(Infinity);
    }
    const down: HalfSpaceGeometry = {
      kind: 'halfspace',
      normal: Float64Array.from({ length: n }, (_, k) => (k === 0 ? -1 : 0)),
      offset: 2,
    };
    const [lo3] = bounds(n, down, x, I, 0);
    expect(Math.abs(lo3[0]! - (x[0]! - 2))).toBeLessThanOrEqual(TOL);
  });
});

describe('computeBounds argument checks', () => {
  const I3 = Float64Array.from([1, 0, 0, 0, 1, 0, 0, 0, 1]);
  const x = new Float64Array(3);
  const box: BoxGeometry = { kind: 'box', halfExtents: [1, 1, 1] };

  it('throws TypeError for wrong types/lengths and RangeError for bad values, before writing', () => {
    const lo = new Float64Array(3).fill(7);
    const hi = new Float64Array(3).fill(7);
    expect(() => computeBounds(new Float64Array(2), hi, 3, box, x, I3, 0)).toThrow(/outMin/);
    expect(() => computeBounds(lo, [0, 0, 0] as unknown as Float64Array, 3, box, x, I3, 0)).toThrow(TypeError);
    expect(() => computeBounds(lo, hi, 9, box, x, I3, 0)).toThrow(RangeError);
    expect(() => computeBounds(lo, hi, 3, box, [0, 0], I3, 0)).toThrow(/x must have length 3/);
    expect(() =>
      computeBounds(
        lo,
        hi,
        3,
        box,
        x,
        I3.map((v, i) => (i === 4 ? Infinity : v)),
        0,
      ),
    ).toThrow(/M\[4\]/);
    expect(() => computeBounds(lo, hi, 3, box, x, I3, -0.1)).toThrow(/margin/);
    expect(() => computeBounds(lo, hi, 3, { kind: 'box', halfExtents: [1, 0, 1] }, x, I3, 0)).toThrow(/halfExtents\[1\]/);
    expect(() =>
      computeBounds(lo, hi, 3, { kind: 'torus', majorRadius: 1, minorRadius: 2, planeI: 0, planeJ: 1 }, x, I3, 0),
    ).toThrow(/majorRadius/);
    expect(() => computeBounds(lo, hi, 3, { kind: 'cone' } as never, x, I3, 0)).toThrow(/kind/);
    expect(() =>
      computeBounds(lo, hi, 3, { kind: 'mesh', vertices: [1, 2], facetNormals: [], facetOffsets: [] }, x, I3, 0),
    ).toThrow(/vertices/);
    expect(Array.from(lo)).toEqual([7, 7, 7]);
    expect(Array.from(hi)).toEqual([7, 7, 7]);
  });
});
