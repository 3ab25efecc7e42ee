/**
 * The direct solver of the rigid joints that form a forest: Baraff's linear-time factorisation
 * ("Linear-time dynamics using Lagrange multipliers", SIGGRAPH 1996) of the system
 *
 * ```
 * [ M  Jᵀ ] [ Δv ]   [ 0 ]
 * [ J  0  ] [ y  ] = [ c ]        Δλ = −y,  c = −(Ċ + bias)  (velocities)  or  −C  (positions)
 * ```
 *
 * over the graph whose nodes are the dynamic bodies and the joints between two dynamic bodies
 * (edges: a joint and its two bodies). Where that graph is a forest, a block LDLᵀ eliminated from
 * the leaves to the root has no fill-in, so one solve costs O(nodes) small dense blocks and meets
 * every equality row of every joint of the tree EXACTLY at once, whatever the mass ratios and
 * the length of the chain: a Gauss–Seidel sweep, by contrast, propagates a load one link per
 * iteration at a rate that worsens with the mass ratio.
 *
 * - A joint to the world (or to a static or kinematic body) is no node: its rows are folded into
 *   its body's node as extra rows of a KKT block [M Jᵀ; J 0], so joint nodes always have two body
 *   neighbours and the root is a body; every block D is then invertible when the rows are
 *   independent. A body's block is positive definite and a joint's (minus its Schur complement)
 *   negative definite, so blocks are factored by an LDLᵀ without pivoting; where a pivot has the
 *   wrong sign or is not clearly nonzero (LDL_TOLERANCE) the node falls back to Gaussian
 *   elimination with complete pivoting, where a pivot below a relative 1e-12 drops its row
 *   (redundant rows, e.g. two welds to the world on one body, or the grid's pinned row).
 * - A rigid joint that would close a cycle (the joint grid) and every soft joint stay with the
 *   Gauss–Seidel solver; the rest of the forest is still solved directly.
 * - Only the equality rows take part; limits, ropes, struts and motors are solved by the
 *   Gauss–Seidel passes around it.
 * - A forest made of chains (joints of any width, in any n) is factored and solved in joint space
 *   instead (`JointChain`, block-tridiagonal in m_p × m_q blocks; point joints in 3D by 3 × 3
 *   blocks: a factorisation in about a third of the time); redundant rows are dropped there,
 *   and only a pivot block that is not even positive semi-definite hands the factorisation here.
 *   Any other forest (a body with three or more tree joints) is factored in joint space leaves
 *   first (`JointSpaceTree`, no fill-in), with the same rule: this node LU is the fallback only.
 *
 * Storage is flat and grows by doubling; nothing is allocated once the scene has been seen.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { growFloat64, growInt32 } from '../contacts/contact-set.js';
import type { SolverBodies } from '../solver/solver-bodies.js';
import { BLOCK_TOLERANCE, geometricLoad } from './joint-blocks.js';
import { JointChain, type ForestLinks } from './joint-chain.js';
import { JointSpaceTree } from './joint-space.js';
import type { JointSolver } from './joint-solver.js';
import { SC_CHANGED, SC_SOLVE_TOL } from './joint-solver.js';

/** Relative size below which a pivot of a node block counts as zero. */
const PIVOT_TOLERANCE = 1e-12;

/**
 * A pivot of the block LDLᵀ whose size is at most this fraction of the block's largest diagonal
 * entry plus the terms that cancelled in it (max|D_ii| + Σ |L_jq² d_q|) is not clearly nonzero,
 * and the node falls back to the LU with complete pivoting (redundant rows, a locked plane): the
 * joint-space blocks' threshold (joint-blocks.ts says why it is not larger).
 */
const LDL_TOLERANCE = BLOCK_TOLERANCE;

/** Joint roles in the forest. */
const ROLE_GS = 0;
const ROLE_NODE = 1;
const ROLE_FOLDED = 2;

/** Who solves the forest: the node factorisation in `mat`, or a joint-space solver. */
const BY_NODES = 0;
const BY_CHAIN = 1;
const BY_BRANCH = 2;

/** The forest of the rigid joints of one sub-step and its factorisation. */
export class JointTree {
  private readonly n: number;
  private readonly k: number;
  /** k + n: the velocity size of a body. */
  private readonly bs: number;

  /** Per joint (solver index): ROLE_*. */
  role = new Int32Array(16);
  /** Count of joints solved by the tree (nodes and folded). */
  treeJoints = 0;

  // union–find over solver slots
  private uf = new Int32Array(16);
  // per slot: node index or −1
  private slotNode = new Int32Array(16);
  // nodes
  private nodeCount = 0;
  private nKind = new Int32Array(16); // 0 body, 1 joint
  private nRef = new Int32Array(16); // slot or joint index
  private nSize = new Int32Array(16);
  private nParent = new Int32Array(16);
  private nVisited = new Int32Array(16);
  private nOrder = new Int32Array(16); // leaves first
  private nD = new Int32Array(16); // offset of D
  private nW = new Int32Array(16); // offset of W (s_i × s_parent)
  private nV = new Int32Array(16); // offset in the vectors
  private nPiv = new Int32Array(16); // offset of the pivots (2 s per node)
  private nLdl = new Int32Array(16); // 1: the node's block is factored by the LDLᵀ; 0: by the LU
  private fold = new Int32Array(16); // body node: first folded joint, −1
  private foldNext = new Int32Array(16); // per joint: next folded joint of the same body
  private adjHead = new Int32Array(16); // body node: first incident joint node (as an edge id)
  private adjNext = new Int32Array(32); // per edge: next edge of the same body
  private adjJoint = new Int32Array(32); // per edge: joint node
  private stack = new Int32Array(16);
  private mat = new Float64Array(256);
  private vec = new Float64Array(64);
  private piv = new Int32Array(64);
  /** 1 / d_j of the LDLᵀ nodes, at the node's offset in the vectors (the solves multiply). */
  private rdiag = new Float64Array(64);
  /** One row's Ċ, from JointSolver.rowVelocityOf (the right-hand side of a velocity solve). */
  private readonly rowSpeed = new Float64Array(1);
  private hblk = new Float64Array(64);
  /** The tree bodies' v and ω after the last `passVelocities` solve (bs per body node). */
  private saved = new Float64Array(64);
  /** 1 while `saved` belongs to the current factorisation. */
  private savedOk = 0;
  /**
   * What the last `factor` factored was made of (see `sameInput`), for the forest `build` last
   * built (a build that builds anew clears `lastOk`). A `factor` whose input is the same, bit for bit,
   * keeps the factorisation (the velocity projection's, at the end of a sub-step, is the next
   * prepare's when nothing moved in between: the same poses, inertia and impulses).
   */
  private lastIn = new Float64Array(64);
  /** The length of that record. */
  private lastLen = -1;
  /**
   * 1 while the factorisation of the input recorded in `lastIn` on this forest is held (in
   * `mat`, `chain` or `branch`, as `factoredBy` says).
   */
  private lastOk = 0;
  /** The joint-space solver of a forest of chains. */
  private readonly chain: JointChain;
  /** The node tables `chain` walks when it builds (pointed at the current arrays then). */
  private readonly links: ForestLinks;
  /** The joint-space solver of a branching forest (the forests `chain` does not take). */
  private readonly branch: JointSpaceTree;
  /** The joint-space solver that takes the forest (set by `build`): BY_CHAIN, BY_BRANCH, or BY_NODES for none. */
  private space = BY_NODES;
  /** Count of body nodes (numbered first, 0 … bodyNodes − 1). */
  private bodyNodes = 0;
  /** Whose the current factorisation is: BY_CHAIN, BY_BRANCH, or BY_NODES (the node one, in `mat`). */
  private factoredBy = BY_NODES;

