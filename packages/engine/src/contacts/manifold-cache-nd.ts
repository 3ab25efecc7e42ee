/**
 * The manifold cache of `@physin/engine`'s worlds: {@link ManifoldCache} with the reuse written out
 * for n = 4 (a 4D face keeps 8 points, each taken through both poses every step it is reused).
 * The 3D entry builds its worlds with the general cache alone, so a 3D app does not carry it.
 *
 * @module
 */
import type { Manifold, Pose } from '../collision/manifold.js';
import { ManifoldCache } from './manifold-cache.js';

/** The manifold cache for any n, with n = 4 written out (see the module comment). @internal */
export class ManifoldCacheND extends ManifoldCache {
  /**
   * {@link ManifoldCache.reuse}; for n = 4 written out: the same sums in the same order as the
   * general loops (each starts from its first term as they do), so bit-identical.
   */
  override reuse(slot: number, m: Manifold, poseA: Pose, poseB: Pose): void {
    if (this.n !== 4) {
      super.reuse(slot, m, poseA, poseB);
      return;
    }
    const N = m.normal;
    const MA = poseA.M;
    const MB = poseB.M;
    const xA = poseA.x;
    const xB = poseB.x;
    const C = this.data;
    const c = slot * this.S + this.NO;
    const m0 = C[c],
      m1 = C[c + 1],
      m2 = C[c + 2],
      m3 = C[c + 3];
    const n0 = 0 + MA[0] * m0 + MA[1] * m1 + MA[2] * m2 + MA[3] * m3;
    const n1 = 0 + MA[4] * m0 + MA[5] * m1 + MA[6] * m2 + MA[7] * m3;
    const n2 = 0 + MA[8] * m0 + MA[9] * m1 + MA[10] * m2 + MA[11] * m3;
    const n3 = 0 + MA[12] * m0 + MA[13] * m1 + MA[14] * m2 + MA[15] * m3;
    N[0] = n0;
    N[1] = n1;
    N[2] = n2;
    N[3] = n3;
    const local = this.data;
    const pts = m.points;
    const xa0 = xA[0],
      xa1 = xA[1],
      xa2 = xA[2],
      xa3 = xA[3];
    const xb0 = xB[0],
      xb1 = xB[1],
      xb2 = xB[2],
      xb3 = xB[3];
    for (let p = 0; p < m.count; p += 1) {
      const o = slot * this.S + this.LO + p * 8;
      const la0 = local[o],
        la1 = local[o + 1],
        la2 = local[o + 2],
        la3 = local[o + 3];
      const lb0 = local[o + 4],
        lb1 = local[o + 5],
        lb2 = local[o + 6],
        lb3 = local[o + 7];
      // The surface points on A and on B in world space.
      const a0 = xa0 + MA[0] * la0 + MA[1] * la1 + MA[2] * la2 + MA[3] * la3;
      const a1 = xa1 + MA[4] * la0 + MA[5] * la1 + MA[6] * la2 + MA[7] * la3;
      const a2 = xa2 + MA[8] * la0 + MA[9] * la1 + MA[10] * la2 + MA[11] * la3;
      const a3 = xa3 + MA[12] * la0 + MA[13] * la1 + MA[14] * la2 + MA[15] * la3;
      const b0 = xb0 + MB[0] * lb0 + MB[1] * lb1 + MB[2] * lb2 + MB[3] * lb3;
      const b1 = xb1 + MB[4] * lb0 + MB[5] * lb1 + MB[6] * lb2 + MB[7] * lb3;
      const b2 = xb2 + MB[8] * lb0 + MB[9] * lb1 + MB[10] * lb2 + MB[11] * lb3;
      const b3 = xb3 + MB[12] * lb0 + MB[13] * lb1 + MB[14] * lb2 + MB[15] * lb3;
      const q = p * 4;
      pts[q] = 0.5 * (a0 + b0);
      pts[q + 1] = 0.5 * (a1 + b1);
      pts[q + 2] = 0.5 * (a2 + b2);
      pts[q + 3] = 0.5 * (a3 + b3);
      m.separations[p] = 0 + (b0 - a0) * n0 + (b1 - a1) * n1 + (b2 - a2) * n2 + (b3 - a3) * n3;
    }
  }
}
