/**
 * The joint-space solve of rigid joint forests with branching bodies (see docs/joints.md, "Trees
 * in joint space"): the forests `JointChain` does not take (a body with three or more tree joints).
 * A = J M̃⁻¹ Jᵀ couples joint p to every other joint at either of its bodies (the line graph of the
 * tree). Each component is rooted at a body and its joints eliminated leaves first: a body's folded
 * joints, then the joint to its parent, bodies in reverse breadth-first order. Joint p (child body c
 * → parent body b) is eliminated after every other joint at c, so its remaining neighbours are the
 * later joints at b, which already couple through b: the block LDLᵀ has no fill-in, and costs the
 * sum over bodies of deg² blocks. Per joint: its diagonal block and its blocks to the later joints
 * at its upper body (b; a folded joint's own body). Each D_p by the LDLᵀ of `JointChain`'s general
 * path, with the same rule: a pivot within ±1e-8 of its size is a redundant row's and dropped, one
 * below minus that fails the factorisation and `JointTree` takes the step.
 *
 * Unlike the tree's body+joint node LU, the order is neutral to where the world holds the tree: a
 * leaf body pinned by its folded joint cannot leave a block singular unless the rows are redundant.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { growFloat64, growInt32 } from '../contacts/contact-set.js';
import type { SolverBodies } from '../solver/solver-bodies.js';
import type { ForestLinks } from './joint-chain.js';
import { bodyChanges, bodyInverses, gatherLoads, ldlFactor, ldlSolve, sideBlock } from './joint-blocks.js';
import type { JointSolver } from './joint-solver.js';

/**
 * `JointSpaceTree`'s solve written out for point joints in 3D (joint-space-point.ts): the same
 * products in the same order, so the same bits. PointJoint's module installs it, so a scene
 * without point joints does not carry its code.
 * @internal
 */
export interface Point3Path {
  /** `sideBlock` for a 3-row joint on a 6-velocity body. */
  side(t: JointSpaceTree, js: JointSolver, j: number, side: number, node: number, g0: number, d0: number): void;
  /** `factor`'s couplings and elimination; 1, or 0 when a pivot block fails. */
  factor(t: JointSpaceTree): number;
  /** `solve`. */
  solve(t: JointSpaceTree, bodyNodes: number): void;
}

let point3Path: Point3Path | null = null;

/**
 * Installs the written-out path for point joints in 3D (called once by PointJoint's module; null
 * takes it out, for the tests). Read by the next `build`.
 * @internal
 */
export function setPoint3Path(path: Point3Path | null): void {
  point3Path = path;
}

/**
 * The written-out path installed, or null (for the tests, which wrap it to see it run).
 * @internal
 */
export function installedPoint3Path(): Point3Path | null {
  return point3Path;
}

/**
 * The branching joint forests in joint space, built by `JointTree.build` when the forest is not
 * made of chains, factored and solved in its place.
 * @internal
 */
