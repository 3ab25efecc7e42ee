import { describe, expect, it } from 'vitest';
import {
  bivectorApply,
  bivectorDot,
  dims,
  inertiaDiagonal,
  inertiaFromCovariance,
  inertiaWorldInverse,
  parallelAxisShift,
  rotorApplyBivector,
  rotorApplyVector,
  rotorExp,
  rotorToMatrix,
  symmetricEigen,
  wedge,
} from '@physin/algebra';
import { randomArray, seeded } from './support/random.js';
import { maxDiff } from './support/compare.js';

/** A cloud of point masses: positions (n each) and masses. */
function cloud(n: number, count: number, rand: () => number): { x: Float64Array[]; m: number[] } {
  const x: Float64Array[] = [];
  const m: number[] = [];
  for (let s = 0; s < count; s += 1) {
    x.push(randomArray(rand, n, -1, 1));
    m.push(0.5 + rand());
  }
  return { x, m };
}

function covarianceAbout(n: number, x: Float64Array[], m: number[], p: ArrayLike<number>): Float64Array {
  const C = new Float64Array(n * n);
  x.forEach((xi, s) => {
    for (let i = 0; i < n; i += 1) {
      for (let j = 0; j < n; j += 1) C[i * n + j] = C[i * n + j]! + m[s]! * (xi[i]! - p[i]!) * (xi[j]! - p[j]!);
    }
  });
  return C;
}

function applyOperator(k: number, I: ArrayLike<number>, w: ArrayLike<number>): Float64Array {
  const out = new Float64Array(k);
  for (let p = 0; p < k; p += 1) for (let q = 0; q < k; q += 1) out[p] = out[p]! + I[p * k + q]! * w[q]!;
  return out;
}

