/**
 * The joint solver: the rows of every joint of a world in one sub-step, in flat preallocated
 * storage, solved by sequential impulses interleaved with the contacts.
 *
 * A row is a direction d (n numbers, zero for an angular row) and two bivector Jacobians J_A, J_B
 * (k numbers each): its velocity is Ċ = d·(v_B − v_A) + J_B·ω_B − J_A·ω_A, and an impulse λ
 * changes v_B += λ d / m_B, ω_B += λ I_B⁻¹J_B (the opposite for A), as a contact row does.
 *
 * Each joint writes (see `Joint.buildRows`):
 * - a block of equality rows (the point's n rows, the locked planes, the locked axes, a rod),
 *   solved together every iteration: K = J M⁻¹ Jᵀ (m×m) is factored once per sub-step
 *   (Cholesky; a pivot below 1e-12 of the largest diagonal drops its row), and each iteration
 *   solves K Δ = −(Ċ + bias) exactly for the block, so a chain link meets its point constraint
 *   in one visit whatever the arms and the inertia (a sequential sweep would need many);
 * - then scalar rows: a motor (|λ| <= maxMotorTorque·h) and inequality rows (λ >= 0: hinge limits,
 *   rope, strut), solved one by one BEFORE the block (Box2D's order: motor, limits, point).
 *
 * Position error: soft rows use the soft step (`soft.ts`); rigid rows a Baumgarte bias
 * (constraintBias / h)·(|C| − constraintSlop)₊ per row, both clamped to constraintMaxBias (m/s or
 * rad/s). An inequality row with slack C > 0 only forbids closing it faster than C / h
 * (speculative, as contacts do).
 *
 * Accumulated impulses live in each joint (`Joint.lambda`, by a fixed key per row), so they
 * warm-start the next sub-step and survive `setAnchors`. After the iterations `store` writes
 * them back, computes the loads |λ_linear| / h and |λ_angular| / h (the motor excluded) and lists
 * the joints whose load passed their break force or torque.
 *
 * Doubles travel in Float64Arrays, never as arguments of calls that are not inlined: the step
 * allocates nothing.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import type { Body } from '../body.js';
import { MOTION_DYNAMIC, MOTION_STATIC } from '../body.js';
import { growFloat64, growInt32, isMoving } from '../contacts/contact-set.js';
import { STEP_H } from '../integrator/step-constants.js';
import type { Params } from '../params.js';
import type { SolverBodies } from '../solver/solver-bodies.js';
import { bivectorRotationInto, reverseInto } from './frames.js';
import { addGeometricLoad, invertSpd } from './joint-blocks.js';
import { JointTree } from './joint-tree.js';
import type { Joint } from './joint.js';
import {
  JS_BREAK_FORCE,
  JS_BREAK_TORQUE,
  JS_DAMPING,
  JS_ERROR,
  JS_FORCE,
  JS_H,
  JS_HERTZ,
  JS_STRETCH_COUNT,
  JS_STRETCH_LIMIT,
  JS_TORQUE,
} from './joint-slots.js';
import {
  SOFT_BIAS_RATE,
  SOFT_COUNT,
  SOFT_DAMPING,
  SOFT_H,
  SOFT_HERTZ,
  SOFT_IMPULSE_SCALE,
  SOFT_MASS_SCALE,
  softStep,
} from './soft.js';

/** Row kind: linear (counts toward breakForce). */
export const KIND_LINEAR = 0;
/** Row kind: angular (counts toward breakTorque). */
export const KIND_ANGULAR = 1;
/** Row kind: motor (counts toward nothing). */
export const KIND_MOTOR = 2;

/** Row type: equality, part of the joint's block. */
export const ROW_EQUAL = 0;
/** Row type: inequality, λ >= 0. */
export const ROW_INEQUAL = 1;
/** Row type: motor, λ in [lo, hi] with a target velocity. */
export const ROW_MOTOR = 2;

/** Scalar scratch of the solver (`JointSolver.sc`). */
export const SC_C = 0;
/** Lower bound of a motor row's impulse. */
export const SC_LO = 1;
/** Upper bound of a motor row's impulse. */
export const SC_HI = 2;
/** Target velocity of a motor row. */
export const SC_TARGET = 3;
/** The sub-step h (s). */
export const SC_H = 4;
const SC_BIAS = 5;
const SC_SLOP = 6;
const SC_MAX_BIAS = 7;
const SC_HERTZ = 8;
const SC_DAMPING = 9;
const SC_HERTZ_MAX = 10;
/** constraintTolerance: the shortest direction a joint accepts (m). */
export const SC_TOL = 12;
/** The impulse handed to applyRow (through the array: a double argument would be boxed). */
const SC_DL = 11;
/** constraintProjectionTolerance: the linear error at which the position projection stops (m). */
const SC_DONE = 13;
/** solverTolerance: a pass that changes no row's velocity by more ends the passes (m/s). */
export const SC_SOLVE_TOL = 14;
/** 1 when the last `pass` changed some row's velocity by more than SC_SOLVE_TOL, else 0. */
export const SC_CHANGED = 15;
const SC_COUNT = 16;

/** Gauss–Seidel passes of the end-of-sub-step velocity projection over the joints outside the tree. */
const VELOCITY_PROJECTION_PASSES = 3;

/**
 * The position projection runs its `iterations` passes, then more while a rigid equality row is
 * still off by more than this fraction of `constraintSlop`, up to `iterations` × the factor below.
 */
const POSITION_TOLERANCE = 0.01;
const POSITION_PASSES_FACTOR = 4;

/**
 * The position projection reuses the tree's factorisation while each pass leaves at most this
 * fraction of the residual of the pass before.
 */
const REUSE_RATE = 0.05;

/**
 * A projection pass that leaves a larger error than the pass before multiplies the geometric
 * stiffness of the tree's next factorisation by this (up to STIFFEN_MOST): more damping for a
 * Newton step that overshot, as Levenberg–Marquardt raises its damping. Without it a chain of
 * light links with a last link 10⁶ times heavier came apart at 1/60 (3D hinges, at step 28); a
 * projection whose every pass above the rounding floor (FLOOR_RESIDUAL) shrinks the error never
 * raises it, and keeps its results.
 */
const STIFFEN_GROWTH = 4;
const STIFFEN_MOST = 1024;

/** A residual this small (m or rad) is rounding: the position projection stops. */
const FINE_RESIDUAL = 2.5e-16;

/** Below this residual, a chord step that no longer shrinks it has met rounding: the projection stops. */
const FLOOR_RESIDUAL = 1e-12;

/**
 * A point row's residual within this many units in the last place of its anchors' coordinate is
 * rounding (at least FINE_RESIDUAL): after a chord step, the position projection stops there.
 */
const FLOOR_ULPS = 4;

/**
 * A chord step predicted to leave every row within its rounding floor, or taken from at most
 * STALL_RESIDUAL (m or rad; from there the floor stops a 1/REUSE_RATE-fold shrink), is likely the
 * last: the check after it builds its rows in full, for the velocity projection to keep.
 */
const STALL_RESIDUAL = 2e-14;

/** A rigid joint whose error ends a sub-step past this × constraintSlop is stretched. */
const STRETCH_FACTOR = 10;

/** Below this fraction of the largest diagonal a Cholesky pivot drops its row. */
const PIVOT_TOLERANCE = 1e-12;

/** The joint rows of one world. */
export class JointSolver {
  /** The dimension tables. */
  readonly D: Dims;
  /** Count of dimensions. */
  readonly n: number;
  /** Count of planes. */
  readonly k: number;
  /** Numbers per row. */
  readonly RS: number;
  /** Offsets in a row. */
  readonly OFF_JA: number;
  readonly OFF_JB: number;
  readonly OFF_MA: number;
  readonly OFF_MB: number;
  readonly OFF_S: number;

  /** Joints solved in this sub-step. */
  count = 0;
  joints: Joint[] = [];
  /** @internal */ jA = new Int32Array(16);
  /** @internal */ jB = new Int32Array(16);
  /** @internal */ jFirst = new Int32Array(16);
  /** @internal */ jBlock = new Int32Array(16);
  /** @internal */ jRows = new Int32Array(16);
  /** @internal */ jFactor = new Int32Array(16);
  /** @internal */ jSoft = new Int32Array(16);

  /** Rows of this sub-step. */
  rowCount = 0;
  /** Row data, RS numbers per row (see the module). */
  rows: Float64Array;
  /** @internal */ lambdaRow = new Float64Array(16);
  /**
   * @internal Per row: the error the position projection aims at in this sub-step,
   * C₀ − clamp(C₀, ±constraintMaxBias·h) (0 unless the error is beyond one sub-step's slide).
   */
  rowTarget = new Float64Array(16);
  /**
   * @internal Per row: the residual (m or rad) that is rounding for it, at least FINE_RESIDUAL: a
   * point row's is FLOOR_ULPS units in the last place of its anchors' coordinate (see `pointRows`).
   */
  rowFloor = new Float64Array(16);
  /** @internal Row count at prepare (the projection's rebuilt rows match it row for row). */
  prepRows = 0;
  /** @internal 1 while the rebuilt rows match the prepared ones (rowTarget applies). */
  layoutOk = 1;
  /**
   * @internal 1 while the position projection rebuilds rows for a chord step: only each row's C,
   * type and bounds are written, not its direction and Jacobians. A chord step reuses the tree's
   * factorisation and reads nothing of a row but C, so writing the Jacobians there is wasted work
   * (about half of building a point row); a pass that factors again rebuilds its rows in full.
   */
  errorsOnly = 0;
  private rowKind = new Int32Array(16);
  /** @internal Per row: its key in `Joint.lambda`. */
  rowKey = new Int32Array(16);
  private factor = new Float64Array(64);
  private factorSize = 0;
  /** 1/m_A + 1/m_B of the joint whose masses were computed last. */
  private blockMass = 0;

