/**
 * Torus–sphere contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionSphere, CollisionTorus } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN, SCALAR_CANDIDATE, SCALAR_RING_COS, SCALAR_RING_SIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { pointToLocal } from './manifold.js';
import { candidateSlot, clearCandidates } from './manifold-reduce.js';
import { ensureClipCapacity, polytopeScratch } from './convex-polytope.js';
import type { PolytopeScratch } from './convex-polytope.js';
import { assembleTorusManifold } from './torus-pairs.js';

/**
 * Contacts between a torus (A; core circle of radius R in its local plane (i, j), tube radius r)
 * and a ball (B, radius ρ). The ball's centre s, in the torus frame, is projected onto the major
 * plane; the nearest core point is q = R·proj/|proj|, normal (s − q)/|s − q| (the radial
 * direction q/R when s is on the core circle), separation |s − q| − r − ρ, point midway between
 * the two surface points on that line, id 0. That point is left out when s is so near the axis
 * that |s − q| varies round the circle by less than featureTieTolerance (every core point is
 * then about as near, and its direction is noise).
 *
 * A ball resting in a ring touches the tube round a whole circle (a sphere of contact in higher
 * n), where one point would push it sideways, off the axis and back, step after step (it sank
 * 21 mm in a 4D ring with one point). So the K = torusRingPoints body-fixed core points
 * q_k = R(cos 2πk/K, sin 2πk/K) (id 1 + k, the one nearest q left out when q is used) are
 * candidates too, each with its own gap and normal, and the manifold is assembled as in
 * torus-pairs.ts ({@link assembleTorusManifold}): candidates within the margin of the deepest,
 * one normal (their weighted mean: straight along the axis for a centred ball, tilted back
 * toward the axis for one off it), separations along it. A ball touching the tube from outside
 * keeps its one exact point: the other core points are much farther.
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing once the scratch has grown.
 */
export function collideTorusSphere(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideTorusSphereKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideTorusSphere} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideTorusSphereKernel(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const scalars = scratch.scalars;
  const margin = scalars[NARROWPHASE_MARGIN];
  const M = poseA.M;
  const s = scratch.v0;
  const dir = scratch.v1;
  const R = a.majorRadius;
  const r = a.minorRadius;
  const rb = b.radius;
  const pi = a.planeI;
  const pj = a.planeJ;
  pointToLocal(s, n, poseA, poseB.x);
  const rho = Math.sqrt(s[pi] * s[pi] + s[pj] * s[pj]);
  let off2 = 0;
  for (let c = 0; c < n; c += 1) off2 += s[c] * s[c];
  off2 -= rho * rho;
  if (off2 < 0) off2 = 0;
  // nearest and farthest core distances
  const near = Math.sqrt(off2 + (R - rho) * (R - rho));
  const far = Math.sqrt(off2 + (R + rho) * (R + rho));
  if (!(near - r - rb < margin)) {
    out.count = 0;
    return false;
  }
  const ps = polytopeScratch(scratch);
  const K = scratch.torusRingPoints;
  ensureClipCapacity(ps, K + 2);
  const cand = scratch.candidates;
  clearCandidates(cand);
  const exact = far - near > scratch.featureTieTolerance;
  const cosStar = rho > 0 ? s[pi] / rho : 1;
  const sinStar = rho > 0 ? s[pj] / rho : 0;
  if (exact) {
    scalars[SCALAR_RING_COS] = cosStar;
    scalars[SCALAR_RING_SIN] = sinStar;
    addCorePoint(cand, n, a, b, poseA, s, dir, ps, scratch, 0);
  }
  const nearCos = Math.cos(Math.PI / K);
  for (let k = 0; k < K; k += 1) {
    const phi = (2 * Math.PI * k) / K;
    const cos = Math.cos(phi);
    const sin = Math.sin(phi);
    if (exact && cos * cosStar + sin * sinStar > nearCos) continue;
    scalars[SCALAR_RING_COS] = cos;
    scalars[SCALAR_RING_SIN] = sin;
    addCorePoint(cand, n, a, b, poseA, s, dir, ps, scratch, 1 + k);
  }
  return assembleTorusManifold(out, n, cand, ps, 0, M, scratch);
}

/**
 * Adds the candidate of the core point q = R(cos, sin) (scalars[SCALAR_RING_COS], _SIN) when its
 * gap |s − q| − r − ρ is below the margin: point midway between the surfaces (world), its normal
 * (A's frame) at ps.cN[slot·n].
 */
function addCorePoint(
  cand: Manifold,
  n: number,
  a: CollisionTorus,
  b: CollisionSphere,
  poseA: Pose,
  s: Float64Array,
  dir: Float64Array,
  ps: PolytopeScratch,
  scratch: NarrowphaseScratch,
  id: number,
): void {
  const scalars = scratch.scalars;
  const R = a.majorRadius;
  const pi = a.planeI;
  const pj = a.planeJ;
  const cos = scalars[SCALAR_RING_COS];
  const sin = scalars[SCALAR_RING_SIN];
  const qi = R * cos;
  const qj = R * sin;
  for (let c = 0; c < n; c += 1) dir[c] = s[c];
  dir[pi] -= qi;
  dir[pj] -= qj;
  let d2 = 0;
  for (let c = 0; c < n; c += 1) d2 += dir[c] * dir[c];
  const dist = Math.sqrt(d2);
  const gap = dist - a.minorRadius - b.radius;
  if (!(gap < scalars[NARROWPHASE_MARGIN])) return;
  if (dist > 0) {
    for (let c = 0; c < n; c += 1) dir[c] /= dist;
  } else {
    for (let c = 0; c < n; c += 1) dir[c] = 0;
    dir[pi] = cos;
    dir[pj] = sin;
  }
  scalars[SCALAR_CANDIDATE] = gap;
  const slot = candidateSlot(cand, scalars, SCALAR_CANDIDATE);
  if (slot < 0) return;
  const M = poseA.M;
  const x = poseA.x;
  const up = a.minorRadius + gap / 2;
  for (let i = 0; i < n; i += 1) {
    let v = x[i] + M[i * n + pi] * qi + M[i * n + pj] * qj;
    for (let c = 0; c < n; c += 1) v += M[i * n + c] * up * dir[c];
    cand.points[slot * n + i] = v;
  }
  for (let c = 0; c < n; c += 1) ps.cN[slot * n + c] = dir[c];
  cand.ids[slot] = id;
}
