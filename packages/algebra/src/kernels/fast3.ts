/**
 * Closed-form rotor kernels for n = 3 (the quaternion algebra, written on our own storage).
 *
 * A 3D rotor is stored as [s, e01, e02, e12]. It is the unit quaternion (w, x, y, z) =
 * (s, −e12, +e02, −e01) of the same rotation (brief §3), and the product of rotors is the
 * Hamilton product of those quaternions, so every kernel below is the quaternion formula with
 * the components renamed and the signs folded in. Nothing is shuffled into gl-matrix's
 * [x, y, z, w] layout: see docs/architecture.md, "Why the 3D fast path does not call gl-matrix".
 *
 * Each kernel is an exact polynomial identity of the even sub-algebra, so it agrees with the
 * generic table-driven kernels on any input (unit or not): the sandwich R v R~ of a non-unit R
 * scales by |R|², as the generic one does. The sandwich is written out in each kernel (no shared
 * helper) so that V8 compiles it in place. Kernels read all inputs into locals before writing,
 * so `out` may alias any input, and they allocate nothing. They do not validate (hot path).
 */
import type { Dims } from '../tables.js';
import type { RotorKernels } from './types.js';

/**
 * Below this angle (rad) sin(θ/2)/θ is taken from its Taylor series 1/2 − θ²/48 + θ⁴/3840,
 * whose first omitted term is θ⁶/645120 < 2e-18: the quotient itself would lose digits to the
 * rounding of sin near 0 long before that bound.
 */
const SINC_SERIES_BELOW = 1e-2;

/**
 * Builds the 3D kernels. `D` must be `dims(3)`'s tables (only its size is implied: the kernels
 * are closed forms and read no table), so `dims` can call this while building D.
 */