  constructor(D: Dims) {
    this.n = D.n;
    this.k = D.k;
    this.bs = D.n + D.k;
    this.chain = new JointChain(D);
    this.branch = new JointSpaceTree(D);
    this.links = {
      slotNode: this.slotNode,
      nRef: this.nRef,
      adjHead: this.adjHead,
      adjNext: this.adjNext,
      adjJoint: this.adjJoint,
      fold: this.fold,
      foldNext: this.foldNext,
    };
  }

  /**
   * Assigns the joints of `js` (after its prepare) to the forest or to Gauss–Seidel and builds
   * the nodes, their parents and the elimination order. Returns the count of tree joints.
   */
  build(js: JointSolver, sb: SolverBodies): number {
    const count = js.count;
    this.savedOk = 0;
    // The forest depends only on what `shapeKey` records: when that is unchanged (every build of
    // a step after the first, as a rule), the forest built last is this one.
    if (this.shapeKey(js, sb) === 1) return this.treeJoints;
    // A new forest: the factorisation `mat` holds is not of it (see `sameInput`).
    this.lastOk = 0;
    this.space = BY_NODES;
    this.role = growInt32(this.role, count);
    this.foldNext = growInt32(this.foldNext, count);
    const slots = sb.count;
    this.uf = growInt32(this.uf, slots);
    this.slotNode = growInt32(this.slotNode, slots);
    for (let s = 0; s < slots; s += 1) {
      this.uf[s] = s;
      this.slotNode[s] = -1;
    }
    this.nodeCount = 0;
    this.treeJoints = 0;
    let edges = 0;
    // Pass 1: roles, body nodes.
    for (let j = 0; j < count; j += 1) {
      this.role[j] = ROLE_GS;
      if (js.jSoft[j] !== 0 || js.jBlock[j] === 0 || js.joints[j].brokenFlag) continue;
      const a = js.jA[j];
      const b = js.jB[j];
      const dynA = a > 0 && sb.invMass[a] > 0;
      const dynB = b > 0 && sb.invMass[b] > 0;
      if (dynA && dynB) {
        const ra = this.find(a);
        const rb = this.find(b);
        if (ra === rb) continue; // closes a cycle: Gauss–Seidel
        this.uf[ra] = rb;
        this.role[j] = ROLE_NODE;
        this.bodyNode(a);
        this.bodyNode(b);
        edges += 2;
      } else if (dynA || dynB) {
        this.role[j] = ROLE_FOLDED;
        this.bodyNode(dynA ? a : b);
      } else {
        continue;
      }
      this.treeJoints += 1;
    }
    if (this.treeJoints === 0) return 0;
    // Pass 2: joint nodes, folded lists, adjacency.
    const bodyNodes = this.nodeCount;
    this.bodyNodes = bodyNodes;
    this.ensureNodes(bodyNodes + count);
    this.adjNext = growInt32(this.adjNext, edges);
    this.adjJoint = growInt32(this.adjJoint, edges);
    for (let i = 0; i < bodyNodes; i += 1) {
      this.fold[i] = -1;
      this.adjHead[i] = -1;
      this.nSize[i] = this.bs;
    }
    let e = 0;
    for (let j = 0; j < count; j += 1) {
      const role = this.role[j];
      if (role === ROLE_GS) continue;
      const a = js.jA[j];
      const b = js.jB[j];
      if (role === ROLE_FOLDED) {
        const node = this.slotNode[a > 0 && sb.invMass[a] > 0 ? a : b];
        this.foldNext[j] = this.fold[node];
        this.fold[node] = j;
        this.nSize[node] += js.jBlock[j];
        continue;
      }
      const node = this.nodeCount++;
      this.nKind[node] = 1;
      this.nRef[node] = j;
      this.nSize[node] = js.jBlock[j];
      const na = this.slotNode[a];
      const nb = this.slotNode[b];
      this.adjJoint[e] = node;
      this.adjNext[e] = this.adjHead[na];
      this.adjHead[na] = e++;
      this.adjJoint[e] = node;
      this.adjNext[e] = this.adjHead[nb];
      this.adjHead[nb] = e++;
    }
    // Pass 3: parents and the order (reverse preorder of a DFS from each root body).
    const N = this.nodeCount;
    this.stack = growInt32(this.stack, N + 1);
    for (let i = 0; i < N; i += 1) this.nVisited[i] = 0;
    let orderLen = 0;
    const order = this.nOrder;
    for (let root = 0; root < bodyNodes; root += 1) {
      if (this.nVisited[root] !== 0) continue;
      let top = 0;
      this.stack[top++] = root;
      this.nVisited[root] = 1;
      this.nParent[root] = -1;
      while (top > 0) {
        const node = this.stack[--top];
        order[orderLen++] = node;
        for (let ed = this.adjHead[node]; ed >= 0; ed = this.adjNext[ed]) {
          const jn = this.adjJoint[ed];
          if (this.nVisited[jn] !== 0) continue;
          this.nVisited[jn] = 1;
          this.nParent[jn] = node;
          order[orderLen++] = jn;
          // The joint's other body.
          const j = this.nRef[jn];
          const other = this.slotNode[this.slotNode[js.jA[j]] === node ? js.jB[j] : js.jA[j]];
          this.nVisited[other] = 1;
          this.nParent[other] = jn;
          this.stack[top++] = other;
        }
      }
    }
    // Reverse: leaves first.
    for (let i = 0, r = orderLen - 1; i < r; i += 1, r -= 1) {
      const t = order[i];
      order[i] = order[r];
      order[r] = t;
    }
    // Offsets.
    let dOff = 0;
    let wOff = 0;
    let vOff = 0;
    for (let i = 0; i < N; i += 1) {
      const s = this.nSize[i];
      this.nD[i] = dOff;
      dOff += s * s;
      this.nV[i] = vOff;
      this.nPiv[i] = 2 * vOff;
      vOff += s;
    }
    for (let i = 0; i < N; i += 1) {
      const p = this.nParent[i];
      this.nW[i] = dOff + wOff;
      if (p >= 0) wOff += this.nSize[i] * this.nSize[p];
    }
    if (dOff + wOff > this.mat.length) {
      this.mat = growFloat64(this.mat, dOff + wOff, 0);
      this.lastOk = 0;
    }
    this.vec = growFloat64(this.vec, vOff, 0);
    this.piv = growInt32(this.piv, 2 * vOff, 0);
    this.rdiag = growFloat64(this.rdiag, vOff, 0);
    const links = this.links;
    links.slotNode = this.slotNode;
    links.nRef = this.nRef;
    links.adjHead = this.adjHead;
    links.adjNext = this.adjNext;
    links.adjJoint = this.adjJoint;
    links.fold = this.fold;
    links.foldNext = this.foldNext;
    if (this.chain.build(js, this.role, bodyNodes, links) === 1) this.space = BY_CHAIN;
    else if (this.branch.build(js, this.role, bodyNodes, links) === 1) this.space = BY_BRANCH;
    return this.treeJoints;
  }

