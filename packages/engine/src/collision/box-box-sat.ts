/**
 * The n-dimensional separating-axis test for two boxes.
 *
 * **Candidate axes.** Two convex polytopes are disjoint iff some direction separates their
 * projections, and for polytopes it suffices to try the normals of the hyperplanes spanned by a
 * p-dimensional face direction of A and a q-dimensional face direction of B with p + q = n − 1.
 * A box's face directions are spans of subsets of its axes, so a candidate is a pair of axis
 * subsets (S_A, S_B), |S_A| + |S_B| = n − 1, and its normal is the generalised cross product of
 * those n − 1 unit vectors. The count is Σ_p C(n,p)·C(n,n−1−p) = C(2n, n−1): 4, 15, 56, 210, 792
 * for n = 2..6. q = 0 gives A's face normals, p = 0 B's; in 3D p = q = 1 are the 9 edge pairs.
 *
 * **Order** of {@link satAxisTable}: A's n face axes (axis i = the one axis missing from S_A),
 * then B's n face axes, then the mixed pairs by p = 1..n−2, each by increasing S_A bitmask, then
 * increasing S_B bitmask. Ties between axes of equal separation go to the earlier axis.
 *
 * **Computation** (in A's frame, where A's axes are the unit vectors): the normal is zero on the
 * coordinates in S_A, so it lives in the m = n − p complementary coordinates and is the
 * generalised cross product there of B's q = m − 1 axes restricted to them: closed-form cofactors
 * for m = 2 (a perpendicular), 3 (the cross product) and 4; for m >= 5 modified Gram–Schmidt of
 * the rows (the product of their residual lengths is the cross product's length) and the unit
 * vector e_k least covered by them minus its projections. The cross product's length is the
 * (n−1)-volume the n − 1 unit axes span (the sine of the angle between two edges in 3D); below
 * `axisTolerance` the candidate is degenerate and skipped. Separation along the unit L:
 * |t·L| − Σ_i a_i|L_i| − Σ_j b_j|c_j·L|, t the centre offset and c_j B's axes in A's frame.
 *
 * **Choice**: the largest separation of each kind (A face, B face, mixed); A's face is the
 * reference unless B's beats it by more than `featureTieTolerance`, and a mixed axis wins only
 * when it beats the chosen face by more than that too (faces give full manifolds and are
 * coherent from step to step).
 *
 * @module
 */
import { boxBoxSat3Kernel } from './box-box-sat3.js';
import { checkNarrowphaseDimension } from './manifold.js';
import type { Pose } from './manifold.js';
import type { CollisionBox } from './narrowphase-shapes.js';
import {
  NARROWPHASE_MARGIN,
  SAT_EDGE,
  SAT_FACE_A,
  SAT_FACE_B,
  SAT_SEPARATED,
  SCALAR_AXIS_TOLERANCE,
} from './narrowphase-scratch.js';
import type { NarrowphaseScratch, SatResult } from './narrowphase-scratch.js';

/** The candidate axes of the box–box SAT in n dimensions, as pairs of axis bitmasks. */
export interface SatAxisTable {
  /** Count of candidate axes, C(2n, n−1). */
  readonly count: number;
  /** For each candidate, the bitmask of A's axes in S_A (p bits). */
  readonly maskA: Uint16Array;
  /** For each candidate, the bitmask of B's axes in S_B (q = n − 1 − p bits). */
  readonly maskB: Uint16Array;
}

const tables: (SatAxisTable | undefined)[] = [];

/** C(2n, n−1): the count of box–box SAT candidate axes in n dimensions (4, 15, 56, 210, 792 for n = 2..6). */
export function satAxisCount(n: number): number {
  checkNarrowphaseDimension(n, 'n');
  let c = 1;
  for (let i = 1; i <= n - 1; i += 1) c = (c * (n + 2 + i - 1)) / i;
  // C(2n, n−1) = Π_{i=1}^{n−1} (n + 1 + i) / i
  return Math.round(c);
}

/**
 * The candidate axes in the order the SAT visits them (see the module comment), built once per n
 * and cached. The table is frozen; do not write its arrays.
 */
