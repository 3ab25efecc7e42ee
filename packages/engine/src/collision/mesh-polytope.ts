/**
 * Convex mesh–box and convex mesh–convex mesh contact manifolds, any n: one general path for two
 * convex polytopes (a box is the polytope of its 2ⁿ corners and 2n faces).
 *
 * 1. **Signed distance** by GJK / EPA (convex-polytope.ts), in A's frame: separation s* and normal.
 *    Beyond the margin: no contact (GJK's lower bound usually says so after a step or two).
 * 2. **Face or not.** The separation along every facet normal of A (min over B's vertices of
 *    N_f·b − o_f) and of B; the best face axis is never above s*. When it comes within
 *    `featureTieTolerance` of s*, a face carries the contact: A's best face is the reference
 *    unless B's beats it by more than the tolerance (as box–box). Otherwise (an edge–edge contact
 *    in 3D, or any contact of lower-dimensional features): one point midway between GJK/EPA's
 *    witness points, normal and separation from step 1.
 * 3. **Clipping.** The incident face is the other polytope's facet most anti-parallel to the
 *    reference normal N_r. The contact region is the incident face cut by the reference face's
 *    prism: {x : N_i·x = o_i; N_h·x <= o_h for the incident face's side facets h;
 *    (N_g − (N_g·N_r)N_r)·x <= o_g − o_r(N_g·N_r) for the reference face's side facets g} — a
 *    side facet being a facet (not parallel to the face) whose plane holds n − 1 or more of the
 *    face's vertices, one per plane. Its vertices are where n − 1 of these constraints meet the
 *    incident plane (each (n−1)-subset solved as an n×n system, kept when it satisfies every
 *    constraint within `clipTolerance` × size). Separation of a point: its height above the
 *    reference plane; points below the margin are kept, at the midpoint between the surfaces,
 *    and reduced to the manifold's bound (manifold-reduce.ts).
 *
 * Faces of a mesh made of several coplanar simplices are named by the lowest facet index of
 * their plane, so the ids do not depend on which simplex rounding favoured. Feature ids: face
 * contact: FNV-1a of (reference is B, reference face, incident face, the constraint facets of
 * the vertex), top bit clear; other contact: FNV-1a of the supporting vertex indices of A and B,
 * top bit set.
 *
 * Unchecked hot-path kernels (see PairCollider). They allocate nothing once the polytope scratch
 * has grown to the largest meshes seen.
 *
 * @module
 */
import type { CollidableShape, Manifold, Pose } from './manifold.js';
import { checkNarrowphaseDimension } from './manifold.js';
import { candidateSlot, clearCandidates, reduceCandidates } from './manifold-reduce.js';
import type { CollisionBox, CollisionMesh } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN, SCALAR_CANDIDATE } from './narrowphase-scratch.js';
import { createNarrowphaseScratch } from './narrowphase-scratch-nd.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { checkCollisionShape, checkNarrowphaseOutput, checkPose } from './narrowphase-checks.js';
import {
  ensureClipCapacity,
  ensureRegionCapacity,
  loadBox,
  loadMesh,
  loadRelativePose,
  POLY_BEYOND,
  PS_FACE,
  PS_MARGIN,
  PS_MERGE,
  polytopeScratch,
  polytopeSeparationKernel,
} from './convex-polytope.js';
import type { PolytopeScratch } from './convex-polytope.js';
import { luFactor, luSolve } from './small-linear.js';

/** Two unit normals with a dot product at least this are the same plane direction. */
const PARALLEL_DOT = 1 - 1e-10;
/** A vertex within this × size of a plane lies on it (mesh vertices may sit 1e-7 × size off). */
const ON_PLANE = 1e-6;
/** Relative pivot below which a clip system is singular (its vertex comes from other subsets). */
const CLIP_PIVOT = 1e-10;
/** Bit of the ids of contacts that are not face contacts. */
const NON_FACE_ID = 0x80000000;

