/**
 * The slice of a solid n-torus by the 3-flat the viewer shows.
 *
 * Exact path (the specification's torus section): while the major plane's two axes lie in xyz, the
 * slice is a 3D torus with the same major circle and a tube of radius √(r² − d²), d the distance
 * from the centre to the flat; it is written as a fixed grid of quads. Otherwise (the major plane
 * uses a w axis, or the body turned out of xyz) the surface {f = 0} of the torus's distance
 * function restricted to the flat is traced by marching tetrahedra over a fixed grid, with normals
 * from f's gradient. Both write into buffers sized once; nothing is allocated per slice.
 *
 * @module
 */

/** Segments of the exact path round the major circle and round the tube. */
const MAJOR_SEGMENTS = 48;
const MINOR_SEGMENTS = 16;
/** cos and sin of the grid angles (index = segment, the last equal to the first), made by the first slicer. */
interface RingTables {
  readonly cosMajor: Float64Array;
  readonly sinMajor: Float64Array;
  readonly cosMinor: Float64Array;
  readonly sinMinor: Float64Array;
}
let ringTables: RingTables | null = null;
function tables(): RingTables {
  const angles = (count: number, f: (x: number) => number): Float64Array =>
    Float64Array.from({ length: count + 1 }, (_, i) => f((2 * Math.PI * i) / count));
  return (ringTables ??= {
    cosMajor: angles(MAJOR_SEGMENTS, Math.cos),
    sinMajor: angles(MAJOR_SEGMENTS, Math.sin),
    cosMinor: angles(MINOR_SEGMENTS, Math.cos),
    sinMinor: angles(MINOR_SEGMENTS, Math.sin),
  });
}
/** Cells per side of the marching grid. */
const GRID = 20;
/** Corner offsets of the unit cube, and its split into six tetrahedra along the main diagonal. */
const CORNER = [
  [0, 0, 0],
  [1, 0, 0],
  [0, 1, 0],
  [1, 1, 0],
  [0, 0, 1],
  [1, 0, 1],
  [0, 1, 1],
  [1, 1, 1],
] as const;
const TETS = [
  [0, 1, 3, 7],
  [0, 3, 2, 7],
  [0, 2, 6, 7],
  [0, 6, 4, 7],
  [0, 4, 5, 7],
  [0, 5, 1, 7],
] as const;

/** Where a torus sits: its shape numbers, and the body's position and rotation. */
export interface TorusPose {
  readonly majorRadius: number;
  readonly minorRadius: number;
  /** Body axes of the major plane. */
  readonly planeI: number;
  readonly planeJ: number;
  /** Centre, n numbers. */
  readonly x: ArrayLike<number>;
  /** Rotation, n × n row-major: column c is the world direction of body axis c. */
  readonly M: ArrayLike<number>;
}

/** A reusable slicer of n-tori. */
export class TorusSlicer {
  readonly n: number;
  /** Vertices one slice can write at most (positions and normals need 3 numbers each). */
  readonly maxVertices: number;
  private readonly values: Float64Array;
  private readonly local: Float64Array;
  private readonly grad: Float64Array;
  private readonly point: Float64Array;
  private readonly p: Float64Array;
  private readonly g: Float64Array;
  private readonly rings: RingTables = tables();
  /** A point of the flat (px, py, pz) and f there, for `field`. */
  private readonly q = new Float64Array(4);

  constructor(n: number) {
    this.n = n;
    const exact = MAJOR_SEGMENTS * MINOR_SEGMENTS * 6;
    // A tetrahedron gives at most two triangles; a closed surface crosses far fewer than all the
    // cells: a quarter of them is more than any torus slice reaches on this grid.
    const marching = (GRID * GRID * GRID * 6 * 2 * 3) / 4;
    this.maxVertices = Math.max(exact, marching);
    this.values = new Float64Array((GRID + 1) ** 3);
    this.local = new Float64Array(n);
    this.grad = new Float64Array(n);
    this.point = new Float64Array(3);
    this.p = new Float64Array(12);
    this.g = new Float64Array(12);
  }