  /** The inputs of `build` at its last run: joint count, slot count, then per joint 3 numbers. */
  private buildKey = new Int32Array(64);
  private buildKeyOk = 0;

  /**
   * Records the inputs of `build` (per joint: soft, broken, which sides are dynamic, its block
   * size, its two slots) and returns 1 when they equal those of the last build.
   */
  private shapeKey(js: JointSolver, sb: SolverBodies): number {
    const count = js.count;
    const len = 2 + 3 * count;
    if (this.buildKey.length < len) {
      this.buildKey = growInt32(this.buildKey, len, 0);
      this.buildKeyOk = 0;
    }
    const key = this.buildKey;
    let same = this.buildKeyOk === 1 && key[0] === count && key[1] === sb.count ? 1 : 0;
    key[0] = count;
    key[1] = sb.count;
    const invMass = sb.invMass;
    for (let j = 0, at = 2; j < count; j += 1, at += 3) {
      const a = js.jA[j];
      const b = js.jB[j];
      const code =
        (js.jSoft[j] !== 0 ? 1 : 0) +
        (js.joints[j].brokenFlag ? 2 : 0) +
        (a > 0 && invMass[a] > 0 ? 4 : 0) +
        (b > 0 && invMass[b] > 0 ? 8 : 0) +
        js.jBlock[j] * 16;
      if (key[at] !== code || key[at + 1] !== a || key[at + 2] !== b) {
        same = 0;
        key[at] = code;
        key[at + 1] = a;
        key[at + 2] = b;
      }
    }
    this.buildKeyOk = 1;
    return same;
  }

  private find(i: number): number {
    const uf = this.uf;
    while (uf[i] !== i) {
      uf[i] = uf[uf[i]];
      i = uf[i];
    }
    return i;
  }

  private bodyNode(slot: number): void {
    if (this.slotNode[slot] >= 0) return;
    const node = this.nodeCount++;
    this.ensureNodes(node + 1);
    this.nKind[node] = 0;
    this.nRef[node] = slot;
    this.slotNode[slot] = node;
  }

  private ensureNodes(need: number): void {
    if (need <= this.nKind.length) return;
    this.nKind = growInt32(this.nKind, need);
    this.nRef = growInt32(this.nRef, need);
    this.nSize = growInt32(this.nSize, need);
    this.nParent = growInt32(this.nParent, need);
    this.nVisited = growInt32(this.nVisited, need);
    this.nOrder = growInt32(this.nOrder, need);
    this.nD = growInt32(this.nD, need);
    this.nW = growInt32(this.nW, need);
    this.nV = growInt32(this.nV, need);
    this.nPiv = growInt32(this.nPiv, need);
    this.nLdl = growInt32(this.nLdl, need);
    this.fold = growInt32(this.fold, need);
    this.adjHead = growInt32(this.adjHead, need);
  }

  // ---- the blocks of H ----

  /**
   * The whole coupling block between joint j's rows and the body in `slot` into H (s × sp,
   * row-major): the Jacobian of each row for that body (+[d, J_B] for b, −[d, J_A] for a; 0 in
   * the folded columns). `jointIsChild` 1: rows are the joint's rows and columns the body's
   * unknowns (s = the joint's rows); 0: the transpose (rows the body's unknowns).
   */
  private couplingBlock(
    js: JointSolver,
    j: number,
    slot: number,
    jointIsChild: number,
    s: number,
    sp: number,
    H: Float64Array,
  ): void {
    const { n, bs } = this;
    const rows = js.rows;
    const RS = js.RS;
    const first = js.jFirst[j];
    const isB = js.jB[j] === slot;
    const sg = isB ? 1 : -1;
    const offJ = (isB ? js.OFF_JB : js.OFF_JA) - n;
    // m: the joint's rows; u: the body's unknowns (folded columns beyond bs are 0).
    const m = jointIsChild === 1 ? s : sp;
    const u = jointIsChild === 1 ? sp : s;
    const stepRow = jointIsChild === 1 ? sp : 1;
    const stepCol = jointIsChild === 1 ? 1 : sp;
    // The columns in three runs (direction, Jacobian, folded zeros): no branch per entry.
    const uj = u < bs ? u : bs;
    const ud = u < n ? u : n;
    for (let r = 0; r < m; r += 1) {
      const base = (first + r) * RS;
      const at = r * stepRow;
      for (let c = 0; c < ud; c += 1) H[at + c * stepCol] = sg * rows[base + c];
      for (let c = ud; c < uj; c += 1) H[at + c * stepCol] = sg * rows[base + offJ + c];
      for (let c = uj; c < u; c += 1) H[at + c * stepCol] = 0;
    }
  }

