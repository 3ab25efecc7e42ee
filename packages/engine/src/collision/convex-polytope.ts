/**
 * Two convex polytopes (convex meshes and boxes) in one frame, and their signed distance by GJK
 * (separated) and EPA (overlapping), in n dimensions.
 *
 * Both polytopes are loaded into the scratch in A's local frame (vertices, unit facet normals,
 * facet offsets: the solid is {x : N_f·x <= o_f}); a box is written out as its 2ⁿ corners
 * (vertex index = corner bitmask, bit c set: +a_c) and its 2n faces (facet 2c: −e_c, 2c + 1:
 * +e_c). D = A − B is the Minkowski difference; its support along d is s_A(d) − s_B(−d).
 *
 * - **GJK** (Gilbert–Johnson–Keerthi): the closest point v of D to the origin, by a simplex of
 *   support points of up to n + 1 vertices whose nearest point (simplex-closest.ts) moves toward
 *   the origin. For polytopes it ends exactly when the new support point adds nothing
 *   (|v|² − v·w <= 1e-13 |v|²). Separated: separation |v|, normal −v/|v| (A to B). It stops early
 *   when the lower bound v·w/|v| of the distance exceeds the margin.
 * - **EPA** (expanding polytope): when GJK's simplex holds the origin, the simplex is completed to
 *   n + 1 affinely independent support points and grown: the facet nearest the origin is pushed
 *   out to the support point along its normal, the facets that see the new point are removed and
 *   the horizon ridges (those bounding exactly one removed facet) are joined to it. It stops when
 *   the support point along the nearest facet's normal lies on its plane (within 1e-12 × size):
 *   depth = that facet's distance, normal its outward normal (A to B). Facet orientation is fixed
 *   by an interior point (the first simplex's centroid), so a touching pair (origin on the
 *   boundary) is handled alike.
 *
 * Unchecked kernels; they allocate nothing once the polytope scratch has grown to the largest
 * meshes seen (the scratch is made on first use and grows by doubling).
 *
 * @module
 */
import type { Pose } from './manifold.js';
import type { CollisionBox, CollisionMesh } from './narrowphase-shapes.js';
import type { NarrowphaseScratch } from './narrowphase-scratch.js';
import { closestPointOnSimplexKernel } from './simplex-closest.js';

/** Most GJK iterations (a polytope pair ends far sooner; this only guards against cycling). */
const GJK_MAX_ITERATIONS = 128;
/** Relative GJK convergence: stop when |v|² − v·w <= this × |v|². */
const GJK_RELATIVE_TOLERANCE = 1e-13;
/** Most EPA points (support points) and iterations. */
const EPA_MAX_POINTS = 192;
/** EPA: a support point within this × size of the nearest facet's plane ends the expansion. */
const EPA_RELATIVE_TOLERANCE = 1e-12;

/** Index in ps.scalars of the margin read by {@link polytopeSeparationKernel}. */
export const PS_MARGIN = 0;
/** Index in ps.scalars of a face axis separation (mesh-polytope.ts). */
export const PS_FACE = 1;
/** Index in ps.scalars of the merge distance of clip points (mesh-polytope.ts). */
export const PS_MERGE = 2;

/** Indices in ps.scalars of EPA's length tolerances: affine independence, facets, fixed ones. */
const PS_TOL_LENGTH = 3;
const PS_TOL_FACET = 4;
const PS_TOL_AXIS = 5;
const PS_TOL_NORMAL = 6;
const PS_ZERO = 7;

/** What {@link polytopeSeparationKernel} found. */
export const POLY_SEPARATED = 0;
/** The polytopes overlap or touch (EPA ran). */
export const POLY_OVERLAP = 1;
/** Farther apart than the margin: nothing else is valid. */
export const POLY_BEYOND = 2;

