// The 3D and 4D closed-form rotor kernels against the table-driven generic kernels, gl-matrix's
// quaternions, Rodrigues' formula and the 4D identities of the brief (§10: 4, 5, 6, 7, 8).
import { createGenericKernels, dims, rotorFromPlane } from '@physin/algebra';
import type { RotorKernels } from '@physin/algebra';
import { mat3, quat, vec3 } from 'gl-matrix';
import { describe, expect, it } from 'vitest';
import { createFast3Kernels } from '../packages/algebra/src/kernels/fast3.js';
import { createFast4Kernels } from '../packages/algebra/src/kernels/fast4.js';
import { randomArray, seeded, uniform } from './support/random.js';
import { maxDiff } from './support/compare.js';

function reverse(n: number, R: Float64Array): Float64Array {
  const D = dims(n);
  return R.map((x, a) => x * D.reverseSign[a]!);
}

/** Unit rotor exp(−B/2) of a seeded random bivector with components in [−range, range]. */
function randomRotor(gen: RotorKernels, n: number, rand: () => number, range = Math.PI): Float64Array {
  const D = dims(n);
  return gen.exp(new Float64Array(D.r), randomArray(rand, D.k, -range, range), 1);
}

/** Rotors that stress the closed forms: half turns, double half turns, isoclinic, tiny angles. */
function specialRotors(n: number): Float64Array[] {
  const D = dims(n);
  const out: Float64Array[] = [];
  const id = new Float64Array(D.r);
  id[0] = 1;
  out.push(id);
  for (let p = 0; p < D.k; p += 1) {
    for (const angle of [Math.PI, -Math.PI, Math.PI - 1e-11, 1e-12, -1e-12, 1e-7]) {
      out.push(rotorFromPlane(D, new Float64Array(D.r), D.planeI[p]!, D.planeJ[p]!, angle));
    }
  }
  const gen = createGenericKernels(D);
  if (n === 4) {
    const planePairs = [
      [0, 5],
      [1, 4],
      [2, 3],
    ] as const;
    for (const [p, q] of planePairs) {
      for (const [t1, t2] of [
        [Math.PI, Math.PI],
        [Math.PI, -Math.PI],
        [0.7, 0.7],
        [0.7, -0.7],
        [1e-12, 1e-12],
        [Math.PI - 1e-11, Math.PI],
        [2.1, 0.4],
      ]) {
        const B = new Float64Array(D.k);
        B[p] = t1;
        B[q] = t2;
        out.push(gen.exp(new Float64Array(D.r), B, 1));
      }
    }
    // The exact double half turns ±I (I = e0123).
    const I = new Float64Array(D.r);
    I[7] = 1;
    out.push(
      I,
      I.map((x) => -x),
    );
  }
  return out;
}

/** Seeded unit rotors, special rotors and raw (non-unit) even elements. */
function rotorInputs(gen: RotorKernels, n: number, seed: number): Float64Array[] {
  const rand = seeded(seed);
  const D = dims(n);
  const list = specialRotors(n);
  for (let t = 0; t < 40; t += 1) list.push(randomRotor(gen, n, rand));
  for (let t = 0; t < 20; t += 1) list.push(randomArray(rand, D.r, -1.5, 1.5));
  return list;
}

const AGREE = 1e-12;

