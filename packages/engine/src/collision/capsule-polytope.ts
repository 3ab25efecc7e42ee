/**
 * Capsule–box and capsule–convex mesh contacts, any n. A capsule is its core segment swept by a
 * ball of radius r, so its signed distance to a polytope is the segment's minus r.
 *
 * 1. **Signed distance** of the segment and the polytope by the GJK / EPA of convex-polytope.ts,
 *    in the capsule's frame, the segment loaded as a polytope of two vertices (±h·e₁): GJK when
 *    they are apart (the capsule is resting: the segment stays r above the surface), EPA when
 *    the segment itself goes in (deep penetration still gets its least-translation normal and
 *    depth). Beyond margin + r: no contact.
 * 2. **Face or not.** The separation of the segment along each facet normal of the polytope (its
 *    lower end's height); when the best comes within `featureTieTolerance` of the signed
 *    distance, that facet carries the contact.
 * 3. **Face contact:** the segment projected onto the facet's plane and clipped by every other
 *    (non-coplanar) facet's half-space — in the plane, the polytope is exactly the face — gives
 *    an interval of the segment; each of its two ends is a contact point, separation its height
 *    above the plane minus r. A capsule lying on a face so gets two points and rests; a capsule
 *    standing on it gets one (its upper end is far beyond the margin). When the clipping cut off
 *    the deepest part of the segment (its deepest point lies past the face's edge by more than
 *    the tie), step 4 is taken instead.
 * 4. **Otherwise** (the closest feature is an edge or a corner): one point midway between the
 *    surfaces at GJK/EPA's witness on the segment.
 *
 * Feature ids: face contact — FNV-1a of (face, end, the facet that clipped the end or none), top
 * bit clear; other — FNV-1a of the supporting vertices, top bit set.
 *
 * Unchecked hot-path kernels (see PairCollider); they read the margin from
 * `scratch.scalars[NARROWPHASE_MARGIN]` and allocate nothing once the polytope scratch has grown
 * to the largest meshes seen.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import type { CollisionBox, CollisionCapsule, CollisionMesh } from './narrowphase-shapes.js';
import { NARROWPHASE_MARGIN } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import {
  loadBox,
  loadMesh,
  loadRelativePose,
  POLY_BEYOND,
  PS_MARGIN,
  polytopeScratch,
  polytopeSeparationKernel,
} from './convex-polytope.js';
import type { PolytopeScratch } from './convex-polytope.js';

/** Two unit normals with a dot product at least this are the same plane direction. */
const PARALLEL_DOT = 1 - 1e-10;
/** A segment whose two projected ends lie within this × size outside a facet plane is kept (cut to it). */
const ON_PLANE = 1e-9;
/** Bit of the ids of contacts that are not face contacts. */
const NON_FACE_ID = 0x80000000;

/** Contacts between a capsule (A) and a box (B), normal from A to B (see the module comment). */
export function collideCapsuleBoxKernel(
  out: Manifold,
  n: number,
  a: CollisionCapsule,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const ps = polytopeScratch(scratch);
  loadRelativePose(n, ps, poseA, poseB);
  loadBox(n, ps, b, true);
  return capsulePolytope(out, n, a, ps, poseA, scratch);
}

/** Contacts between a capsule (A) and a convex mesh (B), normal from A to B (see the module comment). */
export function collideCapsuleMeshKernel(
  out: Manifold,
  n: number,
  a: CollisionCapsule,
  poseA: Pose,
  b: CollisionMesh,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const ps = polytopeScratch(scratch);
  loadRelativePose(n, ps, poseA, poseB);
  loadMesh(n, ps, b, true);
  return capsulePolytope(out, n, a, ps, poseA, scratch);
}

/** The capsule's core segment as polytope A: vertices −h·e₁ and +h·e₁, no facets. */
function loadSegment(n: number, ps: PolytopeScratch, h: number): void {
  const V = ps.aV; // at least 32·n numbers (createPolytopeScratch), never shrunk
  for (let c = 0; c < 2 * n; c += 1) V[c] = 0;
  V[1] = -h;
  V[n + 1] = h;
  ps.aVC = 2;
  ps.aFC = 0;
  if (h > ps.size) ps.size = h;
}

function capsulePolytope(
  out: Manifold,
  n: number,
  a: CollisionCapsule,
  ps: PolytopeScratch,
  poseA: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const r = a.radius;
  const h = a.halfHeight;
  loadSegment(n, ps, h);
  ps.scalars[PS_MARGIN] = margin + r;
  polytopeSeparationKernel(n, ps, scratch);
  if (ps.status === POLY_BEYOND || !(ps.separation - r < margin)) {
    out.count = 0;
    return false;
  }
  // the segment's separation along each facet normal of B: −h·|N_g[1]| − o_g
  const N = ps.bN;
  let best = -Infinity;
  let face = 0;
  for (let g = 0; g < ps.bFC; g += 1) {
    const s = -h * Math.abs(N[g * n + 1]) - ps.bO[g];
    if (s > best) {
      best = s;
      face = g;
    }
  }
  let count = 0;
  if (ps.supportCount === 0 || best >= ps.separation - scratch.featureTieTolerance) {
    count = faceContact(out, n, a, ps, face, poseA, scratch);
    // the clipped face points must hold the penetration: when the clipping cut off the deepest
    // part of the segment (it goes in past the face's edge), the witness point carries the contact
    let low = Infinity;
    for (let k = 0; k < count; k += 1) if (out.separations[k] < low) low = out.separations[k];
    if (count > 0 && low > ps.separation - r + scratch.featureTieTolerance) count = 0;
  }
  if (count === 0 && ps.supportCount > 0) count = witnessContact(out, n, a, ps, poseA);
  out.count = count;
  return count > 0;
}