  /** True when the exact path applies: both major axes have no component outside xyz. */
  isExact(pose: TorusPose): boolean {
    const n = this.n;
    for (let row = 3; row < n; row += 1) {
      if (Math.abs(pose.M[row * n + pose.planeI]!) > 1e-9 || Math.abs(pose.M[row * n + pose.planeJ]!) > 1e-9) return false;
    }
    return true;
  }

  /**
   * Writes the slice's triangles (positions relative to the first three coordinates of the centre,
   * flat-shaded normals pointing out) and returns the vertex count, 0 when the flat misses it.
   */
  slice(positions: Float32Array, normals: Float32Array, pose: TorusPose, slice: ArrayLike<number>): number {
    return this.isExact(pose)
      ? this.sliceExact(positions, normals, pose, slice)
      : this.sliceMarching(positions, normals, pose, slice);
  }

  /** The exact path: a 3D torus of tube radius √(r² − d²). */
  private sliceExact(positions: Float32Array, normals: Float32Array, pose: TorusPose, slice: ArrayLike<number>): number {
    const n = this.n;
    let d2 = 0;
    for (let a = 3; a < n; a += 1) {
      const d = slice[a - 3]! - pose.x[a]!;
      d2 += d * d;
    }
    const s = pose.minorRadius * pose.minorRadius - d2;
    if (s <= 0) return 0;
    const tube = Math.sqrt(s);
    const R = pose.majorRadius;
    const M = pose.M;
    // u, v: the major plane's axes in xyz; w = u × v its normal.
    const ux = M[pose.planeI]!,
      uy = M[n + pose.planeI]!,
      uz = M[2 * n + pose.planeI]!;
    const vx = M[pose.planeJ]!,
      vy = M[n + pose.planeJ]!,
      vz = M[2 * n + pose.planeJ]!;
    const wx = uy * vz - uz * vy,
      wy = uz * vx - ux * vz,
      wz = ux * vy - uy * vx;
    const frame = this.p;
    frame[0] = ux;
    frame[1] = uy;
    frame[2] = uz;
    frame[3] = vx;
    frame[4] = vy;
    frame[5] = vz;
    frame[6] = wx;
    frame[7] = wy;
    frame[8] = wz;
    // the radii travel in the scratch too: doubles passed as arguments would be boxed
    frame[9] = R;
    frame[10] = tube;
    let at = 0;
    for (let i = 0; i < MAJOR_SEGMENTS; i += 1) {
      for (let j = 0; j < MINOR_SEGMENTS; j += 1) {
        at = this.ring(positions, normals, at, i, j);
        at = this.ring(positions, normals, at, i + 1, j);
        at = this.ring(positions, normals, at, i + 1, j + 1);
        at = this.ring(positions, normals, at, i, j);
        at = this.ring(positions, normals, at, i + 1, j + 1);
        at = this.ring(positions, normals, at, i, j + 1);
      }
    }
    return (at / 3) | 0;
  }

  /** One vertex of the exact torus at grid (i, j); frame u, v, w in `p[0..8]`, R and tube in `p[9..10]`. */
  private ring(positions: Float32Array, normals: Float32Array, at: number, i: number, j: number): number {
    const f = this.p;
    const R = f[9]!;
    const tube = f[10]!;
    const t = this.rings;
    const ca = t.cosMajor[i]!,
      sa = t.sinMajor[i]!,
      cb = t.cosMinor[j]!,
      sb = t.sinMinor[j]!;
    const rx = ca * f[0]! + sa * f[3]!,
      ry = ca * f[1]! + sa * f[4]!,
      rz = ca * f[2]! + sa * f[5]!;
    // outward normal: cos b · radial + sin b · w
    const nx = cb * rx + sb * f[6]!,
      ny = cb * ry + sb * f[7]!,
      nz = cb * rz + sb * f[8]!;
    positions[at] = R * rx + tube * nx;
    positions[at + 1] = R * ry + tube * ny;
    positions[at + 2] = R * rz + tube * nz;
    normals[at] = nx;
    normals[at + 1] = ny;
    normals[at + 2] = nz;
    return at + 3;
  }