for (const n of [3, 4] as const) {
  describe(`n = ${n}: fast kernels agree with the generic kernels (tolerance ${AGREE})`, () => {
    const D = dims(n);
    const gen = createGenericKernels(D);
    const fast = n === 3 ? createFast3Kernels(D) : createFast4Kernels(D);
    const rotors = rotorInputs(gen, n, 100 + n);
    const rand = seeded(200 + n);

    it(`dims(${n}) selected the fast kernels once (cached)`, () => {
      expect(D.kernels.name).toBe(`fast${n}`);
      expect(dims(n).kernels).toBe(D.kernels);
    });

    it('mul, on every pair drawn from the inputs; out may alias a or b', () => {
      let worst = 0;
      const o1 = new Float64Array(D.r);
      const o2 = new Float64Array(D.r);
      for (let i = 0; i < rotors.length; i += 1) {
        for (let j = 0; j < rotors.length; j += 7) {
          const a = rotors[i]!;
          const b = rotors[(i + j) % rotors.length]!;
          worst = Math.max(worst, maxDiff(fast.mul(o1, a, b), gen.mul(o2, a, b)));
        }
      }
      expect(worst).toBeLessThanOrEqual(AGREE);
      const a = rotors[50]!.slice();
      const b = rotors[60]!.slice();
      const expected = gen.mul(new Float64Array(D.r), a, b);
      expect(maxDiff(fast.mul(a, a, b), expected)).toBeLessThanOrEqual(AGREE);
      const a2 = rotors[50]!.slice();
      expect(maxDiff(fast.mul(b, a2, b), expected)).toBeLessThanOrEqual(AGREE);
    });

    it('applyVector / applyVectorInverse / applyBivector / applyBivectorInverse; out may alias the input', () => {
      let worst = 0;
      const o1v = new Float64Array(n);
      const o2v = new Float64Array(n);
      const o1b = new Float64Array(D.k);
      const o2b = new Float64Array(D.k);
      for (const R of rotors) {
        for (let t = 0; t < 3; t += 1) {
          const v = randomArray(rand, n, -2, 2);
          const B = randomArray(rand, D.k, -2, 2);
          worst = Math.max(worst, maxDiff(fast.applyVector(o1v, R, v), gen.applyVector(o2v, R, v)));
          worst = Math.max(worst, maxDiff(fast.applyVectorInverse(o1v, R, v), gen.applyVectorInverse(o2v, R, v)));
          worst = Math.max(worst, maxDiff(fast.applyBivector(o1b, R, B), gen.applyBivector(o2b, R, B)));
          worst = Math.max(worst, maxDiff(fast.applyBivectorInverse(o1b, R, B), gen.applyBivectorInverse(o2b, R, B)));
          // In place.
          const expectedV = gen.applyVector(new Float64Array(n), R, v);
          worst = Math.max(worst, maxDiff(fast.applyVector(v, R, v), expectedV));
          const expectedB = gen.applyBivectorInverse(new Float64Array(D.k), R, B);
          worst = Math.max(worst, maxDiff(fast.applyBivectorInverse(B, R, B), expectedB));
        }
      }
      expect(worst).toBeLessThanOrEqual(AGREE);
    });

    it('toMatrix, and the inverse sandwich is the transpose for unit rotors', () => {
      let worst = 0;
      const m1 = new Float64Array(n * n);
      const m2 = new Float64Array(n * n);
      for (const R of rotors) worst = Math.max(worst, maxDiff(fast.toMatrix(m1, R), gen.toMatrix(m2, R)));
      expect(worst).toBeLessThanOrEqual(AGREE);
      const R = rotors[rotors.length - 30]!; // a seeded unit rotor
      fast.toMatrix(m1, R);
      const v = randomArray(rand, n);
      const w = fast.applyVectorInverse(new Float64Array(n), R, v);
      for (let c = 0; c < n; c += 1) {
        let s = 0;
        for (let i = 0; i < n; i += 1) s += m1[i * n + c]! * v[i]!;
        expect(Math.abs(s - w[c]!)).toBeLessThanOrEqual(1e-14);
      }
    });

    it('exp: random, large, tiny (1e-12), zero and (4D) isoclinic bivectors, several scales', () => {
      const bivectors: Float64Array[] = [];
      for (let t = 0; t < 40; t += 1) bivectors.push(randomArray(rand, D.k, -1, 1).map((x) => x * 10 ** uniform(rand, -3, 1)));
      for (let p = 0; p < D.k; p += 1) {
        for (const angle of [Math.PI, 2 * Math.PI, 1e-12, 1e-5, 1e-2, 0.0099999]) {
          const B = new Float64Array(D.k);
          B[p] = angle;
          bivectors.push(B);
        }
      }
      bivectors.push(new Float64Array(D.k));
      if (n === 4) {
        for (const t of [1, -1, Math.PI, 1e-12, 1e-3]) {
          bivectors.push(Float64Array.from([t, 0, 0, 0, 0, t]), Float64Array.from([t, 0, 0, 0, 0, -t]));
          bivectors.push(Float64Array.from([0, t, 0, 0, -t, 0]), Float64Array.from([0, 0, t, t, 0, 0]));
          // Nearly isoclinic: θ− tiny but not zero.
          bivectors.push(Float64Array.from([t, 0, 0, 0, 0, t * (1 + 1e-9)]));
        }
      }
      let worst = 0;
      const o1 = new Float64Array(D.r);
      const o2 = new Float64Array(D.r);
      for (const B of bivectors) {
        for (const scale of [1, 0.01, -0.5, 1 / 60]) {
          worst = Math.max(worst, maxDiff(fast.exp(o1, B, scale), gen.exp(o2, B, scale)));
        }
      }
      expect(worst).toBeLessThanOrEqual(AGREE);
    });

    it('defect and correct, on rotors perturbed by up to 1e-3 and on raw even elements', () => {
      let worstDefect = 0;
      let worstCorrect = 0;
      const o1 = new Float64Array(D.r);
      const o2 = new Float64Array(D.r);
      for (const R of rotors) {
        const P = R.map((x) => x + uniform(rand, -1e-3, 1e-3));
        for (const X of [R, P]) {
          worstDefect = Math.max(worstDefect, Math.abs(fast.defect(X) - gen.defect(X)));
          worstCorrect = Math.max(worstCorrect, maxDiff(fast.correct(o1, X), gen.correct(o2, X)));
        }
      }
      expect(worstDefect).toBeLessThanOrEqual(AGREE);
      expect(worstCorrect).toBeLessThanOrEqual(AGREE);
    });
  });
}

