import { dims } from '@physin/algebra';
import { describe, expect, it } from 'vitest';
import { ballVolume, gammaHalfInteger, HalfSpace, HyperBox, HyperSphere, HyperTorus } from '@physin/engine/internal';
import { seeded, uniform } from './support/random.js';

/** |a − b| <= tol · max(|a|, |b|, tiny). */
function expectRel(actual: number, expected: number, tol: number): void {
  const scale = Math.max(Math.abs(actual), Math.abs(expected), 1e-300);
  expect(Math.abs(actual - expected) / scale).toBeLessThanOrEqual(tol);
}

/** Ball volumes by the recurrence V_n = (2π/n) V_(n−2), V_0 = 1, V_1 = 2: no Γ involved. */
function ballVolumeByRecurrence(n: number): number {
  let v = n % 2 === 0 ? 1 : 2;
  for (let m = n % 2 === 0 ? 2 : 3; m <= n; m += 2) v *= (2 * Math.PI) / m;
  return v;
}

const NS = [2, 3, 4, 5, 6];

describe('ball volume and Γ at half-integers', () => {
  it('Γ takes its exact values: Γ(1/2) = √π, Γ(5) = 24, Γ(7/2) = 15√π/8 (1e-15 relative)', () => {
    expectRel(gammaHalfInteger(0.5), Math.sqrt(Math.PI), 1e-15);
    expect(gammaHalfInteger(1)).toBe(1);
    expect(gammaHalfInteger(5)).toBe(24);
    expectRel(gammaHalfInteger(3.5), (15 * Math.sqrt(Math.PI)) / 8, 1e-15);
    expect(() => gammaHalfInteger(0.3)).toThrow(RangeError);
    expect(() => gammaHalfInteger(0)).toThrow(RangeError);
  });

  it('identity 12: unit ball volumes V_2..V_6 = π, 4π/3, π²/2, 8π²/15, π³/6 (1e-15 relative)', () => {
    const expected = [Math.PI, (4 * Math.PI) / 3, Math.PI ** 2 / 2, (8 * Math.PI ** 2) / 15, Math.PI ** 3 / 6];
    NS.forEach((n, i) => {
      expectRel(ballVolume(n, 1), expected[i], 1e-15);
      expectRel(ballVolume(n, 1), ballVolumeByRecurrence(n), 1e-15);
    });
    expect(ballVolume(0, 3)).toBe(1);
    expect(ballVolume(1, 0.7)).toBeCloseTo(1.4, 15);
    // n up to 8 and a radius: V_n(ρ) = V_n(1) ρⁿ
    for (let n = 2; n <= 8; n += 1) expectRel(ballVolume(n, 1.7), ballVolumeByRecurrence(n) * 1.7 ** n, 1e-14);
  });
});

describe('HyperSphere', () => {
  it('has volume V_n(ρ) and C_ii = mρ²/(n+2), I_(ij) = 2mρ²/(n+2) for n = 2..6 (1e-14 relative)', () => {
    const rho = 1.3;
    const m = 2.5;
    for (const n of NS) {
      const D = dims(n);
      const ball = HyperSphere(D, rho);
      expect(ball.kind).toBe('sphere');
      expect(ball.n).toBe(n);
      expect(Object.isFrozen(ball)).toBe(true);
      const mp = ball.massProperties(D, m);
      expectRel(mp.volume, ballVolumeByRecurrence(n) * rho ** n, 1e-14);
      expect(mp.covariance.length).toBe(n);
      expect(mp.inertia.length).toBe(D.k);
      for (let i = 0; i < n; i += 1) expectRel(mp.covariance[i], (m * rho * rho) / (n + 2), 1e-14);
      for (let p = 0; p < D.k; p += 1) expectRel(mp.inertia[p], (2 * m * rho * rho) / (n + 2), 1e-14);
    }
  });

  it('C_ii = mρ²/(n+2) agrees with the radial integral E[|x|²] = ∫ r² · n rⁿ⁻¹ dr / ρⁿ, divided by n (midpoint rule, 1e-8)', () => {
    const rho = 0.9;
    for (const n of NS) {
      const steps = 20000;
      let sum = 0;
      for (let s = 0; s < steps; s += 1) {
        const r = ((s + 0.5) / steps) * rho;
        sum += r * r * n * r ** (n - 1) * (rho / steps);
      }
      const perAxis = sum / rho ** n / n;
      const mp = HyperSphere(dims(n), rho).massProperties(dims(n), 1);
      expectRel(mp.covariance[0], perAxis, 1e-8);
    }
  });

  it('refuses a bad radius and bad massProperties arguments', () => {
    const D = dims(3);
    expect(() => HyperSphere(D, 0)).toThrow(RangeError);
    expect(() => HyperSphere(D, -1)).toThrow(/'radius' must be > 0/);
    expect(() => HyperSphere(D, Number.NaN)).toThrow(RangeError);
    expect(() => HyperSphere(D, Number.POSITIVE_INFINITY)).toThrow(RangeError);
    expect(() => HyperSphere(D, '1' as unknown as number)).toThrow(TypeError);
    const ball = HyperSphere(D, 1);
    expect(() => ball.massProperties(dims(3), 0)).toThrow(/'mass' must be > 0/);
    expect(() => ball.massProperties(dims(3), Number.NaN)).toThrow(RangeError);
    expect(() => ball.massProperties({ n: 3 } as never, 1)).toThrow(TypeError);
    expect(() => ball.massProperties(dims(4), 1)).toThrow(/built for n = 3/);
    expect(() => HyperSphere({ n: 3 } as never, 1)).toThrow(/argument 'D'/);
  });
});

