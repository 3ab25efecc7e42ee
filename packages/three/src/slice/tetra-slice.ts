/**
 * The slice of a 4D body bounded by tetrahedra (a `HyperMesh`): each boundary tetrahedron the
 * hyperplane w = const crosses gives a triangle or a quad, its normal the tetrahedron's outward
 * normal projected to xyz.
 *
 * @module
 */

/** A reusable slicer of one tetrahedral boundary. */
export class TetraSlicer {
  /** Vertices one slice can write at most (two triangles a tetrahedron). */
  readonly maxVertices: number;
  private readonly vertices: Float64Array;
  private readonly cells: Uint32Array;
  /** Outward unit normal of each cell in body coordinates, 4 numbers each. */
  private readonly cellNormals: Float64Array;
  /** Per vertex: xyz offset from the centre and signed w distance to the slice. */
  private readonly world: Float64Array;
  private readonly p: Float64Array = new Float64Array(12);

  /**
   * @param vertices 4 numbers per vertex, body coordinates
   * @param cells 4 vertex indices per boundary tetrahedron
   */
  constructor(vertices: ArrayLike<number>, cells: ArrayLike<number>) {
    this.vertices = Float64Array.from(vertices);
    this.cells = Uint32Array.from(cells);
    const count = this.cells.length / 4;
    this.maxVertices = count * 6;
    this.world = new Float64Array((this.vertices.length / 4) * 4);
    this.cellNormals = new Float64Array(count * 4);
    const v = this.vertices;
    const centre = [0, 0, 0, 0];
    const nv = v.length / 4;
    for (let i = 0; i < nv; i += 1) for (let c = 0; c < 4; c += 1) centre[c]! += v[4 * i + c]! / nv;
    for (let t = 0; t < count; t += 1) {
      const a = 4 * this.cells[4 * t]!,
        b = 4 * this.cells[4 * t + 1]!,
        c = 4 * this.cells[4 * t + 2]!,
        d = 4 * this.cells[4 * t + 3]!;
      const e = [0, 1, 2].map((q) => {
        const o = [b, c, d][q]!;
        return [v[o]! - v[a]!, v[o + 1]! - v[a + 1]!, v[o + 2]! - v[a + 2]!, v[o + 3]! - v[a + 3]!];
      });
      // the 4D cross product of three edges: cofactors of the 4 × 4 determinant
      const N = [0, 1, 2, 3].map((col) => {
        const cols = [0, 1, 2, 3].filter((x) => x !== col);
        const m = e.map((row) => cols.map((x) => row[x]!));
        const det =
          m[0]![0]! * (m[1]![1]! * m[2]![2]! - m[1]![2]! * m[2]![1]!) -
          m[0]![1]! * (m[1]![0]! * m[2]![2]! - m[1]![2]! * m[2]![0]!) +
          m[0]![2]! * (m[1]![0]! * m[2]![1]! - m[1]![1]! * m[2]![0]!);
        return (col % 2 === 0 ? 1 : -1) * det;
      });
      let out = 0;
      for (let q = 0; q < 4; q += 1) out += N[q]! * (v[a + q]! - centre[q]!);
      const len = Math.hypot(...N) || 1;
      const sign = out >= 0 ? 1 : -1;
      for (let q = 0; q < 4; q += 1) this.cellNormals[4 * t + q] = (sign * N[q]!) / len;
    }
  }

  /**
   * Cuts by the hyperplane w = `slice[0]` the body at `x` with rotation `M` (4 × 4 row-major,
   * column c the world direction of body axis c). Writes triangles relative to (x0, x1, x2) and
   * returns the vertex count.
   */
  slice(
    positions: Float32Array,
    normals: Float32Array,
    x: ArrayLike<number>,
    M: ArrayLike<number>,
    slice: ArrayLike<number>,
  ): number {
    const v = this.vertices;
    const w = this.world;
    const nv = v.length / 4;
    const s = slice[0]! - x[3]!;
    let below = false;
    let above = false;
    for (let i = 0; i < nv; i += 1) {
      for (let row = 0; row < 4; row += 1) {
        let sum = 0;
        for (let c = 0; c < 4; c += 1) sum += M[row * 4 + c]! * v[4 * i + c]!;
        w[4 * i + row] = row === 3 ? sum - s : sum;
      }
      if (w[4 * i + 3]! < 0) below = true;
      else above = true;
    }
    if (!below || !above) return 0;
    const cells = this.cells;
    const p = this.p;
    const limit = Math.min(positions.length, normals.length);
    let at = 0;
    for (let t = 0; t < cells.length / 4; t += 1) {
      let mask = 0;
      for (let q = 0; q < 4; q += 1) if (w[4 * cells[4 * t + q]! + 3]! < 0) mask |= 1 << q;
      if (mask === 0 || mask === 15) continue;
      let count = 0;
      for (let a = 0; a < 4; a += 1) {
        for (let b = a + 1; b < 4; b += 1) {
          if (((mask >> a) & 1) === ((mask >> b) & 1)) continue;
          const ia = 4 * cells[4 * t + a]!,
            ib = 4 * cells[4 * t + b]!;
          const k = w[ia + 3]! / (w[ia + 3]! - w[ib + 3]!);
          for (let c = 0; c < 3; c += 1) p[3 * count + c] = w[ia + c]! + k * (w[ib + c]! - w[ia + c]!);
          count += 1;
        }
      }
      // the cell's normal in the world, projected to xyz
      let nx = 0,
        ny = 0,
        nz = 0;
      for (let c = 0; c < 4; c += 1) {
        const b = this.cellNormals[4 * t + c]!;
        nx += M[c]! * b;
        ny += M[4 + c]! * b;
        nz += M[8 + c]! * b;
      }
      const len = Math.sqrt(nx * nx + ny * ny + nz * nz);
      if (len < 1e-12) continue;
      nx /= len;
      ny /= len;
      nz /= len;
      if (at + 9 * (count - 2) > limit) break;
      at = this.triangle(positions, normals, at, 0, 1, 2, nx, ny, nz);
      // a quad's crossings in cyclic order are 0-1-3-2
      if (count === 4) at = this.triangle(positions, normals, at, 1, 3, 2, nx, ny, nz);
    }
    return (at / 3) | 0;
  }

  private triangle(
    positions: Float32Array,
    normals: Float32Array,
    at: number,
    a: number,
    b: number,
    c: number,
    nx: number,
    ny: number,
    nz: number,
  ): number {
    const p = this.p;
    const e1x = p[3 * b]! - p[3 * a]!,
      e1y = p[3 * b + 1]! - p[3 * a + 1]!,
      e1z = p[3 * b + 2]! - p[3 * a + 2]!;
    const e2x = p[3 * c]! - p[3 * a]!,
      e2y = p[3 * c + 1]! - p[3 * a + 1]!,
      e2z = p[3 * c + 2]! - p[3 * a + 2]!;
    const turn = (e1y * e2z - e1z * e2y) * nx + (e1z * e2x - e1x * e2z) * ny + (e1x * e2y - e1y * e2x) * nz;
    const second = turn >= 0 ? b : c;
    const third = turn >= 0 ? c : b;
    for (let m = 0; m < 3; m += 1) {
      const q = m === 0 ? a : m === 1 ? second : third;
      positions[at] = p[3 * q]!;
      positions[at + 1] = p[3 * q + 1]!;
      positions[at + 2] = p[3 * q + 2]!;
      normals[at] = nx;
      normals[at + 1] = ny;
      normals[at + 2] = nz;
      at += 3;
    }
    return at;
  }
}