  /**
   * f at the flat's point (x0 + px, x1 + py, x2 + pz, slice…), (px, py, pz) read from `q[0..2]`:
   * the distance to the major circle minus r, √((ρ − R)² + Σ others) − r, in body coordinates. Writes f to
   * `q[3]` and ∂f/∂(px, py, pz) to `point` (through scratch, as a double argument or result of a
   * call that is not inlined is boxed).
   */
  private field(pose: TorusPose, slice: ArrayLike<number>): void {
    const n = this.n;
    const px = this.q[0]!;
    const py = this.q[1]!;
    const pz = this.q[2]!;
    const M = pose.M;
    const local = this.local;
    // body coordinates ξ = Mᵀ (X − x)
    for (let c = 0; c < n; c += 1) {
      let s = M[c]! * px + M[n + c]! * py + M[2 * n + c]! * pz;
      for (let row = 3; row < n; row += 1) s += M[row * n + c]! * (slice[row - 3]! - pose.x[row]!);
      local[c] = s;
    }
    const i = pose.planeI,
      j = pose.planeJ;
    const rho = Math.sqrt(local[i]! * local[i]! + local[j]! * local[j]!);
    const R = pose.majorRadius;
    let f = (rho - R) * (rho - R);
    const grad = this.grad;
    for (let c = 0; c < n; c += 1) {
      if (c === i || c === j) continue;
      f += local[c]! * local[c]!;
      grad[c] = 2 * local[c]!;
    }
    const k = rho > 1e-12 ? (2 * (rho - R)) / rho : 0;
    grad[i] = k * local[i]!;
    grad[j] = k * local[j]!;
    // back to world xyz: ∂f/∂X_row = Σ_c M[row, c] ∂f/∂ξ_c
    const point = this.point;
    for (let row = 0; row < 3; row += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += M[row * n + c]! * grad[c]!;
      point[row] = s;
    }
    // the distance minus r, not its square minus r²: linear near the surface, so the crossings the
    // grid interpolates fall on it rather than inside (a thin torus lost up to 10 % of its volume)
    this.q[3] = Math.sqrt(f) - pose.minorRadius;
  }

  /** Marching tetrahedra over a grid that holds the torus's bound. */
  private sliceMarching(positions: Float32Array, normals: Float32Array, pose: TorusPose, slice: ArrayLike<number>): number {
    let d2 = 0;
    for (let a = 3; a < this.n; a += 1) {
      const d = slice[a - 3]! - pose.x[a]!;
      d2 += d * d;
    }
    const bound = pose.majorRadius + pose.minorRadius;
    if (d2 >= bound * bound) return 0;
    const half = bound * 1.02;
    const h = (2 * half) / GRID;
    const values = this.values;
    const side = GRID + 1;
    let inside = false;
    for (let z = 0; z <= GRID; z += 1) {
      for (let y = 0; y <= GRID; y += 1) {
        for (let x = 0; x <= GRID; x += 1) {
          this.q[0] = -half + x * h;
          this.q[1] = -half + y * h;
          this.q[2] = -half + z * h;
          this.field(pose, slice);
          const f = this.q[3]!;
          values[(z * side + y) * side + x] = f;
          if (f < 0) inside = true;
        }
      }
    }
    if (!inside) return 0;
    const limit = Math.min(positions.length, normals.length) - 9;
    const p = this.p;
    let at = 0;
    for (let z = 0; z < GRID; z += 1) {
      for (let y = 0; y < GRID; y += 1) {
        for (let x = 0; x < GRID; x += 1) {
          for (let t = 0; t < TETS.length; t += 1) {
            const tet = TETS[t]!;
            // corners below (inside) and above the surface
            let below = 0;
            for (let q = 0; q < 4; q += 1) {
              const c = CORNER[tet[q]!]!;
              if (values[((z + c[2]) * side + y + c[1]) * side + x + c[0]]! < 0) below |= 1 << q;
            }
            if (below === 0 || below === 15) continue;
            // crossing points on the edges whose ends differ
            let count = 0;
            for (let a = 0; a < 4; a += 1) {
              for (let b = a + 1; b < 4; b += 1) {
                if (((below >> a) & 1) === ((below >> b) & 1)) continue;
                const ca = CORNER[tet[a]!]!,
                  cb = CORNER[tet[b]!]!;
                const fa = values[((z + ca[2]) * side + y + ca[1]) * side + x + ca[0]]!;
                const fb = values[((z + cb[2]) * side + y + cb[1]) * side + x + cb[0]]!;
                const t = fa / (fa - fb);
                p[3 * count] = -half + (x + ca[0] + t * (cb[0] - ca[0])) * h;
                p[3 * count + 1] = -half + (y + ca[1] + t * (cb[1] - ca[1])) * h;
                p[3 * count + 2] = -half + (z + ca[2] + t * (cb[2] - ca[2])) * h;
                count += 1;
              }
            }
            // three crossings: a triangle; four: a quad (its edges in cyclic order are 0-1-3-2)
            if (at > limit) return (at / 3) | 0;
            at = this.emit(positions, normals, at, pose, slice, 0, 1, 2);
            if (count === 4) {
              if (at > limit) return (at / 3) | 0;
              at = this.emit(positions, normals, at, pose, slice, 1, 3, 2);
            }
          }
        }
      }
    }
    return (at / 3) | 0;
  }

