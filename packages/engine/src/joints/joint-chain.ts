/**
 * The joint-space solve of the rigid joints that form chains (see docs/joints.md, "Chains in joint
 * space"): where every component of the joint forest is a path (each dynamic body has at most two
 * tree joints, those to the world included) of joints of any width, the system the forest solves,
 *
 * ```
 * A Δλ = c,   A = J M̃⁻¹ Jᵀ,   Δv = M̃⁻¹ Jᵀ Δλ
 * ```
 *
 * (M̃: the mass matrix with the geometric stiffness on its angular blocks, as in `JointTree`), is
 * block-tridiagonal in m_p × m_q blocks (m_p: joint p's equality rows) when the joints are taken
 * along the path: joint p couples only to the joints before and after it, through the body they
 * share. Its block LDLᵀ then has no fill-in either. A is positive definite whenever the rows are
 * independent, whatever the order: a chain held at both ends is solved as exactly as one held at
 * one end (the tree's order is not so neutral: a leaf body whose folded joint fixes a point can
 * leave its parent joint's block singular there, and the chain comes apart). With redundant rows
 * (a planar loop of hinges, a chain welded at both ends, a taut chain) A is positive
 * semi-definite, and so is each D_p.
 *
 * Two paths: point joints in 3D by 3 × 3 blocks and their cofactor inverses (a third of the size
 * of the tree's nodes: a factorisation of the chain of 10 in about 4 µs instead of 11), and every
 * other chain (hinges, welds, mixed widths, any n) by dense blocks, each D_p by an LDLᵀ. The
 * general path takes 15–20% longer a step on a 3-row chain than the 3 × 3 one, so both are kept.
 *
 * A pivot of D_p's LDLᵀ within ±1e-8 of its size (A_pp's largest diagonal entry plus what
 * cancelled in it) belongs to a redundant row: it is dropped (1/d := 0, its column of L zero). For
 * a semi-definite A that column is zero up to rounding anyway, L D Lᵀ is still A, and
 * L⁻ᵀ D⁺ L⁻¹ is a generalised inverse of A: the solve meets every row whose right-hand side is
 * consistent with the others (the redundant rows' c are, up to drift), the dropped direction
 * taking no Δλ. A pivot below −1e-8 of its size means A is not semi-definite (nor the rows a
 * joint's): the factorisation fails and `JointTree` factors and solves the forest itself.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { growFloat64, growInt32 } from '../contacts/contact-set.js';
import type { SolverBodies } from '../solver/solver-bodies.js';
import { BLOCK_TOLERANCE, bodyChanges, bodyInverses, gatherLoads, ldlFactor, ldlSolve, sideBlock } from './joint-blocks.js';
import type { JointSolver } from './joint-solver.js';

/**
 * The node tables of `JointTree` that `JointChain.build` walks (see `JointTree` for each): the
 * tree points this record at its arrays before each build, as they may have grown.
 * @internal
 */
export interface ForestLinks {
  /** Per solver slot: its body node, or −1. */
  slotNode: Int32Array;
  /** Per node: its slot (body node) or joint index (joint node). */
  nRef: Int32Array;
  /** Per body node: its first incident joint node as an edge id, −1 for none. */
  adjHead: Int32Array;
  /** Per edge: the next edge of the same body. */
  adjNext: Int32Array;
  /** Per edge: its joint node. */
  adjJoint: Int32Array;
  /** Per body node: its first folded joint, −1 for none. */
  fold: Int32Array;
  /** Per joint: the next folded joint of the same body. */
  foldNext: Int32Array;
}

/**
 * The chains of a joint forest in joint space, built by `JointTree.build` when the forest is
 * made of chains, factored and solved in its place.
 * @internal
 */