/** Contacts between a convex mesh (A) and a box (B), normal from A to B (see the module comment). */
export function collideMeshBox(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideMeshBoxKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideMeshBox} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]`. */
export function collideMeshBoxKernel(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const ps = polytopeScratch(scratch);
  loadRelativePose(n, ps, poseA, poseB);
  loadMesh(n, ps, a, false);
  loadBox(n, ps, b, true);
  return polytopeManifold(out, n, ps, poseA, scratch);
}

/** Contacts between two convex meshes, normal from A to B (see the module comment). */
export function collideMeshMesh(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionMesh,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  return collideMeshMeshKernel(out, n, a, poseA, b, poseB, scratch);
}

/** {@link collideMeshMesh} with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]`. */
export function collideMeshMeshKernel(
  out: Manifold,
  n: number,
  a: CollisionMesh,
  poseA: Pose,
  b: CollisionMesh,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const ps = polytopeScratch(scratch);
  loadRelativePose(n, ps, poseA, poseB);
  loadMesh(n, ps, a, false);
  loadMesh(n, ps, b, true);
  return polytopeManifold(out, n, ps, poseA, scratch);
}

const scratchByN: (NarrowphaseScratch | undefined)[] = [];

/**
 * The signed distance between two convex polytopes (boxes or convex meshes, either order) by
 * GJK and EPA: positive = the gap, negative = the penetration depth (the least translation that
 * separates them). Writes the unit normal from A to B (world) into `outNormal`. Validates its
 * arguments, then runs the kernels on a per-n scratch of this module.
 *
 * @throws TypeError / RangeError for a bad n, shape, pose or output (nothing is written then).
 */
export function polytopeSeparation(
  n: number,
  shapeA: CollidableShape,
  poseA: Pose,
  shapeB: CollidableShape,
  poseB: Pose,
  outNormal: Float64Array,
): number {
  checkNarrowphaseDimension(n, 'n');
  checkCollisionShape(shapeA, n, 'shapeA');
  checkPose(poseA, n, 'poseA');
  checkCollisionShape(shapeB, n, 'shapeB');
  checkPose(poseB, n, 'poseB');
  checkNarrowphaseOutput(outNormal, n, 'outNormal');
  for (const [shape, name] of [
    [shapeA, 'shapeA'],
    [shapeB, 'shapeB'],
  ] as const) {
    if (shape.kind !== 'box' && shape.kind !== 'mesh') {
      throw new TypeError(`polytopeSeparation: '${name}' must be a box or a convex mesh, got kind '${shape.kind}'`);
    }
  }
  let scratch = scratchByN[n];
  if (!scratch) {
    scratch = createNarrowphaseScratch(n);
    scratchByN[n] = scratch;
  }
  const ps = polytopeScratch(scratch);
  loadRelativePose(n, ps, poseA, poseB);
  if (shapeA.kind === 'box') loadBox(n, ps, shapeA as unknown as CollisionBox, false);
  else loadMesh(n, ps, shapeA as unknown as CollisionMesh, false);
  if (shapeB.kind === 'box') loadBox(n, ps, shapeB as unknown as CollisionBox, true);
  else loadMesh(n, ps, shapeB as unknown as CollisionMesh, true);
  ps.scalars[PS_MARGIN] = Infinity;
  polytopeSeparationKernel(n, ps, scratch);
  const M = poseA.M;
  for (let i = 0; i < n; i += 1) {
    let s = 0;
    for (let c = 0; c < n; c += 1) s += M[i * n + c] * ps.normal[c];
    outNormal[i] = s;
  }
  return ps.separation;
}

/** The manifold of the polytopes loaded in `ps` (see the module comment). */
function polytopeManifold(out: Manifold, n: number, ps: PolytopeScratch, poseA: Pose, scratch: NarrowphaseScratch): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  ps.scalars[PS_MARGIN] = margin;
  polytopeSeparationKernel(n, ps, scratch);
  if (ps.status === POLY_BEYOND || !(ps.separation < margin)) {
    out.count = 0;
    return false;
  }
  // separation along every face axis of A, then of B
  let bestA = -Infinity;
  let faceA = 0;
  for (let f = 0; f < ps.aFC; f += 1) {
    faceSeparation(n, ps.aN, ps.aO, f, ps.bV, ps.bVC, ps.scalars);
    const s = ps.scalars[PS_FACE];
    if (s > bestA) {
      bestA = s;
      faceA = f;
    }
  }
  let bestB = -Infinity;
  let faceB = 0;
  for (let g = 0; g < ps.bFC; g += 1) {
    faceSeparation(n, ps.bN, ps.bO, g, ps.aV, ps.aVC, ps.scalars);
    const s = ps.scalars[PS_FACE];
    if (s > bestB) {
      bestB = s;
      faceB = g;
    }
  }
  const tie = scratch.featureTieTolerance;
  const cand = scratch.candidates;
  clearCandidates(cand);
  const worldNormal = scratch.v0;
  const M = poseA.M;
  if (ps.supportCount === 0 || Math.max(bestA, bestB) >= ps.separation - tie) {
    const refIsB = bestB > bestA + tie;
    clipFaces(n, ps, refIsB, refIsB ? faceB : faceA, poseA, scratch);
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += M[i * n + c] * scratch.v4[c];
      worldNormal[i] = s;
    }
  }
  if (cand.count === 0 && ps.supportCount > 0) witnessContact(n, ps, poseA, worldNormal, scratch);
  if (cand.count === 0) {
    out.count = 0;
    return false;
  }
  return reduceCandidates(out, n, cand, worldNormal, scratch);
}

