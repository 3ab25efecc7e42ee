import { describe, expect, it } from 'vitest';
import {
  bivectorApply,
  bivectorCommutator,
  bivectorDot,
  bivectorNorm,
  bivectorToMatrix,
  bivectorWedgeSelfNorm,
  bladeProductSign,
  isSimple,
  matrixToBivector,
  pfaffian4,
  dims,
  inertiaDiagonal,
  inertiaFromCovariance,
  matrixToRotor,
  planeBivector,
  rotateInPlane,
  rotorApplyBivector,
  rotorApplyVector,
  rotorCorrect,
  rotorDefect,
  rotorExp,
  rotorFromPlane,
  rotorIdentity,
  rotorMul,
  rotorReverse,
  rotorToMatrix,
  wedge,
  wedgeMatrix,
} from '@physin/algebra';
import { randomArray, seeded, uniform } from './support/random.js';
import { maxDiff } from './support/compare.js';
import { randomRotor, seriesExp } from './support/rotors.js';

describe('brief §10 identities', () => {
  it('identity 1: bitmask product signs (e0 e1 = e01, e1 e0 = −e01, e01 e01 = −1)', () => {
    expect(bladeProductSign(0b01, 0b10)).toBe(1);
    expect(bladeProductSign(0b10, 0b01)).toBe(-1);
    expect(bladeProductSign(0b11, 0b11)).toBe(-1);
    // The same through the even product of the 3D rotor algebra: e01 e01 = −1 exactly.
    const D = dims(3);
    const e01 = new Float64Array([0, 1, 0, 0]);
    expect(Array.from(rotorMul(D, new Float64Array(4), e01, e01))).toEqual([-1, 0, 0, 0]);
  });

  it('identity 2: simple rotor (0,1), θ = 0.3 turns e0 to (cos 0.3, sin 0.3, 0) (1e-15)', () => {
    const D = dims(3);
    const R = rotorFromPlane(D, new Float64Array(4), 0, 1, 0.3);
    const v = rotorApplyVector(D, new Float64Array(3), R, [1, 0, 0]);
    expect(maxDiff(v, [Math.cos(0.3), Math.sin(0.3), 0])).toBeLessThan(1e-15);
    expect(v[0]).toBeCloseTo(0.955336, 6);
    expect(v[1]).toBeCloseTo(0.29552, 6);
  });

  it('identity 3: exp(−½·0.3 e01) = 0.988771 − 0.149438 e01 (1e-6 on the quoted digits, 1e-15 on cos/sin)', () => {
    for (const n of [2, 3, 4, 5]) {
      const D = dims(n);
      const B = planeBivector(D, new Float64Array(D.k), 0, 1, 0.3);
      const R = rotorExp(D, new Float64Array(D.r), B);
      expect(Math.abs(R[0]! - 0.988771)).toBeLessThan(1e-6);
      expect(Math.abs(R[1]! + 0.149438)).toBeLessThan(1e-6);
      const exact = new Float64Array(D.r);
      exact[0] = Math.cos(0.15);
      exact[1] = -Math.sin(0.15);
      expect(maxDiff(R, exact)).toBeLessThan(1e-15);
    }
  });

  it('identity 4: 4D s = 0.3, p = 0.2, B = (0.1, −0.4, 0.5, 0.2, 0.3, −0.6) gives R R~ = 1.04 − 0.2 I (1e-15)', () => {
    const D = dims(4);
    const R = new Float64Array([0.3, 0.1, -0.4, 0.5, 0.2, 0.3, -0.6, 0.2]);
    const RR = rotorMul(D, new Float64Array(8), R, rotorReverse(D, new Float64Array(8), R));
    expect(maxDiff(RR, [1.04, 0, 0, 0, 0, 0, 0, -0.2])).toBeLessThan(1e-15);
    // The defect is the largest component of R R~ − 1: max(0.04, 0.2).
    expect(Math.abs(rotorDefect(D, R) - 0.2)).toBeLessThan(1e-15);
  });

  it('identity 5: 4D exp equals the 40-term series for B = (0.7, −0.4, 1.5, 0.2, 0.9, −0.6) (1e-15)', () => {
    const D = dims(4);
    const B = [0.7, -0.4, 1.5, 0.2, 0.9, -0.6];
    const R = rotorExp(D, new Float64Array(8), B);
    expect(maxDiff(R, seriesExp(D, B))).toBeLessThan(1e-15);
  });

  it('identity 6: isoclinic B = e_xy + e_zw: exp(−B/2) = 0.770151 − 0.420735(e_xy + e_zw) + 0.229849 I (1e-6)', () => {
    const D = dims(4);
    const R = rotorExp(D, new Float64Array(8), [1, 0, 0, 0, 0, 1]);
    // Exactly cos²(½) − sin(½)cos(½)(e_xy + e_zw) + sin²(½) I.
    const c = Math.cos(0.5);
    const s = Math.sin(0.5);
    expect(maxDiff(R, [c * c, -s * c, 0, 0, 0, 0, -s * c, s * s])).toBeLessThan(1e-15);
    expect(maxDiff(R, [0.770151, -0.420735, 0, 0, 0, 0, -0.420735, 0.229849])).toBeLessThan(1e-6);
  });

  it('identity 7: 3D turn by 0.8 about (0.3, −0.5, 0.81)/|·| matches Rodrigues (4e-16) and the quaternion map (2e-16)', () => {
    const D = dims(3);
    const a = [0.3, -0.5, 0.81];
    const len = Math.hypot(...a);
    const u = a.map((x) => x / len);
    const angle = 0.8;
    // Axis u ↔ bivector by the 3D dictionary: ω_xy = u_z, ω_xz = −u_y, ω_yz = u_x.
    const B = [u[2]! * angle, -u[1]! * angle, u[0]! * angle];
    const R = rotorExp(D, new Float64Array(4), B);
    const M = rotorToMatrix(D, new Float64Array(9), R);
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    const rod = new Float64Array(9);
    // Rodrigues: c·1 + s [u]× + (1 − c) u uᵀ, with [u]× the cross-product matrix.
    const cross = [0, -u[2]!, u[1]!, u[2]!, 0, -u[0]!, -u[1]!, u[0]!, 0];
    for (let i = 0; i < 9; i += 1) rod[i] = (i % 4 === 0 ? c : 0) + s * cross[i]! + (1 - c) * u[Math.floor(i / 3)]! * u[i % 3]!;
    expect(maxDiff(M, rod)).toBeLessThan(4e-16);
    // Quaternion (w, x, y, z) = (cos ½θ, sin ½θ u): w = R[1], x = −R[e12], y = +R[e02], z = −R[e01].
    const half = Math.sin(angle / 2);
    expect(maxDiff([R[0]!, -R[3]!, R[2]!, -R[1]!], [Math.cos(angle / 2), half * u[0]!, half * u[1]!, half * u[2]!])).toBeLessThan(
      2e-16,
    );
  });

  it('identity 8: rotorCorrect after a 1e-3 perturbation gives R R~ = 1 to < 1e-15, also at a double half turn', () => {
    const rand = seeded(8);
    for (const n of [3, 4, 5, 6]) {
      const D = dims(n);
      const starts = [randomRotor(D, rand)];
      if (n >= 4) {
        // Double half turn: π in xy and π in zw (R = ±e0123).
        const R = rotorFromPlane(D, new Float64Array(D.r), 0, 1, Math.PI);
        starts.push(rotateInPlane(D, R, R, 2, 3, Math.PI));
      }
      for (const R0 of starts) {
        const R = R0.map((x) => x + uniform(rand, -1e-3, 1e-3));
        expect(rotorDefect(D, R)).toBeGreaterThan(1e-5);
        const C = rotorCorrect(D, new Float64Array(D.r), R);
        expect(rotorDefect(D, C)).toBeLessThan(1e-15);
        // The correction stays next to the perturbed rotor (same sign, within the perturbation).
        expect(maxDiff(C, R0)).toBeLessThan(5e-3);
      }
    }
  });

  it('identity 9: matrix → rotor → matrix at θ = π, π ± 1e-11, 0, 1e-12 and 4D/6D multi-plane half turns (1e-13)', () => {
    const cases: [number, [number, number, number][]][] = [];
    for (const t of [Math.PI, Math.PI - 1e-11, Math.PI + 1e-11, 0, 1e-12, 0.3]) cases.push([3, [[0, 1, t]]]);
    cases.push([
      4,
      [
        [0, 1, Math.PI],
        [2, 3, Math.PI],
      ],
    ]);
    cases.push([
      4,
      [
        [0, 1, Math.PI - 1e-11],
        [2, 3, Math.PI],
      ],
    ]);
    cases.push([
      6,
      [
        [0, 1, Math.PI],
        [2, 3, Math.PI - 1e-11],
        [4, 5, 0.7],
      ],
    ]);
    for (const [n, planes] of cases) {
      const D = dims(n);
      const R = rotorIdentity(D, new Float64Array(D.r));
      for (const [i, j, t] of planes) rotateInPlane(D, R, R, i, j, t);
      const M = rotorToMatrix(D, new Float64Array(n * n), R);
      const R2 = matrixToRotor(D, new Float64Array(D.r), M);
      const M2 = rotorToMatrix(D, new Float64Array(n * n), R2);
      expect(maxDiff(M2, M)).toBeLessThan(1e-13);
      expect(rotorDefect(D, R2)).toBeLessThan(1e-15);
    }
  });

  it('identity 10: Σ [r]*[r]*ᵀ over points equals inertiaFromCovariance of Σ r rᵀ (3e-15 relative)', () => {
    const rand = seeded(10);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const sum = new Float64Array(D.k * D.k);
      const C = new Float64Array(n * n);
      const W = new Float64Array(D.k * n);
      for (let s = 0; s < 20; s += 1) {
        const r = randomArray(rand, n);
        wedgeMatrix(D, W, r);
        for (let p = 0; p < D.k; p += 1) {
          for (let q = 0; q < D.k; q += 1) {
            let x = 0;
            for (let c = 0; c < n; c += 1) x += W[p * n + c]! * W[q * n + c]!;
            sum[p * D.k + q] = sum[p * D.k + q]! + x;
          }
        }
        for (let i = 0; i < n; i += 1) for (let j = 0; j < n; j += 1) C[i * n + j] = C[i * n + j]! + r[i]! * r[j]!;
      }
      const I = inertiaFromCovariance(D, new Float64Array(D.k * D.k), C);
      expect(maxDiff(I, sum)).toBeLessThan(3e-15 * 20);
    }
  });

  it('identity 11: unit cube, m = 1: C = diag(1/12) gives I = 1/6 on every plane (exact to 1e-16)', () => {
    const D = dims(3);
    const C = [1 / 12, 0, 0, 0, 1 / 12, 0, 0, 0, 1 / 12];
    const I = inertiaFromCovariance(D, new Float64Array(9), C);
    expect(maxDiff(I, [1 / 6, 0, 0, 0, 1 / 6, 0, 0, 0, 1 / 6])).toBeLessThan(1e-16);
    expect(maxDiff(inertiaDiagonal(D, new Float64Array(3), [1 / 12, 1 / 12, 1 / 12]), [1 / 6, 1 / 6, 1 / 6])).toBeLessThan(1e-16);
  });
});