/** Working memory of the polytope pair kernels, in A's local frame. Grows with the meshes. */
export interface PolytopeScratch {
  readonly n: number;
  /** Vertices (n each), unit facet normals (n each), facet offsets of A and B, in A's frame. */
  aV: Float64Array;
  aN: Float64Array;
  aO: Float64Array;
  bV: Float64Array;
  bN: Float64Array;
  bO: Float64Array;
  aVC: number;
  aFC: number;
  bVC: number;
  bFC: number;
  /** Largest vertex distance from its own shape's origin, over both shapes (m): the length scale. */
  size: number;
  /** B's rotation in A's frame (n×n, row-major) and B's origin in A's frame. */
  readonly R: Float64Array;
  readonly t: Float64Array;
  /** Result: POLY_SEPARATED, POLY_OVERLAP or POLY_BEYOND. */
  status: number;
  /** Result: signed separation (m; negative = depth) and unit normal from A to B (A's frame). */
  separation: number;
  readonly normal: Float64Array;
  /** Result: witness points of A and B (A's frame) and the vertex indices supporting them. */
  readonly witnessA: Float64Array;
  readonly witnessB: Float64Array;
  readonly supportA: Int32Array;
  readonly supportB: Int32Array;
  supportCount: number;
  // GJK simplex
  readonly simplex: Float64Array;
  readonly simplexA: Int32Array;
  readonly simplexB: Int32Array;
  simplexCount: number;
  readonly v: Float64Array;
  readonly w: Float64Array;
  readonly d: Float64Array;
  readonly zero: Float64Array;
  readonly basis: Float64Array;
  readonly facetVerts: Float64Array;
  // EPA
  readonly pts: Float64Array;
  readonly ptA: Int32Array;
  readonly ptB: Int32Array;
  facets: Int32Array;
  fN: Float64Array;
  fO: Float64Array;
  fDead: Uint8Array;
  facetCapacity: number;
  readonly centre: Float64Array;
  ridges: Int32Array;
  ridgeCount: Int32Array;
  /** Open-addressing table of the ridges of one EPA iteration: ridge index, and the iteration that wrote the slot. */
  ridgeTable: Int32Array;
  ridgeStamp: Int32Array;
  epoch: number;
  // face clipping (mesh-polytope.ts)
  cN: Float64Array;
  cO: Float64Array;
  cId: Int32Array;
  readonly comb: Int32Array;
  /** Face clipping by half-spaces: the region's vertices (n each), their tight-constraint masks, heights; two buffers. */
  clipV: Float64Array;
  clipMask: Int32Array;
  clipV2: Float64Array;
  clipMask2: Int32Array;
  clipS: Float64Array;
  /** Numbers passed between the kernels (a double argument or return value of a call V8 does not inline is boxed). */
  readonly scalars: Float64Array;
}

function grow(a: Float64Array, size: number): Float64Array {
  return a.length >= size ? a : new Float64Array(Math.max(size, 2 * a.length));
}

/** A fresh polytope scratch for n dimensions (allocates; made once per narrowphase scratch). */
export function createPolytopeScratch(n: number): PolytopeScratch {
  const m = n + 1;
  const vCap = Math.max(2 ** n, 32);
  const fCap = Math.max(2 * n, 32);
  const facetCapacity = 256;
  return {
    n,
    aV: new Float64Array(vCap * n),
    aN: new Float64Array(fCap * n),
    aO: new Float64Array(fCap),
    bV: new Float64Array(vCap * n),
    bN: new Float64Array(fCap * n),
    bO: new Float64Array(fCap),
    aVC: 0,
    aFC: 0,
    bVC: 0,
    bFC: 0,
    size: 1,
    R: new Float64Array(n * n),
    t: new Float64Array(n),
    status: POLY_BEYOND,
    separation: Infinity,
    normal: new Float64Array(n),
    witnessA: new Float64Array(n),
    witnessB: new Float64Array(n),
    supportA: new Int32Array(m),
    supportB: new Int32Array(m),
    supportCount: 0,
    simplex: new Float64Array(m * n),
    simplexA: new Int32Array(m),
    simplexB: new Int32Array(m),
    simplexCount: 0,
    v: new Float64Array(n),
    w: new Float64Array(n),
    d: new Float64Array(n),
    zero: new Float64Array(n),
    basis: new Float64Array(n * n),
    facetVerts: new Float64Array(m * n),
    pts: new Float64Array(EPA_MAX_POINTS * n),
    ptA: new Int32Array(EPA_MAX_POINTS),
    ptB: new Int32Array(EPA_MAX_POINTS),
    facets: new Int32Array(facetCapacity * n),
    fN: new Float64Array(facetCapacity * n),
    fO: new Float64Array(facetCapacity),
    fDead: new Uint8Array(facetCapacity),
    facetCapacity,
    centre: new Float64Array(n),
    ridges: new Int32Array(facetCapacity * n * (n - 1)),
    ridgeCount: new Int32Array(facetCapacity * n),
    ridgeTable: new Int32Array(tableSize(facetCapacity * n)),
    ridgeStamp: new Int32Array(tableSize(facetCapacity * n)),
    epoch: 0,
    cN: new Float64Array(64 * n),
    cO: new Float64Array(64),
    cId: new Int32Array(64),
    comb: new Int32Array(n),
    clipV: new Float64Array(64 * n),
    clipMask: new Int32Array(64),
    clipV2: new Float64Array(64 * n),
    clipMask2: new Int32Array(64),
    clipS: new Float64Array(64),
    scalars: Float64Array.of(0, 0, 0, 0, 0, 1e-6, 1e-8, 0),
  };
}

