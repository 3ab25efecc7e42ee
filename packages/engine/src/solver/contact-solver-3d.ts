/**
 * The contact solver of 3D: {@link ContactSolver} with the rows and the manifold solve written out
 * for n = 3 (k = 3, 2 tangent and 1 twist row, row stride 18). `@physin/engine/3d` builds its
 * world with this one alone, so a 3D app carries neither the 4D copies nor the general loop;
 * `@physin/engine` builds its worlds with {@link ContactSolverND}, which extends this one.
 *
 * Both copies do the same arithmetic in the same order as the general loop of
 * contact-solver-nd.ts, so results are bit-identical to it (generated from it; keep them in step).
 *
 * @module
 */
import { growFloat64, growInt32 } from '../contacts/contact-set.js';
import { ContactSolver, SOLVE_CHANGE, SOLVE_TOLERANCE } from './contact-solver.js';
import type { SolverBodies } from './solver-bodies.js';

/** Rows of the shock block solve at most: 2 tangent, 1 twist, 4 normal (see solveBlock). */
const BLOCK_ROWS = 7;
/** A pivot of the block solve below this share of its row's K marks a redundant row. */
const BLOCK_PIVOT = 1e-6;
/** Numbers of one manifold's block factors: L's 21 below the diagonal, then D's 7. */
const BLOCK_LD = 28;

/** The contact solver for n = 3 alone (see the module comment). */
export class ContactSolver3 extends ContactSolver {
  /** @internal The block solve's K = J M⁻¹ Jᵀ of one manifold (see solveBlock). */
  private readonly blockK = new Float64Array(BLOCK_ROWS * BLOCK_ROWS);
  /** @internal The block solve's right-hand side, then its Δλ. */
  private readonly blockX = new Float64Array(BLOCK_ROWS);
  /** @internal The impulses a redundant row leaves free (K ν = 0). */
  private readonly blockNu = new Float64Array(BLOCK_ROWS);
  /**
   * @internal Per manifold, the LDLᵀ factors of its block in this sub-step's shock passes: L's
   * lower triangle row by row (21 numbers), then the pivots D (7).
   */
  private blockLD = new Float64Array(16 * BLOCK_LD);
  /**
   * @internal Per manifold, `blockEpoch` when blockLD holds its factors for this sub-step's shock
   * passes, −`blockEpoch` when it has no block (no points, or more rows than BLOCK_ROWS), else older.
   */
  private blockStamp = new Int32Array(16);
  /** @internal Counts the sub-steps' shock propagations (the stamps of blockLD). */
  private blockEpoch = 0;

  /** {@link ContactSolver.ensureManifolds}, and the block factors' room for n = 3. */
  protected override ensureManifolds(need: number): void {
    super.ensureManifolds(need);
    if (this.n === 3 && need > this.blockStamp.length) {
      this.blockStamp = growInt32(this.blockStamp, need);
      this.blockLD = growFloat64(this.blockLD, need * BLOCK_LD, 0);
    }
  }

  /** {@link ContactSolver.shockPropagate}, the block factors of the sub-step before made stale. */
  override shockPropagate(sb: SolverBodies, passes: number): void {
    this.blockEpoch += 1;
    super.shockPropagate(sb, passes);
  }

