/**
 * Table-driven rotor kernels for any n (used for n = 2 and n >= 5, and as the reference the
 * 3D/4D fast paths are tested against).
 *
 * Everything is built once per dimension from the even product table of `Dims` plus two small
 * tables for the sandwich products, so no call allocates: each kernel set owns its scratch.
 *
 * - Sandwiches R x R~ are done in two sparse stages (R x, then (R x) R~ keeping only the grade of
 *   x), which costs 2·r·n multiply-adds for a vector and 2·r·k for a bivector instead of the r²
 *   of a full product. The odd blades needed for R v are tabulated here, not in `Dims`.
 * - exp: closed forms for n = 2 and 3 (every bivector is simple there); for n >= 4 scaling and
 *   squaring: exp(X) = (exp(X / 2^s))^(2^s) with a Taylor polynomial of X / 2^s, whose operator
 *   norm is at most 2; the degree is chosen per call so the first dropped term is below 1e-17
 *   (about 7 terms for a typical time step, at most 29). Each squaring can double the rounding
 *   error, so a turn of total angle θ > 2 is accurate to about θ·1e-16.
 * - correct: n <= 3 normalises (every unit even element is a rotor there); otherwise matrix →
 *   nearest rotation (polar factor) → rotor by reflections, with the sign of the input.
 */
import type { Dims } from '../tables.js';
import { bladeProductSign, popcount } from '../tables.js';
import { orthonormalizeUnchecked } from '../linalg.js';
import { createMatrixToRotorScratch, matrixToRotorUnchecked } from '../matrix-to-rotor.js';
import type { RotorKernels } from './types.js';

/**
 * Largest operator norm of X = −scale·B/2 handed to the Taylor polynomial of exp (n >= 4); larger
 * X is halved first and the result squared back. At 2 the terms stay below 2 in size, so the sum
 * loses no digits to cancellation, and at most 28 terms are needed.
 */
const EXP_TAYLOR_RADIUS = 2;
/** The Taylor series stops at the first term whose bound is below this (rounding level of a unit rotor). */
const EXP_TAYLOR_TRUNCATION = 1e-17;
/** Guard on the Taylor degree (2^29/29! < 1e-17 already). */
const EXP_TAYLOR_MAX_DEGREE = 40;

/**
 * Builds the generic kernels of dimension D.n. Reads only the tables of D (never D.kernels), so
 * `dims` can call it while building D.
 */
