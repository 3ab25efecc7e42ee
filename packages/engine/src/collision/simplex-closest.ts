/**
 * The closest point of a simplex to a point, in n dimensions, by barycentric least squares over
 * its sub-simplices.
 *
 * The closest point of a simplex lies in the relative interior of exactly one of its faces (a
 * vertex, an edge, …, the whole simplex), and there it is the orthogonal projection onto that
 * face's affine hull. So: for every non-empty vertex subset, project the point onto the subset's
 * affine hull (least squares: the Gram system of the edge vectors from the first vertex); the
 * projection is a point of the simplex iff all its barycentric coordinates are >= 0; the answer
 * is the nearest such point. Degenerate subsets (singular Gram matrix) are skipped: their points
 * are covered by smaller subsets, and single vertices always qualify. Cost: 2^m − 1 subsets of an
 * m-vertex simplex, fine for m <= n + 1 <= 9 (the narrowphase's facets have m = n).
 *
 * @module
 */
import { checkFiniteArray, checkNarrowphaseOutput } from './narrowphase-checks.js';
import { checkNarrowphaseDimension } from './manifold.js';
import { createNarrowphaseScratch } from './narrowphase-scratch-nd.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { luFactor, luSolve } from './small-linear.js';

/** Relative pivot below which a sub-simplex counts as degenerate. */
const GRAM_PIVOT_TOLERANCE = 1e-13;

/**
 * The kernel: closest point of the simplex with `m` vertices (flat in `verts`, n numbers each,
 * 1 <= m <= n + 1) to `p`. Writes the point into `out`, its barycentric coordinates into
 * `scratch.simplexBest` (m numbers, exactly 0 for vertices outside the face that holds the
 * point) and the squared distance into `scratch.scalars[3]`. Unchecked; allocates nothing.
 * Uses scratch.mat, piv, rhs, sol and simplexBary.
 */
export function closestPointOnSimplexKernel(
  n: number,
  out: Float64Array,
  verts: ArrayLike<number>,
  m: number,
  p: ArrayLike<number>,
  scratch: NarrowphaseScratch,
): void {
  const { mat, piv, rhs, sol, simplexBary: bary, simplexBest: best } = scratch;
  let bestD2 = Infinity;
  const subsets = 1 << m;
  for (let mask = 1; mask < subsets; mask += 1) {
    let v0 = -1;
    let s = 0;
    for (let i = 0; i < m; i += 1) {
      if (!(mask & (1 << i))) continue;
      if (v0 < 0) v0 = i;
      else bary[s++] = i; // the edge vectors' vertex indices, temporarily
    }
    // Gram system G μ = E (p − v0), E the edges v_k − v0
    for (let r = 0; r < s; r += 1) {
      const er = bary[r] * n;
      let b = 0;
      for (let c = 0; c < n; c += 1) b += (verts[er + c] - verts[v0 * n + c]) * (p[c] - verts[v0 * n + c]);
      rhs[r] = b;
      for (let q = r; q < s; q += 1) {
        const eq = bary[q] * n;
        let g = 0;
        for (let c = 0; c < n; c += 1) g += (verts[er + c] - verts[v0 * n + c]) * (verts[eq + c] - verts[v0 * n + c]);
        mat[r * s + q] = g;
        mat[q * s + r] = g;
      }
    }
    if (s > 0) {
      if (!luFactor(s, mat, piv, GRAM_PIVOT_TOLERANCE)) continue;
      luSolve(s, mat, piv, rhs, sol);
    }
    let lambda0 = 1;
    let inside = true;
    for (let r = 0; r < s; r += 1) {
      if (sol[r] < 0) inside = false;
      lambda0 -= sol[r];
    }
    if (!inside || lambda0 < 0) continue;
    let d2 = 0;
    for (let c = 0; c < n; c += 1) {
      let x = verts[v0 * n + c];
      for (let r = 0; r < s; r += 1) x += sol[r] * (verts[bary[r] * n + c] - verts[v0 * n + c]);
      const delta = x - p[c];
      d2 += delta * delta;
    }
    if (d2 < bestD2) {
      bestD2 = d2;
      for (let i = 0; i < m; i += 1) best[i] = 0;
      best[v0] = lambda0;
      for (let r = 0; r < s; r += 1) best[bary[r]] = sol[r];
    }
  }
  for (let c = 0; c < n; c += 1) {
    let x = 0;
    for (let i = 0; i < m; i += 1) x += best[i] * verts[i * n + c];
    out[c] = x;
  }
  scratch.scalars[3] = bestD2;
}

const scratchByN: (NarrowphaseScratch | undefined)[] = [];

/**
 * The closest point of a simplex to `point` (see the module comment). Validates its arguments,
 * then runs the kernel on a per-n scratch of this module.
 *
 * @param out - receives the closest point (Float64Array of n).
 * @param n - count of dimensions (2..8).
 * @param vertices - the simplex's m vertices, flat (m·n finite numbers, 1 <= m <= n + 1); a
 *   degenerate simplex is allowed (the nearest point of its convex hull is returned).
 * @param point - the query point (n finite numbers).
 * @param outBarycentric - optional, receives the m barycentric coordinates of the closest point.
 * @returns the distance (m).
 * @throws TypeError for wrong types or lengths; RangeError for n out of range or non-finite numbers.
 */
export function closestPointOnSimplex(
  out: Float64Array,
  n: number,
  vertices: ArrayLike<number>,
  point: ArrayLike<number>,
  outBarycentric?: Float64Array,
): number {
  checkNarrowphaseDimension(n, 'n');
  checkNarrowphaseOutput(out, n, 'out');
  if (vertices === null || typeof vertices !== 'object' || typeof vertices.length !== 'number') {
    throw new TypeError(`closestPointOnSimplex: 'vertices' must be a flat array of numbers`);
  }
  const m = vertices.length / n;
  if (!Number.isInteger(m) || m < 1 || m > n + 1) {
    throw new TypeError(
      `closestPointOnSimplex: 'vertices' must hold 1 to ${n + 1} points of ${n} numbers, got ${vertices.length} numbers`,
    );
  }
  checkFiniteArray(vertices, m * n, 'vertices');
  checkFiniteArray(point, n, 'point');
  if (outBarycentric !== undefined) checkNarrowphaseOutput(outBarycentric, m, 'outBarycentric');
  let scratch = scratchByN[n];
  if (!scratch) {
    scratch = createNarrowphaseScratch(n);
    scratchByN[n] = scratch;
  }
  closestPointOnSimplexKernel(n, out, vertices, m, point, scratch);
  const d2 = scratch.scalars[3];
  if (outBarycentric) for (let i = 0; i < m; i += 1) outBarycentric[i] = scratch.simplexBest[i];
  return Math.sqrt(d2);
}