/**
 * The one-point contact midway between the witness points, with GJK/EPA's normal and separation
 * (ps.normal is still theirs: clipFaces sets it only when it finds points).
 */
function witnessContact(
  n: number,
  ps: PolytopeScratch,
  poseA: Pose,
  worldNormal: Float64Array,
  scratch: NarrowphaseScratch,
): void {
  const cand = scratch.candidates;
  const M = poseA.M;
  const p = scratch.v1;
  for (let c = 0; c < n; c += 1) p[c] = (ps.witnessA[c] + ps.witnessB[c]) / 2;
  scratch.scalars[SCALAR_CANDIDATE] = ps.separation;
  const slot = candidateSlot(cand, scratch.scalars, SCALAR_CANDIDATE);
  for (let i = 0; i < n; i += 1) {
    let s = poseA.x[i];
    let w = 0;
    for (let c = 0; c < n; c += 1) {
      s += M[i * n + c] * p[c];
      w += M[i * n + c] * ps.normal[c];
    }
    cand.points[slot * n + i] = s;
    worldNormal[i] = w;
  }
  sortInts(ps.supportA, ps.supportCount);
  sortInts(ps.supportB, ps.supportCount);
  let h = Math.imul(0x811c9dc5 ^ 3, 0x01000193);
  for (let k = 0; k < ps.supportCount; k += 1) h = Math.imul(h ^ ps.supportA[k], 0x01000193);
  h = Math.imul(h ^ -1, 0x01000193);
  for (let k = 0; k < ps.supportCount; k += 1) h = Math.imul(h ^ ps.supportB[k], 0x01000193);
  cand.ids[slot] = h | NON_FACE_ID;
}

/** out[PS_FACE] = min over the vertices V of N_f·v − o_f. */
function faceSeparation(
  n: number,
  N: Float64Array,
  O: Float64Array,
  f: number,
  V: Float64Array,
  count: number,
  out: Float64Array,
): void {
  let low = Infinity;
  for (let k = 0; k < count; k += 1) {
    let s = 0;
    for (let c = 0; c < n; c += 1) s += N[f * n + c] * V[k * n + c];
    if (s < low) low = s;
  }
  out[PS_FACE] = low - O[f];
}

/** The lowest facet index whose normal is parallel to facet f's (the face's name). */
function canonicalFace(n: number, N: Float64Array, f: number): number {
  for (let g = 0; g < f; g += 1) {
    let d = 0;
    for (let c = 0; c < n; c += 1) d += N[g * n + c] * N[f * n + c];
    if (d >= PARALLEL_DOT) return g;
  }
  return f;
}

/**
 * Appends the side constraints of the face (normal F = N[face], offset O[face]) of the polytope
 * (V, N, O): each non-parallel facet whose plane holds n − 1 or more of the face's vertices, one
 * per plane direction. With `prism`, the constraint is the facet's plane made parallel to F:
 * (N_g − (N_g·F)F)·x <= o_g − o_F(N_g·F), normalised. Returns the new constraint count.
 */
