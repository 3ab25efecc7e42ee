import { describe, expect, it } from 'vitest';
import {
  dims,
  matMul,
  matrixToRotor,
  rotateInPlane,
  rotorCorrect,
  rotorDefect,
  rotorExp,
  rotorFromPlane,
  rotorIdentity,
  rotorToMatrix,
} from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { randomArray, seeded } from './support/random.js';
import { maxDiff } from './support/compare.js';

/** The exact matrix of a turn by θ in plane (i, j): e_i → cos θ e_i + sin θ e_j. */
function planeMatrix(n: number, i: number, j: number, theta: number): Float64Array {
  const M = new Float64Array(n * n);
  for (let a = 0; a < n; a += 1) M[a * n + a] = 1;
  const c = Math.cos(theta);
  const s = Math.sin(theta);
  M[i * n + i] = c;
  M[j * n + j] = c;
  M[j * n + i] = s;
  M[i * n + j] = -s;
  return M;
}

/** Angles through π: π itself and π ± 1e-13 .. 1e-3. */
const OFFSETS = [0, 1e-13, -1e-13, 1e-11, -1e-11, 1e-9, -1e-9, 1e-7, -1e-7, 1e-5, -1e-5, 1e-3, -1e-3];
const TOL = 1e-12;

function roundTrip(D: Dims, M: Float64Array): Float64Array {
  const R = matrixToRotor(D, new Float64Array(D.r), M);
  expect(rotorDefect(D, R)).toBeLessThan(1e-15);
  return rotorToMatrix(D, new Float64Array(D.n * D.n), R);
}

describe('half turns: matrix → rotor → matrix', () => {
  it('a turn exactly at π and at π − 1e-11, every plane of n = 2..6 (1e-12)', () => {
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      for (let i = 0; i < n; i += 1) {
        for (let j = i + 1; j < n; j += 1) {
          for (const t of [Math.PI, Math.PI - 1e-11]) {
            const M = planeMatrix(n, i, j, t);
            expect(maxDiff(roundTrip(D, M), M)).toBeLessThan(TOL);
          }
        }
      }
    }
  });

  for (let n = 3; n <= 6; n += 1) {
    it(`n = ${n}: a sweep of angles through π (π ± 1e-13 .. 1e-3) in every plane, both orientations (1e-12)`, () => {
      const D = dims(n);
      let worst = 0;
      for (let i = 0; i < n; i += 1) {
        for (let j = 0; j < n; j += 1) {
          if (i === j) continue;
          for (const off of OFFSETS) {
            const M = planeMatrix(n, i, j, Math.PI + off);
            worst = Math.max(worst, maxDiff(roundTrip(D, M), M));
          }
        }
      }
      expect(worst).toBeLessThan(TOL);
    });

    it(`n = ${n}: the same sweep in planes tilted by a random rotation (M = Q P Qᵀ) (1e-12)`, () => {
      const D = dims(n);
      const rand = seeded(40 + n);
      const Q = rotorToMatrix(D, new Float64Array(n * n), rotorExp(D, new Float64Array(D.r), randomArray(rand, D.k, -2, 2)));
      const Qt = new Float64Array(n * n);
      for (let a = 0; a < n; a += 1) for (let b = 0; b < n; b += 1) Qt[a * n + b] = Q[b * n + a]!;
      let worst = 0;
      for (let i = 0; i < n; i += 1) {
        for (let j = i + 1; j < n; j += 1) {
          for (const off of OFFSETS) {
            const M = matMul(
              n,
              new Float64Array(n * n),
              Q,
              matMul(n, new Float64Array(n * n), planeMatrix(n, i, j, Math.PI + off), Qt),
            );
            worst = Math.max(worst, maxDiff(roundTrip(D, M), M));
          }
        }
      }
      expect(worst).toBeLessThan(TOL);
    });

    it(`n = ${n}: rotorCorrect at half-turn rotors leaves their matrix unchanged (1e-12)`, () => {
      const D = dims(n);
      let worst = 0;
      for (let i = 0; i < n; i += 1) {
        for (let j = i + 1; j < n; j += 1) {
          for (const off of OFFSETS) {
            const R = rotorFromPlane(D, new Float64Array(D.r), i, j, Math.PI + off);
            const before = rotorToMatrix(D, new Float64Array(n * n), R);
            const C = rotorCorrect(D, new Float64Array(D.r), R);
            worst = Math.max(worst, maxDiff(rotorToMatrix(D, new Float64Array(n * n), C), before));
            // Same sign as the input: the correction does not flip the rotor.
            expect(maxDiff(C, R)).toBeLessThan(TOL);
          }
        }
      }
      expect(worst).toBeLessThan(TOL);
    });
  }

  it('4D double half turns: (π, π), (π − 1e-11, π), (π, π + 1e-9) in the plane pairs xy/zw, xz/yw, xw/yz (1e-12)', () => {
    const D = dims(4);
    const pairs: [number, number, number, number][] = [
      [0, 1, 2, 3],
      [0, 2, 1, 3],
      [0, 3, 1, 2],
    ];
    for (const [a, b, c, d] of pairs) {
      for (const [t1, t2] of [
        [Math.PI, Math.PI],
        [Math.PI - 1e-11, Math.PI],
        [Math.PI, Math.PI + 1e-9],
      ] as const) {
        const R = rotorIdentity(D, new Float64Array(8));
        rotateInPlane(D, R, R, a, b, t1);
        rotateInPlane(D, R, R, c, d, t2);
        const M = rotorToMatrix(D, new Float64Array(16), R);
        expect(maxDiff(roundTrip(D, M), M)).toBeLessThan(TOL);
        const C = rotorCorrect(D, new Float64Array(8), R);
        expect(maxDiff(rotorToMatrix(D, new Float64Array(16), C), M)).toBeLessThan(TOL);
      }
    }
    // The exact double half turn −I (every axis reversed) has the rotor ±e0123.
    const minusI = new Float64Array(16);
    for (let a = 0; a < 4; a += 1) minusI[a * 4 + a] = -1;
    const R = matrixToRotor(D, new Float64Array(8), minusI);
    expect(maxDiff(R.map(Math.abs), [0, 0, 0, 0, 0, 0, 0, 1])).toBeLessThan(1e-15);
  });

  it('6D: planes at π, π − 1e-11 and 0.7 together (1e-12)', () => {
    const D = dims(6);
    const R = rotorIdentity(D, new Float64Array(D.r));
    rotateInPlane(D, R, R, 0, 1, Math.PI);
    rotateInPlane(D, R, R, 2, 3, Math.PI - 1e-11);
    rotateInPlane(D, R, R, 4, 5, 0.7);
    const M = rotorToMatrix(D, new Float64Array(36), R);
    expect(maxDiff(roundTrip(D, M), M)).toBeLessThan(TOL);
  });

  it('small turns stay exact through the first-order residual step: 1e-12 .. 2e-6 in 4D (1e-15)', () => {
    const D = dims(4);
    for (const t of [0, 1e-12, 1e-9, 1e-7, 5e-7, 9.9e-7, 1.1e-6, 2e-6]) {
      const M = planeMatrix(4, 1, 3, t);
      expect(maxDiff(roundTrip(D, M), M)).toBeLessThan(1e-15);
    }
  });
});