  /**
   * The scale of the geometric stiffness added to the angular blocks by the next `factor`: the
   * sub-step h for the velocity passes, the position projection and the velocity projection; 0
   * for none (see docs/joints.md, "Heavy loads: the geometric stiffness").
   */
  stiffness = 0;

  /** Writes H_ii of every node into its D block. */
  private assemble(js: JointSolver, sb: SolverBodies, mat: Float64Array): void {
    const { n, k, bs } = this;
    for (let i = 0; i < this.nodeCount; i += 1) {
      const s = this.nSize[i];
      const d0 = this.nD[i];
      mat.fill(0, d0, d0 + s * s);
      if (this.nKind[i] === 1) continue;
      const slot = this.nRef[i];
      const m = 1 / sb.invMass[slot];
      for (let d = 0; d < n; d += 1) mat[d0 + d * s + d] = m;
      const I = sb.inertia;
      const i0 = slot * k * k;
      for (let r = 0; r < k; r += 1) for (let c = 0; c < k; c += 1) mat[d0 + (n + r) * s + n + c] = I[i0 + r * k + c];
      if (this.stiffness > 0) {
        // Geometric stiffness (Andrews, Teichmann & Kry 2017): h·Σ|λ||J_angular| on the diagonal.
        let g = 0;
        for (let ed = this.adjHead[i]; ed >= 0; ed = this.adjNext[ed]) g += geometricLoad(js, this.nRef[this.adjJoint[ed]], slot);
        for (let j = this.fold[i]; j >= 0; j = this.foldNext[j]) g += geometricLoad(js, j, slot);
        g *= this.stiffness;
        for (let r = 0; r < k; r += 1) mat[d0 + (n + r) * s + n + r] += g;
      }
      let row = bs;
      for (let j = this.fold[i]; j >= 0; j = this.foldNext[j]) {
        const m2 = js.jBlock[j];
        if (this.hblk.length < m2 * bs) this.hblk = growFloat64(this.hblk, m2 * bs, 0);
        const H = this.hblk;
        this.couplingBlock(js, j, slot, 1, m2, bs, H);
        for (let r = 0; r < m2; r += 1) {
          for (let c = 0; c < bs; c += 1) {
            const v = H[r * bs + c];
            mat[d0 + (row + r) * s + c] = v;
            mat[d0 + c * s + row + r] = v;
          }
        }
        row += m2;
      }
    }
  }

  /**
   * Records what the D blocks and the couplings are made of (the stiffness scale; each body
   * node's mass and world inertia; every tree joint's Jacobian rows and, with a stiffness, its
   * impulses) and returns 1 when all of it equals, bit for bit, what the factorisation `mat`
   * holds was made of, on the same forest: the factorisation is then that of this input (and
   * `factoredBy` says whose it is: the same input takes the same path).
   * Comparing the sources costs less than assembling the blocks to compare them.
   */
  private sameInput(js: JointSolver, sb: SolverBodies): number {
    const { k } = this;
    const N = this.nodeCount;
    const width = this.n + 2 * k;
    const stiff = this.stiffness;
    let len = 1;
    for (let i = 0; i < N; i += 1) {
      if (this.nKind[i] === 1) len += this.nSize[i] * (width + 1);
      else {
        len += 1 + k * k;
        for (let j = this.fold[i]; j >= 0; j = this.foldNext[j]) len += js.jBlock[j] * (width + 1);
      }
    }
    if (this.lastIn.length < len) {
      this.lastIn = growFloat64(this.lastIn, len, 0);
      this.lastOk = 0;
    }
    const last = this.lastIn;
    let same = this.lastOk === 1 && this.lastLen === len ? 1 : 0;
    let at = 0;
    if (last[at] !== stiff) {
      same = 0;
      last[at] = stiff;
    }
    at += 1;
    const inertia = sb.inertia;
    for (let i = 0; i < N; i += 1) {
      if (this.nKind[i] === 1) {
        at = this.recordRows(js, this.nRef[i], width, stiff, at);
        if (at < 0) {
          same = 0;
          at = -at;
        }
        continue;
      }
      const slot = this.nRef[i];
      const im = sb.invMass[slot];
      if (last[at] !== im) {
        same = 0;
        last[at] = im;
      }
      at += 1;
      for (let q = 0, i0 = slot * k * k; q < k * k; q += 1, at += 1) {
        const v = inertia[i0 + q];
        if (last[at] !== v) {
          same = 0;
          last[at] = v;
        }
      }
      for (let j = this.fold[i]; j >= 0; j = this.foldNext[j]) {
        at = this.recordRows(js, j, width, stiff, at);
        if (at < 0) {
          same = 0;
          at = -at;
        }
      }
    }
    this.lastLen = len;
    return same;
  }

  /**
   * Records joint j's Jacobian rows (and, with a stiffness, its impulses) into `lastIn` from `at`;
   * returns the end, negated when anything differed from what was there.
   */
  private recordRows(js: JointSolver, j: number, width: number, stiff: number, at: number): number {
    const last = this.lastIn;
    const rows = js.rows;
    const RS = js.RS;
    const first = js.jFirst[j];
    const lam = js.joints[j].lambda;
    let differs = 0;
    for (let r = 0; r < js.jBlock[j]; r += 1) {
      const base = (first + r) * RS;
      for (let c = 0; c < width; c += 1, at += 1) {
        const v = rows[base + c];
        if (last[at] !== v) {
          differs = 1;
          last[at] = v;
        }
      }
      const l = stiff > 0 ? lam[js.rowKey[first + r]] : 0;
      if (last[at] !== l) {
        differs = 1;
        last[at] = l;
      }
      at += 1;
    }
    return differs === 1 ? -at : at;
  }

