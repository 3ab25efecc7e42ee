import { describe, expect, it } from 'vitest';
import { createRayHit, rayCastShape } from '../packages/engine/src/collision/raycast.js';
import type { RayHit } from '../packages/engine/src/collision/raycast.js';
import type {
  BoxGeometry,
  ConvexMeshGeometry,
  HalfSpaceGeometry,
  QueryShape,
  SphereGeometry,
  TorusGeometry,
} from '../packages/engine/src/collision/query-shapes.js';
import { randomArray, seeded, uniform } from './support/random.js';
import { randomRotation, toWorld } from './support/poses.js';

const DIMS = [2, 3, 4, 5, 6];
const TOL = 1e-9;

/** M·v (a direction). */
function rotate(n: number, M: Float64Array, v: ArrayLike<number>): Float64Array {
  return toWorld(n, new Float64Array(n), M, v);
}

function unit(v: Float64Array): Float64Array {
  let s = 0;
  for (const x of v) s += x * x;
  const inv = 1 / Math.sqrt(s);
  return v.map((x) => x * inv);
}

function dot(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let s = 0;
  for (let i = 0; i < a.length; i += 1) s += a[i]! * b[i]!;
  return s;
}

function axis(n: number, k: number, s = 1): Float64Array {
  const v = new Float64Array(n);
  v[k] = s;
  return v;
}

function expectVec(actual: ArrayLike<number>, expected: ArrayLike<number>, tol: number): void {
  expect(actual.length).toBe(expected.length);
  for (let i = 0; i < expected.length; i += 1) {
    expect(Math.abs(actual[i]! - expected[i]!)).toBeLessThanOrEqual(tol);
  }
}

/** Random unit vector (rejection from the cube, seeded). */
function randomUnit(rand: () => number, n: number): Float64Array {
  for (;;) {
    const v = randomArray(rand, n);
    const s = dot(v, v);
    if (s > 0.01 && s <= 1) return unit(v);
  }
}

/**
 * A ray that enters a convex solid at the boundary point p (local) with outward normal nrm (local):
 * any direction d with d·nrm < 0 enters there, so the first hit is at exactly t0 from o = p − t0·d.
 */
function enteringRay(
  rand: () => number,
  n: number,
  x: Float64Array,
  M: Float64Array,
  pLocal: Float64Array,
  nLocal: Float64Array,
  t0: number,
): { o: Float64Array; d: Float64Array; p: Float64Array; normal: Float64Array } {
  let dLocal: Float64Array;
  do {
    dLocal = randomUnit(rand, n);
    if (dot(dLocal, nLocal) > 0) dLocal = dLocal.map((v) => -v);
  } while (dot(dLocal, nLocal) > -0.2);
  const p = toWorld(n, x, M, pLocal);
  const d = rotate(n, M, dLocal);
  const o = p.map((v, i) => v - t0 * d[i]!);
  // Scale the direction to check that its length does not matter.
  return { o, d: d.map((v) => v * 2.5), p, normal: unit(rotate(n, M, nLocal)) };
}

function crossPolytope(n: number, scale: number): ConvexMeshGeometry {
  const vertices: number[] = [];
  for (let k = 0; k < n; k += 1) {
    for (const s of [1, -1]) {
      const v = new Array<number>(n).fill(0);
      v[k] = s * scale;
      vertices.push(...v);
    }
  }
  const normals: number[] = [];
  const offsets: number[] = [];
  const inv = 1 / Math.sqrt(n);
  for (let mask = 0; mask < 1 << n; mask += 1) {
    for (let k = 0; k < n; k += 1) normals.push((mask >> k) & 1 ? -inv : inv);
    offsets.push(scale * inv);
  }
  return {
    kind: 'mesh',
    vertices: Float64Array.from(vertices),
    facetNormals: Float64Array.from(normals),
    facetOffsets: Float64Array.from(offsets),
  };
}

function cast(
  n: number,
  shape: QueryShape,
  x: Float64Array,
  M: Float64Array,
  o: ArrayLike<number>,
  d: ArrayLike<number>,
  maxDistance = Infinity,
): RayHit {
  const hit = createRayHit(n);
  const t = rayCastShape(n, shape, x, M, o, d, maxDistance, hit);
  expect(t).toBe(hit.distance);
  return hit;
}

