/**
 * The face–face contact region of two boxes in n dimensions: an exact clipper of one
 * (n−1)-parallelotope against an (n−1)-box.
 *
 * Set-up. The reference face (a face of box R with outward normal n_ref toward the other box)
 * is an (n−1)-box Q = {y : |y_l| <= a_l} in its own tangent coordinates y. The incident face of
 * box I (I's face most anti-parallel to n_ref) is X(σ) = f + Σ_k σ_k h_k, σ ∈ [−1, 1]^(n−1), with
 * f its centre and h_k its half-edge vectors. Projected along n_ref into the reference plane it
 * is the parallelotope P = {y0 + Gσ}, G_lk = u_l·h_k; its height above the reference plane is
 * z(σ) = z0 + Σ gz_k σ_k, which is the separation of that incident point (negative = below the
 * reference face, overlap). The incident face is the most anti-parallel one, so |det G| >= the
 * face's volume / √n and P is never flat.
 *
 * Clipping. The vertices of P ∩ Q are the points where an a-dimensional face of P meets an
 * (n−1−a)-dimensional face of Q, a = 0..n−1 (a = 0: corners of P inside Q; a = n−1: corners of Q
 * inside P; between: P's edges through Q's facets, and so on; in 3D exactly the output of
 * Sutherland–Hodgman polygon clipping). An a-face of P fixes n−1−a of the σ to ±1 and frees a of
 * them (set F); an (n−1−a)-face of Q fixes a of the y to ±a_l (set K). Their meeting point solves
 * the a×a system G[K, F] σ_F = ±a_K − (y0 + G σ_fixed)_K, and is a vertex of P ∩ Q when
 * σ_F ∈ [−1, 1] and the free y lie in Q. Faces are pruned by interval bounds before any solve:
 * the range of y_l and of z over a face of P is its centre ± Σ_{k∈F} |G_lk|, so a face of P that
 * misses Q, lies wholly above the margin, or cannot reach a plane y_l = ±a_l of the Q face is
 * skipped. Each G[K, F] is factorised on first use only and reused for every sign choice, so in
 * practice few systems are factorised or solved. Singular systems (a face of P parallel to a face of Q) are skipped: their vertices are
 * found from lower-dimensional faces. Points that coincide within the clip tolerance are merged,
 * the first found kept: corners of P before crossings before corners of Q, which keeps ids stable
 * for boxes stacked face to face.
 *
 * Feature ids. A clip point is named by its face of P (per incident axis a base-3 digit:
 * 0 free, 1 fixed at −1, 2 fixed at +1) and its face of Q (per reference axis: 0 free, 1 at −a,
 * 2 at +a): clip = codeP + 3^(n−1)·codeQ < 9^(n−1). The full id prefixes the reference box
 * (A or B), the reference face (2·axis + (1 if +)) and the incident face:
 * id = ((refIsB·2n + refFace)·2n + incFace)·9^(n−1) + clip, below 2.45e9 for n <= 8.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import { candidateSlot } from './manifold-reduce.js';
import type { CollisionBox } from './narrowphase-shapes.js';
import {
  NARROWPHASE_MARGIN,
  SCALAR_CANDIDATE,
  SCALAR_CLIP_EPS,
  SCALAR_CLIP_EPS_SIGMA,
  SCALAR_CLIP_Z0,
} from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { luFactorAt, luSolveAt } from './small-linear.js';

/** Relative pivot below which a clip system counts as singular (parallel faces). */
const CLIP_PIVOT_TOLERANCE = 1e-12;

/**
 * Appends to `scratch.candidates` the clip points of the incident face of box `inc` against the
 * reference face (axis `refAxis`, sign `refSign`) of box `ref`, keeping those with separation
 * < margin. Points are written midway between the incident face and the reference plane.
 *
 * @param refIsB - 1 when the reference box is shape B of the pair (goes into the ids).
 * Unchecked hot-path kernel; allocates nothing.
 */