export function createFast3Kernels(D: Dims): RotorKernels {
  if (D.n !== 3) throw new RangeError(`createFast3Kernels: argument 'D' must be the tables of n = 3, got n = ${D.n}`);

  return {
    name: 'fast3',

    mul(out, a, b) {
      const as = a[0]!,
        a1 = a[1]!,
        a2 = a[2]!,
        a3 = a[3]!;
      const bs = b[0]!,
        b1 = b[1]!,
        b2 = b[2]!,
        b3 = b[3]!;
      // The Hamilton product with (w, x, y, z) = (s, −e12, e02, −e01) substituted.
      out[0] = as * bs - a1 * b1 - a2 * b2 - a3 * b3;
      out[1] = as * b1 + a1 * bs + a3 * b2 - a2 * b3;
      out[2] = as * b2 + a2 * bs + a1 * b3 - a3 * b1;
      out[3] = as * b3 + a3 * bs + a2 * b1 - a1 * b2;
      return out;
    },

    applyVector(out, R, v) {
      const w = R[0]!,
        x = -R[3]!,
        y = R[2]!,
        z = -R[1]!;
      const v0 = v[0]!,
        v1 = v[1]!,
        v2 = v[2]!;
      // q v q* = (w² − u·u) v + 2 (u·v) u + 2 w (u × v), u = (x, y, z): exact for any q.
      const a = w * w - x * x - y * y - z * z;
      const d2 = 2 * (x * v0 + y * v1 + z * v2);
      const w2 = 2 * w;
      out[0] = a * v0 + d2 * x + w2 * (y * v2 - z * v1);
      out[1] = a * v1 + d2 * y + w2 * (z * v0 - x * v2);
      out[2] = a * v2 + d2 * z + w2 * (x * v1 - y * v0);
      return out;
    },

    applyVectorInverse(out, R, v) {
      // R~ is the conjugate quaternion.
      const w = R[0]!,
        x = R[3]!,
        y = -R[2]!,
        z = R[1]!;
      const v0 = v[0]!,
        v1 = v[1]!,
        v2 = v[2]!;
      // q v q* = (w² − u·u) v + 2 (u·v) u + 2 w (u × v), u = (x, y, z): exact for any q.
      const a = w * w - x * x - y * y - z * z;
      const d2 = 2 * (x * v0 + y * v1 + z * v2);
      const w2 = 2 * w;
      out[0] = a * v0 + d2 * x + w2 * (y * v2 - z * v1);
      out[1] = a * v1 + d2 * y + w2 * (z * v0 - x * v2);
      out[2] = a * v2 + d2 * z + w2 * (x * v1 - y * v0);
      return out;
    },

    applyBivector(out, R, B) {
      const w = R[0]!,
        x = -R[3]!,
        y = R[2]!,
        z = -R[1]!;
      // Rotate the axial vector (b12, −b02, b01) of B (ω_x = ω_yz, ω_y = −ω_xz, ω_z = ω_xy), map back.
      const v0 = B[2]!,
        v1 = -B[1]!,
        v2 = B[0]!;
      const a = w * w - x * x - y * y - z * z;
      const d2 = 2 * (x * v0 + y * v1 + z * v2);
      const w2 = 2 * w;
      const o0 = a * v0 + d2 * x + w2 * (y * v2 - z * v1);
      const o1 = a * v1 + d2 * y + w2 * (z * v0 - x * v2);
      const o2 = a * v2 + d2 * z + w2 * (x * v1 - y * v0);
      out[0] = o2;
      out[1] = -o1;
      out[2] = o0;
      return out;
    },

    applyBivectorInverse(out, R, B) {
      // R~ is the conjugate quaternion.
      const w = R[0]!,
        x = R[3]!,
        y = -R[2]!,
        z = R[1]!;
      // Rotate the axial vector (b12, −b02, b01) of B (ω_x = ω_yz, ω_y = −ω_xz, ω_z = ω_xy), map back.
      const v0 = B[2]!,
        v1 = -B[1]!,
        v2 = B[0]!;
      const a = w * w - x * x - y * y - z * z;
      const d2 = 2 * (x * v0 + y * v1 + z * v2);
      const w2 = 2 * w;
      const o0 = a * v0 + d2 * x + w2 * (y * v2 - z * v1);
      const o1 = a * v1 + d2 * y + w2 * (z * v0 - x * v2);
      const o2 = a * v2 + d2 * z + w2 * (x * v1 - y * v0);
      out[0] = o2;
      out[1] = -o1;
      out[2] = o0;
      return out;
    },

    toMatrix(out, R) {
      const w = R[0]!,
        x = -R[3]!,
        y = R[2]!,
        z = -R[1]!;
      const ww = w * w,
        xx = x * x,
        yy = y * y,
        zz = z * z;
      const xy = 2 * x * y,
        xz = 2 * x * z,
        yz = 2 * y * z;
      const wx = 2 * w * x,
        wy = 2 * w * y,
        wz = 2 * w * z;
      out[0] = ww + xx - yy - zz;
      out[1] = xy - wz;
      out[2] = xz + wy;
      out[3] = xy + wz;
      out[4] = ww - xx + yy - zz;
      out[5] = yz - wx;
      out[6] = xz - wy;
      out[7] = yz + wx;
      out[8] = ww - xx - yy + zz;
      return out;
    },

    exp(out, B, scale) {
      const b0 = B[0]!,
        b1 = B[1]!,
        b2 = B[2]!;
      // Every 3D bivector is simple: exp(−X/2) = cos(θ/2) − (sin(θ/2)/θ) X with X = scale·B, θ = |X|.
      const theta = Math.abs(scale) * Math.sqrt(b0 * b0 + b1 * b1 + b2 * b2);
      // sin(θ/2)/θ written out (not a helper): V8 boxes a double returned by a call it does not inline.
      const t2 = theta * theta;
      const f = -(theta < SINC_SERIES_BELOW ? 0.5 - t2 / 48 + (t2 * t2) / 3840 : Math.sin(0.5 * theta) / theta) * scale;
      out[0] = Math.cos(0.5 * theta);
      out[1] = f * b0;
      out[2] = f * b1;
      out[3] = f * b2;
      return out;
    },

    defect(R) {
      // R R~ = |R|² exactly in 3D (no other grade appears), so only the norm can drift.
      const s = R[0]!,
        a = R[1]!,
        b = R[2]!,
        c = R[3]!;
      return Math.abs(s * s + a * a + b * b + c * c - 1);
    },

    correct(out, R) {
      // Every unit even element of the 3D algebra is a rotor: normalising is the exact fix.
      // A zero R gives non-finite numbers; the public rotorCorrect refuses it first.
      const s = R[0]!,
        a = R[1]!,
        b = R[2]!,
        c = R[3]!;
      const inv = 1 / Math.sqrt(s * s + a * a + b * b + c * c);
      out[0] = s * inv;
      out[1] = a * inv;
      out[2] = b * inv;
      out[3] = c * inv;
      return out;
    },
  };
}
