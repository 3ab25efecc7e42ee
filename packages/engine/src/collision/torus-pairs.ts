/**
 * Torus–box, torus–convex mesh, torus–capsule and torus–torus contacts, any n >= 3 (and the
 * manifold assembly torus–ball shares, torus-sphere.ts).
 *
 * **Method.** The solid torus A is a ball of radius r swept along its core circle
 * c(θ) = x + R(cos θ e_i + sin θ e_j). Its gap to the other shape B is the minimum over θ of
 * g(θ) = dist(c(θ), B's core) − r − r_B, where B's core is the convex polytope itself (box, mesh;
 * r_B = 0), the segment ±halfHeight·e₁ (capsule, r_B = its radius) or B's core circle (torus,
 * r_B = its tube radius). dist(·) is exact and signed: a box by clamping (inside: the nearest
 * face), a mesh by its facet planes when the point is inside (the nearest facet) and by GJK
 * (convex-polytope.ts, point against polytope) when outside, a segment and a circle in closed
 * form. g has several local minima (a linked pair of rings, a ring hanging over a box's two top
 * edges): g is sampled at S = 4·torusRingPoints body-fixed angles θ_k = 2πk/S, and every sampled
 * local minimum whose bracket [θ_(k−1), θ_(k+1)] may reach below the margin (g is R-Lipschitz in
 * θ, so the bracket's minimum is at least g_k − R·π/S) is refined: the span of two samples either side is
 * sampled 4 times finer, then golden-section search round the best and a last parabolic step (to about 1e-9 rad on a smooth g). Each refined minimum below the margin is
 * a contact (id S + k); a minimum whose bracket is flat within featureTieTolerance (a torus lying
 * flat on a face, where the whole circle is equally near) is not refined, and the body-fixed ring
 * samples (id k, each below the margin) carry the contact instead, spread round the circle so the
 * torus rests still; the samples within two of a refined minimum's bracket are left out (as
 * torus–half-space leaves out the ring point beside its exact one): on a curved surface their own
 * normals lean away from the minimum's and would tilt the common normal.
 *
 * **One normal.** A manifold has one normal (manifold.ts), but a ring's contacts need not share
 * one (a ball in a ring touches the tube round a whole circle, a ring hanging over a box touches
 * its two edges). {@link assembleTorusManifold} keeps the candidates within `band` (the margin, at
 * least featureTieTolerance) of the deepest, weighs each by how much deeper than that bound it is,
 * and takes as the normal the weighted mean of their own normals (when those nearly cancel, under
 * 0.2 of the total weight, the deepest one's normal); a candidate whose own normal is more than 78°
 * from it is dropped, and each kept separation is its gap measured along the common normal,
 * g/cos(angle). A symmetric contact set thus pushes along its axis (a ball in a ring straight
 * up), an off-centre one back toward the centre, and a single contact keeps its exact normal.
 *
 * Working memory: scratch.v0..v4, scratch.t, scratch.sat's two vectors, scalars[13..15], and the
 * polytope scratch (convex-polytope.ts; its clip buffers hold the per-sample gaps and normals).
 * Unchecked hot-path kernels (see PairCollider); they allocate nothing once the scratch has grown.
 *
 * @module
 */
import type { Manifold, Pose } from './manifold.js';
import { candidateSlot, clearCandidates, reduceCandidates } from './manifold-reduce.js';
import type { CollisionCapsule, CollisionMesh, CollisionTorus } from './narrowphase-shapes.js';
import type { CollisionBox } from './narrowphase-shapes.js';
import { ensureCandidateCapacity, NARROWPHASE_MARGIN, SCALAR_CANDIDATE } from './narrowphase-scratch.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import {
  ensureClipCapacity,
  loadMesh,
  POLY_BEYOND,
  POLY_SEPARATED,
  polytopeScratch,
  polytopeSeparationKernel,
  PS_MARGIN,
} from './convex-polytope.js';
import type { PolytopeScratch } from './convex-polytope.js';