function addSides(
  n: number,
  ps: PolytopeScratch,
  V: Float64Array,
  vc: number,
  N: Float64Array,
  O: Float64Array,
  fc: number,
  face: number,
  prism: boolean,
  tag: number,
  start: number,
): number {
  let m = start;
  const tol = ON_PLANE * ps.size;
  const of = O[face];
  for (let g = 0; g < fc; g += 1) {
    let dot = 0;
    for (let c = 0; c < n; c += 1) dot += N[g * n + c] * N[face * n + c];
    if (dot >= PARALLEL_DOT || dot <= -PARALLEL_DOT) continue;
    let onBoth = 0;
    for (let k = 0; k < vc && onBoth < n - 1; k += 1) {
      let sf = -of;
      let sg = -O[g];
      for (let c = 0; c < n; c += 1) {
        sf += N[face * n + c] * V[k * n + c];
        sg += N[g * n + c] * V[k * n + c];
      }
      if (Math.abs(sf) <= tol && Math.abs(sg) <= tol) onBoth += 1;
    }
    if (onBoth < n - 1) continue;
    ensureClipCapacity(ps, m + 1);
    const cN = ps.cN;
    let len = 0;
    for (let c = 0; c < n; c += 1) {
      const v = prism ? N[g * n + c] - dot * N[face * n + c] : N[g * n + c];
      cN[m * n + c] = v;
      len += v * v;
    }
    len = Math.sqrt(len);
    let off = prism ? O[g] - of * dot : O[g];
    for (let c = 0; c < n; c += 1) cN[m * n + c] /= len;
    off /= len;
    // one constraint per plane direction
    let repeat = false;
    for (let j = start; j < m && !repeat; j += 1) {
      let d = 0;
      for (let c = 0; c < n; c += 1) d += cN[j * n + c] * cN[m * n + c];
      if (d >= PARALLEL_DOT) repeat = true;
    }
    if (repeat) continue;
    ps.cO[m] = off;
    ps.cId[m] = tag | g;
    m += 1;
  }
  return m;
}

/**
 * Clips the incident face against the reference face (see the module comment) and writes the
 * candidates into scratch.candidates; writes the manifold normal (A to B, A's frame) into scratch.v4.
 */
function clipFaces(
  n: number,
  ps: PolytopeScratch,
  refIsB: boolean,
  refFace: number,
  poseA: Pose,
  scratch: NarrowphaseScratch,
): void {
  const rV = refIsB ? ps.bV : ps.aV;
  const rN = refIsB ? ps.bN : ps.aN;
  const rO = refIsB ? ps.bO : ps.aO;
  const rVC = refIsB ? ps.bVC : ps.aVC;
  const rFC = refIsB ? ps.bFC : ps.aFC;
  const qV = refIsB ? ps.aV : ps.bV;
  const qN = refIsB ? ps.aN : ps.bN;
  const qO = refIsB ? ps.aO : ps.bO;
  const qVC = refIsB ? ps.aVC : ps.bVC;
  const qFC = refIsB ? ps.aFC : ps.bFC;
  const fr = canonicalFace(n, rN, refFace);
  // incident face: most anti-parallel to the reference normal
  let fi = 0;
  let low = Infinity;
  for (let q = 0; q < qFC; q += 1) {
    let d = 0;
    for (let c = 0; c < n; c += 1) d += qN[q * n + c] * rN[fr * n + c];
    if (d < low) {
      low = d;
      fi = q;
    }
  }
  fi = canonicalFace(n, qN, fi);
  const sign = refIsB ? -1 : 1;
  const faceNormal = scratch.v4;
  for (let c = 0; c < n; c += 1) faceNormal[c] = sign * rN[fr * n + c];
  const mInc = addSides(n, ps, qV, qVC, qN, qO, qFC, fi, false, 1 << 24, 0);
  const m = addSides(n, ps, rV, rVC, rN, rO, rFC, fr, true, 2 << 24, mInc);
  if (m <= 30 && clipRegion(n, ps, qV, qVC, qN, qO, fi, mInc, m, rN, rO, fr, refIsB, poseA, scratch)) return;
  clearCandidates(scratch.candidates);
  const k = n - 1;
  if (m < k) return;
  const { mat, piv, rhs, sol } = scratch;
  const cN = ps.cN;
  const cO = ps.cO;
  const comb = ps.comb;
  const or = rO[fr];
  const eps = Math.max(scratch.clipTolerance, 1e-12) * ps.size;
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const cand = scratch.candidates;
  const M = poseA.M;
  const xa = poseA.x;
  const mid = scratch.v2;
  const world = scratch.v3;
  for (let j = 0; j < k; j += 1) comb[j] = j;
  for (;;) {
    for (let c = 0; c < n; c += 1) mat[c] = qN[fi * n + c];
    rhs[0] = qO[fi];
    for (let j = 0; j < k; j += 1) {
      const r = comb[j];
      for (let c = 0; c < n; c += 1) mat[(j + 1) * n + c] = cN[r * n + c];
      rhs[j + 1] = cO[r];
    }
    if (luFactor(n, mat, piv, CLIP_PIVOT)) {
      luSolve(n, mat, piv, rhs, sol);
      let inside = true;
      for (let r = 0; r < m && inside; r += 1) {
        let s = -cO[r];
        for (let c = 0; c < n; c += 1) s += cN[r * n + c] * sol[c];
        if (s > eps) inside = false;
      }
      if (inside) {
        let z = -or;
        for (let c = 0; c < n; c += 1) z += rN[fr * n + c] * sol[c];
        if (z < margin) {
          for (let c = 0; c < n; c += 1) mid[c] = sol[c] - (z / 2) * rN[fr * n + c];
          for (let i = 0; i < n; i += 1) {
            let s = xa[i];
            for (let c = 0; c < n; c += 1) s += M[i * n + c] * mid[c];
            world[i] = s;
          }
          ps.scalars[PS_MERGE] = 10 * eps;
          if (!isDuplicate(n, cand, world, ps.scalars)) {
            scratch.scalars[SCALAR_CANDIDATE] = z;
            const slot = candidateSlot(cand, scratch.scalars, SCALAR_CANDIDATE);
            if (slot >= 0) {
              for (let i = 0; i < n; i += 1) cand.points[slot * n + i] = world[i];
              // FNV-1a, inline (a hash returned from a call would be a boxed double)
              let h = Math.imul(0x811c9dc5 ^ (refIsB ? 1 : 0), 0x01000193);
              h = Math.imul(h ^ fr, 0x01000193);
              h = Math.imul(h ^ fi, 0x01000193);
              for (let j = 0; j < k; j += 1) h = Math.imul(h ^ ps.cId[comb[j]], 0x01000193);
              cand.ids[slot] = h & 0x7fffffff;
            }
          }
        }
      }
    }
    // next (n−1)-subset in lexicographic order
    let j = k - 1;
    while (j >= 0 && comb[j] === m - k + j) j -= 1;
    if (j < 0) break;
    comb[j] += 1;
    for (let q = j + 1; q < k; q += 1) comb[q] = comb[q - 1] + 1;
  }
}