  /**
   * Factors the forest: for each node, leaves first, D_i = H_ii − Σ_children H_ic W_c (done as the
   * children finish), its LU with complete pivoting, and W_i = D_i⁻¹ H_ip. With `keep` 1 (the
   * default) a factorisation of the same input, bit for bit, is kept (see `sameInput`); 0 factors
   * without comparing or recording.
   */
  factor(js: JointSolver, sb: SolverBodies, keep = 1): void {
    this.savedOk = 0;
    // The caller knows the input is new with `keep` 0 (the position projection, at poses just
    // moved): nothing is recorded, so the next `factor` compares against no input and factors
    // (factoring the same input again gives the same bits).
    if (keep === 1 && this.sameInput(js, sb) === 1) return;
    this.lastOk = keep;
    // A joint-space factorisation that fails (a block not semi-definite) leaves it to the nodes.
    this.factoredBy = BY_NODES;
    if (this.space === BY_CHAIN) {
      const chain = this.chain;
      chain.stiffness = this.stiffness;
      if (chain.factor(js, sb, this.bodyNodes, this.nRef) === 1) this.factoredBy = BY_CHAIN;
      chain.stiffness = 0;
    } else if (this.space === BY_BRANCH) {
      const branch = this.branch;
      branch.stiffness = this.stiffness;
      if (branch.factor(js, sb, this.bodyNodes, this.nRef) === 1) this.factoredBy = BY_BRANCH;
      branch.stiffness = 0;
    }
    if (this.factoredBy !== BY_NODES) return;
    this.assemble(js, sb, this.mat);
    const N = this.nodeCount;
    const order = this.nOrder;
    const size = this.nSize;
    const kind = this.nKind;
    const ref = this.nRef;
    const parent = this.nParent;
    const nD = this.nD;
    const nW = this.nW;
    const nV = this.nV;
    const ldl = this.nLdl;
    let maxSize = 0;
    for (let i = 0; i < N; i += 1) if (size[i] > maxSize) maxSize = size[i];
    if (this.hblk.length < maxSize * maxSize) this.hblk = growFloat64(this.hblk, maxSize * maxSize, 0);
    const H = this.hblk;
    const mat = this.mat;
    for (let o = 0; o < N; o += 1) {
      const i = order[o];
      const s = size[i];
      // A body's unknowns give positive pivots, its folded rows and a joint's rows negative ones.
      ldl[i] = this.ldlFactor(nD[i], s, kind[i] === 1 ? 0 : this.bs, nV[i]);
      if (ldl[i] === 0) this.luFactor(nD[i], s, this.nPiv[i]);
      const p = parent[i];
      if (p < 0) continue;
      const sp = size[p];
      const w0 = nW[i];
      const jointIsChild = kind[i] === 1;
      const j = jointIsChild ? ref[i] : ref[p];
      const slot = jointIsChild ? ref[p] : ref[i];
      // H_ip (s × sp) once, then W_i = D_i⁻¹ H_ip column by column and D_p −= H_ipᵀ W_i.
      this.couplingBlock(js, j, slot, jointIsChild ? 1 : 0, s, sp, H);
      for (let q = 0; q < s * sp; q += 1) mat[w0 + q] = H[q];
      if (ldl[i] === 1) this.ldlSolveColumns(nD[i], s, mat, w0, sp, nV[i]);
      else this.luSolveColumns(nD[i], s, this.nPiv[i], mat, w0, sp);
      // D_p −= H_ipᵀ W_i is symmetric: only its lower triangle (and diagonal) is updated, which is
      // all the LDLᵀ reads (a fallback to the LU mirrors it first).
      const dp = nD[p];
      for (let q = 0; q < s; q += 1) {
        const wq = w0 + q * sp;
        for (let r = 0, hq = q * sp; r < sp; r += 1) {
          const h = H[hq + r];
          if (h === 0) continue;
          const dr = dp + r * sp;
          for (let c = 0; c <= r; c += 1) mat[dr + c] -= h * mat[wq + c];
        }
      }
    }
  }

  /**
   * Solves H x = b with b already in `vec` (body nodes: 0 then the folded rows' c; joint nodes:
   * c), leaving x there. H = L D Lᵀ with L_pi = W_iᵀ: forward z_p −= W_iᵀ z_i (leaves first) and
   * w_i = D_i⁻¹ z_i, then backward x_i = w_i − W_i x_p (root first).
   */
  private solveVec(): void {
    // The fields read in the loops, in locals (the calls below could otherwise make V8 reload them).
    const mat = this.mat;
    const vec = this.vec;
    const order = this.nOrder;
    const size = this.nSize;
    const parent = this.nParent;
    const nV = this.nV;
    const nW = this.nW;
    const nD = this.nD;
    const ldl = this.nLdl;
    const N = this.nodeCount;
    for (let o = 0; o < N; o += 1) {
      const i = order[o];
      const s = size[i];
      const v0 = nV[i];
      const p = parent[i];
      if (p >= 0) {
        const sp = size[p];
        const w0 = nW[i];
        const vp = nV[p];
        for (let c = 0; c < sp; c += 1) {
          let sum = 0;
          for (let r = 0, at = w0 + c; r < s; r += 1, at += sp) sum += mat[at] * vec[v0 + r];
          vec[vp + c] -= sum;
        }
      }
      if (ldl[i] === 1) this.ldlSolveColumns(nD[i], s, vec, v0, 1, v0);
      else this.luSolveColumns(nD[i], s, this.nPiv[i], vec, v0, 1);
    }
    for (let o = N - 1; o >= 0; o -= 1) {
      const i = order[o];
      const p = parent[i];
      if (p < 0) continue;
      const s = size[i];
      const sp = size[p];
      const v0 = nV[i];
      const vp = nV[p];
      for (let r = 0, at = nW[i]; r < s; r += 1) {
        let sum = 0;
        for (let c = 0; c < sp; c += 1, at += 1) sum += mat[at] * vec[vp + c];
        vec[v0 + r] -= sum;
      }
    }
  }

