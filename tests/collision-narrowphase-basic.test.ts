import { afterEach, describe, expect, it, vi } from 'vitest';
import { boxColliders } from '../packages/engine/src/collision/box-colliders.js';
import { collideBoxHalfSpace } from '../packages/engine/src/collision/box-halfspace.js';
import { collideBoxSphere } from '../packages/engine/src/collision/box-sphere.js';
import { collide, collidePair } from '../packages/engine/src/collision/collide.js';
import { createManifold, createPose, maxManifoldPoints } from '../packages/engine/src/collision/manifold.js';
import type { CollidableShape } from '../packages/engine/src/collision/manifold.js';
import { createNarrowphaseScratch } from '../packages/engine/src/collision/narrowphase-scratch-nd.js';
import { collideSphereHalfSpace } from '../packages/engine/src/collision/sphere-halfspace.js';
import { sphereColliders } from '../packages/engine/src/collision/sphere-colliders.js';
import { collideSphereSphere } from '../packages/engine/src/collision/sphere-sphere.js';
import { resetCollisionWarnings, warnOnce } from '../packages/engine/src/collision/warn-once.js';
import { randomArray, seeded, uniform } from './support/random.js';
import { randomPose, turn } from './support/poses.js';
import { box, plane, sphere } from './support/shapes.js';

const DIMS = [2, 3, 4, 5, 6];
const TOL = 1e-12;

function norm(v: ArrayLike<number>, n: number): number {
  let s = 0;
  for (let i = 0; i < n; i += 1) s += v[i] * v[i];
  return Math.sqrt(s);
}