export class JointChain {
  /** Joints in path order, component after component. */
  count = 0;
  /** Per joint (solver index): 1 once placed on a path (`build`). */
  private seen = new Int32Array(16);
  /** Per position: the joint (solver index). */
  pJoint = new Int32Array(16);
  /** Per position: 1 when it shares a body with the position before (its block couples). */
  private pLink = new Int32Array(16);
  /** Per position: the side (0: A, 1: B) of the shared body, of this joint and of the one before. */
  private pSide = new Int32Array(16);
  private pPrevSide = new Int32Array(16);
  /** Per position and side (2p + side): the tree's body node, −1 for no dynamic body. */
  private sNode = new Int32Array(32);
  /** M̃⁻¹ Gᵀ per position and side: 6 × 3 (row-major), G the side's signed Jacobian (3 × 6). */
  private U = new Float64Array(32 * 18);
  /** Per position: the coupling block A_p,p−1 (3 × 3). */
  private off = new Float64Array(16 * 9);
  /** Per position: L_p (3 × 3). */
  private L = new Float64Array(16 * 9);
  /** Per position: D_p⁻¹. */
  private Dinv = new Float64Array(16 * 9);
  /** Per body node: 1/m and the angular M̃⁻¹ (3 × 3). */
  private bodyInv = new Float64Array(16 * 10);
  /** Per body node (general path): the scalar of its M̃ angular inverse when that is s·1, else −1. */
  private bodyIso = new Float64Array(16);
  /** Per body node: Σ|λ||J_angular| over its joints (the geometric stiffness before its scale). */
  private bodyG = new Float64Array(16);
  /** Per body node: the Δv and Δω of a solve. */
  acc = new Float64Array(16 * 6);
  /** The right-hand side, then the solution Δλ (3 per position). */
  vec = new Float64Array(48);
  /** The pivot block D_p being factored (its upper triangle). */
  private readonly blk = new Float64Array(9);
  /** The leading minors of order 2 and 3 of the block `inverse` inverted last. */
  private readonly minors = new Float64Array(2);
  /** The signed Jacobians (3 × 6) of the two sides of the position being factored. */
  private G = new Float64Array(36);
  /** A body's M̃ angular block (k × k) being inverted (general path). */
  private kblk = new Float64Array(9);
  /** The scale of the geometric stiffness for the next `factor` (`JointTree.stiffness`). */
  stiffness = 0;
  /** Count of dimensions. */
  private readonly n: number;
  /** Angular components of a body (k = n(n − 1)/2). */
  private readonly k: number;
  /** n + k: the velocity size of a body (the stride of `acc`). */
  readonly bs: number;
  /**
   * 1 when the chains are solved by the general path (joints of any width m, any n: blocks
   * m_p × m_q, each D_p by a dense LDLᵀ); 0 for the 3 × 3 path (point joints in 3D).
   */
  private wide = 0;
  /** Per position: its first entry in `vec` (the sum of the widths before it); P + 1 entries. */
  vOff = new Int32Array(17);
  /** Per position (general path): the offset of its A_p,p−1 and L_p (m_p × m_p−1) in `off` and `L`. */
  private cOff = new Int32Array(16);
  /** Per position (general path): the offset of its factored D_p (m_p × m_p) in `Dinv`. */
  private dOff = new Int32Array(16);
  /** Per entry of `vec` (general path): 1 / d_j of its position's LDLᵀ. */
  private rd = new Float64Array(48);
  /**
   * Per row of the block the next `ldlFactor` factors: the size its pivot is measured against
   * (A_pp's largest diagonal entry plus what the Schur complement took from that row's diagonal).
   */
  private size = new Float64Array(6);
  /** Three columns of the generalised inverse of a semi-definite 3 × 3 pivot block (`semiInverse`). */
  private readonly cols = new Float64Array(9);
  /** The widest joint of the forest (general path). */
  private mMax = 3;

  constructor(D: Dims) {
    this.n = D.n;
    this.k = D.k;
    this.bs = D.n + D.k;
  }