  /**
   * A shock pass's manifold whose other body is frozen or immovable, solved whole: the friction
   * patch (2 tangent rows, the twist row) and the normal rows together, for the impulses that
   * bring every row to its target at once, a redundant row (a face's 4 points are 4 rows for 3
   * degrees of freedom) left at its impulse. Gauss–Seidel takes these rows one at a time and
   * converges at about 0.55× a sweep. Kept only when the impulses are admissible (normals ≥ 0, the
   * patch inside its cone): returns whether they were; otherwise the visit is left to
   * Gauss–Seidel. `x` is the moving body, `onB` whether it is body B. Tall stacks only: in a short
   * one the factoring costs more than the 3 inner sweeps it saves.
   * @internal
   */
  protected solveBlock(sb: SolverBodies, mf: number, x: number, onB: boolean): boolean {
    const epoch = this.blockEpoch;
    const stamp = this.blockStamp[mf];
    if (stamp === -epoch) return false;
    const points = this.mfPoints[mf];
    const mu = this.mfFriction[mf];
    const radius = this.mfRadius[mf];
    const nf = mu > 0 ? (radius > 0 ? 3 : 2) : 0;
    const nr = nf + points;
    if (points === 0 || nr > BLOCK_ROWS) {
      this.blockStamp[mf] = -epoch;
      return false;
    }
    const rows = this.rows;
    const patch = this.patchRows;
    const LD = this.blockLD;
    const lo = mf * BLOCK_LD;
    const jo = onB ? 6 : 3;
    const io = onB ? 12 : 9;
    const im = sb.invMass[x];
    const first = this.mfFirst[mf];
    const pb = mf * 54 - (first - nf) * 18;
    if (stamp !== epoch) {
      this.blockStamp[mf] = epoch;
      const K = this.blockK;
      for (let i = 0; i < nr; i += 1) {
        const si = i < nf ? patch : rows;
        const bi = (i < nf ? pb : 0) + (first + i - nf) * 18;
        const li = i !== 2 || nf !== 3 ? im : 0;
        for (let j = 0; j <= i; j += 1) {
          const sj = j < nf ? patch : rows;
          const bj = (j < nf ? pb : 0) + (first + j - nf) * 18;
          const lin = j !== 2 || nf !== 3 ? li : 0;
          K[i * BLOCK_ROWS + j] =
            lin * (si[bi] * sj[bj] + si[bi + 1] * sj[bj + 1] + si[bi + 2] * sj[bj + 2]) +
            (si[bi + jo] * sj[bj + io] + si[bi + jo + 1] * sj[bj + io + 1] + si[bi + jo + 2] * sj[bj + io + 2]);
        }
      }
      // LDLᵀ; a pivot that is (nearly) spanned by the rows before it marks a redundant row: its
      // column of L is zero and its Δλ 0.
      for (let j = 0; j < nr; j += 1) {
        const kjj = K[j * BLOCK_ROWS + j];
        const lj = lo + ((j * (j - 1)) >> 1);
        let djj = kjj;
        for (let k = 0; k < j; k += 1) djj -= LD[lj + k] * LD[lj + k] * LD[lo + 21 + k];
        const keep = djj > BLOCK_PIVOT * kjj;
        LD[lo + 21 + j] = keep ? djj : 0;
        for (let i = j + 1; i < nr; i += 1) {
          const li = lo + ((i * (i - 1)) >> 1);
          let s = 0;
          if (keep) {
            s = K[i * BLOCK_ROWS + j];
            for (let k = 0; k < j; k += 1) s -= LD[li + k] * LD[lj + k] * LD[lo + 21 + k];
            s /= djj;
          }
          LD[li + j] = s;
        }
      }
    }
    const V = sb.v;
    const W = sb.w;
    const a = this.mfA[mf];
    const b = this.mfB[mf];
    const X = this.blockX;
    const lambdaN = this.lambdaN;
    const target = this.target;
    const dvx = V[b * 3] - V[a * 3];
    const dvy = V[b * 3 + 1] - V[a * 3 + 1];
    const dvz = V[b * 3 + 2] - V[a * 3 + 2];
    const wa0 = W[a * 3];
    const wa1 = W[a * 3 + 1];
    const wa2 = W[a * 3 + 2];
    const wb0 = W[b * 3];
    const wb1 = W[b * 3 + 1];
    const wb2 = W[b * 3 + 2];
    for (let r = 0; r < nr; r += 1) {
      const src = r < nf ? patch : rows;
      const base = (r < nf ? pb : 0) + (first + r - nf) * 18;
      const lin = r !== 2 || nf !== 3 ? 1 : 0;
      const v =
        lin * (src[base] * dvx + src[base + 1] * dvy + src[base + 2] * dvz) +
        (src[base + 6] * wb0 - src[base + 3] * wa0) +
        (src[base + 7] * wb1 - src[base + 4] * wa1) +
        (src[base + 8] * wb2 - src[base + 5] * wa2);
      // Forward substitution as the right-hand side is formed.
      let y = r < nf ? -v : target[first + r - nf] - v;
      const lr = lo + ((r * (r - 1)) >> 1);
      for (let k = 0; k < r; k += 1) y -= LD[lr + k] * X[k];
      X[r] = y;
    }
    for (let i = 0; i < nr; i += 1) {
      const d = LD[lo + 21 + i];
      X[i] = d > 0 ? X[i] / d : 0;
    }
    for (let i = nr - 1; i >= 0; i -= 1) for (let k = i + 1; k < nr; k += 1) X[i] -= LD[lo + ((k * (k - 1)) >> 1) + i] * X[k];
    // A redundant normal row leaves one impulse free (K ν = 0): where the solve left a point
    // pulling, the smallest shift along ν that makes every normal impulse ≥ 0, if one does.
    let free = -1;
    let pulling = false;
    for (let r = nf; r < nr; r += 1) {
      if (LD[lo + 21 + r] === 0) free = r;
      if (lambdaN[first + r - nf] + X[r] < 0) pulling = true;
    }
    if (free >= 0 && pulling) {
      let lowT = -Infinity;
      let highT = Infinity;
      for (let i = nr - 1; i >= 0; i -= 1) {
        let nu = i === free ? 1 : 0;
        if (i < free) for (let k = i + 1; k <= free; k += 1) nu -= LD[lo + ((k * (k - 1)) >> 1) + i] * this.blockNu[k];
        this.blockNu[i] = nu;
        if (i >= nf && nu !== 0) {
          const t = -(lambdaN[first + i - nf] + X[i]) / nu;
          if (nu > 0) lowT = Math.max(lowT, t);
          else highT = Math.min(highT, t);
        }
      }
      const t = lowT > 0 ? lowT : highT < 0 ? highT : 0;
      if (t !== 0 && lowT <= highT) for (let i = 0; i < nr; i += 1) X[i] += t * this.blockNu[i];
    }
    // Admissible?
    let sumN = 0;
    for (let r = nf; r < nr; r += 1) {
      const nl = lambdaN[first + r - nf] + X[r];
      sumN += nl;
      if (!(nl >= 0)) sumN = NaN;
    }
    const lambdaP = this.lambdaP;
    const lambdaW = this.lambdaW;
    let ok = sumN >= 0;
    if (ok && nf > 0) {
      const maxT = mu * sumN;
      const p1 = lambdaP[mf * 2] + X[0];
      const p2 = lambdaP[mf * 2 + 1] + X[1];
      ok = p1 * p1 + p2 * p2 <= maxT * maxT && (nf === 2 || Math.abs(lambdaW[mf] + X[2]) <= maxT * radius);
      if (ok) {
        lambdaP[mf * 2] = p1;
        lambdaP[mf * 2 + 1] = p2;
        if (nf === 3) lambdaW[mf] += X[2];
      }
    }
    if (!ok) return false;
    const bouncy = this.mfRestitution[mf] !== 0;
    const maxLambda = this.maxLambda;
    const tolerance = this.constants[SOLVE_TOLERANCE];
    const ko = onB ? 17 : 16;
    let change = 0;
    let lx = 0;
    let ly = 0;
    let lz = 0;
    let g0 = 0;
    let g1 = 0;
    let g2 = 0;
    for (let r = 0; r < nr; r += 1) {
      const dl = X[r];
      const src = r < nf ? patch : rows;
      const base = (r < nf ? pb : 0) + (first + r - nf) * 18;
      const ll = r !== 2 || nf !== 3 ? dl : 0;
      lx += ll * src[base];
      ly += ll * src[base + 1];
      lz += ll * src[base + 2];
      g0 += dl * src[base + io];
      g1 += dl * src[base + io + 1];
      g2 += dl * src[base + io + 2];
      const moved = Math.abs(dl) * src[base + ko];
      if (moved > tolerance) change = moved;
      if (r >= nf) {
        const cp = first + r - nf;
        const nl = lambdaN[cp] + dl;
        lambdaN[cp] = nl;
        if (bouncy && nl > maxLambda[cp]) maxLambda[cp] = nl;
      }
    }
    const s = onB ? im : -im;
    V[x * 3] += s * lx;
    V[x * 3 + 1] += s * ly;
    V[x * 3 + 2] += s * lz;
    if (onB) {
      W[x * 3] += g0;
      W[x * 3 + 1] += g1;
      W[x * 3 + 2] += g2;
    } else {
      W[x * 3] -= g0;
      W[x * 3 + 1] -= g1;
      W[x * 3 + 2] -= g2;
    }
    if (change > this.constants[SOLVE_CHANGE]) this.constants[SOLVE_CHANGE] = change;
    return true;
  }

