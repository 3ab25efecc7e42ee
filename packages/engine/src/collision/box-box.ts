/**
 * Box–box contact manifolds in n dimensions: the separating-axis test (box-box-sat.ts, with the
 * closed-form 3D path), then either the clipped face region (box-box-clip.ts) or, for a mixed
 * axis, one point between the closest points of the two touching faces.
 *
 * @module
 */
import { clipBoxFacesKernel } from './box-box-clip.js';
import type { Manifold, Pose } from './manifold.js';
import { clearCandidates, reduceCandidates } from './manifold-reduce.js';
import type { CollisionBox } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN, SAT_EDGE, SAT_FACE_A } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { luFactor, luSolve } from './small-linear.js';

/** Relative pivot below which the closest-point system of a mixed axis counts as singular. */
const EDGE_PIVOT_TOLERANCE = 1e-12;

/**
 * Contacts between two boxes, normal from A to B.
 *
 * Face axis chosen by the SAT: the reference face is that face (of A or of B), the incident face
 * the other box's face most anti-parallel to it; the incident face is clipped against the
 * reference face, points with separation < margin kept and reduced to the manifold's bound
 * (deepest first, then spread out). Separation of a point = height of the incident face point
 * above the reference face plane.
 *
 * Mixed axis (p face directions of A and q of B, p, q >= 1; the edge–edge case of 3D): one
 * point midway between the closest points of A's supporting p-face and B's supporting q-face
 * (a least-squares problem in n − 1 unknowns, parameters clamped to the faces), separation = the
 * SAT separation. Its id is 2³² − 1 − (digits of A's face + 3ⁿ · digits of B's face), the digits
 * base 3 per axis (0 spanning, 1 at −, 2 at +), so it never meets a face-clip id.
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideBoxBox(
  out: Manifold,
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideBoxBoxKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideBoxBox} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideBoxBoxKernel(
  out: Manifold,
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  if (!scratch.boxBoxSat(n, a, poseA, b, poseB, scratch)) {
    out.count = 0;
    return false;
  }
  const sat = scratch.sat;
  if (sat.kind === SAT_EDGE) return mixedAxisContact(out, n, a, poseA, b, scratch);
  const cand = scratch.candidates;
  clearCandidates(cand);
  if (sat.kind === SAT_FACE_A) {
    // the local normal is ±1 on A's face axis: pass its sign as an integer
    clipBoxFacesKernel(n, a, poseA, sat.axis, sat.localNormal[sat.axis] > 0 ? 1 : -1, b, poseB, 0, scratch);
  } else {
    // B's face normal toward A is −normal; its sign along B's axis
    let s = 0;
    for (let i = 0; i < n; i += 1) s += poseB.M[i * n + sat.axis] * sat.normal[i];
    clipBoxFacesKernel(n, b, poseB, sat.axis, s > 0 ? -1 : 1, a, poseA, 1, scratch);
  }
  if (cand.count === 0) {
    out.count = 0;
    return false;
  }
  return reduceCandidates(out, n, cand, sat.normal, scratch);
}

/** The one-point manifold of a mixed SAT axis (see {@link collideBoxBox}). */
function mixedAxisContact(
  out: Manifold,
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  scratch: NarrowphaseScratch,
): boolean {
  const { sat, C, t, mat, piv, rhs, sol } = scratch;
  const L = sat.localNormal;
  const ha = a.halfExtents;
  const hb = b.halfExtents;
  const cA = scratch.v1;
  const cB = scratch.v2;
  const r = scratch.v3;
  const V = scratch.rows; // columns of the least-squares problem, stored by column (n−1 of n)
  const maskA = sat.maskA;
  const maskB = sat.maskB;
  // supporting faces in A's frame: A's toward +L, B's toward −L
  let codeA = 0;
  let codeB = 0;
  let p3 = 1;
  for (let i = 0; i < n; i += 1) cA[i] = 0;
  for (let i = 0; i < n; i += 1) cB[i] = t[i];
  for (let k = 0; k < n; k += 1, p3 *= 3) {
    if (!(maskA & (1 << k))) {
      const s = L[k] >= 0 ? 1 : -1;
      cA[k] = s * ha[k];
      codeA += (s > 0 ? 2 : 1) * p3;
    }
    if (!(maskB & (1 << k))) {
      let dot = 0;
      for (let i = 0; i < n; i += 1) dot += C[i * n + k] * L[i];
      const s = dot >= 0 ? -1 : 1;
      for (let i = 0; i < n; i += 1) cB[i] += s * hb[k] * C[i * n + k];
      codeB += (s > 0 ? 2 : 1) * p3;
    }
  }
  // unknowns z = (σ_A over maskA, σ_B over maskB), V = [a_k e_k | −b_k c_k]: minimise |V z − (cB − cA)|
  let m = 0;
  for (let k = 0; k < n; k += 1) {
    if (!(maskA & (1 << k))) continue;
    for (let i = 0; i < n; i += 1) V[m * n + i] = i === k ? ha[k] : 0;
    m += 1;
  }
  const countA = m;
  for (let k = 0; k < n; k += 1) {
    if (!(maskB & (1 << k))) continue;
    for (let i = 0; i < n; i += 1) V[m * n + i] = -hb[k] * C[i * n + k];
    m += 1;
  }
  for (let i = 0; i < n; i += 1) r[i] = cB[i] - cA[i];
  for (let p = 0; p < m; p += 1) {
    let s = 0;
    for (let i = 0; i < n; i += 1) s += V[p * n + i] * r[i];
    rhs[p] = s;
    for (let q = 0; q < m; q += 1) {
      let g = 0;
      for (let i = 0; i < n; i += 1) g += V[p * n + i] * V[q * n + i];
      mat[p * m + q] = g;
    }
  }
  if (luFactor(m, mat, piv, EDGE_PIVOT_TOLERANCE)) luSolve(m, mat, piv, rhs, sol);
  else for (let p = 0; p < sol.length; p += 1) sol[p] = 0;
  // midpoint of cA + V_A σ_A and cB + V_B σ_B, in A's frame, then to the world
  const mid = scratch.v4;
  for (let i = 0; i < n; i += 1) mid[i] = (cA[i] + cB[i]) / 2;
  for (let p = 0; p < m; p += 1) {
    // A's point is cA + V_A σ_A, B's is cB − V_B σ_B (its columns are stored negated)
    const s = (p < countA ? 0.5 : -0.5) * Math.max(-1, Math.min(1, sol[p]));
    for (let i = 0; i < n; i += 1) mid[i] += V[p * n + i] * s;
  }
  const MA = poseA.M;
  for (let i = 0; i < n; i += 1) {
    let s = poseA.x[i];
    for (let c = 0; c < n; c += 1) s += MA[i * n + c] * mid[c];
    out.points[i] = s;
    out.normal[i] = sat.normal[i];
  }
  out.separations[0] = sat.separation;
  out.ids[0] = 0xffffffff - (codeA + 3 ** n * codeB);
  out.count = 1;
  return true;
}
