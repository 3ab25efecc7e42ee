/**
 * The contact solver of `@physin/engine`, for any n: the general loops of the rows and of the
 * manifold solve, with copies written out for n = 4 here and for n = 3 in the 3D solver it extends
 * (contact-solver-3d.ts). The written-out copies do the same arithmetic in the same order as the
 * general loops, so results are bit-identical to them (`writtenOut` switches them off to show it).
 *
 * @module
 */
import type { Body } from '../body.js';
import { MOTION_DYNAMIC } from '../body.js';
import type { ContactSet } from '../contacts/contact-set.js';
import { CONTACT_ACTIVE, growInt32 } from '../contacts/contact-set.js';
import { STEP_H } from '../integrator/step-constants.js';
import type { Params } from '../params.js';
import { SOLVE_BIAS, SOLVE_CHANGE, SOLVE_H, SOLVE_SLOP, SOLVE_THRESHOLD, SOLVE_TOLERANCE } from './contact-solver.js';
import { ContactSolver3 } from './contact-solver-3d.js';
import type { SolverBodies } from './solver-bodies.js';

/** The contact solver for any n (see the module comment). */
export class ContactSolverND extends ContactSolver3 {
  /**
   * Whether n = 3 and n = 4 use the written-out copies of the rows and of the manifold solve
   * (default true). They are bit-identical to the general loops; tests switch them off to show it.
   * @internal
   */
  writtenOut = true;

  /**
   * n >= 4: whether manifold mf's next Gauss–Seidel pass takes its normal rows last to first.
   * Passes alternate the order (symmetric Gauss–Seidel over the 2^(n−1) corners of a face), the
   * first of a sub-step backwards; the shock passes keep the forward order. In one order the
   * first corner visited takes most of a landing's impulse, and the box tips: a 4D stack of 9
   * landed swaying (5 mm/s) and took 265 steps to come to rest; alternating, about 205.
   */
  private mfReverse = new Int32Array(16);

  protected override buildRow(rows: Float64Array, base: number, a: number, b: number, sb: SolverBodies): void {
    if (this.writtenOut && this.n === 3) super.buildRow(rows, base, a, b, sb);
    else if (this.writtenOut && this.n === 4) this.buildRow4(rows, base, a, b, sb);
    else this.buildRowGeneral(rows, base, a, b, sb);
  }

  /** {@link ContactSolver.buildRow} for n = 4, written out (the same sums in the same order as the general loop). */
  private buildRow4(rows: Float64Array, base: number, a: number, b: number, sb: SolverBodies): void {
    const k = this.k;
    const rA = this.rA;
    const rB = this.rB;
    const imA = sb.invMass[a];
    const imB = sb.invMass[b];
    const IA = a * k * k;
    const IB = b * k * k;
    const IW = sb.invInertia;
    // s ≥ 0 when the body's I⁻¹ is s·identity (then I⁻¹J = s·J), else −1 (see SolverBodies).
    const isoA = sb.isoInvInertia[a];
    const isoB = sb.isoInvInertia[b];
    const d0 = rows[base];
    const d1 = rows[base + 1];
    const d2 = rows[base + 2];
    const d3 = rows[base + 3];
    if (isoA >= 0 && isoB >= 0) {
      // Two isotropic bodies (boxes, balls): the arms in locals and no per-entry test.
      const ra0 = rA[0],
        ra1 = rA[1],
        ra2 = rA[2],
        ra3 = rA[3];
      const rb0 = rB[0],
        rb1 = rB[1],
        rb2 = rB[2],
        rb3 = rB[3];
      const ia0 = ra0 * d1 - ra1 * d0;
      const ia1 = ra0 * d2 - ra2 * d0;
      const ia2 = ra0 * d3 - ra3 * d0;
      const ia3 = ra1 * d2 - ra2 * d1;
      const ia4 = ra1 * d3 - ra3 * d1;
      const ia5 = ra2 * d3 - ra3 * d2;
      const ib0 = rb0 * d1 - rb1 * d0;
      const ib1 = rb0 * d2 - rb2 * d0;
      const ib2 = rb0 * d3 - rb3 * d0;
      const ib3 = rb1 * d2 - rb2 * d1;
      const ib4 = rb1 * d3 - rb3 * d1;
      const ib5 = rb2 * d3 - rb3 * d2;
      rows[base + 4] = ia0;
      rows[base + 5] = ia1;
      rows[base + 6] = ia2;
      rows[base + 7] = ia3;
      rows[base + 8] = ia4;
      rows[base + 9] = ia5;
      rows[base + 10] = ib0;
      rows[base + 11] = ib1;
      rows[base + 12] = ib2;
      rows[base + 13] = ib3;
      rows[base + 14] = ib4;
      rows[base + 15] = ib5;
      // I⁻¹J = s·J, then K_X = 1/m_X + Σ (s J)·J in the general loop's order (no boxed doubles: inline).
      const sa0 = isoA * ia0;
      const sa1 = isoA * ia1;
      const sa2 = isoA * ia2;
      const sa3 = isoA * ia3;
      const sa4 = isoA * ia4;
      const sa5 = isoA * ia5;
      const sb0 = isoB * ib0;
      const sb1 = isoB * ib1;
      const sb2 = isoB * ib2;
      const sb3 = isoB * ib3;
      const sb4 = isoB * ib4;
      const sb5 = isoB * ib5;
      rows[base + 16] = sa0;
      rows[base + 17] = sa1;
      rows[base + 18] = sa2;
      rows[base + 19] = sa3;
      rows[base + 20] = sa4;
      rows[base + 21] = sa5;
      rows[base + 22] = sb0;
      rows[base + 23] = sb1;
      rows[base + 24] = sb2;
      rows[base + 25] = sb3;
      rows[base + 26] = sb4;
      rows[base + 27] = sb5;
      const KA = imA + sa0 * ia0 + sa1 * ia1 + sa2 * ia2 + sa3 * ia3 + sa4 * ia4 + sa5 * ia5;
      const KB = imB + sb0 * ib0 + sb1 * ib1 + sb2 * ib2 + sb3 * ib3 + sb4 * ib4 + sb5 * ib5;
      const K = KA + KB;
      rows[base + 28] = K > 0 ? 1 / K : 0;
      rows[base + 29] = KA;
      rows[base + 30] = KB;
      return;
    }
    const ja0 = rA[0] * d1 - rA[1] * d0;
    const jb0 = rB[0] * d1 - rB[1] * d0;
    rows[base + 4] = ja0;
    rows[base + 10] = jb0;
    const ja1 = rA[0] * d2 - rA[2] * d0;
    const jb1 = rB[0] * d2 - rB[2] * d0;
    rows[base + 5] = ja1;
    rows[base + 11] = jb1;
    const ja2 = rA[0] * d3 - rA[3] * d0;
    const jb2 = rB[0] * d3 - rB[3] * d0;
    rows[base + 6] = ja2;
    rows[base + 12] = jb2;
    const ja3 = rA[1] * d2 - rA[2] * d1;
    const jb3 = rB[1] * d2 - rB[2] * d1;
    rows[base + 7] = ja3;
    rows[base + 13] = jb3;
    const ja4 = rA[1] * d3 - rA[3] * d1;
    const jb4 = rB[1] * d3 - rB[3] * d1;
    rows[base + 8] = ja4;
    rows[base + 14] = jb4;
    const ja5 = rA[2] * d3 - rA[3] * d2;
    const jb5 = rB[2] * d3 - rB[3] * d2;
    rows[base + 9] = ja5;
    rows[base + 15] = jb5;
    let KA = imA;
    let KB = imB;
    const sa0 =
      isoA >= 0
        ? isoA * ja0
        : 0 + IW[IA] * ja0 + IW[IA + 1] * ja1 + IW[IA + 2] * ja2 + IW[IA + 3] * ja3 + IW[IA + 4] * ja4 + IW[IA + 5] * ja5;
    const sb0 =
      isoB >= 0
        ? isoB * jb0
        : 0 + IW[IB] * jb0 + IW[IB + 1] * jb1 + IW[IB + 2] * jb2 + IW[IB + 3] * jb3 + IW[IB + 4] * jb4 + IW[IB + 5] * jb5;
    rows[base + 16] = sa0;
    rows[base + 22] = sb0;
    KA += sa0 * ja0;
    KB += sb0 * jb0;
    const sa1 =
      isoA >= 0
        ? isoA * ja1
        : 0 + IW[IA + 6] * ja0 + IW[IA + 7] * ja1 + IW[IA + 8] * ja2 + IW[IA + 9] * ja3 + IW[IA + 10] * ja4 + IW[IA + 11] * ja5;
    const sb1 =
      isoB >= 0
        ? isoB * jb1
        : 0 + IW[IB + 6] * jb0 + IW[IB + 7] * jb1 + IW[IB + 8] * jb2 + IW[IB + 9] * jb3 + IW[IB + 10] * jb4 + IW[IB + 11] * jb5;
    rows[base + 17] = sa1;
    rows[base + 23] = sb1;
    KA += sa1 * ja1;
    KB += sb1 * jb1;
    const sa2 =
      isoA >= 0
        ? isoA * ja2
        : 0 +
          IW[IA + 12] * ja0 +
          IW[IA + 13] * ja1 +
          IW[IA + 14] * ja2 +
          IW[IA + 15] * ja3 +
          IW[IA + 16] * ja4 +
          IW[IA + 17] * ja5;
    const sb2 =
      isoB >= 0
        ? isoB * jb2
        : 0 +
          IW[IB + 12] * jb0 +
          IW[IB + 13] * jb1 +
          IW[IB + 14] * jb2 +
          IW[IB + 15] * jb3 +
          IW[IB + 16] * jb4 +
          IW[IB + 17] * jb5;
    rows[base + 18] = sa2;
    rows[base + 24] = sb2;
    KA += sa2 * ja2;
    KB += sb2 * jb2;
    const sa3 =
      isoA >= 0
        ? isoA * ja3
        : 0 +
          IW[IA + 18] * ja0 +
          IW[IA + 19] * ja1 +
          IW[IA + 20] * ja2 +
          IW[IA + 21] * ja3 +
          IW[IA + 22] * ja4 +
          IW[IA + 23] * ja5;
    const sb3 =
      isoB >= 0
        ? isoB * jb3
        : 0 +
          IW[IB + 18] * jb0 +
          IW[IB + 19] * jb1 +
          IW[IB + 20] * jb2 +
          IW[IB + 21] * jb3 +
          IW[IB + 22] * jb4 +
          IW[IB + 23] * jb5;
    rows[base + 19] = sa3;
    rows[base + 25] = sb3;
    KA += sa3 * ja3;
    KB += sb3 * jb3;
    const sa4 =
      isoA >= 0
        ? isoA * ja4
        : 0 +
          IW[IA + 24] * ja0 +
          IW[IA + 25] * ja1 +
          IW[IA + 26] * ja2 +
          IW[IA + 27] * ja3 +
          IW[IA + 28] * ja4 +
          IW[IA + 29] * ja5;
    const sb4 =
      isoB >= 0
        ? isoB * jb4
        : 0 +
          IW[IB + 24] * jb0 +
          IW[IB + 25] * jb1 +
          IW[IB + 26] * jb2 +
          IW[IB + 27] * jb3 +
          IW[IB + 28] * jb4 +
          IW[IB + 29] * jb5;
    rows[base + 20] = sa4;
    rows[base + 26] = sb4;
    KA += sa4 * ja4;
    KB += sb4 * jb4;
    const sa5 =
      isoA >= 0
        ? isoA * ja5
        : 0 +
          IW[IA + 30] * ja0 +
          IW[IA + 31] * ja1 +
          IW[IA + 32] * ja2 +
          IW[IA + 33] * ja3 +
          IW[IA + 34] * ja4 +
          IW[IA + 35] * ja5;
    const sb5 =
      isoB >= 0
        ? isoB * jb5
        : 0 +
          IW[IB + 30] * jb0 +
          IW[IB + 31] * jb1 +
          IW[IB + 32] * jb2 +
          IW[IB + 33] * jb3 +
          IW[IB + 34] * jb4 +
          IW[IB + 35] * jb5;
    rows[base + 21] = sa5;
    rows[base + 27] = sb5;
    KA += sa5 * ja5;
    KB += sb5 * jb5;
    const K = KA + KB;
    rows[base + 28] = K > 0 ? 1 / K : 0;
    rows[base + 29] = KA;
    rows[base + 30] = KB;
  }

