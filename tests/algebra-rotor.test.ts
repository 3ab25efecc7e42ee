import { describe, expect, it } from 'vitest';
import {
  createGenericKernels,
  determinant,
  dims,
  matMul,
  matrixToRotor,
  rotateInPlane,
  rotorApplyBivector,
  rotorApplyBivectorInverse,
  rotorApplyVector,
  rotorApplyVectorInverse,
  rotorCorrect,
  rotorDefect,
  rotorExp,
  rotorFromPlane,
  rotorIdentity,
  rotorMul,
  rotorNorm,
  rotorNormalize,
  rotorReverse,
  rotorToMatrix,
} from '@physin/algebra';
import { randomArray, seeded } from './support/random.js';
import { maxDiff } from './support/compare.js';
import { randomRotor, seriesExp } from './support/rotors.js';

/** Distance between two rotors up to their common sign (R and −R are the same rotation). */
function diffUpToSign(a: ArrayLike<number>, b: ArrayLike<number>): number {
  const neg = Array.from(b, (x) => -x);
  return Math.min(maxDiff(a, b), maxDiff(a, neg));
}

/** Largest entry of |MᵀM − 1|. */
function orthoError(n: number, M: ArrayLike<number>): number {
  let w = 0;
  for (let i = 0; i < n; i += 1) {
    for (let j = 0; j < n; j += 1) {
      let s = 0;
      for (let m = 0; m < n; m += 1) s += M[m * n + i]! * M[m * n + j]!;
      w = Math.max(w, Math.abs(s - (i === j ? 1 : 0)));
    }
  }
  return w;
}

describe('rotor exponential', () => {
  for (let n = 2; n <= 6; n += 1) {
    it(`n = ${n}: exp equals the 40-term series (1e-12), small and large angles (|B| > 2π)`, () => {
      const D = dims(n);
      const rand = seeded(100 + n);
      for (let trial = 0; trial < 12; trial += 1) {
        const B = randomArray(rand, D.k);
        let norm = 0;
        for (const x of B) norm += x * x;
        norm = Math.sqrt(norm);
        // Sizes from a tiny time step to more than a full turn (|B| = 7 > 2π).
        const size = [1e-8, 1e-3, 0.5, 2, 4, 7][trial % 6]!;
        for (let p = 0; p < D.k; p += 1) B[p] = (B[p]! / norm) * size;
        const R = rotorExp(D, new Float64Array(D.r), B);
        expect(maxDiff(R, seriesExp(D, B))).toBeLessThan(1e-12);
        expect(rotorDefect(D, R)).toBeLessThan(1e-13);
        // scale is a time: exp(−h B/2) = exp of the bivector hB.
        const h = 0.37;
        const hB = B.map((x) => x * h);
        expect(maxDiff(rotorExp(D, new Float64Array(D.r), B, h), rotorExp(D, new Float64Array(D.r), hB))).toBeLessThan(1e-14);
      }
    });
  }

  it('exp is a one-parameter group: exp(sB) exp(tB) = exp((s+t)B) for n = 2..6 (1e-13)', () => {
    const rand = seeded(7);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const B = randomArray(rand, D.k, -2, 2);
      const a = rotorExp(D, new Float64Array(D.r), B, 0.3);
      const b = rotorExp(D, new Float64Array(D.r), B, 1.1);
      const ab = rotorMul(D, new Float64Array(D.r), a, b);
      expect(maxDiff(ab, rotorExp(D, new Float64Array(D.r), B, 1.4))).toBeLessThan(1e-13);
    }
  });

  it('dR/dt = −½ B R: a small step of exp moves R by −(h/2) B R to first order (relative 1e-5 at h = 1e-6)', () => {
    const rand = seeded(9);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const B = randomArray(rand, D.k);
      const Bfull = new Float64Array(D.r);
      for (let p = 0; p < D.k; p += 1) Bfull[1 + p] = B[p]!;
      const R = randomRotor(D, rand);
      const h = 1e-6;
      const stepped = rotorMul(D, new Float64Array(D.r), rotorExp(D, new Float64Array(D.r), B, h), R);
      const deriv = rotorMul(D, new Float64Array(D.r), Bfull, R).map((x) => -0.5 * x);
      const fd = stepped.map((x, a) => (x - R[a]!) / h);
      expect(maxDiff(fd, deriv)).toBeLessThan(1e-5);
    }
  });
});

