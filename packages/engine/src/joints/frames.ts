/**
 * Frames of the angular rows: the rotor that carries the coordinate plane e₀∧e₁ onto a given
 * simple plane (the hinge's free plane), the k×k rotation of bivectors by a rotation matrix, and
 * the relative rotor of two bodies. Set-up helpers may allocate; the `…Into` helpers do not.
 *
 * @module
 */
import { matrixToRotor } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import type { Joint } from './joint.js';

/**
 * The k×k matrix that rotates bivectors by the rotation matrix M (n×n, row-major): column (ij) is
 * (M e_i) ∧ (M e_j), so the bivector R B R~ is rot · B. Writes `out`; allocates nothing.
 */
export function bivectorRotationInto(D: Dims, out: Float64Array, M: Float64Array): void {
  const { n, k, planeI, planeJ } = D;
  for (let col = 0; col < k; col += 1) {
    const i = planeI[col];
    const j = planeJ[col];
    for (let row = 0; row < k; row += 1) {
      const a = planeI[row];
      const b = planeJ[row];
      out[row * k + col] = M[a * n + i] * M[b * n + j] - M[b * n + i] * M[a * n + j];
    }
  }
}

/** out = R~ (the reverse of a rotor). */
export function reverseInto(D: Dims, out: Float64Array, R: Float64Array): void {
  const s = D.reverseSign;
  for (let c = 0; c < D.r; c += 1) out[c] = R[c] * s[c];
}

/**
 * The rotor C whose rotation takes e₀ → u and e₁ → v, where u ∧ v = F/|F| (F a simple bivector,
 * non-zero), completing the frame with Gram–Schmidt on the axes (last column flipped to keep the
 * determinant +1). So the coordinate plane 0 of the frame R·C is the plane F of the frame R.
 * Set-up only (allocates).
 */
export function planeFrameRotor(D: Dims, F: ArrayLike<number>): Float64Array {
  const { n, k, planeI, planeJ } = D;
  // Skew matrix of F: A[i][j] = F_ij, A[j][i] = −F_ij. For F = u∧v (unit): A x = u (v·x) − v (u·x).
  const A = new Float64Array(n * n);
  let norm2 = 0;
  for (let p = 0; p < k; p += 1) norm2 += F[p]! * F[p]!;
  const inv = 1 / Math.sqrt(norm2);
  for (let p = 0; p < k; p += 1) {
    A[planeI[p]! * n + planeJ[p]!] = F[p]! * inv;
    A[planeJ[p]! * n + planeI[p]!] = -F[p]! * inv;
  }
  // The column of A with the largest norm lies in the plane.
  let best = 0;
  let bestNorm = -1;
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let r = 0; r < n; r += 1) s += A[r * n + c]! ** 2;
    if (s > bestNorm) {
      bestNorm = s;
      best = c;
    }
  }
  const x = new Float64Array(n);
  for (let r = 0; r < n; r += 1) x[r] = A[r * n + best]!;
  normalize(x);
  const y = new Float64Array(n);
  for (let r = 0; r < n; r += 1) {
    let s = 0;
    for (let c = 0; c < n; c += 1) s += A[r * n + c]! * x[c]!;
    y[r] = s;
  }
  normalize(y);
  // Orientation: (x ∧ y)·F must be positive.
  let dot = 0;
  for (let p = 0; p < k; p += 1) {
    const i = planeI[p]!;
    const j = planeJ[p]!;
    dot += (x[i]! * y[j]! - x[j]! * y[i]!) * F[p]!;
  }
  if (dot < 0) for (let r = 0; r < n; r += 1) y[r] = -y[r]!;
  const cols: Float64Array[] = [x, y];
  for (let e = 0; e < n && cols.length < n; e += 1) {
    const v = new Float64Array(n);
    v[e] = 1;
    for (const c of cols) {
      let s = 0;
      for (let r = 0; r < n; r += 1) s += v[r]! * c[r]!;
      for (let r = 0; r < n; r += 1) v[r] = v[r]! - s * c[r]!;
    }
    let len = 0;
    for (let r = 0; r < n; r += 1) len += v[r]! * v[r]!;
    if (len < 1e-6) continue;
    normalize(v);
    cols.push(v);
  }
  const M = new Float64Array(n * n);
  for (let c = 0; c < n; c += 1) for (let r = 0; r < n; r += 1) M[r * n + c] = cols[c]![r]!;
  if (determinant(M, n) < 0) for (let r = 0; r < n; r += 1) M[r * n + n - 1] = -M[r * n + n - 1]!;
  return matrixToRotor(D, new Float64Array(D.r), M);
}