function expectHit(hit: RayHit, t: number, p: ArrayLike<number>, normal: ArrayLike<number>): void {
  expect(Math.abs(hit.distance - t)).toBeLessThanOrEqual(TOL);
  expectVec(hit.point, p, TOL);
  expectVec(hit.normal, normal, TOL);
}

/** A start inside: distance 0, point = origin, normal = −d̂. */
function expectInside(hit: RayHit, o: ArrayLike<number>, d: Float64Array): void {
  expect(hit.distance).toBe(0);
  expectVec(hit.point, o, 0);
  expectVec(
    hit.normal,
    unit(d).map((v) => -v),
    1e-15,
  );
}

describe.each(DIMS)('ray casts in %iD', (n) => {
  it('sphere: entry at the analytic point, misses, start inside, maxDistance', () => {
    const rand = seeded(100 + n);
    for (let trial = 0; trial < 40; trial += 1) {
      const radius = uniform(rand, 0.2, 3);
      const shape: SphereGeometry = { kind: 'sphere', radius };
      const x = randomArray(rand, n, -5, 5);
      const M = randomRotation(rand, n);
      const u = randomUnit(rand, n);
      const t0 = uniform(rand, 0.1, 10);
      const ray = enteringRay(
        rand,
        n,
        x,
        M,
        u.map((v) => v * radius),
        u,
        t0,
      );
      expectHit(cast(n, shape, x, M, ray.o, ray.d), t0, ray.p, ray.normal);
      expect(cast(n, shape, x, M, ray.o, ray.d, t0 * (1 - 1e-9)).distance).toBe(-1);
      // The same ray backwards misses: the sphere is behind it.
      expect(
        cast(
          n,
          shape,
          x,
          M,
          ray.o,
          ray.d.map((v) => -v),
        ).distance,
      ).toBe(-1);
      // A ray whose line passes at distance radius·1.01 from the centre misses.
      const w = randomUnit(rand, n);
      const side = unit(w.map((v, i) => v - dot(w, u) * u[i]!));
      const o = x.map((c, i) => c + side[i]! * radius * 1.01 - u[i]! * 10);
      expect(cast(n, shape, x, M, o, u).distance).toBe(-1);
      const inside = x.map((c, i) => c + u[i]! * radius * 0.5);
      expectInside(cast(n, shape, x, M, inside, ray.d), inside, ray.d);
    }
  });

  it('box: slab entry on every face, normal of that face, misses and start inside', () => {
    const rand = seeded(200 + n);
    for (let trial = 0; trial < 40; trial += 1) {
      const a = randomArray(rand, n, 0.2, 2);
      const shape: BoxGeometry = { kind: 'box', halfExtents: a };
      const x = randomArray(rand, n, -5, 5);
      const M = randomRotation(rand, n);
      const k = trial % n;
      const s = trial % (2 * n) < n ? 1 : -1;
      const p = a.map((h, c) => (c === k ? s * h : uniform(rand, -0.9, 0.9) * h));
      const t0 = uniform(rand, 0.1, 10);
      const ray = enteringRay(rand, n, x, M, p, axis(n, k, s), t0);
      expectHit(cast(n, shape, x, M, ray.o, ray.d), t0, ray.p, ray.normal);
      expect(cast(n, shape, x, M, ray.o, ray.d, t0 - 1e-6).distance).toBe(-1);
      expect(
        cast(
          n,
          shape,
          x,
          M,
          ray.o,
          ray.d.map((v) => -v),
        ).distance,
      ).toBe(-1);
      // Parallel to face k, outside its slab: a miss (the d = 0 branch of the slab test).
      const outside = a.map((h, c) => (c === k ? s * h * 1.001 : 0));
      const along = axis(n, (k + 1) % n);
      const o = toWorld(
        n,
        x,
        M,
        outside.map((v, c) => v - 5 * along[c]!),
      );
      expect(cast(n, shape, x, M, o, rotate(n, M, along)).distance).toBe(-1);
      const inside = toWorld(
        n,
        x,
        M,
        a.map((h) => uniform(rand, -0.9, 0.9) * h),
      );
      expectInside(cast(n, shape, x, M, inside, ray.d), inside, ray.d);
    }
  });

  it('half-space: the plane crossing, parallel and receding rays miss, below counts as inside', () => {
    const rand = seeded(300 + n);
    for (let trial = 0; trial < 40; trial += 1) {
      const nrm = randomUnit(rand, n);
      const offset = uniform(rand, -2, 2);
      // A non-unit normal with the offset scaled alike is the same half-space.
      const scale = uniform(rand, 0.5, 3);
      const shape: HalfSpaceGeometry = { kind: 'halfspace', normal: nrm.map((v) => v * scale), offset: offset * scale };
      const x = randomArray(rand, n, -5, 5);
      const M = randomRotation(rand, n);
      const w = randomArray(rand, n, -3, 3);
      const p = w.map((v, i) => v + (offset - dot(w, nrm)) * nrm[i]!);
      const t0 = uniform(rand, 0.1, 10);
      const ray = enteringRay(rand, n, x, M, p, nrm, t0);
      expectHit(cast(n, shape, x, M, ray.o, ray.d), t0, ray.p, ray.normal);
      expect(
        cast(
          n,
          shape,
          x,
          M,
          ray.o,
          ray.d.map((v) => -v),
        ).distance,
      ).toBe(-1);
      // A miss writes the distance only.
      const kept = createRayHit(n);
      kept.point.fill(9);
      kept.normal.fill(9);
      expect(
        rayCastShape(
          n,
          shape,
          x,
          M,
          ray.o,
          ray.d.map((v) => -v),
          Infinity,
          kept,
        ),
      ).toBe(-1);
      expect(kept.distance).toBe(-1);
      expect([...kept.point, ...kept.normal].every((v) => v === 9)).toBe(true);
      const tangent = unit(randomUnit(rand, n).map((v, i, all) => v - dot(all, nrm) * nrm[i]!));
      // (Rounding leaves the rotated tangent a hair off parallel: a hit ~1e16 away, so cap the range.)
      expect(cast(n, shape, x, M, ray.o, rotate(n, M, tangent), 1e6).distance).toBe(-1);
      const below = toWorld(
        n,
        x,
        M,
        p.map((v, i) => v - 0.3 * nrm[i]!),
      );
      expectInside(cast(n, shape, x, M, below, ray.d), below, ray.d);
    }
  });

  it('convex mesh (cross polytope |x|₁ <= s): facet hit analytic, misses, start inside', () => {
    const rand = seeded(400 + n);
    for (let trial = 0; trial < 40; trial += 1) {
      const sc = uniform(rand, 0.5, 2);
      const shape = crossPolytope(n, sc);
      const x = randomArray(rand, n, -5, 5);
      const M = randomRotation(rand, n);
      // A point inside facet `signs`: a positive barycentric mix of its vertices s_k·sc·e_k.
      const signs = Array.from({ length: n }, () => (rand() < 0.5 ? -1 : 1));
      const weights = Array.from({ length: n }, () => uniform(rand, 0.2, 1));
      const total = weights.reduce((p, q) => p + q, 0);
      const p = Float64Array.from(signs.map((s, k) => (s * sc * weights[k]!) / total));
      const nrm = unit(Float64Array.from(signs));
      const t0 = uniform(rand, 0.1, 10);
      const ray = enteringRay(rand, n, x, M, p, nrm, t0);
      expectHit(cast(n, shape, x, M, ray.o, ray.d), t0, ray.p, ray.normal);
      expect(
        cast(
          n,
          shape,
          x,
          M,
          ray.o,
          ray.d.map((v) => -v),
        ).distance,
      ).toBe(-1);
      // A vertex's axis line through the apex hits at the vertex: t = L − sc along −e_k.
      const k = trial % n;
      const o = toWorld(n, x, M, axis(n, k, sc + 3));
      const hit = cast(n, shape, x, M, o, rotate(n, M, axis(n, k, -1)));
      expect(Math.abs(hit.distance - 3)).toBeLessThanOrEqual(TOL);
      expectVec(hit.point, toWorld(n, x, M, axis(n, k, sc)), TOL);
      // A ray parallel to an axis, offset past the apex region: |x|₁ > sc everywhere on it.
      const off = axis(n, (k + 1) % n, sc * 1.01).map((v, c) => v + (c === k ? -10 : 0));
      const miss = cast(n, shape, x, M, toWorld(n, x, M, off), rotate(n, M, axis(n, k)));
      expect(miss.distance).toBe(-1);
      const inside = toWorld(
        n,
        x,
        M,
        p.map((v) => v * 0.5),
      );
      expectInside(cast(n, shape, x, M, inside, ray.d), inside, ray.d);
    }
  });

  it('torus: rays along axes through the tube and through the hole, analytic', () => {
    const rand = seeded(500 + n);
    for (let trial = 0; trial < 30; trial += 1) {
      const R = trial === 0 ? 2 : uniform(rand, 1, 3);
      const r = trial === 0 ? 0.7 : uniform(rand, 0.1, 0.9) * R;
      const i = Math.floor(rand() * n);
      const j = (i + 1 + Math.floor(rand() * (n - 1))) % n;
      const shape: TorusGeometry = { kind: 'torus', majorRadius: R, minorRadius: r, planeI: i, planeJ: j };
      const x = randomArray(rand, n, -5, 5);
      const M = randomRotation(rand, n);
      const L = uniform(rand, 5, 20);
      // Along e_i from −L: the outer wall at x_i = −(R + r).
      let hit = cast(n, shape, x, M, toWorld(n, x, M, axis(n, i, -L)), rotate(n, M, axis(n, i)));
      expectHit(hit, L - R - r, toWorld(n, x, M, axis(n, i, -(R + r))), rotate(n, M, axis(n, i, -1)));
      // From the centre (in the hole) along e_i: the inner wall at x_i = R − r, normal toward the centre.
      hit = cast(n, shape, x, M, x, rotate(n, M, axis(n, i)));
      expectHit(hit, R - r, toWorld(n, x, M, axis(n, i, R - r)), rotate(n, M, axis(n, i, -1)));
      // Along e_j through x_i = R: meets the tube where √(R² + y²) = R + r.
      const y0 = Math.sqrt(r * r + 2 * R * r);
      const start = axis(n, i, R).map((v, c) => (c === j ? -L : v));
      hit = cast(n, shape, x, M, toWorld(n, x, M, start), rotate(n, M, axis(n, j)));
      const pl = axis(n, i, R).map((v, c) => (c === j ? -y0 : v));
      const nl = pl.map((v) => v / (R + r));
      expectHit(hit, L - y0, toWorld(n, x, M, pl), rotate(n, M, nl));
      if (n >= 3) {
        const k = [...Array(n).keys()].find((c) => c !== i && c !== j)!;
        // Along an axis off the plane, through the centre: the hole, a miss.
        expect(cast(n, shape, x, M, toWorld(n, x, M, axis(n, k, -L)), rotate(n, M, axis(n, k))).distance).toBe(-1);
        // The same axis through the core circle at R·e_j: the tube's cap at x_k = −r.
        const o = axis(n, j, R).map((v, c) => (c === k ? -L : v));
        hit = cast(n, shape, x, M, toWorld(n, x, M, o), rotate(n, M, axis(n, k)));
        const pk = axis(n, j, R).map((v, c) => (c === k ? -r : v));
        expectHit(hit, L - r, toWorld(n, x, M, pk), rotate(n, M, axis(n, k, -1)));
      } else {
        // 2D: the line x_i = 0 crosses the annulus at x_j = −(R + r).
        hit = cast(n, shape, x, M, toWorld(n, x, M, axis(n, j, -L)), rotate(n, M, axis(n, j)));
        expectHit(hit, L - R - r, toWorld(n, x, M, axis(n, j, -(R + r))), rotate(n, M, axis(n, j, -1)));
      }
      // Beyond maxDistance: a miss; start inside the tube: distance 0.
      expect(cast(n, shape, x, M, toWorld(n, x, M, axis(n, i, -L)), rotate(n, M, axis(n, i)), L - R - r - 1e-6).distance).toBe(
        -1,
      );
      const inTube = toWorld(n, x, M, axis(n, i, R + 0.5 * r));
      const d = rotate(n, M, axis(n, j));
      expectInside(cast(n, shape, x, M, inTube, d), inTube, d);
    }
  });

  it('torus: random rays agree with a dense scan + bisection of the implicit function', () => {
    const rand = seeded(600 + n);
    const R = 2;
    const r = 0.7;
    const shape: TorusGeometry = { kind: 'torus', majorRadius: R, minorRadius: r, planeI: 0, planeJ: n - 1 };
    const x = randomArray(rand, n, -1, 1);
    const M = randomRotation(rand, n);
    const inside = (t: number, o: Float64Array, d: Float64Array): number => {
      // Local point, then (ρ − R)² + Σ others − r² (negative inside).
      const w = o.map((v, c) => v + t * d[c]! - x[c]!);
      const q = new Float64Array(n);
      for (let c = 0; c < n; c += 1) for (let k = 0; k < n; k += 1) q[c] += M[k * n + c]! * w[k]!;
      let s = 0;
      for (let c = 1; c < n - 1; c += 1) s += q[c]! * q[c]!;
      const rho = Math.hypot(q[0]!, q[n - 1]!);
      return (rho - R) ** 2 + s - r * r;
    };
    let hits = 0;
    let misses = 0;
    for (let trial = 0; trial < 60; trial += 1) {
      const o = x.map((c) => c + uniform(rand, -4, 4)).map((v, c) => v + (c === 0 ? 4 : 0));
      // Even trials aim at a point of the surface (a hit, maybe an earlier one), odd ones anywhere.
      let target: Float64Array;
      if (trial % 2 === 0) {
        const phi = uniform(rand, 0, 2 * Math.PI);
        const tube = randomUnit(rand, n - 1);
        const q = new Float64Array(n);
        q[0] = (R + r * tube[0]!) * Math.cos(phi);
        q[n - 1] = (R + r * tube[0]!) * Math.sin(phi);
        for (let c = 1; c < n - 1; c += 1) q[c] = r * tube[c]!;
        target = toWorld(n, x, M, q);
      } else {
        target = x.map((c) => c + uniform(rand, -2.5, 2.5));
      }
      const d = unit(target.map((v, c) => v - o[c]!));
      if (inside(0, o, d) <= 0) continue;
      // Scan at 1e-3 steps, then bisect the first sign change.
      let expected = -1;
      for (let t = 0; t < 15; t += 1e-3) {
        if (inside(t + 1e-3, o, d) <= 0) {
          let lo = t;
          let hi = t + 1e-3;
          for (let it = 0; it < 60; it += 1) {
            const mid = 0.5 * (lo + hi);
            if (inside(mid, o, d) <= 0) hi = mid;
            else lo = mid;
          }
          expected = 0.5 * (lo + hi);
          break;
        }
      }
      const hit = cast(n, shape, x, M, o, d, 15);
      if (expected < 0) {
        misses += 1;
        expect(hit.distance).toBe(-1);
      } else {
        hits += 1;
        expect(Math.abs(hit.distance - expected)).toBeLessThanOrEqual(TOL);
        // The normal is the unit gradient of the implicit function at the hit.
        const h = 1e-6;
        const g = Array.from({ length: n }, (_, c) => {
          const e = axis(n, c, h);
          const fp = inside(
            0,
            hit.point.map((v, q) => v + e[q]!),
            d,
          );
          const fm = inside(
            0,
            hit.point.map((v, q) => v - e[q]!),
            d,
          );
          return (fp - fm) / (2 * h);
        });
        expectVec(hit.normal, unit(Float64Array.from(g)), 1e-6);
        expect(dot(hit.normal, d)).toBeLessThan(0);
      }
    }
    expect(hits).toBeGreaterThan(10);
    expect(misses).toBeGreaterThanOrEqual(3);
  });
});