/** The polytope scratch of a narrowphase scratch, made on first use. */
export function polytopeScratch(scratch: NarrowphaseScratch): PolytopeScratch {
  let ps = scratch.polytope;
  if (ps === null) {
    ps = createPolytopeScratch(scratch.n);
    scratch.polytope = ps;
  }
  return ps;
}

/** Makes room for the clip constraints (grows by doubling, keeps those held). */
export function ensureClipCapacity(ps: PolytopeScratch, count: number): void {
  if (ps.cO.length >= count) return;
  const cap = Math.max(count, 2 * ps.cO.length);
  const cN = new Float64Array(cap * ps.n);
  cN.set(ps.cN);
  const cO = new Float64Array(cap);
  cO.set(ps.cO);
  const cId = new Int32Array(cap);
  cId.set(ps.cId);
  ps.cN = cN;
  ps.cO = cO;
  ps.cId = cId;
}

/** Makes room for `count` clip region vertices in every clip buffer (grows by doubling, keeps their contents). */
export function ensureRegionCapacity(ps: PolytopeScratch, count: number): void {
  if (ps.clipMask.length >= count) return;
  const cap = Math.max(count, 2 * ps.clipMask.length);
  const n = ps.n;
  const V = new Float64Array(cap * n);
  V.set(ps.clipV);
  const V2 = new Float64Array(cap * n);
  V2.set(ps.clipV2);
  const mask = new Int32Array(cap);
  mask.set(ps.clipMask);
  const mask2 = new Int32Array(cap);
  mask2.set(ps.clipMask2);
  const S = new Float64Array(cap);
  S.set(ps.clipS);
  ps.clipV = V;
  ps.clipV2 = V2;
  ps.clipMask = mask;
  ps.clipMask2 = mask2;
  ps.clipS = S;
}

/** Loads B's pose relative to A: R = M_Aᵀ M_B, t = M_Aᵀ (x_B − x_A). */
export function loadRelativePose(n: number, ps: PolytopeScratch, poseA: Pose, poseB: Pose): void {
  const MA = poseA.M;
  const MB = poseB.M;
  const R = ps.R;
  const t = ps.t;
  for (let i = 0; i < n; i += 1) {
    let s = 0;
    for (let k = 0; k < n; k += 1) s += MA[k * n + i] * (poseB.x[k] - poseA.x[k]);
    t[i] = s;
    for (let j = 0; j < n; j += 1) {
      let r = 0;
      for (let k = 0; k < n; k += 1) r += MA[k * n + i] * MB[k * n + j];
      R[i * n + j] = r;
    }
  }
  ps.size = 0;
}

/**
 * Writes a mesh into slot A (its own frame, as is) or slot B (carried into A's frame by R, t).
 * `loadRelativePose` first.
 */
export function loadMesh(n: number, ps: PolytopeScratch, mesh: CollisionMesh, intoB: boolean): void {
  const src = mesh.vertices;
  const srcN = mesh.facetNormals;
  const srcO = mesh.facetOffsets;
  const vc = src.length / n;
  const fc = srcO.length;
  let V: Float64Array;
  let N: Float64Array;
  let O: Float64Array;
  if (intoB) {
    V = ps.bV = grow(ps.bV, vc * n);
    N = ps.bN = grow(ps.bN, fc * n);
    O = ps.bO = grow(ps.bO, fc);
    ps.bVC = vc;
    ps.bFC = fc;
  } else {
    V = ps.aV = grow(ps.aV, vc * n);
    N = ps.aN = grow(ps.aN, fc * n);
    O = ps.aO = grow(ps.aO, fc);
    ps.aVC = vc;
    ps.aFC = fc;
  }
  let size = ps.size;
  const R = ps.R;
  const t = ps.t;
  for (let k = 0; k < vc; k += 1) {
    let r2 = 0;
    for (let c = 0; c < n; c += 1) r2 += src[k * n + c] * src[k * n + c];
    if (r2 > size * size) size = Math.sqrt(r2);
    if (!intoB) {
      for (let c = 0; c < n; c += 1) V[k * n + c] = src[k * n + c];
      continue;
    }
    for (let i = 0; i < n; i += 1) {
      let s = t[i];
      for (let c = 0; c < n; c += 1) s += R[i * n + c] * src[k * n + c];
      V[k * n + i] = s;
    }
  }
  ps.size = size;
  for (let f = 0; f < fc; f += 1) {
    if (!intoB) {
      for (let c = 0; c < n; c += 1) N[f * n + c] = srcN[f * n + c];
      O[f] = srcO[f];
      continue;
    }
    let o = srcO[f];
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += R[i * n + c] * srcN[f * n + c];
      N[f * n + i] = s;
      o += s * t[i];
    }
    O[f] = o;
  }
}