  /** {@link ContactSolver.buildRow} for n = 3, written out. */
  protected buildRow(rows: Float64Array, base: number, a: number, b: number, sb: SolverBodies): void {
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
    // The same sums in the same order as the general loop of contact-solver-nd.ts; each sum
    // starts at `0 +` as the loop's does, so a −0 product still sums to +0.
    const d0 = rows[base];
    const d1 = rows[base + 1];
    const d2 = rows[base + 2];
    const ja0 = rA[0] * d1 - rA[1] * d0;
    const jb0 = rB[0] * d1 - rB[1] * d0;
    rows[base + 3] = ja0;
    rows[base + 6] = jb0;
    const ja1 = rA[0] * d2 - rA[2] * d0;
    const jb1 = rB[0] * d2 - rB[2] * d0;
    rows[base + 4] = ja1;
    rows[base + 7] = jb1;
    const ja2 = rA[1] * d2 - rA[2] * d1;
    const jb2 = rB[1] * d2 - rB[2] * d1;
    rows[base + 5] = ja2;
    rows[base + 8] = jb2;
    let KA = imA;
    let KB = imB;
    const sa0 = isoA >= 0 ? isoA * ja0 : 0 + IW[IA] * ja0 + IW[IA + 1] * ja1 + IW[IA + 2] * ja2;
    const sb0 = isoB >= 0 ? isoB * jb0 : 0 + IW[IB] * jb0 + IW[IB + 1] * jb1 + IW[IB + 2] * jb2;
    rows[base + 9] = sa0;
    rows[base + 12] = sb0;
    KA += sa0 * ja0;
    KB += sb0 * jb0;
    const sa1 = isoA >= 0 ? isoA * ja1 : 0 + IW[IA + 3] * ja0 + IW[IA + 4] * ja1 + IW[IA + 5] * ja2;
    const sb1 = isoB >= 0 ? isoB * jb1 : 0 + IW[IB + 3] * jb0 + IW[IB + 4] * jb1 + IW[IB + 5] * jb2;
    rows[base + 10] = sa1;
    rows[base + 13] = sb1;
    KA += sa1 * ja1;
    KB += sb1 * jb1;
    const sa2 = isoA >= 0 ? isoA * ja2 : 0 + IW[IA + 6] * ja0 + IW[IA + 7] * ja1 + IW[IA + 8] * ja2;
    const sb2 = isoB >= 0 ? isoB * jb2 : 0 + IW[IB + 6] * jb0 + IW[IB + 7] * jb1 + IW[IB + 8] * jb2;
    rows[base + 11] = sa2;
    rows[base + 14] = sb2;
    KA += sa2 * ja2;
    KB += sb2 * jb2;
    const K = KA + KB;
    rows[base + 15] = K > 0 ? 1 / K : 0;
    rows[base + 16] = KA;
    rows[base + 17] = KB;
  }

