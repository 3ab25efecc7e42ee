import { describe, expect, it } from 'vitest';
import * as A from '@physin/algebra';
import { dims } from '@physin/algebra';

const D4 = dims(4);
const good = {
  v: [1, 2, 3, 4],
  B: [0.1, 0.2, 0.3, 0.4, 0.5, 0.6],
  R: [1, 0, 0, 0, 0, 0, 0, 0],
  M: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1],
};

interface Case {
  what: string;
  outLength: number;
  call: (out: Float64Array) => unknown;
  error: typeof TypeError | typeof RangeError;
  message: RegExp;
}

/** Runs `call` on a sentinel-filled `out` and checks the error, its message and that out kept its bytes. */
function expectRejected(c: Case): void {
  const out = new Float64Array(c.outLength).fill(12345.678);
  const before = new Uint8Array(out.buffer.slice(0));
  let thrown: unknown;
  try {
    c.call(out);
  } catch (e) {
    thrown = e;
  }
  expect(thrown, c.what).toBeInstanceOf(c.error);
  expect((thrown as Error).message, c.what).toMatch(c.message);
  expect(Array.from(new Uint8Array(out.buffer)), `${c.what}: out untouched`).toEqual(Array.from(before));
}

const cases: Case[] = [
  // dims
  {
    what: 'dims(1)',
    outLength: 1,
    call: () => dims(1),
    error: RangeError,
    message: /dims: argument 'n' must be an integer in \[2, 8\], got 1/,
  },
  { what: 'dims(9)', outLength: 1, call: () => dims(9), error: RangeError, message: /'n'.*got 9/ },
  { what: 'dims(3.5)', outLength: 1, call: () => dims(3.5), error: RangeError, message: /'n'.*got 3.5/ },
  {
    what: "dims('3')",
    outLength: 1,
    call: () => dims('3' as unknown as number),
    error: TypeError,
    message: /'n' must be an integer, got string/,
  },
  { what: 'dims(NaN)', outLength: 1, call: () => dims(Number.NaN), error: RangeError, message: /'n'/ },
  {
    what: 'planeIndex i == j',
    outLength: 1,
    call: () => A.planeIndex(D4, 2, 2),
    error: RangeError,
    message: /'i' and 'j' must name two different axes/,
  },
  {
    what: 'planeIndex j = 4',
    outLength: 1,
    call: () => A.planeIndex(D4, 0, 4),
    error: RangeError,
    message: /planeIndex: argument 'j' must be an integer in \[0, 3\], got 4/,
  },
  {
    what: 'planeIndex D swapped',
    outLength: 1,
    call: () => A.planeIndex(4 as unknown as A.Dims, 0, 1),
    error: TypeError,
    message: /argument 'D' must be the tables returned by dims\(n\)/,
  },
  // bivectors
  {
    what: 'wedge short a',
    outLength: 6,
    call: (o) => A.wedge(D4, o, [1, 2, 3], good.v),
    error: TypeError,
    message: /wedge: argument 'a' must be a Float64Array-like of length 4 \(a vector for n = 4\), got length 3/,
  },
  {
    what: 'wedge NaN b',
    outLength: 6,
    call: (o) => A.wedge(D4, o, good.v, [1, Number.NaN, 0, 0]),
    error: RangeError,
    message: /wedge: argument 'b' must contain only finite numbers, got NaN at index 1/,
  },
  {
    what: 'wedge out wrong length',
    outLength: 5,
    call: (o) => A.wedge(D4, o, good.v, good.v),
    error: TypeError,
    message: /argument 'out' must be a Float64Array of length 6/,
  },
  {
    what: 'wedge out not Float64Array',
    outLength: 6,
    call: () => A.wedge(D4, [0, 0, 0, 0, 0, 0] as unknown as Float64Array, good.v, good.v),
    error: TypeError,
    message: /'out' must be a Float64Array of length 6.*got Array of length 6/,
  },
  {
    what: 'planeBivector i == j',
    outLength: 6,
    call: (o) => A.planeBivector(D4, o, 1, 1),
    error: RangeError,
    message: /'i' and 'j'/,
  },
  {
    what: 'planeBivector i = -1',
    outLength: 6,
    call: (o) => A.planeBivector(D4, o, -1, 2),
    error: RangeError,
    message: /'i' must be an integer in \[0, 3\], got -1/,
  },
  {
    what: 'planeBivector scale Inf',
    outLength: 6,
    call: (o) => A.planeBivector(D4, o, 0, 1, Number.POSITIVE_INFINITY),
    error: RangeError,
    message: /'scale' must be a finite number/,
  },
  {
    what: 'bivectorToMatrix short B',
    outLength: 16,
    call: (o) => A.bivectorToMatrix(D4, o, [1, 2]),
    error: TypeError,
    message: /'B' must be a Float64Array-like of length 6 \(a bivector for n = 4\), got length 2/,
  },
  {
    what: 'matrixToBivector short M',
    outLength: 6,
    call: (o) => A.matrixToBivector(D4, o, [1, 2, 3]),
    error: TypeError,
    message: /'M'.*length 16/,
  },
  {
    what: 'bivectorCommutator NaN A',
    outLength: 6,
    call: (o) => A.bivectorCommutator(D4, o, [0, 0, 0, 0, 0, Number.NaN], good.B),
    error: RangeError,
    message: /'A' must contain only finite numbers/,
  },
  {
    what: 'bivectorApply v not array',
    outLength: 4,
    call: (o) => A.bivectorApply(D4, o, good.B, 3 as unknown as number[]),
    error: TypeError,
    message: /'v'.*got number/,
  },
  {
    what: 'wedgeMatrix out wrong',
    outLength: 16,
    call: (o) => A.wedgeMatrix(D4, o, good.v),
    error: TypeError,
    message: /'out' must be a Float64Array of length 24/,
  },
  {
    what: 'bivectorDot short',
    outLength: 1,
    call: () => A.bivectorDot(D4, good.B, [1]),
    error: TypeError,
    message: /bivectorDot: argument 'B'/,
  },
  {
    what: 'bivectorNorm Inf',
    outLength: 1,
    call: () => A.bivectorNorm(D4, [Number.NEGATIVE_INFINITY, 0, 0, 0, 0, 0]),
    error: RangeError,
    message: /'B'.*-Infinity at index 0/,
  },
  {
    what: 'pfaffian4 of a 3D bivector',
    outLength: 1,
    call: () => A.pfaffian4([1, 2, 3]),
    error: TypeError,
    message: /pfaffian4: argument 'B' must be a Float64Array-like of length 6/,
  },
  {
    what: 'isSimple negative tol',
    outLength: 1,
    call: () => A.isSimple(D4, good.B, -1),
    error: RangeError,
    message: /'tol' must be >= 0/,
  },
  // rotors
  {
    what: 'rotorMul short a',
    outLength: 8,
    call: (o) => A.rotorMul(D4, o, [1, 0, 0, 0, 0, 0], good.R),
    error: TypeError,
    message: /^rotorMul: argument 'a' must be a Float64Array-like of length 8 \(a rotor for n = 4\), got length 6$/,
  },
  {
    what: 'rotorMul NaN b',
    outLength: 8,
    call: (o) => A.rotorMul(D4, o, good.R, [1, 0, 0, 0, 0, 0, 0, Number.NaN]),
    error: RangeError,
    message: /'b'.*NaN at index 7/,
  },
  {
    what: 'rotorIdentity out short',
    outLength: 4,
    call: (o) => A.rotorIdentity(D4, o),
    error: TypeError,
    message: /'out'.*length 8/,
  },
  { what: 'rotorReverse short R', outLength: 8, call: (o) => A.rotorReverse(D4, o, [1]), error: TypeError, message: /'R'/ },
  {
    what: 'rotorApplyVector short v',
    outLength: 4,
    call: (o) => A.rotorApplyVector(D4, o, good.R, [1, 2, 3]),
    error: TypeError,
    message: /rotorApplyVector: argument 'v'/,
  },
  {
    what: 'rotorApplyVectorInverse NaN R',
    outLength: 4,
    call: (o) => A.rotorApplyVectorInverse(D4, o, [Number.NaN, 0, 0, 0, 0, 0, 0, 0], good.v),
    error: RangeError,
    message: /'R'/,
  },
  {
    what: 'rotorApplyBivector short B',
    outLength: 6,
    call: (o) => A.rotorApplyBivector(D4, o, good.R, [1, 2, 3]),
    error: TypeError,
    message: /'B'.*length 6/,
  },
  {
    what: 'rotorApplyBivectorInverse out',
    outLength: 8,
    call: (o) => A.rotorApplyBivectorInverse(D4, o, good.R, good.B),
    error: TypeError,
    message: /'out'.*length 6/,
  },
  {
    what: 'rotorToMatrix out short',
    outLength: 9,
    call: (o) => A.rotorToMatrix(D4, o, good.R),
    error: TypeError,
    message: /'out'.*length 16/,
  },
  {
    what: 'matrixToRotor not orthogonal',
    outLength: 8,
    call: (o) =>
      A.matrixToRotor(
        D4,
        o,
        good.M.map((x) => 2 * x),
      ),
    error: RangeError,
    message: /not orthogonal|orthogonal to within 1e-6/,
  },
  {
    what: 'matrixToRotor reflection',
    outLength: 8,
    call: (o) => A.matrixToRotor(D4, o, [-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]),
    error: RangeError,
    message: /determinant -1/,
  },
  {
    what: 'matrixToRotor 3D reflection (odd swap)',
    outLength: 4,
    call: (o) => A.matrixToRotor(dims(3), o, [0, 1, 0, 1, 0, 0, 0, 0, 1]),
    error: RangeError,
    message: /determinant -1/,
  },
  {
    what: 'rotorFromPlane i == j',
    outLength: 8,
    call: (o) => A.rotorFromPlane(D4, o, 3, 3, 1),
    error: RangeError,
    message: /'i' and 'j'/,
  },
  {
    what: 'rotorFromPlane angle NaN',
    outLength: 8,
    call: (o) => A.rotorFromPlane(D4, o, 0, 1, Number.NaN),
    error: RangeError,
    message: /'angle' must be a finite number/,
  },
  {
    what: 'rotateInPlane j out of range',
    outLength: 8,
    call: (o) => A.rotateInPlane(D4, o, good.R, 0, 7, 1),
    error: RangeError,
    message: /'j'.*\[0, 3\].*7/,
  },
  {
    what: 'rotateInPlane i not integer',
    outLength: 8,
    call: (o) => A.rotateInPlane(D4, o, good.R, 0.5, 1, 1),
    error: RangeError,
    message: /'i'/,
  },
  {
    what: 'rotorExp scale string',
    outLength: 8,
    call: (o) => A.rotorExp(D4, o, good.B, '2' as unknown as number),
    error: TypeError,
    message: /'scale' must be a number/,
  },
  {
    what: 'rotorExp short B',
    outLength: 8,
    call: (o) => A.rotorExp(D4, o, [1, 2, 3]),
    error: TypeError,
    message: /rotorExp: argument 'B'/,
  },
  {
    what: 'rotorDefect short R',
    outLength: 1,
    call: () => A.rotorDefect(D4, [1, 0, 0, 0]),
    error: TypeError,
    message: /'R'.*length 8/,
  },
  {
    what: 'rotorCorrect zero',
    outLength: 8,
    call: (o) => A.rotorCorrect(D4, o, new Float64Array(8)),
    error: RangeError,
    message: /'R' is zero/,
  },
  {
    what: 'rotorNormalize zero',
    outLength: 8,
    call: (o) => A.rotorNormalize(D4, o, new Float64Array(8)),
    error: RangeError,
    message: /'R' is zero/,
  },
  {
    what: 'rotorNorm Inf',
    outLength: 1,
    call: () => A.rotorNorm(D4, [Number.POSITIVE_INFINITY, 0, 0, 0, 0, 0, 0, 0]),
    error: RangeError,
    message: /'R'/,
  },
  // inertia
  {
    what: 'inertiaFromCovariance out n*n',
    outLength: 16,
    call: (o) => A.inertiaFromCovariance(D4, o, good.M),
    error: TypeError,
    message: /'out'.*length 36/,
  },
  {
    what: 'inertiaFromCovariance NaN C',
    outLength: 36,
    call: (o) =>
      A.inertiaFromCovariance(
        D4,
        o,
        good.M.map((x, i) => (i === 5 ? Number.NaN : x)),
      ),
    error: RangeError,
    message: /'C'.*index 5/,
  },
  {
    what: 'inertiaDiagonal short c',
    outLength: 6,
    call: (o) => A.inertiaDiagonal(D4, o, [1, 2, 3]),
    error: TypeError,
    message: /'c'.*length 4/,
  },
  {
    what: 'parallelAxisShift mass NaN',
    outLength: 16,
    call: (o) => A.parallelAxisShift(D4, o, good.M, Number.NaN, good.v),
    error: RangeError,
    message: /'mass'/,
  },
  {
    what: 'parallelAxisShift short d',
    outLength: 16,
    call: (o) => A.parallelAxisShift(D4, o, good.M, 1, [1]),
    error: TypeError,
    message: /'d'/,
  },
  {
    what: 'inertiaWorldInverse short L',
    outLength: 6,
    call: (o) => A.inertiaWorldInverse(D4, o, good.R, good.B, [1, 2]),
    error: TypeError,
    message: /inertiaWorldInverse: argument 'L'/,
  },
  {
    what: 'inertiaWorldInverse bad scratch',
    outLength: 6,
    call: (o) => A.inertiaWorldInverse(D4, o, good.R, good.B, good.B, new Float64Array(2)),
    error: TypeError,
    message: /'scratch'/,
  },
  // linear algebra
  {
    what: 'symmetricEigen n = 0',
    outLength: 1,
    call: (o) => A.symmetricEigen(0, o, new Float64Array(1), [1]),
    error: RangeError,
    message: /symmetricEigen: argument 'n'/,
  },
  {
    what: 'symmetricEigen short A',
    outLength: 3,
    call: (o) => A.symmetricEigen(3, o, new Float64Array(9), [1, 2]),
    error: TypeError,
    message: /'A'.*length 9/,
  },
  {
    what: 'orthonormalize NaN',
    outLength: 4,
    call: (o) => A.orthonormalize(2, o, [1, 0, Number.NaN, 1]),
    error: RangeError,
    message: /'M'/,
  },
  {
    what: 'determinant short',
    outLength: 1,
    call: () => A.determinant(3, [1, 2, 3]),
    error: TypeError,
    message: /determinant: argument 'M'/,
  },
  {
    what: 'matMul out short',
    outLength: 3,
    call: (o) => A.matMul(2, o, [1, 0, 0, 1], [1, 0, 0, 1]),
    error: TypeError,
    message: /'out'/,
  },
];