export class JointSpaceTree {
  /** Joints in elimination order. */
  count = 0;
  /** Per position: the joint (solver index). */
  pJoint = new Int32Array(16);
  /** Per position: its first entry in `vec`; P + 1 entries. */
  vOff = new Int32Array(17);
  /** Per position and side (2p + side): the body node, −1 for none. */
  sNode = new Int32Array(32);
  /** Per position: its upper body node (the parent body; a folded joint's own body). */
  pUp = new Int32Array(16);
  /** Per position: its index in its upper body's list. */
  pIdx = new Int32Array(16);
  /** Per position: the offset of its blocks to the later joints at its upper body in `S` and `L`. */
  lOff = new Int32Array(16);
  /** Per position: the offset of its m_p × m_p block in `Dm`. */
  private dOff = new Int32Array(16);
  /** Per position: the largest diagonal entry of A_pp. */
  big = new Float64Array(16);
  /** Per body node: the start of its joints (positions, increasing) in `bj`; bodies + 1 entries. */
  bStart = new Int32Array(17);
  /** Per entry: a position at the body, and that joint's side (0: A, 1: B) there. */
  bj = new Int32Array(32);
  bjSide = new Int32Array(32);
  /** Scratch of `build`: fill counts per body, BFS queue, parents, visited. */
  private bFill = new Int32Array(16);
  private queue = new Int32Array(16);
  private parentJ = new Int32Array(16);
  private visited = new Int32Array(16);
  /** M̃⁻¹ Gᵀ and G per position and side (bs × m_p and m_p × bs, row-major). */
  U = new Float64Array(64);
  G = new Float64Array(64);
  /** The coupling blocks S_qp (m_q × m_p), updated, and L_qp = S_qp D_p⁺. */
  S = new Float64Array(64);
  L = new Float64Array(64);
  /** The diagonal blocks, factored in place (L in the lower triangle). */
  Dm = new Float64Array(64);
  /** Per entry of `vec`: 1 / d_j (0 dropped), and what cancelled in its row's pivot. */
  rd = new Float64Array(48);
  cut = new Float64Array(48);
  /** The sizes of the pivots of the block `ldlFactor` factors. */
  size = new Float64Array(6);
  /** Per body node: 1/m then the angular M̃⁻¹ (k × k); its scalar when isotropic, else −1. */
  bodyInv = new Float64Array(16 * 10);
  bodyIso = new Float64Array(16);
  /** Per body node: Σ|λ||J_angular| over its joints. */
  private bodyG = new Float64Array(16);
  /** A body's M̃ angular block being inverted. */
  private kblk = new Float64Array(9);
  /** Per body node: the Δv and Δω of a solve (bs each). */
  acc = new Float64Array(16 * 6);
  /** The right-hand side, then Δλ. */
  vec = new Float64Array(48);
  /** The scale of the geometric stiffness for the next `factor`. */
  stiffness = 0;
  /** Every joint 3 rows and every body 6 velocities (point joints in 3D), and the path installed. */
  private point3 = false;
  /** Angular components of a body (k = n(n − 1)/2). */
  private readonly k: number;
  /** n + k: the velocity size of a body (the stride of `acc`). */
  readonly bs: number;

  constructor(D: Dims) {
    this.k = D.k;
    this.bs = D.n + D.k;
  }