  /**
   * {@link ContactSolver.solveManifold} for n = 3, written out: the velocities of the two bodies
   * stay in locals for the whole manifold.
   */
  protected solveManifold(sb: SolverBodies, mf: number, shock: boolean): void {
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
    // A body frozen in a shock pass, or the immovable body (slot 0), only ever receives zero
    // changes: its updates are skipped.
    const moveA = fa !== 0 && a !== 0;
    const moveB = fb !== 0 && b !== 0;
    if (shock && moveA !== moveB && this.tallShock && this.solveBlock(sb, mf, moveA ? a : b, moveB)) return;
    const va = a * 3;
    const vb = b * 3;
    const wa = a * 3;
    const wb = b * 3;
    let vax = V[va],
      vay = V[va + 1],
      vaz = V[va + 2];
    let vbx = V[vb],
      vby = V[vb + 1],
      vbz = V[vb + 2];
    let wa0 = W[wa],
      wa1 = W[wa + 1],
      wa2 = W[wa + 2];
    let wb0 = W[wb],
      wb1 = W[wb + 1],
      wb2 = W[wb + 2];
    const mu = this.mfFriction[mf];
    const first = this.mfFirst[mf];
    const last = first + this.mfPoints[mf];
    const lambdaN = this.lambdaN;
    const lambdaP = this.lambdaP;
    const lambdaW = this.lambdaW;
    const target = this.target;
    const maxLambda = this.maxLambda;
    // Only restitution and store read maxLambda, and only for a pair that bounces.
    const bouncy = this.mfRestitution[mf] !== 0;
    // The passes only ask whether some row's velocity changed by more than the tolerance: a
    // change above it is kept, not the largest (a compare with a running maximum is a branch
    // the processor mispredicts on every row).
    const tolerance = this.constants[SOLVE_TOLERANCE];
    let change = 0;
    if (mu > 0) {
      let sumN = 0;
      for (let cp = first; cp < last; cp += 1) sumN += lambdaN[cp];
      const maxT = mu * sumN;
      const radius = this.mfRadius[mf];
      const pb = mf * 54;
      const t1 = pb;
      const t2 = pb + 18;
      {
        const v1 =
          patch[t1] * (vbx - vax) +
          patch[t1 + 1] * (vby - vay) +
          patch[t1 + 2] * (vbz - vaz) +
          (patch[t1 + 6] * wb0 - patch[t1 + 3] * wa0) +
          (patch[t1 + 7] * wb1 - patch[t1 + 4] * wa1) +
          (patch[t1 + 8] * wb2 - patch[t1 + 5] * wa2);
        const v2 =
          patch[t2] * (vbx - vax) +
          patch[t2 + 1] * (vby - vay) +
          patch[t2 + 2] * (vbz - vaz) +
          (patch[t2 + 6] * wb0 - patch[t2 + 3] * wa0) +
          (patch[t2 + 7] * wb1 - patch[t2 + 4] * wa1) +
          (patch[t2 + 8] * wb2 - patch[t2 + 5] * wa2);
        const K1 = fa * patch[t1 + 16] + fb * patch[t1 + 17];
        const K2 = fa * patch[t2 + 16] + fb * patch[t2 + 17];
        const o1 = lambdaP[mf * 2];
        const o2 = lambdaP[mf * 2 + 1];
        let n1 = K1 > 0 ? o1 - v1 / K1 : o1;
        let n2 = K2 > 0 ? o2 - v2 / K2 : o2;
        const norm2 = n1 * n1 + n2 * n2;
        if (norm2 > maxT * maxT) {
          const scale = maxT / Math.sqrt(norm2);
          n1 *= scale;
          n2 *= scale;
        }
        lambdaP[mf * 2] = n1;
        lambdaP[mf * 2 + 1] = n2;
        const d1 = n1 - o1;
        const d2 = n2 - o2;
        // Applied one row after the other, as the general loop does.
        if (d1 !== 0) {
          const moved = Math.abs(d1) * K1;
          if (moved > tolerance) change = moved;
          if (moveA) {
            const la = ima * d1;
            vax -= la * patch[t1];
            vay -= la * patch[t1 + 1];
            vaz -= la * patch[t1 + 2];
            const ga = fa * d1;
            wa0 -= ga * patch[t1 + 9];
            wa1 -= ga * patch[t1 + 10];
            wa2 -= ga * patch[t1 + 11];
          }
          if (moveB) {
            const lb = imb * d1;
            vbx += lb * patch[t1];
            vby += lb * patch[t1 + 1];
            vbz += lb * patch[t1 + 2];
            const gb = fb * d1;
            wb0 += gb * patch[t1 + 12];
            wb1 += gb * patch[t1 + 13];
            wb2 += gb * patch[t1 + 14];
          }
        }
        if (d2 !== 0) {
          const moved = Math.abs(d2) * K2;
          if (moved > tolerance) change = moved;
          if (moveA) {
            const la = ima * d2;
            vax -= la * patch[t2];
            vay -= la * patch[t2 + 1];
            vaz -= la * patch[t2 + 2];
            const ga = fa * d2;
            wa0 -= ga * patch[t2 + 9];
            wa1 -= ga * patch[t2 + 10];
            wa2 -= ga * patch[t2 + 11];
          }
          if (moveB) {
            const lb = imb * d2;
            vbx += lb * patch[t2];
            vby += lb * patch[t2 + 1];
            vbz += lb * patch[t2 + 2];
            const gb = fb * d2;
            wb0 += gb * patch[t2 + 12];
            wb1 += gb * patch[t2 + 13];
            wb2 += gb * patch[t2 + 14];
          }
        }
      }
      if (radius > 0) {
        const limit = maxT * radius;
        const w1 = pb + 36;
        const v1 =
          patch[w1 + 6] * wb0 -
          patch[w1 + 3] * wa0 +
          (patch[w1 + 7] * wb1 - patch[w1 + 4] * wa1) +
          (patch[w1 + 8] * wb2 - patch[w1 + 5] * wa2);
        const K1 = fa * patch[w1 + 16] + fb * patch[w1 + 17];
        const o1 = lambdaW[mf];
        let n1 = K1 > 0 ? o1 - v1 / K1 : o1;
        const norm2 = n1 * n1;
        if (norm2 > limit * limit) {
          const scale = limit / Math.sqrt(norm2);
          n1 *= scale;
        }
        lambdaW[mf] = n1;
        const d1 = n1 - o1;
        // Applied one row after the other, as the general loop does.
        if (d1 !== 0) {
          const moved = Math.abs(d1) * K1;
          if (moved > tolerance) change = moved;
          if (moveA) {
            const ga = fa * d1;
            wa0 -= ga * patch[w1 + 9];
            wa1 -= ga * patch[w1 + 10];
            wa2 -= ga * patch[w1 + 11];
          }
          if (moveB) {
            const gb = fb * d1;
            wb0 += gb * patch[w1 + 12];
            wb1 += gb * patch[w1 + 13];
            wb2 += gb * patch[w1 + 14];
          }
        }
      }
    }
    for (let cp = first; cp < last; cp += 1) {
      const rb = cp * 18;
      const K = fa * rows[rb + 16] + fb * rows[rb + 17];
      if (!(K > 0)) continue;
      const vn =
        rows[rb] * (vbx - vax) +
        rows[rb + 1] * (vby - vay) +
        rows[rb + 2] * (vbz - vaz) +
        (rows[rb + 6] * wb0 - rows[rb + 3] * wa0) +
        (rows[rb + 7] * wb1 - rows[rb + 4] * wa1) +
        (rows[rb + 8] * wb2 - rows[rb + 5] * wa2);
      const old = lambdaN[cp];
      const nl = Math.max(0, old + (target[cp] - vn) / K);
      lambdaN[cp] = nl;
      if (bouncy && nl > maxLambda[cp]) maxLambda[cp] = nl;
      const dl = nl - old;
      if (dl === 0) continue;
      const moved = Math.abs(dl) * K;
      if (moved > tolerance) change = moved;
      if (moveA) {
        const la = ima * dl;
        vax -= la * rows[rb];
        vay -= la * rows[rb + 1];
        vaz -= la * rows[rb + 2];
        const ga = fa * dl;
        wa0 -= ga * rows[rb + 9];
        wa1 -= ga * rows[rb + 10];
        wa2 -= ga * rows[rb + 11];
      }
      if (moveB) {
        const lb = imb * dl;
        vbx += lb * rows[rb];
        vby += lb * rows[rb + 1];
        vbz += lb * rows[rb + 2];
        const gb = fb * dl;
        wb0 += gb * rows[rb + 12];
        wb1 += gb * rows[rb + 13];
        wb2 += gb * rows[rb + 14];
      }
    }
    if (moveA) {
      V[va] = vax;
      V[va + 1] = vay;
      V[va + 2] = vaz;
      W[wa] = wa0;
      W[wa + 1] = wa1;
      W[wa + 2] = wa2;
    }
    if (moveB) {
      V[vb] = vbx;
      V[vb + 1] = vby;
      V[vb + 2] = vbz;
      W[wb] = wb0;
      W[wb + 1] = wb1;
      W[wb + 2] = wb2;
    }
    if (change > this.constants[SOLVE_CHANGE]) this.constants[SOLVE_CHANGE] = change;
  }
}