  /**
   * Orders the forest's joints along its paths. Returns 1 when the forest is made of chains
   * (at most two tree joints per body: joints of any width, to the world or not), else 0.
   * `forest` holds the tree's node tables as `JointTree.build` left them.
   */
  build(js: JointSolver, role: Int32Array, bodyNodes: number, forest: ForestLinks): number {
    this.count = 0;
    const { slotNode, adjHead, adjNext, fold, foldNext } = forest;
    const count = js.count;
    let tree = 0;
    let wide = this.n !== 3 ? 1 : 0;
    let mMax = 0;
    for (let j = 0; j < count; j += 1) {
      if (role[j] === 0) continue;
      const m = js.jBlock[j];
      if (m !== 3) wide = 1;
      if (m > mMax) mMax = m;
      tree += 1;
    }
    for (let i = 0; i < bodyNodes; i += 1) {
      let deg = 0;
      for (let ed = adjHead[i]; ed >= 0; ed = adjNext[ed]) deg += 1;
      for (let j = fold[i]; j >= 0; j = foldNext[j]) deg += 1;
      if (deg > 2) return 0;
    }
    this.grow(tree, bodyNodes);
    this.seen = growInt32(this.seen, count, 0);
    const seen = this.seen;
    for (let j = 0; j < count; j += 1) seen[j] = 0;
    let P = 0;
    // Each path from one of its ends.
    for (let j0 = 0; j0 < count; j0 += 1) {
      if (role[j0] === 0 || seen[j0] !== 0) continue;
      // An end: at most one side's body has another tree joint.
      let ends = 0;
      for (let side = 0; side < 2; side += 1) {
        const b = slotNode[side === 0 ? js.jA[j0] : js.jB[j0]];
        if (b >= 0 && this.other(b, j0, forest) >= 0) ends += 1;
      }
      if (ends > 1) continue;
      let cur = j0;
      let prev = -1; // the body node shared with the joint before
      let prevJ = -1;
      while (cur >= 0 && seen[cur] === 0) {
        seen[cur] = 1;
        this.pJoint[P] = cur;
        this.pLink[P] = prev >= 0 ? 1 : 0;
        const nA = slotNode[js.jA[cur]];
        const nB = slotNode[js.jB[cur]];
        this.sNode[2 * P] = js.jA[cur] > 0 ? nA : -1;
        this.sNode[2 * P + 1] = js.jB[cur] > 0 ? nB : -1;
        if (prev >= 0) {
          this.pSide[P] = nB === prev ? 1 : 0;
          this.pPrevSide[P] = slotNode[js.jB[prevJ]] === prev ? 1 : 0;
        }
        P += 1;
        let next = -1;
        let via = -1;
        for (let side = 0; side < 2 && next < 0; side += 1) {
          const b = side === 0 ? nA : nB;
          if (b < 0 || b === prev) continue;
          const o = this.other(b, cur, forest);
          if (o >= 0 && seen[o] === 0) {
            next = o;
            via = b;
          }
        }
        prevJ = cur;
        prev = via;
        cur = next;
      }
    }
    if (P !== tree) return 0; // a cycle of joints (not in a forest): the tree decides
    this.count = P;
    this.wide = wide;
    this.mMax = mMax;
    // Offsets along the path (the 3 × 3 path's are 3p, 9p and 36p by construction).
    const vOff = this.vOff;
    let v = 0;
    let c = 0;
    let d = 0;
    for (let p = 0; p < P; p += 1) {
      const m = js.jBlock[this.pJoint[p]];
      vOff[p] = v;
      this.cOff[p] = c;
      this.dOff[p] = d;
      if (this.pLink[p] === 1) c += m * js.jBlock[this.pJoint[p - 1]];
      d += m * m;
      v += m;
    }
    vOff[P] = v;
    if (wide === 1) {
      const bs = this.bs;
      this.U = growFloat64(this.U, 2 * v * bs, 0);
      this.off = growFloat64(this.off, c, 0);
      this.L = growFloat64(this.L, c, 0);
      this.Dinv = growFloat64(this.Dinv, d, 0);
      this.vec = growFloat64(this.vec, v, 0);
      this.rd = growFloat64(this.rd, v, 0);
      this.size = growFloat64(this.size, mMax, 0);
      this.G = growFloat64(this.G, 2 * mMax * bs, 0);
      const k = this.k;
      this.bodyInv = growFloat64(this.bodyInv, (1 + k * k) * bodyNodes, 0);
      this.acc = growFloat64(this.acc, bs * bodyNodes, 0);
      this.bodyIso = growFloat64(this.bodyIso, bodyNodes, 0);
      this.kblk = growFloat64(this.kblk, k * k, 0);
    }
    return 1;
  }