describe('test plan item 1: algebra identities for n = 2..6', () => {
  const rand = seeded(1);
  for (let n = 2; n <= 6; n += 1) {
    it(`n = ${n}: r ∧ a = [r]* a, r·w = [r]*ᵀ w, [R]₂ B = R B R~ (1e-14)`, () => {
      const D = dims(n);
      const W = new Float64Array(D.k * n);
      for (let trial = 0; trial < 10; trial += 1) {
        const r = randomArray(rand, n);
        const a = randomArray(rand, n);
        const w = randomArray(rand, D.k);
        wedgeMatrix(D, W, r);
        const ra = wedge(D, new Float64Array(D.k), r, a);
        const Wa = new Float64Array(D.k);
        for (let p = 0; p < D.k; p += 1) for (let c = 0; c < n; c += 1) Wa[p] = Wa[p]! + W[p * n + c]! * a[c]!;
        expect(maxDiff(ra, Wa)).toBeLessThan(1e-15);
        const v = bivectorApply(D, new Float64Array(n), w, r);
        const Wtw = new Float64Array(n);
        for (let c = 0; c < n; c += 1) for (let p = 0; p < D.k; p += 1) Wtw[c] = Wtw[c]! + W[p * n + c]! * w[p]!;
        expect(maxDiff(v, Wtw)).toBeLessThan(1e-15);
        // [R]₂ from the rotation matrix M: (M Ω Mᵀ) — the second compound of M — vs the rotor sandwich.
        const R = randomRotor(D, rand);
        const M = rotorToMatrix(D, new Float64Array(n * n), R);
        const RB = rotorApplyBivector(D, new Float64Array(D.k), R, w);
        const viaMatrix = new Float64Array(D.k);
        for (let p = 0; p < D.k; p += 1) {
          const i = D.planeI[p]!;
          const j = D.planeJ[p]!;
          for (let q = 0; q < D.k; q += 1) {
            const a2 = D.planeI[q]!;
            const b2 = D.planeJ[q]!;
            const compound = M[i * n + a2]! * M[j * n + b2]! - M[i * n + b2]! * M[j * n + a2]!;
            viaMatrix[p] = viaMatrix[p]! + compound * w[q]!;
          }
        }
        expect(maxDiff(RB, viaMatrix)).toBeLessThan(1e-14);
      }
    });
  }

  it('commutator in 3D is the cross product of the dictionary vectors (1e-15)', () => {
    const D = dims(3);
    const toVec = (b: ArrayLike<number>) => [b[2]!, -b[1]!, b[0]!];
    const A = randomArray(rand, 3);
    const B = randomArray(rand, 3);
    const c = toVec(bivectorCommutator(D, new Float64Array(3), A, B));
    const a = toVec(A);
    const b = toVec(B);
    const cross = [a[1]! * b[2]! - a[2]! * b[1]!, a[2]! * b[0]! - a[0]! * b[2]!, a[0]! * b[1]! - a[1]! * b[0]!];
    expect(maxDiff(c, cross)).toBeLessThan(1e-15);
  });
});

