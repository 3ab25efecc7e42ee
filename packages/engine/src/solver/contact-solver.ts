/**
 * The contact solver: sequential impulses on the manifolds of one sub-step, in n dimensions.
 *
 * Each manifold point gives one row along the normal (a non-negative impulse). Friction is one
 * patch per manifold (PhysX's patch friction, Box2D v2's friction anchor): n − 1 tangent rows at
 * the centroid c of the manifold's points, and (n−1)(n−2)/2 twist rows, one per plane of the
 * tangent space, that resist spinning about the normal. The tangent impulse vector is clamped to
 * the disc |P_t| <= μ Σλ_n (a circular cone in any n) and the twist bivector to
 * |P_w| <= μ Σλ_n·R, R the mean distance of the points from c. A row along the unit direction d
 * at arms r_A, r_B has the angular Jacobians J = r ∧ d (bivectors), the effective mass
 * 1 / (1/m_A + 1/m_B + J_A·I_A⁻¹J_A + J_B·I_B⁻¹J_B), and an impulse λ changes
 * v_B += λ d/m_B, ω_B += λ I_B⁻¹J_B (the opposite for A); a twist row has no linear part and
 * J_A = J_B = t_i ∧ t_j. The momentum follows at the end as L_B += I_B Δω_B = Σ λ J_B.
 *
 * The pass order, Box2D's with Guendelman's shock propagation:
 * 1. prepare: rows, effective masses, the normal velocity before the solve, the velocity target of
 *    each point (Baumgarte for overlap beyond `penetrationSlop`, the speculative s/h for a gap);
 * 2. warm start: the impulses of the last sub-step (normal ones matched by feature id, the patch
 *    kept per pair) applied again;
 * 3. `iterations` Gauss–Seidel passes: per manifold, friction patch then normals;
 * 4. shock propagation (`shockIterations` passes, ground up): in a contact between layers, the
 *    lower body acts as infinitely heavy, so a stack cannot push its base down; the contacts of
 *    a body with the layer below are swept together;
 * 5. restitution: touching points that approached faster than `restitutionThreshold` are given
 *    the bounce velocity e·|v_n| (a speculative stop records v_n and bounces one sub-step later).
 *
 * Data live in flat Float64Arrays that grow by doubling; a sub-step allocates nothing.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import type { Body } from '../body.js';
import type { ContactSet } from '../contacts/contact-set.js';
import { MOTION_DYNAMIC } from '../body.js';
import { CONTACT_ACTIVE, growFloat64, growInt32 } from '../contacts/contact-set.js';
import { STEP_H } from '../integrator/step-constants.js';
import type { Params } from '../params.js';
import type { SolverBodies } from './solver-bodies.js';

/** The numbers of one sub-step the solver reads (kept in an array: no boxed doubles). */
export const SOLVE_H = 0;
export const SOLVE_BIAS = 1;
export const SOLVE_SLOP = 2;
export const SOLVE_THRESHOLD = 3;
/** The impulse handed to `apply` (through the array: a double argument would be boxed). */
const SOLVE_LAMBDA = 4;
/** `solverTolerance` (m/s): a pass or inner sweep that changes no row's velocity more ends early. */
export const SOLVE_TOLERANCE = 5;
/** Largest change of a row's velocity, |Δλ|·K, since it was last reset (m/s). */
export const SOLVE_CHANGE = 6;
/**
 * Inner sweeps over the contacts of one body with the layer below it in a shock pass (at most:
 * see SOLVE_TOLERANCE).
 */
const SHOCK_INNER_SWEEPS = 3;
/**
 * Layers from the ground (see {@link ContactSolver.shockPropagate}) from which the contacts form a
 * *tall* stack: `iterations` passes (10) then cannot carry the load from the ground to the top,
 * and the shock passes do most of the work. There they sweep the contacts of each body with the
 * layer below up to TALL_INNER_SWEEPS times, and most of their impulses stay out of the warm start.
 */
const TALL_LAYERS = 12;
/**
 * Inner sweeps over the contacts of one body with the layer below in a shock pass of a tall stack
 * (at most). A box of a pyramid rests on two: with 8 the pyramid of 40 rows slid apart after
 * about 10 s, with 16 it stands (see {@link ContactSolver.shockPropagate}).
 */
const TALL_INNER_SWEEPS = 16;
/**
 * The share of a tall stack's shock impulses that the warm start leaves out (see
 * {@link ContactSolver.shockPropagate}). With all of it (1) the columns stand as well, but the
 * passes reach the early exit later.
 */
const SHOCK_LEFT_OUT = 0.8;
/** Sweeps over the bouncing points of one manifold in the restitution pass (at most). */
const RESTITUTION_SWEEPS = 32;

/** Sequential-impulse solver of the contacts of one world. */
export abstract class ContactSolver {
  protected readonly D: Dims;
  protected readonly n: number;
  protected readonly k: number;
  /** Tangent rows of a patch: n − 1. */
  protected readonly m: number;
  /** Twist rows of a patch: the planes of the tangent space, (n−1)(n−2)/2. */
  protected readonly q: number;
  /** Rows of a patch: m + q. */
  protected readonly PR: number;
  /** Numbers per row: dir (n), J_A, J_B, I_A⁻¹J_A, I_B⁻¹J_B (k each), mass, K_A, K_B. */
  protected readonly RS: number;