  /**
   * Fills the right-hand side: for every equality row of the tree, c = −(Ċ + bias) (`positions`
   * 0, velocities from the solver bodies) or −C (`positions` 1); zeros for the body unknowns.
   */
  private rhs(js: JointSolver, sb: SolverBodies, positions: number): void {
    const vec = this.vec;
    const bs = this.bs;
    const scratch = this.rowSpeed;
    for (let i = 0; i < this.nodeCount; i += 1) {
      const v0 = this.nV[i];
      if (this.nKind[i] === 1) {
        this.rowsRhs(js, sb, this.nRef[i], vec, v0, positions, scratch);
        continue;
      }
      for (let c = 0; c < bs; c += 1) vec[v0 + c] = 0;
      let row = v0 + bs;
      for (let j = this.fold[i]; j >= 0; j = this.foldNext[j]) {
        this.rowsRhs(js, sb, j, vec, row, positions, scratch);
        row += js.jBlock[j];
      }
    }
  }

  private rowsRhs(
    js: JointSolver,
    sb: SolverBodies,
    j: number,
    vec: Float64Array,
    at: number,
    positions: number,
    scratch: Float64Array,
  ): void {
    const first = js.jFirst[j];
    const m = js.jBlock[j];
    const S = js.OFF_S;
    const rows = js.rows;
    for (let r = 0; r < m; r += 1) {
      const base = (first + r) * js.RS;
      if (positions === 1) {
        vec[at + r] = (js.layoutOk === 1 ? js.rowTarget[first + r] : 0) - rows[base + S + 6];
      } else {
        js.rowVelocityOf(sb, first + r, js.jA[j], js.jB[j], scratch, 0);
        vec[at + r] = -(scratch[0] + rows[base + S + 1]);
      }
    }
  }

  /** Takes the impulses of the solution: λ −= y for every tree row. */
  private takeImpulses(js: JointSolver): void {
    const vec = this.vec;
    const lambda = js.lambdaRow;
    for (let i = 0; i < this.nodeCount; i += 1) {
      const v0 = this.nV[i];
      if (this.nKind[i] === 1) {
        const j = this.nRef[i];
        const first = js.jFirst[j];
        for (let r = 0; r < js.jBlock[j]; r += 1) lambda[first + r] -= vec[v0 + r];
        continue;
      }
      let row = v0 + this.bs;
      for (let j = this.fold[i]; j >= 0; j = this.foldNext[j]) {
        const first = js.jFirst[j];
        for (let r = 0; r < js.jBlock[j]; r += 1) lambda[first + r] -= vec[row + r];
        row += js.jBlock[j];
      }
    }
  }

  /**
   * A pass of the solver over the forest: `solveVelocities`, unless no velocity of a tree body
   * changed since the last one of this factorisation (nothing else moved them: the rows are met
   * already, and a solve would only move λ by rounding).
   */
  passVelocities(js: JointSolver, sb: SolverBodies): void {
    if (this.treeJoints === 0) return;
    const { n, k, bs } = this;
    const V = sb.v;
    const W = sb.w;
    const saved = this.saved;
    if (this.savedOk === 1) {
      let same = 1;
      for (let i = 0, at = 0; i < this.nodeCount && same === 1; i += 1) {
        if (this.nKind[i] === 1) continue;
        const slot = this.nRef[i];
        for (let d = 0; d < n; d += 1) if (saved[at++] !== V[slot * n + d]) same = 0;
        for (let p = 0; p < k; p += 1) if (saved[at++] !== W[slot * k + p]) same = 0;
      }
      if (same === 1) return;
    }
    this.solveVelocities(js, sb);
    if (saved.length < this.nodeCount * bs) this.saved = growFloat64(this.saved, this.nodeCount * bs, 0);
    const out = this.saved;
    for (let i = 0, at = 0; i < this.nodeCount; i += 1) {
      if (this.nKind[i] === 1) continue;
      const slot = this.nRef[i];
      for (let d = 0; d < n; d += 1) out[at++] = V[slot * n + d];
      for (let p = 0; p < k; p += 1) out[at++] = W[slot * k + p];
    }
    this.savedOk = 1;
  }

  /** One exact velocity solve of every equality row of the forest (a pass of the solver). */
  solveVelocities(js: JointSolver, sb: SolverBodies): void {
    if (this.treeJoints === 0) return;
    if (this.factoredBy === BY_CHAIN) {
      this.chainSolve(js, sb, 0);
      return;
    }
    if (this.factoredBy === BY_BRANCH) {
      this.branchSolve(js, sb, 0);
      return;
    }
    // (the node fallback does not measure its change: the passes run on)
    js.sc[SC_CHANGED] = 1;
    this.rhs(js, sb, 0);
    this.solveVec();
    const { n, k } = this;
    const vec = this.vec;
    const V = sb.v;
    const W = sb.w;
    for (let i = 0; i < this.nodeCount; i += 1) {
      if (this.nKind[i] === 1) continue;
      const slot = this.nRef[i];
      const v0 = this.nV[i];
      for (let d = 0; d < n; d += 1) V[slot * n + d] += vec[v0 + d];
      for (let p = 0; p < k; p += 1) W[slot * k + p] += vec[v0 + n + p];
    }
    this.takeImpulses(js);
  }

  /**
   * One exact linearised position projection of the forest (after `build` and `factor` on rows
   * built from the current poses): each body moves by Δx and turns by Δθ such that J [Δx; Δθ] = −C.
   */
  solvePositions(js: JointSolver, sb: SolverBodies): void {
    if (this.treeJoints === 0) return;
    if (this.factoredBy === BY_CHAIN) {
      this.chainSolve(js, sb, 1);
      return;
    }
    if (this.factoredBy === BY_BRANCH) {
      this.branchSolve(js, sb, 1);
      return;
    }
    this.rhs(js, sb, 1);
    this.solveVec();
    const { n, k } = this;
    const vec = this.vec;
    const dx = js.pA;
    const dθ = js.ja;
    for (let i = 0; i < this.nodeCount; i += 1) {
      if (this.nKind[i] === 1) continue;
      const v0 = this.nV[i];
      for (let d = 0; d < n; d += 1) dx[d] = vec[v0 + d];
      for (let p = 0; p < k; p += 1) dθ[p] = vec[v0 + n + p];
      js.moveBody(sb.bodies[this.nRef[i]]!, dx, dθ);
    }
  }

