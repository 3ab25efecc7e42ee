/**
 * Torus–half-space contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import { candidateSlot, clearCandidates, reduceCandidates } from './manifold-reduce.js';
import type { CollisionHalfSpace, CollisionTorus } from './narrowphase-shapes.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { worldPlane } from './world-plane.js';

/**
 * Contacts between a torus (A; core circle of radius R in its local plane (i, j), tube radius r)
 * and a half-space (B) with outward world normal N and plane N·x = h. Normal −N.
 *
 * The lowest point of the tube round a core point q is q − rN, at height
 * h0 + R(N_i cos φ + N_j sin φ) − r (h0 the centre's height, N_i, N_j the components of N in the
 * torus's major plane, in its frame). Candidates: K ring points at the body-fixed angles
 * φ_k = 2πk/K (K = scratch.torusRingPoints, id k), so a torus lying flat, where the whole circle
 * is equally deep, rests on points spread round the circle and keeps their ids while it moves;
 * plus the exact deepest point, at φ with (cos φ, sin φ) = −(N_i, N_j)/|(N_i, N_j)|, depth
 * h0 − R|(N_i, N_j)| − r (id K), added when the torus is tilted: when the height of the core
 * circle varies by more than featureTieTolerance round it (2R|(N_i, N_j)| > tolerance). Below
 * that the deepest direction is noise and a point following it would jump round the circle from
 * step to step; the ring points then miss the deepest depth by at most
 * (tolerance/2)(1 − cos(π/K)) (2e-5 m with the defaults). Points below `margin` are kept and
 * reduced to the manifold's bound; each lies midway between the tube point and the plane.
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideTorusHalfSpace(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  const N = scratch.v0;
  worldPlane(N, n, b, poseB, scratch.scalars, 2);
  const h = scratch.scalars[2];
  const M = poseA.M;
  const xa = poseA.x;
  const R = a.majorRadius;
  const r = a.minorRadius;
  const pi = a.planeI;
  const pj = a.planeJ;
  let h0 = -h;
  let ni = 0;
  let nj = 0;
  for (let c = 0; c < n; c += 1) {
    h0 += N[c] * xa[c];
    ni += N[c] * M[c * n + pi];
    nj += N[c] * M[c * n + pj];
  }
  const np = Math.sqrt(ni * ni + nj * nj);
  const deepest = h0 - R * np - r;
  if (!(deepest < margin)) {
    out.count = 0;
    return false;
  }
  const cand = scratch.candidates;
  clearCandidates(cand);
  const K = scratch.torusRingPoints;
  let deepestRing = Infinity;
  for (let k = 0; k < K; k += 1) {
    const phi = (2 * Math.PI * k) / K;
    const cos = Math.cos(phi);
    const sin = Math.sin(phi);
    const height = h0 + R * (ni * cos + nj * sin) - r;
    deepestRing = Math.min(deepestRing, height);
    if (!(height < margin)) continue;
    addRingPoint(cand, n, M, xa, N, pi, pj, R, r, cos, sin, height, k);
  }
  // tilted enough that the deepest direction is well defined: add the exact deepest point
  if (2 * R * np > scratch.featureTieTolerance && deepest < deepestRing) {
    addRingPoint(cand, n, M, xa, N, pi, pj, R, r, -ni / np, -nj / np, deepest, K);
  }
  for (let c = 0; c < n; c += 1) scratch.v1[c] = -N[c];
  return reduceCandidates(out, n, cand, scratch.v1, scratch.reduceDistance);
}

function addRingPoint(
  cand: Manifold,
  n: number,
  M: Float64Array,
  x: Float64Array,
  N: Float64Array,
  pi: number,
  pj: number,
  R: number,
  r: number,
  cos: number,
  sin: number,
  height: number,
  id: number,
): void {
  const slot = candidateSlot(cand, height);
  if (slot < 0) return;
  // tube point q − rN, moved halfway down to the plane
  const down = r + height / 2;
  for (let c = 0; c < n; c += 1) {
    cand.points[slot * n + c] = x[c] + R * (cos * M[c * n + pi] + sin * M[c * n + pj]) - down * N[c];
  }
  cand.ids[slot] = id;
}