  /**
   * Rigid joints whose error at the end of the last sub-step passed the stretch threshold
   * (10 × constraintSlop, m or rad; see `Joint.stretched`).
   */
  stretchedCount = 0;
  /** Sum of `stretchedCount` over every sub-step solved so far. */
  stretchTotal = 0;

  /** Joints that broke in the last `store` (their count in `brokenCount`). */
  broken: Joint[] = [];
  brokenCount = 0;

  // ---- scratch the joint classes use to write rows (no allocation) ----
  /** Scalars handed to the row writers (SC_* indices). */
  readonly sc = new Float64Array(SC_COUNT);
  /** Row direction (n). */
  readonly dir: Float64Array;
  /** World anchors and arms (n each). */
  readonly pA: Float64Array;
  readonly pB: Float64Array;
  readonly armA: Float64Array;
  readonly armB: Float64Array;
  /** Bivector Jacobians of the next angular row (k each). */
  readonly ja: Float64Array;
  readonly jb: Float64Array;
  /** Rotors: the joint frames, the relative rotor, a temporary (r each). */
  readonly RJA: Float64Array;
  readonly RJB: Float64Array;
  readonly Q: Float64Array;
  readonly T: Float64Array;
  readonly U: Float64Array;
  /** Rotation matrix of the frame R_JA (n×n) and its bivector rotation (k×k). */
  readonly MJA: Float64Array;
  readonly rot: Float64Array;
  private readonly rotB: Float64Array;
  /** Gradient of the locked rotor components (k×k: row p = plane, column q). */
  readonly G: Float64Array;
  readonly gA: Float64Array;
  private readonly soft = new Float64Array(SOFT_COUNT);
  /** The direct solver of the rigid joints that form a forest. */
  private readonly tree: JointTree;
  private vecC: Float64Array;
  private vecX: Float64Array;
  /** Per joint: jFirst·65536 + jBlock when the tree was last factored in the projection. */
  private layoutBlock = new Int32Array(16);
  private layoutRows = -1;
  /** 1 while the tree holds the prepare's factorisation of this sub-step (the velocity passes keep it). */
  private prepTree = 0;
  /** Per solver slot: h·Σ|λ||J_angular| over its tree joints (scratch of `stiffenInertia`). */
  private slotLoad = new Float64Array(16);
  /** The slots `stiffenInertia` changed, and their inverse inertia before ((k² + 1) each: I⁻¹, then the scalar). */
  private stiffSlots = new Int32Array(16);
  private stiffSaved = new Float64Array(16);
  private stiffCount = 0;
  /** k × k scratch of `stiffenInertia`. */
  private readonly stiffBlk: Float64Array;
  /**
   * What `rigidResidual` measured: [0] the largest |C − target| of the rigid equality rows, [1]
   * that of their angular rows alone, [2] the largest |C − target| / `rowFloor` (at most 1: every
   * row at its rounding floor). Through an array: a double returned by a call V8 does not
   * inline is boxed (an allocation per call).
   */
  private residual = new Float64Array(3);
  /**
   * 1 while `rows` hold every joint's rows built in full by the position projection at the current
   * poses: the velocity projection then measures and keeps them instead of building them again.
   */
  private rowsFresh = 0;
  /**
   * @internal 1 when the last `pass` had nothing to solve but the tree's equality rows (no scalar
   * row, no Gauss–Seidel block): with no contact either, the tree's solve was exact and nothing
   * else moves a velocity, so every further pass would find its velocities unchanged and skip.
   */
  treeOnly = 0;
  /** Per solver slot: 1 once `solvePositions` brought the body's pose up to date. */
  private synced = new Int32Array(16);

  constructor(D: Dims) {
    const { n, k, r } = D;
    this.D = D;
    this.n = n;
    this.k = k;
    this.OFF_JA = n;
    this.OFF_JB = n + k;
    this.OFF_MA = n + 2 * k;
    this.OFF_MB = n + 3 * k;
    this.OFF_S = n + 4 * k;
    this.RS = n + 4 * k + 8;
    this.rows = new Float64Array(16 * this.RS);
    this.dir = new Float64Array(n);
    this.pA = new Float64Array(n);
    this.pB = new Float64Array(n);
    this.armA = new Float64Array(n);
    this.armB = new Float64Array(n);
    this.ja = new Float64Array(k);
    this.jb = new Float64Array(k);
    this.RJA = new Float64Array(r);
    this.RJB = new Float64Array(r);
    this.Q = new Float64Array(r);
    this.T = new Float64Array(r);
    this.U = new Float64Array(r);
    this.MJA = new Float64Array(n * n);
    this.rot = new Float64Array(k * k);
    this.rotB = new Float64Array(k * k);
    this.G = new Float64Array(k * k);
    this.gA = new Float64Array(k * k);
    this.stiffBlk = new Float64Array(k * k);
    this.tree = new JointTree(D);
    this.vecC = new Float64Array(n + k + 4);
    this.vecX = new Float64Array(n + k + 4);
  }

  // ---- prepare ----

  /**
   * Builds the rows of every joint with a moving body (waking a sleeping partner), gives their
   * bodies solver slots, factors the blocks and loads the warm-start impulses. Returns the count
   * of joints solved.
   */
  prepare(joints: readonly Joint[], sb: SolverBodies, stepConstants: Float64Array, p: Readonly<Params>): number {
    const h = stepConstants[STEP_H];
    const sc = this.sc;
    sc[SC_H] = h;
    sc[SC_BIAS] = p.constraintBias / h;
    sc[SC_SLOP] = p.constraintSlop;
    sc[SC_MAX_BIAS] = p.constraintMaxBias;
    sc[SC_HERTZ] = p.constraintHertz;
    sc[SC_DAMPING] = p.constraintDamping;
    sc[SC_HERTZ_MAX] = p.constraintHertzRatio / h;
    sc[SC_TOL] = p.constraintTolerance;
    sc[SC_DONE] = p.constraintProjectionTolerance;
    sc[SC_SOLVE_TOL] = p.solverTolerance;
    const warm = p.useWarmStart;
    // A sub-step that threw between stiffenInertia and restoreInertia leaves nothing to restore
    // into slots that now hold other bodies.
    this.stiffCount = 0;
    this.count = 0;
    this.rowCount = 0;
    this.factorSize = 0;
    this.brokenCount = 0;
    for (let i = 0; i < joints.length; i += 1) {
      const joint = joints[i];
      const A = joint.a;
      const B = joint.b;
      if (!isMoving(A) && (B === null || !isMoving(B))) continue;
      if (A.sleeping) A.wake();
      if (B !== null && B.sleeping) B.wake();
      const j = this.count;
      this.ensureJoints(j + 1);
      this.count = j + 1;
      this.joints[j] = joint;
      this.jA[j] = sb.slotOf(A);
      this.jB[j] = B === null ? 0 : sb.slotOf(B);
      this.jFirst[j] = this.rowCount;
      this.jBlock[j] = 0;
      this.jRows[j] = 0;
      joint.buildRows(this, j);
      this.finishJoint(j, warm);
    }
    this.prepRows = this.rowCount;
    const inTree = this.count > 0 ? this.tree.build(this, sb) : 0;
    // I⁻¹J and the effective masses of the rows a pass reads: a tree joint's equality rows are
    // the tree's, which reads neither (nor does its warm start, which skips them).
    for (let j = 0; j < this.count; j += 1) this.rowMasses(sb, j, this.tree.role[j] === 0 ? 0 : this.jBlock[j]);
    this.factorBlocks(sb);
    if (inTree > 0) {
      this.tree.stiffness = h;
      this.tree.factor(this, sb);
      this.tree.stiffness = 0;
    }
    // The layout the prepare's factorisation belongs to (the projection may reuse it, below).
    this.saveLayout();
    this.prepTree = inTree > 0 ? 1 : 0;
    return this.count;
  }

