/**
 * The dense pieces both joint-space solvers build their blocks from (`JointChain`'s general path
 * for paths, `JointSpaceTree` for branching forests): each body's M̃⁻¹, a joint side's signed
 * Jacobian G and U = M̃⁻¹ Gᵀ, the diagonal block G U, and the LDLᵀ of a block that drops a
 * redundant row's pivot (see docs/joints.md, "Redundant rows").
 *
 * Every argument is a typed array or an integer: a double passed to a call V8 does not inline is
 * boxed, an allocation per call.
 *
 * @module
 */
import type { SolverBodies } from '../solver/solver-bodies.js';
import type { JointSolver } from './joint-solver.js';

/**
 * A pivot within this fraction of its size (the block's largest diagonal entry plus what
 * cancelled in it: the tree's LDL_TOLERANCE) is a redundant row's, and dropped; below minus it the
 * block is not semi-definite and the factorisation fails. A redundant row's pivot is rounding
 * (about 1e-14 of its size), a genuine row's as small as the inverse of a mass ratio (2.6e-10 in
 * a chain whose every other link is 10⁸ times heavier, which fell freely at 1e-8).
 * @internal
 */
export const BLOCK_TOLERANCE = 1e-11;

/** The sum `geometricLoad` returns (0 + x is x, bit for bit). */
const LOAD = new Float64Array(1);

/**
 * |λ| · |J_angular| of joint j's equality rows on the body in `slot` (N·s·m): the size of the
 * torque the joint's last impulse exerts per radian the body turns (times h). λ is the impulse
 * the joint kept from its last solve (`Joint.lambda`).
 * @internal
 */
export function geometricLoad(js: JointSolver, j: number, slot: number): number {
  LOAD[0] = 0;
  addGeometricLoad(js, j, slot, LOAD, 0);
  return LOAD[0];
}

/**
 * out[at] += `geometricLoad`(js, j, slot), the sum made here: the factorisations that call this
 * are too large for V8 to inline `geometricLoad` into them, and the double it returned would be
 * boxed, an allocation per call (this returns nothing).
 * @internal
 */
export function addGeometricLoad(js: JointSolver, j: number, slot: number, out: Float64Array, at: number): void {
  const first = js.jFirst[j];
  const m = js.jBlock[j];
  const off = js.jB[j] === slot ? js.OFF_JB : js.OFF_JA;
  const lam = js.joints[j].lambda;
  const rows = js.rows;
  const k = js.k;
  let l2 = 0;
  let a2 = 0;
  for (let r = 0; r < m; r += 1) {
    const q = first + r;
    const l = lam[js.rowKey[q]];
    l2 += l * l;
    const base = q * js.RS + off;
    for (let p = 0; p < k; p += 1) a2 += rows[base + p] * rows[base + p];
  }
  out[at] += Math.sqrt(l2 * a2);
}

/**
 * Each body node's Σ|λ||J_angular| over the `count` joints pJoint[0..count) into g (zeroed over
 * `bodyNodes` first; left 0 when `on` is 0: no geometric stiffness asked). sNode holds each
 * joint's two body nodes (−1: none).
 * @internal
 */
export function gatherLoads(
  js: JointSolver,
  count: number,
  pJoint: Int32Array,
  sNode: Int32Array,
  g: Float64Array,
  bodyNodes: number,
  on: number,
): void {
  for (let i = 0; i < bodyNodes; i += 1) g[i] = 0;
  if (on === 0) return;
  for (let p = 0; p < count; p += 1) {
    const j = pJoint[p];
    const nA = sNode[2 * p];
    const nB = sNode[2 * p + 1];
    if (nA >= 0) addGeometricLoad(js, j, js.jA[j], g, nA);
    if (nB >= 0) addGeometricLoad(js, j, js.jB[j], g, nB);
  }
}

/**
 * Per body node i (of `bodyNodes`, solver slot nRef[i]): 1/m into bi[(1 + k²) i] and the angular
 * M̃⁻¹ (k × k) after it, with g[i] (the geometric stiffness, already scaled) on the diagonal of
 * I_world; iso[i] the scalar of that inverse when the inertia is the same in every plane (balls,
 * cubes: k products a row instead of k², and no k × k inverse), else −1. `kblk` is k × k scratch.
 * @internal
 */
