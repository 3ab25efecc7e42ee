/**
 * Collecting raw contact candidates and reducing them to a manifold's bound.
 *
 * Reduction: the deepest candidate first (it carries the penetration the solver must remove),
 * where candidates within `featureTieTolerance` of the deepest count as equally deep and the one
 * of lowest feature id is taken — a face resting flat has many corners at the same depth up to
 * rounding, and picking among them by noise would change the kept set (and lose the warm-start
 * impulses) every step; then, repeatedly, the candidate farthest from every point kept so far, distance measured in
 * the tangent space (the component along the normal ignored). Farthest-point order picks the
 * extremes of the contact region along its tangent directions first and keeps antipodal pairs of
 * a symmetric region, so the kept set spans the region and its hull contains the centre. Ties go
 * to the lower candidate index, so the choice is deterministic for a given candidate order.
 *
 * Unchecked kernels; they allocate nothing.
 *
 * @module
 */
import type { Manifold } from './manifold.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';

/** Empties a candidate buffer. */
export function clearCandidates(buf: Manifold): void {
  buf.count = 0;
}

/**
 * Reserves a slot for a candidate of separation `values[at]` and returns its index, or −1 when
 * the buffer is full and every held candidate is at least as deep (the shallowest is replaced
 * otherwise). The caller writes the point (n numbers at index·n) and the id; the separation is
 * written here. (The separation travels in an array: a double argument of a call V8 does not
 * inline would be boxed.)
 */
export function candidateSlot(buf: Manifold, values: Float64Array, at: number): number {
  const separation = values[at];
  if (buf.count < buf.capacity) {
    const index = buf.count;
    buf.count += 1;
    buf.separations[index] = separation;
    return index;
  }
  let worst = 0;
  for (let i = 1; i < buf.count; i += 1) if (buf.separations[i] > buf.separations[worst]) worst = i;
  if (!(separation < buf.separations[worst])) return -1;
  buf.separations[worst] = separation;
  return worst;
}

/**
 * Writes the candidates into `out` with `normal` (unit, A to B), keeping at most `out.capacity`
 * points as described in the module comment. Returns true when at least one point was written.
 *
 * @param scratch - its `reduceDistance` (at least `candidates.count` numbers) is used, and its
 *   `featureTieTolerance` decides which depths tie.
 */
export function reduceCandidates(
  out: Manifold,
  n: number,
  candidates: Manifold,
  normal: ArrayLike<number>,
  scratch: NarrowphaseScratch,
): boolean {
  const distance = scratch.reduceDistance;
  for (let c = 0; c < n; c += 1) out.normal[c] = normal[c];
  const count = candidates.count;
  const cap = out.capacity;
  if (count <= cap) {
    for (let p = 0; p < count; p += 1) copyCandidate(out, p, candidates, p, n);
    out.count = count;
    return count > 0;
  }
  const seps = candidates.separations;
  let deepest = 0;
  for (let p = 1; p < count; p += 1) if (seps[p] < seps[deepest]) deepest = p;
  const tie = seps[deepest] + scratch.featureTieTolerance;
  for (let p = 0; p < count; p += 1) {
    if (seps[p] <= tie && candidates.ids[p] < candidates.ids[deepest]) deepest = p;
  }
  const pts = candidates.points;
  for (let p = 0; p < count; p += 1) distance[p] = Infinity;
  let chosen = deepest;
  for (let kept = 0; kept < cap; kept += 1) {
    copyCandidate(out, kept, candidates, chosen, n);
    distance[chosen] = -1;
    if (kept === cap - 1) break;
    const o = chosen * n;
    let next = -1;
    let best = -1;
    for (let p = 0; p < count; p += 1) {
      if (distance[p] < 0) continue;
      let d2 = 0;
      let along = 0;
      for (let c = 0; c < n; c += 1) {
        const delta = pts[p * n + c] - pts[o + c];
        d2 += delta * delta;
        along += delta * normal[c];
      }
      d2 -= along * along;
      if (d2 < distance[p]) distance[p] = d2;
      if (distance[p] > best) {
        best = distance[p];
        next = p;
      }
    }
    chosen = next;
  }
  out.count = cap;
  return true;
}

function copyCandidate(out: Manifold, to: number, from: Manifold, index: number, n: number): void {
  for (let c = 0; c < n; c += 1) out.points[to * n + c] = from.points[index * n + c];
  out.separations[to] = from.separations[index];
  out.ids[to] = from.ids[index];
}