  /**
   * @internal Gives the solver bodies of the tree the inertia the tree's velocity solve uses: I_world
   * plus the geometric stiffness h·Σ|λ||J_angular| on the diagonal (see `JointTree.stiffness`), so
   * that the contacts (prepared again by the world) and the Gauss–Seidel rows solved in the same
   * passes see the same inverse inertia M̃⁻¹ as the tree. Each row's update is then a projection
   * in one metric, which no sequence of passes can make grow. With two metrics (the tree in M̃,
   * the contacts in M) the alternating passes are not a contraction: a 4D chain of 10 whipping
   * onto a floor gained energy every sub-step until it overflowed (docs/joints.md, "Contacts and
   * the geometric stiffness"). Call after `prepare`, before the warm start; `restoreInertia`
   * undoes it before the velocities are written back. Returns the count of slots changed.
   */
  stiffenInertia(sb: SolverBodies): number {
    this.stiffCount = 0;
    if (this.prepTree === 0) return 0;
    const k = this.k;
    const kk = k * k;
    const h = this.sc[SC_H];
    if (this.slotLoad.length < sb.count) this.slotLoad = growFloat64(this.slotLoad, sb.count);
    const g = this.slotLoad;
    g.fill(0, 0, sb.count);
    const role = this.tree.role;
    const im = sb.invMass;
    for (let j = 0; j < this.count; j += 1) {
      if (role[j] === 0) continue;
      const a = this.jA[j];
      const b = this.jB[j];
      if (im[a] > 0) addGeometricLoad(this, j, a, g, a);
      if (im[b] > 0) addGeometricLoad(this, j, b, g, b);
    }
    for (let s = 1; s < sb.count; s += 1) {
      const gi = g[s] * h;
      if (!(gi > 0)) continue;
      const c = this.stiffCount;
      this.stiffCount = c + 1;
      if (c >= this.stiffSlots.length) this.stiffSlots = growInt32(this.stiffSlots, c + 1);
      if ((c + 1) * (kk + 1) > this.stiffSaved.length) this.stiffSaved = growFloat64(this.stiffSaved, (c + 1) * (kk + 1));
      this.stiffSlots[c] = s;
      const saved = this.stiffSaved;
      const o = c * (kk + 1);
      const at = s * kk;
      for (let q = 0; q < kk; q += 1) saved[o + q] = sb.invInertia[at + q];
      const iso = sb.isoInvInertia[s];
      saved[o + kk] = iso;
      if (iso > 0) {
        // Still the same in every plane: 1/(I + g).
        const ni = 1 / (sb.inertia[at] + gi);
        sb.isoInvInertia[s] = ni;
        for (let r = 0; r < k; r += 1) sb.invInertia[at + r * k + r] = ni;
      } else {
        const blk = this.stiffBlk;
        for (let q = 0; q < kk; q += 1) blk[q] = sb.inertia[at + q];
        for (let r = 0; r < k; r += 1) blk[r * k + r] += gi;
        invertSpd(blk, k, sb.invInertia, at);
      }
    }
    if (this.stiffCount === 0) return 0;
    // The scalar and Gauss–Seidel rows of the joints on those bodies in the same metric as the tree.
    for (let j = 0; j < this.count; j += 1) {
      const a = this.jA[j];
      const b = this.jB[j];
      if (!(g[a] > 0) && !(g[b] > 0)) continue;
      const gs = role[j] === 0;
      this.rowMasses(sb, j, gs ? 0 : this.jBlock[j]);
      if (gs) this.factorBlock(j, this.jFactor[j]);
    }
    return this.stiffCount;
  }

  /** @internal Gives back the slots' own inverse inertia (undoes `stiffenInertia`). */
  restoreInertia(sb: SolverBodies): void {
    const kk = this.k * this.k;
    const saved = this.stiffSaved;
    for (let c = 0; c < this.stiffCount; c += 1) {
      const s = this.stiffSlots[c];
      const o = c * (kk + 1);
      for (let q = 0; q < kk; q += 1) sb.invInertia[s * kk + q] = saved[o + q];
      sb.isoInvInertia[s] = saved[o + kk];
    }
    this.stiffCount = 0;
  }

  private ensureJoints(need: number): void {
    if (need <= this.jA.length) return;
    this.jA = growInt32(this.jA, need);
    this.jB = growInt32(this.jB, need);
    this.jFirst = growInt32(this.jFirst, need);
    this.jBlock = growInt32(this.jBlock, need);
    this.jRows = growInt32(this.jRows, need);
    this.jFactor = growInt32(this.jFactor, need);
    this.jSoft = growInt32(this.jSoft, need);
  }

  private ensureRows(need: number): void {
    if (need <= this.lambdaRow.length) return;
    const keep = this.rowCount;
    this.rows = growFloat64(this.rows, need * this.RS, keep * this.RS);
    this.lambdaRow = growFloat64(this.lambdaRow, need, keep);
    this.rowTarget = growFloat64(this.rowTarget, need, keep);
    this.rowFloor = growFloat64(this.rowFloor, need, keep);
    this.rowKind = growInt32(this.rowKind, need, keep);
    this.rowKey = growInt32(this.rowKey, need, keep);
  }

  /**
   * Appends a row to joint j from the scratch: direction `dir` (linear rows; pass `linear` 1 to
   * form J_A = armA ∧ dir and J_B = armB ∧ dir, 0 for an angular row whose Jacobians are in
   * `ja`, `jb`), the position error sc[SC_C], and for a motor row sc[SC_LO], sc[SC_HI],
   * sc[SC_TARGET]. `key` indexes the joint's `lambda`. Equality rows must come first.
   */
  addRow(j: number, key: number, kind: number, type: number, linear: number): void {
    const { n, k, RS } = this;
    const row = this.rowCount;
    this.ensureRows(row + 1);
    this.rowCount = row + 1;
    this.jRows[j] += 1;
    if (type === ROW_EQUAL) this.jBlock[j] += 1;
    this.rowKind[row] = kind;
    this.rowKey[row] = key;
    this.rowFloor[row] = FINE_RESIDUAL;
    const rows = this.rows;
    const base = row * RS;
    const ja = base + this.OFF_JA;
    const jb = base + this.OFF_JB;
    if (this.errorsOnly === 1) {
      // A chord step of the position projection reads only C (see `errorsOnly`).
    } else if (linear === 1) {
      const dir = this.dir;
      const rA = this.armA;
      const rB = this.armB;
      const planeI = this.D.planeI;
      const planeJ = this.D.planeJ;
      for (let d = 0; d < n; d += 1) rows[base + d] = dir[d];
      for (let pl = 0; pl < k; pl += 1) {
        const pi = planeI[pl];
        const pj = planeJ[pl];
        const di = dir[pi];
        const dj = dir[pj];
        rows[ja + pl] = rA[pi] * dj - rA[pj] * di;
        rows[jb + pl] = rB[pi] * dj - rB[pj] * di;
      }
    } else {
      for (let d = 0; d < n; d += 1) rows[base + d] = 0;
      for (let pl = 0; pl < k; pl += 1) {
        rows[ja + pl] = this.ja[pl];
        rows[jb + pl] = this.jb[pl];
      }
    }
    const S = base + this.OFF_S;
    const sc = this.sc;
    rows[S + 6] = sc[SC_C];
    rows[S + 7] = type;
    rows[S + 4] = type === ROW_MOTOR ? sc[SC_LO] : 0;
    rows[S + 5] = type === ROW_MOTOR ? sc[SC_HI] : 0;
    rows[S + 1] = type === ROW_MOTOR ? -sc[SC_TARGET] : 0;
  }

  /**
   * The bias of each of joint j's rows and the warm-start impulses (I⁻¹J and the effective masses
   * follow the tree's build, in `prepare`).
   */
  private finishJoint(j: number, warm: boolean): void {
    const RS = this.RS;
    const first = this.jFirst[j];
    const count = this.jRows[j];
    const rows = this.rows;
    // Softness of this joint in this sub-step.
    const joint = this.joints[j];
    const st = joint.state;
    const sc = this.sc;
    const soft = this.soft;
    let hz = st[JS_HERTZ];
    if (hz !== hz) hz = sc[SC_HERTZ];
    if (hz > sc[SC_HERTZ_MAX]) hz = sc[SC_HERTZ_MAX];
    let zeta = st[JS_DAMPING];
    if (zeta !== zeta) zeta = sc[SC_DAMPING];
    soft[SOFT_HERTZ] = hz;
    soft[SOFT_DAMPING] = zeta;
    soft[SOFT_H] = sc[SC_H];
    softStep(soft);
    const isSoft = hz > 0;
    this.jSoft[j] = isSoft ? 1 : 0;
    const biasRate = soft[SOFT_BIAS_RATE];
    const ms = soft[SOFT_MASS_SCALE];
    const is = soft[SOFT_IMPULSE_SCALE];
    const beta = sc[SC_BIAS];
    const slop = sc[SC_SLOP];
    const maxBias = sc[SC_MAX_BIAS];
    const h = sc[SC_H];
    const lam = joint.lambda;
    const maxCorr = maxBias * h;
    for (let q = first; q < first + count; q += 1) {
      const S = q * RS + this.OFF_S;
      const C = rows[S + 6];
      const type = rows[S + 7];
      this.rowTarget[q] = C > maxCorr ? C - maxCorr : C < -maxCorr ? C + maxCorr : 0;
      let bias = 0;
      let rowMs = 1;
      let rowIs = 0;
      if (type === ROW_EQUAL) {
        if (isSoft) {
          bias = biasRate * C;
          rowMs = ms;
          rowIs = is;
        } else if (C > slop) {
          bias = beta * (C - slop);
        } else if (C < -slop) {
          bias = beta * (C + slop);
        }
        if (bias > maxBias) bias = maxBias;
        else if (bias < -maxBias) bias = -maxBias;
      } else if (type === ROW_INEQUAL) {
        rows[S + 4] = 0;
        rows[S + 5] = Infinity;
        if (C >= 0) {
          bias = C / h;
        } else if (isSoft) {
          bias = biasRate * C;
          rowMs = ms;
          rowIs = is;
          if (bias < -maxBias) bias = -maxBias;
        } else {
          bias = C + slop < 0 ? beta * (C + slop) : 0;
          if (bias < -maxBias) bias = -maxBias;
        }
      } else {
        bias = rows[S + 1];
      }
      rows[S + 1] = bias;
      rows[S + 2] = rowMs;
      rows[S + 3] = rowIs;
      let l0 = warm ? lam[this.rowKey[q]] : 0;
      if (type !== ROW_EQUAL) {
        if (l0 < rows[S + 4]) l0 = rows[S + 4];
        if (l0 > rows[S + 5]) l0 = rows[S + 5];
      }
      this.lambdaRow[q] = l0;
    }
  }