describe('sphere–sphere', () => {
  it('depth, normal and midpoint are exact, any n', () => {
    for (const n of DIMS) {
      const rand = seeded(100 + n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      for (let trial = 0; trial < 20; trial += 1) {
        const pa = randomPose(rand, n, 2);
        const pb = randomPose(rand, n, 2);
        const ra = uniform(rand, 0.2, 2);
        const rb = uniform(rand, 0.2, 2);
        const d = new Float64Array(n);
        for (let c = 0; c < n; c += 1) d[c] = pb.x[c] - pa.x[c];
        const dist = norm(d, n);
        const hit = collideSphereSphere(out, n, sphere(ra), pa, sphere(rb), pb, 0.02, scratch);
        expect(hit).toBe(dist - ra - rb < 0.02);
        if (!hit) {
          expect(out.count).toBe(0);
          continue;
        }
        expect(Math.abs(out.separations[0] - (dist - ra - rb))).toBeLessThanOrEqual(TOL * 10);
        for (let c = 0; c < n; c += 1) {
          expect(Math.abs(out.normal[c] - d[c] / dist)).toBeLessThanOrEqual(TOL);
          // midway between x_A + ρ_A N and x_B − ρ_B N
          const mid = (pa.x[c] + (ra * d[c]) / dist + pb.x[c] - (rb * d[c]) / dist) / 2;
          expect(Math.abs(out.points[c] - mid)).toBeLessThanOrEqual(TOL * 10);
        }
      }
    }
  });

  it('coincident centres: normal e_0, depth the sum of radii', () => {
    const out = createManifold(3);
    collideSphereSphere(out, 3, sphere(1), createPose(3), sphere(0.5), createPose(3), 0, createNarrowphaseScratch(3));
    expect(Array.from(out.normal)).toEqual([1, 0, 0]);
    expect(out.separations[0]).toBe(-1.5);
  });
});

describe('sphere–half-space', () => {
  it('depth = height − ρ, normal −N, point midway (non-unit normal, posed plane), any n', () => {
    for (const n of DIMS) {
      const rand = seeded(200 + n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      for (let trial = 0; trial < 20; trial += 1) {
        const local = randomArray(rand, n, -1, 1);
        const offset = uniform(rand, -1, 1);
        const ph = randomPose(rand, n, 1);
        const ps = randomPose(rand, n, 2);
        const rho = uniform(rand, 0.1, 1);
        // world plane: N = M n/|n|, height = offset/|n| + N·x
        const len = norm(local, n);
        const N = new Float64Array(n);
        let h = offset / len;
        for (let i = 0; i < n; i += 1) {
          for (let c = 0; c < n; c += 1) N[i] += (ph.M[i * n + c] * local[c]) / len;
          h += N[i] * ph.x[i];
        }
        let height = -h;
        for (let i = 0; i < n; i += 1) height += N[i] * ps.x[i];
        const hit = collideSphereHalfSpace(out, n, sphere(rho), ps, plane(local, offset), ph, 0.05, scratch);
        expect(hit).toBe(height - rho < 0.05);
        if (!hit) continue;
        expect(Math.abs(out.separations[0] - (height - rho))).toBeLessThanOrEqual(1e-12);
        for (let i = 0; i < n; i += 1) {
          expect(Math.abs(out.normal[i] + N[i])).toBeLessThanOrEqual(1e-12);
          expect(Math.abs(out.points[i] - (ps.x[i] - ((rho + height) / 2) * N[i]))).toBeLessThanOrEqual(1e-12);
        }
      }
    }
  });
});

describe('box–sphere', () => {
  it('outside a face, an edge-type feature and a corner: exact depth and normal, any n', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const rand = seeded(300 + n);
      const pb = randomPose(rand, n, 1);
      const half = randomArray(rand, n, 0.5, 1.5);
      for (let clamped = 1; clamped <= n; clamped += 1) {
        // centre beyond the box on the first `clamped` axes by 0.3 each, inside on the others
        const local = new Float64Array(n);
        const gap = new Float64Array(n);
        for (let c = 0; c < n; c += 1) {
          local[c] = c < clamped ? half[c] + 0.3 : 0.5 * half[c];
          gap[c] = c < clamped ? 0.3 : 0;
        }
        const dist = 0.3 * Math.sqrt(clamped);
        const rho = dist + 0.01; // overlap 0.01
        const ps = createPose(n);
        for (let i = 0; i < n; i += 1) {
          let s = pb.x[i];
          for (let c = 0; c < n; c += 1) s += pb.M[i * n + c] * local[c];
          ps.x[i] = s;
        }
        expect(collideBoxSphere(out, n, box(half), pb, sphere(rho), ps, 0.02, scratch)).toBe(true);
        expect(Math.abs(out.separations[0] + 0.01)).toBeLessThanOrEqual(1e-12);
        for (let i = 0; i < n; i += 1) {
          let e = 0;
          for (let c = 0; c < n; c += 1) e += (pb.M[i * n + c] * gap[c]) / dist;
          expect(Math.abs(out.normal[i] - e)).toBeLessThanOrEqual(1e-12);
        }
        // id: base-3 digit 2 (clamped at +a) on the clamped axes
        let id = 0;
        for (let c = 0; c < clamped; c += 1) id += 2 * 3 ** c;
        expect(out.ids[0]).toBe(id);
      }
    }
  });

  it('centre inside: pushed out along the axis of least depth', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const half = new Float64Array(n).fill(1);
      const ps = createPose(n);
      const axis = n - 1;
      ps.x.fill(0.2);
      ps.x[axis] = -0.9; // depth 0.1 below the −a face of the last axis; 0.8 on the others
      expect(collideBoxSphere(out, n, box(half), createPose(n), sphere(0.25), ps, 0, scratch)).toBe(true);
      expect(Math.abs(out.separations[0] - (-0.1 - 0.25))).toBeLessThanOrEqual(1e-12);
      for (let c = 0; c < n; c += 1) expect(out.normal[c] + 0).toBe(c === axis ? -1 : 0); // + 0: −0 is fine
      expect(out.ids[0]).toBe(3 ** n + 2 * axis);
    }
  });

  it('no contact beyond the margin', () => {
    const ps = createPose(3);
    ps.x[0] = 1 + 0.5 + 0.021;
    const out = createManifold(3);
    expect(collideBoxSphere(out, 3, box([1, 1, 1]), createPose(3), sphere(0.5), ps, 0.02, createNarrowphaseScratch(3))).toBe(
      false,
    );
    expect(out.count).toBe(0);
  });
});