describe('the specification conventions', () => {
  it('in 4D a torque in the (x w) plane is [0, 0, 9, 0, 0, 0]', () => {
    const D = dims(4);
    expect(Array.from(planeBivector(D, new Float64Array(6), 0, 3, 9))).toEqual([0, 0, 9, 0, 0, 0]);
    expect(Array.from(planeBivector(D, new Float64Array(6), 3, 0, 9))).toEqual([0, 0, -9, 0, 0, 0]);
  });

  it('rotateInPlane(0, 3, θ) turns e_x toward e_w (1e-16)', () => {
    const D = dims(4);
    const R = rotateInPlane(D, new Float64Array(8), rotorIdentity(D, new Float64Array(8)), 0, 3, 0.4);
    const v = rotorApplyVector(D, new Float64Array(4), R, [1, 0, 0, 0]);
    expect(maxDiff(v, [Math.cos(0.4), 0, 0, Math.sin(0.4)])).toBeLessThan(2e-16);
    // The same turn as the exponential of the (x w) plane bivector, and ω_xw > 0 moves e_x toward e_w.
    const E = rotorExp(D, new Float64Array(8), planeBivector(D, new Float64Array(6), 0, 3, 0.4));
    expect(maxDiff(E, R)).toBeLessThan(1e-16);
    const vel = bivectorApply(D, new Float64Array(4), [0, 0, 1, 0, 0, 0], [1, 0, 0, 0]);
    expect(Array.from(vel)).toEqual([0, 0, 0, 1]);
  });
});

