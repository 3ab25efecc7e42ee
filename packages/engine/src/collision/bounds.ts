/**
 * World-space axis-aligned bounding boxes of posed shapes, in n dimensions.
 *
 * Each bound is exact (the smallest axis-aligned box of the posed solid) before the margin is
 * added: along world axis k the box reaches the shape's support point in direction ±e_k.
 */
import { checkDimension, checkNumber, checkOutput, checkPose, checkShape } from './query-checks.js';
import type {
  BoxGeometry,
  CapsuleGeometry,
  ConvexMeshGeometry,
  HalfSpaceGeometry,
  QueryShape,
  SphereGeometry,
  TorusGeometry,
} from './query-shapes.js';
import { shapeKind } from './shape-kind.js';

/**
 * The bounds of a posed shape: the signature of {@link computeBounds}, and of the kernels that skip
 * its checks (what a torus, mesh or capsule attaches as its `bounds` for {@link computeBoundsCommon}).
 */
export type ShapeBounds = typeof computeBounds;

/**
 * Writes the world bounding box of `shape` placed at pose (x, M), grown by `margin` on every
 * side, into outMin/outMax (n numbers each, m). Validates every argument first.
 *
 * - box, half extents a: extent along world axis k is Σ_c |M[k][c]| a_c;
 * - sphere, radius ρ: ρ on every axis;
 * - torus (core circle radius R in local plane (i, j), tube radius r): R·√(M[k][i]² + M[k][j]²) + r,
 *   the exact extent of the solid torus (the circle's extent plus the ball's);
 * - convex mesh: min and max over its vertices;
 * - capsule (segment ±h·e₁, radius r): h·|M[k][1]| + r;
 * - half-space: infinite (−∞, +∞) on every axis, except that a plane whose world normal is
 *   exactly a coordinate axis bounds that one axis on its solid side. The broadphase keeps
 *   half-spaces aside and never puts them in its tree.
 *
 * @param outMin receives the lower corner (n numbers).
 * @param outMax receives the upper corner (n numbers).
 * @param n count of dimensions (2..8).
 * @param shape the shape's geometry in its local frame.
 * @param x world position of the local origin (n numbers).
 * @param M world rotation, n*n row-major (`M[i*n + c]` = component i of local axis c).
 * @param margin extra room added on every side (m, >= 0).
 * @returns outMin.
 */
export function computeBounds(
  outMin: Float64Array,
  outMax: Float64Array,
  n: number,
  shape: QueryShape,
  x: ArrayLike<number>,
  M: ArrayLike<number>,
  margin: number,
): Float64Array {
  checkDimension(n);
  checkOutput(outMin, n, 'outMin');
  checkOutput(outMax, n, 'outMax');
  checkShape(shape, n);
  checkPose(n, x, M);
  checkNumber(margin, 'margin', 0);
  return computeBoundsUnchecked(outMin, outMax, n, shape, x, M, margin);
}

/**
 * {@link computeBounds} without any argument check: the engine's per-step kernel for data it
 * validated when the body entered the world. Allocates nothing. (The kind is read through
 * {@link shapeKind}, so the number fields of each kind load unboxed; see shape-kind.ts.)
 */