export function clipBoxFaces(
  n: number,
  ref: CollisionBox,
  refPose: Pose,
  refAxis: number,
  refSign: number,
  inc: CollisionBox,
  incPose: Pose,
  refIsB: number,
  margin: number,
  scratch: NarrowphaseScratch,
): void {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  clipBoxFacesKernel(n, ref, refPose, refAxis, refSign, inc, incPose, refIsB, scratch);
}

/**
 * {@link clipBoxFaces} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]`; `refSign`
 * must be the integer 1 or −1. Unchecked hot-path kernel; allocates nothing.
 */
export function clipBoxFacesKernel(
  n: number,
  ref: CollisionBox,
  refPose: Pose,
  refAxis: number,
  refSign: number,
  inc: CollisionBox,
  incPose: Pose,
  refIsB: number,
  scratch: NarrowphaseScratch,
): void {
  const scalars = scratch.scalars;
  const margin = scalars[NARROWPHASE_MARGIN];
  const d = n - 1;
  const MR = refPose.M;
  const MI = incPose.M;
  const ha = ref.halfExtents;
  const hb = inc.halfExtents;
  const nref = scratch.v1;
  const f = scratch.v2;
  const rc = scratch.v3;
  const X = scratch.v4;
  const { clipH: H, clipU: U, clipG: G, clipY0: y0, clipGz: gz, clipHalf: half } = scratch;
  const { clipCentre: centre, clipRadius: radius, clipSigma: sigma, clipFree: free, clipFixed: fixed } = scratch;
  const { rhs, sol } = scratch;
  const cand = scratch.candidates;

  for (let i = 0; i < n; i += 1) nref[i] = refSign * MR[i * n + refAxis];
  // incident face: the face of `inc` whose outward normal is most anti-parallel to n_ref
  let incAxis = 0;
  let bestDot = -1;
  let dotAtBest = 0;
  for (let j = 0; j < n; j += 1) {
    let s = 0;
    for (let i = 0; i < n; i += 1) s += MI[i * n + j] * nref[i];
    if (Math.abs(s) > bestDot) {
      bestDot = Math.abs(s);
      incAxis = j;
      dotAtBest = s;
    }
  }
  const incSign = dotAtBest > 0 ? -1 : 1;
  let scale = 0;
  for (let c = 0; c < n; c += 1) scale = Math.max(scale, ha[c], hb[c]);
  const eps = scratch.clipTolerance * scale;
  scalars[SCALAR_CLIP_EPS] = eps;
  scalars[SCALAR_CLIP_EPS_SIGMA] = scratch.clipTolerance;

  for (let i = 0; i < n; i += 1) {
    f[i] = incPose.x[i] + incSign * hb[incAxis] * MI[i * n + incAxis];
    rc[i] = refPose.x[i] + ha[refAxis] * nref[i];
    X[i] = f[i] - rc[i];
  }
  // tangent axes u_l of the reference face, half-edges h_k of the incident face
  for (let l = 0, c = 0; c < n; c += 1) {
    if (c === refAxis) continue;
    half[l] = ha[c];
    for (let i = 0; i < n; i += 1) U[l * n + i] = MR[i * n + c];
    l += 1;
  }
  for (let k = 0, c = 0; c < n; c += 1) {
    if (c === incAxis) continue;
    for (let i = 0; i < n; i += 1) H[k * n + i] = hb[c] * MI[i * n + c];
    k += 1;
  }
  let z0 = 0;
  for (let i = 0; i < n; i += 1) z0 += nref[i] * X[i];
  scalars[SCALAR_CLIP_Z0] = z0;
  for (let l = 0; l < d; l += 1) {
    let s = 0;
    for (let i = 0; i < n; i += 1) s += U[l * n + i] * X[i];
    y0[l] = s;
    for (let k = 0; k < d; k += 1) {
      let g = 0;
      for (let i = 0; i < n; i += 1) g += U[l * n + i] * H[k * n + i];
      G[l * d + k] = g;
    }
  }
  for (let k = 0; k < d; k += 1) {
    let s = 0;
    for (let i = 0; i < n; i += 1) s += nref[i] * H[k * n + i];
    gz[k] = s;
  }

  const refFace = 2 * refAxis + (refSign > 0 ? 1 : 0);
  const incFace = 2 * incAxis + (incSign > 0 ? 1 : 0);
  const pow3d = 3 ** d;
  const idBase = ((refIsB * 2 * n + refFace) * 2 * n + incFace) * pow3d * pow3d;
  const all = (1 << d) - 1;

  const dd = d * d;
  const { clipLu: lu, clipLuPiv: luPiv, clipLuState: luState } = scratch;
  for (let a = 0; a <= d; a += 1) {
    for (let F = 0; F <= all; F += 1) {
      if (popcount(F) !== a) continue;
      let nf = 0;
      for (let k = 0; k < d; k += 1) if (F & (1 << k)) free[nf++] = k;
      // ranges of y_l and z over a face of P with free set F: centre ± radius
      let zr = 0;
      for (let k = 0; k < nf; k += 1) zr += Math.abs(gz[free[k]]);
      for (let l = 0; l < d; l += 1) {
        let r = 0;
        for (let k = 0; k < nf; k += 1) r += Math.abs(G[l * d + free[k]]);
        radius[l] = r;
      }
      // the a×a systems G[K, F] are factorised on first use only (0 = not yet, 1 = ok, 2 = singular)
      for (let K = 0; K <= all; K += 1) luState[K] = 0;
      const fixedP = all & ~F;
      // every sign choice of P's fixed coordinates (submasks of fixedP: bit set = +1)
      for (let sp = fixedP; ; sp = (sp - 1) & fixedP) {
        let zc = z0;
        for (let l = 0; l < d; l += 1) centre[l] = y0[l];
        let codeP = 0;
        for (let k = 0, p3 = 1; k < d; k += 1, p3 *= 3) {
          if (F & (1 << k)) continue;
          const s = sp & (1 << k) ? 1 : -1;
          sigma[k] = s;
          codeP += (s > 0 ? 2 : 1) * p3;
          zc += s * gz[k];
          for (let l = 0; l < d; l += 1) centre[l] += s * G[l * d + k];
        }
        let reachable = zc - zr < margin;
        for (let l = 0; reachable && l < d; l += 1) {
          if (centre[l] - radius[l] > half[l] + eps || centre[l] + radius[l] < -half[l] - eps) reachable = false;
        }
        if (reachable) {
          for (let K = 0; K <= all; K += 1) {
            if (popcount(K) !== a) continue;
            // this P face must reach one of the two planes y_l = ±a_l of every fixed Q coordinate
            let nk = 0;
            let meets = true;
            for (let l = 0; meets && l < d; l += 1) {
              if (!(K & (1 << l))) continue;
              fixed[nk++] = l;
              const lo = centre[l] - radius[l] - eps;
              const hi = centre[l] + radius[l] + eps;
              if (!((lo <= half[l] && half[l] <= hi) || (lo <= -half[l] && -half[l] <= hi))) meets = false;
            }
            if (!meets) continue;
            const mo = K * dd;
            if (a > 0) {
              if (luState[K] === 0) {
                for (let r = 0; r < a; r += 1) {
                  for (let c = 0; c < a; c += 1) lu[mo + r * a + c] = G[fixed[r] * d + free[c]];
                }
                luState[K] = luFactorAt(a, lu, mo, luPiv, K * d, CLIP_PIVOT_TOLERANCE) ? 1 : 2;
              }
              if (luState[K] === 2) continue;
            }
            // every sign choice of Q's fixed coordinates (submasks of K: bit set = +a_l)
            crossing: for (let sq = K; ; sq = (sq - 1) & K) {
              let codeQ = 0;
              for (let r = 0; r < a; r += 1) {
                const l = fixed[r];
                const target = sq & (1 << l) ? half[l] : -half[l];
                if (target < centre[l] - radius[l] - eps || target > centre[l] + radius[l] + eps) {
                  if (sq === 0) break crossing;
                  continue crossing;
                }
                rhs[r] = target - centre[l];
                codeQ += (sq & (1 << l) ? 2 : 1) * 3 ** l;
              }
              if (a > 0) luSolveAt(a, lu, mo, luPiv, K * d, rhs, sol);
              if (appendCrossing(n, d, a, K, sol, free, sigma, centre, G, gz, half, f, nref, H, X, scalars, cand)) {
                cand.ids[cand.count - 1] = idBase + codeP + pow3d * codeQ;
              }
              if (sq === 0) break;
            }
          }
        }
        if (sp === 0) break;
      }
    }
  }
}