  /**
   * The Cholesky factor of the block of every joint the tree does not solve (after `tree.build`):
   * only the Gauss–Seidel passes read a block's factor, so the tree's joints skip it.
   */
  private factorBlocks(sb: SolverBodies): void {
    this.factorSize = 0;
    const im = sb.invMass;
    for (let j = 0; j < this.count; j += 1) {
      if (this.tree.role[j] !== 0) continue;
      const m = this.jBlock[j];
      this.blockMass = im[this.jA[j]] + im[this.jB[j]];
      this.jFactor[j] = this.factorSize;
      this.factorBlock(j, this.factorSize);
      this.factorSize += m * m;
    }
  }

  /**
   * I⁻¹J of joint j's rows from its row `skip` on and the effective mass of each (1 / J M⁻¹ Jᵀ, 0
   * if it cannot move).
   */
  private rowMasses(sb: SolverBodies, j: number, skip = 0): void {
    const { n, k, RS } = this;
    const a = this.jA[j];
    const b = this.jB[j];
    const imA = sb.invMass[a];
    const imB = sb.invMass[b];
    const IW = sb.invInertia;
    const IA = a * k * k;
    const IB = b * k * k;
    const first = this.jFirst[j];
    const count = this.jRows[j];
    const rows = this.rows;
    const OFF_JA = this.OFF_JA;
    const OFF_JB = this.OFF_JB;
    const OFF_MA = this.OFF_MA;
    const OFF_MB = this.OFF_MB;
    for (let q = first + skip; q < first + count; q += 1) {
      const base = q * RS;
      let K = 0;
      for (let d = 0; d < n; d += 1) K += rows[base + d] * rows[base + d];
      K *= imA + imB;
      for (let row = 0; row < k; row += 1) {
        let sa = 0;
        let sbv = 0;
        for (let col = 0; col < k; col += 1) {
          sa += IW[IA + row * k + col] * rows[base + OFF_JA + col];
          sbv += IW[IB + row * k + col] * rows[base + OFF_JB + col];
        }
        rows[base + OFF_MA + row] = sa;
        rows[base + OFF_MB + row] = sbv;
        K += sa * rows[base + OFF_JA + row] + sbv * rows[base + OFF_JB + row];
      }
      rows[base + this.OFF_S] = K > 0 ? 1 / K : 0;
    }
    this.blockMass = imA + imB;
  }

  /**
   * The block's K = J M⁻¹ Jᵀ (m×m), factored in place at `f0` of `factor` (Cholesky, lower
   * triangle, row-major); a pivot below PIVOT_TOLERANCE of the largest diagonal drops its row.
   */
  private factorBlock(j: number, f0: number): void {
    const { n, k, RS } = this;
    const m = this.jBlock[j];
    if (m === 0) return;
    const first = this.jFirst[j];
    const rows = this.rows;
    const OFF_JA = this.OFF_JA;
    const OFF_JB = this.OFF_JB;
    const OFF_MA = this.OFF_MA;
    const OFF_MB = this.OFF_MB;
    const im = this.blockMass;
    if (f0 + m * m > this.factor.length) this.factor = growFloat64(this.factor, f0 + m * m, f0);
    const F = this.factor;
    let maxDiag = 0;
    for (let r = 0; r < m; r += 1) {
      const br = (first + r) * RS;
      for (let c = 0; c <= r; c += 1) {
        const bc = (first + c) * RS;
        let s = 0;
        for (let d = 0; d < n; d += 1) s += rows[br + d] * rows[bc + d];
        s *= im;
        for (let pl = 0; pl < k; pl += 1) {
          s += rows[br + OFF_JA + pl] * rows[bc + OFF_MA + pl] + rows[br + OFF_JB + pl] * rows[bc + OFF_MB + pl];
        }
        F[f0 + r * m + c] = s;
      }
      if (F[f0 + r * m + r] > maxDiag) maxDiag = F[f0 + r * m + r];
    }
    const tol = maxDiag * PIVOT_TOLERANCE;
    for (let c = 0; c < m; c += 1) {
      let d = F[f0 + c * m + c];
      for (let q = 0; q < c; q += 1) d -= F[f0 + c * m + q] * F[f0 + c * m + q];
      if (!(d > tol)) {
        // A dependent row (or a body that cannot turn that way): dropped from the block.
        for (let r = c; r < m; r += 1) F[f0 + r * m + c] = 0;
        continue;
      }
      const L = Math.sqrt(d);
      F[f0 + c * m + c] = L;
      for (let r = c + 1; r < m; r += 1) {
        let s = F[f0 + r * m + c];
        for (let q = 0; q < c; q += 1) s -= F[f0 + r * m + q] * F[f0 + c * m + q];
        F[f0 + r * m + c] = s / L;
      }
    }
  }

  /** X = K⁻¹ C for the block factored at f0 (m rows); dropped rows get 0. */
  private solveBlock(f0: number, m: number): void {
    const F = this.factor;
    const C = this.vecC;
    const X = this.vecX;
    for (let r = 0; r < m; r += 1) {
      const L = F[f0 + r * m + r];
      if (L === 0) {
        X[r] = 0;
        continue;
      }
      let s = C[r];
      for (let q = 0; q < r; q += 1) s -= F[f0 + r * m + q] * X[q];
      X[r] = s / L;
    }
    for (let r = m - 1; r >= 0; r -= 1) {
      const L = F[f0 + r * m + r];
      if (L === 0) {
        X[r] = 0;
        continue;
      }
      let s = X[r];
      for (let q = r + 1; q < m; q += 1) s -= F[f0 + q * m + r] * X[q];
      X[r] = s / L;
    }
  }

  // ---- solve ----

  /** Applies the impulse sc[SC_DL] of row q between slots a (−) and b (+). */
  private applyRow(sb: SolverBodies, q: number, a: number, b: number): void {
    const { n, k, RS } = this;
    const dl = this.sc[SC_DL];
    const rows = this.rows;
    const V = sb.v;
    const W = sb.w;
    const base = q * RS;
    const la = dl * sb.invMass[a];
    const lb = dl * sb.invMass[b];
    for (let d = 0; d < n; d += 1) {
      const dir = rows[base + d];
      V[a * n + d] -= la * dir;
      V[b * n + d] += lb * dir;
    }
    const ia = base + this.OFF_MA;
    const ib = base + this.OFF_MB;
    for (let pl = 0; pl < k; pl += 1) {
      W[a * k + pl] -= dl * rows[ia + pl];
      W[b * k + pl] += dl * rows[ib + pl];
    }
  }

  /** @internal Ċ of row q into out[at]. */
  rowVelocityOf(sb: SolverBodies, q: number, a: number, b: number, out: Float64Array, at: number): void {
    this.rowVelocity(sb, q, a, b, out, at);
  }

  /** Ċ of row q. */
  private rowVelocity(sb: SolverBodies, q: number, a: number, b: number, out: Float64Array, at: number): void {
    const { n, k, RS } = this;
    const rows = this.rows;
    const V = sb.v;
    const W = sb.w;
    const base = q * RS;
    let v = 0;
    for (let d = 0; d < n; d += 1) v += rows[base + d] * (V[b * n + d] - V[a * n + d]);
    const ja = base + this.OFF_JA;
    const jb = base + this.OFF_JB;
    for (let pl = 0; pl < k; pl += 1) v += rows[jb + pl] * W[b * k + pl] - rows[ja + pl] * W[a * k + pl];
    out[at] = v;
  }

  /** Applies the warm-start impulses of every row. */
  warmStart(sb: SolverBodies): void {
    for (let j = 0; j < this.count; j += 1) {
      const a = this.jA[j];
      const b = this.jB[j];
      const first = this.jFirst[j];
      const last = first + this.jRows[j];
      // The equality rows of the tree start from 0: the tree solve is exact without a warm start,
      // and it solves with the stiffened inertia, which an impulse applied here would not see.
      let from = first;
      if (this.tree.role[j] !== 0) {
        from = first + this.jBlock[j];
        for (let q = first; q < from; q += 1) this.lambdaRow[q] = 0;
      }
      for (let q = from; q < last; q += 1) {
        const l = this.lambdaRow[q];
        if (l === 0) continue;
        this.sc[SC_DL] = l;
        this.applyRow(sb, q, a, b);
      }
    }
  }