/** Writes a box into slot A or B, as {@link loadMesh}: corners by bitmask, faces 2c (−) and 2c + 1 (+). */
export function loadBox(n: number, ps: PolytopeScratch, box: CollisionBox, intoB: boolean): void {
  const h = box.halfExtents;
  const vc = 1 << n;
  const fc = 2 * n;
  let V: Float64Array;
  let N: Float64Array;
  let O: Float64Array;
  if (intoB) {
    V = ps.bV = grow(ps.bV, vc * n);
    N = ps.bN = grow(ps.bN, fc * n);
    O = ps.bO = grow(ps.bO, fc);
    ps.bVC = vc;
    ps.bFC = fc;
  } else {
    V = ps.aV = grow(ps.aV, vc * n);
    N = ps.aN = grow(ps.aN, fc * n);
    O = ps.aO = grow(ps.aO, fc);
    ps.aVC = vc;
    ps.aFC = fc;
  }
  let r2 = 0;
  for (let c = 0; c < n; c += 1) r2 += h[c] * h[c];
  if (r2 > ps.size * ps.size) ps.size = Math.sqrt(r2);
  const R = ps.R;
  const t = ps.t;
  for (let k = 0; k < vc; k += 1) {
    for (let i = 0; i < n; i += 1) {
      if (!intoB) {
        V[k * n + i] = (k >> i) & 1 ? h[i] : -h[i];
        continue;
      }
      let s = t[i];
      for (let c = 0; c < n; c += 1) s += R[i * n + c] * ((k >> c) & 1 ? h[c] : -h[c]);
      V[k * n + i] = s;
    }
  }
  for (let c = 0; c < n; c += 1) {
    for (let side = 0; side < 2; side += 1) {
      const f = 2 * c + side;
      const sign = side === 1 ? 1 : -1;
      let o = h[c];
      for (let i = 0; i < n; i += 1) {
        const s = intoB ? sign * R[i * n + c] : i === c ? sign : 0;
        N[f * n + i] = s;
        if (intoB) o += s * t[i];
      }
      O[f] = o;
    }
  }
}

/** Index of the vertex of V (count vertices) farthest along d (the first on ties). */
export function supportIndex(n: number, V: Float64Array, count: number, d: Float64Array): number {
  let best = -Infinity;
  let index = 0;
  for (let k = 0; k < count; k += 1) {
    let s = 0;
    for (let c = 0; c < n; c += 1) s += V[k * n + c] * d[c];
    if (s > best) {
      best = s;
      index = k;
    }
  }
  return index;
}

/**
 * Support point of D = A − B along `d`, written into out[o ..]; its A and B vertex indices into
 * ia[io], ib[io]. Uses ps.w as the negated direction.
 */
function supportD(
  n: number,
  ps: PolytopeScratch,
  d: Float64Array,
  out: Float64Array,
  o: number,
  ia: Int32Array,
  ib: Int32Array,
  io: number,
): void {
  const a = supportIndex(n, ps.aV, ps.aVC, d);
  const neg = ps.d === d ? ps.w : ps.d;
  for (let c = 0; c < n; c += 1) neg[c] = -d[c];
  const b = supportIndex(n, ps.bV, ps.bVC, neg);
  for (let c = 0; c < n; c += 1) out[o + c] = ps.aV[a * n + c] - ps.bV[b * n + c];
  ia[io] = a;
  ib[io] = b;
}

/**
 * The signed distance between the loaded polytopes (see the module comment). Sets ps.status,
 * ps.separation, ps.normal (A to B, A's frame), the witness points and their supporting vertex
 * indices. With status POLY_BEYOND (lower bound of the distance above `margin`) only that is
 * known. The margin is read from ps.scalars[PS_MARGIN]. Uses scratch.mat, piv, rhs, sol, simplex*
 * (through simplex-closest.ts) and scalars[3].
 */