  /** Normal passes the last `solve` ran (at most `iterations`; see `Params.solverTolerance`). @internal */
  passesRun = 0;

  /** Manifolds of this sub-step. */
  protected mfCount = 0;
  protected mfContact = new Int32Array(16);
  protected mfA = new Int32Array(16);
  protected mfB = new Int32Array(16);
  protected mfFirst = new Int32Array(16);
  protected mfPoints = new Int32Array(16);
  protected mfFriction = new Float64Array(16);
  protected mfRestitution = new Float64Array(16);
  /** Twist radius R of each patch: the mean distance of its points from their centroid. */
  protected mfRadius = new Float64Array(16);
  /**
   * Manifold order of the shock passes: lowest layer first, and in a layer the manifolds of one
   * upper body together (see {@link ContactSolver.shockPropagate}).
   */
  private shockOrder = new Int32Array(16);
  /** The upper body of each manifold of `shockOrder`, at the same place: a run of one is a group. */
  private shockUpper = new Int32Array(16);
  /** The manifolds in order of their upper body (the first of the two sorts of shockPropagate). */
  private byUpper = new Int32Array(16);
  /** The upper body of each manifold, by manifold index (see {@link ContactSolver.upperBody}). */
  private mfUpper = new Int32Array(16);
  private layerCount = new Int32Array(16);
  private upperCount = new Int32Array(16);
  /** The friction patch rows, PR per manifold. */
  protected patchRows: Float64Array;
  /** Accumulated tangent impulses (m per manifold) and twist impulses (q per manifold). */
  protected lambdaP: Float64Array;
  protected lambdaW: Float64Array;
  /**
   * The impulses the shock passes of this sub-step added, which `store` leaves out of the warm
   * start (see {@link ContactSolver.shockPropagate}).
   */
  protected keptP: Float64Array;
  protected keptW: Float64Array;
  protected keptN = new Float64Array(16);
  /** Whether the kept* arrays hold this sub-step's shock impulses. */
  protected shocked = false;
  /** Whether this sub-step's shock passes are those of a tall stack (see TALL_LAYERS). */
  protected tallShock = false;

  /** Points of this sub-step. */
  protected cpCount = 0;
  /** The normal rows, one per point. */
  protected rows: Float64Array;
  protected target = new Float64Array(16);
  protected vn0 = new Float64Array(16);
  /**
   * Per point: the approach a speculative stop records for the next sub-step's bounce (see
   * `restitution`), in the units of vn0 (the bounce sets the normal velocity to −e times it).
   */
  protected vnStop = new Float64Array(16);
  /** Per point: the gap (the shared prepare sets it, and vn0, vnStop, bounceGap, only if e != 0). */
  protected sep = new Float64Array(16);
  /**
   * Per point: the largest gap from which it bounces in this sub-step: `penetrationSlop` for a
   * point a speculative stop brought to the surface in the last sub-step, else 0 (a point still
   * apart is stopped at the surface first and bounces from there one sub-step later).
   */
  protected bounceGap = new Float64Array(16);
  protected lambdaN = new Float64Array(16);
  /** Per point: the largest normal impulse of the sub-step (read, and in 3D kept, only if e != 0). */
  protected maxLambda = new Float64Array(16);

  protected readonly constants = new Float64Array(7);
  protected readonly tangents: Float64Array;
  protected readonly tmp: Float64Array;
  protected readonly rA: Float64Array;
  protected readonly rB: Float64Array;
  protected readonly centre: Float64Array;

  constructor(D: Dims, gravity: Float64Array) {
    this.D = D;
    this.n = D.n;
    this.k = D.k;
    this.m = D.n - 1;
    this.q = ((D.n - 1) * (D.n - 2)) / 2;
    this.PR = this.m + this.q;
    this.RS = D.n + 4 * D.k + 3;
    this.rows = new Float64Array(16 * this.RS);
    this.patchRows = new Float64Array(16 * this.PR * this.RS);
    this.lambdaP = new Float64Array(16 * this.m);
    this.lambdaW = new Float64Array(16 * Math.max(1, this.q));
    this.keptP = new Float64Array(16 * this.m);
    this.keptW = new Float64Array(16 * Math.max(1, this.q));
    this.tangents = new Float64Array(this.m * D.n);
    this.tmp = new Float64Array(Math.max(this.m, this.q, 1));
    this.rA = new Float64Array(D.n);
    this.rB = new Float64Array(D.n);
    this.centre = new Float64Array(D.n);
    this.gravity = gravity;
  }

  /**
   * The world's gravity (n numbers): the world's own array, shared, so it is never copied and never
   * stale. Restitution reads the relative normal acceleration of a contact (gravity and applied
   * forces) to find the approach speed at the moment of impact (see `restitution`).
   * @internal
   */
  readonly gravity: Float64Array;

  /** Count of contact points in the last sub-step's solve. */
  get pointCount(): number {
    return this.cpCount;
  }