  /**
   * One Gauss–Seidel pass over every joint: scalar rows (motor, limits), then the block; then the
   * tree's exact solve. Leaves in sc[SC_CHANGED] whether some row's velocity changed by more than
   * `solverTolerance` (a row moved by |Δλ|·K, K its inverse effective mass; a tree row by its
   * whole right-hand side): 0 means the velocities are a fixed point of the passes to it.
   */
  pass(sb: SolverBodies, scalars = 1): void {
    const RS = this.RS;
    const rows = this.rows;
    const lambda = this.lambdaRow;
    const C = this.vecC;
    const X = this.vecX;
    const tol = this.sc[SC_SOLVE_TOL];
    let work = 0;
    let changed = 0;
    for (let j = 0; j < this.count; j += 1) {
      const a = this.jA[j];
      const b = this.jB[j];
      const first = this.jFirst[j];
      const m = this.jBlock[j];
      const last = first + this.jRows[j];
      // Scalar rows.
      for (let q = first + m; q < last && scalars === 1; q += 1) {
        const S = q * RS + this.OFF_S;
        const mass = rows[S];
        if (mass === 0) continue;
        work = 1;
        this.rowVelocity(sb, q, a, b, C, 0);
        const old = lambda[q];
        let nl = old - mass * rows[S + 2] * (C[0] + rows[S + 1]) - rows[S + 3] * old;
        if (nl < rows[S + 4]) nl = rows[S + 4];
        if (nl > rows[S + 5]) nl = rows[S + 5];
        lambda[q] = nl;
        const dl = nl - old;
        if (dl === 0) continue;
        // |Δλ|·K > tol, as |Δλ| > tol·m_eff (no division).
        if (Math.abs(dl) > tol * mass) changed = 1;
        this.sc[SC_DL] = dl;
        this.applyRow(sb, q, a, b);
      }
      if (m === 0 || this.tree.role[j] !== 0) continue;
      work = 1;
      // The block: K Δ = −(Ċ + bias), soft-scaled.
      for (let r = 0; r < m; r += 1) {
        this.rowVelocity(sb, first + r, a, b, C, r);
        C[r] += rows[(first + r) * RS + this.OFF_S + 1];
      }
      this.solveBlock(this.jFactor[j], m);
      for (let r = 0; r < m; r += 1) {
        const q = first + r;
        const S = q * RS + this.OFF_S;
        const old = lambda[q];
        const dl = -rows[S + 2] * X[r] - rows[S + 3] * old;
        lambda[q] = old + dl;
        if (dl === 0) continue;
        if (Math.abs(dl) > tol * rows[S]) changed = 1;
        this.sc[SC_DL] = dl;
        this.applyRow(sb, q, a, b);
      }
    }
    this.treeOnly = work === 0 ? 1 : 0;
    this.sc[SC_CHANGED] = changed;
    // (the tree's solve sets SC_CHANGED when one of its rows moves by more than the tolerance)
    if (this.tree.treeJoints > 0 && scalars === 1) this.tree.passVelocities(this, sb);
  }

  /**
   * @internal 1 when the last `pass` changed some row's velocity by more than `solverTolerance`,
   * else 0 (the world then skips the passes left).
   */
  passChanged(): number {
    return this.sc[SC_CHANGED] === 0 ? 0 : 1;
  }

  /**
   * Writes the accumulated impulses back to the joints, their loads (N, N·m), and lists in
   * `broken` the joints whose load passed a break limit (the world removes them).
   */
  store(): void {
    const h = this.sc[SC_H];
    const lambda = this.lambdaRow;
    for (let j = 0; j < this.count; j += 1) {
      const joint = this.joints[j];
      const lam = joint.lambda;
      const first = this.jFirst[j];
      const last = first + this.jRows[j];
      let lin = 0;
      let ang = 0;
      for (let q = first; q < last; q += 1) {
        const l = lambda[q];
        lam[this.rowKey[q]] = l;
        const kind = this.rowKind[q];
        if (kind === KIND_LINEAR) lin += l * l;
        else if (kind === KIND_ANGULAR) ang += l * l;
      }
      const st = joint.state;
      st[JS_FORCE] = Math.sqrt(lin) / h;
      st[JS_TORQUE] = Math.sqrt(ang) / h;
      st[JS_H] = h;
      const bf = st[JS_BREAK_FORCE];
      const bt = st[JS_BREAK_TORQUE];
      if ((bf > 0 && st[JS_FORCE] > bf) || (bt > 0 && st[JS_TORQUE] > bt)) {
        if (this.brokenCount < this.broken.length) this.broken[this.brokenCount] = joint;
        else this.broken.push(joint);
        this.brokenCount += 1;
      }
    }
  }

  // ---- position projection ----

  /**
   * Position projection of the rigid joints after the positions were integrated (nonlinear
   * Gauss–Seidel, Box2D v2's "solve positions"): `iterations` passes in which each rigid joint
   * rebuilds its rows from the current poses and moves its bodies by the position impulse
   * Δ = −K⁻¹ C of its block (and, for a violated limit or rope, of that row), x += M⁻¹ Jᵀ Δ and
   * R ← exp(I⁻¹ J Δ) R. Velocities and L are not touched; ω is rebuilt from L under the new rotor.
   * Soft joints are skipped (their error is their spring).
   */
  solvePositions(sb: SolverBodies, iterations: number): void {
    if (this.count === 0) return;
    // The poses lag the integrated x and R until the world updates them: bring them up first, each
    // body once (a chain link belongs to two joints; its slot says whether it was done already).
    const K = this.D.kernels;
    if (this.synced.length < sb.count) this.synced = growInt32(this.synced, sb.count);
    const synced = this.synced;
    synced.fill(0, 0, sb.count);
    for (let j = 0; j < this.count; j += 1) {
      const joint = this.joints[j];
      const A = joint.a;
      const a = this.jA[j];
      if (A.motion !== MOTION_STATIC && !A.sleeping && synced[a] === 0) {
        synced[a] = 1;
        A.pose!.x.set(A.x);
        K.toMatrix(A.pose!.M, A.R);
      }
      const B = joint.b;
      const b = this.jB[j];
      if (B !== null && B.motion !== MOTION_STATIC && !B.sleeping && synced[b] === 0) {
        synced[b] = 1;
        B.pose!.x.set(B.x);
        K.toMatrix(B.pose!.M, B.R);
      }
    }
    const tolerance = POSITION_TOLERANCE * this.sc[SC_SLOP];
    // Once every angular row is at rounding, a linear residual within constraintProjectionTolerance
    // (0 at the defaults: rounding) ends the projection after a pass. Angular rows are still taken to
    // rounding: their error, −2⟨Q⟩_p, is ill-conditioned near a half turn (a 4D pin stopped at 1e-9
    // passed a 1e-12 angle error on to a w-plane spin that grew to 2e-3 rad/s at the step its
    // rotor's scalar part crossed 0). Below `tolerance` (1e-5 m) one pass is always taken, a Newton
    // step that takes a settling chain to rounding (skipped, errors of 1e-15 add up to 1e-9); a
    // tolerance at or above it also skips the projection when the sub-step left the error within it.
    const done = this.sc[SC_DONE];
    const first = done >= tolerance ? 0 : 1;
    const most = iterations * POSITION_PASSES_FACTOR;
    // The tree is factored at the first pass and its factorisation reused (a chord Newton step)
    // while the rows keep their layout and each pass shrinks the residual at least REUSE_RATE-fold;
    // a pass that converges slower, or a changed layout, factors again. Chord steps converge
    // linearly where Newton steps converge quadratically, so after a chord step the projection
    // stops only at the rounding floor (FINE_RESIDUAL, or no longer shrinking), never merely
    // within the tolerance: it ends as accurate as the Newton passes it replaces.
    let factored = 0;
    let chord = 0;
    let late = 0;
    let before = Infinity;
    // 1 when the next check is likely the last: its rows are built in full, and the velocity
    // projection takes them as they are instead of building them again (`rowsFresh`).
    let last = 0;
    // The factor on the geometric stiffness of the next factorisation (STIFFEN_GROWTH).
    let stiffen = 1;
    this.rowsFresh = 0;
    for (let it = 0; it < most; it += 1) {
      // Rows from the current poses (the impulses were stored already); after a factorisation,
      // C alone, for a chord step (a pass that factors again rebuilds them in full, below).
      this.buildProjectionRows(factored === 1 && last === 0 ? 1 : 0);
      this.rigidResidual();
      const residual = this.residual[0];
      // An error at the level of rounding ends the projection at once, and so does a linear error
      // within `done` with the angular rows at rounding (after `first` passes).
      // After a chord step, every row within its rounding floor (`rowFloor`) ends it too: the anchors
      // are computed to a few units in the last place of their coordinates, and one more step would
      // only reshuffle that rounding. Only after a chord step: an error never projected in this
      // sub-step stays held to FINE_RESIDUAL (a hanging rope of 100 links, 99.5 m long, keeps its
      // joints at 2.3e-16 m, below a unit in the last place of its coordinates).
      const floors = this.residual[2];
      const angularFine = this.residual[1] <= FINE_RESIDUAL;
      if (residual <= FINE_RESIDUAL || (chord === 1 && floors <= 1) || (angularFine && it >= first && residual <= done)) break;
      const canReuse = factored === 1 && this.sameLayout() === 1;
      // A chord step that no longer shrinks the error by REUSE_RATE: at the rounding floor, the
      // projection is done; above it, the tree is factored again.
      const stalled = chord === 1 && residual > REUSE_RATE * before;
      if (stalled && residual <= FLOOR_RESIDUAL) break;
      // Past the `iterations` passes, the projection goes on only while an error is left, or
      // while a chord step (cheap) still shrinks it; a chord step that stalls within the
      // tolerance gets one more Newton step (factored past the `iterations` passes) first.
      if (it >= iterations && residual <= tolerance && (canReuse === false || (stalled && late === 1))) break;
      const reuse = canReuse && (residual <= REUSE_RATE * before || (it >= iterations && residual <= tolerance));
      // (At the rounding floor a larger error is rounding, not an overshoot.)
      if (residual > before && residual > FLOOR_RESIDUAL && stiffen < STIFFEN_MOST) stiffen *= STIFFEN_GROWTH;
      const rate = residual / before;
      before = residual;
      last = 0;
      if (it === 0 && residual <= FLOOR_RESIDUAL && this.prepTree === 1 && this.sameLayout() === 1) {
        // An error this small (a settling chain: 1e-15) takes one step with the prepare's
        // factorisation, still in the tree, instead of a factorisation of its own: its Jacobians
        // are those of the start of the sub-step, but a step of 1e-12 cannot throw a body far,
        // and a pass that leaves more than the tolerance factors at the next pass.
        this.tree.solvePositions(this, sb);
        chord = 0;
      } else if (reuse) {
        this.tree.solvePositions(this, sb);
        chord = 1;
        // Chord steps converge linearly: at this rate the rows' next distance to their floors is about
        // floors × rate, and a check at the floors, or one that can no longer shrink 1/REUSE_RATE-fold,
        // ends the projection.
        if (floors * rate <= 1 || residual <= STALL_RESIDUAL) last = 1;
      } else {
        // A pass that factors again needs its rows in full, not C alone.
        if (this.errorsOnly === 1) this.buildProjectionRows(0);
        if (this.tree.build(this, sb) > 0) {
          // The tree is factored at the current poses (with the Jacobians of the start of the
          // sub-step, a whipping chain's projection diverges), with the geometric stiffness.
          this.tree.stiffness = this.sc[SC_H] * stiffen;
          this.tree.factor(this, sb, 0);
          this.tree.stiffness = 0;
          this.tree.solvePositions(this, sb);
          this.saveLayout();
          factored = 1;
          if (it >= iterations) late = 1;
        } else {
          factored = 0;
        }
        chord = 0;
      }
      // The Gauss–Seidel joints build their own rows, in full; one whose rows were all within their
      // rounding floors, or within STALL_RESIDUAL, when they were built at the start of this pass
      // is left (a step would only reshuffle that rounding: the grid's closing joints, which its
      // tree's steps keep at 1e-14 m). Those rows are from before the tree's step of this pass, so
      // a joint that step opens is caught by the check after the pass and projected in the next
      // one; after the last pass it waits for the next sub-step's projection.
      this.errorsOnly = 0;
      for (let j = 0; j < this.count; j += 1) {
        if (this.jSoft[j] === 0 && this.tree.role[j] === 0 && !this.joints[j].brokenFlag && this.offFloor(j) === 1) {
          this.projectJoint(sb, j);
        }
      }
      // The poses moved: the rows are not theirs any more.
      this.rowsFresh = 0;
    }
    this.errorsOnly = 0;
    // ω from L under the new rotors, once per jointed body (the slots `synced` marked).
    for (let s = 1; s < sb.count; s += 1) {
      const body = sb.bodies[s]!;
      if (synced[s] === 1 && body.motion === MOTION_DYNAMIC) body.omegaFromMomentum();
    }
    this.projectVelocities(sb);
  }