/** Our 3D rotor as a gl-matrix quaternion [x, y, z, w] = [−e12, e02, −e01, s]. */
function toGlQuat(R: Float64Array): Float64Array {
  return Float64Array.from([-R[3]!, R[2]!, -R[1]!, R[0]!]);
}

describe('n = 3: agreement with gl-matrix quaternions and Rodrigues (brief §10.7)', () => {
  const D = dims(3);
  const K = D.kernels;
  const gen = createGenericKernels(D);
  const rand = seeded(303);
  const rotors = rotorInputs(gen, 3, 304).filter((R) => Math.abs(Math.hypot(...R) - 1) < 1e-14);

  it('quat.multiply, vec3.transformQuat and mat3.fromQuat give the same numbers to 1e-15', () => {
    expect(rotors.length).toBeGreaterThan(50);
    let worst = 0;
    const q = new Float64Array(4);
    const v3 = new Float64Array(3);
    const m3 = new Float64Array(9);
    const ours = new Float64Array(9);
    for (let i = 0; i < rotors.length; i += 1) {
      const a = rotors[i]!;
      const b = rotors[(i * 13 + 5) % rotors.length]!;
      quat.multiply(q, toGlQuat(a), toGlQuat(b));
      worst = Math.max(worst, maxDiff(toGlQuat(K.mul(new Float64Array(4), a, b)), q));
      const v = randomArray(rand, 3, -2, 2);
      vec3.transformQuat(v3, v, toGlQuat(a));
      worst = Math.max(worst, maxDiff(K.applyVector(new Float64Array(3), a, v), v3));
      // gl-matrix matrices are column-major: m3[c*3 + i] is our M[i*3 + c].
      mat3.fromQuat(m3, toGlQuat(a));
      K.toMatrix(ours, a);
      for (let i = 0; i < 3; i += 1) {
        for (let c = 0; c < 3; c += 1) worst = Math.max(worst, Math.abs(ours[i * 3 + c]! - m3[c * 3 + i]!));
      }
    }
    expect(worst).toBeLessThanOrEqual(1e-15);
  });

  it('a turn of 0.8 rad about (0.3, −0.5, 0.81)/|·| matches Rodrigues (e_c: 2.3e-16, random v: 1e-15) and maps to the quaternion of §3', () => {
    const len = Math.hypot(0.3, -0.5, 0.81);
    const u = [0.3 / len, -0.5 / len, 0.81 / len] as const;
    const theta = 0.8;
    // Axis u ↔ bivector: ω_xy = ω_z, ω_xz = −ω_y, ω_yz = ω_x.
    const B = Float64Array.from([theta * u[2], -theta * u[1], theta * u[0]]);
    const R = K.exp(new Float64Array(4), B, 1);
    const q = toGlQuat(R);
    const s = Math.sin(theta / 2);
    expect(maxDiff(q, [s * u[0], s * u[1], s * u[2], Math.cos(theta / 2)])).toBeLessThanOrEqual(2e-16);
    const rodrigues = (v: Float64Array): number => {
      const dot = u[0] * v[0]! + u[1] * v[1]! + u[2] * v[2]!;
      const cross = [u[1] * v[2]! - u[2] * v[1]!, u[2] * v[0]! - u[0] * v[2]!, u[0] * v[1]! - u[1] * v[0]!];
      const c = Math.cos(theta);
      const rod = [0, 1, 2].map((i) => v[i]! * c + cross[i]! * Math.sin(theta) + u[i]! * dot * (1 - c));
      return maxDiff(K.applyVector(new Float64Array(3), R, v), rod);
    };
    // Basis vectors: within one rounding of 1 (2^-53 ≈ 1.1e-16 measured).
    for (let c = 0; c < 3; c += 1) {
      const e = new Float64Array(3);
      e[c] = 1;
      expect(rodrigues(e)).toBeLessThanOrEqual(2.3e-16);
    }
    // Random |v| ≤ √3: a few roundings of each formula (4.4e-16 measured; gl-matrix's 6.7e-16).
    let worst = 0;
    for (let t = 0; t < 200; t += 1) worst = Math.max(worst, rodrigues(randomArray(rand, 3, -1, 1)));
    expect(worst).toBeLessThanOrEqual(1e-15);
  });

  it('correct normalises: the defect |R R~ − 1| = ||R|² − 1| drops from ~1e-3 to ≤ 4.5e-16 (two ulps of 1)', () => {
    for (let t = 0; t < 50; t += 1) {
      const R = rotors[t]!.map((x) => x + uniform(rand, -1e-3, 1e-3));
      const before = K.defect(R);
      expect(before).toBeGreaterThan(1e-6);
      const C = K.correct(new Float64Array(4), R);
      expect(K.defect(C)).toBeLessThanOrEqual(4.5e-16);
      expect(gen.defect(C)).toBeLessThanOrEqual(4.5e-16);
    }
  });
});