  protected ensureManifolds(need: number): void {
    if (need <= this.mfContact.length) return;
    const keep = this.mfCount;
    this.mfContact = growInt32(this.mfContact, need);
    this.mfA = growInt32(this.mfA, need);
    this.mfB = growInt32(this.mfB, need);
    this.mfFirst = growInt32(this.mfFirst, need);
    this.mfPoints = growInt32(this.mfPoints, need);
    this.mfFriction = growFloat64(this.mfFriction, need);
    this.mfRestitution = growFloat64(this.mfRestitution, need);
    this.mfRadius = growFloat64(this.mfRadius, need);
    this.shockOrder = growInt32(this.shockOrder, need);
    this.shockUpper = growInt32(this.shockUpper, need);
    this.byUpper = growInt32(this.byUpper, need);
    this.mfUpper = growInt32(this.mfUpper, need);
    this.patchRows = growFloat64(this.patchRows, need * this.PR * this.RS, keep * this.PR * this.RS);
    this.lambdaP = growFloat64(this.lambdaP, need * this.m, keep * this.m);
    this.lambdaW = growFloat64(this.lambdaW, need * Math.max(1, this.q), keep * this.q);
    this.keptP = growFloat64(this.keptP, need * this.m, 0);
    this.keptW = growFloat64(this.keptW, need * Math.max(1, this.q), 0);
  }

  protected ensurePoints(need: number): void {
    if (need <= this.target.length) return;
    const keep = this.cpCount;
    this.rows = growFloat64(this.rows, need * this.RS, keep * this.RS);
    this.target = growFloat64(this.target, need, keep);
    this.vn0 = growFloat64(this.vn0, need, keep);
    this.vnStop = growFloat64(this.vnStop, need, keep);
    this.sep = growFloat64(this.sep, need, keep);
    this.bounceGap = growFloat64(this.bounceGap, need, keep);
    this.lambdaN = growFloat64(this.lambdaN, need, keep);
    this.keptN = growFloat64(this.keptN, need, 0);
    this.maxLambda = growFloat64(this.maxLambda, need, keep);
  }