  /**
   * {@link ContactSolver.prepare}; for n = 4 a copy written out (the tangent basis, the normal rows
   * of two isotropic bodies built inline from the point, the patch radius and the warm-start
   * projections of the patch): the same operations in the same order as the shared prepare and
   * its general loops, so bit-identical (keep the two in step).
   */
  override prepare(contacts: ContactSet, sb: SolverBodies, stepConstants: Float64Array, p: Readonly<Params>): number {
    const points =
      this.writtenOut && this.n === 4
        ? this.prepare4(contacts, sb, stepConstants, p)
        : super.prepare(contacts, sb, stepConstants, p);
    if (this.n >= 4) {
      // Every manifold's first pass of the sub-step takes its points last to first (see mfReverse).
      this.mfReverse = growInt32(this.mfReverse, this.mfCount);
      this.mfReverse.fill(1, 0, this.mfCount);
    }
    return points;
  }

  /** {@link ContactSolverND.prepare} for n = 4 (see there). */
  private prepare4(contacts: ContactSet, sb: SolverBodies, stepConstants: Float64Array, p: Readonly<Params>): number {
    this.shocked = false;
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
    const PT = contacts.patchTangent;
    const PW = contacts.patchTwist;
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
      const rows = this.rows;
      const mf = this.mfCount++;
      this.mfContact[mf] = slot;
      this.mfA[mf] = a;
      this.mfB[mf] = b;
      this.mfFirst[mf] = this.cpCount;
      this.mfPoints[mf] = count;
      this.mfFriction[mf] = contacts.friction[slot];
      this.mfRestitution[mf] = contacts.restitution[slot];
      const N = man.normal;
      const d0 = N[0],
        d1 = N[1],
        d2 = N[2],
        d3 = N[3];
      // The tangent basis of the shared prepare (a Householder reflection), written out.
      let big = 0;
      if (Math.abs(d1) > Math.abs(N[big])) big = 1;
      if (Math.abs(d2) > Math.abs(N[big])) big = 2;
      if (Math.abs(d3) > Math.abs(N[big])) big = 3;
      const sgn = N[big] >= 0 ? 1 : -1;
      const twoOverUU = 2 / (2 + 2 * Math.abs(N[big]));
      {
        const u0 = big === 0 ? d0 + sgn : d0;
        const u1 = big === 1 ? d1 + sgn : d1;
        const u2 = big === 2 ? d2 + sgn : d2;
        const u3 = big === 3 ? d3 + sgn : d3;
        for (let t = 0, col = 0; col < 4; col += 1) {
          if (col === big) continue;
          const uc = N[col] * twoOverUU;
          const o = t * 4;
          tangents[o] = (col === 0 ? 1 : 0) - u0 * uc;
          tangents[o + 1] = (col === 1 ? 1 : 0) - u1 * uc;
          tangents[o + 2] = (col === 2 ? 1 : 0) - u2 * uc;
          tangents[o + 3] = (col === 3 ? 1 : 0) - u3 * uc;
          t += 1;
        }
      }
      const xA = A.x;
      const xB = B.x;
      const V = sb.v;
      const W = sb.w;
      const e = this.mfRestitution[mf];
      const bouncy = e !== 0;
      let accel = 0;
      if (bouncy) {
        const g = this.gravity;
        const fA = A.motion === MOTION_DYNAMIC ? A.force : null;
        const fB = B.motion === MOTION_DYNAMIC ? B.force : null;
        const imA = A.invMass;
        const imB = B.invMass;
        for (let d = 0; d < 4; d += 1) {
          const aA = fA !== null ? g[d] + fA[d] * imA : 0;
          const aB = fB !== null ? g[d] + fB[d] * imB : 0;
          accel += N[d] * (aB - aA);
        }
      }
      const isoA = sb.isoInvInertia[a];
      const isoB = sb.isoInvInertia[b];
      const iso = isoA >= 0 && isoB >= 0;
      const imA = sb.invMass[a];
      const imB = sb.invMass[b];
      const xa0 = xA[0],
        xa1 = xA[1],
        xa2 = xA[2],
        xa3 = xA[3];
      const xb0 = xB[0],
        xb1 = xB[1],
        xb2 = xB[2],
        xb3 = xB[3];
      const pts = man.points;
      let c0 = 0,
        c1 = 0,
        c2 = 0,
        c3 = 0;
      for (let pq = 0; pq < count; pq += 1) {
        const cp = this.cpCount++;
        const o = pq * 4;
        const p0 = pts[o],
          p1 = pts[o + 1],
          p2 = pts[o + 2],
          p3 = pts[o + 3];
        c0 += p0;
        c1 += p1;
        c2 += p2;
        c3 += p3;
        const base = cp * 31;
        rows[base] = d0;
        rows[base + 1] = d1;
        rows[base + 2] = d2;
        rows[base + 3] = d3;
        const ra0 = p0 - xa0,
          ra1 = p1 - xa1,
          ra2 = p2 - xa2,
          ra3 = p3 - xa3;
        const rb0 = p0 - xb0,
          rb1 = p1 - xb1,
          rb2 = p2 - xb2,
          rb3 = p3 - xb3;
        if (iso) {
          const ja0 = ra0 * d1 - ra1 * d0;
          const ja1 = ra0 * d2 - ra2 * d0;
          const ja2 = ra0 * d3 - ra3 * d0;
          const ja3 = ra1 * d2 - ra2 * d1;
          const ja4 = ra1 * d3 - ra3 * d1;
          const ja5 = ra2 * d3 - ra3 * d2;
          const jb0 = rb0 * d1 - rb1 * d0;
          const jb1 = rb0 * d2 - rb2 * d0;
          const jb2 = rb0 * d3 - rb3 * d0;
          const jb3 = rb1 * d2 - rb2 * d1;
          const jb4 = rb1 * d3 - rb3 * d1;
          const jb5 = rb2 * d3 - rb3 * d2;
          rows[base + 4] = ja0;
          rows[base + 5] = ja1;
          rows[base + 6] = ja2;
          rows[base + 7] = ja3;
          rows[base + 8] = ja4;
          rows[base + 9] = ja5;
          rows[base + 10] = jb0;
          rows[base + 11] = jb1;
          rows[base + 12] = jb2;
          rows[base + 13] = jb3;
          rows[base + 14] = jb4;
          rows[base + 15] = jb5;
          // I⁻¹J = s·J, then K_X = 1/m_X + Σ (s J)·J in the general loop's order (no boxed doubles: inline).
          const sa0 = isoA * ja0;
          const sa1 = isoA * ja1;
          const sa2 = isoA * ja2;
          const sa3 = isoA * ja3;
          const sa4 = isoA * ja4;
          const sa5 = isoA * ja5;
          const sb0 = isoB * jb0;
          const sb1 = isoB * jb1;
          const sb2 = isoB * jb2;
          const sb3 = isoB * jb3;
          const sb4 = isoB * jb4;
          const sb5 = isoB * jb5;
          rows[base + 16] = sa0;
          rows[base + 17] = sa1;
          rows[base + 18] = sa2;
          rows[base + 19] = sa3;
          rows[base + 20] = sa4;
          rows[base + 21] = sa5;
          rows[base + 22] = sb0;
          rows[base + 23] = sb1;
          rows[base + 24] = sb2;
          rows[base + 25] = sb3;
          rows[base + 26] = sb4;
          rows[base + 27] = sb5;
          const KA = imA + sa0 * ja0 + sa1 * ja1 + sa2 * ja2 + sa3 * ja3 + sa4 * ja4 + sa5 * ja5;
          const KB = imB + sb0 * jb0 + sb1 * jb1 + sb2 * jb2 + sb3 * jb3 + sb4 * jb4 + sb5 * jb5;
          const K = KA + KB;
          rows[base + 28] = K > 0 ? 1 / K : 0;
          rows[base + 29] = KA;
          rows[base + 30] = KB;
        } else {
          rA[0] = ra0;
          rA[1] = ra1;
          rA[2] = ra2;
          rA[3] = ra3;
          rB[0] = rb0;
          rB[1] = rb1;
          rB[2] = rb2;
          rB[3] = rb3;
          this.buildRow4(rows, base, a, b, sb);
        }
        if (bouncy) {
          // The shared prepare's restitution set-up (see there), for n = 4.
          let vn = 0;
          for (let d = 0; d < 4; d += 1) vn += rows[base + d] * (V[b * 4 + d] - V[a * 4 + d]);
          for (let pl = 0; pl < 6; pl += 1) vn += rows[base + 10 + pl] * W[b * 6 + pl] - rows[base + 4 + pl] * W[a * 6 + pl];
          const s = man.separations[pq];
          const w0 = vn - 0.5 * accel * h;
          const shift = (0.5 * accel * h) / e;
          const wNow = -Math.abs(w0);
          const wStop = -Math.sqrt(Math.max(0, w0 * w0 - 2 * accel * Math.max(0, s)));
          this.vnStop[cp] = vn < 0 ? wStop - shift : 0;
          const recorded = contacts.approachSpeed[slot * P + pq];
          this.vn0[cp] = Math.min(vn < 0 ? wNow - shift : vn, recorded);
          this.bounceGap[cp] = recorded < 0 ? c[SOLVE_SLOP] : 0;
        } else {
          this.bounceGap[cp] = 0;
          this.vn0[cp] = 0;
          this.vnStop[cp] = 0;
        }
        const s = man.separations[pq];
        this.sep[cp] = s;
        this.target[cp] = s > 0 ? -s / h : c[SOLVE_BIAS] * Math.max(0, -s - c[SOLVE_SLOP]);
        this.maxLambda[cp] = 0;
        this.lambdaN[cp] = warm ? contacts.normalImpulse[slot * P + pq] : 0;
      }
      // The friction patch at the centroid of the points.
      c0 /= count;
      c1 /= count;
      c2 /= count;
      c3 /= count;
      let radius = 0;
      for (let pq = 0; pq < count; pq += 1) {
        const o = pq * 4;
        const e0 = pts[o] - c0;
        const e1 = pts[o + 1] - c1;
        const e2 = pts[o + 2] - c2;
        const e3 = pts[o + 3] - c3;
        radius += Math.sqrt(0 + e0 * e0 + e1 * e1 + e2 * e2 + e3 * e3);
      }
      this.mfRadius[mf] = radius / count;
      rA[0] = c0 - xa0;
      rA[1] = c1 - xa1;
      rA[2] = c2 - xa2;
      rA[3] = c3 - xa3;
      rB[0] = c0 - xb0;
      rB[1] = c1 - xb1;
      rB[2] = c2 - xb2;
      rB[3] = c3 - xb3;
      const patch = this.patchRows;
      const pb = mf * 186;
      const ti = slot * 4;
      const g0 = PT[ti],
        g1 = PT[ti + 1],
        g2 = PT[ti + 2],
        g3 = PT[ti + 3];
      for (let t = 0; t < 3; t += 1) {
        const base = pb + t * 31;
        const o = t * 4;
        const t0 = tangents[o],
          t1 = tangents[o + 1],
          t2 = tangents[o + 2],
          t3 = tangents[o + 3];
        patch[base] = t0;
        patch[base + 1] = t1;
        patch[base + 2] = t2;
        patch[base + 3] = t3;
        this.buildRow4(patch, base, a, b, sb);
        this.lambdaP[mf * 3 + t] = warm ? 0 + g0 * t0 + g1 * t1 + g2 * t2 + g3 * t3 : 0;
      }
      const wi = slot * 6;
      // A patch of one point (R = 0) has no twist friction (see the shared prepare).
      const twistWarm = warm && radius > 0;
      for (let t1 = 0, w = 0; t1 < 3; t1 += 1) {
        for (let t2 = t1 + 1; t2 < 3; t2 += 1, w += 1) {
          const base = pb + (3 + w) * 31;
          this.buildTwistRow(patch, base, t1, t2, a, b, sb);
          this.lambdaW[mf * 3 + w] = twistWarm
            ? 0 +
              PW[wi] * patch[base + 4] +
              PW[wi + 1] * patch[base + 5] +
              PW[wi + 2] * patch[base + 6] +
              PW[wi + 3] * patch[base + 7] +
              PW[wi + 4] * patch[base + 8] +
              PW[wi + 5] * patch[base + 9]
            : 0;
        }
      }
    }
    return this.cpCount;
  }

  /**
   * {@link ContactSolver.buildTwistRow} for n = 4 and two isotropic bodies, written out (the same
   * sums in the same order as the general loop: K_A = 0 + Σ (s_A e)·e).
   */
  protected override buildTwistRow(
    rows: Float64Array,
    base: number,
    t1: number,
    t2: number,
    a: number,
    b: number,
    sb: SolverBodies,
  ): void {
    const isoA = sb.isoInvInertia[a];
    const isoB = sb.isoInvInertia[b];
    if (!this.writtenOut || this.n !== 4 || isoA < 0 || isoB < 0) {
      super.buildTwistRow(rows, base, t1, t2, a, b, sb);
      return;
    }
    const T = this.tangents;
    const u = t1 * 4;
    const v = t2 * 4;
    const u0 = T[u],
      u1 = T[u + 1],
      u2 = T[u + 2],
      u3 = T[u + 3];
    const v0 = T[v],
      v1 = T[v + 1],
      v2 = T[v + 2],
      v3 = T[v + 3];
    const e0 = u0 * v1 - u1 * v0;
    const e1 = u0 * v2 - u2 * v0;
    const e2 = u0 * v3 - u3 * v0;
    const e3 = u1 * v2 - u2 * v1;
    const e4 = u1 * v3 - u3 * v1;
    const e5 = u2 * v3 - u3 * v2;
    rows[base] = 0;
    rows[base + 1] = 0;
    rows[base + 2] = 0;
    rows[base + 3] = 0;
    rows[base + 4] = e0;
    rows[base + 5] = e1;
    rows[base + 6] = e2;
    rows[base + 7] = e3;
    rows[base + 8] = e4;
    rows[base + 9] = e5;
    rows[base + 10] = e0;
    rows[base + 11] = e1;
    rows[base + 12] = e2;
    rows[base + 13] = e3;
    rows[base + 14] = e4;
    rows[base + 15] = e5;
    // I⁻¹J = s·J, then K_X = 1/m_X + Σ (s J)·J in the general loop's order (no boxed doubles: inline).
    const sa0 = isoA * e0;
    const sa1 = isoA * e1;
    const sa2 = isoA * e2;
    const sa3 = isoA * e3;
    const sa4 = isoA * e4;
    const sa5 = isoA * e5;
    const sb0 = isoB * e0;
    const sb1 = isoB * e1;
    const sb2 = isoB * e2;
    const sb3 = isoB * e3;
    const sb4 = isoB * e4;
    const sb5 = isoB * e5;
    rows[base + 16] = sa0;
    rows[base + 17] = sa1;
    rows[base + 18] = sa2;
    rows[base + 19] = sa3;
    rows[base + 20] = sa4;
    rows[base + 21] = sa5;
    rows[base + 22] = sb0;
    rows[base + 23] = sb1;
    rows[base + 24] = sb2;
    rows[base + 25] = sb3;
    rows[base + 26] = sb4;
    rows[base + 27] = sb5;
    const KA = 0 + sa0 * e0 + sa1 * e1 + sa2 * e2 + sa3 * e3 + sa4 * e4 + sa5 * e5;
    const KB = 0 + sb0 * e0 + sb1 * e1 + sb2 * e2 + sb3 * e3 + sb4 * e4 + sb5 * e5;
    const K = KA + KB;
    rows[base + 28] = K > 0 ? 1 / K : 0;
    rows[base + 29] = KA;
    rows[base + 30] = KB;
  }

  /**
   * {@link ContactSolver.warmStart}; for n = 4 written out (row stride 31: dir at 0, I⁻¹J_A at 16,
   * I⁻¹J_B at 22): the same arithmetic in the same order, so bit-identical to the general loop;
   * the velocities of the two bodies stay in locals for the whole manifold instead of being read
   * and written back in memory by every point (8 of them on a resting face).
   */
  override warmStart(sb: SolverBodies): void {
    if (!this.writtenOut || this.n !== 4) {
      super.warmStart(sb);
      return;
    }
    const V = sb.v;
    const W = sb.w;
    const rows = this.rows;
    const patch = this.patchRows;
    const lambdaN = this.lambdaN;
    const lambdaP = this.lambdaP;
    const lambdaW = this.lambdaW;
    for (let mf = 0; mf < this.mfCount; mf += 1) {
      const a = this.mfA[mf];
      const b = this.mfB[mf];
      const ima = sb.invMass[a];
      const imb = sb.invMass[b];
      const va = a * 4;
      const vb = b * 4;
      const wa = a * 6;
      const wb = b * 6;
      let vax = V[va],
        vay = V[va + 1],
        vaz = V[va + 2],
        vaw = V[va + 3];
      let vbx = V[vb],
        vby = V[vb + 1],
        vbz = V[vb + 2],
        vbw = V[vb + 3];
      let wa0 = W[wa],
        wa1 = W[wa + 1],
        wa2 = W[wa + 2],
        wa3 = W[wa + 3],
        wa4 = W[wa + 4],
        wa5 = W[wa + 5];
      let wb0 = W[wb],
        wb1 = W[wb + 1],
        wb2 = W[wb + 2],
        wb3 = W[wb + 3],
        wb4 = W[wb + 4],
        wb5 = W[wb + 5];
      const first = this.mfFirst[mf];
      const last = first + this.mfPoints[mf];
      for (let cp = first; cp < last; cp += 1) {
        const lambda = lambdaN[cp];
        if (lambda === 0) continue;
        const base = cp * 31;
        const la = lambda * ima;
        const lb = lambda * imb;
        vax -= la * rows[base];
        vbx += lb * rows[base];
        vay -= la * rows[base + 1];
        vby += lb * rows[base + 1];
        vaz -= la * rows[base + 2];
        vbz += lb * rows[base + 2];
        vaw -= la * rows[base + 3];
        vbw += lb * rows[base + 3];
        wa0 -= lambda * rows[base + 16];
        wb0 += lambda * rows[base + 22];
        wa1 -= lambda * rows[base + 17];
        wb1 += lambda * rows[base + 23];
        wa2 -= lambda * rows[base + 18];
        wb2 += lambda * rows[base + 24];
        wa3 -= lambda * rows[base + 19];
        wb3 += lambda * rows[base + 25];
        wa4 -= lambda * rows[base + 20];
        wb4 += lambda * rows[base + 26];
        wa5 -= lambda * rows[base + 21];
        wb5 += lambda * rows[base + 27];
      }
      // the patch: tangent rows (linear and angular), then twist rows (angular only)
      for (let r = 0; r < 6; r += 1) {
        const lambda = r < 3 ? lambdaP[mf * 3 + r] : lambdaW[mf * 3 + r - 3];
        if (lambda === 0) continue;
        const base = (mf * 6 + r) * 31;
        if (r < 3) {
          const la = lambda * ima;
          const lb = lambda * imb;
          vax -= la * patch[base];
          vbx += lb * patch[base];
          vay -= la * patch[base + 1];
          vby += lb * patch[base + 1];
          vaz -= la * patch[base + 2];
          vbz += lb * patch[base + 2];
          vaw -= la * patch[base + 3];
          vbw += lb * patch[base + 3];
        }
        wa0 -= lambda * patch[base + 16];
        wb0 += lambda * patch[base + 22];
        wa1 -= lambda * patch[base + 17];
        wb1 += lambda * patch[base + 23];
        wa2 -= lambda * patch[base + 18];
        wb2 += lambda * patch[base + 24];
        wa3 -= lambda * patch[base + 19];
        wb3 += lambda * patch[base + 25];
        wa4 -= lambda * patch[base + 20];
        wb4 += lambda * patch[base + 26];
        wa5 -= lambda * patch[base + 21];
        wb5 += lambda * patch[base + 27];
      }
      // Slot 0 (the immovable body) only ever receives zero changes; writing them is harmless.
      V[va] = vax;
      V[va + 1] = vay;
      V[va + 2] = vaz;
      V[va + 3] = vaw;
      W[wa] = wa0;
      W[wa + 1] = wa1;
      W[wa + 2] = wa2;
      W[wa + 3] = wa3;
      W[wa + 4] = wa4;
      W[wa + 5] = wa5;
      V[vb] = vbx;
      V[vb + 1] = vby;
      V[vb + 2] = vbz;
      V[vb + 3] = vbw;
      W[wb] = wb0;
      W[wb + 1] = wb1;
      W[wb + 2] = wb2;
      W[wb + 3] = wb3;
      W[wb + 4] = wb4;
      W[wb + 5] = wb5;
    }
  }

  /**
   * {@link ContactSolver.store}; for n = 4 with the patch projection written out (the same sums
   * in the same order as the general loops).
   */
  override store(contacts: ContactSet): void {
    if (!this.writtenOut || this.n !== 4) {
      super.store(contacts);
      return;
    }
    const P = contacts.pointCapacity;
    const patch = this.patchRows;
    const shocked = this.shocked;
    this.shocked = false;
    const lambdaP = this.lambdaP;
    const lambdaW = this.lambdaW;
    const PT = contacts.patchTangent;
    const PW = contacts.patchTwist;
    for (let mf = 0; mf < this.mfCount; mf += 1) {
      const slot = this.mfContact[mf];
      const first = this.mfFirst[mf];
      const count = this.mfPoints[mf];
      for (let pq = 0; pq < count; pq += 1) {
        const cp = first + pq;
        const ni = slot * P + pq;
        contacts.normalImpulse[ni] = shocked ? Math.max(0, this.lambdaN[cp] - this.keptN[cp]) : this.lambdaN[cp];
        contacts.approachSpeed[ni] = this.sep[cp] > this.bounceGap[cp] && this.maxLambda[cp] > 0 ? this.vnStop[cp] : 0;
      }
      // The patch as a world vector and a world bivector: they survive a change of tangent basis.
      const pb = mf * 186;
      const m3 = mf * 3;
      const l1 = lambdaP[m3] - (shocked ? this.keptP[m3] : 0);
      const l2 = lambdaP[m3 + 1] - (shocked ? this.keptP[m3 + 1] : 0);
      const l3 = lambdaP[m3 + 2] - (shocked ? this.keptP[m3 + 2] : 0);
      const ti = slot * 4;
      for (let d = 0; d < 4; d += 1) PT[ti + d] = 0 + l1 * patch[pb + d] + l2 * patch[pb + 31 + d] + l3 * patch[pb + 62 + d];
      const w1 = lambdaW[m3] - (shocked ? this.keptW[m3] : 0);
      const w2 = lambdaW[m3 + 1] - (shocked ? this.keptW[m3 + 1] : 0);
      const w3 = lambdaW[m3 + 2] - (shocked ? this.keptW[m3 + 2] : 0);
      const wi = slot * 6;
      for (let pl = 0; pl < 6; pl += 1) {
        PW[wi + pl] = 0 + w1 * patch[pb + 97 + pl] + w2 * patch[pb + 128 + pl] + w3 * patch[pb + 159 + pl];
      }
    }
  }

  /** {@link ContactSolver.buildRow} for any n: the general loop. */
  private buildRowGeneral(rows: Float64Array, base: number, a: number, b: number, sb: SolverBodies): void {
    const { n, k } = this;
    const planeI = this.D.planeI;
    const planeJ = this.D.planeJ;
    const rA = this.rA;
    const rB = this.rB;
    const imA = sb.invMass[a];
    const imB = sb.invMass[b];
    const IA = a * k * k;
    const IB = b * k * k;
    const IW = sb.invInertia;
    // s ≥ 0 when the body's I⁻¹ is s·identity (then I⁻¹J = s·J), else −1 (see SolverBodies).
    const isoA = sb.isoInvInertia[a];
    const isoB = sb.isoInvInertia[b];
    // J = r ∧ dir
    for (let pl = 0; pl < k; pl += 1) {
      const pi = planeI[pl];
      const pj = planeJ[pl];
      const di = rows[base + pi];
      const dj = rows[base + pj];
      rows[base + n + pl] = rA[pi] * dj - rA[pj] * di;
      rows[base + n + k + pl] = rB[pi] * dj - rB[pj] * di;
    }
    // I⁻¹J and K = 1/m + J·I⁻¹J per body
    let KA = imA;
    let KB = imB;
    for (let row = 0; row < k; row += 1) {
      let sa = 0;
      let sbv = 0;
      if (isoA >= 0) sa = isoA * rows[base + n + row];
      else for (let col = 0; col < k; col += 1) sa += IW[IA + row * k + col] * rows[base + n + col];
      if (isoB >= 0) sbv = isoB * rows[base + n + k + row];
      else for (let col = 0; col < k; col += 1) sbv += IW[IB + row * k + col] * rows[base + n + k + col];
      rows[base + n + 2 * k + row] = sa;
      rows[base + n + 3 * k + row] = sbv;
      KA += sa * rows[base + n + row];
      KB += sbv * rows[base + n + k + row];
    }
    const K = KA + KB;
    rows[base + n + 4 * k] = K > 0 ? 1 / K : 0;
    rows[base + n + 4 * k + 1] = KA;
    rows[base + n + 4 * k + 2] = KB;
  }

  protected override solveManifold(sb: SolverBodies, mf: number, shock: boolean): void {
    if (this.writtenOut && this.n === 3) super.solveManifold(sb, mf, shock);
    else if (this.writtenOut && this.n === 4) this.solveManifold4(sb, mf, shock);
    else this.solveManifoldGeneral(sb, mf, shock);
  }

  /**
   * {@link ContactSolver.solveManifold} for any n: the general loop. The row velocity and the
   * impulse are written out inline: this is the innermost loop of the engine.
   */
  private solveManifoldGeneral(sb: SolverBodies, mf: number, shock: boolean): void {
    const { n, k, m, q, PR, RS } = this;
    const rows = this.rows;
    const patch = this.patchRows;
    const V = sb.v;
    const W = sb.w;
    const a = this.mfA[mf];
    const b = this.mfB[mf];
    let fa = 1;
    let fb = 1;
    if (shock) {
      const da = sb.depth[a];
      const db = sb.depth[b];
      if (da < db) fa = 0;
      else if (db < da) fb = 0;
    }
    // n = 3: the tall stack's block solve, as the written-out solve does.
    const moveA = fa !== 0 && a !== 0;
    const moveB = fb !== 0 && b !== 0;
    if (shock && n === 3 && moveA !== moveB && this.tallShock && this.solveBlock(sb, mf, moveA ? a : b, moveB)) return;
    const ima = fa * sb.invMass[a];
    const imb = fb * sb.invMass[b];
    const va = a * n;
    const vb = b * n;
    const wa = a * k;
    const wb = b * k;
    const jA = n;
    const jB = n + k;
    const iA = n + 2 * k;
    const iB = n + 3 * k;
    const mu = this.mfFriction[mf];
    const first = this.mfFirst[mf];
    const last = first + this.mfPoints[mf];
    const lambdaN = this.lambdaN;
    const tmp = this.tmp;
    let change = 0;
    if (mu > 0) {
      let sumN = 0;
      for (let cp = first; cp < last; cp += 1) sumN += lambdaN[cp];
      const maxT = mu * sumN;
      const radius = this.mfRadius[mf];
      // block 0: the m tangent rows (limit μΣλ_n); block 1: the q twist rows (limit μΣλ_n·R)
      for (let blk = 0; blk < 2; blk += 1) {
        const twist = blk === 1;
        const count = twist ? (radius > 0 ? q : 0) : m;
        const lam = twist ? this.lambdaW : this.lambdaP;
        const lo = twist ? mf * q : mf * m;
        const rb0 = mf * PR * RS + (twist ? m * RS : 0);
        const limit = twist ? maxT * radius : maxT;
        let norm2 = 0;
        for (let t = 0; t < count; t += 1) {
          const rb = rb0 + t * RS;
          let vt = 0;
          if (!twist) for (let d = 0; d < n; d += 1) vt += patch[rb + d] * (V[vb + d] - V[va + d]);
          for (let pl = 0; pl < k; pl += 1) vt += patch[rb + jB + pl] * W[wb + pl] - patch[rb + jA + pl] * W[wa + pl];
          const K = fa * patch[rb + RS - 2] + fb * patch[rb + RS - 1];
          const nl = K > 0 ? lam[lo + t] - vt / K : lam[lo + t];
          tmp[t] = nl;
          norm2 += nl * nl;
        }
        const scale = norm2 > limit * limit ? limit / Math.sqrt(norm2) : 1;
        for (let t = 0; t < count; t += 1) {
          const nl = tmp[t] * scale;
          const dl = nl - lam[lo + t];
          lam[lo + t] = nl;
          if (dl === 0) continue;
          const rb = rb0 + t * RS;
          const moved = Math.abs(dl) * (fa * patch[rb + RS - 2] + fb * patch[rb + RS - 1]);
          if (moved > change) change = moved;
          if (!twist) {
            const la = ima * dl;
            const lb = imb * dl;
            for (let d = 0; d < n; d += 1) {
              const dir = patch[rb + d];
              V[va + d] -= la * dir;
              V[vb + d] += lb * dir;
            }
          }
          const ga = fa * dl;
          const gb = fb * dl;
          for (let pl = 0; pl < k; pl += 1) {
            W[wa + pl] -= ga * patch[rb + iA + pl];
            W[wb + pl] += gb * patch[rb + iB + pl];
          }
        }
      }
    }
    // n >= 4: every other pass takes the points last to first (see mfReverse).
    let reverse = 0;
    if (!shock && n >= 4) {
      reverse = this.mfReverse[mf];
      this.mfReverse[mf] = reverse ^ 1;
    }
    for (let i = first; i < last; i += 1) {
      const cp = reverse === 0 ? i : first + last - 1 - i;
      const rb = cp * RS;
      const K = fa * rows[rb + RS - 2] + fb * rows[rb + RS - 1];
      if (!(K > 0)) continue;
      let vn = 0;
      for (let d = 0; d < n; d += 1) vn += rows[rb + d] * (V[vb + d] - V[va + d]);
      for (let pl = 0; pl < k; pl += 1) vn += rows[rb + jB + pl] * W[wb + pl] - rows[rb + jA + pl] * W[wa + pl];
      const old = lambdaN[cp];
      const nl = Math.max(0, old + (this.target[cp] - vn) / K);
      lambdaN[cp] = nl;
      if (nl > this.maxLambda[cp]) this.maxLambda[cp] = nl;
      const dl = nl - old;
      if (dl === 0) continue;
      const moved = Math.abs(dl) * K;
      if (moved > change) change = moved;
      const la = ima * dl;
      const lb = imb * dl;
      for (let d = 0; d < n; d += 1) {
        const dir = rows[rb + d];
        V[va + d] -= la * dir;
        V[vb + d] += lb * dir;
      }
      const ga = fa * dl;
      const gb = fb * dl;
      for (let pl = 0; pl < k; pl += 1) {
        W[wa + pl] -= ga * rows[rb + iA + pl];
        W[wb + pl] += gb * rows[rb + iB + pl];
      }
    }
    if (change > this.constants[SOLVE_CHANGE]) this.constants[SOLVE_CHANGE] = change;
  }

  /**
   * {@link ContactSolver.solveManifold} for n = 4, written out (k = 6, 3 tangent and 3 twist
   * rows, row stride 31): the same arithmetic in the same order, so results are bit-identical
   * to the general loop; the velocities of the two bodies stay in locals for the whole manifold.
   * (Generated from the general loop; keep the two in step.)
   */
  private solveManifold4(sb: SolverBodies, mf: number, shock: boolean): void {
    const rows = this.rows;
    const patch = this.patchRows;
    const V = sb.v;
    const W = sb.w;
    const a = this.mfA[mf];
    const b = this.mfB[mf];
    let fa = 1;
    let fb = 1;
    if (shock) {
      const da = sb.depth[a];
      const db = sb.depth[b];
      if (da < db) fa = 0;
      else if (db < da) fb = 0;
    }
    const ima = fa * sb.invMass[a];
    const imb = fb * sb.invMass[b];
    const va = a * 4;
    const vb = b * 4;
    const wa = a * 6;
    const wb = b * 6;
    let vax = V[va],
      vay = V[va + 1],
      vaz = V[va + 2],
      vaw = V[va + 3];
    let vbx = V[vb],
      vby = V[vb + 1],
      vbz = V[vb + 2],
      vbw = V[vb + 3];
    let wa0 = W[wa],
      wa1 = W[wa + 1],
      wa2 = W[wa + 2],
      wa3 = W[wa + 3],
      wa4 = W[wa + 4],
      wa5 = W[wa + 5];
    let wb0 = W[wb],
      wb1 = W[wb + 1],
      wb2 = W[wb + 2],
      wb3 = W[wb + 3],
      wb4 = W[wb + 4],
      wb5 = W[wb + 5];
    const mu = this.mfFriction[mf];
    const first = this.mfFirst[mf];
    const last = first + this.mfPoints[mf];
    const lambdaN = this.lambdaN;
    const lambdaP = this.lambdaP;
    const lambdaW = this.lambdaW;
    const target = this.target;
    const maxLambda = this.maxLambda;
    let change = 0;
    if (mu > 0) {
      let sumN = 0;
      for (let cp = first; cp < last; cp += 1) sumN += lambdaN[cp];
      const maxT = mu * sumN;
      const radius = this.mfRadius[mf];
      const pb = mf * 186;
      const t1 = pb;
      const t2 = pb + 31;
      const t3 = pb + 62;
      {
        const v1 =
          patch[t1] * (vbx - vax) +
          patch[t1 + 1] * (vby - vay) +
          patch[t1 + 2] * (vbz - vaz) +
          patch[t1 + 3] * (vbw - vaw) +
          (patch[t1 + 10] * wb0 - patch[t1 + 4] * wa0) +
          (patch[t1 + 11] * wb1 - patch[t1 + 5] * wa1) +
          (patch[t1 + 12] * wb2 - patch[t1 + 6] * wa2) +
          (patch[t1 + 13] * wb3 - patch[t1 + 7] * wa3) +
          (patch[t1 + 14] * wb4 - patch[t1 + 8] * wa4) +
          (patch[t1 + 15] * wb5 - patch[t1 + 9] * wa5);
        const v2 =
          patch[t2] * (vbx - vax) +
          patch[t2 + 1] * (vby - vay) +
          patch[t2 + 2] * (vbz - vaz) +
          patch[t2 + 3] * (vbw - vaw) +
          (patch[t2 + 10] * wb0 - patch[t2 + 4] * wa0) +
          (patch[t2 + 11] * wb1 - patch[t2 + 5] * wa1) +
          (patch[t2 + 12] * wb2 - patch[t2 + 6] * wa2) +
          (patch[t2 + 13] * wb3 - patch[t2 + 7] * wa3) +
          (patch[t2 + 14] * wb4 - patch[t2 + 8] * wa4) +
          (patch[t2 + 15] * wb5 - patch[t2 + 9] * wa5);
        const v3 =
          patch[t3] * (vbx - vax) +
          patch[t3 + 1] * (vby - vay) +
          patch[t3 + 2] * (vbz - vaz) +
          patch[t3 + 3] * (vbw - vaw) +
          (patch[t3 + 10] * wb0 - patch[t3 + 4] * wa0) +
          (patch[t3 + 11] * wb1 - patch[t3 + 5] * wa1) +
          (patch[t3 + 12] * wb2 - patch[t3 + 6] * wa2) +
          (patch[t3 + 13] * wb3 - patch[t3 + 7] * wa3) +
          (patch[t3 + 14] * wb4 - patch[t3 + 8] * wa4) +
          (patch[t3 + 15] * wb5 - patch[t3 + 9] * wa5);
        const K1 = fa * patch[t1 + 29] + fb * patch[t1 + 30];
        const K2 = fa * patch[t2 + 29] + fb * patch[t2 + 30];
        const K3 = fa * patch[t3 + 29] + fb * patch[t3 + 30];
        const o1 = lambdaP[mf * 3];
        const o2 = lambdaP[mf * 3 + 1];
        const o3 = lambdaP[mf * 3 + 2];
        let n1 = K1 > 0 ? o1 - v1 / K1 : o1;
        let n2 = K2 > 0 ? o2 - v2 / K2 : o2;
        let n3 = K3 > 0 ? o3 - v3 / K3 : o3;
        const norm2 = n1 * n1 + n2 * n2 + n3 * n3;
        if (norm2 > maxT * maxT) {
          const scale = maxT / Math.sqrt(norm2);
          n1 *= scale;
          n2 *= scale;
          n3 *= scale;
        }
        lambdaP[mf * 3] = n1;
        lambdaP[mf * 3 + 1] = n2;
        lambdaP[mf * 3 + 2] = n3;
        const d1 = n1 - o1;
        const d2 = n2 - o2;
        const d3 = n3 - o3;
        // Applied one row after the other, as the general loop does.
        if (d1 !== 0) {
          const moved = Math.abs(d1) * K1;
          if (moved > change) change = moved;
          const la = ima * d1;
          const lb = imb * d1;
          vax -= la * patch[t1];
          vbx += lb * patch[t1];
          vay -= la * patch[t1 + 1];
          vby += lb * patch[t1 + 1];
          vaz -= la * patch[t1 + 2];
          vbz += lb * patch[t1 + 2];
          vaw -= la * patch[t1 + 3];
          vbw += lb * patch[t1 + 3];
          const ga = fa * d1;
          const gb = fb * d1;
          wa0 -= ga * patch[t1 + 16];
          wb0 += gb * patch[t1 + 22];
          wa1 -= ga * patch[t1 + 17];
          wb1 += gb * patch[t1 + 23];
          wa2 -= ga * patch[t1 + 18];
          wb2 += gb * patch[t1 + 24];
          wa3 -= ga * patch[t1 + 19];
          wb3 += gb * patch[t1 + 25];
          wa4 -= ga * patch[t1 + 20];
          wb4 += gb * patch[t1 + 26];
          wa5 -= ga * patch[t1 + 21];
          wb5 += gb * patch[t1 + 27];
        }
        if (d2 !== 0) {
          const moved = Math.abs(d2) * K2;
          if (moved > change) change = moved;
          const la = ima * d2;
          const lb = imb * d2;
          vax -= la * patch[t2];
          vbx += lb * patch[t2];
          vay -= la * patch[t2 + 1];
          vby += lb * patch[t2 + 1];
          vaz -= la * patch[t2 + 2];
          vbz += lb * patch[t2 + 2];
          vaw -= la * patch[t2 + 3];
          vbw += lb * patch[t2 + 3];
          const ga = fa * d2;
          const gb = fb * d2;
          wa0 -= ga * patch[t2 + 16];
          wb0 += gb * patch[t2 + 22];
          wa1 -= ga * patch[t2 + 17];
          wb1 += gb * patch[t2 + 23];
          wa2 -= ga * patch[t2 + 18];
          wb2 += gb * patch[t2 + 24];
          wa3 -= ga * patch[t2 + 19];
          wb3 += gb * patch[t2 + 25];
          wa4 -= ga * patch[t2 + 20];
          wb4 += gb * patch[t2 + 26];
          wa5 -= ga * patch[t2 + 21];
          wb5 += gb * patch[t2 + 27];
        }
        if (d3 !== 0) {
          const moved = Math.abs(d3) * K3;
          if (moved > change) change = moved;
          const la = ima * d3;
          const lb = imb * d3;
          vax -= la * patch[t3];
          vbx += lb * patch[t3];
          vay -= la * patch[t3 + 1];
          vby += lb * patch[t3 + 1];
          vaz -= la * patch[t3 + 2];
          vbz += lb * patch[t3 + 2];
          vaw -= la * patch[t3 + 3];
          vbw += lb * patch[t3 + 3];
          const ga = fa * d3;
          const gb = fb * d3;
          wa0 -= ga * patch[t3 + 16];
          wb0 += gb * patch[t3 + 22];
          wa1 -= ga * patch[t3 + 17];
          wb1 += gb * patch[t3 + 23];
          wa2 -= ga * patch[t3 + 18];
          wb2 += gb * patch[t3 + 24];
          wa3 -= ga * patch[t3 + 19];
          wb3 += gb * patch[t3 + 25];
          wa4 -= ga * patch[t3 + 20];
          wb4 += gb * patch[t3 + 26];
          wa5 -= ga * patch[t3 + 21];
          wb5 += gb * patch[t3 + 27];
        }
      }
      if (radius > 0) {
        const limit = maxT * radius;
        const w1 = pb + 93;
        const w2 = pb + 124;
        const w3 = pb + 155;
        const v1 =
          patch[w1 + 10] * wb0 -
          patch[w1 + 4] * wa0 +
          (patch[w1 + 11] * wb1 - patch[w1 + 5] * wa1) +
          (patch[w1 + 12] * wb2 - patch[w1 + 6] * wa2) +
          (patch[w1 + 13] * wb3 - patch[w1 + 7] * wa3) +
          (patch[w1 + 14] * wb4 - patch[w1 + 8] * wa4) +
          (patch[w1 + 15] * wb5 - patch[w1 + 9] * wa5);
        const v2 =
          patch[w2 + 10] * wb0 -
          patch[w2 + 4] * wa0 +
          (patch[w2 + 11] * wb1 - patch[w2 + 5] * wa1) +
          (patch[w2 + 12] * wb2 - patch[w2 + 6] * wa2) +
          (patch[w2 + 13] * wb3 - patch[w2 + 7] * wa3) +
          (patch[w2 + 14] * wb4 - patch[w2 + 8] * wa4) +
          (patch[w2 + 15] * wb5 - patch[w2 + 9] * wa5);
        const v3 =
          patch[w3 + 10] * wb0 -
          patch[w3 + 4] * wa0 +
          (patch[w3 + 11] * wb1 - patch[w3 + 5] * wa1) +
          (patch[w3 + 12] * wb2 - patch[w3 + 6] * wa2) +
          (patch[w3 + 13] * wb3 - patch[w3 + 7] * wa3) +
          (patch[w3 + 14] * wb4 - patch[w3 + 8] * wa4) +
          (patch[w3 + 15] * wb5 - patch[w3 + 9] * wa5);
        const K1 = fa * patch[w1 + 29] + fb * patch[w1 + 30];
        const K2 = fa * patch[w2 + 29] + fb * patch[w2 + 30];
        const K3 = fa * patch[w3 + 29] + fb * patch[w3 + 30];
        const o1 = lambdaW[mf * 3];
        const o2 = lambdaW[mf * 3 + 1];
        const o3 = lambdaW[mf * 3 + 2];
        let n1 = K1 > 0 ? o1 - v1 / K1 : o1;
        let n2 = K2 > 0 ? o2 - v2 / K2 : o2;
        let n3 = K3 > 0 ? o3 - v3 / K3 : o3;
        const norm2 = n1 * n1 + n2 * n2 + n3 * n3;
        if (norm2 > limit * limit) {
          const scale = limit / Math.sqrt(norm2);
          n1 *= scale;
          n2 *= scale;
          n3 *= scale;
        }
        lambdaW[mf * 3] = n1;
        lambdaW[mf * 3 + 1] = n2;
        lambdaW[mf * 3 + 2] = n3;
        const d1 = n1 - o1;
        const d2 = n2 - o2;
        const d3 = n3 - o3;
        // Applied one row after the other, as the general loop does.
        if (d1 !== 0) {
          const moved = Math.abs(d1) * K1;
          if (moved > change) change = moved;
          const ga = fa * d1;
          const gb = fb * d1;
          wa0 -= ga * patch[w1 + 16];
          wb0 += gb * patch[w1 + 22];
          wa1 -= ga * patch[w1 + 17];
          wb1 += gb * patch[w1 + 23];
          wa2 -= ga * patch[w1 + 18];
          wb2 += gb * patch[w1 + 24];
          wa3 -= ga * patch[w1 + 19];
          wb3 += gb * patch[w1 + 25];
          wa4 -= ga * patch[w1 + 20];
          wb4 += gb * patch[w1 + 26];
          wa5 -= ga * patch[w1 + 21];
          wb5 += gb * patch[w1 + 27];
        }
        if (d2 !== 0) {
          const moved = Math.abs(d2) * K2;
          if (moved > change) change = moved;
          const ga = fa * d2;
          const gb = fb * d2;
          wa0 -= ga * patch[w2 + 16];
          wb0 += gb * patch[w2 + 22];
          wa1 -= ga * patch[w2 + 17];
          wb1 += gb * patch[w2 + 23];
          wa2 -= ga * patch[w2 + 18];
          wb2 += gb * patch[w2 + 24];
          wa3 -= ga * patch[w2 + 19];
          wb3 += gb * patch[w2 + 25];
          wa4 -= ga * patch[w2 + 20];
          wb4 += gb * patch[w2 + 26];
          wa5 -= ga * patch[w2 + 21];
          wb5 += gb * patch[w2 + 27];
        }
        if (d3 !== 0) {
          const moved = Math.abs(d3) * K3;
          if (moved > change) change = moved;
          const ga = fa * d3;
          const gb = fb * d3;
          wa0 -= ga * patch[w3 + 16];
          wb0 += gb * patch[w3 + 22];
          wa1 -= ga * patch[w3 + 17];
          wb1 += gb * patch[w3 + 23];
          wa2 -= ga * patch[w3 + 18];
          wb2 += gb * patch[w3 + 24];
          wa3 -= ga * patch[w3 + 19];
          wb3 += gb * patch[w3 + 25];
          wa4 -= ga * patch[w3 + 20];
          wb4 += gb * patch[w3 + 26];
          wa5 -= ga * patch[w3 + 21];
          wb5 += gb * patch[w3 + 27];
        }
      }
    }
    // Every other pass takes the points last to first (see mfReverse).
    let reverse = 0;
    if (!shock) {
      reverse = this.mfReverse[mf];
      this.mfReverse[mf] = reverse ^ 1;
    }
    for (let i = first; i < last; i += 1) {
      const cp = reverse === 0 ? i : first + last - 1 - i;
      const rb = cp * 31;
      const K = fa * rows[rb + 29] + fb * rows[rb + 30];
      if (!(K > 0)) continue;
      const vn =
        rows[rb] * (vbx - vax) +
        rows[rb + 1] * (vby - vay) +
        rows[rb + 2] * (vbz - vaz) +
        rows[rb + 3] * (vbw - vaw) +
        (rows[rb + 10] * wb0 - rows[rb + 4] * wa0) +
        (rows[rb + 11] * wb1 - rows[rb + 5] * wa1) +
        (rows[rb + 12] * wb2 - rows[rb + 6] * wa2) +
        (rows[rb + 13] * wb3 - rows[rb + 7] * wa3) +
        (rows[rb + 14] * wb4 - rows[rb + 8] * wa4) +
        (rows[rb + 15] * wb5 - rows[rb + 9] * wa5);
      const old = lambdaN[cp];
      const nl = Math.max(0, old + (target[cp] - vn) / K);
      lambdaN[cp] = nl;
      if (nl > maxLambda[cp]) maxLambda[cp] = nl;
      const dl = nl - old;
      if (dl === 0) continue;
      const moved = Math.abs(dl) * K;
      if (moved > change) change = moved;
      const la = ima * dl;
      const lb = imb * dl;
      vax -= la * rows[rb];
      vbx += lb * rows[rb];
      vay -= la * rows[rb + 1];
      vby += lb * rows[rb + 1];
      vaz -= la * rows[rb + 2];
      vbz += lb * rows[rb + 2];
      vaw -= la * rows[rb + 3];
      vbw += lb * rows[rb + 3];
      const ga = fa * dl;
      const gb = fb * dl;
      wa0 -= ga * rows[rb + 16];
      wb0 += gb * rows[rb + 22];
      wa1 -= ga * rows[rb + 17];
      wb1 += gb * rows[rb + 23];
      wa2 -= ga * rows[rb + 18];
      wb2 += gb * rows[rb + 24];
      wa3 -= ga * rows[rb + 19];
      wb3 += gb * rows[rb + 25];
      wa4 -= ga * rows[rb + 20];
      wb4 += gb * rows[rb + 26];
      wa5 -= ga * rows[rb + 21];
      wb5 += gb * rows[rb + 27];
    }
    // Slot 0 (the immovable body) only ever receives zero changes; writing them is harmless.
    V[va] = vax;
    V[va + 1] = vay;
    V[va + 2] = vaz;
    V[va + 3] = vaw;
    W[wa] = wa0;
    W[wa + 1] = wa1;
    W[wa + 2] = wa2;
    W[wa + 3] = wa3;
    W[wa + 4] = wa4;
    W[wa + 5] = wa5;
    V[vb] = vbx;
    V[vb + 1] = vby;
    V[vb + 2] = vbz;
    V[vb + 3] = vbw;
    W[wb] = wb0;
    W[wb + 1] = wb1;
    W[wb + 2] = wb2;
    W[wb + 3] = wb3;
    W[wb + 4] = wb4;
    W[wb + 5] = wb5;
    if (change > this.constants[SOLVE_CHANGE]) this.constants[SOLVE_CHANGE] = change;
  }
}