export const computeBoundsUnchecked: ShapeBounds = function computeBoundsUnchecked(outMin, outMax, n, shape, x, M, margin) {
  switch (shapeKind(shape)) {
    case 'torus': {
      const torus = shape as TorusGeometry;
      const R = torus.majorRadius;
      const r = torus.minorRadius;
      const pi = torus.planeI;
      const pj = torus.planeJ;
      for (let k = 0; k < n; k += 1) {
        const u = M[k * n + pi]!;
        const v = M[k * n + pj]!;
        // The core circle's extent along e_k is R times the length of e_k projected on its plane.
        const e = R * Math.sqrt(u * u + v * v) + r + margin;
        outMin[k] = x[k]! - e;
        outMax[k] = x[k]! + e;
      }
      return outMin;
    }
    case 'mesh': {
      const vs = (shape as ConvexMeshGeometry).vertices;
      const count = vs.length / n;
      for (let k = 0; k < n; k += 1) {
        let lo = Infinity;
        let hi = -Infinity;
        const row = k * n;
        for (let v = 0; v < count; v += 1) {
          let w = 0;
          const base = v * n;
          for (let c = 0; c < n; c += 1) w += M[row + c]! * vs[base + c]!;
          if (w < lo) lo = w;
          if (w > hi) hi = w;
        }
        outMin[k] = x[k]! + lo - margin;
        outMax[k] = x[k]! + hi + margin;
      }
      return outMin;
    }
    case 'capsule': {
      const capsule = shape as CapsuleGeometry;
      const h = capsule.halfHeight;
      const e0 = capsule.radius + margin;
      // The core segment runs along local axis 1: its extent along e_k is h·|M[k][1]|.
      for (let k = 0; k < n; k += 1) {
        const e = h * Math.abs(M[k * n + 1]!) + e0;
        outMin[k] = x[k]! - e;
        outMax[k] = x[k]! + e;
      }
      return outMin;
    }
    case 'box':
    case 'sphere':
    case 'halfspace':
      return computeBoundsCommon(outMin, outMax, n, shape, x, M, margin);
    default:
      // A compound has no bounds of its own: each of its parts is placed as a shape of its own.
      throw new TypeError(`computeBounds: a '${String(shapeKind(shape))}' shape has no bounds of its own`);
  }
};

/**
 * The bounds a world asks for each step: {@link computeBoundsUnchecked} for a box, a ball or a
 * half-space, and for every other kind the `bounds` its factory attaches (HyperTorus, ConvexMesh
 * and HyperCapsule attach computeBoundsUnchecked), so a world of boxes carries none of the torus,
 * mesh or capsule code. The same bits as computeBoundsUnchecked; allocates nothing.
 */
export const computeBoundsCommon: ShapeBounds = function computeBoundsCommon(outMin, outMax, n, shape, x, M, margin) {
  switch (shapeKind(shape)) {
    case 'box': {
      const a = (shape as BoxGeometry).halfExtents;
      for (let k = 0; k < n; k += 1) {
        let e = 0;
        const row = k * n;
        for (let c = 0; c < n; c += 1) e += Math.abs(M[row + c]!) * a[c]!;
        e += margin;
        outMin[k] = x[k]! - e;
        outMax[k] = x[k]! + e;
      }
      return outMin;
    }
    case 'sphere': {
      const e = (shape as SphereGeometry).radius + margin;
      for (let k = 0; k < n; k += 1) {
        outMin[k] = x[k]! - e;
        outMax[k] = x[k]! + e;
      }
      return outMin;
    }
    case 'halfspace': {
      halfSpaceBounds(outMin, outMax, n, shape as HalfSpaceGeometry, x, M, margin);
      return outMin;
    }
    default: {
      const own = (shape as { readonly bounds?: ShapeBounds }).bounds;
      if (own === undefined) throw new TypeError(`computeBounds: a '${String(shapeKind(shape))}' shape has no bounds of its own`);
      return own(outMin, outMax, n, shape, x, M, margin);
    }
  }
};

/** Bounds of a posed half-space: infinite except along an axis its world normal is exactly. */
function halfSpaceBounds(
  outMin: Float64Array,
  outMax: Float64Array,
  n: number,
  shape: HalfSpaceGeometry,
  x: ArrayLike<number>,
  M: ArrayLike<number>,
  margin: number,
): void {
  // the shape, not its offset, is passed: a number argument of a call V8 does not inline is boxed
  const normal = shape.normal;
  const offset = shape.offset;
  let axis = -1;
  let nonzero = 0;
  let wk = 0;
  let wDotX = 0;
  for (let k = 0; k < n; k += 1) {
    outMin[k] = -Infinity;
    outMax[k] = Infinity;
    let w = 0;
    for (let c = 0; c < n; c += 1) w += M[k * n + c]! * normal[c]!;
    wDotX += w * x[k]!;
    if (w !== 0) {
      nonzero += 1;
      axis = k;
      wk = w;
    }
  }
  if (nonzero !== 1) return;
  // World plane: w·p <= offset + w·x with w = wk e_axis, so p_axis is bounded on one side.
  const limit = (offset + wDotX) / wk;
  if (wk > 0) outMax[axis] = limit + margin;
  else outMin[axis] = limit - margin;
}
