/**
 * The slice of a hyperbox: the 3-flat {coordinates 3..n−1 = slice} meets the box in a convex
 * polyhedron, one face per facet of the box that the flat crosses.
 *
 * @module
 */
import { PolytopeCut } from './polytope-cut.js';

/** Scratch of one dimension's box slicer. */
export class BoxSlicer {
  readonly n: number;
  private readonly cut: PolytopeCut;

  constructor(n: number) {
    this.n = n;
    this.cut = new PolytopeCut({ faces: 2 * n + 7, vertices: 4 * n + 8 });
  }

  /** Most triangles one slice can hold. */
  get maxTriangles(): number {
    return (2 * this.n + 6) * (4 * this.n + 6);
  }

  /**
   * Cuts the box of half extents `he` at `x` with rotation `M` (n × n, row-major: column c is the
   * world direction of body axis c) by the flat whose coordinates 3..n−1 are `slice`. Writes
   * triangles (positions relative to (x0, x1, x2)) and flat normals; returns the vertex count, 0
   * when the flat misses the box.
   */
  slice(
    positions: Float32Array,
    normals: Float32Array,
    he: ArrayLike<number>,
    x: ArrayLike<number>,
    M: ArrayLike<number>,
    slice: ArrayLike<number>,
  ): number {
    const n = this.n;
    const cut = this.cut;
    let radius = 0;
    for (let i = 0; i < n; i += 1) radius += he[i]! * he[i]!;
    cut.plane[3] = Math.sqrt(radius) * 1.01 + 1e-6;
    cut.resetToCube();
    for (let i = 0; i < n; i += 1) {
      // body coordinate i of the point u (relative to x) of the flat: a·u + b
      const ax = M[0 * n + i]!;
      const ay = M[1 * n + i]!;
      const az = M[2 * n + i]!;
      let b = 0;
      for (let row = 3; row < n; row += 1) b += M[row * n + i]! * (slice[row - 3]! - x[row]!);
      const len = Math.sqrt(ax * ax + ay * ay + az * az);
      const h = he[i]!;
      if (len < 1e-12) {
        if (Math.abs(b) > h) return 0;
        continue;
      }
      const plane = cut.plane;
      plane[0] = ax / len;
      plane[1] = ay / len;
      plane[2] = az / len;
      plane[3] = (h - b) / len;
      if (!cut.clipByPlane()) return 0;
      plane[0] = -ax / len;
      plane[1] = -ay / len;
      plane[2] = -az / len;
      plane[3] = (h + b) / len;
      if (!cut.clipByPlane()) return 0;
    }
    return cut.writeTriangles(positions, normals);
  }
}