export function bodyInverses(
  sb: SolverBodies,
  nRef: Int32Array,
  bodyNodes: number,
  k: number,
  g: Float64Array,
  bi: Float64Array,
  iso: Float64Array,
  kblk: Float64Array,
): void {
  const kk1 = 1 + k * k;
  for (let i = 0; i < bodyNodes; i += 1) {
    const slot = nRef[i];
    const o = kk1 * i;
    bi[o] = sb.invMass[slot];
    const gi = g[i];
    const s = sb.isoInvInertia[slot];
    iso[i] = s > 0 ? (gi > 0 ? 1 / (sb.inertia[slot * k * k] + gi) : s) : -1;
    if (s > 0) continue;
    if (gi > 0) {
      // (I_world + g·1)⁻¹ (symmetric positive definite).
      for (let q = 0, at = slot * k * k; q < k * k; q += 1) kblk[q] = sb.inertia[at + q];
      for (let a = 0; a < k; a += 1) kblk[a * k + a] += gi;
      invertSpd(kblk, k, bi, o + 1);
    } else {
      const II = sb.invInertia;
      for (let q = 0, at = slot * k * k; q < k * k; q += 1) bi[o + 1 + q] = II[at + q];
    }
  }
}

/**
 * One side of joint j (`side` 0: body a, −G; 1: body b, +G) on body node `node`: its m rows'
 * signed Jacobians into G (row r at g0 + r (n + k)) and U = M̃⁻¹ Gᵀ into U[u0] ((n + k) × m,
 * row-major), with the inverses `bodyInverses` left in bi and iso; then G U's upper triangle
 * added to the m × m block at Dm[d0].
 * @internal
 */
export function sideBlock(
  js: JointSolver,
  j: number,
  side: number,
  node: number,
  k: number,
  bi: Float64Array,
  iso: Float64Array,
  G: Float64Array,
  g0: number,
  U: Float64Array,
  u0: number,
  Dm: Float64Array,
  d0: number,
): void {
  const n = js.D.n;
  const bs = n + k;
  const rows = js.rows;
  const RS = js.RS;
  const first = js.jFirst[j];
  const m = js.jBlock[j];
  const sg = side === 1 ? 1 : -1;
  const oj = side === 1 ? js.OFF_JB : js.OFF_JA;
  const b0 = (1 + k * k) * node;
  const im = bi[b0];
  const si = iso[node];
  for (let r = 0; r < m; r += 1) {
    const base = (first + r) * RS;
    const gr = g0 + r * bs;
    for (let d = 0; d < n; d += 1) {
      const x = sg * rows[base + d];
      G[gr + d] = x;
      U[u0 + d * m + r] = x * im;
    }
    for (let a = 0; a < k; a += 1) G[gr + n + a] = sg * rows[base + oj + a];
    if (si >= 0) {
      for (let a = 0; a < k; a += 1) U[u0 + (n + a) * m + r] = si * G[gr + n + a];
      continue;
    }
    for (let a = 0; a < k; a += 1) {
      let sum = 0;
      for (let b = 0; b < k; b += 1) sum += bi[b0 + 1 + a * k + b] * G[gr + n + b];
      U[u0 + (n + a) * m + r] = sum;
    }
  }
  // A_pp += G U, its upper triangle (all the LDLᵀ reads).
  for (let r = 0; r < m; r += 1) {
    const gr = g0 + r * bs;
    for (let c = r; c < m; c += 1) {
      let sum = 0;
      for (let e = 0; e < bs; e += 1) sum += G[gr + e] * U[u0 + e * m + c];
      Dm[d0 + r * m + c] += sum;
    }
  }
}

/**
 * Each body node's M̃⁻¹ Jᵀ Δλ into acc (n + k per body node, zeroed over `bodyNodes` first): joint p's
 * Δλ at x[vOff[p]], its sides' U (`sideBlock`) at U[(2 vOff[p] + side · m_p)(n + k)], its body
 * nodes in sNode[2p], sNode[2p + 1] (−1: none).
 * @internal
 */
export function bodyChanges(
  acc: Float64Array,
  bodyNodes: number,
  bs: number,
  P: number,
  vOff: Int32Array,
  sNode: Int32Array,
  U: Float64Array,
  x: Float64Array,
): void {
  for (let q = 0; q < bs * bodyNodes; q += 1) acc[q] = 0;
  for (let p = 0; p < P; p += 1) {
    const v = vOff[p];
    const m = vOff[p + 1] - v;
    for (let side = 0; side < 2; side += 1) {
      const node = sNode[2 * p + side];
      if (node < 0) continue;
      const u0 = (2 * v + side * m) * bs;
      const a0 = bs * node;
      for (let e = 0; e < bs; e += 1) {
        let sum = 0;
        for (let r = 0; r < m; r += 1) sum += U[u0 + e * m + r] * x[v + r];
        acc[a0 + e] += sum;
      }
    }
  }
}