  /**
   * 1 when one of joint j's equality rows (just built) is off its target by more than its rounding
   * floor (`rowFloor`) and STALL_RESIDUAL (below which a step cannot shrink it 1/REUSE_RATE-fold),
   * or j has scalar rows (a limit the projection may push back); else 0.
   */
  private offFloor(j: number): number {
    const first = this.jFirst[j];
    const m = this.jBlock[j];
    if (this.jRows[j] !== m) return 1;
    const RS = this.RS;
    const rows = this.rows;
    const ok = this.layoutOk === 1;
    for (let q = first; q < first + m; q += 1) {
      const e = Math.abs(rows[q * RS + this.OFF_S + 6] - (ok ? this.rowTarget[q] : 0));
      if (e > this.rowFloor[q] && e > STALL_RESIDUAL) return 1;
    }
    return 0;
  }

  /**
   * Rebuilds the rows of every joint from the current poses for a pass of the position
   * projection: in full (`errorsOnly` 0), or only their C (1: a chord step reads nothing else).
   * Leaves `errorsOnly` as asked.
   */
  private buildProjectionRows(errorsOnly: number): void {
    this.errorsOnly = errorsOnly;
    this.rowsFresh = errorsOnly === 0 ? 1 : 0;
    this.rowCount = 0;
    this.factorSize = 0;
    for (let j = 0; j < this.count; j += 1) {
      this.jFirst[j] = this.rowCount;
      this.jBlock[j] = 0;
      this.jRows[j] = 0;
      if (this.joints[j].brokenFlag) continue;
      this.joints[j].buildRows(this, j);
    }
    this.layoutOk = this.rowCount === this.prepRows ? 1 : 0;
  }

  /** Records the row layout the tree was factored with (`sameLayout` compares against it). */
  private saveLayout(): void {
    if (this.layoutBlock.length < this.count) this.layoutBlock = growInt32(this.layoutBlock, this.count);
    for (let j = 0; j < this.count; j += 1) this.layoutBlock[j] = this.jFirst[j] * 65536 + this.jBlock[j];
    this.layoutRows = this.rowCount;
  }

  /** 1 when the rows just built have the layout of the last factorisation (`saveLayout`). */
  private sameLayout(): number {
    if (this.rowCount !== this.layoutRows) return 0;
    for (let j = 0; j < this.count; j += 1) if (this.layoutBlock[j] !== this.jFirst[j] * 65536 + this.jBlock[j]) return 0;
    return 1;
  }

  /**
   * The largest |C − target| over the equality rows of the rigid joints (rows just built): what
   * the position projection has left to remove, into `residual[0]`; the largest over the angular
   * rows alone into `residual[1]`; the largest of |C − target| / `rowFloor` into `residual[2]`.
   */
  private rigidResidual(): void {
    const RS = this.RS;
    const rows = this.rows;
    const ok = this.layoutOk === 1;
    const kind = this.rowKind;
    const floor = this.rowFloor;
    let worst = 0;
    let angular = 0;
    let floors = 0;
    for (let j = 0; j < this.count; j += 1) {
      if (this.jSoft[j] !== 0) continue;
      const first = this.jFirst[j];
      for (let q = first; q < first + this.jBlock[j]; q += 1) {
        const e = Math.abs(rows[q * RS + this.OFF_S + 6] - (ok ? this.rowTarget[q] : 0));
        if (e > worst) worst = e;
        if (kind[q] !== KIND_LINEAR && e > angular) angular = e;
        const f = e / floor[q];
        if (f > floors) floors = f;
      }
    }
    this.residual[0] = worst;
    this.residual[1] = angular;
    this.residual[2] = floors;
  }

  /**
   * Velocity projection at the end of the sub-step: the equality rows of the rigid joints,
   * rebuilt at the final poses with the final world inertia, get Ċ = 0 (the tree exactly, the
   * other rigid joints by `VELOCITY_PROJECTION_PASSES` block passes). v and L change by the
   * projection impulse (L += I Δω, so ω = I⁻¹L stays exact). It removes the velocity the
   * Baumgarte bias and the integration drift left along the constraint, so a locked plane or axis
   * keeps ω and v at 0 at the end of every step. Its impulses are not accumulated.
   */
  private projectVelocities(sb: SolverBodies): void {
    const { n, k } = this;
    this.stretchedCount = 0;
    // Current inertia and velocities into the slots of the joint bodies.
    for (let s2 = 1; s2 < sb.count; s2 += 1) {
      const body = sb.bodies[s2]!;
      if (body.motion !== MOTION_DYNAMIC || body.jointCount === 0) continue;
      this.refreshSlot(sb, s2, body);
    }
    // The rows the position projection ended with, when it built them in full at these poses, are
    // the rows built here (the same poses, the same numbers): kept, not built again.
    const keep = this.rowsFresh;
    this.rowsFresh = 0;
    const RS = this.RS;
    this.rowCount = 0;
    this.factorSize = 0;
    for (let j = 0; j < this.count; j += 1) {
      const from = this.jFirst[j];
      const block = this.jBlock[j];
      this.jFirst[j] = this.rowCount;
      const joint = this.joints[j];
      if (joint.brokenFlag || this.jSoft[j] !== 0) {
        this.jBlock[j] = 0;
        this.jRows[j] = 0;
        joint.state[JS_ERROR] = 0;
        continue;
      }
      if (keep === 1) {
        // Measured where they are, then the equality rows moved down over any skipped ones.
        const to = this.rowCount;
        this.jFirst[j] = from;
        this.measureStretch(j);
        if (to !== from) {
          this.rows.copyWithin(to * RS, from * RS, (from + block) * RS);
          this.rowKind.copyWithin(to, from, from + block);
          this.rowKey.copyWithin(to, from, from + block);
        }
        this.jFirst[j] = to;
        this.jBlock[j] = block;
        this.jRows[j] = block;
        this.rowCount = to + block;
      } else {
        this.jBlock[j] = 0;
        this.jRows[j] = 0;
        joint.buildRows(this, j);
        this.measureStretch(j);
      }
      // Scalar rows (motor, limits) take no part.
      this.rowCount = this.jFirst[j] + this.jBlock[j];
      this.jRows[j] = this.jBlock[j];
      for (let q = this.jFirst[j]; q < this.rowCount; q += 1) {
        const S = q * this.RS + this.OFF_S;
        this.rows[S + 1] = 0;
        this.rows[S + 2] = 1;
        this.rows[S + 3] = 0;
        this.lambdaRow[q] = 0;
      }
    }
    const inTree = this.tree.build(this, sb);
    // The joints outside the tree: I⁻¹J and their block factors (the tree needs neither).
    for (let j = 0; j < this.count; j += 1) if (this.tree.role[j] === 0 && this.jRows[j] > 0) this.rowMasses(sb, j);
    this.factorBlocks(sb);
    if (inTree > 0) {
      this.tree.stiffness = this.sc[SC_H];
      this.tree.factor(this, sb);
      this.tree.stiffness = 0;
      this.tree.solveVelocities(this, sb);
    }
    let gs = 0;
    for (let j = 0; j < this.count; j += 1) if (this.tree.role[j] === 0 && this.jBlock[j] > 0) gs += 1;
    // Fewer passes once one moves no row by more than `solverTolerance` (see `pass`).
    for (let it = 0; gs > 0 && it < VELOCITY_PROJECTION_PASSES; it += 1) {
      this.pass(sb, 0);
      if (this.sc[SC_CHANGED] === 0) break;
    }
    // Back to the bodies: v, and L += I (ω − ω_body), ω from L.
    for (let s2 = 1; s2 < sb.count; s2 += 1) {
      const body = sb.bodies[s2]!;
      if (body.motion !== MOTION_DYNAMIC || body.jointCount === 0) continue;
      const v = body.v;
      for (let d = 0; d < n; d += 1) v[d] = sb.v[s2 * n + d];
      const w = body.w;
      const L = body.L;
      const I = sb.inertia;
      const at = s2 * k * k;
      for (let r = 0; r < k; r += 1) {
        let dL = 0;
        for (let c = 0; c < k; c += 1) dL += I[at + r * k + c] * (sb.w[s2 * k + c] - w[c]);
        L[r] += dL;
      }
      body.omegaFromMomentum();
    }
  }

