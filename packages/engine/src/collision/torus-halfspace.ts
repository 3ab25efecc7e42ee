/**
 * Torus–half-space contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import { candidateSlot, clearCandidates, reduceCandidates } from './manifold-reduce.js';
import type { CollisionHalfSpace, CollisionTorus } from './narrowphase-shapes.js';
import {
  NARROWPHASE_MARGIN,
  SCALAR_CANDIDATE,
  SCALAR_RING_COS,
  SCALAR_RING_HEIGHT,
  SCALAR_RING_SIN,
} from './narrowphase-scratch.js';
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
 * circle varies by more than featureTieTolerance round it (2R|(N_i, N_j)| > tolerance), in place
 * of the ring point within half a ring spacing of it (a body-fixed point beside the true contact
 * would share the load and push a torus standing on its rim into rolling). Below
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
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideTorusHalfSpaceKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideTorusHalfSpace} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideTorusHalfSpaceKernel(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const scalars = scratch.scalars;
  const N = scratch.v0;
  worldPlane(N, n, b, poseB, scalars, 2);
  const h = scalars[2];
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
  // Tilted enough that the deepest direction is well defined: the exact deepest point is added,
  // and the ring point next to it (within half the ring spacing) is left out. Both would carry
  // the load, and the ring point, fixed to the body, moves off the bottom as the torus rolls:
  // a torus standing on its rim would be pushed into rolling by it.
  const tilted = 2 * R * np > scratch.featureTieTolerance;
  const nearCos = Math.cos(Math.PI / K);
  for (let k = 0; k < K; k += 1) {
    const phi = (2 * Math.PI * k) / K;
    const cos = Math.cos(phi);
    const sin = Math.sin(phi);
    const height = h0 + R * (ni * cos + nj * sin) - r;
    if (!(height < margin)) continue;
    if (tilted && -(ni * cos + nj * sin) / np > nearCos) continue;
    scalars[SCALAR_RING_COS] = cos;
    scalars[SCALAR_RING_SIN] = sin;
    scalars[SCALAR_RING_HEIGHT] = height;
    addRingPoint(cand, n, M, xa, N, a, scalars, k);
  }
  // tilted enough that the deepest direction is well defined: add the exact deepest point
  if (tilted) {
    scalars[SCALAR_RING_COS] = -ni / np;
    scalars[SCALAR_RING_SIN] = -nj / np;
    scalars[SCALAR_RING_HEIGHT] = deepest;
    addRingPoint(cand, n, M, xa, N, a, scalars, K);
  }
  for (let c = 0; c < n; c += 1) scratch.v1[c] = -N[c];
  return reduceCandidates(out, n, cand, scratch.v1, scratch);
}

/**
 * Adds the ring point of the torus at the angle and height in scalars[SCALAR_RING_COS, _SIN,
 * _HEIGHT] (numbers travel in the array: double arguments of a call V8 does not inline are boxed).
 */
function addRingPoint(
  cand: Manifold,
  n: number,
  M: Float64Array,
  x: Float64Array,
  N: Float64Array,
  torus: CollisionTorus,
  scalars: Float64Array,
  id: number,
): void {
  const pi = torus.planeI;
  const pj = torus.planeJ;
  const R = torus.majorRadius;
  const r = torus.minorRadius;
  const cos = scalars[SCALAR_RING_COS];
  const sin = scalars[SCALAR_RING_SIN];
  const height = scalars[SCALAR_RING_HEIGHT];
  scalars[SCALAR_CANDIDATE] = height;
  const slot = candidateSlot(cand, scalars, SCALAR_CANDIDATE);
  if (slot < 0) return;
  // tube point q − rN, moved halfway down to the plane
  const down = r + height / 2;
  for (let c = 0; c < n; c += 1) {
    cand.points[slot * n + c] = x[c] + R * (cos * M[c * n + pi] + sin * M[c * n + pj]) - down * N[c];
  }
  cand.ids[slot] = id;
}