  /** The tree joint of body node b other than j, or −1. */
  private other(b: number, j: number, forest: ForestLinks): number {
    const { nRef, adjHead, adjNext, adjJoint, fold, foldNext } = forest;
    for (let ed = adjHead[b]; ed >= 0; ed = adjNext[ed]) {
      const o = nRef[adjJoint[ed]];
      if (o !== j) return o;
    }
    for (let o = fold[b]; o >= 0; o = foldNext[o]) if (o !== j) return o;
    return -1;
  }

  private grow(P: number, bodies: number): void {
    this.pJoint = growInt32(this.pJoint, P, 0);
    this.vOff = growInt32(this.vOff, P + 1, 0);
    this.cOff = growInt32(this.cOff, P, 0);
    this.dOff = growInt32(this.dOff, P, 0);
    this.pLink = growInt32(this.pLink, P, 0);
    this.pSide = growInt32(this.pSide, P, 0);
    this.pPrevSide = growInt32(this.pPrevSide, P, 0);
    this.sNode = growInt32(this.sNode, 2 * P, 0);
    this.U = growFloat64(this.U, 36 * P, 0);
    this.off = growFloat64(this.off, 9 * P, 0);
    this.L = growFloat64(this.L, 9 * P, 0);
    this.Dinv = growFloat64(this.Dinv, 9 * P, 0);
    this.vec = growFloat64(this.vec, 3 * P, 0);
    this.rd = growFloat64(this.rd, 3 * P, 0);
    this.bodyInv = growFloat64(this.bodyInv, 10 * bodies, 0);
    this.bodyG = growFloat64(this.bodyG, bodies, 0);
    this.acc = growFloat64(this.acc, 6 * bodies, 0);
  }