  /**
   * Joint j's error at the end of the sub-step, from its rows just built at the final poses: the
   * largest of |C| over its linear equality rows (m), |C| over its angular ones (rad) and the
   * violation of an inequality row (a rope longer than its rest, a hinge past a limit); past
   * 10 × constraintSlop the joint is stretched.
   */
  private measureStretch(j: number): void {
    const RS = this.RS;
    const rows = this.rows;
    const first = this.jFirst[j];
    let lin = 0;
    let ang = 0;
    let worst = 0;
    for (let q = first; q < first + this.jRows[j]; q += 1) {
      const S = q * RS + this.OFF_S;
      const C = rows[S + 6];
      const type = rows[S + 7];
      if (type === ROW_EQUAL) {
        if (this.rowKind[q] === KIND_LINEAR) lin += C * C;
        else ang += C * C;
      } else if (type === ROW_INEQUAL && -C > worst) {
        worst = -C;
      }
    }
    lin = Math.sqrt(lin);
    ang = Math.sqrt(ang);
    if (lin > worst) worst = lin;
    if (ang > worst) worst = ang;
    const st = this.joints[j].state;
    const limit = STRETCH_FACTOR * this.sc[SC_SLOP];
    st[JS_ERROR] = worst;
    st[JS_STRETCH_LIMIT] = limit;
    if (worst > limit) {
      st[JS_STRETCH_COUNT] += 1;
      this.stretchedCount += 1;
      this.stretchTotal += 1;
    }
  }

  /** The slot's v, ω and world inertia from the body's current state (after the positions moved). */
  private refreshSlot(sb: SolverBodies, slot: number, body: Body): void {
    const { n, k } = this;
    for (let d = 0; d < n; d += 1) sb.v[slot * n + d] = body.v[d];
    for (let p = 0; p < k; p += 1) sb.w[slot * k + p] = body.w[p];
    const inv = body.invInertia;
    const I = body.inertia;
    const at = slot * k * k;
    let iso = true;
    for (let q = 1; q < k; q += 1) if (inv[q] !== inv[0] || I[q] !== I[0]) iso = false;
    if (iso) {
      // As the solver bodies do (SolverBodies.worldInverseInertia): an isotropic body's world
      // inertia is its body inertia, exactly; so the next prepare finds the same input and the
      // tree keeps this factorisation (JointTree.sameInput).
      sb.invInertia.fill(0, at, at + k * k);
      sb.inertia.fill(0, at, at + k * k);
      for (let r = 0; r < k; r += 1) {
        sb.invInertia[at + r * k + r] = inv[0];
        sb.inertia[at + r * k + r] = I[0];
      }
      return;
    }
    const rot = this.rotB;
    bivectorRotationInto(this.D, rot, body.pose!.M);
    for (let r = 0; r < k; r += 1) {
      for (let c = r; c < k; c += 1) {
        let s2 = 0;
        let t = 0;
        for (let q = 0; q < k; q += 1) {
          const qq = rot[r * k + q] * rot[c * k + q];
          s2 += qq * inv[q];
          t += qq * I[q];
        }
        sb.invInertia[at + r * k + c] = s2;
        sb.invInertia[at + c * k + r] = s2;
        sb.inertia[at + r * k + c] = t;
        sb.inertia[at + c * k + r] = t;
      }
    }
  }

  private projectJoint(sb: SolverBodies, j: number): void {
    const { n, k, RS } = this;
    const saveRows = this.rowCount;
    const saveFirst = this.jFirst[j];
    const saveBlock = this.jBlock[j];
    const saveCount = this.jRows[j];
    this.jFirst[j] = saveRows;
    this.jBlock[j] = 0;
    this.jRows[j] = 0;
    const joint = this.joints[j];
    joint.buildRows(this, j);
    this.rowMasses(sb, j);
    const m = this.jBlock[j];
    const first = saveRows;
    const last = first + this.jRows[j];
    const f0 = this.factorSize;
    this.factorBlock(j, f0);
    const rows = this.rows;
    const S0 = this.OFF_S;
    const X = this.vecX;
    const C = this.vecC;
    const ok = this.layoutOk;
    const target = this.rowTarget;
    for (let r = 0; r < m; r += 1) C[r] = (ok === 1 ? target[saveFirst + r] : 0) - rows[(first + r) * RS + S0 + 6];
    this.solveBlock(f0, m);
    // Scalar rows: a violated inequality pushes back alone (motors do nothing here).
    for (let q = first + m; q < last; q += 1) {
      const S = q * RS + S0;
      const c = rows[S + 6];
      const t = ok === 1 ? target[saveFirst + q - first] : 0;
      X[q - first] = rows[S + 7] === ROW_INEQUAL && c < t ? (t - c) * rows[S] : 0;
    }
    const a = this.jA[j];
    const b = this.jB[j];
    const dxA = this.pA;
    const dxB = this.pB;
    const dA = this.ja;
    const dB = this.jb;
    dxA.fill(0);
    dxB.fill(0);
    dA.fill(0);
    dB.fill(0);
    for (let q = first; q < last; q += 1) {
      const dl = X[q - first];
      if (dl === 0) continue;
      const base = q * RS;
      for (let d = 0; d < n; d += 1) {
        dxA[d] -= dl * rows[base + d];
        dxB[d] += dl * rows[base + d];
      }
      for (let pl = 0; pl < k; pl += 1) {
        dA[pl] -= dl * rows[base + this.OFF_MA + pl];
        dB[pl] += dl * rows[base + this.OFF_MB + pl];
      }
    }
    this.rowCount = saveRows;
    this.jFirst[j] = saveFirst;
    this.jBlock[j] = saveBlock;
    this.jRows[j] = saveCount;
    this.movePose(sb, joint.a, a, dxA, dA);
    if (joint.b !== null) this.movePose(sb, joint.b, b, dxB, dB);
  }

  /** @internal x += dx, R ← exp(dθ) R, pose updated (a dynamic body). */
  moveBody(body: Body, dx: Float64Array, dθ: Float64Array): void {
    const x = body.x;
    for (let d = 0; d < this.n; d += 1) x[d] += dx[d];
    const K = this.D.kernels;
    K.exp(this.T, dθ, 1);
    K.mul(body.R, this.T, body.R);
    const pose = body.pose!;
    pose.x.set(x);
    K.toMatrix(pose.M, body.R);
  }

  /** x += dx / m (the slot's inverse mass), R ← exp(dθ) R, pose updated (dynamic bodies only). */
  private movePose(sb: SolverBodies, body: Body, slot: number, dx: Float64Array, dθ: Float64Array): void {
    if (body.motion !== MOTION_DYNAMIC) return;
    const im = sb.invMass[slot];
    const x = body.x;
    for (let d = 0; d < this.n; d += 1) x[d] += im * dx[d];
    const K = this.D.kernels;
    K.exp(this.T, dθ, 1);
    K.mul(body.R, this.T, body.R);
    const pose = body.pose!;
    pose.x.set(x);
    K.toMatrix(pose.M, body.R);
  }

  // ---- geometry helpers for the joint classes (no allocation) ----