/**
 * The contact region by clipping (n-dimensional Sutherland–Hodgman): the incident face, as its
 * vertices with the masks of the incident side constraints they lie on, is cut by each reference
 * side half-space in turn. Inside vertices stay (gaining the constraint's bit when on its plane);
 * where an inside and an outside vertex share n − 2 or more constraints (an edge of the region)
 * the crossing point is added, with the shared constraints and the new one. Faster than the
 * enumeration of every (n−1)-subset of constraints in 5D and 6D, and the same vertices and ids.
 * Writes the candidates; returns false (nothing written) when the region outgrows 4096 vertices.
 */
function clipRegion(
  n: number,
  ps: PolytopeScratch,
  qV: Float64Array,
  qVC: number,
  qN: Float64Array,
  qO: Float64Array,
  fi: number,
  mInc: number,
  m: number,
  rN: Float64Array,
  rO: Float64Array,
  fr: number,
  refIsB: boolean,
  poseA: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const tolPlane = ON_PLANE * ps.size;
  const eps = Math.max(scratch.clipTolerance, 1e-12) * ps.size;
  const cN = ps.cN;
  const cO = ps.cO;
  // the incident face's vertices and the incident sides they lie on
  let count = 0;
  for (let v = 0; v < qVC; v += 1) {
    let h = -qO[fi];
    for (let c = 0; c < n; c += 1) h += qN[fi * n + c] * qV[v * n + c];
    if (!(Math.abs(h) <= tolPlane)) continue;
    ensureRegionCapacity(ps, count + 1);
    let mask = 0;
    for (let j = 0; j < mInc; j += 1) {
      let s = -cO[j];
      for (let c = 0; c < n; c += 1) s += cN[j * n + c] * qV[v * n + c];
      if (Math.abs(s) <= tolPlane) mask |= 1 << j;
    }
    for (let c = 0; c < n; c += 1) ps.clipV[count * n + c] = qV[v * n + c];
    ps.clipMask[count] = mask;
    count += 1;
  }
  const need = n - 2;
  for (let j = mInc; j < m && count > 0; j += 1) {
    const S = ps.clipS;
    let outside = 0;
    for (let v = 0; v < count; v += 1) {
      let s = -cO[j];
      for (let c = 0; c < n; c += 1) s += cN[j * n + c] * ps.clipV[v * n + c];
      S[v] = s;
      if (s > eps) outside += 1;
    }
    if (outside === 0) {
      for (let v = 0; v < count; v += 1) if (S[v] >= -eps) ps.clipMask[v] |= 1 << j;
      continue;
    }
    let next = 0;
    for (let v = 0; v < count; v += 1) {
      if (S[v] > eps) continue;
      ensureRegionCapacity(ps, next + 1);
      for (let c = 0; c < n; c += 1) ps.clipV2[next * n + c] = ps.clipV[v * n + c];
      ps.clipMask2[next] = S[v] >= -eps ? ps.clipMask[v] | (1 << j) : ps.clipMask[v];
      next += 1;
    }
    for (let v = 0; v < count; v += 1) {
      if (!(S[v] < -eps)) continue;
      for (let w = 0; w < count; w += 1) {
        if (!(S[w] > eps)) continue;
        const shared = ps.clipMask[v] & ps.clipMask[w];
        if (popcount(shared) < need) continue;
        const t = S[v] / (S[v] - S[w]);
        if (next >= 4096) return false;
        ensureRegionCapacity(ps, next + 1);
        for (let c = 0; c < n; c += 1) {
          ps.clipV2[next * n + c] = ps.clipV[v * n + c] + t * (ps.clipV[w * n + c] - ps.clipV[v * n + c]);
        }
        // a crossing met before (degenerate faces) is not added twice
        let repeat = false;
        for (let q = 0; q < next && !repeat; q += 1) {
          let d2 = 0;
          for (let c = 0; c < n; c += 1) {
            const d = ps.clipV2[q * n + c] - ps.clipV2[next * n + c];
            d2 += d * d;
          }
          if (d2 <= 100 * eps * eps) repeat = true;
        }
        if (repeat) continue;
        ps.clipMask2[next] = shared | (1 << j);
        next += 1;
      }
    }
    // swap the buffers
    const V = ps.clipV;
    ps.clipV = ps.clipV2;
    ps.clipV2 = V;
    const M2 = ps.clipMask;
    ps.clipMask = ps.clipMask2;
    ps.clipMask2 = M2;
    count = next;
  }
  // heights above the reference plane; candidates below the margin
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const cand = scratch.candidates;
  const M = poseA.M;
  const xa = poseA.x;
  const world = scratch.v3;
  for (let v = 0; v < count; v += 1) {
    let z = -rO[fr];
    for (let c = 0; c < n; c += 1) z += rN[fr * n + c] * ps.clipV[v * n + c];
    if (!(z < margin)) continue;
    for (let i = 0; i < n; i += 1) {
      let s = xa[i];
      for (let c = 0; c < n; c += 1) s += M[i * n + c] * (ps.clipV[v * n + c] - (z / 2) * rN[fr * n + c]);
      world[i] = s;
    }
    scratch.scalars[SCALAR_CANDIDATE] = z;
    const slot = candidateSlot(cand, scratch.scalars, SCALAR_CANDIDATE);
    if (slot < 0) continue;
    for (let i = 0; i < n; i += 1) cand.points[slot * n + i] = world[i];
    let h = Math.imul(0x811c9dc5 ^ (refIsB ? 1 : 0), 0x01000193);
    h = Math.imul(h ^ fr, 0x01000193);
    h = Math.imul(h ^ fi, 0x01000193);
    const mask = ps.clipMask[v];
    for (let j = 0; j < m; j += 1) if (mask & (1 << j)) h = Math.imul(h ^ ps.cId[j], 0x01000193);
    cand.ids[slot] = h & 0x7fffffff;
  }
  return true;
}

function popcount(x: number): number {
  let v = x - ((x >>> 1) & 0x55555555);
  v = (v & 0x33333333) + ((v >>> 2) & 0x33333333);
  return (Math.imul((v + (v >>> 4)) & 0x0f0f0f0f, 0x01010101) >>> 24) & 0xff;
}

function isDuplicate(n: number, cand: Manifold, p: Float64Array, scalars: Float64Array): boolean {
  const t2 = scalars[PS_MERGE] * scalars[PS_MERGE];
  for (let q = 0; q < cand.count; q += 1) {
    let d2 = 0;
    for (let c = 0; c < n; c += 1) {
      const d = cand.points[q * n + c] - p[c];
      d2 += d * d;
    }
    if (d2 <= t2) return true;
  }
  return false;
}

function sortInts(a: Int32Array, count: number): void {
  for (let i = 1; i < count; i += 1) {
    const v = a[i];
    let j = i - 1;
    while (j >= 0 && a[j] > v) {
      a[j + 1] = a[j];
      j -= 1;
    }
    a[j + 1] = v;
  }
}