describe('bad input is rejected with a named argument, before anything is written', () => {
  for (const c of cases) {
    it(c.what, () => expectRejected(c));
  }

  it('every dimension 2..8 is accepted and cached (the same object twice)', () => {
    for (let n = 2; n <= 8; n += 1) {
      const D = dims(n);
      expect(D).toBe(dims(n));
      expect(D.k).toBe((n * (n - 1)) / 2);
      expect(D.r).toBe(2 ** (n - 1));
      // Plane p is rotor component 1 + p.
      for (let p = 0; p < D.k; p += 1) expect(D.blades[1 + p]).toBe((1 << D.planeI[p]!) | (1 << D.planeJ[p]!));
      // The plane index formula of the conventions.
      for (let p = 0; p < D.k; p += 1) {
        const i = D.planeI[p]!;
        const j = D.planeJ[p]!;
        expect(i * n - (i * (i + 1)) / 2 + (j - i - 1)).toBe(p);
        expect(A.planeIndex(D, j, i)).toBe(p);
      }
    }
  });

  it('array-like inputs (number[]) work and give the same result as Float64Array', () => {
    const a = A.rotorExp(D4, new Float64Array(8), good.B);
    const b = A.rotorExp(D4, new Float64Array(8), Float64Array.from(good.B));
    expect(Array.from(a)).toEqual(Array.from(b));
  });
});
