/**
 * Hypercubes and how the rotors page turns them into something three.js can draw: vertices and
 * edges of the n-cube, the linear map of a rotation matrix, and the perspective projection of 4D
 * points to 3D along the w axis.
 *
 * Pure (no DOM, no three.js). The per-frame functions write into caller-owned arrays and
 * allocate nothing; they are unchecked (lengths are the caller's business) because the page
 * calls them on every frame with arrays it sized once from the counts below.
 */

/**
 * The 2^n vertices of the axis-aligned n-cube of half-extent `half` centred at the origin, as a
 * flat array (vertex v at `[v*n, v*n + n)`). Vertex v has coordinate i = +half when bit i of v is
 * set and −half otherwise, so two vertices share an edge exactly when their indices differ in
 * one bit.
 */
export function hypercubeVertices(n: number, half: number): Float64Array {
  if (!Number.isInteger(n) || n < 1 || n > 8)
    throw new RangeError(`hypercubeVertices: argument 'n' must be an integer in [1, 8], got ${n}`);
  if (!Number.isFinite(half) || half <= 0)
    throw new RangeError(`hypercubeVertices: argument 'half' must be a positive finite number, got ${half}`);
  const count = 1 << n;
  const out = new Float64Array(count * n);
  for (let v = 0; v < count; v += 1) {
    for (let i = 0; i < n; i += 1) out[v * n + i] = (v >> i) & 1 ? half : -half;
  }
  return out;
}

/**
 * The n·2^(n−1) edges of the n-cube as vertex index pairs (edge e joins `out[2e]` and
 * `out[2e + 1]`): 4 for a square, 12 for a cube, 32 for a tesseract. Ordered by the lower vertex,
 * then by the axis the edge runs along.
 */
export function hypercubeEdges(n: number): Uint16Array {
  if (!Number.isInteger(n) || n < 1 || n > 8)
    throw new RangeError(`hypercubeEdges: argument 'n' must be an integer in [1, 8], got ${n}`);
  const count = 1 << n;
  const out = new Uint16Array(n * (count >> 1) * 2);
  let e = 0;
  for (let v = 0; v < count; v += 1) {
    for (let i = 0; i < n; i += 1) {
      if ((v >> i) & 1) continue;
      out[e++] = v;
      out[e++] = v | (1 << i);
    }
  }
  return out;
}

/**
 * out = M p for `count` points of dimension n (flat arrays, `n` numbers per point), with M an n×n
 * row-major matrix (`M[i*n + c]` = component i of the image of e_c). Unchecked hot-path helper;
 * `out` must not alias `points`.
 */
export function transformPoints(
  n: number,
  out: Float64Array,
  M: Float64Array,
  points: Float64Array,
  count: number,
): Float64Array {
  for (let p = 0; p < count; p += 1) {
    const base = p * n;
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      const row = i * n;
      for (let c = 0; c < n; c += 1) s += M[row + c]! * points[base + c]!;
      out[base + i] = s;
    }
  }
  return out;
}

/**
 * The scale factor of the perspective projection along w: a pinhole eye on the w axis at
 * w = `distance` looks toward the origin and every point is projected onto the hyperplane w = 0,
 * so (x, y, z, w) lands at (x, y, z) · distance / (distance − w). Points nearer the eye (larger w)
 * come out larger, which is why the classic picture shows a small cube (w < 0) inside a big one
 * (w > 0). The depth distance − w is clamped to at least `minDepth` so a point that reaches the
 * eye stays finite instead of flying off to infinity.
 */
export function perspectiveScale(w: number, distance: number, minDepth: number): number {
  const depth = distance - w;
  return distance / (depth > minDepth ? depth : minDepth);
}

/**
 * Projects `count` 4D points (flat, 4 per point) to 3D by `perspectiveScale` (see there), writing
 * x, y, z into `out3` (3 per point) and the scale factor of each point into `outScale` (the page
 * sizes the vertex spheres by it). Unchecked hot-path helper.
 */
export function projectFromW(
  out3: Float32Array | Float64Array,
  outScale: Float32Array | Float64Array,
  points4: Float64Array,
  count: number,
  distance: number,
  minDepth: number,
): void {
  for (let p = 0; p < count; p += 1) {
    const s = perspectiveScale(points4[4 * p + 3]!, distance, minDepth);
    out3[3 * p] = s * points4[4 * p]!;
    out3[3 * p + 1] = s * points4[4 * p + 1]!;
    out3[3 * p + 2] = s * points4[4 * p + 2]!;
    outScale[p] = s;
  }
}

/**
 * Fills the vertex buffer of a line-segment mesh: segment e goes from point `edges[2e]` to point
 * `edges[2e + 1]` of `points3` (3 numbers per point), written as 6 numbers at `out[6e]`.
 * Unchecked hot-path helper; `out` holds 6 numbers per edge.
 */
export function writeSegments(out: Float32Array, points3: Float32Array | Float64Array, edges: Uint16Array): Float32Array {
  const m = edges.length >> 1;
  for (let e = 0; e < m; e += 1) {
    const a = 3 * edges[2 * e]!;
    const b = 3 * edges[2 * e + 1]!;
    const o = 6 * e;
    out[o] = points3[a]!;
    out[o + 1] = points3[a + 1]!;
    out[o + 2] = points3[a + 2]!;
    out[o + 3] = points3[b]!;
    out[o + 4] = points3[b + 1]!;
    out[o + 5] = points3[b + 2]!;
  }
  return out;
}
