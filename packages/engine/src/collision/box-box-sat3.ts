/**
 * The 3D box–box separating-axis test in closed form: 3 face axes of A, 3 of B, 9 edge pairs
 * e_i × c_j, in A's frame (Gottschalk's OBB test), visiting the axes in the same order and
 * choosing by the same rules as the general-n test (box-box-sat.ts), so the two agree.
 *
 * @module
 */
import type { Pose } from './manifold.js';
import type { CollisionBox } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN, SAT_EDGE, SAT_FACE_A, SAT_FACE_B, SAT_SEPARATED } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';

/**
 * Box–box SAT for n = 3 (see {@link boxBoxSat} for the contract). Unchecked hot-path kernel;
 * allocates nothing.
 */
export function boxBoxSat3(
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return boxBoxSat3Kernel(a, poseA, b, poseB, scratch);
}

/** {@link boxBoxSat3} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]`. */
export function boxBoxSat3Kernel(
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const MA = poseA.M;
  const MB = poseB.M;
  const xa = poseA.x;
  const xb = poseB.x;
  const { C, absC, t, sat } = scratch;
  const dx = xb[0] - xa[0];
  const dy = xb[1] - xa[1];
  const dz = xb[2] - xa[2];
  for (let i = 0; i < 3; i += 1) {
    const u0 = MA[i];
    const u1 = MA[3 + i];
    const u2 = MA[6 + i];
    for (let j = 0; j < 3; j += 1) {
      const s = u0 * MB[j] + u1 * MB[3 + j] + u2 * MB[6 + j];
      C[i * 3 + j] = s;
      absC[i * 3 + j] = Math.abs(s);
    }
    t[i] = u0 * dx + u1 * dy + u2 * dz;
  }
  const a0 = a.halfExtents[0];
  const a1 = a.halfExtents[1];
  const a2 = a.halfExtents[2];
  const b0 = b.halfExtents[0];
  const b1 = b.halfExtents[1];
  const b2 = b.halfExtents[2];
  const t0 = t[0];
  const t1 = t[1];
  const t2 = t[2];

  let sepA = -Infinity;
  let axisA = 0;
  for (let i = 0; i < 3; i += 1) {
    const ai = i === 0 ? a0 : i === 1 ? a1 : a2;
    const s = Math.abs(t[i]) - ai - (b0 * absC[i * 3] + b1 * absC[i * 3 + 1] + b2 * absC[i * 3 + 2]);
    if (s > margin) {
      sat.kind = SAT_SEPARATED;
      sat.separation = s;
      sat.axis = i;
      return false;
    }
    if (s > sepA) {
      sepA = s;
      axisA = i;
    }
  }
  let sepB = -Infinity;
  let axisB = 0;
  for (let j = 0; j < 3; j += 1) {
    const bj = j === 0 ? b0 : j === 1 ? b1 : b2;
    const d = t0 * C[j] + t1 * C[3 + j] + t2 * C[6 + j];
    const s = Math.abs(d) - (a0 * absC[j] + a1 * absC[3 + j] + a2 * absC[6 + j]) - bj;
    if (s > margin) {
      sat.kind = SAT_SEPARATED;
      sat.separation = s;
      sat.axis = 3 + j;
      return false;
    }
    if (s > sepB) {
      sepB = s;
      axisB = j;
    }
  }

  const tol = scratch.axisTolerance;
  let sepE = -Infinity;
  let edgeI = -1;
  let edgeJ = -1;
  let eL0 = 0;
  let eL1 = 0;
  let eL2 = 0;
  for (let i = 0; i < 3; i += 1) {
    for (let j = 0; j < 3; j += 1) {
      const c0 = C[j];
      const c1 = C[3 + j];
      const c2 = C[6 + j];
      // e_i × c_j; its length is the sine of the angle between the two edges
      let l0: number;
      let l1: number;
      let l2: number;
      if (i === 0) {
        l0 = 0;
        l1 = -c2;
        l2 = c1;
      } else if (i === 1) {
        l0 = c2;
        l1 = 0;
        l2 = -c0;
      } else {
        l0 = -c1;
        l1 = c0;
        l2 = 0;
      }
      const len = Math.sqrt(l0 * l0 + l1 * l1 + l2 * l2);
      if (!(len >= tol)) continue;
      l0 /= len;
      l1 /= len;
      l2 /= len;
      const d = t0 * l0 + t1 * l1 + t2 * l2;
      const ra = a0 * Math.abs(l0) + a1 * Math.abs(l1) + a2 * Math.abs(l2);
      let rb = 0;
      for (let k = 0; k < 3; k += 1) {
        if (k === j) continue;
        const bk = k === 0 ? b0 : k === 1 ? b1 : b2;
        rb += bk * Math.abs(C[k] * l0 + C[3 + k] * l1 + C[6 + k] * l2);
      }
      const s = Math.abs(d) - ra - rb;
      if (s > margin) {
        sat.kind = SAT_SEPARATED;
        sat.separation = s;
        sat.axis = -1;
        return false;
      }
      if (s > sepE) {
        sepE = s;
        edgeI = i;
        edgeJ = j;
        const sign = d >= 0 ? 1 : -1;
        eL0 = sign * l0;
        eL1 = sign * l1;
        eL2 = sign * l2;
      }
    }
  }

  const tie = scratch.featureTieTolerance;
  const n = sat.localNormal;
  let faceSep = sepA;
  sat.kind = SAT_FACE_A;
  if (sepB > sepA + tie) {
    faceSep = sepB;
    sat.kind = SAT_FACE_B;
  }
  sat.maskA = 0;
  sat.maskB = 0;
  if (edgeI >= 0 && sepE > faceSep + tie) {
    sat.kind = SAT_EDGE;
    sat.separation = sepE;
    sat.axis = -1;
    sat.maskA = 1 << edgeI;
    sat.maskB = 1 << edgeJ;
    n[0] = eL0;
    n[1] = eL1;
    n[2] = eL2;
  } else if (sat.kind === SAT_FACE_A) {
    const sign = t[axisA] >= 0 ? 1 : -1;
    n[0] = 0;
    n[1] = 0;
    n[2] = 0;
    n[axisA] = sign;
    sat.separation = sepA;
    sat.axis = axisA;
  } else {
    const d = t0 * C[axisB] + t1 * C[3 + axisB] + t2 * C[6 + axisB];
    const sign = d >= 0 ? 1 : -1;
    n[0] = sign * C[axisB];
    n[1] = sign * C[3 + axisB];
    n[2] = sign * C[6 + axisB];
    sat.separation = sepB;
    sat.axis = axisB;
  }
  const w = sat.normal;
  for (let r = 0; r < 3; r += 1) w[r] = MA[r * 3] * n[0] + MA[r * 3 + 1] * n[1] + MA[r * 3 + 2] * n[2];
  return true;
}