/** Index in scratch.scalars of the angle θ handed to the gap evaluation. */
const S_THETA = 13;
/** Index in scratch.scalars of the gap the evaluation returns (m). */
const S_GAP = 14;
/** Index in scratch.scalars of the reach (margin + slack) the mesh evaluation needs exactly. */
const S_REACH = 15;

/** Samples of the core circle per torusRingPoints (S = 4·8 = 32 by default: 11.25° apart). */
const SAMPLES_PER_RING_POINT = 4;

const KIND_BOX = 0;
const KIND_MESH = 1;
const KIND_CAPSULE = 2;
const KIND_TORUS = 3;

/**
 * Intervals the span [θ_(k−2), θ_(k+2)] round a sampled minimum is first cut into (two minima may
 * lie within a sample spacing or two, where the tube cuts deep into a polytope).
 */
const SUB_SAMPLES = 16;
/** Golden-section iterations of a refinement (the sub-bracket shrinks by 0.618 each: 0.618³² ≈ 2e-7). */
const GOLDEN_ITERATIONS = 32;
const INV_PHI = (Math.sqrt(5) - 1) / 2;
/**
 * A candidate whose normal is farther than this cosine (about 78°) from the common normal is
 * dropped (a ball wedged in a ring touches at 60° and more from the axis).
 */
const MIN_COS = 0.2;

/**
 * Contacts between a torus (A) and a box, a convex mesh, a capsule or a torus (B), normal from A
 * to B (see the module comment), with the margin as an argument. Unchecked; allocates nothing
 * once the scratch has grown.
 */
export function collideTorusOther(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionBox | CollisionMesh | CollisionCapsule | CollisionTorus,
  poseB: Pose,
  margin: number,
  scratch: NarrowphaseScratch,
): boolean {
  scratch.scalars[NARROWPHASE_MARGIN] = margin;
  const kind = b.kind === 'box' ? KIND_BOX : b.kind === 'mesh' ? KIND_MESH : b.kind === 'capsule' ? KIND_CAPSULE : KIND_TORUS;
  return torusPair(out, n, a, poseA, b, poseB, scratch, kind);
}

/** Torus (A) – box (B), the margin read from scratch.scalars[NARROWPHASE_MARGIN] (pair-kernel.ts). */
export function collideTorusBoxKernel(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  return torusPair(out, n, a, poseA, b, poseB, scratch, KIND_BOX);
}

/** Torus (A) – convex mesh (B), as {@link collideTorusBoxKernel}. */
export function collideTorusMeshKernel(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionMesh,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  return torusPair(out, n, a, poseA, b, poseB, scratch, KIND_MESH);
}

/** Torus (A) – capsule (B), as {@link collideTorusBoxKernel}. */
export function collideTorusCapsuleKernel(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionCapsule,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  return torusPair(out, n, a, poseA, b, poseB, scratch, KIND_CAPSULE);
}

/** Torus (A) – torus (B), as {@link collideTorusBoxKernel}. */
export function collideTorusTorusKernel(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: CollisionTorus,
  poseB: Pose,
  scratch: NarrowphaseScratch,
): boolean {
  return torusPair(out, n, a, poseA, b, poseB, scratch, KIND_TORUS);
}

type Other = CollisionBox | CollisionMesh | CollisionCapsule | CollisionTorus;