describe('bivector helpers', () => {
  it('bivectorToMatrix and matrixToBivector are inverse, Ω is antisymmetric with Ω[j][i] = +ω_ij, n = 2..6 (exact)', () => {
    const rand = seeded(12);
    for (let n = 2; n <= 6; n += 1) {
      const D = dims(n);
      const B = randomArray(rand, D.k);
      const O = bivectorToMatrix(D, new Float64Array(n * n), B);
      for (let p = 0; p < D.k; p += 1) {
        expect(O[D.planeJ[p]! * n + D.planeI[p]!]).toBe(B[p]);
        expect(O[D.planeI[p]! * n + D.planeJ[p]!]).toBe(-B[p]!);
      }
      expect(Array.from(matrixToBivector(D, new Float64Array(D.k), O))).toEqual(Array.from(B));
      expect(Math.abs(bivectorNorm(D, B) ** 2 - bivectorDot(D, B, B))).toBeLessThan(1e-15);
    }
  });

  it('simplicity: Pf(e_xy + e_zw) = 1 (not simple); a wedge of two vectors is simple in n = 4..6 (|B∧B| < 1e-15)', () => {
    const D4 = dims(4);
    expect(pfaffian4([1, 0, 0, 0, 0, 1])).toBe(1);
    expect(pfaffian4([0.1, -0.4, 0.5, 0.2, 0.3, -0.6])).toBeCloseTo(0.1 * -0.6 - -0.4 * 0.3 + 0.5 * 0.2, 15);
    expect(isSimple(D4, [1, 0, 0, 0, 0, 1], 1e-12)).toBe(false);
    expect(bivectorWedgeSelfNorm(D4, [1, 0, 0, 0, 0, 1])).toBe(2);
    const rand = seeded(13);
    for (let n = 4; n <= 6; n += 1) {
      const D = dims(n);
      const B = wedge(D, new Float64Array(D.k), randomArray(rand, n), randomArray(rand, n));
      expect(bivectorWedgeSelfNorm(D, B)).toBeLessThan(1e-15);
      expect(isSimple(D, B, 1e-12)).toBe(true);
      // Two orthogonal planes with rates 1 and 2: |B ∧ B| = 2·|1·2| = 4.
      const two = new Float64Array(D.k);
      two[D.planeIndexOf[0 * n + 1]!] = 1;
      two[D.planeIndexOf[2 * n + 3]!] = 2;
      expect(bivectorWedgeSelfNorm(D, two)).toBeCloseTo(4, 15);
      expect(isSimple(D, two, 1e-12)).toBe(false);
    }
    // Below 4D every bivector is simple.
    expect(isSimple(dims(3), [1, 2, 3], 0)).toBe(true);
  });
});