describe('rotor products and actions', () => {
  it('composition: first R1 then R2 is R2 R1, for vectors and bivectors, n = 2..6 (1e-14)', () => {
    const rand = seeded(21);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const R1 = randomRotor(D, rand);
      const R2 = randomRotor(D, rand);
      const R21 = rotorMul(D, new Float64Array(D.r), R2, R1);
      const v = randomArray(rand, n);
      const step = rotorApplyVector(D, new Float64Array(n), R2, rotorApplyVector(D, new Float64Array(n), R1, v));
      expect(maxDiff(step, rotorApplyVector(D, new Float64Array(n), R21, v))).toBeLessThan(1e-14);
      const B = randomArray(rand, D.k);
      const stepB = rotorApplyBivector(D, new Float64Array(D.k), R2, rotorApplyBivector(D, new Float64Array(D.k), R1, B));
      expect(maxDiff(stepB, rotorApplyBivector(D, new Float64Array(D.k), R21, B))).toBeLessThan(1e-14);
      // Matrices compose the same way: M(R2 R1) = M(R2) M(R1).
      const M1 = rotorToMatrix(D, new Float64Array(n * n), R1);
      const M2 = rotorToMatrix(D, new Float64Array(n * n), R2);
      expect(maxDiff(rotorToMatrix(D, new Float64Array(n * n), R21), matMul(n, new Float64Array(n * n), M2, M1))).toBeLessThan(
        1e-14,
      );
    }
  });

  it('inverse actions undo the actions and the reverse is the inverse, n = 2..6 (1e-14)', () => {
    const rand = seeded(22);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const R = randomRotor(D, rand);
      const v = randomArray(rand, n);
      const B = randomArray(rand, D.k);
      const back = rotorApplyVectorInverse(D, new Float64Array(n), R, rotorApplyVector(D, new Float64Array(n), R, v));
      expect(maxDiff(back, v)).toBeLessThan(1e-14);
      const backB = rotorApplyBivectorInverse(D, new Float64Array(D.k), R, rotorApplyBivector(D, new Float64Array(D.k), R, B));
      expect(maxDiff(backB, B)).toBeLessThan(1e-14);
      const one = rotorMul(D, new Float64Array(D.r), R, rotorReverse(D, new Float64Array(D.r), R));
      expect(maxDiff(one, rotorIdentity(D, new Float64Array(D.r)))).toBeLessThan(1e-14);
      // In-place (out aliasing the input) gives the same result.
      const w = Float64Array.from(v);
      rotorApplyVector(D, w, R, w);
      expect(maxDiff(w, rotorApplyVector(D, new Float64Array(n), R, v))).toBe(0);
    }
  });

  it('simple rotors: rotorFromPlane(i, j, θ) turns e_i to cos θ e_i + sin θ e_j in every plane of n = 2..6 (1e-15)', () => {
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      for (let i = 0; i < n; i += 1) {
        for (let j = 0; j < n; j += 1) {
          if (i === j) continue;
          const R = rotorFromPlane(D, new Float64Array(D.r), i, j, 0.7);
          const ei = new Float64Array(n);
          ei[i] = 1;
          const want = new Float64Array(n);
          want[i] = Math.cos(0.7);
          want[j] = Math.sin(0.7);
          expect(maxDiff(rotorApplyVector(D, new Float64Array(n), R, ei), want)).toBeLessThan(1e-15);
        }
      }
    }
  });

  it('rotateInPlane turns in the world frame after R: P R (1e-15)', () => {
    const rand = seeded(23);
    const D = dims(5);
    const R = randomRotor(D, rand);
    const P = rotorFromPlane(D, new Float64Array(D.r), 1, 4, -0.9);
    const want = rotorMul(D, new Float64Array(D.r), P, R);
    expect(maxDiff(rotateInPlane(D, new Float64Array(D.r), R, 1, 4, -0.9), want)).toBeLessThan(1e-15);
    expect(maxDiff(rotateInPlane(D, new Float64Array(D.r), R, 4, 1, 0.9), want)).toBeLessThan(1e-15);
  });

  it('the generic kernels created afresh agree with those of dims(n) for n = 2..6 (exactly for n != 3, 4)', () => {
    const rand = seeded(24);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const G = createGenericKernels(D);
      const R = randomRotor(D, rand);
      const M = G.toMatrix(new Float64Array(n * n), R);
      const tol = n === 3 || n === 4 ? 1e-14 : 0;
      expect(maxDiff(M, D.kernels.toMatrix(new Float64Array(n * n), R))).toBeLessThanOrEqual(tol);
    }
  });
});

describe('test plan item 2: rotor closure', () => {
  for (let n = 2; n <= 6; n += 1) {
    it(`n = ${n}: the product of 200 random rotors, corrected, is a rotation (R R~ = 1, MᵀM = 1, det +1 to 1e-12)`, () => {
      const D = dims(n);
      const rand = seeded(200 + n);
      const R = rotorIdentity(D, new Float64Array(D.r));
      const Mprod = new Float64Array(n * n);
      for (let i = 0; i < n; i += 1) Mprod[i * n + i] = 1;
      const Mi = new Float64Array(n * n);
      for (let s = 0; s < 200; s += 1) {
        const Ri = randomRotor(D, rand, 2);
        rotorMul(D, R, Ri, R);
        matMul(n, Mprod, rotorToMatrix(D, Mi, Ri), Mprod);
      }
      const C = rotorCorrect(D, new Float64Array(D.r), R);
      expect(rotorDefect(D, C)).toBeLessThan(1e-12);
      const M = rotorToMatrix(D, new Float64Array(n * n), C);
      expect(orthoError(n, M)).toBeLessThan(1e-12);
      expect(Math.abs(determinant(n, M) - 1)).toBeLessThan(1e-12);
      // The corrected rotor is still the product: same rotation as the product of the 200 matrices.
      expect(maxDiff(M, Mprod)).toBeLessThan(1e-11);
      expect(maxDiff(C, R)).toBeLessThan(1e-11);
    });
  }
});

