/**
 * Meshes built by the tests, independently of the library: the boundary of a box as
 * (n−1)-simplices, for the mesh mass properties and for convex-mesh bodies in the solver tests.
 */

/** A boundary mesh: vertices, and facets as tuples of n vertex indices. */
export interface TestMesh {
  vertices: number[][];
  facets: number[][];
}

/** Every ordering of `items`. */
function permutations(items: number[]): number[][] {
  if (items.length <= 1) return [items.slice()];
  const out: number[][] = [];
  items.forEach((x, i) => {
    for (const rest of permutations([...items.slice(0, i), ...items.slice(i + 1)])) out.push([x, ...rest]);
  });
  return out;
}

/**
 * The boundary of the box centre + Q·diag(a)·[−1, 1]ⁿ, each (n−1)-cube facet split into (n−1)!
 * simplices by the Kuhn (Freudenthal) triangulation: from the facet's lowest corner, raise the
 * other coordinates one at a time in every order. Corner index = bitmask of the raised axes.
 */
export function cubeBoundary(n: number, a: number[], centre?: number[], Q?: Float64Array): TestMesh {
  const vertices: number[][] = [];
  for (let mask = 0; mask < 1 << n; mask += 1) {
    const local = a.map((x, c) => (mask & (1 << c) ? x : -x));
    const v = new Array<number>(n).fill(0);
    for (let r = 0; r < n; r += 1) {
      v[r] = centre ? centre[r] : 0;
      for (let c = 0; c < n; c += 1) v[r] += (Q ? Q[r * n + c] : r === c ? 1 : 0) * local[c];
    }
    vertices.push(v);
  }
  const facets: number[][] = [];
  for (let d = 0; d < n; d += 1) {
    const others = [...Array(n).keys()].filter((c) => c !== d);
    for (const side of [0, 1]) {
      for (const order of permutations(others)) {
        let mask = side << d;
        const f = [mask];
        for (const c of order) {
          mask |= 1 << c;
          f.push(mask);
        }
        facets.push(f);
      }
    }
  }
  return { vertices, facets };
}
