import { symmetricEigen } from '@physin/algebra';
import { determinantInPlace } from './mesh-geometry.js';

/**
 * Off-diagonal covariance entries at or below this fraction of the trace are rounding noise of
 * the integration (it is accurate to ~1e-15): they are set to zero before the eigen solve, so a
 * body whose covariance is diagonal in its input axes keeps those axes, and an isotropic one
 * (a cube) is not turned by an arbitrary angle. Zeroing them changes the inertia by at most
 * this fraction.
 */
const NOISE_FRACTION = 1e-13;

/**
 * The principal frame of a symmetric covariance matrix K (n×n, row-major): a rotation Q
 * (det +1; columns = principal axes in input coordinates) and the diagonal d = diag(Qᵀ K Q).
 *
 * Among the many valid answers (axis order, signs, any basis of a repeated eigenvalue) this
 * picks the one closest to the input axes: each principal axis takes the place of the input axis
 * it is most aligned with, with a positive component along it. A covariance that is already
 * diagonal gives Q = identity.
 *
 * @param n - count of dimensions.
 * @param outRotation - n×n row-major, receives Q.
 * @param outDiagonal - n numbers, receives d (d_c = q_cᵀ K q_c).
 * @param K - symmetric n×n (not modified).
 */
export function principalFrame(n: number, outRotation: Float64Array, outDiagonal: Float64Array, K: Float64Array): void {
  let trace = 0;
  for (let i = 0; i < n; i += 1) trace += Math.abs(K[i * n + i]);
  const A = Float64Array.from(K);
  for (let r = 0; r < n; r += 1) {
    for (let c = 0; c < n; c += 1) if (r !== c && Math.abs(A[r * n + c]) <= NOISE_FRACTION * trace) A[r * n + c] = 0;
  }
  const values = new Float64Array(n);
  const vectors = new Float64Array(n * n);
  symmetricEigen(n, values, vectors, A);

  // match eigenvectors to input axes, largest |component| first
  const rowUsed = new Uint8Array(n);
  const colUsed = new Uint8Array(n);
  outRotation.fill(0);
  for (let step = 0; step < n; step += 1) {
    let best = -1;
    let bestRow = 0;
    let bestCol = 0;
    for (let r = 0; r < n; r += 1) {
      if (rowUsed[r]) continue;
      for (let c = 0; c < n; c += 1) {
        if (colUsed[c]) continue;
        const v = Math.abs(vectors[r * n + c]);
        if (v > best) {
          best = v;
          bestRow = r;
          bestCol = c;
        }
      }
    }
    rowUsed[bestRow] = 1;
    colUsed[bestCol] = 1;
    const sign = vectors[bestRow * n + bestCol] < 0 ? -1 : 1;
    for (let r = 0; r < n; r += 1) outRotation[r * n + bestRow] = sign * vectors[r * n + bestCol];
  }
  if (determinantInPlace(n, Float64Array.from(outRotation)) < 0) {
    // a mirror: flip the axis that is least aligned with its input axis
    let worst = 0;
    for (let c = 1; c < n; c += 1) {
      if (Math.abs(outRotation[c * n + c]) < Math.abs(outRotation[worst * n + worst])) worst = c;
    }
    for (let r = 0; r < n; r += 1) outRotation[r * n + worst] = -outRotation[r * n + worst];
  }
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let r = 0; r < n; r += 1) {
      let kq = 0;
      for (let m = 0; m < n; m += 1) kq += K[r * n + m] * outRotation[m * n + c];
      s += outRotation[r * n + c] * kq;
    }
    outDiagonal[c] = s;
  }
}