  /**
   * Orders the forest's joints leaves first, component by component. Returns 1 (0 when the joints
   * do not form a forest on the body nodes).
   */
  build(js: JointSolver, role: Int32Array, bodyNodes: number, forest: ForestLinks): number {
    this.count = 0;
    const { slotNode, nRef, adjHead, adjNext, adjJoint, fold, foldNext } = forest;
    const count = js.count;
    let tree = 0;
    let mMax = 0;
    let mMin = 1 << 30;
    for (let j = 0; j < count; j += 1) {
      if (role[j] === 0) continue;
      if (js.jBlock[j] > mMax) mMax = js.jBlock[j];
      if (js.jBlock[j] < mMin) mMin = js.jBlock[j];
      tree += 1;
    }
    this.point3 = point3Path !== null && this.bs === 6 && mMin === 3 && mMax === 3;
    const B = bodyNodes;
    this.pJoint = growInt32(this.pJoint, tree, 0);
    this.vOff = growInt32(this.vOff, tree + 1, 0);
    this.sNode = growInt32(this.sNode, 2 * tree, 0);
    this.pUp = growInt32(this.pUp, tree, 0);
    this.pIdx = growInt32(this.pIdx, tree, 0);
    this.lOff = growInt32(this.lOff, tree, 0);
    this.dOff = growInt32(this.dOff, tree, 0);
    this.big = growFloat64(this.big, tree, 0);
    this.bStart = growInt32(this.bStart, B + 1, 0);
    this.bj = growInt32(this.bj, 2 * tree, 0);
    this.bjSide = growInt32(this.bjSide, 2 * tree, 0);
    this.bFill = growInt32(this.bFill, B, 0);
    this.queue = growInt32(this.queue, B, 0);
    this.parentJ = growInt32(this.parentJ, B, 0);
    this.visited = growInt32(this.visited, B, 0);
    const queue = this.queue;
    const parentJ = this.parentJ;
    const visited = this.visited;
    for (let i = 0; i < B; i += 1) visited[i] = 0;
    let P = 0;
    for (let r = 0; r < B; r += 1) {
      if (visited[r] !== 0) continue;
      // Breadth first from r, then its bodies in reverse: each body's folded joints, then its parent joint.
      let head = 0;
      let tail = 0;
      queue[tail++] = r;
      visited[r] = 1;
      parentJ[r] = -1;
      while (head < tail) {
        const c = queue[head++];
        for (let ed = adjHead[c]; ed >= 0; ed = adjNext[ed]) {
          const j = nRef[adjJoint[ed]];
          if (j === parentJ[c]) continue;
          const a = slotNode[js.jA[j]];
          const o = a === c ? slotNode[js.jB[j]] : a;
          if (visited[o] !== 0) return 0;
          visited[o] = 1;
          parentJ[o] = j;
          queue[tail++] = o;
        }
      }
      for (let q = tail - 1; q >= 0; q -= 1) {
        const c = queue[q];
        for (let j = fold[c]; j >= 0; j = foldNext[j]) {
          this.place(js, P, j, slotNode);
          this.pUp[P] = c;
          P += 1;
        }
        const j = parentJ[c];
        if (j >= 0) {
          this.place(js, P, j, slotNode);
          const a = slotNode[js.jA[j]];
          this.pUp[P] = a === c ? slotNode[js.jB[j]] : a;
          P += 1;
        }
      }
    }
    if (P !== tree) return 0;
    // Each body's joints in position order.
    const bStart = this.bStart;
    const fill = this.bFill;
    for (let i = 0; i <= B; i += 1) bStart[i] = 0;
    for (let p = 0; p < P; p += 1) {
      if (this.sNode[2 * p] >= 0) bStart[this.sNode[2 * p] + 1] += 1;
      if (this.sNode[2 * p + 1] >= 0) bStart[this.sNode[2 * p + 1] + 1] += 1;
    }
    for (let i = 0; i < B; i += 1) {
      bStart[i + 1] += bStart[i];
      fill[i] = bStart[i];
    }
    for (let p = 0; p < P; p += 1) {
      for (let side = 0; side < 2; side += 1) {
        const b = this.sNode[2 * p + side];
        if (b < 0) continue;
        if (b === this.pUp[p]) this.pIdx[p] = fill[b] - bStart[b];
        this.bj[fill[b]] = p;
        this.bjSide[fill[b]++] = side;
      }
    }
    // Offsets; a node joint must be the last at its lower body (no fill-in).
    let v = 0;
    let l = 0;
    let d = 0;
    for (let p = 0; p < P; p += 1) {
      const m = js.jBlock[this.pJoint[p]];
      for (let side = 0; side < 2; side += 1) {
        const b = this.sNode[2 * p + side];
        if (b >= 0 && b !== this.pUp[p] && this.bj[bStart[b + 1] - 1] !== p) return 0;
      }
      this.vOff[p] = v;
      this.lOff[p] = l;
      this.dOff[p] = d;
      const b = this.pUp[p];
      for (let e = bStart[b] + this.pIdx[p] + 1; e < bStart[b + 1]; e += 1) l += m * js.jBlock[this.pJoint[this.bj[e]]];
      d += m * m;
      v += m;
    }
    this.vOff[P] = v;
    this.count = P;
    const { bs, k } = this;
    this.U = growFloat64(this.U, 2 * v * bs, 0);
    this.G = growFloat64(this.G, 2 * v * bs, 0);
    this.S = growFloat64(this.S, l, 0);
    this.L = growFloat64(this.L, l, 0);
    this.Dm = growFloat64(this.Dm, d, 0);
    this.vec = growFloat64(this.vec, v, 0);
    this.rd = growFloat64(this.rd, v, 0);
    this.cut = growFloat64(this.cut, v, 0);
    this.size = growFloat64(this.size, mMax, 0);
    this.bodyInv = growFloat64(this.bodyInv, (1 + k * k) * B, 0);
    this.bodyIso = growFloat64(this.bodyIso, B, 0);
    this.bodyG = growFloat64(this.bodyG, B, 0);
    this.acc = growFloat64(this.acc, bs * B, 0);
    this.kblk = growFloat64(this.kblk, k * k, 0);
    return 1;
  }

  /** Records joint j at position p and its body nodes per side. */
  private place(js: JointSolver, p: number, j: number, slotNode: Int32Array): void {
    this.pJoint[p] = j;
    const a = js.jA[j];
    const b = js.jB[j];
    this.sNode[2 * p] = a > 0 ? slotNode[a] : -1;
    this.sNode[2 * p + 1] = b > 0 ? slotNode[b] : -1;
  }