/** The common kernel (see the module comment); works in B's frame. */
function torusPair(
  out: Manifold,
  n: number,
  a: CollisionTorus,
  poseA: Pose,
  b: Other,
  poseB: Pose,
  scratch: NarrowphaseScratch,
  kind: number,
): boolean {
  const scalars = scratch.scalars;
  const margin = scalars[NARROWPHASE_MARGIN];
  const MA = poseA.M;
  const MB = poseB.M;
  const xa = poseA.x;
  const xb = poseB.x;
  const R = a.majorRadius;
  const pi = a.planeI;
  const pj = a.planeJ;
  // the core circle in B's frame: T + cos θ U + sin θ V
  const T = scratch.v0;
  const U = scratch.v1;
  const V = scratch.v2;
  let tLen2 = 0;
  for (let c = 0; c < n; c += 1) {
    let t = 0;
    let u = 0;
    let v = 0;
    for (let i = 0; i < n; i += 1) {
      const m = MB[i * n + c];
      t += m * (xa[i] - xb[i]);
      u += m * MA[i * n + pi];
      v += m * MA[i * n + pj];
    }
    T[c] = t;
    U[c] = R * u;
    V[c] = R * v;
    tLen2 += t * t;
  }
  // the whole torus lies within R + r of its centre: farther than that (plus B's radius and the
  // margin) from B's core, nothing touches
  scalars[S_GAP] = a.minorRadius + R + margin;
  if (farApart(n, kind, b, T, scratch)) {
    out.count = 0;
    return false;
  }
  const ps = polytopeScratch(scratch);
  const K = scratch.torusRingPoints;
  const S = SAMPLES_PER_RING_POINT * K;
  ensureClipCapacity(ps, 4 * S);
  const slack = (R * Math.PI) / S;
  scalars[S_REACH] = margin + a.minorRadius + slack;
  if (kind === KIND_MESH) {
    ps.size = Math.sqrt(tLen2) + R;
    loadMesh(n, ps, b as CollisionMesh, false);
  }
  const gaps = ps.cO;
  const normals = ps.cN;
  const skip = ps.cId;
  const Nn = scratch.v4;
  let lowest = Infinity;
  for (let k = 0; k < S; k += 1) {
    scalars[S_THETA] = (2 * Math.PI * k) / S;
    evalGap(n, kind, a, b, ps, scratch);
    const g = scalars[S_GAP];
    gaps[k] = g;
    for (let c = 0; c < n; c += 1) normals[k * n + c] = Nn[c];
    skip[k] = 0;
    if (g < lowest) lowest = g;
  }
  if (!(lowest - slack < margin)) {
    out.count = 0;
    return false;
  }
  const cand = ensureCandidateCapacity(scratch, S + S / 2 + 1);
  clearCandidates(cand);
  const tie = scratch.featureTieTolerance;
  // refined minima: candidate data at index S + slot of gaps/normals, their angles from 3S on
  let found = 0;
  for (let k = 0; k < S; k += 1) {
    const g = gaps[k];
    const prev = gaps[(k + S - 1) % S];
    const next = gaps[(k + 1) % S];
    if (!(g < prev && g <= next && g - slack < margin)) continue;
    if (!(Math.max(prev, next) - g > tie)) continue;
    refine(n, kind, a, b, ps, scratch, k, S);
    const gm = scalars[S_GAP];
    const theta = scalars[S_THETA];
    // two neighbouring samples' searches may end at the same minimum: keep the first
    let seen = false;
    for (let m = 0; m < found; m += 1) {
      const d = Math.abs(gaps[3 * S + m] - theta);
      if (d < 1e-6 || Math.abs(d - 2 * Math.PI) < 1e-6) seen = true;
    }
    if (seen) continue;
    gaps[3 * S + found] = theta;
    found += 1;
    // the samples of the span searched are left out: on a curved surface their own normals lean
    // away from the minimum's and would tilt the common normal (a ring lying across a ring slid off)
    for (let q = k - 2; q <= k + 2; q += 1) skip[(q + S) % S] = 1;
    if (!(gm < margin)) continue;
    addCandidate(cand, n, a, poseB, ps, scratch, S + k);
  }
  for (let k = 0; k < S; k += 1) {
    if (skip[k] === 1 || !(gaps[k] < margin)) continue;
    scalars[S_THETA] = (2 * Math.PI * k) / S;
    scalars[S_GAP] = gaps[k];
    for (let c = 0; c < n; c += 1) Nn[c] = normals[k * n + c];
    addCandidate(cand, n, a, poseB, ps, scratch, k);
  }
  return assembleTorusManifold(out, n, cand, ps, S, MB, scratch);
}

/**
 * Whether B's core is farther than scalars[S_GAP] (+ B's radius) from the point T (B's frame): a
 * lower bound of the distance (the mesh: its farthest facet plane). Uses scratch.t.
 */