  /**
   * Builds the rows of every active manifold with points. Sleeping bodies met here are woken (an
   * awake body reached them). `maxContacts` > 0 stops adding manifolds once that many points are
   * in. The sub-step h is read from `stepConstants[STEP_H]`. Returns the count of points.
   */
  prepare(contacts: ContactSet, sb: SolverBodies, stepConstants: Float64Array, p: Readonly<Params>): number {
    this.shocked = false;
    const { n, k, m, q, PR, RS } = this;
    const c = this.constants;
    const h = stepConstants[STEP_H];
    c[SOLVE_H] = h;
    c[SOLVE_BIAS] = p.biasFactor / h;
    c[SOLVE_SLOP] = p.penetrationSlop;
    c[SOLVE_THRESHOLD] = p.restitutionThreshold;
    c[SOLVE_TOLERANCE] = p.solverTolerance;
    const warm = p.useWarmStart;
    const maxPoints = p.maxContacts;
    const P = contacts.pointCapacity;
    const tangents = this.tangents;
    const rA = this.rA;
    const rB = this.rB;
    const centre = this.centre;
    const bias = c[SOLVE_BIAS];
    const slop = c[SOLVE_SLOP];
    const normalImpulse = contacts.normalImpulse;
    const patchTangent = contacts.patchTangent;
    const patchTwist = contacts.patchTwist;
    this.mfCount = 0;
    this.cpCount = 0;
    for (let i = 0; i < contacts.count; i += 1) {
      const slot = contacts.order[i];
      if (!(contacts.flags[slot] & CONTACT_ACTIVE)) continue;
      const man = contacts.manifolds[slot];
      const count = man.count;
      if (count === 0) continue;
      if (maxPoints > 0 && this.cpCount + count > maxPoints) break;
      const A = contacts.bodyA[slot] as Body;
      const B = contacts.bodyB[slot] as Body;
      if (A.sleeping) A.wake();
      if (B.sleeping) B.wake();
      const a = sb.slotOf(A);
      const b = sb.slotOf(B);
      this.ensureManifolds(this.mfCount + 1);
      this.ensurePoints(this.cpCount + count);
      // The arrays in locals: the calls below (buildRow) would make each `this.` load again.
      const rows = this.rows;
      const target = this.target;
      const sep = this.sep;
      const lambdaN = this.lambdaN;
      const maxLambda = this.maxLambda;
      const pts = man.points;
      const seps = man.separations;
      const mf = this.mfCount++;
      this.mfContact[mf] = slot;
      this.mfA[mf] = a;
      this.mfB[mf] = b;
      this.mfFirst[mf] = this.cpCount;
      this.mfPoints[mf] = count;
      this.mfFriction[mf] = contacts.friction[slot];
      this.mfRestitution[mf] = contacts.restitution[slot];
      const N = man.normal;
      // Tangent basis: the columns other than e_big of the Householder reflection taking e_big to
      // ∓N, where big is N's largest component (orthonormal, and continuous in N away from ties).
      let big = 0;
      for (let d = 1; d < n; d += 1) if (Math.abs(N[d]) > Math.abs(N[big])) big = d;
      const sgn = N[big] >= 0 ? 1 : -1;
      const twoOverUU = 2 / (2 + 2 * Math.abs(N[big])); // one division, not n²
      for (let t = 0, col = 0; col < n; col += 1) {
        if (col === big) continue;
        const uc = N[col] * twoOverUU;
        for (let d = 0; d < n; d += 1) {
          const ud = d === big ? N[d] + sgn : N[d];
          tangents[t * n + d] = (d === col ? 1 : 0) - ud * uc;
        }
        t += 1;
      }
      // The centres straight from the bodies' records (x first): the views A.x, B.x are two more
      // objects, and cache lines, to load per manifold.
      const xA = A.storage;
      const xB = B.storage;
      const oA = A.storageOffset;
      const oB = B.storageOffset;
      const V = sb.v;
      const W = sb.w;
      const e = this.mfRestitution[mf];
      const bouncy = e !== 0;
      // The relative acceleration of B against A along N in this sub-step (gravity and applied
      // forces of dynamic bodies; torques are left out): restitution uses it to go back from the
      // velocity after this sub-step's kick to the velocity at the moment of impact.
      let accel = 0;
      if (bouncy) {
        const g = this.gravity;
        const fA = A.motion === MOTION_DYNAMIC ? A.force : null;
        const fB = B.motion === MOTION_DYNAMIC ? B.force : null;
        const imA = A.invMass;
        const imB = B.invMass;
        for (let d = 0; d < n; d += 1) {
          const aA = fA !== null ? g[d] + fA[d] * imA : 0;
          const aB = fB !== null ? g[d] + fB[d] * imB : 0;
          accel += N[d] * (aB - aA);
        }
      }
      for (let d = 0; d < n; d += 1) centre[d] = 0;
      for (let pq = 0; pq < count; pq += 1) {
        const cp = this.cpCount++;
        for (let d = 0; d < n; d += 1) {
          const pd = pts[pq * n + d];
          rA[d] = pd - xA[oA + d];
          rB[d] = pd - xB[oB + d];
          centre[d] += pd;
        }
        const base = cp * RS;
        for (let d = 0; d < n; d += 1) rows[base + d] = N[d];
        this.buildRow(rows, base, a, b, sb);
        // Normal velocity before the solve: only restitution reads it (from vn0 here, and from
        // the approach speed it leaves for the next sub-step), so a pair that cannot bounce skips it.
        if (bouncy) {
          let vn = 0;
          for (let d = 0; d < n; d += 1) vn += rows[base + d] * (V[b * n + d] - V[a * n + d]);
          for (let pl = 0; pl < k; pl += 1) {
            vn += rows[base + n + k + pl] * W[b * k + pl] - rows[base + n + pl] * W[a * k + pl];
          }
          // The motion in the sub-step is a parabola in the gap: vn is its slope at the middle of
          // the sub-step, w0 = vn − a·h/2 its slope at the start, and it meets the surface (a gap
          // s > 0 closed) with the slope w_i = −√(w0² − 2·a·s). The bounce leaves the surface with
          // −e·w_i; the velocity that moves a body through the next sub-step on that parabola is
          // its slope half a sub-step later, −e·w_i + a·h/2. vn0 holds that value over −e (the
          // bounce's goal is −e·vn0) for a bounce now; vnStop the same for a bounce one sub-step
          // later, when a speculative row stops the body at the surface in this one.
          const s = seps[pq];
          const w0 = vn - 0.5 * accel * h;
          const shift = (0.5 * accel * h) / e;
          const wNow = -Math.abs(w0);
          const wStop = -Math.sqrt(Math.max(0, w0 * w0 - 2 * accel * Math.max(0, s)));
          this.vnStop[cp] = vn < 0 ? wStop - shift : 0;
          // Restitution bounces from the faster of the approach now and the approach a
          // speculative contact stopped in the last sub-step (see ContactSet.approachSpeed).
          const recorded = contacts.approachSpeed[slot * P + pq];
          this.vn0[cp] = Math.min(vn < 0 ? wNow - shift : vn, recorded);
          this.bounceGap[cp] = recorded < 0 ? slop : 0;
          sep[cp] = s;
          maxLambda[cp] = 0;
        }
        // A pair with e = 0 leaves vn0, vnStop, bounceGap, sep and maxLambda as they are: only
        // restitution and store read them, for a pair that bounces (streams less to write).
        // The velocity target of the point.
        const s = seps[pq];
        target[cp] = s > 0 ? -s / h : bias * Math.max(0, -s - slop);
        lambdaN[cp] = warm ? normalImpulse[slot * P + pq] : 0;
      }
      // The friction patch at the centroid of the points.
      for (let d = 0; d < n; d += 1) centre[d] /= count;
      let radius = 0;
      for (let pq = 0; pq < count; pq += 1) {
        let r2 = 0;
        for (let d = 0; d < n; d += 1) {
          const e = pts[pq * n + d] - centre[d];
          r2 += e * e;
        }
        radius += Math.sqrt(r2);
      }
      this.mfRadius[mf] = radius / count;
      for (let d = 0; d < n; d += 1) {
        rA[d] = centre[d] - xA[oA + d];
        rB[d] = centre[d] - xB[oB + d];
      }
      const patch = this.patchRows;
      const pb = mf * PR * RS;
      const ti = slot * n;
      for (let t = 0; t < m; t += 1) {
        const base = pb + t * RS;
        let s2 = 0;
        for (let d = 0; d < n; d += 1) {
          patch[base + d] = tangents[t * n + d];
          s2 += patchTangent[ti + d] * tangents[t * n + d];
        }
        this.buildRow(patch, base, a, b, sb);
        this.lambdaP[mf * m + t] = warm ? s2 : 0;
      }
      const wi = slot * k;
      for (let t1 = 0, w = 0; t1 < m; t1 += 1) {
        for (let t2 = t1 + 1; t2 < m; t2 += 1, w += 1) {
          const base = pb + (m + w) * RS;
          this.buildTwistRow(patch, base, t1, t2, a, b, sb);
          let s2 = 0;
          for (let pl = 0; pl < k; pl += 1) s2 += patchTwist[wi + pl] * patch[base + n + pl];
          // A patch of one point (R = 0) has no twist friction: nothing of an older patch's twist
          // may be warm-started into it, since no pass would ever clamp it again.
          this.lambdaW[mf * q + w] = warm && radius > 0 ? s2 : 0;
        }
      }
    }
    return this.cpCount;
  }

