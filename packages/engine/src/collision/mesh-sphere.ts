/**
 * Convex mesh–sphere contact, any n.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionMesh, CollisionSphere } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { closestPointOnSimplexKernel } from './simplex-closest.js';
import { pointToLocal } from './manifold.js';

/** Flag bit of the id of a contact whose ball centre is inside the mesh (id = flag | facet). */
export const MESH_INSIDE_ID = 0x80000000;

/**
 * One contact between a convex mesh (A) and a ball (B), normal from the mesh to the ball.
 *
 * The ball's centre c is taken into the mesh frame and measured against every facet plane.
 * Inside (every N_f·c − o_f <= 0): the facet of least depth pushes the ball out along its normal,
 * separation (N_f·c − o_f) − ρ, id MESH_INSIDE_ID | f. Outside: the nearest point of the mesh
 * lies on a facet whose plane has c on its outer side, so only those facets are searched, each
 * by barycentric least squares over its sub-simplices (simplex-closest.ts); normal along
 * c − (nearest point), separation |c − nearest| − ρ, id a hash of the sorted vertex indices of the
 * face holding the nearest point (the same from every facet sharing it), top bit clear. Quick
 * reject: the largest plane distance is a lower bound of the distance to the mesh. The point lies
 * midway between the two surface points.
 *
 * Unchecked hot-path kernel (see PairCollider); allocates nothing.
 */
export function collideMeshSphere(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideMeshSphereKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideMeshSphere} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]` (see pair-kernel.ts). */
export function collideMeshSphereKernel(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionSphere,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const M = poseA.M;
  const xb = poseB.x;
  const c = scratch.v0;
  const nearest = scratch.v1;
  const local = scratch.v2;
  pointToLocal(c, n, poseA, poseB.x);
  const normals = a.facetNormals;
  const offsets = a.facetOffsets;
  const facets = a.facets;
  const verts = a.vertices;
  const facetCount = offsets.length;
  const rho = b.radius;
  let top = -Infinity;
  let topFacet = 0;
  for (let f = 0; f < facetCount; f += 1) {
    let s = -offsets[f];
    for (let k = 0; k < n; k += 1) s += normals[f * n + k] * c[k];
    if (s > top) {
      top = s;
      topFacet = f;
    }
  }
  if (!(top - rho < margin)) {
    out.count = 0;
    return false;
  }
  let separation: number;
  if (top <= 0) {
    separation = top - rho;
    for (let k = 0; k < n; k += 1) local[k] = normals[topFacet * n + k];
    out.ids[0] = (MESH_INSIDE_ID | topFacet) >>> 0;
  } else {
    const sv = scratch.simplexVerts;
    const support = scratch.simplexIndex;
    let bestD2 = Infinity;
    let supportCount = 0;
    for (let f = 0; f < facetCount; f += 1) {
      let s = -offsets[f];
      for (let k = 0; k < n; k += 1) s += normals[f * n + k] * c[k];
      if (!(s > 0)) continue;
      for (let v = 0; v < n; v += 1) {
        const o = facets[f * n + v] * n;
        for (let k = 0; k < n; k += 1) sv[v * n + k] = verts[o + k];
      }
      closestPointOnSimplexKernel(n, local, sv, n, c, scratch);
      const d2 = scratch.scalars[3];
      if (d2 < bestD2) {
        bestD2 = d2;
        for (let k = 0; k < n; k += 1) nearest[k] = local[k];
        supportCount = 0;
        for (let v = 0; v < n; v += 1) if (scratch.simplexBest[v] !== 0) support[supportCount++] = facets[f * n + v];
      }
    }
    const dist = Math.sqrt(bestD2);
    separation = dist - rho;
    if (!(separation < margin)) {
      out.count = 0;
      return false;
    }
    if (dist > 0) {
      for (let k = 0; k < n; k += 1) local[k] = (c[k] - nearest[k]) / dist;
    } else {
      for (let k = 0; k < n; k += 1) local[k] = normals[topFacet * n + k];
    }
    featureHashInto(out.ids, support, supportCount);
  }
  const N = out.normal;
  for (let i = 0; i < n; i += 1) {
    let s = 0;
    for (let k = 0; k < n; k += 1) s += M[i * n + k] * local[k];
    N[i] = s;
  }
  const back = rho + separation / 2;
  for (let i = 0; i < n; i += 1) out.points[i] = xb[i] - back * N[i];
  out.separations[0] = separation;
  out.count = 1;
  return true;
}

/** ids[0] = FNV-1a over the vertex indices in increasing order (sorted in place), top bit cleared. */
function featureHashInto(ids: Uint32Array, indices: Int32Array, count: number): void {
  for (let i = 1; i < count; i += 1) {
    const v = indices[i];
    let j = i - 1;
    while (j >= 0 && indices[j] > v) {
      indices[j + 1] = indices[j];
      j -= 1;
    }
    indices[j + 1] = v;
  }
  let h = 0x811c9dc5;
  for (let i = 0; i < count; i += 1) {
    h = Math.imul(h ^ indices[i], 0x01000193);
  }
  ids[0] = h & 0x7fffffff;
}