function farApart(n: number, kind: number, b: Other, T: Float64Array, scratch: NarrowphaseScratch): boolean {
  const reach = scratch.scalars[S_GAP];
  let d2 = 0;
  if (kind === KIND_BOX) {
    const h = (b as CollisionBox).halfExtents;
    for (let c = 0; c < n; c += 1) {
      const e = Math.abs(T[c]) - h[c];
      if (e > 0) d2 += e * e;
    }
    return d2 > reach * reach;
  }
  if (kind === KIND_MESH) {
    const mesh = b as CollisionMesh;
    const FN = mesh.facetNormals;
    const FO = mesh.facetOffsets;
    for (let f = 0; f < FO.length; f += 1) {
      let s = -FO[f];
      for (let c = 0; c < n; c += 1) s += FN[f * n + c] * T[c];
      if (s > reach) return true;
    }
    return false;
  }
  if (kind === KIND_CAPSULE) {
    const cap = b as CollisionCapsule;
    const hh = cap.halfHeight;
    for (let c = 0; c < n; c += 1) {
      const e = c === 1 ? Math.abs(T[c]) - hh : T[c];
      if (c !== 1 || e > 0) d2 += e * e;
    }
    const far = reach + cap.radius;
    return d2 > far * far;
  }
  const tor = b as CollisionTorus;
  for (let c = 0; c < n; c += 1) d2 += T[c] * T[c];
  const far = reach + tor.majorRadius + tor.minorRadius;
  if (d2 > far * far) return true;
  // Two slabs. B lies within r_B of its plane (through its centre, spanned by e_bi, e_bj), A's
  // tube within r_A of its core circle: if the circle keeps farther than r_A + r_B + margin from
  // that plane, nothing touches, and the same with the roles swapped. Each distance is bounded
  // below along one unit direction w normal to the plane (the distance from a plane is at least
  // the component along any such w): w along the part of the other centre off the plane, where
  // the circle's reach along w is R·|(its plane's axes)·w|.
  const U = scratch.v1;
  const V = scratch.v2;
  const bi = tor.planeI;
  const bj = tor.planeJ;
  const Rb = tor.majorRadius;
  let u2 = 0;
  for (let c = 0; c < n; c += 1) u2 += U[c] * U[c];
  // r_A + margin + r_B (reach is r_A + R_A + margin; U, V carry the factor R_A)
  const rr = reach - Math.sqrt(u2) + tor.minorRadius;
  // A's circle against B's plane: w = T off the plane (e_bi, e_bj)
  let off2 = 0;
  let uw = 0;
  let vw = 0;
  for (let c = 0; c < n; c += 1) {
    if (c === bi || c === bj) continue;
    off2 += T[c] * T[c];
  }
  if (off2 > rr * rr) {
    const off = Math.sqrt(off2);
    for (let c = 0; c < n; c += 1) {
      if (c === bi || c === bj) continue;
      uw += U[c] * T[c];
      vw += V[c] * T[c];
    }
    // the circle's extent along w: |(U·w, V·w)| (U, V carry the factor R_A)
    if (off - Math.sqrt(uw * uw + vw * vw) / off > rr) return true;
  }
  // B's circle against A's plane (T + span(U, V)): w = −T off that plane
  let tu = 0;
  let tv = 0;
  for (let c = 0; c < n; c += 1) {
    tu += T[c] * U[c];
    tv += T[c] * V[c];
  }
  // U ⊥ V, |U| = |V| = R_A: T's part off A's plane is T − (T·U)U/R² − (T·V)V/R²
  const k = u2 > 0 ? 1 / u2 : 0;
  let w2 = 0;
  let wi = 0;
  let wj = 0;
  for (let c = 0; c < n; c += 1) {
    const w = T[c] - k * (tu * U[c] + tv * V[c]);
    w2 += w * w;
    if (c === bi) wi = w;
    if (c === bj) wj = w;
  }
  if (!(w2 > rr * rr)) return false;
  const wl = Math.sqrt(w2);
  return wl - (Rb * Math.sqrt(wi * wi + wj * wj)) / wl > rr;
}

