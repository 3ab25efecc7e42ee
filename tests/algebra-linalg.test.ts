import { describe, expect, it } from 'vitest';
import { determinant, matMul, orthonormalize, symmetricEigen } from '@physin/algebra';
import { randomArray, seeded } from './support/random.js';
import { maxDiff } from './support/compare.js';

function transpose(n: number, A: ArrayLike<number>): Float64Array {
  const T = new Float64Array(n * n);
  for (let i = 0; i < n; i += 1) for (let j = 0; j < n; j += 1) T[i * n + j] = A[j * n + i]!;
  return T;
}

function identity(n: number): Float64Array {
  const I = new Float64Array(n * n);
  for (let i = 0; i < n; i += 1) I[i * n + i] = 1;
  return I;
}

describe('linear algebra', () => {
  it('symmetricEigen: A V = V Λ, VᵀV = 1, det V = +1, values descending, sizes 1..28 (1e-12 relative)', () => {
    const rand = seeded(61);
    for (const n of [1, 2, 3, 4, 5, 6, 8, 10, 15, 28]) {
      const X = randomArray(rand, n * n);
      const A = matMul(n, new Float64Array(n * n), X, transpose(n, X));
      const values = new Float64Array(n);
      const V = new Float64Array(n * n);
      symmetricEigen(n, values, V, A);
      const AV = matMul(n, new Float64Array(n * n), A, V);
      const VL = new Float64Array(n * n);
      for (let i = 0; i < n; i += 1) for (let c = 0; c < n; c += 1) VL[i * n + c] = V[i * n + c]! * values[c]!;
      const scale = Math.max(1, values[0]!);
      expect(maxDiff(AV, VL) / scale).toBeLessThan(1e-12);
      expect(maxDiff(matMul(n, new Float64Array(n * n), transpose(n, V), V), identity(n))).toBeLessThan(1e-13);
      expect(Math.abs(determinant(n, V) - 1)).toBeLessThan(1e-12);
      for (let i = 1; i < n; i += 1) expect(values[i]!).toBeLessThanOrEqual(values[i - 1]!);
    }
  });

  it('symmetricEigen on repeated eigenvalues (the identity, a diagonal with ties) returns them exactly', () => {
    const values = new Float64Array(4);
    const V = new Float64Array(16);
    symmetricEigen(4, values, V, [2, 0, 0, 0, 0, 5, 0, 0, 0, 0, 2, 0, 0, 0, 0, 7]);
    expect(Array.from(values)).toEqual([7, 5, 2, 2]);
    expect(Math.abs(determinant(4, V) - 1)).toBeLessThan(1e-15);
  });

  it('determinant: known values and det(AB) = det A det B (1e-12 relative)', () => {
    expect(determinant(2, [1, 2, 3, 4])).toBeCloseTo(-2, 14);
    expect(determinant(3, [2, 0, 0, 0, 3, 0, 0, 0, 4])).toBe(24);
    expect(determinant(3, [1, 2, 3, 4, 5, 6, 7, 8, 9])).toBeCloseTo(0, 13);
    const rand = seeded(62);
    for (let n = 1; n <= 8; n += 1) {
      const A = randomArray(rand, n * n);
      const B = randomArray(rand, n * n);
      const dAB = determinant(n, matMul(n, new Float64Array(n * n), A, B));
      const prod = determinant(n, A) * determinant(n, B);
      expect(Math.abs(dAB - prod)).toBeLessThan(1e-12 * Math.max(1, Math.abs(prod)));
    }
  });

  it('matMul: out may alias an input; a known 2×2 product', () => {
    const A = new Float64Array([1, 2, 3, 4]);
    expect(Array.from(matMul(2, A, A, [0, 1, 1, 0]))).toEqual([2, 1, 4, 3]);
  });

  it('orthonormalize: a perturbed rotation goes to its nearest rotation (the polar factor), sizes 2..8 (1e-14)', () => {
    const rand = seeded(63);
    for (let n = 2; n <= 8; n += 1) {
      // A random rotation Q from the eigenvectors of a random symmetric matrix (det +1).
      const X = randomArray(rand, n * n);
      const S = matMul(n, new Float64Array(n * n), X, transpose(n, X));
      const Q = new Float64Array(n * n);
      symmetricEigen(n, new Float64Array(n), Q, S);
      // M = Q (1 + E) with E symmetric: its polar factor is exactly Q.
      const E = randomArray(rand, n * n, -1e-3, 1e-3);
      const Es = new Float64Array(n * n);
      for (let i = 0; i < n; i += 1)
        for (let j = 0; j < n; j += 1) Es[i * n + j] = (i === j ? 1 : 0) + 0.5 * (E[i * n + j]! + E[j * n + i]!);
      const M = matMul(n, new Float64Array(n * n), Q, Es);
      const O = orthonormalize(n, new Float64Array(n * n), M);
      expect(maxDiff(O, Q)).toBeLessThan(1e-14);
      // A positive scale does not change the result.
      expect(
        maxDiff(
          orthonormalize(
            n,
            new Float64Array(n * n),
            M.map((x) => 3 * x),
          ),
          Q,
        ),
      ).toBeLessThan(1e-14);
    }
  });

  it('orthonormalize: a matrix far from a rotation gives an orthogonal matrix with the same determinant sign (1e-14)', () => {
    const rand = seeded(64);
    for (let n = 2; n <= 8; n += 1) {
      const M = randomArray(rand, n * n);
      const O = orthonormalize(n, new Float64Array(n * n), M);
      expect(maxDiff(matMul(n, new Float64Array(n * n), transpose(n, O), O), identity(n))).toBeLessThan(1e-14);
      expect(Math.sign(determinant(n, O))).toBe(Math.sign(determinant(n, M)));
    }
    // Rank-deficient input: the missing direction is completed.
    const O = orthonormalize(3, new Float64Array(9), [1, 1, 0, 0, 0, 0, 0, 0, 1]);
    expect(maxDiff(matMul(3, new Float64Array(9), transpose(3, O), O), identity(3))).toBeLessThan(1e-15);
  });
});