describe('torus trace settings', () => {
  const n = 3;
  const I = Float64Array.from([1, 0, 0, 0, 1, 0, 0, 0, 1]);
  const x = new Float64Array(3);
  const shape: TorusGeometry = { kind: 'torus', majorRadius: 2, minorRadius: 0.5, planeI: 0, planeJ: 1 };

  it('tolerance: a ray passing 1e-3 outside the tube is a miss by default and a hit at tolerance 1e-2', () => {
    // The line z = 0.501 along x (y = 0) passes 1e-3 above the tube's top (z = 0.5 at ρ = 2).
    const o = Float64Array.from([-5, 0, 0.501]);
    const d = Float64Array.from([1, 0, 0]);
    const hit = createRayHit(n);
    expect(rayCastShape(n, shape, x, I, o, d, 20, hit)).toBe(-1);
    const t = rayCastShape(n, shape, x, I, o, d, 20, hit, { tolerance: 1e-2 });
    // It stops within the tolerance of the surface, near the first top point x = −2 (t = 3).
    expect(t).toBeGreaterThan(2.8);
    expect(t).toBeLessThan(3);
  });

  it('maxSteps bounds the work: a shallow ray that needs many steps reports a miss when capped', () => {
    // Down onto the top of the tube at (−2, 0, 0.5) (horizontal tangent plane) at a slope of 0.05:
    // sphere tracing gains only ~5 % per step there, and Newton finishes the job.
    const d = Float64Array.from([1, 0, -0.05]);
    const len = Math.hypot(...d);
    const o = Float64Array.from([-2, 0, 0.5]).map((v, k) => v - (3 * d[k]!) / len);
    const hit = createRayHit(n);
    expect(Math.abs(rayCastShape(n, shape, x, I, o, d, 20, hit) - 3)).toBeLessThanOrEqual(TOL);
    expectVec(hit.normal, [0, 0, 1], TOL);
    expect(rayCastShape(n, shape, x, I, o, d, 20, hit, { maxSteps: 3 })).toBe(-1);
  });
});