function fnv(h: number, value: number): number {
  return Math.imul(h ^ value, 0x01000193);
}

/** The face contact on B's facet `face` (step 3 of the module comment); returns the count of points. */
function faceContact(
  out: Manifold,
  n: number,
  a: CollisionCapsule,
  ps: PolytopeScratch,
  face: number,
  poseA: Pose,
  scratch: NarrowphaseScratch,
): number {
  const margin = scratch.scalars[NARROWPHASE_MARGIN];
  const h = a.halfHeight;
  const r = a.radius;
  const N = ps.bN;
  const O = ps.bO;
  const f = face * n;
  const o = O[face];
  const ny = N[f + 1];
  // heights of the two ends above the face's plane
  const height0 = -h * ny - o;
  const height1 = h * ny - o;
  const tol = ON_PLANE * ps.size;
  let lo = 0;
  let hi = 1;
  let loFacet = -1;
  let hiFacet = -1;
  let canonical = face;
  for (let g = 0; g < ps.bFC; g += 1) {
    if (g === face) continue;
    let dot = 0;
    for (let c = 0; c < n; c += 1) dot += N[g * n + c] * N[f + c];
    if (dot >= PARALLEL_DOT) {
      if (g < canonical) canonical = g;
      continue;
    }
    // N_g · (projected end) − o_g at both ends; the projection is p − height·N
    const f0 = -h * N[g * n + 1] - height0 * dot - O[g];
    const f1 = h * N[g * n + 1] - height1 * dot - O[g];
    if (f0 > tol && f1 > tol) return 0;
    if (f0 > 0) {
      const cut = f0 / (f0 - f1);
      if (cut > lo) {
        lo = cut;
        loFacet = g;
      }
    } else if (f1 > 0) {
      const cut = f0 / (f0 - f1);
      if (cut < hi) {
        hi = cut;
        hiFacet = g;
      }
    }
  }
  if (lo > hi) return 0;
  const M = poseA.M;
  const x = poseA.x;
  let count = 0;
  for (let k = 0; k < 2; k += 1) {
    const s = k === 0 ? lo : hi;
    const y = -h + 2 * h * s;
    const height = ny * y - o;
    const separation = height - r;
    if (!(separation < margin)) continue;
    // midpoint of the capsule's surface point (y·e₁ − r·N) and the plane point (y·e₁ − height·N)
    const down = (r + height) / 2;
    for (let i = 0; i < n; i += 1) {
      let w = x[i] + M[i * n + 1] * y;
      for (let c = 0; c < n; c += 1) w -= M[i * n + c] * N[f + c] * down;
      out.points[count * n + i] = w;
    }
    out.separations[count] = separation;
    let id = fnv(0x811c9dc5, canonical);
    id = fnv(id, k);
    id = fnv(id, k === 0 ? loFacet : hiFacet);
    out.ids[count] = (id & ~NON_FACE_ID) >>> 0;
    count += 1;
  }
  if (count === 0) return 0;
  for (let i = 0; i < n; i += 1) {
    let w = 0;
    for (let c = 0; c < n; c += 1) w -= M[i * n + c] * N[f + c];
    out.normal[i] = w;
  }
  return count;
}

/** Sorts the first `count` entries of `a` in place (insertion sort: a handful of indices). */
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

/** One point midway between the surfaces at the segment's witness point (step 4); returns 1. */
function witnessContact(out: Manifold, n: number, a: CollisionCapsule, ps: PolytopeScratch, poseA: Pose): number {
  const M = poseA.M;
  const x = poseA.x;
  const u = ps.normal;
  const along = (a.radius + ps.separation) / 2;
  for (let i = 0; i < n; i += 1) {
    let p = x[i];
    let w = 0;
    for (let c = 0; c < n; c += 1) {
      p += M[i * n + c] * (ps.witnessA[c] + along * u[c]);
      w += M[i * n + c] * u[c];
    }
    out.points[i] = p;
    out.normal[i] = w;
  }
  out.separations[0] = ps.separation - a.radius;
  sortInts(ps.supportA, ps.supportCount);
  sortInts(ps.supportB, ps.supportCount);
  let id = fnv(0x811c9dc5, 5);
  for (let k = 0; k < ps.supportCount; k += 1) id = fnv(id, ps.supportA[k]);
  id = fnv(id, -1);
  for (let k = 0; k < ps.supportCount; k += 1) id = fnv(id, ps.supportB[k]);
  out.ids[0] = (id | NON_FACE_ID) >>> 0;
  return 1;
}