  /**
   * Assembles A's blocks (M̃ with the geometric stiffness `stiffness`·Σ|λ||J_angular| on its angular
   * diagonal) and factors them leaves first, redundant rows' pivots dropped. Returns 1, or 0 when a
   * pivot block is not positive semi-definite (the caller falls back to the tree).
   */
  factor(js: JointSolver, sb: SolverBodies, bodyNodes: number, nRef: Int32Array): number {
    const P = this.count;
    const { k, bs } = this;
    const stiffness = this.stiffness;
    const bi = this.bodyInv;
    const g = this.bodyG;
    gatherLoads(js, P, this.pJoint, this.sNode, g, bodyNodes, stiffness > 0 ? 1 : 0);
    // The stiffness scaled in here, not passed: a double argument is boxed (see joint-blocks.ts).
    for (let i = 0; i < bodyNodes; i += 1) g[i] *= stiffness;
    const iso = this.bodyIso;
    bodyInverses(sb, nRef, bodyNodes, k, g, bi, iso, this.kblk);
    const U = this.U;
    const G = this.G;
    const Dm = this.Dm;
    const S = this.S;
    const L = this.L;
    const cut = this.cut;
    // G, U per side, A_pp.
    for (let p = 0; p < P; p += 1) {
      const j = this.pJoint[p];
      const m = js.jBlock[j];
      const v0 = this.vOff[p];
      const d0 = this.dOff[p];
      for (let q = 0; q < m * m; q += 1) Dm[d0 + q] = 0;
      for (let r = 0; r < m; r += 1) cut[v0 + r] = 0;
      for (let side = 0; side < 2; side += 1) {
        const node = this.sNode[2 * p + side];
        if (node < 0) continue;
        if (this.point3) point3Path!.side(this, js, j, side, node, (2 * v0 + side * m) * bs, d0);
        else sideBlock(js, j, side, node, k, bi, iso, G, (2 * v0 + side * m) * bs, U, (2 * v0 + side * m) * bs, Dm, d0);
      }
      let big = 0;
      for (let r = 0; r < m; r += 1) if (Dm[d0 + r * m + r] > big) big = Dm[d0 + r * m + r];
      this.big[p] = big;
    }
    if (this.point3) return point3Path!.factor(this);
    // The couplings S_qp = G_q,b U_p,b to the later joints q at p's upper body b.
    const bStart = this.bStart;
    for (let p = 0; p < P; p += 1) {
      const m = this.vOff[p + 1] - this.vOff[p];
      const b = this.pUp[p];
      const e0 = bStart[b] + this.pIdx[p];
      const up = (2 * this.vOff[p] + this.bjSide[e0] * m) * bs;
      let o = this.lOff[p];
      for (let e = e0 + 1; e < bStart[b + 1]; e += 1) {
        const q = this.bj[e];
        const mq = this.vOff[q + 1] - this.vOff[q];
        const gq = (2 * this.vOff[q] + this.bjSide[e] * mq) * bs;
        for (let r = 0; r < mq; r += 1) {
          for (let c = 0; c < m; c += 1) {
            let sum = 0;
            for (let t = 0; t < bs; t += 1) sum += G[gq + r * bs + t] * U[up + t * m + c];
            S[o + r * m + c] = sum;
          }
        }
        o += mq * m;
      }
    }
    // Leaves first: D_p's LDLᵀ, L_qp = S_qp D_p⁺, and the Schur complement on the later joints at b.
    for (let p = 0; p < P; p += 1) {
      const m = this.vOff[p + 1] - this.vOff[p];
      const v0 = this.vOff[p];
      for (let r = 0; r < m; r += 1) this.size[r] = this.big[p] + cut[v0 + r];
      if (ldlFactor(this.Dm, this.dOff[p], m, this.rd, v0, this.size) === 0) return 0;
      const b = this.pUp[p];
      const e0 = bStart[b] + this.pIdx[p] + 1;
      const e1 = bStart[b + 1];
      let o = this.lOff[p];
      for (let e = e0; e < e1; e += 1) {
        const q = this.bj[e];
        const mq = this.vOff[q + 1] - this.vOff[q];
        for (let r = 0; r < mq; r += 1) {
          for (let c = 0; c < m; c += 1) L[o + r * m + c] = S[o + r * m + c];
          ldlSolve(this.Dm, this.dOff[p], m, this.rd, v0, L, o + r * m);
        }
        o += mq * m;
      }
      let oq = this.lOff[p];
      for (let e = e0; e < e1; e += 1) {
        const q = this.bj[e];
        const vq = this.vOff[q];
        const mq = this.vOff[q + 1] - vq;
        // D_q -= L_qp S_qpᵀ (upper triangle), and the size of what cancelled.
        const dq = this.dOff[q];
        for (let r = 0; r < mq; r += 1) {
          let c0 = 0;
          for (let t = 0; t < m; t += 1) c0 += Math.abs(L[oq + r * m + t] * S[oq + r * m + t]);
          cut[vq + r] += c0;
          for (let c = r; c < mq; c += 1) {
            let sum = 0;
            for (let t = 0; t < m; t += 1) sum += L[oq + r * m + t] * S[oq + c * m + t];
            Dm[dq + r * mq + c] -= sum;
          }
        }
        // S_rq -= L_rp S_qpᵀ for the joints r after q at b (stored in q's blocks: q's upper body is b).
        let or = oq + mq * m;
        let sq = this.lOff[q];
        for (let e2 = e + 1; e2 < e1; e2 += 1) {
          const rr = this.bj[e2];
          const mr = this.vOff[rr + 1] - this.vOff[rr];
          for (let r = 0; r < mr; r += 1) {
            for (let c = 0; c < mq; c += 1) {
              let sum = 0;
              for (let t = 0; t < m; t += 1) sum += L[or + r * m + t] * S[oq + c * m + t];
              S[sq + r * mq + c] -= sum;
            }
          }
          or += mr * m;
          sq += mr * mq;
        }
        oq += mq * m;
      }
    }
    return 1;
  }