  /**
   * The solve of `solveVelocities` (`positions` 0) or `solvePositions` (1) by the chain's
   * factorisation: Δλ from A Δλ = c, each body moved by M̃⁻¹ Jᵀ Δλ, and (velocities) λ += Δλ.
   */
  private chainSolve(js: JointSolver, sb: SolverBodies, positions: number): void {
    const c = this.chain;
    this.spaceRhs(js, sb, positions, c.count, c.pJoint, c.vec, c.vOff);
    if (positions === 0) this.changed(js, c.vec, c.vOff[c.count]);
    c.solve(this.bodyNodes);
    this.spaceApply(js, sb, positions, c.count, c.pJoint, c.vec, c.vOff, c.acc);
  }

  /**
   * `chainSolve` by the branching forest's joint-space factorisation (`branch`): a call site of
   * its own, so that each sees one class.
   */
  private branchSolve(js: JointSolver, sb: SolverBodies, positions: number): void {
    const c = this.branch;
    this.spaceRhs(js, sb, positions, c.count, c.pJoint, c.vec, c.vOff);
    if (positions === 0) this.changed(js, c.vec, c.vOff[c.count]);
    c.solve(this.bodyNodes);
    this.spaceApply(js, sb, positions, c.count, c.pJoint, c.vec, c.vOff, c.acc);
  }

  /**
   * Sets the solver's SC_CHANGED when a velocity solve moves some row by more than
   * `solverTolerance`: the exact solve changes each row's velocity by its whole c.
   */
  private changed(js: JointSolver, vec: Float64Array, count: number): void {
    const tol = js.sc[SC_SOLVE_TOL];
    for (let i = 0; i < count; i += 1) {
      if (Math.abs(vec[i]) > tol) {
        js.sc[SC_CHANGED] = 1;
        return;
      }
    }
  }

  /** c for each row of a joint-space solve (−(Ċ + bias) or target − C), joint by joint in its order. */
  private spaceRhs(
    js: JointSolver,
    sb: SolverBodies,
    positions: number,
    P: number,
    pJoint: Int32Array,
    vec: Float64Array,
    vOff: Int32Array,
  ): void {
    for (let p = 0; p < P; p += 1) this.rowsRhs(js, sb, pJoint[p], vec, vOff[p], positions, this.rowSpeed);
  }

  /**
   * What a joint-space solve left (Δλ in `vec`, each body node's M̃⁻¹ Jᵀ Δλ in `acc`) applied: the
   * bodies moved (`positions` 1), or λ += Δλ and v, ω += the change (0).
   */
  private spaceApply(
    js: JointSolver,
    sb: SolverBodies,
    positions: number,
    P: number,
    pJoint: Int32Array,
    vec: Float64Array,
    vOff: Int32Array,
    acc: Float64Array,
  ): void {
    const { n, k, bs } = this;
    const B = this.bodyNodes;
    if (positions === 1) {
      // A projection moves the poses only: its Δλ is no impulse (as the tree's `solvePositions`).
      const dx = js.pA;
      const dθ = js.ja;
      for (let i = 0; i < B; i += 1) {
        const a0 = bs * i;
        for (let d = 0; d < n; d += 1) dx[d] = acc[a0 + d];
        for (let p = 0; p < k; p += 1) dθ[p] = acc[a0 + n + p];
        js.moveBody(sb.bodies[this.nRef[i]]!, dx, dθ);
      }
      return;
    }
    const lambda = js.lambdaRow;
    for (let p = 0; p < P; p += 1) {
      const j = pJoint[p];
      const first = js.jFirst[j];
      const v = vOff[p];
      for (let r = 0; r < js.jBlock[j]; r += 1) lambda[first + r] += vec[v + r];
    }
    const V = sb.v;
    const W = sb.w;
    for (let i = 0; i < B; i += 1) {
      const slot = this.nRef[i];
      const a0 = bs * i;
      for (let d = 0; d < n; d += 1) V[slot * n + d] += acc[a0 + d];
      for (let p = 0; p < k; p += 1) W[slot * k + p] += acc[a0 + n + p];
    }
  }

  // ---- block LDLᵀ without pivoting, in place at mat[d0], s×s ----

  /**
   * The LDLᵀ of the symmetric block at d0 (its lower triangle and diagonal are read), left-looking
   * (Crout): 1 / d_j in `rdiag`, L_rj stored transposed in the upper triangle (at (j, r)), so the
   * lower triangle and the diagonal keep the block. The first `pos` pivots must be positive (a body's unknowns:
   * M plus what its children add, positive definite) and the rest negative (joint rows: minus
   * their Schur complement J D⁻¹ Jᵀ). Returns 1, or 0 when a pivot has the wrong sign or is not
   * clearly nonzero (LDL_TOLERANCE); the block, mirrored into the upper triangle, is then whole for the LU.
   */
  private ldlFactor(d0: number, s: number, pos: number, r0: number): number {
    const A = this.mat;
    const rd = this.rdiag; // d_j while factoring, 1 / d_j once done
    // A pivot is measured against what cancelled in it and against the block's largest diagonal
    // entry (a first pivot of rounding noise in a block of size 10 is no pivot).
    let big = 0;
    for (let j = 0; j < s; j += 1) big = Math.max(big, Math.abs(A[d0 + j * s + j]));
    for (let j = 0; j < s; j += 1) {
      let d = A[d0 + j * s + j];
      let size = big;
      for (let q = 0; q < j; q += 1) {
        const u = A[d0 + q * s + j];
        const t = u * u * rd[r0 + q];
        d -= t;
        size += Math.abs(t);
      }
      if (!(j < pos ? d > 0 : d < 0) || !(Math.abs(d) > size * LDL_TOLERANCE)) {
        // The lower triangle and the diagonal still hold the block: mirror it into the upper.
        for (let r = 1; r < s; r += 1) for (let c = 0; c < r; c += 1) A[d0 + c * s + r] = A[d0 + r * s + c];
        return 0;
      }
      rd[r0 + j] = d;
      for (let r = j + 1; r < s; r += 1) {
        let sum = A[d0 + r * s + j];
        for (let q = 0; q < j; q += 1) sum -= A[d0 + q * s + r] * A[d0 + q * s + j] * rd[r0 + q];
        A[d0 + j * s + r] = sum / d;
      }
    }
    for (let j = 0; j < s; j += 1) rd[r0 + j] = 1 / rd[r0 + j];
    return 1;
  }