describe('rotor ↔ matrix round trips', () => {
  for (let n = 2; n <= 6; n += 1) {
    it(`n = ${n}: rotor → matrix → rotor gives ±R (1e-13) for 50 random rotors`, () => {
      const D = dims(n);
      const rand = seeded(300 + n);
      const M = new Float64Array(n * n);
      const back = new Float64Array(D.r);
      for (let t = 0; t < 50; t += 1) {
        const R = randomRotor(D, rand, t % 2 === 0 ? 3 : 1e-4);
        matrixToRotor(D, back, rotorToMatrix(D, M, R));
        expect(diffUpToSign(back, R)).toBeLessThan(1e-13);
      }
    });
  }
});

describe('correction', () => {
  it('rotorCorrect leaves an exact rotor unchanged and keeps the sign of its input, n = 2..6 (1e-15)', () => {
    const rand = seeded(31);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const R = randomRotor(D, rand);
      expect(maxDiff(rotorCorrect(D, new Float64Array(D.r), R), R)).toBeLessThan(1e-15);
      const neg = R.map((x) => -x);
      expect(maxDiff(rotorCorrect(D, new Float64Array(D.r), neg), neg)).toBeLessThan(1e-15);
    }
  });

  it('4D: a unit-norm even element that is not a rotor is detected by the defect and fixed by rotorCorrect', () => {
    const D = dims(4);
    // s + B + p I with s p ≠ Pf(B): |R| = 1 exactly, yet R R~ has an e0123 part.
    const R = rotorNormalize(D, new Float64Array(8), [0.8, 0.3, 0, 0, 0, 0, 0.3, 0.4]);
    expect(Math.abs(rotorNorm(D, R) - 1)).toBeLessThan(1e-15);
    expect(rotorDefect(D, R)).toBeGreaterThan(0.1);
    const C = rotorCorrect(D, new Float64Array(8), R);
    expect(rotorDefect(D, C)).toBeLessThan(1e-15);
    expect(orthoError(4, rotorToMatrix(D, new Float64Array(16), C))).toBeLessThan(1e-15);
  });
});

describe('test plan item 7 at the algebra level: double rotation stability', () => {
  const rotorTolerance = 1e-9; // the engine's defaultParams.rotorTolerance
  const D = dims(4);
  const B = new Float64Array([1.3, 0, 0, 0, 0, -2.1]); // xy and zw at once: Pf(B) ≠ 0
  const Bfull = new Float64Array(8);
  for (let p = 0; p < 6; p += 1) Bfull[1 + p] = B[p]!;
  const h = 1e-3;
  const steps = 100_000;

  /** 10^5 first-order steps R ← R − (h/2) B R, renormalised by the norm only; returns the largest defect seen. */
  function run(correct: boolean): { worst: number; R: Float64Array } {
    const R = rotorIdentity(D, new Float64Array(8));
    const BR = new Float64Array(8);
    const k = D.kernels;
    let worst = 0;
    for (let s = 0; s < steps; s += 1) {
      k.mul(BR, Bfull, R);
      let norm = 0;
      for (let a = 0; a < 8; a += 1) {
        R[a] = R[a]! - 0.5 * h * BR[a]!;
        norm += R[a]! * R[a]!;
      }
      norm = Math.sqrt(norm);
      for (let a = 0; a < 8; a += 1) R[a] = R[a]! / norm;
      if (correct && k.defect(R) > rotorTolerance) k.correct(R, R);
      worst = Math.max(worst, k.defect(R));
    }
    return { worst, R };
  }

  it('with correction the defect stays under rotorTolerance = 1e-9 over 10^5 steps, and the matrix stays orthonormal (1e-14)', () => {
    const { worst, R } = run(true);
    expect(worst).toBeLessThan(rotorTolerance);
    expect(orthoError(4, rotorToMatrix(D, new Float64Array(16), R))).toBeLessThan(1e-14);
  });

  it('without correction the defect grows past 1e-6 (the norm alone gives no warning)', () => {
    const { worst, R } = run(false);
    expect(worst).toBeGreaterThan(1e-6);
    expect(Math.abs(rotorNorm(D, R) - 1)).toBeLessThan(1e-14);
  });
});
