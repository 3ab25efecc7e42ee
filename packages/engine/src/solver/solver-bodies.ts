/**
 * The bodies as the solver sees them in one sub-step: flat arrays of velocities, inverse masses
 * and world inverse inertia operators, one slot per body that a contact or joint touches.
 *
 * Slot 0 is the immovable body (zero velocity, zero inverse mass): every static body maps to it.
 * A kinematic body gets a slot of its own with its velocity and zero inverse mass, so it pushes
 * without being pushed. A dynamic body gets its v, ω and the k×k operator I_world⁻¹, built once
 * here so that every row of every constraint can form I⁻¹J with one small matrix product.
 *
 * Angular impulses change ω only (the inner loop stays short); {@link SolverBodies.writeBack}
 * then adds I_world Δω to the body's L. L stays the state, so a body that receives no impulse
 * keeps its L bit-exactly.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import { Body, MOTION_DYNAMIC, MOTION_STATIC } from '../body.js';
import { growFloat64, growInt32 } from '../contacts/contact-set.js';

/** Flat per-slot solver state of one sub-step. */
export class SolverBodies {
  /** The dimension tables. */
  readonly D: Dims;
  /** Count of slots in use (slot 0, the immovable body, is always there). */
  count = 1;
  /** The body of each slot (null for slot 0). */
  bodies: (Body | null)[] = [null];
  /** Linear velocity, n per slot (m/s). */
  v: Float64Array;
  /** Angular velocity, k per slot (rad/s, world frame). */
  w: Float64Array;
  /** Angular velocity at the start of the solve, k per slot (rad/s). */
  w0: Float64Array;
  /** Inverse mass per slot (1/kg); 0 for slot 0 and kinematic bodies. */
  invMass: Float64Array;
  /** World inverse inertia, k×k row-major per slot; zeros for slot 0 and kinematic bodies. */
  invInertia: Float64Array;
  /** World inertia, k×k row-major per slot (dynamic bodies only). */
  inertia: Float64Array;
  /**
   * Per slot: s when I_world⁻¹ = s·identity (a body whose inertia is the same in every plane: a
   * hypercube, a hypersphere; also 0 for slot 0 and kinematic bodies), −1 otherwise. Such a body's
   * I⁻¹J is s·J whatever its rotation: k products instead of k² per row.
   */
  isoInvInertia: Float64Array;
  /** Shock-propagation layer per slot (0 for immovable and kinematic slots). */
  depth: Int32Array;

  /** The bivector rotation of one body (k×k), scratch. */
  private readonly rot: Float64Array;

  constructor(D: Dims) {
    this.D = D;
    this.v = new Float64Array(16 * D.n);
    this.w = new Float64Array(16 * D.k);
    this.w0 = new Float64Array(16 * D.k);
    this.invMass = new Float64Array(16);
    this.invInertia = new Float64Array(16 * D.k * D.k);
    this.inertia = new Float64Array(16 * D.k * D.k);
    this.isoInvInertia = new Float64Array(16);
    this.depth = new Int32Array(16);
    this.rot = new Float64Array(D.k * D.k);
  }

  /** Forgets the slots of the last sub-step (the bodies' solverSlot go back to -1). */
  reset(): void {
    for (let s = 1; s < this.count; s += 1) {
      this.bodies[s]!.solverSlot = -1;
      this.bodies[s] = null;
    }
    this.count = 1;
  }

  /** The slot of `body`, created on first use in this sub-step. Allocates only when growing. */
  slotOf(body: Body): number {
    if (body.motion === MOTION_STATIC) return 0;
    if (body.solverSlot > 0) return body.solverSlot;
    const { n, k } = this.D;
    const s = this.count;
    this.count = s + 1;
    if (s * n + n > this.v.length) this.grow(s + 1);
    this.bodies[s] = body;
    body.solverSlot = s;
    // v and ω straight from the body's record (x, R, v, L, ω, ...): its views are more objects to load.
    const rec = body.storage;
    const v = body.storageOffset + Body.velocityOffset(this.D);
    const w = v + n + k;
    for (let i = 0; i < n; i += 1) this.v[s * n + i] = rec[v + i];
    for (let p = 0; p < k; p += 1) {
      this.w[s * k + p] = rec[w + p];
      this.w0[s * k + p] = rec[w + p];
    }
    const kk = k * k;
    if (body.motion === MOTION_DYNAMIC) {
      this.invMass[s] = body.invMass;
      this.worldInverseInertia(body, s * kk);
    } else {
      this.invMass[s] = 0;
      this.invInertia.fill(0, s * kk, s * kk + kk);
      this.isoInvInertia[s] = 0;
    }
    this.depth[s] = body.motion === MOTION_DYNAMIC ? -1 : 0;
    return s;
  }