export function polytopeSeparationKernel(n: number, ps: PolytopeScratch, scratch: NarrowphaseScratch): void {
  const margin = ps.scalars[PS_MARGIN];
  const W = ps.simplex;
  const WA = ps.simplexA;
  const WB = ps.simplexB;
  const v = ps.v;
  const dir = ps.d;
  const best = scratch.simplexBest;
  // start from the difference of the centres (B's origin in A's frame is t)
  let v2 = 0;
  for (let c = 0; c < n; c += 1) {
    v[c] = -ps.t[c];
    v2 += v[c] * v[c];
  }
  if (!(v2 > 0)) {
    v[0] = 1;
    v2 = 1;
  }
  let count = 0;
  let overlap = false;
  const tiny = 1e-24 * ps.size * ps.size;
  for (let iter = 0; iter < GJK_MAX_ITERATIONS; iter += 1) {
    for (let c = 0; c < n; c += 1) dir[c] = -v[c];
    supportD(n, ps, dir, W, count * n, WA, WB, count);
    let vw = 0;
    for (let c = 0; c < n; c += 1) vw += v[c] * W[count * n + c];
    if (vw > 0 && vw * vw > margin * margin * v2 && vw > margin * Math.sqrt(v2)) {
      ps.status = POLY_BEYOND;
      ps.separation = vw / Math.sqrt(v2);
      return;
    }
    // converged, or the new point repeats one held
    let repeat = false;
    for (let k = 0; k < count; k += 1) if (WA[k] === WA[count] && WB[k] === WB[count]) repeat = true;
    if (count > 0 && (repeat || v2 - vw <= GJK_RELATIVE_TOLERANCE * v2)) break;
    count += 1;
    closestPointOnSimplexKernel(n, v, W, count, ps.zero, scratch);
    v2 = scratch.scalars[3];
    // keep the vertices that carry the nearest point
    let kept = 0;
    for (let k = 0; k < count; k += 1) {
      if (best[k] === 0) continue;
      if (kept !== k) {
        for (let c = 0; c < n; c += 1) W[kept * n + c] = W[k * n + c];
        WA[kept] = WA[k];
        WB[kept] = WB[k];
      }
      best[kept] = best[k];
      kept += 1;
    }
    count = kept;
    if (v2 <= tiny || count === n + 1) {
      overlap = true;
      break;
    }
  }
  ps.simplexCount = count;
  if (!overlap) {
    const dist = Math.sqrt(v2);
    ps.status = POLY_SEPARATED;
    ps.separation = dist;
    for (let c = 0; c < n; c += 1) ps.normal[c] = -v[c] / dist;
    witnessesFrom(n, ps, WA, WB, best, count);
    return;
  }
  epa(n, ps, scratch);
}

/** Witness points Σ λ_k A[ia_k], Σ λ_k B[ib_k] and the support lists, from weights `lambda`. */
function witnessesFrom(
  n: number,
  ps: PolytopeScratch,
  ia: Int32Array,
  ib: Int32Array,
  lambda: Float64Array,
  count: number,
): void {
  const wa = ps.witnessA;
  const wb = ps.witnessB;
  for (let c = 0; c < n; c += 1) {
    wa[c] = 0;
    wb[c] = 0;
  }
  ps.supportCount = 0;
  for (let k = 0; k < count; k += 1) {
    const l = lambda[k];
    if (l === 0) continue;
    for (let c = 0; c < n; c += 1) {
      wa[c] += l * ps.aV[ia[k] * n + c];
      wb[c] += l * ps.bV[ib[k] * n + c];
    }
    ps.supportA[ps.supportCount] = ia[k];
    ps.supportB[ps.supportCount] = ib[k];
    ps.supportCount += 1;
  }
}

/**
 * Orthonormalises the `count` vectors vec[k] − vec[0] (k = 1..count−1, rows of `vecs` at n each)
 * into ps.basis by modified Gram–Schmidt twice; returns the rank found (vectors shorter than
 * ps.scalars[PS_TOL_LENGTH] after projection are dropped).
 */
function affineBasis(n: number, ps: PolytopeScratch, vecs: Float64Array, count: number): number {
  const B = ps.basis;
  let rank = 0;
  for (let k = 1; k < count; k += 1) {
    for (let c = 0; c < n; c += 1) B[rank * n + c] = vecs[k * n + c] - vecs[c];
    if (orthogonalise(n, B, rank, ps.scalars, PS_TOL_LENGTH)) rank += 1;
  }
  return rank;
}

/**
 * Projects row `r` of B off rows 0..r−1 (twice) and normalises it; false when shorter than
 * tols[at] (the tolerance travels in an array: a double argument would be boxed).
 */
function orthogonalise(n: number, B: Float64Array, r: number, tols: Float64Array, at: number): boolean {
  const tol = tols[at];
  for (let pass = 0; pass < 2; pass += 1) {
    for (let q = 0; q < r; q += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += B[r * n + c] * B[q * n + c];
      for (let c = 0; c < n; c += 1) B[r * n + c] -= s * B[q * n + c];
    }
  }
  let l = 0;
  for (let c = 0; c < n; c += 1) l += B[r * n + c] * B[r * n + c];
  l = Math.sqrt(l);
  if (!(l > tol)) return false;
  for (let c = 0; c < n; c += 1) B[r * n + c] /= l;
  return true;
}