  /**
   * Assembles A's blocks from the rows and the bodies' inverse mass and inertia (with the
   * geometric stiffness `stiffness`·Σ|λ||J_angular| on the angular diagonal of M̃)
   * and factors A = L D Lᵀ along each path, redundant rows' pivots dropped. Returns 1, or 0 when a
   * pivot block is not positive semi-definite (the caller falls back to the tree).
   */
  factor(js: JointSolver, sb: SolverBodies, bodyNodes: number, nRef: Int32Array): number {
    if (this.wide === 1) return this.factorWide(js, sb, bodyNodes, nRef);
    const P = this.count;
    const stiffness = this.stiffness;
    const rows = js.rows;
    const RS = js.RS;
    const bi = this.bodyInv;
    const g = this.bodyG;
    gatherLoads(js, this.count, this.pJoint, this.sNode, this.bodyG, bodyNodes, this.stiffness > 0 ? 1 : 0);
    for (let i = 0; i < bodyNodes; i += 1) {
      const slot = nRef[i];
      const o = 10 * i;
      bi[o] = sb.invMass[slot];
      const gi = g[i] * stiffness;
      if (gi > 0) {
        // (I_world + g·1)⁻¹ (symmetric positive definite).
        const I = sb.inertia;
        const D = this.blk;
        for (let q = 0, at = slot * 9; q < 9; q += 1) D[q] = I[at + q];
        D[0] += gi;
        D[4] += gi;
        D[8] += gi;
        this.inverse(bi, o + 1);
      } else {
        const II = sb.invInertia;
        for (let q = 0, s = slot * 9; q < 9; q += 1) bi[o + 1 + q] = II[s + q];
      }
    }
    const U = this.U;
    const D = this.blk;
    const off = this.off;
    const L = this.L;
    const Dinv = this.Dinv;
    const G = this.G;
    for (let p = 0; p < P; p += 1) {
      const first = js.jFirst[this.pJoint[p]];
      for (let q = 0; q < 9; q += 1) D[q] = 0;
      // For each side: its signed Jacobian G (3 × 6) into G, U = M̃⁻¹ Gᵀ, and A_pp += G U (symmetric).
      for (let side = 0; side < 2; side += 1) {
        const node = this.sNode[2 * p + side];
        if (node < 0) continue;
        const sg = side === 1 ? 1 : -1;
        const oj = side === 1 ? js.OFF_JB : js.OFF_JA;
        const u0 = (2 * p + side) * 18;
        const g0 = side * 18;
        const b0 = 10 * node;
        const im = bi[b0];
        const i0 = bi[b0 + 1];
        const i1 = bi[b0 + 2];
        const i2 = bi[b0 + 3];
        const i3 = bi[b0 + 4];
        const i4 = bi[b0 + 5];
        const i5 = bi[b0 + 6];
        const i6 = bi[b0 + 7];
        const i7 = bi[b0 + 8];
        const i8 = bi[b0 + 9];
        for (let r = 0; r < 3; r += 1) {
          const base = (first + r) * RS;
          const jb = base + oj;
          const x0 = sg * rows[base];
          const x1 = sg * rows[base + 1];
          const x2 = sg * rows[base + 2];
          const j0 = sg * rows[jb];
          const j1 = sg * rows[jb + 1];
          const j2 = sg * rows[jb + 2];
          const gr = g0 + 6 * r;
          G[gr] = x0;
          G[gr + 1] = x1;
          G[gr + 2] = x2;
          G[gr + 3] = j0;
          G[gr + 4] = j1;
          G[gr + 5] = j2;
          U[u0 + r] = x0 * im;
          U[u0 + 3 + r] = x1 * im;
          U[u0 + 6 + r] = x2 * im;
          U[u0 + 9 + r] = i0 * j0 + i1 * j1 + i2 * j2;
          U[u0 + 12 + r] = i3 * j0 + i4 * j1 + i5 * j2;
          U[u0 + 15 + r] = i6 * j0 + i7 * j1 + i8 * j2;
        }
        // The upper triangle (the check and the inverse below read no other).
        this.addGU(D, 0, g0, u0, 1);
      }
      let big = D[0];
      if (D[4] > big) big = D[4];
      if (D[8] > big) big = D[8];
      const o9 = 9 * p;
      if (this.pLink[p] === 1) {
        // A_p,p−1 = G_p(b) U_p−1(b) over the shared body b (off), L_p = off · D_p−1⁻¹, and
        // D_p = A_pp − L_p offᵀ.
        const g0 = 18 * this.pSide[p];
        const u0 = (2 * (p - 1) + this.pPrevSide[p]) * 18;
        for (let q = 0; q < 9; q += 1) off[o9 + q] = 0;
        this.addGU(off, o9, g0, u0, 0);
        const d9 = o9 - 9;
        for (let r = 0; r < 3; r += 1) {
          const f0 = off[o9 + 3 * r];
          const f1 = off[o9 + 3 * r + 1];
          const f2 = off[o9 + 3 * r + 2];
          for (let c = 0; c < 3; c += 1) L[o9 + 3 * r + c] = f0 * Dinv[d9 + c] + f1 * Dinv[d9 + 3 + c] + f2 * Dinv[d9 + 6 + c];
        }
        for (let r = 0; r < 3; r += 1) {
          const l0 = L[o9 + 3 * r];
          const l1 = L[o9 + 3 * r + 1];
          const l2 = L[o9 + 3 * r + 2];
          for (let c = r; c < 3; c += 1)
            D[3 * r + c] -= l0 * off[o9 + 3 * c] + l1 * off[o9 + 3 * c + 1] + l2 * off[o9 + 3 * c + 2];
        }
      }
      // D_p⁻¹ when D_p is clearly positive definite (its leading minors), else its generalised inverse.
      const a0 = D[0];
      const tol = big * BLOCK_TOLERANCE;
      this.inverse(Dinv, o9);
      const m2 = this.minors[0];
      if (!(a0 > tol) || !(m2 > tol * a0) || !(this.minors[1] > tol * m2)) {
        if (this.semiInverse(p, big) === 0) return 0;
      }
    }
    return 1;
  }