  /**
   * Fills row `base` of `rows` (its direction d already written) for the arms this.rA, this.rB
   * between slots a and b: J = r ∧ d, I⁻¹J, the effective mass and the two inverse masses. Each
   * dimension's solver has its own (see contact-solver-3d.ts and contact-solver-nd.ts), so a 3D
   * app carries the 3D rows alone.
   */
  protected abstract buildRow(rows: Float64Array, base: number, a: number, b: number, sb: SolverBodies): void;

  /**
   * Fills the twist row `base` of `rows` for tangents t1 < t2: no linear part, J_A = J_B the unit
   * bivector t1 ∧ t2, and K_A = J·I_A⁻¹J (no 1/m: a twist moves no centre of mass).
   */
  protected buildTwistRow(
    rows: Float64Array,
    base: number,
    t1: number,
    t2: number,
    a: number,
    b: number,
    sb: SolverBodies,
  ): void {
    const { n, k } = this;
    const planeI = this.D.planeI;
    const planeJ = this.D.planeJ;
    const T = this.tangents;
    const IA = a * k * k;
    const IB = b * k * k;
    const IW = sb.invInertia;
    const isoA = sb.isoInvInertia[a];
    const isoB = sb.isoInvInertia[b];
    for (let d = 0; d < n; d += 1) rows[base + d] = 0;
    for (let pl = 0; pl < k; pl += 1) {
      const i = planeI[pl];
      const j = planeJ[pl];
      const e = T[t1 * n + i] * T[t2 * n + j] - T[t1 * n + j] * T[t2 * n + i];
      rows[base + n + pl] = e;
      rows[base + n + k + pl] = e;
    }
    let KA = 0;
    let KB = 0;
    for (let row = 0; row < k; row += 1) {
      const e = rows[base + n + row];
      let sa = 0;
      let sbv = 0;
      if (isoA >= 0) sa = isoA * e;
      else for (let col = 0; col < k; col += 1) sa += IW[IA + row * k + col] * rows[base + n + col];
      if (isoB >= 0) sbv = isoB * e;
      else for (let col = 0; col < k; col += 1) sbv += IW[IB + row * k + col] * rows[base + n + col];
      rows[base + n + 2 * k + row] = sa;
      rows[base + n + 3 * k + row] = sbv;
      KA += sa * e;
      KB += sbv * e;
    }
    const K = KA + KB;
    rows[base + n + 4 * k] = K > 0 ? 1 / K : 0;
    rows[base + n + 4 * k + 1] = KA;
    rows[base + n + 4 * k + 2] = KB;
  }

  /**
   * Applies the impulse constants[SOLVE_LAMBDA] of row `base` between slots a (−) and b (+);
   * fa, fb (0 or 1) say which of the two bodies receive it.
   */
  private apply(sb: SolverBodies, base: number, a: number, b: number, fa: number, fb: number): void {
    const { n, k } = this;
    const rows = this.rows;
    const lambda = this.constants[SOLVE_LAMBDA];
    const V = sb.v;
    const W = sb.w;
    const la = lambda * fa * sb.invMass[a];
    const lb = lambda * fb * sb.invMass[b];
    for (let d = 0; d < n; d += 1) {
      const dir = rows[base + d];
      V[a * n + d] -= la * dir;
      V[b * n + d] += lb * dir;
    }
    const ga = lambda * fa;
    const gb = lambda * fb;
    const ia = base + n + 2 * k;
    const ib = base + n + 3 * k;
    for (let pl = 0; pl < k; pl += 1) {
      W[a * k + pl] -= ga * rows[ia + pl];
      W[b * k + pl] += gb * rows[ib + pl];
    }
  }

