/**
 * Convex mesh–half-space contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import { candidateSlot, clearCandidates, reduceCandidates } from './manifold-reduce.js';
import type { CollisionHalfSpace, CollisionMesh } from './narrowphase-shapes.js';
import { ensureCandidateCapacity, NARROWPHASE_MARGIN, SCALAR_CANDIDATE } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { worldPlane } from './world-plane.js';

/**
 * Contacts between a convex mesh (A) and a half-space (B): every vertex whose height above the
 * plane is below `margin` (the support set along −N), reduced to the manifold's bound (deepest
 * first, then spread out). Normal −N; separation = the vertex height; point midway between the
 * vertex and the plane; id = the vertex index.
 *
 * Unchecked hot-path kernel (see PairCollider). Allocates nothing once the scratch's candidate
 * buffer has grown to the mesh's vertex count (the first contact of the largest mesh).
 */
export function collideMeshHalfSpace(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideMeshHalfSpaceKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideMeshHalfSpace} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideMeshHalfSpaceKernel(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionHalfSpace,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const N = scratch.v0;
  const Nl = scratch.v1;
  worldPlane(N, n, b, poseB, scratch.scalars, 2);
  const h = scratch.scalars[2];
  const M = poseA.M;
  const xa = poseA.x;
  let h0 = -h;
  for (let c = 0; c < n; c += 1) {
    h0 += N[c] * xa[c];
    let s = 0;
    for (let i = 0; i < n; i += 1) s += M[i * n + c] * N[i];
    Nl[c] = s;
  }
  const v = a.vertices;
  const count = v.length / n;
  const cand = ensureCandidateCapacity(scratch, count);
  clearCandidates(cand);
  for (let k = 0; k < count; k += 1) {
    let height = h0;
    for (let c = 0; c < n; c += 1) height += Nl[c] * v[k * n + c];
    if (!(height < margin)) continue;
    scratch.scalars[SCALAR_CANDIDATE] = height;
    const slot = candidateSlot(cand, scratch.scalars, SCALAR_CANDIDATE);
    if (slot < 0) continue;
    for (let i = 0; i < n; i += 1) {
      let p = xa[i] - (height / 2) * N[i];
      for (let c = 0; c < n; c += 1) p += M[i * n + c] * v[k * n + c];
      cand.points[slot * n + i] = p;
    }
    cand.ids[slot] = k;
  }
  if (cand.count === 0) {
    out.count = 0;
    return false;
  }
  for (let c = 0; c < n; c += 1) scratch.v2[c] = -N[c];
  return reduceCandidates(out, n, cand, scratch.v2, scratch);
}