  /**
   * D_p⁻¹ of the 3 × 3 path when D_p (in `blk`) is not clearly positive definite: its LDLᵀ with the
   * rule of the general path (a redundant row's pivot dropped) and the generalised inverse
   * L⁻ᵀ D⁺ L⁻¹ into Dinv, column by column. Returns 0 when D_p is not semi-definite.
   */
  private semiInverse(p: number, big: number): number {
    const o9 = 9 * p;
    const A = this.Dinv;
    const D = this.blk;
    for (let r = 0; r < 3; r += 1) {
      let cut = 0;
      if (this.pLink[p] === 1) for (let c = 0; c < 3; c += 1) cut += Math.abs(this.L[o9 + 3 * r + c] * this.off[o9 + 3 * r + c]);
      this.size[r] = big + cut;
      for (let c = r; c < 3; c += 1) A[o9 + 3 * r + c] = D[3 * r + c];
    }
    if (ldlFactor(this.Dinv, o9, 3, this.rd, 3 * p, this.size) === 0) return 0;
    const X = this.cols;
    for (let q = 0; q < 9; q += 1) X[q] = q % 4 === 0 ? 1 : 0;
    for (let c = 0; c < 3; c += 1) ldlSolve(this.Dinv, o9, 3, this.rd, 3 * p, X, 3 * c);
    for (let r = 0; r < 3; r += 1) for (let c = 0; c < 3; c += 1) A[o9 + 3 * r + c] = X[3 * c + r];
    return 1;
  }

  /**
   * out[o + 3r + c] += (G U)_rc for the G at G[g0] (3 × 6) and the U at U[u0] (6 × 3); `upper` 1:
   * only c >= r.
   */
  private addGU(out: Float64Array, o: number, g0: number, u0: number, upper: number): void {
    const G = this.G;
    const U = this.U;
    for (let r = 0; r < 3; r += 1) {
      const g = g0 + 6 * r;
      for (let c = upper === 1 ? r : 0; c < 3; c += 1) {
        out[o + 3 * r + c] +=
          G[g] * U[u0 + c] +
          G[g + 1] * U[u0 + 3 + c] +
          G[g + 2] * U[u0 + 6 + c] +
          G[g + 3] * U[u0 + 9 + c] +
          G[g + 4] * U[u0 + 12 + c] +
          G[g + 5] * U[u0 + 15 + c];
      }
    }
  }

  /**
   * The inverse of the symmetric 3 × 3 in `blk` (its upper triangle is read) into out[o..o+9],
   * by its cofactors; its leading minors of order 2 and 3 into `minors`.
   */
  private inverse(out: Float64Array, o: number): void {
    const D = this.blk;
    const a0 = D[0];
    const a1 = D[1];
    const a2 = D[2];
    const a4 = D[4];
    const a5 = D[5];
    const a8 = D[8];
    const m2 = a0 * a4 - a1 * a1;
    const c0 = a4 * a8 - a5 * a5;
    const c1 = a5 * a2 - a1 * a8;
    const c2 = a1 * a5 - a4 * a2;
    const c5 = a2 * a1 - a0 * a5;
    const det = a0 * c0 + a1 * c1 + a2 * c2;
    this.minors[0] = m2;
    this.minors[1] = det;
    const id = 1 / det;
    out[o] = c0 * id;
    out[o + 1] = c1 * id;
    out[o + 2] = c2 * id;
    out[o + 3] = c1 * id;
    out[o + 4] = (a0 * a8 - a2 * a2) * id;
    out[o + 5] = c5 * id;
    out[o + 6] = c2 * id;
    out[o + 7] = c5 * id;
    out[o + 8] = m2 * id;
  }