function normalize(v: Float64Array): void {
  let s = 0;
  for (let i = 0; i < v.length; i += 1) s += v[i]! * v[i]!;
  const inv = 1 / Math.sqrt(s);
  for (let i = 0; i < v.length; i += 1) v[i] = v[i]! * inv;
}

function determinant(M0: Float64Array, n: number): number {
  const M = Float64Array.from(M0);
  let det = 1;
  for (let c = 0; c < n; c += 1) {
    let p = c;
    for (let r = c + 1; r < n; r += 1) if (Math.abs(M[r * n + c]!) > Math.abs(M[p * n + c]!)) p = r;
    if (M[p * n + c] === 0) return 0;
    if (p !== c) {
      for (let j = 0; j < n; j += 1) {
        const t = M[c * n + j]!;
        M[c * n + j] = M[p * n + j]!;
        M[p * n + j] = t;
      }
      det = -det;
    }
    det *= M[c * n + c]!;
    for (let r = c + 1; r < n; r += 1) {
      const f = M[r * n + c]! / M[c * n + c]!;
      for (let j = c; j < n; j += 1) M[r * n + j] = M[r * n + j]! - f * M[c * n + j]!;
    }
  }
  return det;
}

/**
 * The world anchors of a joint from its bodies' current state (x, R), for the user-level
 * `error()` methods (allocates). pB is the anchor itself for a joint to the world.
 */
export function currentAnchors(joint: Joint): { pA: Float64Array; pB: Float64Array } {
  const D = joint.D;
  const pA = D.kernels.applyVector(new Float64Array(D.n), joint.a.R, joint.anchorA);
  for (let i = 0; i < D.n; i += 1) pA[i] = pA[i]! + joint.a.x[i]!;
  let pB: Float64Array;
  if (joint.b === null) {
    pB = Float64Array.from(joint.anchorB);
  } else {
    pB = D.kernels.applyVector(new Float64Array(D.n), joint.b.R, joint.anchorB);
    for (let i = 0; i < D.n; i += 1) pB[i] = pB[i]! + joint.b.x[i]!;
  }
  return { pA, pB };
}

/**
 * The relative rotor of the joint frames from the bodies' current rotors (allocates):
 * Q = R_JA~ R_JB (`worldFrame` false) or W = R_JB R_JA~ (true), R_JA = R_A C_A, R_JB = R_B C_B,
 * with the sign that makes its scalar part >= 0.
 */
export function currentRelative(joint: Joint, CA: Float64Array, CB: Float64Array, worldFrame: boolean): Float64Array {
  const D = joint.D;
  const K = D.kernels;
  const RJA = K.mul(new Float64Array(D.r), joint.a.R, CA);
  const RJB = joint.b === null ? Float64Array.from(CB) : K.mul(new Float64Array(D.r), joint.b.R, CB);
  const T = new Float64Array(D.r);
  reverseInto(D, T, RJA);
  const Q = worldFrame ? K.mul(new Float64Array(D.r), RJB, T) : K.mul(new Float64Array(D.r), T, RJB);
  if (Q[0]! < 0) for (let c = 0; c < D.r; c += 1) Q[c] = -Q[c]!;
  return Q;
}

/**
 * The angle (rad) of the turn a unit rotor Q makes, 2·acos|⟨Q⟩₀|, taken as 2·atan2(|Q − ⟨Q⟩₀|, |⟨Q⟩₀|):
 * the same number, but acos near 1 cannot tell turns below about 2e-8 rad from none.
 */
export function turnAngle(Q: Float64Array): number {
  let s = 0;
  for (let c = 1; c < Q.length; c += 1) s += Q[c]! * Q[c]!;
  return 2 * Math.atan2(Math.sqrt(s), Math.abs(Q[0]!));
}

/** The reference C_B = R_B~ R_A C_A of a joint (R_B = 1 for the world): Q = 1 now. Allocates. */
export function referenceFrame(joint: Joint, CA: Float64Array): Float64Array {
  const D = joint.D;
  const K = D.kernels;
  const AC = K.mul(new Float64Array(D.r), joint.a.R, CA);
  if (joint.b === null) return AC;
  const T = new Float64Array(D.r);
  reverseInto(D, T, joint.b.R);
  return K.mul(new Float64Array(D.r), T, AC);
}

/** The identity rotor of D (allocates). */
export function identityRotor(D: Dims): Float64Array {
  const R = new Float64Array(D.r);
  R[0] = 1;
  return R;
}

/** Distance between two points. */
export function distance(a: Float64Array, b: Float64Array): number {
  let s = 0;
  for (let i = 0; i < a.length; i += 1) s += (b[i]! - a[i]!) ** 2;
  return Math.sqrt(s);
}