  /**
   * Applies the warm-start impulses (normals and friction patch) of every manifold: the arithmetic
   * of `apply` with both bodies receiving, written inline (one call per sub-step, not per row).
   */
  warmStart(sb: SolverBodies): void {
    const { n, k, m, q, PR, RS } = this;
    const V = sb.v;
    const W = sb.w;
    const iA = n + 2 * k;
    const iB = n + 3 * k;
    for (let mf = 0; mf < this.mfCount; mf += 1) {
      const a = this.mfA[mf];
      const b = this.mfB[mf];
      const ima = sb.invMass[a];
      const imb = sb.invMass[b];
      const va = a * n;
      const vb = b * n;
      const wa = a * k;
      const wb = b * k;
      const first = this.mfFirst[mf];
      const last = first + this.mfPoints[mf];
      const rows = this.rows;
      for (let cp = first; cp < last; cp += 1) {
        const lambda = this.lambdaN[cp];
        if (lambda === 0) continue;
        const base = cp * RS;
        const la = lambda * ima;
        const lb = lambda * imb;
        for (let d = 0; d < n; d += 1) {
          const dir = rows[base + d];
          V[va + d] -= la * dir;
          V[vb + d] += lb * dir;
        }
        for (let pl = 0; pl < k; pl += 1) {
          W[wa + pl] -= lambda * rows[base + iA + pl];
          W[wb + pl] += lambda * rows[base + iB + pl];
        }
      }
      // the patch: tangent rows (linear and angular), then twist rows (angular only)
      const patch = this.patchRows;
      for (let r = 0; r < PR; r += 1) {
        const lambda = r < m ? this.lambdaP[mf * m + r] : this.lambdaW[mf * q + r - m];
        if (lambda === 0) continue;
        const base = (mf * PR + r) * RS;
        if (r < m) {
          const la = lambda * ima;
          const lb = lambda * imb;
          for (let d = 0; d < n; d += 1) {
            const dir = patch[base + d];
            V[va + d] -= la * dir;
            V[vb + d] += lb * dir;
          }
        }
        for (let pl = 0; pl < k; pl += 1) {
          W[wa + pl] -= lambda * patch[base + iA + pl];
          W[wb + pl] += lambda * patch[base + iB + pl];
        }
      }
    }
  }

  /** Relative velocity (B − A) along row `base`. */
  private rowVelocity(sb: SolverBodies, base: number, a: number, b: number, out: Float64Array, at: number): void {
    const { n, k } = this;
    const rows = this.rows;
    const V = sb.v;
    const W = sb.w;
    let v = 0;
    for (let d = 0; d < n; d += 1) v += rows[base + d] * (V[b * n + d] - V[a * n + d]);
    const ja = base + n;
    const jb = base + n + k;
    for (let pl = 0; pl < k; pl += 1) v += rows[jb + pl] * W[b * k + pl] - rows[ja + pl] * W[a * k + pl];
    out[at] = v;
  }

  /**
   * One Gauss–Seidel pass over the manifolds (friction, then normal). Returns whether no row's
   * velocity changed by more than the tolerance.
   */
  private pass(sb: SolverBodies): boolean {
    const c = this.constants;
    c[SOLVE_CHANGE] = 0;
    for (let mf = 0; mf < this.mfCount; mf += 1) this.solveManifold(sb, mf, false);
    return c[SOLVE_CHANGE] <= c[SOLVE_TOLERANCE];
  }

  /**
   * One shock pass: the manifolds in layer order, the lower body of each contact between layers
   * receiving no impulse. The contacts of one upper body with the layer below are settled together
   * against their frozen lower bodies, with up to `sweeps` sweeps over them: the block is then
   * solved whole, so the points of a face share the load evenly (one sweep leaves it on the first
   * corner visited, which spins the body), and a body resting on two (a box of a pyramid) gets the
   * velocity both supports allow, not that of the one visited last. A sweep that changed no row's
   * velocity by more than the tolerance ends them: the next would change less. Returns whether
   * every group's first sweep was such a sweep.
   */
  private shockPass(sb: SolverBodies, sweeps: number): boolean {
    const c = this.constants;
    const tolerance = c[SOLVE_TOLERANCE];
    const order = this.shockOrder;
    const upper = this.shockUpper;
    const count = this.mfCount;
    let converged = true;
    let start = 0;
    while (start < count) {
      let end = start + 1;
      while (end < count && upper[end] === upper[start]) end += 1;
      for (let sweep = 0; sweep < sweeps; sweep += 1) {
        c[SOLVE_CHANGE] = 0;
        for (let o = start; o < end; o += 1) this.solveManifold(sb, order[o], true);
        if (c[SOLVE_CHANGE] <= tolerance) break;
        converged = false;
      }
      start = end;
    }
    return converged;
  }

  /**
   * The friction patch, then the normals, of manifold `mf` (see {@link ContactSolver.pass}), the
   * innermost loop of the engine. Each dimension's solver has its own, as for `buildRow`.
   */
  protected abstract solveManifold(sb: SolverBodies, mf: number, shock: boolean): void;

