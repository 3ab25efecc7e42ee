/**
 * `JointSpaceTree`'s factorisation and solve written out for point joints in 3D (3 rows a joint, 6
 * velocities a body: the 20 × 20 grid's spanning tree), the same products in the same order as the
 * general path, so the same bits (docs/joints.md, "Trees in joint space"). PointJoint's module
 * installs it (`setPoint3Path`), so a scene without point joints does not carry it.
 *
 * @module
 */
import { ldlFactor } from './joint-blocks.js';
import type { JointSolver } from './joint-solver.js';
import { setPoint3Path, type JointSpaceTree } from './joint-space.js';

/** `sideBlock` written out for `factor3`'s joints (the same products in the same order). */
function side3(t: JointSpaceTree, js: JointSolver, j: number, side: number, node: number, g0: number, d0: number): void {
  const { G, U, Dm, bodyInv: bi } = t;
  const rows = js.rows;
  const RS = js.RS;
  const sg = side === 1 ? 1 : -1;
  const oj = side === 1 ? js.OFF_JB : js.OFF_JA;
  const b0 = 10 * node;
  const im = bi[b0];
  const si = t.bodyIso[node];
  for (let r = 0, base = js.jFirst[j] * RS, gr = g0; r < 3; r += 1, base += RS, gr += 6) {
    for (let d = 0; d < 3; d += 1) {
      const x = sg * rows[base + d];
      G[gr + d] = x;
      U[g0 + d * 3 + r] = x * im;
    }
    const w0 = (G[gr + 3] = sg * rows[base + oj]);
    const w1 = (G[gr + 4] = sg * rows[base + oj + 1]);
    const w2 = (G[gr + 5] = sg * rows[base + oj + 2]);
    const u = g0 + 9 + r;
    if (si >= 0) {
      U[u] = si * w0;
      U[u + 3] = si * w1;
      U[u + 6] = si * w2;
    } else {
      U[u] = 0 + bi[b0 + 1] * w0 + bi[b0 + 2] * w1 + bi[b0 + 3] * w2;
      U[u + 3] = 0 + bi[b0 + 4] * w0 + bi[b0 + 5] * w1 + bi[b0 + 6] * w2;
      U[u + 6] = 0 + bi[b0 + 7] * w0 + bi[b0 + 8] * w1 + bi[b0 + 9] * w2;
    }
  }
  // A_pp += G U, its upper triangle.
  for (let r = 0, gr = g0; r < 3; r += 1, gr += 6) {
    const e0 = G[gr];
    const e1 = G[gr + 1];
    const e2 = G[gr + 2];
    const e3 = G[gr + 3];
    const e4 = G[gr + 4];
    const e5 = G[gr + 5];
    for (let c = r; c < 3; c += 1) {
      const u = g0 + c;
      Dm[d0 + 3 * r + c] += 0 + e0 * U[u] + e1 * U[u + 3] + e2 * U[u + 6] + e3 * U[u + 9] + e4 * U[u + 12] + e5 * U[u + 15];
    }
  }
}

/**
 * `factor`'s couplings and elimination written out for 3-row joints on 6-velocity bodies (the
 * grid's point joints in 3D): the same products in the same order, so the same bits.
 */
function factor3(t: JointSpaceTree): number {
  const P = t.count;
  const { G, U, S, L, Dm, cut, rd, bStart, bj, bjSide, size } = t;
  for (let p = 0; p < P; p += 1) {
    const b = t.pUp[p];
    const e0 = bStart[b] + t.pIdx[p];
    const up = (6 * p + bjSide[e0] * 3) * 6;
    let o = t.lOff[p];
    for (let e = e0 + 1; e < bStart[b + 1]; e += 1) {
      let g = (6 * bj[e] + bjSide[e] * 3) * 6;
      for (let r = 0; r < 3; r += 1, g += 6, o += 3) {
        const g0 = G[g];
        const g1 = G[g + 1];
        const g2 = G[g + 2];
        const g3 = G[g + 3];
        const g4 = G[g + 4];
        const g5 = G[g + 5];
        for (let c = 0; c < 3; c += 1) {
          const u = up + c;
          S[o + c] = 0 + g0 * U[u] + g1 * U[u + 3] + g2 * U[u + 6] + g3 * U[u + 9] + g4 * U[u + 12] + g5 * U[u + 15];
        }
      }
    }
  }
  for (let p = 0; p < P; p += 1) {
    const v0 = 3 * p;
    const d0 = 9 * p;
    for (let r = 0; r < 3; r += 1) size[r] = t.big[p] + cut[v0 + r];
    if (ldlFactor(Dm, d0, 3, rd, v0, size) === 0) return 0;
    const a10 = Dm[d0 + 3];
    const a20 = Dm[d0 + 6];
    const a21 = Dm[d0 + 7];
    const r0 = rd[v0];
    const r1 = rd[v0 + 1];
    const r2 = rd[v0 + 2];
    const b = t.pUp[p];
    const e0 = bStart[b] + t.pIdx[p] + 1;
    const e1 = bStart[b + 1];
    const oEnd = t.lOff[p] + 9 * (e1 - e0);
    // L_qp = S_qp D_p⁺, row by row (ldlSolve written out).
    for (let o = t.lOff[p]; o < oEnd; o += 3) {
      const x0 = S[o];
      const y1 = S[o + 1] - a10 * x0;
      const y2 = S[o + 2] - a20 * x0 - a21 * y1;
      const z2 = y2 * r2;
      const z1 = y1 * r1 - a21 * z2;
      L[o] = x0 * r0 - a10 * z1 - a20 * z2;
      L[o + 1] = z1;
      L[o + 2] = z2;
    }
    let oq = t.lOff[p];
    for (let e = e0; e < e1; e += 1, oq += 9) {
      const q = bj[e];
      const vq = 3 * q;
      const dq = 9 * q;
      // D_q -= L_qp S_qpᵀ (upper triangle), and the size of what cancelled.
      for (let r = 0; r < 3; r += 1) {
        const l = oq + 3 * r;
        const l0 = L[l];
        const l1 = L[l + 1];
        const l2 = L[l + 2];
        cut[vq + r] += Math.abs(l0 * S[l]) + Math.abs(l1 * S[l + 1]) + Math.abs(l2 * S[l + 2]);
        for (let c = r; c < 3; c += 1) {
          const s = oq + 3 * c;
          Dm[dq + 3 * r + c] -= 0 + l0 * S[s] + l1 * S[s + 1] + l2 * S[s + 2];
        }
      }
      // S_rq -= L_rp S_qpᵀ for the joints r after q at b.
      let sq = t.lOff[q];
      for (let or = oq + 9; or < oEnd; or += 3) {
        const l0 = L[or];
        const l1 = L[or + 1];
        const l2 = L[or + 2];
        for (let c = 0; c < 3; c += 1, sq += 1) {
          const s = oq + 3 * c;
          S[sq] -= 0 + l0 * S[s] + l1 * S[s + 1] + l2 * S[s + 2];
        }
      }
    }
  }
  return 1;
}

