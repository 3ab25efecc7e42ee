/**
 * Closed-form rotor kernels for n = 4.
 *
 * A 4D rotor is stored as R = [s, b01, b02, b03, b12, b13, b23, p]: a scalar s, a bivector B
 * (planes in lexicographic order) and a multiple p of the pseudoscalar I = e0123. The pieces of
 * the 4D even algebra that make closed forms possible:
 * - I² = +1 and I commutes with every even element, so P± = (1 ± I)/2 are central idempotents;
 * - I B is the bivector (−b23, b13, −b12, −b03, b02, −b01) (the Hodge dual up to sign);
 * - B² = −|B|² + 2 Pf(B) I with Pf(B) = b01 b23 − b02 b13 + b03 b12;
 * - R R~ = (s² + |B|² + p²) + 2 (s p − Pf(B)) I: only a scalar and an I part.
 * The two squares |B|² ∓ 2 Pf(B) are sums of three squares,
 *   |B|² − 2 Pf = (b01 − b23)² + (b02 + b13)² + (b03 − b12)²,
 *   |B|² + 2 Pf = (b01 + b23)² + (b02 − b13)² + (b03 + b12)²,
 * and the kernels compute them that way, which keeps them exact near the isoclinic case where
 * the difference form would cancel.
 *
 * The product and the sandwiches are unrolled from the blade product table (generated once
 * from the same sign rule as `bladeProductSign`, then checked against the generic kernels in
 * tests/algebra-fast-paths.test.ts). A vector sandwich is done in two stages, R v (an odd
 * element, 32 multiplies) then its grade-1 part times R~ (32 multiplies): cheaper than building
 * the 4×4 matrix (≈ 100 multiplies) for a single vector; the bivector sandwich likewise (96).
 * The sandwich bodies are written out in each kernel instead of calling a shared helper: V8 did
 * not inline a 9-argument helper there, which cost 60 % (28 ns against 17 ns per vector).
 *
 * Every kernel reads its inputs into locals before writing, so `out` may alias an input; none
 * allocates; none validates (hot path: the public functions of rotor.ts check first).
 */
import type { Dims } from '../tables.js';
import type { RotorKernels } from './types.js';

/**
 * Below this angle (rad) sin(θ/2)/θ is taken from its Taylor series 1/2 − θ²/48 + θ⁴/3840
 * (first omitted term θ⁶/645120 < 2e-18 here).
 */
const SINC_SERIES_BELOW = 1e-2;

/**
 * Builds the 4D kernels. `D` must be `dims(4)`'s tables (the kernels are closed forms and read
 * no table), so `dims` can call this while building D.
 */