  /**
   * `iterations` Gauss–Seidel passes over every manifold, fewer when a pass changes no row's
   * velocity by more than `solverTolerance`: the state is then a fixed point of the passes (to
   * the tolerance), and the passes left would not move it. Returns the passes run.
   */
  solve(sb: SolverBodies, iterations: number): number {
    let it = 0;
    while (it < iterations) {
      it += 1;
      if (this.pass(sb)) break;
    }
    this.passesRun = it;
    return it;
  }

  /** One Gauss–Seidel pass over every manifold (the world interleaves it with the joints). */
  iterate(sb: SolverBodies): void {
    this.pass(sb);
  }

  /**
   * Shock propagation: layers counted from the immovable and kinematic bodies through the
   * contacts (breadth first, by relaxation), then `passes` passes from the ground up in which the
   * lower body of a contact between two layers is infinitely heavy.
   *
   * The order of a pass: by layer, and in a layer the manifolds of one upper body together (two
   * stable counting sorts, by upper body, then by layer; the order of the manifolds is otherwise
   * kept). Manifold by manifold, a box resting on two others took the velocity of the one
   * visited last: where the supports spread apart a little (a pyramid's rows do, by the order of
   * the Gauss–Seidel passes), every box above copied the motion of its right-hand support, the
   * upper part of the pyramid slid sideways as one block, and pyramids of 40 rows fell.
   */
  shockPropagate(sb: SolverBodies, passes: number): void {
    if (passes <= 0 || this.mfCount === 0) return;
    const depth = sb.depth;
    let changed = true;
    let maxDepth = 0;
    while (changed) {
      changed = false;
      for (let mf = 0; mf < this.mfCount; mf += 1) {
        const a = this.mfA[mf];
        const b = this.mfB[mf];
        const da = depth[a];
        const db = depth[b];
        if (da >= 0 && (db < 0 || db > da + 1)) {
          depth[b] = da + 1;
          if (da + 1 > maxDepth) maxDepth = da + 1;
          changed = true;
        } else if (db >= 0 && (da < 0 || da > db + 1)) {
          depth[a] = db + 1;
          if (db + 1 > maxDepth) maxDepth = db + 1;
          changed = true;
        }
      }
    }
    // Counting sort of the manifolds by their lower layer (unreached bodies, −1, go first).
    this.layerCount = growInt32(this.layerCount, maxDepth + 3);
    const cnt = this.layerCount;
    cnt.fill(0, 0, maxDepth + 3);
    for (let mf = 0; mf < this.mfCount; mf += 1) {
      const layer = Math.min(depth[this.mfA[mf]], depth[this.mfB[mf]]) + 1;
      cnt[layer + 1] += 1;
    }
    for (let l = 1; l < maxDepth + 3; l += 1) cnt[l] += cnt[l - 1];
    const bodies = sb.count;
    this.upperCount = growInt32(this.upperCount, bodies + 1);
    const ucnt = this.upperCount;
    ucnt.fill(0, 0, bodies + 1);
    const mfUpper = this.mfUpper;
    for (let mf = 0; mf < this.mfCount; mf += 1) {
      const up = this.upperBody(depth, mf);
      mfUpper[mf] = up;
      ucnt[up + 1] += 1;
    }
    for (let i = 1; i <= bodies; i += 1) ucnt[i] += ucnt[i - 1];
    const byUpper = this.byUpper;
    for (let mf = 0; mf < this.mfCount; mf += 1) byUpper[ucnt[mfUpper[mf]]++] = mf;
    for (let i = 0; i < this.mfCount; i += 1) {
      const mf = byUpper[i];
      const layer = Math.min(depth[this.mfA[mf]], depth[this.mfB[mf]]) + 1;
      const at = cnt[layer]++;
      this.shockOrder[at] = mf;
      this.shockUpper[at] = mfUpper[mf];
    }
    this.tallShock = maxDepth >= TALL_LAYERS;
    if (maxDepth < TALL_LAYERS) {
      for (let it = 0; it < passes; it += 1) if (this.shockPass(sb, SHOCK_INNER_SWEEPS)) return;
      return;
    }
    // A tall stack. The impulses a shock pass adds were computed against an infinitely heavy
    // lower body, so they are not impulses of the real pair: warm-started into the next sub-step
    // they would act on the lower body too, which never received them. The column then drifts, a
    // little every sub-step, into stresses the velocities do not show (corner loads and friction
    // patches, in balance, growing until a patch slides: a column of 30 boxes fell after a
    // second). So `store` leaves most of them out (kept here).
    const np = this.mfCount * this.m;
    const nw = this.mfCount * this.q;
    const nn = this.cpCount;
    const keptP = this.keptP;
    const keptW = this.keptW;
    const keptN = this.keptN;
    keptP.set(this.lambdaP.subarray(0, np));
    keptW.set(this.lambdaW.subarray(0, nw));
    keptN.set(this.lambdaN.subarray(0, nn));
    for (let it = 0; it < passes; it += 1) if (this.shockPass(sb, TALL_INNER_SWEEPS)) break;
    for (let i = 0; i < np; i += 1) keptP[i] = SHOCK_LEFT_OUT * (this.lambdaP[i] - keptP[i]);
    for (let i = 0; i < nw; i += 1) keptW[i] = SHOCK_LEFT_OUT * (this.lambdaW[i] - keptW[i]);
    for (let i = 0; i < nn; i += 1) keptN[i] = SHOCK_LEFT_OUT * (this.lambdaN[i] - keptN[i]);
    this.shocked = true;
  }

