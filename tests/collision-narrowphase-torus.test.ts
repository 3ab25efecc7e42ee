import { describe, expect, it } from 'vitest';
import { createManifold, createPose, maxManifoldPoints } from '../packages/engine/src/collision/manifold.js';
import type { Pose } from '../packages/engine/src/collision/manifold.js';
import type { CollisionHalfSpace, CollisionTorus } from '../packages/engine/src/collision/narrowphase-shapes.js';
import { createNarrowphaseScratch } from '../packages/engine/src/collision/narrowphase-scratch-nd.js';
import { collideTorusHalfSpace } from '../packages/engine/src/collision/torus-halfspace.js';
import { collideTorusSphere } from '../packages/engine/src/collision/torus-sphere.js';
import { randomArray, seeded, uniform } from './support/random.js';
import { turn } from './support/poses.js';
import { sphere } from './support/shapes.js';

const TOL = 1e-12;
const R = 2;
const r = 0.7;

const torus = (planeI: number, planeJ: number): CollisionTorus => ({
  kind: 'torus',
  majorRadius: R,
  minorRadius: r,
  planeI,
  planeJ,
});
function floor(n: number): CollisionHalfSpace {
  const normal = new Float64Array(n);
  normal[1] = 1;
  return { kind: 'halfspace', normal, offset: 0 };
}

describe('torus–half-space', () => {
  it('lying flat (3D, 4D): points spread round the circle, all at the analytic depth', () => {
    for (const n of [3, 4, 5]) {
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 16);
      const out = createManifold(n);
      const delta = 0.01;
      const pt = createPose(n);
      pt.x[1] = r - delta; // major plane (x, z) horizontal, the tube's bottom 0.01 under the floor
      expect(collideTorusHalfSpace(all, n, torus(0, 2), pt, floor(n), createPose(n), 0.02, scratch)).toBe(true);
      expect(all.count).toBe(8);
      expect(Array.from(all.ids.subarray(0, 8)).sort()).toEqual([0, 1, 2, 3, 4, 5, 6, 7]);
      for (let p = 0; p < all.count; p += 1) {
        expect(Math.abs(all.separations[p] + delta)).toBeLessThanOrEqual(TOL);
        const x = all.points[p * n];
        const y = all.points[p * n + 1];
        const z = all.points[p * n + 2];
        expect(Math.abs(Math.hypot(x, z) - R)).toBeLessThanOrEqual(TOL);
        expect(Math.abs(y + delta / 2)).toBeLessThanOrEqual(TOL);
        expect(all.normal[1]).toBe(-1);
      }
      collideTorusHalfSpace(out, n, torus(0, 2), pt, floor(n), createPose(n), 0.02, scratch);
      expect(out.count).toBe(Math.min(8, maxManifoldPoints(n)));
      // the kept points surround the centre: their mean lies within R/2 of the axis
      let mx = 0;
      let mz = 0;
      for (let p = 0; p < out.count; p += 1) {
        mx += out.points[p * n] / out.count;
        mz += out.points[p * n + 2] / out.count;
      }
      expect(Math.hypot(mx, mz)).toBeLessThan(R / 2);
    }
  });

  it('standing on its rim (3D, 4D): one point at the bottom of the circle, depth exact', () => {
    for (const n of [3, 4]) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const delta = 0.008;
      for (const spin of [0, 0.3, 1.1]) {
        const pt = createPose(n);
        turn(n, pt.M, 0, 1, spin); // a turn within its own (vertical) major plane changes nothing
        pt.x[1] = R + r - delta;
        expect(collideTorusHalfSpace(out, n, torus(0, 1), pt, floor(n), createPose(n), 0.02, scratch)).toBe(true);
        let deepest = 0;
        for (let p = 1; p < out.count; p += 1) if (out.separations[p] < out.separations[deepest]) deepest = p;
        expect(Math.abs(out.separations[deepest] + delta)).toBeLessThanOrEqual(TOL);
        expect(Math.abs(out.points[deepest * n])).toBeLessThanOrEqual(1e-12);
        expect(Math.abs(out.points[deepest * n + 1] + delta / 2)).toBeLessThanOrEqual(TOL);
        for (let c = 2; c < n; c += 1) expect(Math.abs(out.points[deepest * n + c])).toBeLessThanOrEqual(TOL);
        // no other point of the rim is within the margin (the circle curves away fast)
        expect(out.count).toBe(1);
      }
    }
  });

  it('tilted: the deepest separation is h0 − R·|N_major| − r (1e-12; brute force over the circle 1e-9), n = 3..6', () => {
    for (const n of [3, 4, 5, 6]) {
      const rand = seeded(600 + n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      for (let trial = 0; trial < 10; trial += 1) {
        const pt: Pose = createPose(n);
        for (let i = 0; i < n; i += 1) for (let j = i + 1; j < n; j += 1) turn(n, pt.M, i, j, uniform(rand, -Math.PI, Math.PI));
        const ni = pt.M[n + 0];
        const nj = pt.M[n + 2];
        const h0 = R * Math.hypot(ni, nj) + r - uniform(rand, 0, 0.05);
        pt.x[1] = h0;
        expect(collideTorusHalfSpace(out, n, torus(0, 2), pt, floor(n), createPose(n), 0.02, scratch)).toBe(true);
        let brute = Infinity;
        const samples = 200000;
        for (let s = 0; s < samples; s += 1) {
          const phi = (2 * Math.PI * s) / samples;
          brute = Math.min(brute, h0 + R * (ni * Math.cos(phi) + nj * Math.sin(phi)) - r);
        }
        let deepest = Infinity;
        for (let p = 0; p < out.count; p += 1) deepest = Math.min(deepest, out.separations[p]);
        // the sampled minimum is within R(1 − cos(π/samples)) < 1e-9 of the true one
        expect(Math.abs(deepest - (h0 - R * Math.hypot(ni, nj) - r))).toBeLessThanOrEqual(1e-12);
        expect(Math.abs(deepest - brute)).toBeLessThanOrEqual(1e-9);
        expect(deepest).toBeLessThanOrEqual(brute + 1e-15);
      }
    }
  });

  it('nearly flat: ring points only, depth within (tolerance/2)(1 − cos(π/8)) of the exact one', () => {
    const tie = 5e-4; // the default featureTieTolerance
    for (const n of [3, 4]) {
      const scratch = createNarrowphaseScratch(n);
      const all = createManifold(n, 16);
      for (const tilt of [1e-6, 3e-5, 0.9 * (tie / (2 * R))]) {
        const pt = createPose(n);
        turn(n, pt.M, 1, 2, tilt); // tilts the (x, z) major plane
        turn(n, pt.M, 0, 2, 0.2); // so the deepest direction falls between ring points
        const np = Math.hypot(pt.M[n], pt.M[n + 2]);
        pt.x[1] = r - 0.01;
        collideTorusHalfSpace(all, n, torus(0, 2), pt, floor(n), createPose(n), 0.02, scratch);
        expect(all.count).toBe(8);
        expect(Array.from(all.ids.subarray(0, 8)).sort()).toEqual([0, 1, 2, 3, 4, 5, 6, 7]);
        let deepest = Infinity;
        for (let p = 0; p < all.count; p += 1) deepest = Math.min(deepest, all.separations[p]);
        const exact = r - 0.01 - R * np - r;
        expect(deepest - exact).toBeGreaterThanOrEqual(-1e-15);
        expect(deepest - exact).toBeLessThanOrEqual((tie / 2) * (1 - Math.cos(Math.PI / 8)) + 1e-15);
      }
    }
  });

  it('no contact when the whole torus is above the margin', () => {
    const pt = createPose(4);
    pt.x[1] = r + 0.03;
    const out = createManifold(4);
    expect(collideTorusHalfSpace(out, 4, torus(0, 2), pt, floor(4), createPose(4), 0.02, createNarrowphaseScratch(4))).toBe(
      false,
    );
    expect(out.count).toBe(0);
  });
});