describe('ray cast argument checks', () => {
  const I = Float64Array.from([1, 0, 0, 0, 1, 0, 0, 0, 1]);
  const x = new Float64Array(3);
  const sphere: SphereGeometry = { kind: 'sphere', radius: 1 };
  const o = Float64Array.from([-5, 0, 0]);
  const d = Float64Array.from([1, 0, 0]);

  it('throws TypeError / RangeError naming the argument, and writes nothing', () => {
    const hit = createRayHit(3);
    hit.point.fill(7);
    hit.distance = 42;
    expect(() => rayCastShape(3, sphere, x, I, o, new Float64Array(2), 10, hit)).toThrow(/direction/);
    expect(() => rayCastShape(3, sphere, x, I, o, new Float64Array(3), 10, hit)).toThrow(RangeError);
    expect(() => rayCastShape(3, sphere, x, I, Float64Array.from([NaN, 0, 0]), d, 10, hit)).toThrow(/origin\[0\]/);
    expect(() => rayCastShape(3, sphere, x, I, o, d, -1, hit)).toThrow(/maxDistance/);
    expect(() => rayCastShape(3, sphere, x, I.subarray(0, 8), o, d, 10, hit)).toThrow(TypeError);
    expect(() => rayCastShape(3, { kind: 'sphere', radius: -1 }, x, I, o, d, 10, hit)).toThrow(/radius/);
    expect(() => rayCastShape(1, sphere, x, I, o, d, 10, hit)).toThrow(RangeError);
    expect(() => rayCastShape(3, sphere, x, I, o, d, 10, createRayHit(2))).toThrow(/outHit\.point/);
    const torus: TorusGeometry = { kind: 'torus', majorRadius: 1, minorRadius: 0.2, planeI: 1, planeJ: 1 };
    expect(() => rayCastShape(3, torus, x, I, o, d, 10, hit)).toThrow(/planeJ/);
    expect(() => rayCastShape(3, { ...torus, planeJ: 0 }, x, I, o, d, 10, hit, { maxSteps: 0 })).toThrow(/maxSteps/);
    expect(hit.distance).toBe(42);
    expectVec(hit.point, [7, 7, 7], 0);
  });
});