  /**
   * Solves A Δλ = c with c in `vec` (3 per position), leaving Δλ there, and sums each body
   * node's M̃⁻¹ Jᵀ Δλ into `acc` (6 per body node, of `bodyNodes`).
   */
  solve(bodyNodes: number): void {
    if (this.wide === 1) {
      this.solveWide(bodyNodes);
      return;
    }
    const P = this.count;
    const x = this.vec;
    const L = this.L;
    const Dinv = this.Dinv;
    const link = this.pLink;
    // L z = c.
    for (let p = 1; p < P; p += 1) {
      if (link[p] === 0) continue;
      const o = 9 * p;
      const v = 3 * p;
      const z0 = x[v - 3];
      const z1 = x[v - 2];
      const z2 = x[v - 1];
      x[v] -= L[o] * z0 + L[o + 1] * z1 + L[o + 2] * z2;
      x[v + 1] -= L[o + 3] * z0 + L[o + 4] * z1 + L[o + 5] * z2;
      x[v + 2] -= L[o + 6] * z0 + L[o + 7] * z1 + L[o + 8] * z2;
    }
    // w = D⁻¹ z.
    for (let p = 0; p < P; p += 1) {
      const o = 9 * p;
      const v = 3 * p;
      const a = x[v];
      const b = x[v + 1];
      const c = x[v + 2];
      x[v] = Dinv[o] * a + Dinv[o + 1] * b + Dinv[o + 2] * c;
      x[v + 1] = Dinv[o + 3] * a + Dinv[o + 4] * b + Dinv[o + 5] * c;
      x[v + 2] = Dinv[o + 6] * a + Dinv[o + 7] * b + Dinv[o + 8] * c;
    }
    // Lᵀ x = w.
    for (let p = P - 1; p >= 1; p -= 1) {
      if (link[p] === 0) continue;
      const o = 9 * p;
      const v = 3 * p;
      const y0 = x[v];
      const y1 = x[v + 1];
      const y2 = x[v + 2];
      x[v - 3] -= L[o] * y0 + L[o + 3] * y1 + L[o + 6] * y2;
      x[v - 2] -= L[o + 1] * y0 + L[o + 4] * y1 + L[o + 7] * y2;
      x[v - 1] -= L[o + 2] * y0 + L[o + 5] * y1 + L[o + 8] * y2;
    }
    // Δv = M̃⁻¹ Jᵀ Δλ per body.
    const acc = this.acc;
    for (let q = 0; q < 6 * bodyNodes; q += 1) acc[q] = 0;
    const U = this.U;
    for (let p = 0; p < P; p += 1) {
      const l0 = x[3 * p];
      const l1 = x[3 * p + 1];
      const l2 = x[3 * p + 2];
      for (let side = 0; side < 2; side += 1) {
        const node = this.sNode[2 * p + side];
        if (node < 0) continue;
        const u0 = (2 * p + side) * 18;
        const a0 = 6 * node;
        for (let e = 0; e < 6; e += 1) acc[a0 + e] += U[u0 + 3 * e] * l0 + U[u0 + 3 * e + 1] * l1 + U[u0 + 3 * e + 2] * l2;
      }
    }
  }
  // ---- the general path: joints of any width m_p, bodies of n + k unknowns ----