describe('torus–sphere', () => {
  it('a ball through the hole does not touch; one wider than the hole does, at R − r − ρ (3D, 4D)', () => {
    for (const n of [3, 4]) {
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      const ps = createPose(n);
      for (const along of [0, 0.4, -0.9]) {
        ps.x.fill(0);
        ps.x[n - 1] = along; // along the axis of the hole (the major plane is (0, 1))
        expect(collideTorusSphere(out, n, torus(0, 1), createPose(n), sphere(R - r - 0.05), ps, 0.02, scratch)).toBe(false);
      }
      ps.x.fill(0);
      expect(collideTorusSphere(out, n, torus(0, 1), createPose(n), sphere(R - r + 0.1), ps, 0.02, scratch)).toBe(true);
      expect(Math.abs(out.separations[0] + 0.1)).toBeLessThanOrEqual(TOL);
    }
  });

  it('on the tube: depth |s − q| − r − ρ along the normal from the nearest core point, n = 3..6', () => {
    for (const n of [3, 4, 5, 6]) {
      const rand = seeded(700 + n);
      const scratch = createNarrowphaseScratch(n);
      const out = createManifold(n);
      for (let trial = 0; trial < 20; trial += 1) {
        const pt = createPose(n);
        for (let i = 0; i < n; i += 1) for (let j = i + 1; j < n; j += 1) turn(n, pt.M, i, j, uniform(rand, -Math.PI, Math.PI));
        pt.x.set(randomArray(rand, n, -1, 1));
        // a core point q at angle φ; a unit u normal to the circle there (radial + the other axes)
        const phi = uniform(rand, 0, 2 * Math.PI);
        const u = randomArray(rand, n, -1, 1);
        const radial = uniform(rand, -1, 1);
        u[0] = radial * Math.cos(phi);
        u[1] = radial * Math.sin(phi);
        const len = Math.hypot(...u);
        for (let c = 0; c < n; c += 1) u[c] /= len;
        const dist = uniform(rand, 0.2, 1.2);
        const rho = uniform(rand, 0.1, 0.8);
        const local = new Float64Array(n);
        for (let c = 0; c < n; c += 1) local[c] = dist * u[c];
        local[0] += R * Math.cos(phi);
        local[1] += R * Math.sin(phi);
        const ps = createPose(n);
        for (let i = 0; i < n; i += 1) {
          let s = pt.x[i];
          for (let c = 0; c < n; c += 1) s += pt.M[i * n + c] * local[c];
          ps.x[i] = s;
        }
        const expected = dist - r - rho;
        const hit = collideTorusSphere(out, n, torus(0, 1), pt, sphere(rho), ps, 0.02, scratch);
        expect(hit).toBe(expected < 0.02);
        if (!hit) continue;
        expect(Math.abs(out.separations[0] - expected)).toBeLessThanOrEqual(1e-12);
        for (let i = 0; i < n; i += 1) {
          let e = 0;
          for (let c = 0; c < n; c += 1) e += pt.M[i * n + c] * u[c];
          expect(Math.abs(out.normal[i] - e)).toBeLessThanOrEqual(1e-12);
          expect(Math.abs(out.points[i] - (ps.x[i] - (rho + expected / 2) * e))).toBeLessThanOrEqual(1e-12);
        }
      }
    }
  });
});