/**
 * Unit normal of the hyperplane through the n points pts[facets[f·n ..]] into fN[f], oriented away
 * from ps.centre, offset into fO[f]. Returns false when the points are affinely dependent (an
 * edge shorter than ps.scalars[tolAt] once projected off the others).
 */
function facetPlane(n: number, ps: PolytopeScratch, f: number, tolAt: number): boolean {
  const B = ps.basis;
  const P = ps.pts;
  const idx = ps.facets;
  const p0 = idx[f * n] * n;
  for (let k = 1; k < n; k += 1) {
    const pk = idx[f * n + k] * n;
    for (let c = 0; c < n; c += 1) B[(k - 1) * n + c] = P[pk + c] - P[p0 + c];
    if (!orthogonalise(n, B, k - 1, ps.scalars, tolAt)) return false;
  }
  // the normal: the coordinate axis with the largest residual, projected off the facet's span
  let bestAxis = 0;
  let bestResidual = -1;
  for (let a = 0; a < n; a += 1) {
    let r = 1;
    for (let q = 0; q < n - 1; q += 1) r -= B[q * n + a] * B[q * n + a];
    if (r > bestResidual) {
      bestResidual = r;
      bestAxis = a;
    }
  }
  const r = n - 1;
  for (let c = 0; c < n; c += 1) B[r * n + c] = c === bestAxis ? 1 : 0;
  if (!orthogonalise(n, B, r, ps.scalars, PS_TOL_NORMAL)) return false;
  let side = 0;
  for (let c = 0; c < n; c += 1) side += B[r * n + c] * (P[p0 + c] - ps.centre[c]);
  const sign = side >= 0 ? 1 : -1;
  let o = 0;
  for (let c = 0; c < n; c += 1) {
    const nc = sign * B[r * n + c];
    ps.fN[f * n + c] = nc;
    o += nc * P[p0 + c];
  }
  ps.fO[f] = o;
  return true;
}

function growFacets(ps: PolytopeScratch, n: number, need: number): void {
  if (ps.facetCapacity >= need) return;
  const cap = Math.max(need, 2 * ps.facetCapacity);
  const facets = new Int32Array(cap * n);
  facets.set(ps.facets);
  const fN = new Float64Array(cap * n);
  fN.set(ps.fN);
  const fO = new Float64Array(cap);
  fO.set(ps.fO);
  const fDead = new Uint8Array(cap);
  fDead.set(ps.fDead);
  ps.facets = facets;
  ps.fN = fN;
  ps.fO = fO;
  ps.fDead = fDead;
  ps.ridges = new Int32Array(cap * n * (n - 1));
  ps.ridgeCount = new Int32Array(cap * n);
  ps.ridgeTable = new Int32Array(tableSize(cap * n));
  ps.ridgeStamp = new Int32Array(tableSize(cap * n));
  ps.epoch = 0;
  ps.facetCapacity = cap;
}

/** Sorts facet f's n point indices ascending (insertion sort). */
function sortFacet(n: number, idx: Int32Array, f: number): void {
  const o = f * n;
  for (let i = 1; i < n; i += 1) {
    const v = idx[o + i];
    let j = i - 1;
    while (j >= 0 && idx[o + j] > v) {
      idx[o + j + 1] = idx[o + j];
      j -= 1;
    }
    idx[o + j + 1] = v;
  }
}