  /**
   * The upper body of manifold `mf` in the shock passes: the one farther from the ground; of two
   * in the same layer, the later one (such a contact has no frozen side, and a group of one body
   * settles its contacts with both sides alike).
   */
  private upperBody(depth: Int32Array, mf: number): number {
    const a = this.mfA[mf];
    const b = this.mfB[mf];
    const da = depth[a];
    const db = depth[b];
    if (da > db) return a;
    if (db > da) return b;
    return a > b ? a : b;
  }

  /**
   * Restitution: each touching point (gap <= penetrationSlop) that approached faster than the
   * threshold and pushed in this sub-step gets the normal velocity e·|v_n|, v_n the approach
   * speed before the solve or the one a speculative stop recorded in the last sub-step. A point
   * still short of the surface is only stopped there (speculative); it bounces in the next
   * sub-step, from the surface, at the recorded speed: the same trajectory as a bounce at the
   * moment of impact, a fraction of a sub-step later, so the apex and the energy are right.
   */
  restitution(sb: SolverBodies): void {
    const { RS } = this;
    const c = this.constants;
    const threshold = c[SOLVE_THRESHOLD];
    const tolerance = c[SOLVE_TOLERANCE];
    const tmp = this.tmp;
    const rows = this.rows;
    for (let mf = 0; mf < this.mfCount; mf += 1) {
      const e = this.mfRestitution[mf];
      if (e === 0) continue;
      const a = this.mfA[mf];
      const b = this.mfB[mf];
      const first = this.mfFirst[mf];
      const last = first + this.mfPoints[mf];
      // Gauss–Seidel sweeps over the bouncing points of the manifold until no row's velocity
      // changes by more than the tolerance: the points of a face share one bounce, so a box that
      // lands flat leaves flat (one sweep left most of the impulse on the first corner and spun it).
      for (let sweep = 0; sweep < RESTITUTION_SWEEPS; sweep += 1) {
        let change = 0;
        for (let cp = first; cp < last; cp += 1) {
          const v0 = this.vn0[cp];
          if (v0 > -threshold || this.maxLambda[cp] === 0) continue;
          // A point still short of the surface (a speculative stop) bounces in the next sub-step,
          // from where it touches, with the approach speed the stop recorded.
          if (this.sep[cp] > this.bounceGap[cp]) continue;
          const base = cp * RS;
          this.rowVelocity(sb, base, a, b, tmp, 0);
          const goal = -e * v0;
          const mass = rows[base + RS - 3];
          const old = this.lambdaN[cp];
          const nl = Math.max(0, old + mass * (goal - tmp[0]));
          this.lambdaN[cp] = nl;
          const d = nl - old;
          if (d !== 0) {
            const moved = mass > 0 ? Math.abs(d) / mass : 0;
            if (moved > change) change = moved;
            this.constants[SOLVE_LAMBDA] = d;
            this.apply(sb, base, a, b, 1, 1);
          }
        }
        if (change <= tolerance) break;
      }
    }
  }

  /** Stores the accumulated impulses in the contacts for the next sub-step's warm start. */
  store(contacts: ContactSet): void {
    const { n, k, m, q, PR, RS } = this;
    const P = contacts.pointCapacity;
    const patch = this.patchRows;
    const shocked = this.shocked;
    this.shocked = false;
    for (let mf = 0; mf < this.mfCount; mf += 1) {
      const slot = this.mfContact[mf];
      const first = this.mfFirst[mf];
      const count = this.mfPoints[mf];
      const bouncy = this.mfRestitution[mf] !== 0;
      for (let pq = 0; pq < count; pq += 1) {
        const cp = first + pq;
        const ni = slot * P + pq;
        contacts.normalImpulse[ni] = shocked ? Math.max(0, this.lambdaN[cp] - this.keptN[cp]) : this.lambdaN[cp];
        // (prepare leaves vnStop and bounceGap unset for e = 0: no speculative bounce to record)
        contacts.approachSpeed[ni] = bouncy && this.sep[cp] > this.bounceGap[cp] && this.maxLambda[cp] > 0 ? this.vnStop[cp] : 0;
      }
      // The patch as a world vector and a world bivector: they survive a change of tangent basis.
      const pb = mf * PR * RS;
      for (let d = 0; d < n; d += 1) {
        let s = 0;
        for (let t = 0; t < m; t += 1)
          s += (this.lambdaP[mf * m + t] - (shocked ? this.keptP[mf * m + t] : 0)) * patch[pb + t * RS + d];
        contacts.patchTangent[slot * n + d] = s;
      }
      for (let pl = 0; pl < k; pl += 1) {
        let s = 0;
        for (let w = 0; w < q; w += 1) {
          s += (this.lambdaW[mf * q + w] - (shocked ? this.keptW[mf * q + w] : 0)) * patch[pb + (m + w) * RS + n + pl];
        }
        contacts.patchTwist[slot * k + pl] = s;
      }
    }
  }
}