  /**
   * X ← D⁻¹ X for the LDLᵀ at d0, X the s × m block at X[x0] (row-major; m = 1: a vector); its
   * 1 / d_j at rdiag[r0].
   */
  private ldlSolveColumns(d0: number, s: number, X: Float64Array, x0: number, m: number, r0: number): void {
    const A = this.mat;
    const rd = this.rdiag;
    for (let q = 0; q < s - 1; q += 1) {
      const xq = x0 + q * m;
      for (let r = q + 1, at = d0 + q * s + q + 1; r < s; r += 1, at += 1) {
        const f = A[at];
        if (f === 0) continue;
        const xr = x0 + r * m;
        for (let c = 0; c < m; c += 1) X[xr + c] -= f * X[xq + c];
      }
    }
    for (let r = s - 1; r >= 0; r -= 1) {
      const xr = x0 + r * m;
      const d = rd[r0 + r];
      for (let c = 0; c < m; c += 1) X[xr + c] *= d;
      for (let q = r + 1, at = d0 + r * s + r + 1; q < s; q += 1, at += 1) {
        const f = A[at];
        if (f === 0) continue;
        const xq = x0 + q * m;
        for (let c = 0; c < m; c += 1) X[xr + c] -= f * X[xq + c];
      }
    }
  }

  // ---- dense LU with complete pivoting, in place at mat[d0], s×s; pivots at piv[p0] (rows, cols) ----

  private luFactor(d0: number, s: number, p0: number): void {
    const A = this.mat;
    const piv = this.piv;
    // The tolerance is relative to the largest entry, which the first column's search finds (it
    // scans the whole block): set there, not by a scan of its own.
    let tol = 0;
    for (let c = 0; c < s; c += 1) {
      // Complete pivoting.
      let br = c;
      let bc = c;
      let best = -1;
      for (let r = c; r < s; r += 1) {
        for (let q = c; q < s; q += 1) {
          const v = Math.abs(A[d0 + r * s + q]);
          if (v > best) {
            best = v;
            br = r;
            bc = q;
          }
        }
      }
      if (c === 0) tol = (best > 0 ? best : 0) * PIVOT_TOLERANCE;
      piv[p0 + c] = br;
      piv[p0 + s + c] = bc;
      if (br !== c) {
        for (let q = 0; q < s; q += 1) {
          const t = A[d0 + c * s + q];
          A[d0 + c * s + q] = A[d0 + br * s + q];
          A[d0 + br * s + q] = t;
        }
      }
      if (bc !== c) {
        for (let r = 0; r < s; r += 1) {
          const t = A[d0 + r * s + c];
          A[d0 + r * s + c] = A[d0 + r * s + bc];
          A[d0 + r * s + bc] = t;
        }
      }
      const pv = A[d0 + c * s + c];
      if (!(Math.abs(pv) > tol)) {
        // The rest is (numerically) zero: those unknowns are dropped.
        for (let r = c; r < s; r += 1) for (let q = c; q < s; q += 1) A[d0 + r * s + q] = 0;
        for (let r = c + 1; r < s; r += 1) {
          piv[p0 + r] = r;
          piv[p0 + s + r] = r;
        }
        return;
      }
      for (let r = c + 1; r < s; r += 1) {
        const f = A[d0 + r * s + c] / pv;
        A[d0 + r * s + c] = f;
        if (f === 0) continue;
        for (let q = c + 1; q < s; q += 1) A[d0 + r * s + q] -= f * A[d0 + c * s + q];
      }
    }
  }

  /**
   * X ← D⁻¹ X for the LU at d0, X the s × m block at X[x0] (row-major; m = 1: a vector); dropped
   * unknowns get 0.
   */
  private luSolveColumns(d0: number, s: number, p0: number, X: Float64Array, x0: number, m: number): void {
    const A = this.mat;
    const piv = this.piv;
    for (let c = 0; c < s; c += 1) {
      const r = piv[p0 + c];
      if (r !== c) {
        const xc = x0 + c * m;
        const xr = x0 + r * m;
        for (let q = 0; q < m; q += 1) {
          const t = X[xc + q];
          X[xc + q] = X[xr + q];
          X[xr + q] = t;
        }
      }
    }
    // L y = b (unit lower).
    for (let r = 1; r < s; r += 1) {
      const xr = x0 + r * m;
      for (let q = 0; q < r; q += 1) {
        const f = A[d0 + r * s + q];
        const xq = x0 + q * m;
        for (let c = 0; c < m; c += 1) X[xr + c] -= f * X[xq + c];
      }
    }
    // U x = y.
    for (let r = s - 1; r >= 0; r -= 1) {
      const d = A[d0 + r * s + r];
      const xr = x0 + r * m;
      if (d === 0) {
        for (let c = 0; c < m; c += 1) X[xr + c] = 0;
        continue;
      }
      for (let q = r + 1; q < s; q += 1) {
        const f = A[d0 + r * s + q];
        const xq = x0 + q * m;
        for (let c = 0; c < m; c += 1) X[xr + c] -= f * X[xq + c];
      }
      for (let c = 0; c < m; c += 1) X[xr + c] = X[xr + c] / d;
    }
    // Column swaps, undone in reverse.
    for (let c = s - 1; c >= 0; c -= 1) {
      const q = piv[p0 + s + c];
      if (q !== c) {
        const xc = x0 + c * m;
        const xq = x0 + q * m;
        for (let k = 0; k < m; k += 1) {
          const t = X[xc + k];
          X[xc + k] = X[xq + k];
          X[xq + k] = t;
        }
      }
    }
  }
}