/**
 * Adds the candidate of the core point at scalars[S_THETA] with gap scalars[S_GAP] and normal
 * scratch.v4 (B's frame): point midway between the surfaces, normal and gap kept in the polytope
 * scratch at index base + slot.
 */
function addCandidate(
  cand: Manifold,
  n: number,
  a: CollisionTorus,
  poseB: Pose,
  ps: PolytopeScratch,
  scratch: NarrowphaseScratch,
  id: number,
): void {
  const scalars = scratch.scalars;
  const base = SAMPLES_PER_RING_POINT * scratch.torusRingPoints;
  scalars[SCALAR_CANDIDATE] = scalars[S_GAP];
  const slot = candidateSlot(cand, scalars, SCALAR_CANDIDATE);
  if (slot < 0) return;
  const theta = scalars[S_THETA];
  const cos = Math.cos(theta);
  const sin = Math.sin(theta);
  const T = scratch.v0;
  const U = scratch.v1;
  const V = scratch.v2;
  const Nn = scratch.v4;
  const MB = poseB.M;
  const xb = poseB.x;
  const up = a.minorRadius + scalars[S_GAP] / 2;
  for (let i = 0; i < n; i += 1) {
    let s = xb[i];
    for (let c = 0; c < n; c += 1) s += MB[i * n + c] * (T[c] + cos * U[c] + sin * V[c] + up * Nn[c]);
    cand.points[slot * n + i] = s;
  }
  for (let c = 0; c < n; c += 1) ps.cN[(base + slot) * n + c] = Nn[c];
  ps.cO[base + slot] = scalars[S_GAP];
  cand.ids[slot] = id;
}

/**
 * Golden-section search for the minimum of g on [θ_(k−1), θ_(k+1)], then one parabolic step
 * through the best three points; leaves θ in scalars[S_THETA], the gap in scalars[S_GAP] and the
 * normal in scratch.v4.
 */
function refine(
  n: number,
  kind: number,
  a: CollisionTorus,
  b: Other,
  ps: PolytopeScratch,
  scratch: NarrowphaseScratch,
  k: number,
  S: number,
): void {
  const scalars = scratch.scalars;
  // the best of SUB_SAMPLES + 1 points across the bracket (two minima may share it), then its two neighbours
  const wide = (2 * Math.PI) / S;
  const step = (4 * wide) / SUB_SAMPLES;
  const start = (k - 2) * wide;
  let at = SUB_SAMPLES / 2;
  let atF = Infinity;
  for (let q = 1; q < SUB_SAMPLES; q += 1) {
    scalars[S_THETA] = start + q * step;
    evalGap(n, kind, a, b, ps, scratch);
    if (scalars[S_GAP] < atF) {
      atF = scalars[S_GAP];
      at = q;
    }
  }
  let lo = start + (at - 1) * step;
  let hi = start + (at + 1) * step;
  let x1 = hi - INV_PHI * (hi - lo);
  let x2 = lo + INV_PHI * (hi - lo);
  scalars[S_THETA] = x1;
  evalGap(n, kind, a, b, ps, scratch);
  let f1 = scalars[S_GAP];
  scalars[S_THETA] = x2;
  evalGap(n, kind, a, b, ps, scratch);
  let f2 = scalars[S_GAP];
  for (let it = 0; it < GOLDEN_ITERATIONS; it += 1) {
    if (f1 < f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - INV_PHI * (hi - lo);
      scalars[S_THETA] = x1;
      evalGap(n, kind, a, b, ps, scratch);
      f1 = scalars[S_GAP];
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + INV_PHI * (hi - lo);
      scalars[S_THETA] = x2;
      evalGap(n, kind, a, b, ps, scratch);
      f2 = scalars[S_GAP];
    }
  }
  // the best of x1, x2, their midpoint and the vertex of the parabola through the three
  let bestX = f1 < f2 ? x1 : x2;
  let bestF = f1 < f2 ? f1 : f2;
  const h = x2 - x1;
  if (h > 0) {
    const xm = 0.5 * (x1 + x2);
    scalars[S_THETA] = xm;
    evalGap(n, kind, a, b, ps, scratch);
    const fm = scalars[S_GAP];
    if (fm < bestF) {
      bestX = xm;
      bestF = fm;
    }
    // vertex of the parabola through x1, xm, x2 (equally spaced, spacing h/2)
    const den = f1 - 2 * fm + f2;
    if (den > 0) {
      const xv = xm + ((h / 2) * (f1 - f2)) / (2 * den);
      if (xv > x1 - h && xv < x2 + h) {
        scalars[S_THETA] = xv;
        evalGap(n, kind, a, b, ps, scratch);
        if (scalars[S_GAP] < bestF) bestX = xv;
      }
    }
  }
  scalars[S_THETA] = bestX;
  evalGap(n, kind, a, b, ps, scratch);
}