describe('HyperBox', () => {
  it('identity 11: the unit cube of mass 1 has C = diag(1/12) and I = 1/6 on every plane (n = 3, 4; 1e-15)', () => {
    for (const n of [3, 4]) {
      const D = dims(n);
      const mp = HyperBox(D, new Array(n).fill(0.5)).massProperties(D, 1);
      expectRel(mp.volume, 1, 1e-15);
      for (let i = 0; i < n; i += 1) expectRel(mp.covariance[i], 1 / 12, 1e-15);
      for (let p = 0; p < D.k; p += 1) expectRel(mp.inertia[p], 1 / 6, 1e-15);
    }
  });

  it('has volume ∏ 2a_i, C_ii = m a_i²/3 and I_(ij) = C_ii + C_jj for n = 2..6 (1e-14 relative)', () => {
    const rand = seeded(11);
    for (const n of NS) {
      const D = dims(n);
      const a = Array.from({ length: n }, () => uniform(rand, 0.2, 2));
      const m = uniform(rand, 0.5, 3);
      const box = HyperBox(D, a);
      expect(box.kind).toBe('box');
      expect(box.n).toBe(n);
      expect(Array.from(box.halfExtents)).toEqual(a);
      expect(Object.isFrozen(box)).toBe(true);
      const mp = box.massProperties(D, m);
      expectRel(
        mp.volume,
        a.reduce((v, x) => v * 2 * x, 1),
        1e-14,
      );
      for (let i = 0; i < n; i += 1) expectRel(mp.covariance[i], (m * a[i] * a[i]) / 3, 1e-14);
      for (let p = 0; p < D.k; p += 1) {
        const i = D.planeI[p];
        const j = D.planeJ[p];
        expectRel(mp.inertia[p], (m * (a[i] * a[i] + a[j] * a[j])) / 3, 1e-14);
      }
    }
  });

  it('copies its input and refuses bad arguments before building anything', () => {
    const D = dims(3);
    const input = [1, 2, 3];
    const box = HyperBox(D, input);
    input[0] = 99;
    expect(box.halfExtents[0]).toBe(1);
    expect(() => HyperBox(D, [1, 2])).toThrow(TypeError);
    expect(() => HyperBox(D, [1, 2])).toThrow(/'halfExtents' must have length 3/);
    expect(() => HyperBox(D, [1, 0, 3])).toThrow(/'halfExtents'\[1\] must be > 0/);
    expect(() => HyperBox(D, [1, -2, 3])).toThrow(RangeError);
    expect(() => HyperBox(D, [1, Number.NaN, 3])).toThrow(RangeError);
    expect(() => HyperBox(D, 'abc' as never)).toThrow(TypeError);
    expect(() => HyperBox(undefined as never, [1, 2, 3])).toThrow(/'D' must be the tables/);
    expect(() => box.massProperties(dims(4), 1)).toThrow(/n = 4 but the shape was built for n = 3/);
    expect(() => box.massProperties(D, -1)).toThrow(RangeError);
  });
});

