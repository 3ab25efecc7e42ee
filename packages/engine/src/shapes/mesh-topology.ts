/**
 * Checks that a list of facets ((n−1)-simplices, n vertex indices each) is the boundary of a
 * solid: every (n−2)-face (a facet less one vertex; in 3D an edge) belongs to exactly two
 * facets, and those two facets are oriented consistently (they induce opposite orientations on
 * the face they share, as two triangles of a closed surface run their shared edge in opposite
 * directions).
 *
 * @module
 */

/** Parity (0 even, 1 odd) of the permutation that sorts `a` (distinct values); sorts `a`. */
function sortParity(a: Int32Array): number {
  let parity = 0;
  for (let i = 1; i < a.length; i += 1) {
    const x = a[i];
    let j = i - 1;
    while (j >= 0 && a[j] > x) {
      a[j + 1] = a[j];
      j -= 1;
      parity ^= 1;
    }
    a[j + 1] = x;
  }
  return parity;
}

/** Names used in the error messages of {@link checkClosedBoundary}. */
export interface BoundaryNames {
  /** The function that was called, e.g. 'ConvexMesh'. */
  readonly where: string;
  /** The argument that holds the facets, e.g. 'facets'. */
  readonly facets: string;
  /** How to name facet f in a message; default `'<facets>'[f]`. */
  readonly facet?: (f: number) => string;
}

/**
 * Throws a RangeError naming the facets argument unless the facets form a closed, consistently
 * oriented boundary (see the module comment). Facets must already hold valid, distinct indices.
 *
 * @param n - count of dimensions (facets have n vertices).
 * @param facets - flat facet indices, n per facet.
 * @param checkOrientation - false to check only that the boundary is closed.
 */
export function checkClosedBoundary(n: number, facets: Int32Array, names: BoundaryNames, checkOrientation = true): void {
  const facetCount = facets.length / n;
  const name = names.facet ?? ((f: number) => `'${names.facets}'[${f}]`);
  // value: 2*facet + (orientation bit) for a face seen once, -1 once it has its pair
  const seen = new Map<string, number>();
  const ridge = new Int32Array(n - 1);
  for (let f = 0; f < facetCount; f += 1) {
    for (let drop = 0; drop < n; drop += 1) {
      let w = 0;
      for (let a = 0; a < n; a += 1) if (a !== drop) ridge[w++] = facets[f * n + a];
      // boundary of (a_0..a_(n-1)) has sign (-1)^drop on the face without a_drop
      const sign = (drop & 1) ^ sortParity(ridge);
      const key = ridge.join(',');
      const prior = seen.get(key);
      if (prior === undefined) {
        seen.set(key, 2 * f + sign);
      } else if (prior === -1) {
        throw new RangeError(
          `${names.where}: '${names.facets}' is not the boundary of a solid: the (n-2)-face [${key}] belongs to more than 2 facets (the last is ${name(f)}); each must belong to exactly 2`,
        );
      } else {
        if (checkOrientation && (prior & 1) === sign) {
          throw new RangeError(
            `${names.where}: ${name(prior >> 1)} and ${name(f)} are oriented inconsistently: they run their shared (n-2)-face [${key}] the same way`,
          );
        }
        seen.set(key, -1);
      }
    }
  }
  for (const [key, value] of seen) {
    if (value !== -1) {
      throw new RangeError(
        `${names.where}: '${names.facets}' is not closed: the (n-2)-face [${key}] belongs only to ${name(value >> 1)}; each must belong to exactly 2 facets`,
      );
    }
  }
}