/**
 * The gap between the tube ball round the core point c(θ) (θ = scalars[S_THETA]) and B: into
 * scalars[S_GAP] (m, negative = overlap), with the unit normal from A to B in scratch.v4 (B's
 * frame). Uses scratch.v3 (the core point) and scratch.t.
 */
function evalGap(n: number, kind: number, a: CollisionTorus, b: Other, ps: PolytopeScratch, scratch: NarrowphaseScratch): void {
  const scalars = scratch.scalars;
  const theta = scalars[S_THETA];
  const cos = Math.cos(theta);
  const sin = Math.sin(theta);
  const T = scratch.v0;
  const U = scratch.v1;
  const V = scratch.v2;
  const P = scratch.v3;
  const Nn = scratch.v4;
  const Q = scratch.t;
  for (let c = 0; c < n; c += 1) P[c] = T[c] + cos * U[c] + sin * V[c];
  const r = a.minorRadius;
  if (kind === KIND_BOX) {
    const h = (b as CollisionBox).halfExtents;
    let d2 = 0;
    let face = 0;
    let faceGap = -Infinity;
    for (let c = 0; c < n; c += 1) {
      const p = P[c];
      const q = p > h[c] ? h[c] : p < -h[c] ? -h[c] : p;
      Q[c] = q - p;
      d2 += Q[c] * Q[c];
      const fg = Math.abs(p) - h[c];
      if (fg > faceGap) {
        faceGap = fg;
        face = c;
      }
    }
    if (d2 > 0) {
      const d = Math.sqrt(d2);
      for (let c = 0; c < n; c += 1) Nn[c] = Q[c] / d;
      scalars[S_GAP] = d - r;
    } else {
      for (let c = 0; c < n; c += 1) Nn[c] = 0;
      Nn[face] = P[face] < 0 ? 1 : -1;
      scalars[S_GAP] = faceGap - r;
    }
    return;
  }
  if (kind === KIND_MESH) {
    const mesh = b as CollisionMesh;
    const FN = mesh.facetNormals;
    const FO = mesh.facetOffsets;
    const fc = FO.length;
    let top = 0;
    let topGap = -Infinity;
    for (let f = 0; f < fc; f += 1) {
      let s = -FO[f];
      for (let c = 0; c < n; c += 1) s += FN[f * n + c] * P[c];
      if (s > topGap) {
        topGap = s;
        top = f;
      }
    }
    if (topGap > 0 && topGap < scalars[S_REACH]) {
      // outside, near: the exact distance by GJK (A = the mesh, B = the point)
      ps.bVC = 1;
      ps.bFC = 0;
      for (let c = 0; c < n; c += 1) {
        ps.bV[c] = P[c];
        ps.t[c] = P[c];
      }
      ps.scalars[PS_MARGIN] = scalars[S_REACH];
      polytopeSeparationKernel(n, ps, scratch);
      if (ps.status === POLY_SEPARATED) {
        for (let c = 0; c < n; c += 1) Nn[c] = -ps.normal[c];
        scalars[S_GAP] = ps.separation - r;
        return;
      }
      if (ps.status === POLY_BEYOND) {
        // a lower bound of the distance, past the reach
        for (let c = 0; c < n; c += 1) Nn[c] = -FN[top * n + c];
        scalars[S_GAP] = Math.max(ps.separation, topGap) - r;
        return;
      }
    }
    // inside (the nearest facet), touching, or far (a lower bound past the reach)
    for (let c = 0; c < n; c += 1) Nn[c] = -FN[top * n + c];
    scalars[S_GAP] = topGap - r;
    return;
  }
  let rb: number;
  if (kind === KIND_CAPSULE) {
    const cap = b as CollisionCapsule;
    const hh = cap.halfHeight;
    rb = cap.radius;
    for (let c = 0; c < n; c += 1) Q[c] = 0;
    Q[1] = P[1] > hh ? hh : P[1] < -hh ? -hh : P[1];
  } else {
    const tor = b as CollisionTorus;
    rb = tor.minorRadius;
    const bi = tor.planeI;
    const bj = tor.planeJ;
    const Rb = tor.majorRadius;
    const rho = Math.sqrt(P[bi] * P[bi] + P[bj] * P[bj]);
    for (let c = 0; c < n; c += 1) Q[c] = 0;
    Q[bi] = rho > 0 ? (Rb * P[bi]) / rho : Rb;
    Q[bj] = rho > 0 ? (Rb * P[bj]) / rho : 0;
  }
  let d2 = 0;
  for (let c = 0; c < n; c += 1) {
    Q[c] -= P[c];
    d2 += Q[c] * Q[c];
  }
  if (d2 > 0) {
    const d = Math.sqrt(d2);
    for (let c = 0; c < n; c += 1) Nn[c] = Q[c] / d;
    scalars[S_GAP] = d - r - rb;
  } else {
    // the core point lies on B's core: any direction normal to it, the first axis B's core does not span
    let free = 0;
    if (kind === KIND_TORUS) {
      const tor = b as CollisionTorus;
      while (free === tor.planeI || free === tor.planeJ) free += 1;
      if (free >= n) free = tor.planeI; // n = 2: the plane is all there is
    }
    for (let c = 0; c < n; c += 1) Nn[c] = 0;
    Nn[free] = 1;
    scalars[S_GAP] = -r - rb;
  }
}