describe('HalfSpace', () => {
  it('normalises its normal, scales the offset with it, and keeps the same plane', () => {
    const D = dims(4);
    const h = HalfSpace(D, [0, 2, 0, 0], 3);
    expect(h.kind).toBe('halfspace');
    expect(h.n).toBe(4);
    expect(Array.from(h.normal)).toEqual([0, 1, 0, 0]);
    expect(h.offset).toBe(1.5);
    const tilted = HalfSpace(dims(3), [3, 4, 0], 10);
    expect(tilted.normal[0]).toBeCloseTo(0.6, 15);
    expect(tilted.normal[1]).toBeCloseTo(0.8, 15);
    expect(tilted.offset).toBeCloseTo(2, 15);
    // a point of the given plane, 3x + 4y = 10, stays on the stored one
    expect(tilted.normal[0] * 2 + tilted.normal[1] * 1 - tilted.offset).toBeCloseTo(0, 14);
    expect(Object.isFrozen(h)).toBe(true);
  });

  it('has no mass: massProperties throws a RangeError saying so', () => {
    const D = dims(3);
    expect(() => HalfSpace(D, [0, 1, 0], 0).massProperties(D, 1)).toThrow(RangeError);
    expect(() => HalfSpace(D, [0, 1, 0], 0).massProperties(D, 1)).toThrow(/no mass.*static only/);
  });

  it('refuses a zero normal, a wrong length and non-finite numbers', () => {
    const D = dims(3);
    expect(() => HalfSpace(D, [0, 0, 0], 0)).toThrow(/'normal' must be a non-zero vector/);
    expect(() => HalfSpace(D, [0, 1], 0)).toThrow(TypeError);
    expect(() => HalfSpace(D, [0, Number.NaN, 0], 0)).toThrow(RangeError);
    expect(() => HalfSpace(D, [0, 1, 0], Number.POSITIVE_INFINITY)).toThrow(/'offset' must be finite/);
  });
});

