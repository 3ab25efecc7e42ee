/**
 * Small unchecked geometry kernels for simplicial meshes: determinants, facet normals and the
 * moments of a cone. Callers validate first; these allocate nothing but what they are given.
 *
 * Storage: points are flat (`n` numbers each); a facet is `n` vertex indices into them.
 *
 * @module
 */

/**
 * Determinant of the m×m row-major matrix `a` by Gaussian elimination with partial pivoting.
 * Unchecked; `a` is overwritten. m = 0 gives 1.
 */
export function determinantInPlace(m: number, a: Float64Array): number {
  let det = 1;
  for (let col = 0; col < m; col += 1) {
    let pivot = col;
    let best = Math.abs(a[col * m + col]);
    for (let row = col + 1; row < m; row += 1) {
      const v = Math.abs(a[row * m + col]);
      if (v > best) {
        best = v;
        pivot = row;
      }
    }
    if (best === 0) return 0;
    if (pivot !== col) {
      for (let c = col; c < m; c += 1) {
        const t = a[col * m + c];
        a[col * m + c] = a[pivot * m + c];
        a[pivot * m + c] = t;
      }
      det = -det;
    }
    const d = a[col * m + col];
    det *= d;
    for (let row = col + 1; row < m; row += 1) {
      const f = a[row * m + col] / d;
      if (f === 0) continue;
      for (let c = col + 1; c < m; c += 1) a[row * m + c] -= f * a[col * m + c];
    }
  }
  return det;
}

/**
 * The (unnormalised) normal of facet `f`: the vector N with
 * N · x = det[x, a_1 − a_0, …, a_(n−1) − a_0] for every x, where a_0..a_(n−1) are the facet's
 * vertices in the stored order. |N| = (n−1)! × the facet's (n−1)-volume, and the signed volume of
 * the cone from a point p over the facet is N · (a_0 − p) / n!.
 * In 3D, N = (a_1 − a_0) × (a_2 − a_0).
 *
 * Unchecked. `scratch` needs n(n−1) + (n−1)² numbers.
 */
export function facetNormal(
  n: number,
  out: Float64Array,
  vertices: ArrayLike<number>,
  facets: ArrayLike<number>,
  f: number,
  scratch: Float64Array,
): Float64Array {
  const m = n - 1;
  const base = facets[f * n] * n;
  // edges: n rows (coordinates) × m columns (edge vectors)
  for (let e = 0; e < m; e += 1) {
    const v = facets[f * n + e + 1] * n;
    for (let c = 0; c < n; c += 1) scratch[c * m + e] = vertices[v + c] - vertices[base + c];
  }
  const minor = scratch.subarray(n * m, n * m + m * m);
  for (let c = 0; c < n; c += 1) {
    let row = 0;
    for (let rr = 0; rr < n; rr += 1) {
      if (rr === c) continue;
      for (let e = 0; e < m; e += 1) minor[row * m + e] = scratch[rr * m + e];
      row += 1;
    }
    // cofactor expansion of det[x, edges] along its first column
    const det = determinantInPlace(m, minor);
    out[c] = c % 2 === 0 ? det : -det;
  }
  return out;
}

/** n! for a small integer n. */
export function factorial(n: number): number {
  let f = 1;
  for (let i = 2; i <= n; i += 1) f *= i;
  return f;
}

/**
 * Accumulators of the moments of a solid: signed volume V = ∫ dV, first moment S1 = ∫ x dV
 * (n numbers) and second moment S2 = ∫ x xᵀ dV (n×n), all about a reference point.
 */
export interface Moments {
  volume: number;
  readonly first: Float64Array;
  readonly second: Float64Array;
}

/** A zeroed {@link Moments} for n dimensions. */
export function createMoments(n: number): Moments {
  return { volume: 0, first: new Float64Array(n), second: new Float64Array(n * n) };
}

/**
 * Adds the moments of the simplex with vertices p, a_0..a_(n−1) (the cone from p over a facet),
 * about p, weighted by the signed volume `signedVolume` of that simplex. `w` holds the n facet
 * vertices relative to p (flat, n×n); `sum` is scratch for n numbers.
 *
 * A simplex with vertices v_0..v_n about the origin has ∫ x xᵀ dV = V/((n+1)(n+2)) ·
 * (Σ v vᵀ + (Σ v)(Σ v)ᵀ) and ∫ x dV = V (Σ v)/(n+1); here v_0 = p − p = 0.
 * Unchecked.
 */
export function addCone(n: number, acc: Moments, w: Float64Array, signedVolume: number, sum: Float64Array): void {
  sum.fill(0);
  for (let a = 0; a < n; a += 1) for (let c = 0; c < n; c += 1) sum[c] += w[a * n + c];
  acc.volume += signedVolume;
  const f1 = signedVolume / (n + 1);
  for (let c = 0; c < n; c += 1) acc.first[c] += f1 * sum[c];
  const f2 = signedVolume / ((n + 1) * (n + 2));
  for (let r = 0; r < n; r += 1) {
    for (let c = r; c < n; c += 1) {
      let s = sum[r] * sum[c];
      for (let a = 0; a < n; a += 1) s += w[a * n + r] * w[a * n + c];
      acc.second[r * n + c] += f2 * s;
    }
  }
}

/**
 * Turns moments about a reference point into the centroid (relative to that point) and the
 * volume-weighted covariance about the centroid, ∫ (x − g)(x − g)ᵀ dV = S2 − V g gᵀ, filling the
 * lower triangle of S2 from the upper one. `outCentroid` gets g = S1 / V. Unchecked; V ≠ 0.
 */
export function centreMoments(n: number, acc: Moments, outCentroid: Float64Array, outCovariance: Float64Array): void {
  const V = acc.volume;
  for (let c = 0; c < n; c += 1) outCentroid[c] = acc.first[c] / V;
  for (let r = 0; r < n; r += 1) {
    for (let c = r; c < n; c += 1) {
      const v = acc.second[r * n + c] - V * outCentroid[r] * outCentroid[c];
      outCovariance[r * n + c] = v;
      outCovariance[c * n + r] = v;
    }
  }
}