/**
 * Writes the candidates (gaps in their separations; their own unit normals at
 * ps.cN[(base + slot)·n], in the frame of rotation `M`) into `out` with one normal (see the
 * module comment): the candidates within band = max(margin, featureTieTolerance) of the deepest,
 * weighted by band − (gap − deepest); the normal their weighted mean (the deepest candidate's
 * when the mean is shorter than 0.2 of the total weight); each candidate within 78° of it kept, with
 * separation gap / cos(angle). Returns whether any point was written. Allocates nothing.
 */
export function assembleTorusManifold(
  out: Manifold,
  n: number,
  cand: Manifold,
  ps: PolytopeScratch,
  base: number,
  M: Float64Array,
  scratch: NarrowphaseScratch,
): boolean {
  const count = cand.count;
  if (count === 0) {
    out.count = 0;
    return false;
  }
  const seps = cand.separations;
  const ids = cand.ids;
  const normals = ps.cN;
  const band = Math.max(scratch.scalars[NARROWPHASE_MARGIN], scratch.featureTieTolerance);
  const tie = scratch.featureTieTolerance;
  let deepest = 0;
  for (let p = 1; p < count; p += 1) if (seps[p] < seps[deepest]) deepest = p;
  const lowest = seps[deepest];
  for (let p = 0; p < count; p += 1) if (seps[p] <= lowest + tie && ids[p] < ids[deepest]) deepest = p;
  const N = scratch.sat.localNormal;
  for (let c = 0; c < n; c += 1) N[c] = 0;
  let total = 0;
  for (let p = 0; p < count; p += 1) {
    const w = band - (seps[p] - lowest);
    if (!(w > 0)) continue;
    total += w;
    for (let c = 0; c < n; c += 1) N[c] += w * normals[(base + p) * n + c];
  }
  let len2 = 0;
  for (let c = 0; c < n; c += 1) len2 += N[c] * N[c];
  if (!(len2 > MIN_COS * MIN_COS * total * total)) {
    for (let c = 0; c < n; c += 1) N[c] = normals[(base + deepest) * n + c];
  } else {
    const len = Math.sqrt(len2);
    for (let c = 0; c < n; c += 1) N[c] /= len;
  }
  // keep the candidates near the common normal, separations measured along it
  let kept = 0;
  for (let p = 0; p < count; p += 1) {
    if (!(seps[p] - lowest < band)) continue;
    let cosine = 0;
    for (let c = 0; c < n; c += 1) cosine += normals[(base + p) * n + c] * N[c];
    if (!(cosine >= MIN_COS)) continue;
    const sep = seps[p] / cosine;
    if (kept !== p) {
      for (let c = 0; c < n; c += 1) cand.points[kept * n + c] = cand.points[p * n + c];
      ids[kept] = ids[p];
    }
    seps[kept] = sep;
    kept += 1;
  }
  cand.count = kept;
  const W = scratch.sat.normal;
  for (let i = 0; i < n; i += 1) {
    let s = 0;
    for (let c = 0; c < n; c += 1) s += M[i * n + c] * N[c];
    W[i] = s;
  }
  if (kept <= out.capacity) return reduceCandidates(out, n, cand, W, scratch);
  return reduceByDepthAndSpread(out, n, cand, W, scratch);
}