  /**
   * Solves A Δλ = c with c in `vec`, leaving Δλ there, and sums each body node's M̃⁻¹ Jᵀ Δλ into
   * `acc` (bs per body node).
   */
  solve(bodyNodes: number): void {
    if (this.point3) {
      point3Path!.solve(this, bodyNodes);
      return;
    }
    const P = this.count;
    const bs = this.bs;
    const x = this.vec;
    const L = this.L;
    const vOff = this.vOff;
    const bStart = this.bStart;
    // L z = c.
    for (let p = 0; p < P; p += 1) {
      const v = vOff[p];
      const m = vOff[p + 1] - v;
      const b = this.pUp[p];
      let o = this.lOff[p];
      for (let e = bStart[b] + this.pIdx[p] + 1; e < bStart[b + 1]; e += 1) {
        const q = this.bj[e];
        const vq = vOff[q];
        const mq = vOff[q + 1] - vq;
        for (let r = 0; r < mq; r += 1) {
          let sum = 0;
          for (let t = 0; t < m; t += 1) sum += L[o + r * m + t] * x[v + t];
          x[vq + r] -= sum;
        }
        o += mq * m;
      }
    }
    // w = D⁺ z.
    for (let p = 0; p < P; p += 1) ldlSolve(this.Dm, this.dOff[p], vOff[p + 1] - vOff[p], this.rd, vOff[p], x, vOff[p]);
    // Lᵀ x = w.
    for (let p = P - 1; p >= 0; p -= 1) {
      const v = vOff[p];
      const m = vOff[p + 1] - v;
      const b = this.pUp[p];
      let o = this.lOff[p];
      for (let e = bStart[b] + this.pIdx[p] + 1; e < bStart[b + 1]; e += 1) {
        const q = this.bj[e];
        const vq = vOff[q];
        const mq = vOff[q + 1] - vq;
        for (let t = 0; t < m; t += 1) {
          let sum = 0;
          for (let r = 0; r < mq; r += 1) sum += L[o + r * m + t] * x[vq + r];
          x[v + t] -= sum;
        }
        o += mq * m;
      }
    }
    // Δv = M̃⁻¹ Jᵀ Δλ per body.
    bodyChanges(this.acc, bodyNodes, bs, P, vOff, this.sNode, this.U, x);
  }
}