describe('HyperTorus', () => {
  it('identity 14: R = 2, r = 0.7 has volume 19.344 in 3D and 18.055 in 4D (to the 3 decimals quoted)', () => {
    expect(Math.abs(HyperTorus(dims(3), 2, 0.7, 0).massProperties(dims(3), 1).volume - 19.344)).toBeLessThan(5e-4);
    expect(Math.abs(HyperTorus(dims(4), 2, 0.7, 0).massProperties(dims(4), 1).volume - 18.055)).toBeLessThan(5e-4);
    // and exactly: 2πR·πr² and 2πR·(4/3)πr³
    expectRel(HyperTorus(dims(3), 2, 0.7, 0).massProperties(dims(3), 1).volume, 4 * Math.PI ** 2 * 0.49, 1e-15);
    expectRel(HyperTorus(dims(4), 2, 0.7, 0).massProperties(dims(4), 1).volume, (16 / 3) * Math.PI ** 2 * 0.343, 1e-15);
  });

  it('identity 15: 3D inertia m(R² + 3r²/4) about the axis and m(4R² + 5r²)/8 about a diameter (1e-15)', () => {
    const D = dims(3);
    const [R, r, m] = [2, 0.7, 3.1];
    // core circle in the xz plane (index 1): the symmetry axis is y, so the xz plane is the spin plane
    const mp = HyperTorus(D, R, r, [2, 0]).massProperties(D, m);
    const xy = 0;
    const xz = 1;
    const yz = 2;
    expectRel(mp.inertia[xz], m * (R * R + (3 * r * r) / 4), 1e-15);
    expectRel(mp.inertia[xy], (m * (4 * R * R + 5 * r * r)) / 8, 1e-15);
    expectRel(mp.inertia[yz], (m * (4 * R * R + 5 * r * r)) / 8, 1e-15);
  });

  it('2D: the annulus R ± r has area 4πRr and C_ii = m(R² + r²)/2 (1e-15)', () => {
    const D = dims(2);
    const mp = HyperTorus(D, 1.5, 0.5, 0).massProperties(D, 2);
    expectRel(mp.volume, Math.PI * (2 * 2 - 1 * 1), 1e-15);
    expectRel(mp.covariance[0], (2 * (1.5 ** 2 + 0.5 ** 2)) / 2, 1e-15);
  });

  it('matches a Monte Carlo integral of its defining inequality for n = 2..6 (fixed seed, within 4 standard errors)', () => {
    const [R, r] = [1.6, 0.55];
    const rand = seeded(2024);
    for (const n of NS) {
      const D = dims(n);
      const [pi, pj] = n === 2 ? [0, 1] : [1, n - 1];
      const torus = HyperTorus(D, R, r, [pi, pj]);
      const mp = torus.massProperties(D, 1);
      const half = new Array(n).fill(r);
      half[pi] = R + r;
      half[pj] = R + r;
      const boxVolume = half.reduce((v, x) => v * 2 * x, 1);
      const samples = 150_000;
      let hits = 0;
      const sum2 = new Float64Array(n);
      const sum4 = new Float64Array(n);
      const x = new Float64Array(n);
      for (let s = 0; s < samples; s += 1) {
        for (let c = 0; c < n; c += 1) x[c] = uniform(rand, -half[c], half[c]);
        let other = 0;
        for (let c = 0; c < n; c += 1) if (c !== pi && c !== pj) other += x[c] * x[c];
        const rho = Math.hypot(x[pi], x[pj]);
        if ((rho - R) ** 2 + other > r * r) continue;
        hits += 1;
        for (let c = 0; c < n; c += 1) {
          sum2[c] += x[c] * x[c];
          sum4[c] += x[c] ** 4;
        }
      }
      const p = hits / samples;
      const volume = p * boxVolume;
      const volumeSE = boxVolume * Math.sqrt((p * (1 - p)) / samples);
      expect(Math.abs(volume - mp.volume)).toBeLessThan(4 * volumeSE);
      for (let c = 0; c < n; c += 1) {
        const mean = sum2[c] / hits;
        const se = Math.sqrt((sum4[c] / hits - mean * mean) / hits);
        expect(Math.abs(mean - mp.covariance[c])).toBeLessThan(4 * se);
      }
    }
  });

  it('takes the plane as an index or a pair in either order, and stores planeI < planeJ', () => {
    const D = dims(4);
    const a = HyperTorus(D, 2, 0.5, 4); // yw
    const b = HyperTorus(D, 2, 0.5, [3, 1]);
    for (const t of [a, b]) {
      expect([t.planeI, t.planeJ, t.plane]).toEqual([1, 3, 4]);
      expect(t.kind).toBe('torus');
      expect(t.n).toBe(4);
      expect(Object.isFrozen(t)).toBe(true);
    }
    expect(Array.from(a.massProperties(D, 1).covariance)).toEqual(Array.from(b.massProperties(D, 1).covariance));
    const c = a.massProperties(D, 1).covariance;
    expect(c[1]).toBe(c[3]);
    expect(c[0]).toBe(c[2]);
    expect(c[1]).toBeGreaterThan(c[0]);
  });

  it('refuses r >= R, non-positive radii and bad planes', () => {
    const D = dims(3);
    expect(() => HyperTorus(D, 1, 1, 0)).toThrow(/'minorRadius' must be < 'majorRadius'/);
    expect(() => HyperTorus(D, 1, 2, 0)).toThrow(RangeError);
    expect(() => HyperTorus(D, 1, 0, 0)).toThrow(/'minorRadius' must be > 0/);
    expect(() => HyperTorus(D, -1, 0.5, 0)).toThrow(/'majorRadius' must be > 0/);
    expect(() => HyperTorus(D, 2, 0.5, 3)).toThrow(/'plane' must be an integer in \[0, 2\]/);
    expect(() => HyperTorus(D, 2, 0.5, 0.5)).toThrow(RangeError);
    expect(() => HyperTorus(D, 2, 0.5, [1, 1])).toThrow(/two different axes/);
    expect(() => HyperTorus(D, 2, 0.5, [0, 3])).toThrow(RangeError);
    expect(() => HyperTorus(D, 2, 0.5, [0, 1, 2])).toThrow(TypeError);
    expect(() => HyperTorus(D, 2, 0.5, 'xy' as never)).toThrow(TypeError);
  });
});
