/**
 * Box–half-space contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import { candidateSlot, clearCandidates, reduceCandidates } from './manifold-reduce.js';
import type { CollisionBox, CollisionHalfSpace } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN, SCALAR_CANDIDATE } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { worldPlane } from './world-plane.js';

/**
 * Contacts between a box (A) and a half-space (B): every one of the 2ⁿ corners whose height above
 * the plane is below `margin`, reduced to the manifold's bound (deepest first, then spread out;
 * see manifold-reduce.ts). Normal −N (from the box into the half-space, N the outward plane
 * normal); separation = the corner's height N·p − h; point midway between the corner and its
 * projection on the plane. Feature id: the corner's bitmask (bit c set when the corner is at
 * +a_c along local axis c).
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideBoxHalfSpace(
  out: Manifold,
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideBoxHalfSpaceKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideBoxHalfSpace} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideBoxHalfSpaceKernel(
  out: Manifold,
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const N = scratch.v0;
  const g = scratch.v1;
  worldPlane(N, n, b, poseB, scratch.scalars, 2);
  const h = scratch.scalars[2];
  const M = poseA.M;
  const xa = poseA.x;
  const half = a.halfExtents;
  // corner height = h0 + Σ ±g_c, g_c = a_c N·u_c
  let h0 = -h;
  for (let i = 0; i < n; i += 1) h0 += N[i] * xa[i];
  let lowest = h0;
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let i = 0; i < n; i += 1) s += N[i] * M[i * n + c];
    g[c] = half[c] * s;
    lowest -= Math.abs(g[c]);
  }
  if (!(lowest < margin)) {
    out.count = 0;
    return false;
  }
  const cand = scratch.candidates;
  clearCandidates(cand);
  const corners = 1 << n;
  for (let mask = 0; mask < corners; mask += 1) {
    let height = h0;
    for (let c = 0; c < n; c += 1) height += mask & (1 << c) ? g[c] : -g[c];
    if (!(height < margin)) continue;
    scratch.scalars[SCALAR_CANDIDATE] = height;
    const slot = candidateSlot(cand, scratch.scalars, SCALAR_CANDIDATE);
    if (slot < 0) continue;
    const o = slot * n;
    for (let i = 0; i < n; i += 1) {
      let p = xa[i] - (height / 2) * N[i];
      for (let c = 0; c < n; c += 1) p += (mask & (1 << c) ? half[c] : -half[c]) * M[i * n + c];
      cand.points[o + i] = p;
    }
    cand.ids[slot] = mask;
  }
  for (let i = 0; i < n; i += 1) scratch.v2[i] = -N[i];
  return reduceCandidates(out, n, cand, scratch.v2, scratch);
}