export function createGenericKernels(D: Dims): RotorKernels {
  const { n, k, r, blades, bladeIndex, mulIndex, mulSign, reverseSign } = D;

  // Odd blades, in the same grade-then-lexicographic spirit (their order is internal).
  const oddBlades = new Int32Array(r);
  const oddIndex = new Int32Array(1 << n).fill(-1);
  {
    let o = 0;
    for (let m = 0; m < 1 << n; m += 1) {
      if ((popcount(m) & 1) === 1) {
        oddBlades[o] = m;
        oddIndex[m] = o;
        o += 1;
      }
    }
  }
  // Stage 1 of a vector sandwich: (even a)(e_i) = sign · (odd blade).
  const vecLeftIdx = new Int32Array(r * n);
  const vecLeftSign = new Float64Array(r * n);
  // Stage 2: (odd o)(R~ component b) contributes to e_t, with b = o XOR e_t.
  const vecRightIdx = new Int32Array(r * n);
  const vecRightSign = new Float64Array(r * n);
  for (let a = 0; a < r; a += 1) {
    for (let i = 0; i < n; i += 1) {
      vecLeftIdx[a * n + i] = oddIndex[blades[a]! ^ (1 << i)]!;
      vecLeftSign[a * n + i] = bladeProductSign(blades[a]!, 1 << i);
    }
  }
  for (let o = 0; o < r; o += 1) {
    for (let t = 0; t < n; t += 1) {
      const b = oddBlades[o]! ^ (1 << t);
      const bi = bladeIndex[b]!;
      vecRightIdx[o * n + t] = bi;
      vecRightSign[o * n + t] = bladeProductSign(oddBlades[o]!, b) * reverseSign[bi]!;
    }
  }
  // Stage 2 of a bivector sandwich: (even c)(R~ component b) contributes to plane q.
  const bivRightIdx = new Int32Array(r * k);
  const bivRightSign = new Float64Array(r * k);
  for (let c = 0; c < r; c += 1) {
    for (let q = 0; q < k; q += 1) {
      const b = bladeIndex[blades[c]! ^ blades[1 + q]!]!;
      bivRightIdx[c * k + q] = b;
      bivRightSign[c * k + q] = mulSign[c * r + b]! * reverseSign[b]!;
    }
  }

  // Gather form of the even product, (a b)_c = Σ_x a_x b_(gatherIdx) · gatherSign: the inner loop
  // then accumulates in a register instead of scattering into memory (about twice as fast).
  const gatherIdx = new Int32Array(r * r);
  const gatherSign = new Float64Array(r * r);
  for (let c = 0; c < r; c += 1) {
    for (let x = 0; x < r; x += 1) {
      const y = bladeIndex[blades[c]! ^ blades[x]!]!;
      gatherIdx[c * r + x] = y;
      gatherSign[c * r + x] = mulSign[x * r + y]!;
    }
  }
  // The same for a bivector on the left: (X P)_c = Σ_p X_p P_(bivGatherIdx) · bivGatherSign.
  const bivGatherIdx = new Int32Array(r * k);
  const bivGatherSign = new Float64Array(r * k);
  for (let c = 0; c < r; c += 1) {
    for (let p = 0; p < k; p += 1) {
      const y = bladeIndex[blades[c]! ^ blades[1 + p]!]!;
      bivGatherIdx[c * k + p] = y;
      bivGatherSign[c * k + p] = mulSign[(1 + p) * r + y]!;
    }
  }

  const q = new Float64Array(r);
  const rev = new Float64Array(r);
  const prod = new Float64Array(r);
  const unit = new Float64Array(n);
  const col = new Float64Array(n);
  const expX = new Float64Array(k);
  const expP = new Float64Array(r);
  const expT = new Float64Array(r);
  const corrM = new Float64Array(n * n);
  const corrR = new Float64Array(r);
  const m2r = createMatrixToRotorScratch(D);

  /** out = a b; `out` must not alias a or b. */
  function mulInto(out: Float64Array, a: Float64Array, b: Float64Array): void {
    for (let c = 0; c < r; c += 1) {
      const row = c * r;
      let s = 0;
      for (let x = 0; x < r; x += 1) s += gatherSign[row + x]! * a[x]! * b[gatherIdx[row + x]!]!;
      out[c] = s;
    }
  }

  function sandwichVector(out: Float64Array, R: Float64Array, v: Float64Array): Float64Array {
    q.fill(0);
    for (let a = 0; a < r; a += 1) {
      const ra = R[a]!;
      if (ra === 0) continue;
      const row = a * n;
      for (let i = 0; i < n; i += 1) q[vecLeftIdx[row + i]!] += vecLeftSign[row + i]! * ra * v[i]!;
    }
    for (let t = 0; t < n; t += 1) {
      let s = 0;
      for (let o = 0; o < r; o += 1) s += q[o]! * vecRightSign[o * n + t]! * R[vecRightIdx[o * n + t]!]!;
      out[t] = s;
    }
    return out;
  }

  function sandwichBivector(out: Float64Array, R: Float64Array, B: Float64Array): Float64Array {
    q.fill(0);
    for (let a = 0; a < r; a += 1) {
      const ra = R[a]!;
      if (ra === 0) continue;
      const row = a * r;
      for (let p = 0; p < k; p += 1) q[mulIndex[row + 1 + p]!] += mulSign[row + 1 + p]! * ra * B[p]!;
    }
    for (let p = 0; p < k; p += 1) {
      let s = 0;
      for (let c = 0; c < r; c += 1) s += q[c]! * bivRightSign[c * k + p]! * R[bivRightIdx[c * k + p]!]!;
      out[p] = s;
    }
    return out;
  }

  function reverseInto(out: Float64Array, R: Float64Array): Float64Array {
    for (let a = 0; a < r; a += 1) out[a] = R[a]! * reverseSign[a]!;
    return out;
  }

  /** out = X P for a bivector X (k numbers) and an even element P. */
  function mulBivectorLeft(out: Float64Array, X: Float64Array, P: Float64Array): void {
    for (let c = 0; c < r; c += 1) {
      const row = c * k;
      let s = 0;
      for (let p = 0; p < k; p += 1) s += bivGatherSign[row + p]! * X[p]! * P[bivGatherIdx[row + p]!]!;
      out[c] = s;
    }
  }

  function expSmallN(out: Float64Array, B: Float64Array, scale: number): Float64Array {
    let b2 = 0;
    for (let p = 0; p < k; p += 1) b2 += B[p]! * B[p]!;
    const theta = Math.abs(scale) * Math.sqrt(b2);
    const half = 0.5 * theta;
    // sin(θ/2)/θ, by its series where θ is so small that the quotient would lose digits.
    const sinc = theta < 1e-4 ? 0.5 - (theta * theta) / 48 : Math.sin(half) / theta;
    out[0] = Math.cos(half);
    const f = -sinc * scale;
    for (let p = 0; p < k; p += 1) out[1 + p] = f * B[p]!;
    return out;
  }

  function expSeries(out: Float64Array, B: Float64Array, scale: number): Float64Array {
    let b2 = 0;
    for (let p = 0; p < k; p += 1) b2 += B[p]! * B[p]!;
    // Multiplication by a bivector is antisymmetric on the even algebra; its norm is the sum of
    // the plane rates, at most sqrt(floor(n/2)) |B|.
    const bound = 0.5 * Math.abs(scale) * Math.sqrt(b2 * Math.floor(n / 2));
    let squarings = 0;
    let shrink = 1;
    while (bound * shrink > EXP_TAYLOR_RADIUS) {
      squarings += 1;
      shrink *= 0.5;
    }
    const x = bound * shrink;
    // Smallest degree whose first dropped term is below rounding (the result has norm 1).
    let degree = 1;
    let term = x;
    while (term > EXP_TAYLOR_TRUNCATION && degree < EXP_TAYLOR_MAX_DEGREE) {
      degree += 1;
      term *= x / degree;
    }
    const f = -0.5 * scale * shrink;
    for (let p = 0; p < k; p += 1) expX[p] = f * B[p]!;
    // Horner: P = 1 + X/1 (1 + X/2 (1 + ... (1 + X/degree)))
    expP.fill(0);
    expP[0] = 1;
    for (let m = degree; m >= 1; m -= 1) {
      mulBivectorLeft(expT, expX, expP);
      const inv = 1 / m;
      for (let c = 0; c < r; c += 1) expP[c] = expT[c]! * inv;
      expP[0] = expP[0]! + 1;
    }
    for (let s = 0; s < squarings; s += 1) {
      mulInto(expT, expP, expP);
      expP.set(expT);
    }
    out.set(expP);
    return out;
  }

  const exp = n <= 3 ? expSmallN : expSeries;

  const kernels: RotorKernels = {
    name: 'generic',
    mul(out, a, b) {
      mulInto(prod, a, b);
      out.set(prod);
      return out;
    },
    applyVector(out, R, v) {
      return sandwichVector(out, R, v);
    },
    applyVectorInverse(out, R, v) {
      reverseInto(rev, R);
      return sandwichVector(out, rev, v);
    },
    applyBivector(out, R, B) {
      return sandwichBivector(out, R, B);
    },
    applyBivectorInverse(out, R, B) {
      reverseInto(rev, R);
      return sandwichBivector(out, rev, B);
    },
    toMatrix(out, R) {
      for (let c = 0; c < n; c += 1) {
        unit.fill(0);
        unit[c] = 1;
        sandwichVector(col, R, unit);
        for (let i = 0; i < n; i += 1) out[i * n + c] = col[i]!;
      }
      return out;
    },
    exp(out, B, scale) {
      return exp(out, B, scale);
    },
    defect(R) {
      reverseInto(rev, R);
      mulInto(prod, R, rev);
      let worst = Math.abs(prod[0]! - 1);
      for (let a = 1; a < r; a += 1) worst = Math.max(worst, Math.abs(prod[a]!));
      return worst;
    },
    correct(out, R) {
      if (n <= 3) {
        let norm = 0;
        for (let a = 0; a < r; a += 1) norm += R[a]! * R[a]!;
        const inv = 1 / Math.sqrt(norm);
        for (let a = 0; a < r; a += 1) out[a] = R[a]! * inv;
        return out;
      }
      kernels.toMatrix(corrM, R);
      orthonormalizeUnchecked(n, corrM, corrM);
      if (!matrixToRotorUnchecked(D, corrR, corrM, m2r)) {
        throw new RangeError('rotorCorrect: the rotor is too far from a rotation to be corrected (its frame is a reflection)');
      }
      let dot = 0;
      for (let a = 0; a < r; a += 1) dot += corrR[a]! * R[a]!;
      const sign = dot < 0 ? -1 : 1;
      for (let a = 0; a < r; a += 1) out[a] = sign * corrR[a]!;
      return out;
    },
  };
  return kernels;
}