export function satAxisTable(n: number): SatAxisTable {
  checkNarrowphaseDimension(n, 'n');
  const cached = tables[n];
  if (cached) return cached;
  const full = (1 << n) - 1;
  const maskA: number[] = [];
  const maskB: number[] = [];
  for (let i = 0; i < n; i += 1) {
    maskA.push(full & ~(1 << i));
    maskB.push(0);
  }
  for (let j = 0; j < n; j += 1) {
    maskA.push(0);
    maskB.push(full & ~(1 << j));
  }
  for (let p = 1; p <= n - 2; p += 1) {
    const q = n - 1 - p;
    for (let sa = 0; sa <= full; sa += 1) {
      if (popcount(sa) !== p) continue;
      for (let sb = 0; sb <= full; sb += 1) {
        if (popcount(sb) !== q) continue;
        maskA.push(sa);
        maskB.push(sb);
      }
    }
  }
  const table: SatAxisTable = Object.freeze({
    count: maskA.length,
    maskA: Uint16Array.from(maskA),
    maskB: Uint16Array.from(maskB),
  });
  tables[n] = table;
  return table;
}

/** Count of set bits. */
export function popcount(x: number): number {
  let c = 0;
  for (let v = x; v !== 0; v &= v - 1) c += 1;
  return c;
}

/**
 * Box–box separating-axis test: writes the chosen axis into `scratch.sat` and returns false when
 * some axis separates the boxes by more than `margin` (kind SAT_SEPARATED), true otherwise.
 * n = 3 takes the closed-form path ({@link boxBoxSat3}); every other n the general one
 * ({@link boxBoxSatGeneral}). Unchecked hot-path kernel; allocates nothing.
 */
export function boxBoxSat(
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return boxBoxSatKernel(n, a, poseA, b, poseB, scratch);
}

/** {@link boxBoxSat} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]`. */
export function boxBoxSatKernel(
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  return n === 3 ? boxBoxSat3Kernel(a, poseA, b, poseB, scratch) : boxBoxSatGeneralKernel(n, a, poseA, b, poseB, scratch);
}

/**
 * Fills scratch.C (C[i*n + j] = A's axis i · B's axis j, i.e. B's axes in A's frame, by columns),
 * scratch.absC and scratch.t (B's centre in A's frame). Unchecked.
 */
export function prepareBoxPair(n: number, poseA: Pose, poseB: Pose, scratch: NarrowphaseScratch): void {
  const MA = poseA.M;
  const MB = poseB.M;
  const { C, absC, t } = scratch;
  for (let i = 0; i < n; i += 1) {
    for (let j = 0; j < n; j += 1) {
      let s = 0;
      for (let r = 0; r < n; r += 1) s += MA[r * n + i] * MB[r * n + j];
      C[i * n + j] = s;
      absC[i * n + j] = Math.abs(s);
    }
    let s = 0;
    for (let r = 0; r < n; r += 1) s += MA[r * n + i] * (poseB.x[r] - poseA.x[r]);
    t[i] = s;
  }
}

/**
 * The general-n box–box SAT over all {@link satAxisCount}(n) candidates (see the module comment).
 * Any n in 2..8; used for every n but 3, and by the tests to check the 3D path.
 * Unchecked hot-path kernel; allocates nothing.
 */
export function boxBoxSatGeneral(
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return boxBoxSatGeneralKernel(n, a, poseA, b, poseB, scratch);
}