describe('box–half-space', () => {
  it('keeps the corners below the plane + margin with their exact heights, any n', () => {
    for (const n of DIMS) {
      const rand = seeded(400 + n);
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 1 << n);
      for (let trial = 0; trial < 10; trial += 1) {
        const pb = randomPose(rand, n, 0.3);
        const half = randomArray(rand, n, 0.3, 1);
        const N = new Float64Array(n);
        N[1] = 1;
        const margin = 0.05;
        const hit = collideBoxHalfSpace(all, n, box(half), pb, plane(N, 0), createPose(n), margin, scratch);
        // brute force over the corners
        const expected = new Map<number, number>();
        for (let mask = 0; mask < 1 << n; mask += 1) {
          let y = pb.x[1];
          for (let c = 0; c < n; c += 1) y += pb.M[n + c] * (mask & (1 << c) ? half[c] : -half[c]);
          if (y < margin) expected.set(mask, y);
        }
        expect(hit).toBe(expected.size > 0);
        expect(all.count).toBe(expected.size);
        for (let p = 0; p < all.count; p += 1) {
          const h = expected.get(all.ids[p]);
          expect(h).toBeDefined();
          expect(Math.abs(all.separations[p] - (h as number))).toBeLessThanOrEqual(1e-12);
          expect(Math.abs(all.points[p * n + 1] - (h as number) / 2)).toBeLessThanOrEqual(1e-12);
          expect(all.normal[1]).toBe(-1);
        }
      }
    }
  });

  it('a box lying flat is reduced to the bound, deepest first', () => {
    for (const n of DIMS) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const pb = createPose(n);
      turn(n, pb.M, 0, 1, 0.001);
      pb.x[1] = 0.49;
      expect(
        collideBoxHalfSpace(
          out,
          n,
          box(new Float64Array(n).fill(0.5)),
          pb,
          plane([0, 1, 0, 0, 0, 0].slice(0, n), 0),
          createPose(n),
          0.02,
          scratch,
        ),
      ).toBe(true);
      expect(out.count).toBe(Math.min(1 << (n - 1), maxManifoldPoints(n)));
      for (let p = 1; p < out.count; p += 1) expect(out.separations[0]).toBeLessThanOrEqual(out.separations[p]);
    }
  });
});