  private grow(need: number): void {
    const { n, k } = this.D;
    this.v = growFloat64(this.v, need * n);
    this.w = growFloat64(this.w, need * k);
    this.w0 = growFloat64(this.w0, need * k);
    this.invMass = growFloat64(this.invMass, need);
    this.isoInvInertia = growFloat64(this.isoInvInertia, need);
    this.invInertia = growFloat64(this.invInertia, need * k * k);
    this.inertia = growFloat64(this.inertia, need * k * k);
    this.depth = growInt32(this.depth, need);
  }

  /**
   * I_world⁻¹ = Q diag(invInertia) Qᵀ and I_world = Q diag(inertia) Qᵀ, where Q (k×k) rotates
   * body-frame bivectors into the world: column (ij) is (M e_i) ∧ (M e_j), M the rotation matrix
   * of the body's pose.
   */
  private worldInverseInertia(body: Body, at: number): void {
    const { n, k, planeI, planeJ } = this.D;
    const inv = body.invInertia;
    const I = body.inertia;
    const out = this.invInertia;
    const outI = this.inertia;
    const slot = at / (k * k);
    let iso = true;
    for (let q = 1; q < k; q += 1) if (inv[q] !== inv[0] || I[q] !== I[0]) iso = false;
    if (iso) {
      // Q diag(s) Qᵀ = s·QQᵀ = s·identity: no rotation needed. (A loop: fill is a call per body.)
      const s = inv[0];
      const t = I[0];
      for (let r = 0; r < k; r += 1) {
        for (let c = 0; c < k; c += 1) {
          out[at + r * k + c] = r === c ? s : 0;
          outI[at + r * k + c] = r === c ? t : 0;
        }
      }
      this.isoInvInertia[slot] = inv[0];
      return;
    }
    this.isoInvInertia[slot] = -1;
    const M = body.pose!.M;
    const Q = this.rot;
    for (let col = 0; col < k; col += 1) {
      const i = planeI[col];
      const j = planeJ[col];
      for (let row = 0; row < k; row += 1) {
        const a = planeI[row];
        const b = planeJ[row];
        Q[row * k + col] = M[a * n + i] * M[b * n + j] - M[b * n + i] * M[a * n + j];
      }
    }
    for (let r = 0; r < k; r += 1) {
      for (let c = r; c < k; c += 1) {
        let s = 0;
        let t = 0;
        for (let q = 0; q < k; q += 1) {
          const qq = Q[r * k + q] * Q[c * k + q];
          s += qq * inv[q];
          t += qq * I[q];
        }
        out[at + r * k + c] = s;
        out[at + c * k + r] = s;
        outI[at + r * k + c] = t;
        outI[at + c * k + r] = t;
      }
    }
  }

  /**
   * Writes the solved velocities back: v, L += I_world (ω − ω₀) and ω rebuilt from L for dynamic
   * bodies whose ω changed (kinematic bodies keep their own velocities).
   */
  writeBack(): void {
    const { n, k } = this.D;
    for (let s = 1; s < this.count; s += 1) {
      const body = this.bodies[s]!;
      if (body.motion !== MOTION_DYNAMIC) continue;
      const rec = body.storage;
      const v = body.storageOffset + Body.velocityOffset(this.D);
      for (let i = 0; i < n; i += 1) rec[v + i] = this.v[s * n + i];
      let changed = false;
      for (let p = 0; p < k; p += 1) if (this.w[s * k + p] !== this.w0[s * k + p]) changed = true;
      if (!changed) continue;
      const L = body.L;
      const I = this.inertia;
      const at = s * k * k;
      for (let r = 0; r < k; r += 1) {
        let d = 0;
        for (let c = 0; c < k; c += 1) d += I[at + r * k + c] * (this.w[s * k + c] - this.w0[s * k + c]);
        L[r] += d;
      }
      body.omegaFromMomentum();
    }
  }
}