/** `solve` written out for the path of `factor3` (the same order of operations). */
function solve3(t: JointSpaceTree, bodyNodes: number): void {
  const P = t.count;
  const x = t.vec;
  const { L, Dm, rd, bStart, bj } = t;
  // L z = c.
  for (let p = 0; p < P; p += 1) {
    const v = 3 * p;
    const x0 = x[v];
    const x1 = x[v + 1];
    const x2 = x[v + 2];
    const b = t.pUp[p];
    let o = t.lOff[p];
    for (let e = bStart[b] + t.pIdx[p] + 1; e < bStart[b + 1]; e += 1, o += 9) {
      const vq = 3 * bj[e];
      x[vq] -= 0 + L[o] * x0 + L[o + 1] * x1 + L[o + 2] * x2;
      x[vq + 1] -= 0 + L[o + 3] * x0 + L[o + 4] * x1 + L[o + 5] * x2;
      x[vq + 2] -= 0 + L[o + 6] * x0 + L[o + 7] * x1 + L[o + 8] * x2;
    }
  }
  // w = D⁺ z (ldlSolve written out).
  for (let p = 0; p < P; p += 1) {
    const v = 3 * p;
    const d0 = 9 * p;
    const a10 = Dm[d0 + 3];
    const a20 = Dm[d0 + 6];
    const a21 = Dm[d0 + 7];
    const x0 = x[v];
    const y1 = x[v + 1] - a10 * x0;
    const y2 = x[v + 2] - a20 * x0 - a21 * y1;
    const z2 = y2 * rd[v + 2];
    const z1 = y1 * rd[v + 1] - a21 * z2;
    x[v] = x0 * rd[v] - a10 * z1 - a20 * z2;
    x[v + 1] = z1;
    x[v + 2] = z2;
  }
  // Lᵀ x = w.
  for (let p = P - 1; p >= 0; p -= 1) {
    const v = 3 * p;
    const b = t.pUp[p];
    let o = t.lOff[p];
    for (let e = bStart[b] + t.pIdx[p] + 1; e < bStart[b + 1]; e += 1, o += 9) {
      const vq = 3 * bj[e];
      const q0 = x[vq];
      const q1 = x[vq + 1];
      const q2 = x[vq + 2];
      x[v] -= 0 + L[o] * q0 + L[o + 3] * q1 + L[o + 6] * q2;
      x[v + 1] -= 0 + L[o + 1] * q0 + L[o + 4] * q1 + L[o + 7] * q2;
      x[v + 2] -= 0 + L[o + 2] * q0 + L[o + 5] * q1 + L[o + 8] * q2;
    }
  }
  // Δv = M̃⁻¹ Jᵀ Δλ per body (bodyChanges written out).
  const { acc, U, sNode } = t;
  for (let q = 0; q < 6 * bodyNodes; q += 1) acc[q] = 0;
  for (let p = 0; p < P; p += 1) {
    const v = 3 * p;
    const x0 = x[v];
    const x1 = x[v + 1];
    const x2 = x[v + 2];
    for (let side = 0; side < 2; side += 1) {
      const node = sNode[2 * p + side];
      if (node < 0) continue;
      const u0 = (2 * v + side * 3) * 6;
      const a0 = 6 * node;
      for (let e = 0, u = u0; e < 6; e += 1, u += 3) acc[a0 + e] += 0 + U[u] * x0 + U[u + 1] * x1 + U[u + 2] * x2;
    }
  }
}

/**
 * Installs the written-out path in `JointSpaceTree` (idempotent).
 * @internal
 */
export function usePoint3Path(): void {
  setPoint3Path({ side: side3, factor: factor3, solve: solve3 });
}