describe('dispatch', () => {
  afterEach(() => {
    vi.restoreAllMocks();
    resetCollisionWarnings();
  });

  it('swaps roles when only B owns the pair: normal flipped, points, depths and ids unchanged', () => {
    const n = 4;
    const scratch = createNarrowphaseScratch(n);
    const rand = seeded(500);
    const ab = createManifold(n);
    const ba = createManifold(n);
    const B: CollidableShape = { ...box([0.5, 0.6, 0.7, 0.8]), colliders: boxColliders };
    const S: CollidableShape = { ...sphere(0.6), colliders: sphereColliders };
    const H: CollidableShape = { ...plane([0, 1, 0, 0], 0) };
    for (let trial = 0; trial < 10; trial += 1) {
      const pb = randomPose(rand, n, 0.3);
      pb.x[1] = 0.6;
      const ps = randomPose(rand, n, 1);
      // sphere–box: only the box owns it
      const hit = collide(ab, n, S, ps, B, pb, 0.02, scratch);
      expect(collide(ba, n, B, pb, S, ps, 0.02, scratch)).toBe(hit);
      if (hit) {
        for (let c = 0; c < n; c += 1) {
          expect(ab.normal[c]).toBe(-ba.normal[c]);
          expect(ab.points[c]).toBe(ba.points[c]);
        }
        expect(ab.separations[0]).toBe(ba.separations[0]);
        expect(ab.ids[0]).toBe(ba.ids[0]);
      }
      // half-space first: its pairs live in the box's table
      expect(collide(ab, n, H, createPose(n), B, pb, 0.02, scratch)).toBe(collide(ba, n, B, pb, H, createPose(n), 0.02, scratch));
      for (let c = 0; c < n; c += 1) expect(ab.normal[c]).toBe(-ba.normal[c]);
      expect(Array.from(ab.ids.subarray(0, ab.count))).toEqual(Array.from(ba.ids.subarray(0, ba.count)));
    }
  });

  it('a pair with no collider in either table passes through and warns exactly once per kind pair', () => {
    // Every pair of the engine's shapes has a collider (tests/collision-every-pair.test.ts); a
    // shape without its table (a user's own object) or two half-spaces have none.
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
    resetCollisionWarnings();
    const n = 3;
    const scratch = createNarrowphaseScratch(n);
    const out = createManifold(n);
    const pose = createPose(n);
    const T: CollidableShape = { kind: 'torus' };
    const B: CollidableShape = { kind: 'box' };
    const H: CollidableShape = { kind: 'halfspace' };
    const pairs: [CollidableShape, CollidableShape][] = [
      [T, B],
      [B, T],
      [H, H],
      [T, H],
      [H, T],
    ];
    for (let round = 0; round < 3; round += 1) {
      for (const [a, b] of pairs) {
        out.count = 7;
        expect(collide(out, n, a, pose, b, pose, 0.02, scratch)).toBe(false);
        expect(out.count).toBe(0);
      }
    }
    // three kind pairs: torus–box, halfspace–halfspace, torus–halfspace
    expect(warn).toHaveBeenCalledTimes(3);
    const messages = warn.mock.calls.map((call) => String(call[0]));
    expect(messages.some((m) => m.includes('torus') && m.includes('box'))).toBe(true);
    expect(messages.some((m) => m.includes('a halfspace and a halfspace'))).toBe(true);
    expect(warnOnce('box', 'torus')).toBe(false);
    resetCollisionWarnings();
    expect(warnOnce('box', 'torus')).toBe(true);
    expect(warn).toHaveBeenCalledTimes(4);
  });

  it('collidePair validates before writing', () => {
    const n = 3;
    const scratch = createNarrowphaseScratch(n);
    const out = createManifold(n);
    out.count = 5;
    const S: CollidableShape = { ...sphere(1), colliders: sphereColliders };
    const pose = createPose(n);
    expect(() => collidePair(out, n, S, pose, S, pose, -1, scratch)).toThrow(RangeError);
    expect(() => collidePair(out, n, S, pose, S, pose, Number.NaN, scratch)).toThrow(/margin/);
    expect(() => collidePair(out, n, S, { x: new Float64Array(2), M: pose.M }, S, pose, 0, scratch)).toThrow(TypeError);
    expect(() => collidePair(out, 4, S, pose, S, pose, 0, scratch)).toThrow(RangeError);
    expect(() => collidePair(out, n, S, pose, S, pose, 0, createNarrowphaseScratch(4))).toThrow(/scratch/);
    expect(() =>
      collidePair(out, n, { kind: 'box', halfExtents: [1, -1, 1] } as CollidableShape, pose, S, pose, 0, scratch),
    ).toThrow(/halfExtents/);
    expect(out.count).toBe(5);
    const pb = createPose(n);
    pb.x[0] = 1.5;
    expect(collidePair(out, n, S, pose, S, pb, 0, scratch)).toBe(true);
    expect(out.separations[0]).toBe(-0.5);
  });

  it('createManifold and createNarrowphaseScratch validate', () => {
    expect(() => createManifold(1)).toThrow(RangeError);
    expect(() => createManifold(3, 0)).toThrow(RangeError);
    expect(() => createManifold(3, 1.5)).toThrow(TypeError);
    expect(() => createNarrowphaseScratch(9)).toThrow(RangeError);
    expect(() => createNarrowphaseScratch(3, { axisTolerance: -1 })).toThrow(/axisTolerance/);
    expect(() => createNarrowphaseScratch(3, { torusRingPoints: 2 })).toThrow(RangeError);
    expect([2, 3, 4, 5, 6, 7, 8].map(maxManifoldPoints)).toEqual([2, 4, 8, 16, 32, 32, 32]);
  });
});