/**
 * Keeps `out.capacity` of the candidates (more than that), normal `W`: the deepest first (ties
 * within featureTieTolerance to the lowest id, as reduceCandidates), then, repeatedly, the one
 * whose squared tangent distance to the nearest point kept so far, times its depth weight
 * (band − (separation − deepest))/band, is largest. Plain farthest-point order would take the
 * shallow ring samples spread round a flat pair (a ring lying on a ring, just off centre) before
 * the second, equally deep crossing of the two rings, which then goes unsupported and sinks.
 */
function reduceByDepthAndSpread(out: Manifold, n: number, cand: Manifold, W: Float64Array, scratch: NarrowphaseScratch): boolean {
  // (the band as in assembleTorusManifold, read here: a double argument would be boxed)
  const band = Math.max(scratch.scalars[NARROWPHASE_MARGIN], scratch.featureTieTolerance);
  const distance = scratch.reduceDistance;
  const count = cand.count;
  const cap = out.capacity;
  const seps = cand.separations;
  const ids = cand.ids;
  const pts = cand.points;
  for (let c = 0; c < n; c += 1) out.normal[c] = W[c];
  let deepest = 0;
  for (let p = 1; p < count; p += 1) if (seps[p] < seps[deepest]) deepest = p;
  const lowest = seps[deepest];
  const tie = lowest + scratch.featureTieTolerance;
  for (let p = 0; p < count; p += 1) if (seps[p] <= tie && ids[p] < ids[deepest]) deepest = p;
  for (let p = 0; p < count; p += 1) distance[p] = Infinity;
  let chosen = deepest;
  let kept = 0;
  while (kept < cap) {
    for (let c = 0; c < n; c += 1) out.points[kept * n + c] = pts[chosen * n + c];
    out.separations[kept] = seps[chosen];
    out.ids[kept] = ids[chosen];
    kept += 1;
    distance[chosen] = -1;
    if (kept === cap) break;
    const o = chosen * n;
    let next = -1;
    let best = 0;
    for (let p = 0; p < count; p += 1) {
      if (distance[p] < 0) continue;
      let d2 = 0;
      let along = 0;
      for (let c = 0; c < n; c += 1) {
        const delta = pts[p * n + c] - pts[o + c];
        d2 += delta * delta;
        along += delta * W[c];
      }
      d2 -= along * along;
      if (d2 < distance[p]) distance[p] = d2;
      const w = band - (seps[p] - lowest);
      const score = w > 0 ? distance[p] * w : 0;
      if (score > best) {
        best = score;
        next = p;
      }
    }
    if (next < 0) break;
    chosen = next;
  }
  out.count = kept;
  return true;
}