/** {@link boxBoxSatGeneral} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]`. */
export function boxBoxSatGeneralKernel(
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  prepareBoxPair(n, poseA, poseB, scratch);
  const { C, absC, t, rows, cols, sat, scalars } = scratch;
  const margin = scalars[NARROWPHASE_MARGIN];
  const ha = a.halfExtents;
  const hb = b.halfExtents;
  const L = scratch.v0;

  // A's faces
  let sepA = -Infinity;
  let axisA = 0;
  for (let i = 0; i < n; i += 1) {
    let rb = 0;
    for (let j = 0; j < n; j += 1) rb += hb[j] * absC[i * n + j];
    const s = Math.abs(t[i]) - ha[i] - rb;
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
  // B's faces
  let sepB = -Infinity;
  let axisB = 0;
  for (let j = 0; j < n; j += 1) {
    let ra = 0;
    let d = 0;
    for (let i = 0; i < n; i += 1) {
      ra += ha[i] * absC[i * n + j];
      d += t[i] * C[i * n + j];
    }
    const s = Math.abs(d) - ra - hb[j];
    if (s > margin) {
      sat.kind = SAT_SEPARATED;
      sat.separation = s;
      sat.axis = n + j;
      return false;
    }
    if (s > sepB) {
      sepB = s;
      axisB = j;
    }
  }
  // mixed axes
  const table = satAxisTable(n);
  let sepE = -Infinity;
  let edgeIndex = -1;
  scalars[SCALAR_AXIS_TOLERANCE] = scratch.axisTolerance;
  for (let e = 2 * n; e < table.count; e += 1) {
    if (!mixedAxisSeparation(n, table.maskA[e], table.maskB[e], ha, hb, C, t, rows, cols, L, scalars)) continue;
    const s = scalars[0];
    if (s > margin) {
      sat.kind = SAT_SEPARATED;
      sat.separation = s;
      sat.axis = -1;
      return false;
    }
    if (s > sepE) {
      sepE = s;
      edgeIndex = e;
    }
  }

  const tie = scratch.featureTieTolerance;
  let faceSep = sepA;
  sat.kind = SAT_FACE_A;
  if (sepB > sepA + tie) {
    faceSep = sepB;
    sat.kind = SAT_FACE_B;
  }
  if (edgeIndex >= 0 && sepE > faceSep + tie) {
    // recompute the winner's normal (the loop kept only its index)
    mixedAxisSeparation(n, table.maskA[edgeIndex], table.maskB[edgeIndex], ha, hb, C, t, rows, cols, L, scalars);
    let d = 0;
    for (let i = 0; i < n; i += 1) d += t[i] * L[i];
    const sign = d >= 0 ? 1 : -1;
    for (let i = 0; i < n; i += 1) sat.localNormal[i] = sign * L[i];
    sat.kind = SAT_EDGE;
    sat.separation = sepE;
    sat.axis = -1;
    sat.maskA = table.maskA[edgeIndex];
    sat.maskB = table.maskB[edgeIndex];
  } else if (sat.kind === SAT_FACE_A) {
    const sign = t[axisA] >= 0 ? 1 : -1;
    for (let i = 0; i < n; i += 1) sat.localNormal[i] = 0;
    sat.localNormal[axisA] = sign;
    sat.separation = sepA;
    sat.axis = axisA;
  } else {
    let d = 0;
    for (let i = 0; i < n; i += 1) d += t[i] * C[i * n + axisB];
    const sign = d >= 0 ? 1 : -1;
    for (let i = 0; i < n; i += 1) sat.localNormal[i] = sign * C[i * n + axisB];
    sat.separation = sepB;
    sat.axis = axisB;
  }
  if (sat.kind !== SAT_EDGE) {
    sat.maskA = 0;
    sat.maskB = 0;
  }
  localToWorld(n, sat.normal, poseA.M, sat.localNormal);
  return true;
}

/**
 * The separation of the boxes along the mixed candidate (maskA, maskB): returns false when the
 * candidate is degenerate (its cross product is shorter than the tolerance read from
 * result[SCALAR_AXIS_TOLERANCE]), else writes the separation into result[0] and the unit axis
 * (A's frame, unoriented) into L and returns true. Uses result[1]. Unchecked; allocates nothing.
 */
export function mixedAxisSeparation(
  n: number,
  maskA: number,
  maskB: number,
  ha: ArrayLike<number>,
  hb: ArrayLike<number>,
  C: Float64Array,
  t: Float64Array,
  rows: Float64Array,
  cols: Int32Array,
  L: Float64Array,
  result: Float64Array,
): boolean {
  const tolerance = result[SCALAR_AXIS_TOLERANCE];
  let m = 0;
  for (let i = 0; i < n; i += 1) {
    if (maskA & (1 << i)) L[i] = 0;
    else cols[m++] = i;
  }
  // rows g_r = B's axis j restricted to the complement coordinates (q = m − 1 of them)
  let q = 0;
  for (let j = 0; j < n; j += 1) {
    if (!(maskB & (1 << j))) continue;
    for (let k = 0; k < m; k += 1) rows[q * m + k] = C[cols[k] * n + j];
    q += 1;
  }
  // the generalised cross product of the rows (closed forms up to m = 4), or its direction
  let len: number;
  if (m === 2) {
    L[cols[0]] = -rows[1];
    L[cols[1]] = rows[0];
    len = Math.sqrt(rows[0] * rows[0] + rows[1] * rows[1]);
  } else if (m === 3) {
    const a0 = rows[0],
      a1 = rows[1],
      a2 = rows[2];
    const b0 = rows[3],
      b1 = rows[4],
      b2 = rows[5];
    const x = a1 * b2 - a2 * b1;
    const y = a2 * b0 - a0 * b2;
    const z = a0 * b1 - a1 * b0;
    L[cols[0]] = x;
    L[cols[1]] = y;
    L[cols[2]] = z;
    len = Math.sqrt(x * x + y * y + z * z);
  } else if (m === 4) {
    // cofactors of the 3×4 matrix of rows a, b, c, from its 2×2 minors of b and c
    const a0 = rows[0],
      a1 = rows[1],
      a2 = rows[2],
      a3 = rows[3];
    const b0 = rows[4],
      b1 = rows[5],
      b2 = rows[6],
      b3 = rows[7];
    const c0 = rows[8],
      c1 = rows[9],
      c2 = rows[10],
      c3 = rows[11];
    const m01 = b0 * c1 - b1 * c0;
    const m02 = b0 * c2 - b2 * c0;
    const m03 = b0 * c3 - b3 * c0;
    const m12 = b1 * c2 - b2 * c1;
    const m13 = b1 * c3 - b3 * c1;
    const m23 = b2 * c3 - b3 * c2;
    const x0 = a1 * m23 - a2 * m13 + a3 * m12;
    const x1 = -(a0 * m23 - a2 * m03 + a3 * m02);
    const x2 = a0 * m13 - a1 * m03 + a3 * m01;
    const x3 = -(a0 * m12 - a1 * m02 + a2 * m01);
    L[cols[0]] = x0;
    L[cols[1]] = x1;
    L[cols[2]] = x2;
    L[cols[3]] = x3;
    len = Math.sqrt(x0 * x0 + x1 * x1 + x2 * x2 + x3 * x3);
  } else {
    nullDirection(m, q, rows, cols, L, result);
    len = result[1];
  }
  if (!(len >= tolerance)) return false;
  const inv = 1 / len;
  let d = 0;
  let ra = 0;
  for (let k = 0; k < m; k += 1) {
    const c = cols[k];
    const v = L[c] * inv;
    L[c] = v;
    d += t[c] * v;
    ra += ha[c] * Math.abs(v);
  }
  let rb = 0;
  for (let j = 0; j < n; j += 1) {
    if (maskB & (1 << j)) continue; // orthogonal to L by construction
    let s = 0;
    for (let k = 0; k < m; k += 1) s += C[cols[k] * n + j] * L[cols[k]];
    rb += hb[j] * Math.abs(s);
  }
  result[0] = Math.abs(d) - ra - rb;
  return true;
}

/**
 * For m >= 5: writes into L (at the coordinates `cols`) a vector orthogonal to the q = m − 1
 * rows and into result[1] the length of their generalised cross product (the product of the residual
 * lengths of modified Gram–Schmidt; the rows are overwritten). The direction is the unit vector
 * e_k least covered by the rows minus its projections, orthogonalised twice, scaled to that
 * length; 0 when the rows are dependent.
 */
function nullDirection(m: number, q: number, rows: Float64Array, cols: Int32Array, L: Float64Array, result: Float64Array): void {
  result[1] = 0;
  let volume = 1;
  for (let r = 0; r < q; r += 1) {
    const o = r * m;
    for (let p = 0; p < r; p += 1) {
      let dot = 0;
      for (let k = 0; k < m; k += 1) dot += rows[p * m + k] * rows[o + k];
      for (let k = 0; k < m; k += 1) rows[o + k] -= dot * rows[p * m + k];
    }
    let len2 = 0;
    for (let k = 0; k < m; k += 1) len2 += rows[o + k] * rows[o + k];
    const len = Math.sqrt(len2);
    volume *= len;
    if (len === 0) return;
    for (let k = 0; k < m; k += 1) rows[o + k] /= len;
  }
  let kBest = 0;
  let bestResidual = -1;
  for (let k = 0; k < m; k += 1) {
    let s = 1;
    for (let r = 0; r < q; r += 1) s -= rows[r * m + k] * rows[r * m + k];
    if (s > bestResidual) {
      bestResidual = s;
      kBest = k;
    }
  }
  L[cols[kBest]] = 1;
  for (let pass = 0; pass < 2; pass += 1) {
    for (let r = 0; r < q; r += 1) {
      let dot = 0;
      for (let k = 0; k < m; k += 1) dot += rows[r * m + k] * L[cols[k]];
      for (let k = 0; k < m; k += 1) L[cols[k]] -= dot * rows[r * m + k];
    }
  }
  let len2 = 0;
  for (let k = 0; k < m; k += 1) len2 += L[cols[k]] * L[cols[k]];
  const scale = volume / Math.sqrt(len2);
  for (let k = 0; k < m; k += 1) L[cols[k]] *= scale;
  result[1] = volume;
}

/** out = M·v (local direction to world). */
export function localToWorld(n: number, out: Float64Array, M: Float64Array, v: ArrayLike<number>): void {
  for (let i = 0; i < n; i += 1) {
    let s = 0;
    for (let c = 0; c < n; c += 1) s += M[i * n + c] * v[c];
    out[i] = s;
  }
}

/** Records a separating axis and returns false. */
export function separated(sat: SatResult, separation: number): false {
  sat.kind = SAT_SEPARATED;
  sat.separation = separation;
  return false;
}