  /** Writes triangle (a, b, c) of the crossing points, wound so that its normal points out. */
  private emit(
    positions: Float32Array,
    normals: Float32Array,
    at: number,
    pose: TorusPose,
    slice: ArrayLike<number>,
    a: number,
    b: number,
    c: number,
  ): number {
    const p = this.p;
    const g = this.g;
    for (let m = 0; m < 3; m += 1) {
      const q = m === 0 ? a : m === 1 ? b : c;
      this.q[0] = p[3 * q]!;
      this.q[1] = p[3 * q + 1]!;
      this.q[2] = p[3 * q + 2]!;
      this.field(pose, slice);
      const len =
        Math.sqrt(this.point[0]! * this.point[0]! + this.point[1]! * this.point[1]! + this.point[2]! * this.point[2]!) || 1;
      g[3 * q] = this.point[0]! / len;
      g[3 * q + 1] = this.point[1]! / len;
      g[3 * q + 2] = this.point[2]! / len;
    }
    const e1x = p[3 * b]! - p[3 * a]!,
      e1y = p[3 * b + 1]! - p[3 * a + 1]!,
      e1z = p[3 * b + 2]! - p[3 * a + 2]!;
    const e2x = p[3 * c]! - p[3 * a]!,
      e2y = p[3 * c + 1]! - p[3 * a + 1]!,
      e2z = p[3 * c + 2]! - p[3 * a + 2]!;
    const cx = e1y * e2z - e1z * e2y,
      cy = e1z * e2x - e1x * e2z,
      cz = e1x * e2y - e1y * e2x;
    const out =
      cx * (g[3 * a]! + g[3 * b]! + g[3 * c]!) +
      cy * (g[3 * a + 1]! + g[3 * b + 1]! + g[3 * c + 1]!) +
      cz * (g[3 * a + 2]! + g[3 * b + 2]! + g[3 * c + 2]!);
    const order0 = a;
    const order1 = out >= 0 ? b : c;
    const order2 = out >= 0 ? c : b;
    for (let m = 0; m < 3; m += 1) {
      const q = m === 0 ? order0 : m === 1 ? order1 : order2;
      positions[at] = p[3 * q]!;
      positions[at + 1] = p[3 * q + 1]!;
      positions[at + 2] = p[3 * q + 2]!;
      normals[at] = g[3 * q]!;
      normals[at + 1] = g[3 * q + 1]!;
      normals[at + 2] = g[3 * q + 2]!;
      at += 3;
    }
    return at;
  }
}