/** The expanding polytope (see the module comment); GJK's simplex (ps.simplex*) holds the origin. */
function epa(n: number, ps: PolytopeScratch, scratch: NarrowphaseScratch): void {
  const P = ps.pts;
  const tolLen = 1e-9 * ps.size;
  ps.scalars[PS_TOL_LENGTH] = tolLen;
  ps.scalars[PS_TOL_FACET] = 1e-14 * ps.size;
  // the GJK simplex's affinely independent points, then completion to n + 1
  let count = 0;
  for (let k = 0; k < ps.simplexCount; k += 1) {
    for (let c = 0; c < n; c += 1) P[count * n + c] = ps.simplex[k * n + c];
    ps.ptA[count] = ps.simplexA[k];
    ps.ptB[count] = ps.simplexB[k];
    if (count === 0 || affineBasis(n, ps, P, count + 1) === count) count += 1;
  }
  if (count === 0) {
    supportD(n, ps, unitAxis(n, ps.v, 0), P, 0, ps.ptA, ps.ptB, 0);
    count = 1;
  }
  const dir = ps.v;
  while (count < n + 1) {
    const rank = affineBasis(n, ps, P, count);
    let added = false;
    // directions orthogonal to the current span: residuals of the coordinate axes
    for (let a = 0; a < n && !added; a += 1) {
      for (let c = 0; c < n; c += 1) ps.basis[rank * n + c] = c === a ? 1 : 0;
      if (!orthogonalise(n, ps.basis, rank, ps.scalars, PS_TOL_AXIS)) continue;
      for (let sgn = 1; sgn >= -1 && !added; sgn -= 2) {
        for (let c = 0; c < n; c += 1) dir[c] = sgn * ps.basis[rank * n + c];
        supportD(n, ps, dir, P, count * n, ps.ptA, ps.ptB, count);
        let h = 0;
        for (let c = 0; c < n; c += 1) h += dir[c] * (P[count * n + c] - P[c]);
        if (h > tolLen) added = true;
      }
    }
    if (!added) break;
    count += 1;
  }
  if (count < n + 1) {
    // D is flat within the tolerance (cannot happen for solid shapes): report touching
    ps.status = POLY_OVERLAP;
    ps.separation = 0;
    ps.supportCount = 0;
    return;
  }
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let k = 0; k <= n; k += 1) s += P[k * n + c];
    ps.centre[c] = s / (n + 1);
  }
  growFacets(ps, n, n + 1);
  let facetCount = 0;
  for (let skip = 0; skip <= n; skip += 1) {
    let j = 0;
    for (let k = 0; k <= n; k += 1) if (k !== skip) ps.facets[facetCount * n + j++] = k;
    ps.fDead[facetCount] = 0;
    if (facetPlane(n, ps, facetCount, PS_ZERO)) facetCount += 1;
  }
  let pointCount = n + 1;
  const tol = EPA_RELATIVE_TOLERANCE * ps.size;
  let bestFacet = -1;
  for (let iter = 0; iter < EPA_MAX_POINTS; iter += 1) {
    bestFacet = -1;
    let bestO = Infinity;
    for (let f = 0; f < facetCount; f += 1) {
      if (ps.fO[f] < bestO) {
        bestO = ps.fO[f];
        bestFacet = f;
      }
    }
    if (bestFacet < 0 || pointCount >= EPA_MAX_POINTS) break;
    for (let c = 0; c < n; c += 1) dir[c] = ps.fN[bestFacet * n + c];
    supportD(n, ps, dir, P, pointCount * n, ps.ptA, ps.ptB, pointCount);
    let h = 0;
    for (let c = 0; c < n; c += 1) h += dir[c] * P[pointCount * n + c];
    if (h - bestO <= tol) break;
    const p = pointCount;
    pointCount += 1;
    // visible facets
    for (let f = 0; f < facetCount; f += 1) {
      let s = -ps.fO[f];
      for (let c = 0; c < n; c += 1) s += ps.fN[f * n + c] * P[p * n + c];
      ps.fDead[f] = s > tol ? 1 : 0;
    }
    ps.fDead[bestFacet] = 1;
    // horizon ridges: ridges (sorted n−1 tuples) of removed facets that bound exactly one of them
    const rl = n - 1;
    let ridgeCount = 0;
    // a new stamp empties the ridge table (wrapping after 2³¹ iterations: clear it then)
    ps.epoch = (ps.epoch + 1) | 0;
    if (ps.epoch === 0) {
      ps.ridgeStamp.fill(0);
      ps.epoch = 1;
    }
    for (let f = 0; f < facetCount; f += 1) {
      if (!ps.fDead[f]) continue;
      for (let skip = 0; skip < n; skip += 1) {
        // FNV-1a of the sorted tuple, then linear probing among this iteration's slots
        let key = 0x811c9dc5;
        for (let k = 0; k < n; k += 1) if (k !== skip) key = Math.imul(key ^ ps.facets[f * n + k], 0x01000193);
        const mask = ps.ridgeTable.length - 1;
        let slot = key & mask;
        let found = -1;
        while (ps.ridgeStamp[slot] === ps.epoch) {
          const r = ps.ridgeTable[slot];
          let same = true;
          for (let j = 0, k = 0; k < n; k += 1) {
            if (k === skip) continue;
            if (ps.ridges[r * rl + j] !== ps.facets[f * n + k]) {
              same = false;
              break;
            }
            j += 1;
          }
          if (same) {
            found = r;
            break;
          }
          slot = (slot + 1) & mask;
        }
        if (found >= 0) {
          ps.ridgeCount[found] += 1;
          continue;
        }
        for (let j = 0, k = 0; k < n; k += 1) if (k !== skip) ps.ridges[ridgeCount * rl + j++] = ps.facets[f * n + k];
        ps.ridgeCount[ridgeCount] = 1;
        ps.ridgeStamp[slot] = ps.epoch;
        ps.ridgeTable[slot] = ridgeCount;
        ridgeCount += 1;
      }
    }
    // compact the live facets, then add ridge + p
    let live = 0;
    for (let f = 0; f < facetCount; f += 1) {
      if (ps.fDead[f]) continue;
      if (live !== f) {
        for (let c = 0; c < n; c += 1) {
          ps.facets[live * n + c] = ps.facets[f * n + c];
          ps.fN[live * n + c] = ps.fN[f * n + c];
        }
        ps.fO[live] = ps.fO[f];
      }
      ps.fDead[live] = 0;
      live += 1;
    }
    let horizon = 0;
    for (let r = 0; r < ridgeCount; r += 1) if (ps.ridgeCount[r] === 1) horizon += 1;
    if (live + horizon > ps.facetCapacity) {
      // copy the ridges out of the way of the growth: they are rebuilt each iteration
      growFacetsKeepRidges(ps, n, live + horizon, ridgeCount);
    }
    facetCount = live;
    let broken = false;
    for (let r = 0; r < ridgeCount; r += 1) {
      if (ps.ridgeCount[r] !== 1) continue;
      for (let j = 0; j < rl; j += 1) ps.facets[facetCount * n + j] = ps.ridges[r * rl + j];
      ps.facets[facetCount * n + rl] = p;
      sortFacet(n, ps.facets, facetCount);
      ps.fDead[facetCount] = 0;
      if (facetPlane(n, ps, facetCount, PS_TOL_FACET)) facetCount += 1;
      else broken = true;
    }
    if (broken || facetCount === 0) break;
  }
  if (bestFacet < 0) {
    ps.status = POLY_OVERLAP;
    ps.separation = 0;
    ps.supportCount = 0;
    return;
  }
  // result: the nearest facet found last. Its plane is D's nearest facet plane, but the origin's
  // projection q may lie in a coplanar neighbour (a facet of D made of several simplices): the
  // witnesses come from the coplanar facet that holds q.
  const f = bestFacet;
  ps.status = POLY_OVERLAP;
  ps.separation = -ps.fO[f];
  for (let c = 0; c < n; c += 1) ps.normal[c] = ps.fN[f * n + c];
  const q = ps.d;
  for (let c = 0; c < n; c += 1) q[c] = ps.fO[f] * ps.fN[f * n + c];
  const fv = ps.facetVerts;
  const holdTol = 1e-18 * ps.size * ps.size;
  let holder = f;
  for (let g = -1; g < facetCount; g += 1) {
    // the best facet first, then its coplanar neighbours
    const h = g < 0 ? f : g;
    if (g >= 0) {
      if (g === f) continue;
      let dot = 0;
      for (let c = 0; c < n; c += 1) dot += ps.fN[g * n + c] * ps.fN[f * n + c];
      if (dot < 1 - 1e-9 || Math.abs(ps.fO[g] - ps.fO[f]) > tol) continue;
    }
    for (let k = 0; k < n; k += 1) {
      const pk = ps.facets[h * n + k];
      for (let c = 0; c < n; c += 1) fv[k * n + c] = P[pk * n + c];
    }
    closestPointOnSimplexKernel(n, ps.w, fv, n, q, scratch);
    if (scratch.scalars[3] <= holdTol) {
      holder = h;
      break;
    }
  }
  for (let k = 0; k < n; k += 1) {
    const pk = ps.facets[holder * n + k];
    for (let c = 0; c < n; c += 1) fv[k * n + c] = P[pk * n + c];
    ps.simplexA[k] = ps.ptA[pk];
    ps.simplexB[k] = ps.ptB[pk];
  }
  closestPointOnSimplexKernel(n, ps.w, fv, n, q, scratch);
  witnessesFrom(n, ps, ps.simplexA, ps.simplexB, scratch.simplexBest, n);
}

/** A power of two at least twice `count` (the ridge table's load stays under one half). */
function tableSize(count: number): number {
  let size = 16;
  while (size < 2 * count) size *= 2;
  return size;
}

function growFacetsKeepRidges(ps: PolytopeScratch, n: number, need: number, ridgeCount: number): void {
  const rl = n - 1;
  const ridges = ps.ridges.slice(0, ridgeCount * rl);
  const counts = ps.ridgeCount.slice(0, ridgeCount);
  growFacets(ps, n, need);
  ps.ridges.set(ridges);
  ps.ridgeCount.set(counts);
}

function unitAxis(n: number, out: Float64Array, axis: number): Float64Array {
  for (let c = 0; c < n; c += 1) out[c] = c === axis ? 1 : 0;
  return out;
}