/**
 * Takes the solved free parameters `sol` of one (P face, Q face) meeting, checks that it is a
 * vertex of P ∩ Q with separation < margin and not a copy of a held candidate, and appends it
 * (point and separation; the caller writes the id). Returns whether it appended. z0, the
 * tolerances and the margin are read from `scalars` (see {@link clipBoxFacesKernel}).
 */
function appendCrossing(
  n: number,
  d: number,
  a: number,
  K: number,
  sol: Float64Array,
  free: Int32Array,
  sigma: Float64Array,
  centre: Float64Array,
  G: Float64Array,
  gz: Float64Array,
  half: Float64Array,
  f: Float64Array,
  nref: Float64Array,
  H: Float64Array,
  X: Float64Array,
  scalars: Float64Array,
  cand: Manifold,
): boolean {
  const z0 = scalars[SCALAR_CLIP_Z0];
  const eps = scalars[SCALAR_CLIP_EPS];
  const epsSigma = scalars[SCALAR_CLIP_EPS_SIGMA];
  const margin = scalars[NARROWPHASE_MARGIN];
  for (let c = 0; c < a; c += 1) {
    const s = sol[c];
    if (s < -1 - epsSigma || s > 1 + epsSigma) return false;
    sigma[free[c]] = s < -1 ? -1 : s > 1 ? 1 : s;
  }
  for (let l = 0; l < d; l += 1) {
    if (K & (1 << l)) continue;
    let y = centre[l];
    for (let c = 0; c < a; c += 1) y += G[l * d + free[c]] * sigma[free[c]];
    if (y > half[l] + eps || y < -half[l] - eps) return false;
  }
  let z = z0;
  for (let k = 0; k < d; k += 1) z += gz[k] * sigma[k];
  if (!(z < margin)) return false;
  // the point midway between the incident face and the reference plane
  for (let i = 0; i < n; i += 1) {
    let p = f[i] - (z / 2) * nref[i];
    for (let k = 0; k < d; k += 1) p += sigma[k] * H[k * n + i];
    X[i] = p;
  }
  const eps2 = eps * eps;
  for (let c = 0; c < cand.count; c += 1) {
    let dist2 = 0;
    for (let i = 0; i < n; i += 1) {
      const delta = cand.points[c * n + i] - X[i];
      dist2 += delta * delta;
    }
    if (dist2 <= eps2) return false;
  }
  scalars[SCALAR_CANDIDATE] = z;
  if (cand.count >= cand.capacity) {
    // full: replace the shallowest held point when this one is deeper
    const slot = candidateSlot(cand, scalars, SCALAR_CANDIDATE);
    if (slot < 0) return false;
    swapToEnd(cand, slot, n);
  } else {
    candidateSlot(cand, scalars, SCALAR_CANDIDATE);
  }
  const o = (cand.count - 1) * n;
  for (let i = 0; i < n; i += 1) cand.points[o + i] = X[i];
  return true;
}

/** Moves candidate `slot` to the last position (its point is about to be overwritten anyway). */
function swapToEnd(cand: Manifold, slot: number, n: number): void {
  const last = cand.count - 1;
  if (slot === last) return;
  const s = cand.separations[slot];
  cand.separations[slot] = cand.separations[last];
  cand.ids[slot] = cand.ids[last];
  for (let i = 0; i < n; i += 1) cand.points[slot * n + i] = cand.points[last * n + i];
  cand.separations[last] = s;
}

function popcount(x: number): number {
  let c = 0;
  for (let v = x; v !== 0; v &= v - 1) c += 1;
  return c;
}
