/**
 * The cut of an n-dimensional box by the 3-flat where the coordinates 3..n−1 take fixed values:
 * a convex polyhedron in xyz, built by clipping with the 2n facet half-spaces of the box (each face
 * of the cut is the cut of one facet, its normal that facet's normal projected to xyz). Fixed
 * capacity, no allocation after construction.
 *
 * @module
 */

/** Numbers of room: faces, and vertices per face. */
export interface CutCapacity {
  readonly faces: number;
  readonly vertices: number;
}

/** (u, v) corners of a cube face, counter-clockwise seen from outside, for a + and a − face. */
const CORNERS_OUT = [-1, -1, 1, -1, 1, 1, -1, 1] as const;
const CORNERS_IN = [-1, -1, -1, 1, 1, 1, 1, -1] as const;

/** A reusable clipper of convex polyhedra in 3D. */
export class PolytopeCut {
  /** Face polygons: 3 numbers per vertex, `vertices` vertices of room per face. */
  private readonly poly: Float64Array[];
  private readonly count: Int32Array;
  /** Outward unit normal of each face. */
  private readonly normal: Float64Array;
  private faces = 0;
  private readonly maxFaces: number;
  private readonly maxVerts: number;
  private readonly temp: Float64Array;
  private readonly cap: Float64Array;
  private readonly angle: Float64Array;
  private readonly order: Int32Array;
  /** The inverse's columns (9) and the 8 corners (24) of `resetToSlabs`. */
  private readonly corners = new Float64Array(33);
  /** Signed distances of one face's vertices to the clipping plane. */
  private readonly dist: Float64Array;
  /** The plane of the next `clipByPlane`: outward unit normal (3) and offset d. */
  readonly plane = new Float64Array(4);

  constructor(capacity: CutCapacity) {
    this.maxFaces = capacity.faces;
    this.maxVerts = capacity.vertices;
    this.poly = [];
    for (let f = 0; f < capacity.faces; f += 1) this.poly.push(new Float64Array(3 * capacity.vertices));
    this.count = new Int32Array(capacity.faces);
    this.normal = new Float64Array(3 * capacity.faces);
    this.temp = new Float64Array(3 * capacity.vertices);
    this.dist = new Float64Array(capacity.vertices);
    this.cap = new Float64Array(6 * capacity.faces);
    this.angle = new Float64Array(2 * capacity.faces);
    this.order = new Int32Array(2 * capacity.faces);
  }

  /** Starts from the cube [−s, s]³. */
  reset(s: number): void {
    this.plane[3] = s;
    this.resetToCube();
  }

  /** `reset` with s read from `plane[3]` (no boxed argument on the hot path). */
  resetToCube(): void {
    const s = this.plane[3]!;
    this.faces = 0;
    for (let f = 0; f < 6; f += 1) {
      const axis = f >> 1;
      const sign = (f & 1) === 0 ? 1 : -1;
      this.normal[3 * f] = axis === 0 ? sign : 0;
      this.normal[3 * f + 1] = axis === 1 ? sign : 0;
      this.normal[3 * f + 2] = axis === 2 ? sign : 0;
      // four corners, counter-clockwise seen from outside
      const u = (axis + 1) % 3;
      const v = (axis + 2) % 3;
      const p = this.poly[f]!;
      const corners = sign > 0 ? CORNERS_OUT : CORNERS_IN;
      for (let c = 0; c < 4; c += 1) {
        p[3 * c + axis] = sign * s;
        p[3 * c + u] = corners[2 * c]! * s;
        p[3 * c + v] = corners[2 * c + 1]! * s;
      }
      this.count[f] = 4;
    }
    this.faces = 6;
  }

