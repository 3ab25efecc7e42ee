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
    const axis = this.axis;
    // body coordinate i of the point u (relative to x) of the flat is a_i·u + b_i, |…| ≤ h_i
    for (let i = 0; i < n; i += 1) {
      const ax = M[i]!;
      const ay = M[n + i]!;
      const az = M[2 * n + i]!;
      let b = 0;
      for (let row = 3; row < n; row += 1) b += M[row * n + i]! * (slice[row - 3]! - x[row]!);
      const len = Math.sqrt(ax * ax + ay * ay + az * az);
      // an axis the flat is parallel to: the flat is wholly in or out of its slab
      if (len < 1e-12 && Math.abs(b) > he[i]!) return 0;
      axis[5 * i] = ax;
      axis[5 * i + 1] = ay;
      axis[5 * i + 2] = az;
      axis[5 * i + 3] = b;
      axis[5 * i + 4] = len;
    }
    // start from the parallelepiped of the three most independent slabs, then clip by the rest
    const first = this.bestTriple(he);
    if (first >= 0 && cut.resetToSlabs(this.slabs)) {
      for (let i = 0; i < n; i += 1) {
        if (i === (first & 15) || i === ((first >> 4) & 15) || i === first >> 8) continue;
        if (!this.clipSlab(i, he[i]!)) return 0;
      }
    } else {
      let radius = 0;
      for (let i = 0; i < n; i += 1) radius += he[i]! * he[i]!;
      cut.plane[3] = Math.sqrt(radius) * 1.01 + 1e-6;
      cut.resetToCube();
      for (let i = 0; i < n; i += 1) if (!this.clipSlab(i, he[i]!)) return 0;
    }
    return cut.writeTriangles(positions, normals);
  }

  /** Scratch per body axis: a (3), b, |a|. */
  private readonly axis: Float64Array = new Float64Array(5 * 8);
  /** The chosen three slabs for `PolytopeCut.resetToSlabs`. */
  private readonly slabs: Float64Array = new Float64Array(15);

  /**
   * The three axes whose xyz parts are the most independent (largest |det| over the product of
   * lengths), packed as i | j << 4 | k << 8, with their slabs written to `slabs`; −1 if none.
   */
  private bestTriple(he: ArrayLike<number>): number {
    const n = this.n;
    const a = this.axis;
    let best = -1;
    let bestScore = 1e-6;
    for (let i = 0; i < n; i += 1) {
      for (let j = i + 1; j < n; j += 1) {
        for (let k = j + 1; k < n; k += 1) {
          const li = a[5 * i + 4]!;
          const lj = a[5 * j + 4]!;
          const lk = a[5 * k + 4]!;
          if (li < 1e-12 || lj < 1e-12 || lk < 1e-12) continue;
          const det =
            a[5 * i]! * (a[5 * j + 1]! * a[5 * k + 2]! - a[5 * j + 2]! * a[5 * k + 1]!) -
            a[5 * i + 1]! * (a[5 * j]! * a[5 * k + 2]! - a[5 * j + 2]! * a[5 * k]!) +
            a[5 * i + 2]! * (a[5 * j]! * a[5 * k + 1]! - a[5 * j + 1]! * a[5 * k]!);
          const score = Math.abs(det) / (li * lj * lk);
          if (score > bestScore) {
            bestScore = score;
            best = i | (j << 4) | (k << 8);
          }
        }
      }
    }
    if (best < 0) return -1;
    const slabs = this.slabs;
    for (let q = 0; q < 3; q += 1) {
      const i = q === 0 ? best & 15 : q === 1 ? (best >> 4) & 15 : best >> 8;
      slabs[3 * q] = a[5 * i]!;
      slabs[3 * q + 1] = a[5 * i + 1]!;
      slabs[3 * q + 2] = a[5 * i + 2]!;
      slabs[9 + 2 * q] = -he[i]! - a[5 * i + 3]!;
      slabs[10 + 2 * q] = he[i]! - a[5 * i + 3]!;
    }
    return best;
  }

  /** Clips by both planes of axis i's slab; false when nothing is left. */
  private clipSlab(i: number, h: number): boolean {
    const a = this.axis;
    const len = a[5 * i + 4]!;
    if (len < 1e-12) return true;
    const b = a[5 * i + 3]!;
    const plane = this.cut.plane;
    plane[0] = a[5 * i]! / len;
    plane[1] = a[5 * i + 1]! / len;
    plane[2] = a[5 * i + 2]! / len;
    plane[3] = (h - b) / len;
    if (!this.cut.clipByPlane()) return false;
    plane[0] = -plane[0]!;
    plane[1] = -plane[1]!;
    plane[2] = -plane[2]!;
    plane[3] = (h + b) / len;
    return this.cut.clipByPlane();
  }
}