  /**
   * `factor` for joints of any width: U = M̃⁻¹ Gᵀ per side (bs × m_p, row-major), A_pp and
   * A_p,p−1 from G U, L_p = A_p,p−1 D_p−1⁻¹ (each row by the LDLᵀ of D_p−1), D_p = A_pp − L_p A_p,p−1ᵀ,
   * and each D_p's LDLᵀ (redundant rows dropped); 0 when a block is not semi-definite.
   */
  private factorWide(js: JointSolver, sb: SolverBodies, bodyNodes: number, nRef: Int32Array): number {
    const P = this.count;
    const { k, bs } = this;
    const stiffness = this.stiffness;
    const bi = this.bodyInv;
    const g = this.bodyG;
    gatherLoads(js, this.count, this.pJoint, this.sNode, this.bodyG, bodyNodes, this.stiffness > 0 ? 1 : 0);
    // The stiffness scaled in here, not passed: a double argument is boxed (see joint-blocks.ts).
    for (let i = 0; i < bodyNodes; i += 1) g[i] *= stiffness;
    const iso = this.bodyIso;
    bodyInverses(sb, nRef, bodyNodes, k, g, bi, iso, this.kblk);
    const U = this.U;
    const G = this.G;
    const off = this.off;
    const L = this.L;
    const Dm = this.Dinv;
    const gs = this.mMax * bs;
    for (let p = 0; p < P; p += 1) {
      const j = this.pJoint[p];
      const m = js.jBlock[j];
      const v0 = this.vOff[p];
      const d0 = this.dOff[p];
      for (let q = 0; q < m * m; q += 1) Dm[d0 + q] = 0;
      for (let side = 0; side < 2; side += 1) {
        const node = this.sNode[2 * p + side];
        if (node >= 0) sideBlock(js, j, side, node, k, bi, iso, G, side * gs, U, (2 * v0 + side * m) * bs, Dm, d0);
      }
      let big = 0;
      for (let r = 0; r < m; r += 1) if (Dm[d0 + r * m + r] > big) big = Dm[d0 + r * m + r];
      if (this.pLink[p] === 1) {
        const jp = this.pJoint[p - 1];
        const mp = js.jBlock[jp];
        const c0 = this.cOff[p];
        const g0 = gs * this.pSide[p];
        const up = (2 * this.vOff[p - 1] + this.pPrevSide[p] * mp) * bs;
        for (let r = 0; r < m; r += 1) {
          const gr = g0 + r * bs;
          for (let c = 0; c < mp; c += 1) {
            let sum = 0;
            for (let e = 0; e < bs; e += 1) sum += G[gr + e] * U[up + e * mp + c];
            off[c0 + r * mp + c] = sum;
            L[c0 + r * mp + c] = sum;
          }
          ldlSolve(Dm, this.dOff[p - 1], mp, this.rd, this.vOff[p - 1], L, c0 + r * mp);
        }
        for (let r = 0; r < m; r += 1) {
          let cut = 0;
          for (let q = 0; q < mp; q += 1) cut += Math.abs(L[c0 + r * mp + q] * off[c0 + r * mp + q]);
          this.size[r] = big + cut;
          for (let c = r; c < m; c += 1) {
            let sum = 0;
            for (let q = 0; q < mp; q += 1) sum += L[c0 + r * mp + q] * off[c0 + c * mp + q];
            Dm[d0 + r * m + c] -= sum;
          }
        }
      } else {
        for (let r = 0; r < m; r += 1) this.size[r] = big;
      }
      if (ldlFactor(Dm, d0, m, this.rd, v0, this.size) === 0) return 0;
    }
    return 1;
  }

  /** `solve` for joints of any width. */
  private solveWide(bodyNodes: number): void {
    const P = this.count;
    const bs = this.bs;
    const x = this.vec;
    const L = this.L;
    const vOff = this.vOff;
    const link = this.pLink;
    // L z = c.
    for (let p = 1; p < P; p += 1) {
      if (link[p] === 0) continue;
      const v = vOff[p];
      const vp = vOff[p - 1];
      const m = vOff[p + 1] - v;
      const mp = v - vp;
      const c0 = this.cOff[p];
      for (let r = 0; r < m; r += 1) {
        let sum = 0;
        for (let q = 0; q < mp; q += 1) sum += L[c0 + r * mp + q] * x[vp + q];
        x[v + r] -= sum;
      }
    }
    // w = D⁻¹ z.
    for (let p = 0; p < P; p += 1) ldlSolve(this.Dinv, this.dOff[p], vOff[p + 1] - vOff[p], this.rd, vOff[p], x, vOff[p]);
    // Lᵀ x = w.
    for (let p = P - 1; p >= 1; p -= 1) {
      if (link[p] === 0) continue;
      const v = vOff[p];
      const vp = vOff[p - 1];
      const m = vOff[p + 1] - v;
      const mp = v - vp;
      const c0 = this.cOff[p];
      for (let q = 0; q < mp; q += 1) {
        let sum = 0;
        for (let r = 0; r < m; r += 1) sum += L[c0 + r * mp + q] * x[v + r];
        x[vp + q] -= sum;
      }
    }
    // Δv = M̃⁻¹ Jᵀ Δλ per body.
    bodyChanges(this.acc, bodyNodes, bs, P, vOff, this.sNode, this.U, x);
  }
}