describe('n = 4: identities of the brief §10 (4, 5, 6, 8)', () => {
  const D = dims(4);
  const K = D.kernels;
  const gen = createGenericKernels(D);

  it('§10.4: s = 0.3, p = 0.2, B = (0.1, −0.4, 0.5, 0.2, 0.3, −0.6) gives R R~ = 1.04 − 0.2 I (1e-15), defect 0.2', () => {
    const R = Float64Array.from([0.3, 0.1, -0.4, 0.5, 0.2, 0.3, -0.6, 0.2]);
    const RR = K.mul(new Float64Array(8), R, reverse(4, R));
    expect(maxDiff(RR, [1.04, 0, 0, 0, 0, 0, 0, -0.2])).toBeLessThanOrEqual(1e-15);
    expect(Math.abs(K.defect(R) - 0.2)).toBeLessThanOrEqual(1e-15);
    // The norm can be made 1 while R is still no rotation: only correct() fixes both parts.
    const unit = R.map((x) => x / Math.sqrt(1.04));
    expect(K.defect(unit)).toBeGreaterThan(0.19);
    expect(K.defect(K.correct(new Float64Array(8), unit))).toBeLessThanOrEqual(1e-15);
  });

  it('§10.5: the closed-form exp equals the 40-term series to 2.3e-16 (one ulp of 1) for B = (0.7, −0.4, 1.5, 0.2, 0.9, −0.6)', () => {
    const B = Float64Array.from([0.7, -0.4, 1.5, 0.2, 0.9, -0.6]);
    // Series Σ X^m / m! with X = −B/2 as an even element, multiplied by the generic (table) product.
    const X = new Float64Array(8);
    for (let p = 0; p < 6; p += 1) X[1 + p] = -0.5 * B[p]!;
    const sum = new Float64Array(8);
    const term = new Float64Array(8);
    term[0] = 1;
    sum[0] = 1;
    for (let m = 1; m < 40; m += 1) {
      gen.mul(term, term, X);
      for (let a = 0; a < 8; a += 1) {
        term[a] = term[a]! / m;
        sum[a] = sum[a]! + term[a]!;
      }
    }
    const closed = K.exp(new Float64Array(8), B, 1);
    expect(maxDiff(closed, sum)).toBeLessThanOrEqual(2.3e-16);
    expect(K.defect(closed)).toBeLessThanOrEqual(4.5e-16);
  });

  it('§10.6: isoclinic B = e_xy + e_zw gives 0.770151 − 0.420735 (e_xy + e_zw) + 0.229849 I', () => {
    const R = K.exp(new Float64Array(8), Float64Array.from([1, 0, 0, 0, 0, 1]), 1);
    expect(maxDiff(R, [0.770151, -0.420735, 0, 0, 0, 0, -0.420735, 0.229849])).toBeLessThanOrEqual(5e-7);
    const exact = [(1 + Math.cos(1)) / 2, -Math.sin(1) / 2, 0, 0, 0, 0, -Math.sin(1) / 2, (1 - Math.cos(1)) / 2];
    expect(maxDiff(R, exact)).toBeLessThanOrEqual(1.2e-16);
  });

  it('§10.8: after a 1e-3 perturbation, correct gives R R~ = 1 to < 1e-15 (also at a double half turn)', () => {
    const rand = seeded(408);
    const I = Float64Array.from([0, 0, 0, 0, 0, 0, 0, 1]);
    const doubleHalf = gen.exp(new Float64Array(8), Float64Array.from([Math.PI, 0, 0, 0, 0, Math.PI]), 1);
    const bases = [I, I.map((x) => -x), doubleHalf];
    for (let t = 0; t < 60; t += 1) bases.push(randomRotor(gen, 4, rand));
    const RR = new Float64Array(8);
    let worst = 0;
    for (const R0 of bases) {
      const P = R0.map((x) => x + uniform(rand, -1e-3, 1e-3));
      expect(gen.defect(P)).toBeGreaterThan(1e-5);
      const C = K.correct(new Float64Array(8), P);
      gen.mul(RR, C, reverse(4, C));
      RR[0] = RR[0]! - 1;
      worst = Math.max(worst, maxDiff(RR, new Float64Array(8)));
      // The fix is small: it moves R by about the size of the perturbation.
      expect(maxDiff(C, R0)).toBeLessThanOrEqual(4e-3);
    }
    expect(worst).toBeLessThan(1e-15);
    // Exactly at ±I nothing moves.
    expect(maxDiff(K.correct(new Float64Array(8), I), I)).toBe(0);
  });

  it('in-place exp and correct (out aliases the input) give the same numbers', () => {
    const rand = seeded(409);
    const R = randomArray(rand, 8);
    const expected = K.correct(new Float64Array(8), R);
    expect(maxDiff(K.correct(R, R), expected)).toBe(0);
  });
});

describe('kernel selection per dimension', () => {
  it('n = 3 and 4 use the closed forms, the other n the generic tables', () => {
    expect(dims(3).kernels.name).toBe('fast3');
    expect(dims(4).kernels.name).toBe('fast4');
    for (const n of [2, 5, 6]) expect(dims(n).kernels.name ?? 'generic').not.toMatch(/^fast/);
  });

  it('the factories refuse the tables of another dimension (RangeError naming D)', () => {
    expect(() => createFast3Kernels(dims(4))).toThrow(RangeError);
    expect(() => createFast4Kernels(dims(3))).toThrow(/argument 'D'/);
  });
});