  /**
   * Starts from the parallelepiped {lo_i ≤ a_i·p ≤ hi_i, i = 0, 1, 2} of three independent
   * normals a_i (`slabs`: a0 a1 a2 as 9 numbers, then lo0 hi0 lo1 hi1 lo2 hi2): its 8 corners
   * are solved for directly, so three pairs of clips are saved. Returns false (nothing changed)
   * when the normals are too close to dependent.
   */
  resetToSlabs(slabs: Float64Array): boolean {
    const a = slabs;
    // A⁻¹ by cofactors: u_j, the columns, satisfy a_i·u_j = δ_ij
    const c00 = a[4]! * a[8]! - a[5]! * a[7]!;
    const c01 = a[5]! * a[6]! - a[3]! * a[8]!;
    const c02 = a[3]! * a[7]! - a[4]! * a[6]!;
    const det = a[0]! * c00 + a[1]! * c01 + a[2]! * c02;
    const l0 = a[0]! * a[0]! + a[1]! * a[1]! + a[2]! * a[2]!;
    const l1 = a[3]! * a[3]! + a[4]! * a[4]! + a[5]! * a[5]!;
    const l2 = a[6]! * a[6]! + a[7]! * a[7]! + a[8]! * a[8]!;
    if (!(Math.abs(det) > 1e-6 * Math.sqrt(l0 * l1 * l2))) return false;
    const u = this.corners;
    // u_0 = (a1 × a2)/det, u_1 = (a2 × a0)/det, u_2 = (a0 × a1)/det
    u[0] = c00 / det;
    u[1] = c01 / det;
    u[2] = c02 / det;
    u[3] = (a[7]! * a[2]! - a[8]! * a[1]!) / det;
    u[4] = (a[8]! * a[0]! - a[6]! * a[2]!) / det;
    u[5] = (a[6]! * a[1]! - a[7]! * a[0]!) / det;
    u[6] = (a[1]! * a[5]! - a[2]! * a[4]!) / det;
    u[7] = (a[2]! * a[3]! - a[0]! * a[5]!) / det;
    u[8] = (a[0]! * a[4]! - a[1]! * a[3]!) / det;
    // corner k (bits: which bound of each slab) at Σ_j bound_j u_j
    for (let k = 0; k < 8; k += 1) {
      const b0 = (k & 1) === 0 ? a[9]! : a[10]!;
      const b1 = (k & 2) === 0 ? a[11]! : a[12]!;
      const b2 = (k & 4) === 0 ? a[13]! : a[14]!;
      for (let q = 0; q < 3; q += 1) u[9 + 3 * k + q] = b0 * u[q]! + b1 * u[3 + q]! + b2 * u[6 + q]!;
    }
    const flip = det < 0;
    this.faces = 6;
    for (let f = 0; f < 6; f += 1) {
      const i = f >> 1;
      const upper = (f & 1) === 0;
      const sign = upper ? 1 : -1;
      const len = Math.sqrt(i === 0 ? l0 : i === 1 ? l1 : l2);
      this.normal[3 * f] = (sign * a[3 * i]!) / len;
      this.normal[3 * f + 1] = (sign * a[3 * i + 1]!) / len;
      this.normal[3 * f + 2] = (sign * a[3 * i + 2]!) / len;
      // the face's corners in the order of the two other slabs' bounds, (−,−) (+,−) (+,+) (−,+):
      // counter-clockwise about +a_i when det > 0; the order turns with the sign and the bound
      const j = (i + 1) % 3;
      const m = (i + 2) % 3;
      const reverse = flip !== !upper;
      const p = this.poly[f]!;
      for (let c = 0; c < 4; c += 1) {
        const corner = reverse ? 3 - c : c;
        const sj = corner === 1 || corner === 2 ? 1 : 0;
        const sm = corner >= 2 ? 1 : 0;
        const k = ((upper ? 1 : 0) << i) | (sj << j) | (sm << m);
        p[3 * c] = u[9 + 3 * k]!;
        p[3 * c + 1] = u[9 + 3 * k + 1]!;
        p[3 * c + 2] = u[9 + 3 * k + 2]!;
      }
      this.count[f] = 4;
    }
    return true;
  }

  /** Face count after the last clip. */
  get faceCount(): number {
    return this.faces;
  }

  /**
   * Keeps the part where n·u ≤ d (n a unit vector, the outward normal of the new face). Returns
   * false when nothing is left.
   */
  clip(nx: number, ny: number, nz: number, d: number): boolean {
    const plane = this.plane;
    plane[0] = nx;
    plane[1] = ny;
    plane[2] = nz;
    plane[3] = d;
    return this.clipByPlane();
  }