  /**
   * World anchors pA, pB and arms armA = pA − x_A, armB = pB − x_B of joint j's bodies (for a
   * joint to the world pB is the anchor itself and armB is 0).
   */
  anchors(joint: Joint): void {
    const n = this.n;
    if (n === 3) {
      this.anchors3(joint);
      return;
    }
    const A = joint.a;
    const M = A.pose!.M;
    const la = joint.anchorA;
    const xA = A.x;
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += M[i * n + c] * la[c];
      this.armA[i] = s;
      this.pA[i] = xA[i] + s;
    }
    const B = joint.b;
    const lb = joint.anchorB;
    if (B === null) {
      for (let i = 0; i < n; i += 1) {
        this.armB[i] = 0;
        this.pB[i] = lb[i];
      }
      return;
    }
    const MB = B.pose!.M;
    const xB = B.x;
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += MB[i * n + c] * lb[c];
      this.armB[i] = s;
      this.pB[i] = xB[i] + s;
    }
  }

  /**
   * `anchors` in 3D, written out: the same products summed in the same order from 0 (so the same
   * numbers, signed zeros included), without the loops over n.
   */
  private anchors3(joint: Joint): void {
    const B = joint.b;
    arm3(joint.a.pose!.M, joint.anchorA, joint.a.x, this.armA, this.pA);
    if (B !== null) arm3(B.pose!.M, joint.anchorB, B.x, this.armB, this.pB);
    else
      for (let i = 0; i < 3; i += 1) {
        this.armB[i] = 0;
        this.pB[i] = joint.anchorB[i];
      }
  }

  /**
   * The n equality rows of a point constraint (keys key0 .. key0 + n − 1) from `anchors`:
   * C = pB − pA along each world axis.
   */
  pointRows(j: number, key0: number): void {
    const { n, k, RS } = this;
    const planeI = this.D.planeI;
    const planeJ = this.D.planeJ;
    const rA = this.armA;
    const rB = this.armB;
    const full = this.errorsOnly === 0;
    // `addRow` with dir = e_d, written out: the same products and differences (so the same
    // numbers, signed zeros included), without filling a direction and a call per row.
    for (let d = 0; d < n; d += 1) {
      const row = this.rowCount;
      this.ensureRows(row + 1);
      this.rowCount = row + 1;
      this.jRows[j] += 1;
      this.jBlock[j] += 1;
      this.rowKind[row] = KIND_LINEAR;
      this.rowKey[row] = key0 + d;
      const rows = this.rows;
      const base = row * RS;
      if (full && n === 3) {
        // 3D (planes xy, xz, yz; J_A at 3, J_B at 6): the same entries with the planes' axes as
        // constants, without the loops over n and k.
        const e0 = d === 0 ? 1 : 0;
        const e1 = d === 1 ? 1 : 0;
        const e2 = d === 2 ? 1 : 0;
        rows[base] = e0;
        rows[base + 1] = e1;
        rows[base + 2] = e2;
        rows[base + 3] = rA[0] * e1 - rA[1] * e0;
        rows[base + 4] = rA[0] * e2 - rA[2] * e0;
        rows[base + 5] = rA[1] * e2 - rA[2] * e1;
        rows[base + 6] = rB[0] * e1 - rB[1] * e0;
        rows[base + 7] = rB[0] * e2 - rB[2] * e0;
        rows[base + 8] = rB[1] * e2 - rB[2] * e1;
      } else if (full) {
        const ja = base + this.OFF_JA;
        const jb = base + this.OFF_JB;
        for (let e = 0; e < n; e += 1) rows[base + e] = e === d ? 1 : 0;
        for (let pl = 0; pl < k; pl += 1) {
          const pi = planeI[pl];
          const pj = planeJ[pl];
          const di = pi === d ? 1 : 0;
          const dj = pj === d ? 1 : 0;
          rows[ja + pl] = rA[pi] * dj - rA[pj] * di;
          rows[jb + pl] = rB[pi] * dj - rB[pj] * di;
        }
      }
      const S = base + this.OFF_S;
      const a = this.pA[d];
      const b = this.pB[d];
      rows[S + 6] = b - a;
      // C = p_B − p_A is computed to a few units in the last place of the larger coordinate.
      this.rowFloor[row] = Math.max(FLOOR_ULPS * Number.EPSILON * Math.max(Math.abs(a), Math.abs(b)), FINE_RESIDUAL);
      rows[S + 7] = ROW_EQUAL;
      rows[S + 4] = 0;
      rows[S + 5] = 0;
      rows[S + 1] = 0;
    }
  }

  /**
   * The joint frames R_JA = R_A·C_A and R_JB = R_B·C_B (R_B = 1 for the world), the matrix of R_JA
   * and its bivector rotation `rot`, and the relative rotor Q = R_JA~ R_JB. For a chord step
   * (`errorsOnly` 1) Q alone: the matrix and `rot` feed only the Jacobians.
   */
  frames(joint: Joint, CA: Float64Array, CB: Float64Array): void {
    const K = this.D.kernels;
    K.mul(this.RJA, joint.a.R, CA);
    if (joint.b === null) this.RJB.set(CB);
    else K.mul(this.RJB, joint.b.R, CB);
    if (this.errorsOnly === 0) {
      K.toMatrix(this.MJA, this.RJA);
      bivectorRotationInto(this.D, this.rot, this.MJA);
    }
    reverseInto(this.D, this.T, this.RJA);
    K.mul(this.Q, this.T, this.RJB);
  }

  /**
   * Equality rows that hold the rotor components of the planes listed in `planes` (indices into
   * the frame's planes) at 0, with the exact gradient of those components, so the rows hold at
   * any angle and the free planes (two or more of them, even ones that do not commute) put no
   * drift into the locked ones. `worldFrame` 0: Q = R_JA~ R_JB (planes of a's frame),
   * Ċ_p = Σ_q Ω_q ⟨e_q Q⟩_p with Ω the relative angular velocity in a's frame; 1: W = R_JB R_JA~
   * (planes of the world), Ċ_p = Σ_q ω_B,q ⟨e_q W⟩_p − ω_A,q ⟨W e_q⟩_p. C_p = −2⟨·⟩_p, the
   * angle for small errors. Call `frames` first. Keys key0 + index in `planes`.
   */
  lockedPlaneRows(j: number, planes: Int32Array, worldFrame: number, key0: number): void {
    const { k } = this;
    const r = this.D.r;
    const mulIndex = this.D.mulIndex;
    const mulSign = this.D.mulSign;
    const Q = this.Q;
    if (worldFrame === 1) {
      // W = R_JB R_JA~ (T holds R_JA~ after frames()).
      this.D.kernels.mul(Q, this.RJB, this.T);
    }
    if (Q[0] < 0) for (let c = 0; c < r; c += 1) Q[c] = -Q[c];
    if (this.errorsOnly === 1) {
      // A chord step reads only C: the gradient is not needed (see `errorsOnly`).
      for (let i = 0; i < planes.length; i += 1) {
        this.sc[SC_C] = -2 * Q[1 + planes[i]];
        this.addRow(j, key0 + i, KIND_ANGULAR, ROW_EQUAL, 0);
      }
      return;
    }
    const G = this.G;
    const gA = this.gA;
    G.fill(0);
    gA.fill(0);
    for (let q = 0; q < k; q += 1) {
      const e = 1 + q;
      for (let c = 0; c < r; c += 1) {
        const qc = Q[c];
        if (qc === 0) continue;
        const left = mulIndex[e * r + c];
        if (left >= 1 && left <= k) G[(left - 1) * k + q] += mulSign[e * r + c] * qc;
        if (worldFrame === 1) {
          const right = mulIndex[c * r + e];
          if (right >= 1 && right <= k) gA[(right - 1) * k + q] += mulSign[c * r + e] * qc;
        }
      }
    }
    const rot = this.rot;
    for (let i = 0; i < planes.length; i += 1) {
      const p = planes[i];
      if (worldFrame === 1) {
        for (let q = 0; q < k; q += 1) {
          this.jb[q] = G[p * k + q];
          this.ja[q] = gA[p * k + q];
        }
      } else {
        for (let row = 0; row < k; row += 1) {
          let s = 0;
          for (let q = 0; q < k; q += 1) s += rot[row * k + q] * G[p * k + q];
          this.ja[row] = s;
          this.jb[row] = s;
        }
      }
      this.sc[SC_C] = -2 * Q[1 + p];
      this.addRow(j, key0 + i, KIND_ANGULAR, ROW_EQUAL, 0);
    }
  }

  /** Sets `ja` = `jb` = the world bivector of plane p of the frame R_JA (column p of `rot`), times `sign`. */
  framePlane(p: number, sign: number): void {
    const k = this.k;
    const rot = this.rot;
    for (let row = 0; row < k; row += 1) {
      const v = sign * rot[row * k + p];
      this.ja[row] = v;
      this.jb[row] = v;
    }
  }
}

/** arm = M l and p = x + arm in 3D, each sum from 0 in the order of `anchors` (the same numbers). @internal */
function arm3(M: Float64Array, l: Float64Array, x: Float64Array, arm: Float64Array, p: Float64Array): void {
  for (let i = 0; i < 3; i += 1) {
    const s = 0 + M[3 * i] * l[0] + M[3 * i + 1] * l[1] + M[3 * i + 2] * l[2];
    arm[i] = s;
    p[i] = x[i] + s;
  }
}