/**
 * The LDLᵀ of the symmetric m × m block at A[d0] (its upper triangle is read): L_rj into the
 * lower triangle, 1 / d_j into rd[r0 + j], 0 for a dropped pivot (within ±BLOCK_TOLERANCE of
 * size[j] plus the terms that cancelled in it; its column of L zero). Returns 0 when a pivot is
 * below minus that (or NaN): the block is not semi-definite.
 * @internal
 */
export function ldlFactor(A: Float64Array, d0: number, m: number, rd: Float64Array, r0: number, size: Float64Array): number {
  for (let j = 0; j < m; j += 1) {
    let d = A[d0 + j * m + j];
    let s = size[j];
    for (let q = 0; q < j; q += 1) {
      const l = A[d0 + j * m + q];
      const t = l * l * rd[r0 + q];
      d -= t;
      s += t;
    }
    const tol = s * BLOCK_TOLERANCE;
    if (!(d > tol)) {
      // Not clearly positive: below −tol (or NaN) the block is not semi-definite; within ±tol a
      // redundant row, dropped (1 / d := 0, its column of L zero).
      if (!(d >= -tol)) return 0;
      rd[r0 + j] = 0;
      for (let r = j + 1; r < m; r += 1) A[d0 + r * m + j] = 0;
      continue;
    }
    rd[r0 + j] = d;
    for (let r = j + 1; r < m; r += 1) {
      let sum = A[d0 + j * m + r];
      for (let q = 0; q < j; q += 1) sum -= A[d0 + r * m + q] * A[d0 + j * m + q] * rd[r0 + q];
      A[d0 + r * m + j] = sum / d;
    }
  }
  for (let j = 0; j < m; j += 1) if (rd[r0 + j] !== 0) rd[r0 + j] = 1 / rd[r0 + j];
  return 1;
}

/**
 * x ← D⁺ x (a dropped pivot's 1 / d_j is 0) for the LDLᵀ `ldlFactor` left at A[d0] (m × m, 1 / d_j
 * at rd[r0]), x the m entries at X[x0].
 * @internal
 */
export function ldlSolve(
  A: Float64Array,
  d0: number,
  m: number,
  rd: Float64Array,
  r0: number,
  X: Float64Array,
  x0: number,
): void {
  for (let r = 1; r < m; r += 1) {
    let sum = X[x0 + r];
    for (let q = 0; q < r; q += 1) sum -= A[d0 + r * m + q] * X[x0 + q];
    X[x0 + r] = sum;
  }
  for (let r = m - 1; r >= 0; r -= 1) {
    let sum = X[x0 + r] * rd[r0 + r];
    for (let q = r + 1; q < m; q += 1) sum -= A[d0 + q * m + r] * X[x0 + q];
    X[x0 + r] = sum;
  }
}

/**
 * The inverse of the symmetric positive definite k × k in K (destroyed) into out[o..o + k²], by
 * its Cholesky factor, column by column.
 * @internal
 */
export function invertSpd(K: Float64Array, k: number, out: Float64Array, o: number): void {
  for (let j = 0; j < k; j += 1) {
    let d = K[j * k + j];
    for (let q = 0; q < j; q += 1) d -= K[j * k + q] * K[j * k + q];
    const c = Math.sqrt(d);
    K[j * k + j] = c;
    for (let r = j + 1; r < k; r += 1) {
      let sum = K[r * k + j];
      for (let q = 0; q < j; q += 1) sum -= K[r * k + q] * K[j * k + q];
      K[r * k + j] = sum / c;
    }
  }
  for (let col = 0; col < k; col += 1) {
    for (let r = 0; r < k; r += 1) {
      let sum = r === col ? 1 : 0;
      for (let q = 0; q < r; q += 1) sum -= K[r * k + q] * out[o + q * k + col];
      out[o + r * k + col] = sum / K[r * k + r];
    }
    for (let r = k - 1; r >= 0; r -= 1) {
      let sum = out[o + r * k + col];
      for (let q = r + 1; q < k; q += 1) sum -= K[q * k + r] * out[o + q * k + col];
      out[o + r * k + col] = sum / K[r * k + r];
    }
  }
}