export function createFast4Kernels(D: Dims): RotorKernels {
  if (D.n !== 4) throw new RangeError(`createFast4Kernels: argument 'D' must be the tables of n = 4, got n = ${D.n}`);

  return {
    name: 'fast4',

    mul(out, a, b) {
      const a0 = a[0]!,
        a1 = a[1]!,
        a2 = a[2]!,
        a3 = a[3]!,
        a4 = a[4]!,
        a5 = a[5]!,
        a6 = a[6]!,
        a7 = a[7]!;
      const b0 = b[0]!,
        b1 = b[1]!,
        b2 = b[2]!,
        b3 = b[3]!,
        b4 = b[4]!,
        b5 = b[5]!,
        b6 = b[6]!,
        b7 = b[7]!;
      out[0] = a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3 - a4 * b4 - a5 * b5 - a6 * b6 + a7 * b7;
      out[1] = a0 * b1 + a1 * b0 - a2 * b4 + a4 * b2 - a3 * b5 + a5 * b3 - a6 * b7 - a7 * b6;
      out[2] = a0 * b2 + a1 * b4 + a2 * b0 - a4 * b1 - a3 * b6 + a5 * b7 + a6 * b3 + a7 * b5;
      out[3] = a0 * b3 + a1 * b5 + a2 * b6 - a4 * b7 + a3 * b0 - a5 * b1 - a6 * b2 - a7 * b4;
      out[4] = a0 * b4 - a1 * b2 + a2 * b1 + a4 * b0 - a3 * b7 - a5 * b6 + a6 * b5 - a7 * b3;
      out[5] = a0 * b5 - a1 * b3 + a2 * b7 + a4 * b6 + a3 * b1 + a5 * b0 - a6 * b4 + a7 * b2;
      out[6] = a0 * b6 - a1 * b7 - a2 * b3 - a4 * b5 + a3 * b2 + a5 * b4 + a6 * b0 - a7 * b1;
      out[7] = a0 * b7 + a1 * b6 - a2 * b5 + a4 * b3 + a3 * b4 - a5 * b2 + a6 * b1 + a7 * b0;
      return out;
    },

    applyVector(out, R, v) {
      const r0 = R[0]!,
        r1 = R[1]!,
        r2 = R[2]!,
        r3 = R[3]!,
        r4 = R[4]!,
        r5 = R[5]!,
        r6 = R[6]!,
        r7 = R[7]!;
      const v0 = v[0]!,
        v1 = v[1]!,
        v2 = v[2]!,
        v3 = v[3]!;
      // R v: odd element on e0, e1, e2, e3, e012, e013, e023, e123.
      const t0 = r0 * v0 + r1 * v1 + r2 * v2 + r3 * v3;
      const t1 = r0 * v1 - r1 * v0 + r4 * v2 + r5 * v3;
      const t2 = r0 * v2 - r2 * v0 - r4 * v1 + r6 * v3;
      const t3 = r0 * v3 - r3 * v0 - r5 * v1 - r6 * v2;
      const t4 = r1 * v2 - r2 * v1 + r4 * v0 + r7 * v3;
      const t5 = r1 * v3 - r3 * v1 + r5 * v0 - r7 * v2;
      const t6 = r2 * v3 - r3 * v2 + r6 * v0 + r7 * v1;
      const t7 = r4 * v3 - r5 * v2 + r6 * v1 - r7 * v0;
      // (R v) R~, grade 1 only.
      out[0] = r0 * t0 + r1 * t1 + r2 * t2 + r3 * t3 + r4 * t4 + r5 * t5 + r6 * t6 + r7 * t7;
      out[1] = r0 * t1 - r1 * t0 + r4 * t2 + r5 * t3 - r2 * t4 - r3 * t5 - r7 * t6 + r6 * t7;
      out[2] = r0 * t2 - r2 * t0 - r4 * t1 + r6 * t3 + r1 * t4 + r7 * t5 - r3 * t6 - r5 * t7;
      out[3] = r0 * t3 - r3 * t0 - r5 * t1 - r6 * t2 - r7 * t4 + r1 * t5 + r2 * t6 + r4 * t7;
      return out;
    },

    applyVectorInverse(out, R, v) {
      // R~ keeps the scalar and I parts and negates the bivector part.
      const r0 = R[0]!,
        r1 = -R[1]!,
        r2 = -R[2]!,
        r3 = -R[3]!,
        r4 = -R[4]!,
        r5 = -R[5]!,
        r6 = -R[6]!,
        r7 = R[7]!;
      const v0 = v[0]!,
        v1 = v[1]!,
        v2 = v[2]!,
        v3 = v[3]!;
      // R v: odd element on e0, e1, e2, e3, e012, e013, e023, e123.
      const t0 = r0 * v0 + r1 * v1 + r2 * v2 + r3 * v3;
      const t1 = r0 * v1 - r1 * v0 + r4 * v2 + r5 * v3;
      const t2 = r0 * v2 - r2 * v0 - r4 * v1 + r6 * v3;
      const t3 = r0 * v3 - r3 * v0 - r5 * v1 - r6 * v2;
      const t4 = r1 * v2 - r2 * v1 + r4 * v0 + r7 * v3;
      const t5 = r1 * v3 - r3 * v1 + r5 * v0 - r7 * v2;
      const t6 = r2 * v3 - r3 * v2 + r6 * v0 + r7 * v1;
      const t7 = r4 * v3 - r5 * v2 + r6 * v1 - r7 * v0;
      // (R v) R~, grade 1 only.
      out[0] = r0 * t0 + r1 * t1 + r2 * t2 + r3 * t3 + r4 * t4 + r5 * t5 + r6 * t6 + r7 * t7;
      out[1] = r0 * t1 - r1 * t0 + r4 * t2 + r5 * t3 - r2 * t4 - r3 * t5 - r7 * t6 + r6 * t7;
      out[2] = r0 * t2 - r2 * t0 - r4 * t1 + r6 * t3 + r1 * t4 + r7 * t5 - r3 * t6 - r5 * t7;
      out[3] = r0 * t3 - r3 * t0 - r5 * t1 - r6 * t2 - r7 * t4 + r1 * t5 + r2 * t6 + r4 * t7;
      return out;
    },

    applyBivector(out, R, B) {
      const r0 = R[0]!,
        r1 = R[1]!,
        r2 = R[2]!,
        r3 = R[3]!,
        r4 = R[4]!,
        r5 = R[5]!,
        r6 = R[6]!,
        r7 = R[7]!;
      const B0 = B[0]!,
        B1 = B[1]!,
        B2 = B[2]!,
        B3 = B[3]!,
        B4 = B[4]!,
        B5 = B[5]!;
      // R B: a full even element.
      const u0 = -r1 * B0 - r2 * B1 - r3 * B2 - r4 * B3 - r5 * B4 - r6 * B5;
      const u1 = r0 * B0 - r2 * B3 + r4 * B1 - r3 * B4 + r5 * B2 - r7 * B5;
      const u2 = r0 * B1 + r1 * B3 - r4 * B0 - r3 * B5 + r6 * B2 + r7 * B4;
      const u3 = r0 * B2 + r1 * B4 + r2 * B5 - r5 * B0 - r6 * B1 - r7 * B3;
      const u4 = r0 * B3 - r1 * B1 + r2 * B0 - r5 * B5 + r6 * B4 - r7 * B2;
      const u5 = r0 * B4 - r1 * B2 + r4 * B5 + r3 * B0 - r6 * B3 + r7 * B1;
      const u6 = r0 * B5 - r2 * B2 - r4 * B4 + r3 * B1 + r5 * B3 - r7 * B0;
      const u7 = r1 * B5 - r2 * B4 + r4 * B2 + r3 * B3 - r5 * B1 + r6 * B0;
      // (R B) R~, grade 2 only.
      out[0] = r0 * u1 - r1 * u0 + r4 * u2 - r2 * u4 + r5 * u3 - r3 * u5 - r7 * u6 + r6 * u7;
      out[1] = r0 * u2 - r2 * u0 - r4 * u1 + r1 * u4 + r6 * u3 + r7 * u5 - r3 * u6 - r5 * u7;
      out[2] = r0 * u3 - r3 * u0 - r5 * u1 - r6 * u2 - r7 * u4 + r1 * u5 + r2 * u6 + r4 * u7;
      out[3] = r0 * u4 - r4 * u0 + r2 * u1 - r1 * u2 - r7 * u3 + r6 * u5 - r5 * u6 + r3 * u7;
      out[4] = r0 * u5 - r5 * u0 + r3 * u1 + r7 * u2 - r6 * u4 - r1 * u3 + r4 * u6 - r2 * u7;
      out[5] = r0 * u6 - r6 * u0 - r7 * u1 + r3 * u2 + r5 * u4 - r2 * u3 - r4 * u5 + r1 * u7;
      return out;
    },

    applyBivectorInverse(out, R, B) {
      // R~ keeps the scalar and I parts and negates the bivector part.
      const r0 = R[0]!,
        r1 = -R[1]!,
        r2 = -R[2]!,
        r3 = -R[3]!,
        r4 = -R[4]!,
        r5 = -R[5]!,
        r6 = -R[6]!,
        r7 = R[7]!;
      const B0 = B[0]!,
        B1 = B[1]!,
        B2 = B[2]!,
        B3 = B[3]!,
        B4 = B[4]!,
        B5 = B[5]!;
      // R B: a full even element.
      const u0 = -r1 * B0 - r2 * B1 - r3 * B2 - r4 * B3 - r5 * B4 - r6 * B5;
      const u1 = r0 * B0 - r2 * B3 + r4 * B1 - r3 * B4 + r5 * B2 - r7 * B5;
      const u2 = r0 * B1 + r1 * B3 - r4 * B0 - r3 * B5 + r6 * B2 + r7 * B4;
      const u3 = r0 * B2 + r1 * B4 + r2 * B5 - r5 * B0 - r6 * B1 - r7 * B3;
      const u4 = r0 * B3 - r1 * B1 + r2 * B0 - r5 * B5 + r6 * B4 - r7 * B2;
      const u5 = r0 * B4 - r1 * B2 + r4 * B5 + r3 * B0 - r6 * B3 + r7 * B1;
      const u6 = r0 * B5 - r2 * B2 - r4 * B4 + r3 * B1 + r5 * B3 - r7 * B0;
      const u7 = r1 * B5 - r2 * B4 + r4 * B2 + r3 * B3 - r5 * B1 + r6 * B0;
      // (R B) R~, grade 2 only.
      out[0] = r0 * u1 - r1 * u0 + r4 * u2 - r2 * u4 + r5 * u3 - r3 * u5 - r7 * u6 + r6 * u7;
      out[1] = r0 * u2 - r2 * u0 - r4 * u1 + r1 * u4 + r6 * u3 + r7 * u5 - r3 * u6 - r5 * u7;
      out[2] = r0 * u3 - r3 * u0 - r5 * u1 - r6 * u2 - r7 * u4 + r1 * u5 + r2 * u6 + r4 * u7;
      out[3] = r0 * u4 - r4 * u0 + r2 * u1 - r1 * u2 - r7 * u3 + r6 * u5 - r5 * u6 + r3 * u7;
      out[4] = r0 * u5 - r5 * u0 + r3 * u1 + r7 * u2 - r6 * u4 - r1 * u3 + r4 * u6 - r2 * u7;
      out[5] = r0 * u6 - r6 * u0 - r7 * u1 + r3 * u2 + r5 * u4 - r2 * u3 - r4 * u5 + r1 * u7;
      return out;
    },

    toMatrix(out, R) {
      const r0 = R[0]!,
        r1 = R[1]!,
        r2 = R[2]!,
        r3 = R[3]!,
        r4 = R[4]!,
        r5 = R[5]!,
        r6 = R[6]!,
        r7 = R[7]!;
      const q0 = r0 * r0,
        q1 = r1 * r1,
        q2 = r2 * r2,
        q3 = r3 * r3;
      const q4 = r4 * r4,
        q5 = r5 * r5,
        q6 = r6 * r6,
        q7 = r7 * r7;
      // Column c is R e_c R~ (expanded symbolically from the product table).
      out[0] = q0 - q1 - q2 - q3 + q4 + q5 + q6 - q7;
      out[5] = q0 - q1 + q2 + q3 - q4 - q5 + q6 - q7;
      out[10] = q0 + q1 - q2 + q3 - q4 + q5 - q6 - q7;
      out[15] = q0 + q1 + q2 - q3 + q4 - q5 - q6 - q7;
      out[4] = -2 * (r0 * r1 + r2 * r4 + r3 * r5 + r6 * r7);
      out[1] = 2 * (r0 * r1 - r2 * r4 - r3 * r5 + r6 * r7);
      out[8] = 2 * (-r0 * r2 + r1 * r4 - r3 * r6 + r5 * r7);
      out[2] = 2 * (r0 * r2 + r1 * r4 - r3 * r6 - r5 * r7);
      out[12] = 2 * (-r0 * r3 + r1 * r5 + r2 * r6 - r4 * r7);
      out[3] = 2 * (r0 * r3 + r1 * r5 + r2 * r6 + r4 * r7);
      out[9] = -2 * (r1 * r2 + r0 * r4 + r5 * r6 + r3 * r7);
      out[6] = 2 * (-r1 * r2 + r0 * r4 - r5 * r6 + r3 * r7);
      out[13] = 2 * (-r1 * r3 - r0 * r5 + r4 * r6 + r2 * r7);
      out[7] = 2 * (-r1 * r3 + r0 * r5 + r4 * r6 - r2 * r7);
      out[14] = -2 * (r2 * r3 + r4 * r5 + r0 * r6 + r1 * r7);
      out[11] = 2 * (-r2 * r3 - r4 * r5 + r0 * r6 + r1 * r7);
      return out;
    },

    exp(out, B, scale) {
      const b0 = scale * B[0]!,
        b1 = scale * B[1]!,
        b2 = scale * B[2]!;
      const b3 = scale * B[3]!,
        b4 = scale * B[4]!,
        b5 = scale * B[5]!;
      // X = scale·B; exp(−X/2) = Σ± P± (cos(θ±/2) − (sin(θ±/2)/θ±) X), θ± = √(|X|² ∓ 2 Pf X):
      // no division by θ+² − θ−², so the isoclinic case (one θ zero) needs no special branch.
      const dp0 = b0 - b5,
        dp1 = b1 + b4,
        dp2 = b2 - b3;
      const dm0 = b0 + b5,
        dm1 = b1 - b4,
        dm2 = b2 + b3;
      const thetaP = Math.sqrt(dp0 * dp0 + dp1 * dp1 + dp2 * dp2);
      const thetaM = Math.sqrt(dm0 * dm0 + dm1 * dm1 + dm2 * dm2);
      const cP = Math.cos(0.5 * thetaP);
      const cM = Math.cos(0.5 * thetaM);
      // sin(θ/2)/θ written out (not a helper): V8 boxes a double returned by a call it does not inline.
      const tP2 = thetaP * thetaP,
        tM2 = thetaM * thetaM;
      const fP = thetaP < SINC_SERIES_BELOW ? 0.5 - tP2 / 48 + (tP2 * tP2) / 3840 : Math.sin(0.5 * thetaP) / thetaP;
      const fM = thetaM < SINC_SERIES_BELOW ? 0.5 - tM2 / 48 + (tM2 * tM2) / 3840 : Math.sin(0.5 * thetaM) / thetaM;
      // P± = (1 ± I)/2 expanded: the I parts of the two halves differ in sign.
      const g = 0.5 * (fP + fM);
      const h = 0.5 * (fP - fM);
      out[0] = 0.5 * (cP + cM);
      // −g X − h (I X), with I X = (−b5, b4, −b3, −b2, b1, −b0).
      out[1] = -g * b0 + h * b5;
      out[2] = -g * b1 - h * b4;
      out[3] = -g * b2 + h * b3;
      out[4] = -g * b3 + h * b2;
      out[5] = -g * b4 - h * b1;
      out[6] = -g * b5 + h * b0;
      out[7] = 0.5 * (cP - cM);
      return out;
    },

    defect(R) {
      const s = R[0]!,
        p = R[7]!;
      const b0 = R[1]!,
        b1 = R[2]!,
        b2 = R[3]!,
        b3 = R[4]!,
        b4 = R[5]!,
        b5 = R[6]!;
      const a = s * s + b0 * b0 + b1 * b1 + b2 * b2 + b3 * b3 + b4 * b4 + b5 * b5 + p * p;
      const c = 2 * (s * p - (b0 * b5 - b1 * b4 + b2 * b3));
      return Math.max(Math.abs(a - 1), Math.abs(c));
    },

    correct(out, R) {
      const s = R[0]!,
        p = R[7]!;
      const b0 = R[1]!,
        b1 = R[2]!,
        b2 = R[3]!,
        b3 = R[4]!,
        b4 = R[5]!,
        b5 = R[6]!;
      // R R~ = a + c I = P+ (a + c) + P− (a − c); both halves written as sums of squares.
      const sp = s + p,
        sm = s - p;
      const dp0 = b0 - b5,
        dp1 = b1 + b4,
        dp2 = b2 - b3;
      const dm0 = b0 + b5,
        dm1 = b1 - b4,
        dm2 = b2 + b3;
      const aPlus = sp * sp + dp0 * dp0 + dp1 * dp1 + dp2 * dp2;
      const aMinus = sm * sm + dm0 * dm0 + dm1 * dm1 + dm2 * dm2;
      // X = (R R~)^(−1/2) = P+ (a + c)^(−1/2) + P− (a − c)^(−1/2) is central, so R X is exact:
      // (R X)(R X)~ = R R~ X² = 1. A double half turn (R = ±I) has a ± c = 1 and X = 1.
      const xP = 1 / Math.sqrt(aPlus);
      const xM = 1 / Math.sqrt(aMinus);
      const x0 = 0.5 * (xP + xM);
      const x1 = 0.5 * (xP - xM);
      // R (x0 + x1 I) = x0 R + x1 (p + I B + s I).
      out[0] = x0 * s + x1 * p;
      out[1] = x0 * b0 - x1 * b5;
      out[2] = x0 * b1 + x1 * b4;
      out[3] = x0 * b2 - x1 * b3;
      out[4] = x0 * b3 - x1 * b2;
      out[5] = x0 * b4 + x1 * b1;
      out[6] = x0 * b5 - x1 * b0;
      out[7] = x0 * p + x1 * s;
      return out;
    },
  };
}