  /**
   * `clip` by the plane in `plane` (nx, ny, nz, d). Hot callers write the plane there and call
   * this: a double passed to a function that is not inlined is boxed, one allocation per number.
   */
  clipByPlane(): boolean {
    const nx = this.plane[0]!;
    const ny = this.plane[1]!;
    const nz = this.plane[2]!;
    const d = this.plane[3]!;
    let capCount = 0;
    let out = 0;
    const dist = this.dist;
    for (let f = 0; f < this.faces; f += 1) {
      const p = this.poly[f]!;
      const c = this.count[f]!;
      // each vertex's signed distance once; a face wholly on one side needs no clipping
      let lo = Infinity;
      let hi = -Infinity;
      for (let i = 0; i < c; i += 1) {
        const di = nx * p[3 * i]! + ny * p[3 * i + 1]! + nz * p[3 * i + 2]! - d;
        dist[i] = di;
        if (di < lo) lo = di;
        if (di > hi) hi = di;
      }
      if (lo > 0) continue;
      if (hi < 0) {
        this.keepFace(f, out, -1);
        out += 1;
        continue;
      }
      const t = this.temp;
      let m = 0;
      for (let i = 0; i < c; i += 1) {
        const j = i + 1 === c ? 0 : i + 1;
        const ax = p[3 * i]!;
        const ay = p[3 * i + 1]!;
        const az = p[3 * i + 2]!;
        const da = dist[i]!;
        const db = dist[j]!;
        if (da <= 0) {
          t[3 * m] = ax;
          t[3 * m + 1] = ay;
          t[3 * m + 2] = az;
          m += 1;
        }
        if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
          const s = da / (da - db);
          const x = ax + s * (p[3 * j]! - ax);
          const y = ay + s * (p[3 * j + 1]! - ay);
          const z = az + s * (p[3 * j + 2]! - az);
          t[3 * m] = x;
          t[3 * m + 1] = y;
          t[3 * m + 2] = z;
          m += 1;
          if (capCount < this.cap.length / 3) {
            this.cap[3 * capCount] = x;
            this.cap[3 * capCount + 1] = y;
            this.cap[3 * capCount + 2] = z;
            capCount += 1;
          }
        } else if (da === 0 && capCount < this.cap.length / 3) {
          this.cap[3 * capCount] = ax;
          this.cap[3 * capCount + 1] = ay;
          this.cap[3 * capCount + 2] = az;
          capCount += 1;
        }
      }
      if (m >= 3) {
        this.keepFace(f, out, Math.min(m, this.maxVerts));
        out += 1;
      }
    }
    this.faces = out;
    if (out === 0) return false;
    if (capCount >= 3 && this.faces < this.maxFaces) this.addCap(capCount);
    return true;
  }

  /**
   * Moves face f to slot `out` (faces are kept compacted); with `kept` ≥ 0 its vertices become the
   * first `kept` of `temp` (the clipped polygon), with −1 they stay as they are.
   */
  private keepFace(f: number, out: number, kept: number): void {
    const p = this.poly[f]!;
    if (out !== f) {
      this.poly[f] = this.poly[out]!;
      this.poly[out] = p;
      this.count[out] = this.count[f]!;
      this.normal[3 * out] = this.normal[3 * f]!;
      this.normal[3 * out + 1] = this.normal[3 * f + 1]!;
      this.normal[3 * out + 2] = this.normal[3 * f + 2]!;
    }
    if (kept >= 0) {
      const t = this.temp;
      for (let i = 0; i < 3 * kept; i += 1) p[i] = t[i]!;
      this.count[out] = kept;
    }
  }

  /** Adds the new face: the cut points, without repeats, in counter-clockwise order about n. */
  private addCap(capCount: number): void {
    const nx = this.plane[0]!;
    const ny = this.plane[1]!;
    const nz = this.plane[2]!;
    const c = this.cap;
    let cx = 0;
    let cy = 0;
    let cz = 0;
    for (let i = 0; i < capCount; i += 1) {
      cx += c[3 * i]!;
      cy += c[3 * i + 1]!;
      cz += c[3 * i + 2]!;
    }
    cx /= capCount;
    cy /= capCount;
    cz /= capCount;
    // a basis (e1, e2) of the plane with e1 × e2 = n
    let ex = Math.abs(nx) < 0.9 ? 1 : 0;
    let ey = ex === 1 ? 0 : 1;
    let ez = 0;
    const dot = ex * nx + ey * ny + ez * nz;
    ex -= dot * nx;
    ey -= dot * ny;
    ez -= dot * nz;
    const len = Math.sqrt(ex * ex + ey * ey + ez * ez);
    ex /= len;
    ey /= len;
    ez /= len;
    const fx = ny * ez - nz * ey;
    const fy = nz * ex - nx * ez;
    const fz = nx * ey - ny * ex;
    let unique = 0;
    for (let i = 0; i < capCount; i += 1) {
      const x = c[3 * i]!;
      const y = c[3 * i + 1]!;
      const z = c[3 * i + 2]!;
      let seen = false;
      for (let k = 0; k < unique && !seen; k += 1) {
        const o = this.order[k]!;
        seen = Math.abs(c[3 * o]! - x) + Math.abs(c[3 * o + 1]! - y) + Math.abs(c[3 * o + 2]! - z) < 1e-9;
      }
      if (seen) continue;
      this.order[unique] = i;
      this.angle[unique] = pseudoAngle(
        (x - cx) * ex + (y - cy) * ey + (z - cz) * ez,
        (x - cx) * fx + (y - cy) * fy + (z - cz) * fz,
      );
      unique += 1;
    }
    if (unique < 3) return;
    // insertion sort by angle (a handful of points)
    for (let i = 1; i < unique; i += 1) {
      const a = this.angle[i]!;
      const o = this.order[i]!;
      let j = i - 1;
      while (j >= 0 && this.angle[j]! > a) {
        this.angle[j + 1] = this.angle[j]!;
        this.order[j + 1] = this.order[j]!;
        j -= 1;
      }
      this.angle[j + 1] = a;
      this.order[j + 1] = o;
    }
    const f = this.faces++;
    const p = this.poly[f]!;
    const m = Math.min(unique, this.maxVerts);
    for (let k = 0; k < m; k += 1) {
      const o = this.order[k]!;
      p[3 * k] = c[3 * o]!;
      p[3 * k + 1] = c[3 * o + 1]!;
      p[3 * k + 2] = c[3 * o + 2]!;
    }
    this.count[f] = m;
    this.normal[3 * f] = nx;
    this.normal[3 * f + 1] = ny;
    this.normal[3 * f + 2] = nz;
  }

  /**
   * Writes the faces as triangles (a fan per face, flat normals) into `positions` and `normals`
   * (3 numbers per vertex) and returns the vertex count written.
   */
  writeTriangles(positions: Float32Array, normals: Float32Array): number {
    let v = 0;
    const room = positions.length / 3;
    for (let f = 0; f < this.faces; f += 1) {
      const p = this.poly[f]!;
      const c = this.count[f]!;
      const nx = this.normal[3 * f]!;
      const ny = this.normal[3 * f + 1]!;
      const nz = this.normal[3 * f + 2]!;
      for (let i = 1; i + 1 < c && v + 3 <= room; i += 1) {
        for (let corner = 0; corner < 3; corner += 1) {
          const k = corner === 0 ? 0 : corner === 1 ? i : i + 1;
          positions[3 * v] = p[3 * k]!;
          positions[3 * v + 1] = p[3 * k + 1]!;
          positions[3 * v + 2] = p[3 * k + 2]!;
          normals[3 * v] = nx;
          normals[3 * v + 1] = ny;
          normals[3 * v + 2] = nz;
          v += 1;
        }
      }
    }
    return v;
  }

  /** The vertices of face f (for tests): 3 numbers each. */
  faceVertices(f: number): Float64Array {
    return this.poly[f]!.subarray(0, 3 * this.count[f]!);
  }

  /** The outward normal of face f (for tests). */
  faceNormal(f: number): Float64Array {
    return this.normal.subarray(3 * f, 3 * f + 3);
  }
}

/**
 * A number in [0, 4) that grows with the angle of (u, v) as atan2 does: the position on the unit
 * diamond |u| + |v| = 1, which orders points round a centre as well and costs no transcendental.
 */
function pseudoAngle(u: number, v: number): number {
  const s = Math.abs(u) + Math.abs(v);
  if (s === 0) return 0;
  const t = u / s;
  return v >= 0 ? 1 - t : 3 + t;
}