describe('inertia from covariance', () => {
  it('unit box, m = 1: C = diag(1/12) gives the classical 1/6 on every plane in 3D (1e-16)', () => {
    const D = dims(3);
    const I = inertiaFromCovariance(D, new Float64Array(9), [1 / 12, 0, 0, 0, 1 / 12, 0, 0, 0, 1 / 12]);
    expect(maxDiff(I, [1 / 6, 0, 0, 0, 1 / 6, 0, 0, 0, 1 / 6])).toBeLessThan(1e-16);
    // A 2×1×0.5 box (half-extents a = 1, 0.5, 0.25, C_ii = m a_i²/3), m = 3: I_xy = m(a_x² + a_y²)/3 etc.
    const a = [1, 0.5, 0.25];
    const c = a.map((ai) => (3 * ai * ai) / 3);
    const Ibox = inertiaDiagonal(D, new Float64Array(3), c);
    expect(maxDiff(Ibox, [1 + 0.25, 1 + 0.0625, 0.25 + 0.0625])).toBeLessThan(1e-15);
  });

  for (let n = 2; n <= 6; n += 1) {
    it(`n = ${n}: L = I ω equals Σ m r ∧ (ω r) over a point cloud (angular momentum of the points) (1e-13)`, () => {
      const D = dims(n);
      const rand = seeded(500 + n);
      const { x, m } = cloud(n, 30, rand);
      const C = covarianceAbout(n, x, m, new Float64Array(n));
      const I = inertiaFromCovariance(D, new Float64Array(D.k * D.k), C);
      const w = randomArray(rand, D.k);
      const L = new Float64Array(D.k);
      const v = new Float64Array(n);
      const rv = new Float64Array(D.k);
      x.forEach((xi, s) => {
        bivectorApply(D, v, w, xi);
        wedge(D, rv, xi, v);
        for (let p = 0; p < D.k; p += 1) L[p] = L[p]! + m[s]! * rv[p]!;
      });
      expect(maxDiff(applyOperator(D.k, I, w), L)).toBeLessThan(1e-13);
      // Kinetic energy two ways: ½ ω·Iω = ½ Σ m |ω r|².
      let ke = 0;
      x.forEach((xi, s) => {
        bivectorApply(D, v, w, xi);
        for (const vi of v) ke += 0.5 * m[s]! * vi * vi;
      });
      expect(Math.abs(0.5 * bivectorDot(D, w, applyOperator(D.k, I, w)) - ke)).toBeLessThan(1e-13);
    });

    it(`n = ${n}: inertiaDiagonal equals inertiaFromCovariance in the principal frame of C (1e-13)`, () => {
      const D = dims(n);
      const rand = seeded(600 + n);
      const { x, m } = cloud(n, 25, rand);
      const C = covarianceAbout(n, x, m, new Float64Array(n));
      const values = new Float64Array(n);
      const V = new Float64Array(n * n);
      symmetricEigen(n, values, V, C);
      // C in the principal frame: Vᵀ C V, diagonal with the eigenvalues.
      const Cp = new Float64Array(n * n);
      for (let a = 0; a < n; a += 1) {
        for (let b = 0; b < n; b += 1) {
          let s = 0;
          for (let i = 0; i < n; i += 1) for (let j = 0; j < n; j += 1) s += V[i * n + a]! * C[i * n + j]! * V[j * n + b]!;
          Cp[a * n + b] = s;
        }
      }
      const full = inertiaFromCovariance(D, new Float64Array(D.k * D.k), Cp);
      const diag = inertiaDiagonal(D, new Float64Array(D.k), values);
      const diagOp = new Float64Array(D.k * D.k);
      for (let p = 0; p < D.k; p += 1) diagOp[p * D.k + p] = diag[p]!;
      expect(maxDiff(full, diagOp)).toBeLessThan(1e-13);
    });

    it(`n = ${n}: the operator of the rotated covariance is the rotated operator, I(M C Mᵀ)(R B R~) = R (I(C) B) R~ (1e-13)`, () => {
      const D = dims(n);
      const rand = seeded(700 + n);
      const { x, m } = cloud(n, 20, rand);
      const C = covarianceAbout(n, x, m, new Float64Array(n));
      const R = rotorExp(D, new Float64Array(D.r), randomArray(rand, D.k, -2, 2));
      const M = rotorToMatrix(D, new Float64Array(n * n), R);
      // Rotated cloud → its covariance is M C Mᵀ.
      const xr = x.map((xi) => rotorApplyVector(D, new Float64Array(n), R, xi));
      const Cr = covarianceAbout(n, xr, m, new Float64Array(n));
      const MCMt = new Float64Array(n * n);
      for (let a = 0; a < n; a += 1) {
        for (let b = 0; b < n; b += 1) {
          let s = 0;
          for (let i = 0; i < n; i += 1) for (let j = 0; j < n; j += 1) s += M[a * n + i]! * C[i * n + j]! * M[b * n + j]!;
          MCMt[a * n + b] = s;
        }
      }
      expect(maxDiff(Cr, MCMt)).toBeLessThan(1e-13);
      const I = inertiaFromCovariance(D, new Float64Array(D.k * D.k), C);
      const Ir = inertiaFromCovariance(D, new Float64Array(D.k * D.k), Cr);
      const B = randomArray(rand, D.k);
      const lhs = applyOperator(D.k, Ir, rotorApplyBivector(D, new Float64Array(D.k), R, B));
      const rhs = rotorApplyBivector(D, new Float64Array(D.k), R, applyOperator(D.k, I, B));
      expect(maxDiff(lhs, rhs)).toBeLessThan(1e-13);
    });

    it(`n = ${n}: parallelAxisShift matches the covariance of the cloud about another point, both ways (1e-13)`, () => {
      const D = dims(n);
      const rand = seeded(800 + n);
      const { x, m } = cloud(n, 20, rand);
      const mass = m.reduce((a, b) => a + b, 0);
      const c = new Float64Array(n);
      x.forEach((xi, s) => {
        for (let i = 0; i < n; i += 1) c[i] = c[i]! + (m[s]! * xi[i]!) / mass;
      });
      const p = randomArray(rand, n, -3, 3);
      const d = c.map((ci, i) => ci - p[i]!); // centre of mass as seen from p
      const Ccm = covarianceAbout(n, x, m, c);
      const Cp = covarianceAbout(n, x, m, p);
      expect(maxDiff(parallelAxisShift(D, new Float64Array(n * n), Ccm, mass, d), Cp)).toBeLessThan(1e-13);
      expect(maxDiff(parallelAxisShift(D, new Float64Array(n * n), Cp, -mass, d), Ccm)).toBeLessThan(1e-13);
    });

    it(`n = ${n}: inertiaWorldInverse equals the inverse of the world operator R I R~ applied to L (1e-12)`, () => {
      const D = dims(n);
      const rand = seeded(900 + n);
      const c = randomArray(rand, n, 0.2, 2);
      const Idiag = inertiaDiagonal(D, new Float64Array(D.k), c);
      const inv = Idiag.map((x) => 1 / x);
      const R = rotorExp(D, new Float64Array(D.r), randomArray(rand, D.k, -2, 2));
      const L = randomArray(rand, D.k);
      const w = inertiaWorldInverse(D, new Float64Array(D.k), R, inv, L);
      // Forward: L = R I(R~ ω R) R~ = I_world ω, with I_world the operator of the rotated covariance.
      const M = rotorToMatrix(D, new Float64Array(n * n), R);
      const Cw = new Float64Array(n * n);
      for (let a = 0; a < n; a += 1)
        for (let b = 0; b < n; b += 1)
          for (let i = 0; i < n; i += 1) Cw[a * n + b] = Cw[a * n + b]! + M[a * n + i]! * c[i]! * M[b * n + i]!;
      const Iw = inertiaFromCovariance(D, new Float64Array(D.k * D.k), Cw);
      expect(maxDiff(applyOperator(D.k, Iw, w), L)).toBeLessThan(1e-12);
      // In place (out aliasing L) and with an explicit scratch give the same numbers.
      const L2 = Float64Array.from(L);
      inertiaWorldInverse(D, L2, R, inv, L2, new Float64Array(D.k));
      expect(maxDiff(L2, w)).toBe(0);
    });
  }
});
