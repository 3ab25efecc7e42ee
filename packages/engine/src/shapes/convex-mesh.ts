import { matrixToRotor } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { checkDims, checkPoints, checkPositive, checkTuples } from './checks.js';
import { checkMassArguments, diagonalMassProperties } from './mass-properties.js';
import { formatBound, inputLimits } from './limits.js';
import { createMoments, centreMoments, facetNormal, factorial } from './mesh-geometry.js';
import { accumulateMeshMoments } from './mesh-mass.js';
import { checkClosedBoundary } from './mesh-topology.js';
import { principalFrame } from './principal-frame.js';
import type { MassProperties, Shape } from './shape.js';
import { mergeTriangles } from './triangle-merge.js';
import type { TriangleMergeOptions } from './triangle-merge.js';
import { computeBoundsUnchecked } from '../collision/bounds.js';
import { meshColliders } from '../collision/mesh-colliders.js';
import { registerShapeFactory } from '../snapshot/registry.js';

/**
 * Default relative tolerance of the convex mesh checks, as a fraction of the mesh size (the
 * largest distance of a vertex from the vertex mean). It sits well above the rounding of
 * Float32 positions (6e-8 relative, as three.js stores them) and far below any shape error that
 * matters to the physics.
 */
export const DEFAULT_CONVEX_MESH_TOLERANCE = 1e-7;

/** Options of {@link ConvexMesh}. */
export interface ConvexMeshOptions {
  /**
   * Relative tolerance (fraction of the mesh size, > 0): a vertex may lie this far outside a facet
   * plane, and a facet whose (n−1)-volume is below tolerance × size^(n−1) is degenerate.
   * Default 1e-7.
   */
  readonly tolerance?: number;
}

/** Options of {@link ConvexMesh.fromTriangles}. */
export interface ConvexMeshTriangleOptions extends ConvexMeshOptions, TriangleMergeOptions {}

/**
 * A convex polytope given by its boundary: (n−1)-simplices (facets) over a vertex list.
 *
 * It is stored in its principal frame: the centre of mass at the local origin and the
 * covariance diagonal. `frameOffset` and `frameRotor` say where that frame sits in the
 * coordinates the mesh was given in: input point = frameOffset + frameRotor · (local point).
 * A body that places the mesh at position x with rotor R in the input coordinates therefore
 * uses position x + R·frameOffset and rotor R·frameRotor (first frameRotor, then R).
 */
export interface ConvexMeshShape extends Shape {
  readonly kind: 'mesh';
  readonly n: number;
  /** Vertex coordinates in the principal frame, flat (n per vertex, m). Read only. */
  readonly vertices: Float64Array;
  /** Count of vertices. */
  readonly vertexCount: number;
  /**
   * Facets, flat (n vertex indices each), oriented outward: for a facet (a_0..a_(n−1)),
   * det[a_0 − p, …, a_(n−1) − p] > 0 for p inside (3D: counter-clockwise seen from outside). Read only.
   */
  readonly facets: Int32Array;
  /** Count of facets. */
  readonly facetCount: number;
  /** Unit outward normal of each facet in the principal frame, flat (n per facet). Read only. */
  readonly facetNormals: Float64Array;
  /** Offset of each facet plane: the mesh is {x : facetNormals[f] · x <= facetOffsets[f] for all f} (m). Read only. */
  readonly facetOffsets: Float64Array;
  /** The centre of mass in the input coordinates (n numbers, m). Read only. */
  readonly frameOffset: Float64Array;
  /** The rotor that takes principal-frame coordinates to input coordinates (r numbers). Read only. */
  readonly frameRotor: Float64Array;
  /** The n-volume (m^n). */
  readonly volume: number;
  /** The absolute tolerance the checks used (m): the relative tolerance × the mesh size. */
  readonly tolerance: number;
}

/** How error messages name the input (the triangle path names merged positions differently). */
interface InputLabels {
  /** The argument holding the facets. */
  readonly facets: string;
  readonly vertex: (i: number) => string;
  readonly facet: (f: number) => string;
}

/**
 * Builds a convex mesh shape from its vertices and boundary facets.
 *
 * The input is checked and refused (nothing is built) when: a facet repeats a vertex or its
 * (n−1)-volume is below tolerance × size^(n−1) (degenerate); an (n−2)-face does not belong to
 * exactly two facets (not closed); a vertex is used by no facet; any vertex lies outside the
 * plane of any facet by more than tolerance × size (not convex — the message names both); the
 * vertex mean lies on a facet plane (flat). Facets may come in any orientation: each is turned
 * outward. The mesh need not contain or be centred on the origin.
 *
 * Mass properties come from signed cones over the facets (see closedMeshMassProperties); the
 * mesh is then moved into its principal frame (see {@link ConvexMeshShape}), so its
 * covariance, and so its inertia, is diagonal. The frame is the one closest to the input axes:
 * a mesh whose covariance is already diagonal keeps its axes (frameRotor = identity).
 *
 * @param D - the tables of the dimension.
 * @param vertices - points as number[][] or flat (n numbers per point); at least n + 1.
 * @param facets - n vertex indices per facet, as number[][] or flat.
 * @param options - see {@link ConvexMeshOptions}.
 * @throws TypeError for wrong types or lengths; RangeError for the faults listed above,
 *   non-finite coordinates or indices out of range.
 */
export function ConvexMesh(D: Dims, vertices: unknown, facets: unknown, options: ConvexMeshOptions = {}): ConvexMeshShape {
  const where = 'ConvexMesh';
  const checked = checkDims(where, D);
  const n = checked.n;
  const tolerance = readTolerance(where, options);
  const v = checkPoints(where, vertices, 'vertices', n);
  const count = v.length / n;
  if (count < n + 1)
    throw new RangeError(`${where}: argument 'vertices' must hold at least ${n + 1} points in ${n}D, got ${count}`);
  const f = checkTuples(where, facets, 'facets', n, count);
  return buildConvexMesh(where, checked, v, f, tolerance, {
    facets: 'facets',
    vertex: (i) => `'vertices'[${i}]`,
    facet: (i) => `'facets'[${i}]`,
  });
}

/**
 * Builds a 3D convex mesh from a triangle list as three.js gives it
 * (`geometry.attributes.position.array` and `geometry.index?.array`).
 *
 * Repeated vertices (three.js repeats a vertex once per normal or uv) are merged: by exact
 * position, or within `options.mergeTolerance` (m) when it is given. Triangles that collapse
 * when their vertices merge (two equal indices) are dropped. The result is checked like
 * {@link ConvexMesh}.
 *
 * @param D - the tables of n = 3.
 * @param positions - vertex positions, flat (x, y, z per vertex) or number[][].
 * @param indices - three vertex indices per triangle (flat or nested); omitted or null: every
 *   three consecutive positions are a triangle.
 * @param options - merge and convexity tolerances.
 */
function fromTriangles(D: Dims, positions: unknown, indices?: unknown, options: ConvexMeshTriangleOptions = {}): ConvexMeshShape {
  const where = 'ConvexMesh.fromTriangles';
  const checked = checkDims(where, D);
  if (checked.n !== 3)
    throw new RangeError(`${where}: argument 'D' must be the tables of n = 3 (a triangle mesh is 3D), got n = ${checked.n}`);
  const tolerance = readTolerance(where, options);
  const merged = mergeTriangles(where, positions, indices, options);
  if (merged.vertexCount < 4) {
    throw new RangeError(`${where}: argument 'positions' must hold at least 4 distinct points, got ${merged.vertexCount}`);
  }
  const { firstSource, triangleSource } = merged;
  try {
    return buildConvexMesh(where, checked, merged.vertices, merged.triangles, tolerance, {
      facets: 'indices',
      vertex: (i) => `'positions' vertex ${firstSource[i]}`,
      facet: (f) => `triangle ${triangleSource[f]}`,
    });
  } catch (error) {
    if (error instanceof RangeError && / not closed/.test(error.message) && !options.mergeTolerance) {
      // the usual cause: copies of a corner that differ by rounding (three.js sphere seams and poles)
      throw new RangeError(
        `${error.message}. Copies of a position that differ by rounding are not merged by default: pass options.mergeTolerance`,
        { cause: error },
      );
    }
    throw error;
  }
}

/**
 * Builds a 3D convex mesh from a triangle soup (as in a three.js `BufferGeometry`): coplanar
 * triangles merge into facets, duplicated positions into vertices. See {@link ConvexMeshTriangleOptions}.
 */
ConvexMesh.fromTriangles = fromTriangles;

// World snapshots rebuild saved meshes with this factory (snapshot/registry.ts).
registerShapeFactory('mesh', ConvexMesh);

function readTolerance(where: string, options: unknown): number {
  if (typeof options !== 'object' || options === null) {
    throw new TypeError(`${where}: argument 'options' must be an object, got ${options === null ? 'null' : typeof options}`);
  }
  const t = (options as ConvexMeshOptions).tolerance;
  return t === undefined ? DEFAULT_CONVEX_MESH_TOLERANCE : checkPositive(where, t, 'options.tolerance');
}

function buildConvexMesh(
  where: string,
  D: Dims,
  input: Float64Array,
  facets: Int32Array,
  relativeTolerance: number,
  label: InputLabels,
): ConvexMeshShape {
  const n = D.n;
  const count = input.length / n;
  const facetCount = facets.length / n;
  if (facetCount < n + 1) {
    throw new RangeError(`${where}: a closed mesh in ${n}D needs at least ${n + 1} facets, got ${facetCount}`);
  }

  // coordinates within ±maxPosition, so the sums, squares and the centroid below stay finite
  const maxPosition = inputLimits.maxPosition;
  for (let i = 0; i < input.length; i += 1) {
    if (!(Math.abs(input[i]) <= maxPosition)) {
      const v = Math.floor(i / n);
      throw new RangeError(
        `${where}: ${label.vertex(v)} coordinate ${i % n} must be within ±${formatBound(maxPosition)} m (Body.limits), got ${input[i]}`,
      );
    }
  }
  // the vertex mean is inside a convex polytope: it anchors the cones and measures the size
  const mean = new Float64Array(n);
  for (let i = 0; i < count; i += 1) for (let c = 0; c < n; c += 1) mean[c] += input[i * n + c];
  for (let c = 0; c < n; c += 1) mean[c] /= count;
  // all geometry below is relative to the mean, so a mesh far from the origin keeps its digits
  const x = new Float64Array(input.length);
  let size = 0;
  for (let i = 0; i < count; i += 1) {
    let d2 = 0;
    for (let c = 0; c < n; c += 1) {
      x[i * n + c] = input[i * n + c] - mean[c];
      d2 += x[i * n + c] ** 2;
    }
    size = Math.max(size, Math.sqrt(d2));
  }
  if (!(size >= inputLimits.minLength && size <= inputLimits.maxLength)) {
    throw new RangeError(
      `${where}: the mesh's size (largest distance of a vertex from the vertex mean) must be within [${formatBound(inputLimits.minLength)}, ${formatBound(inputLimits.maxLength)}] m (Body.limits), got ${size}`,
    );
  }
  const tolerance = relativeTolerance * size;

  const used = new Uint8Array(count);
  for (let i = 0; i < facets.length; i += 1) used[facets[i]] = 1;
  for (let i = 0; i < count; i += 1) {
    if (!used[i]) throw new RangeError(`${where}: ${label.vertex(i)} is used by no facet`);
  }

  const normals = new Float64Array(facets.length);
  const offsets = new Float64Array(facetCount);
  const normal = new Float64Array(n);
  const scratch = new Float64Array(2 * n * n);
  const minArea = relativeTolerance * size ** (n - 1);
  const areaScale = factorial(n - 1);
  for (let f = 0; f < facetCount; f += 1) {
    facetNormal(n, normal, x, facets, f, scratch);
    let length = 0;
    for (let c = 0; c < n; c += 1) length = Math.hypot(length, normal[c]);
    if (!(length / areaScale > minArea)) {
      throw new RangeError(
        `${where}: ${label.facet(f)} is degenerate: its (n-1)-volume ${length / areaScale} is below ${minArea} (tolerance × size^(n-1))`,
      );
    }
    const a0 = facets[f * n] * n;
    let offset = 0;
    for (let c = 0; c < n; c += 1) {
      normal[c] /= length;
      offset += normal[c] * x[a0 + c];
    }
    // one pass over the vertices: the farthest one lies on the inner side of a convex mesh's
    // facet (it orients the facet), and nothing may lie beyond the plane on the other side
    let low = 0;
    let high = 0;
    let lowVertex = 0;
    let highVertex = 0;
    const n0 = normal[0];
    const n1 = normal[1];
    const n2 = n > 2 ? normal[2] : 0;
    for (let i = 0, o = 0; i < count; i += 1, o += n) {
      // O(vertices × facets) in all: the 2D and 3D dot products are written out
      let d: number;
      if (n === 3) d = n0 * x[o] + n1 * x[o + 1] + n2 * x[o + 2] - offset;
      else if (n === 2) d = n0 * x[o] + n1 * x[o + 1] - offset;
      else {
        d = -offset;
        for (let c = 0; c < n; c += 1) d += normal[c] * x[o + c];
      }
      if (d < low) {
        low = d;
        lowVertex = i;
      } else if (d > high) {
        high = d;
        highVertex = i;
      }
    }
    if (Math.max(-low, high) <= tolerance) {
      throw new RangeError(
        `${where}: the mesh is flat: every vertex lies within the tolerance ${tolerance.toPrecision(4)} of the plane of ${label.facet(f)}`,
      );
    }
    const outward = -low >= high;
    const outside = outward ? high : -low;
    if (outside > tolerance) {
      const i = outward ? highVertex : lowVertex;
      const at = Array.from(input.subarray(i * n, i * n + n), (value) => +value.toPrecision(6)).join(', ');
      throw new RangeError(
        `${where}: the mesh is not convex: ${label.vertex(i)} (${at}) lies outside the plane of ${label.facet(f)} by ${outside.toPrecision(4)} (tolerance ${tolerance.toPrecision(4)}; ${label.vertex(outward ? lowVertex : highVertex)} lies ${Math.max(-low, high).toPrecision(4)} on the other side)`,
      );
    }
    if (!outward) {
      // turn the facet outward: swap two vertices and negate the plane
      const t = facets[f * n];
      facets[f * n] = facets[f * n + 1];
      facets[f * n + 1] = t;
      for (let c = 0; c < n; c += 1) normal[c] = -normal[c];
      offset = -offset;
    }
    normals.set(normal, f * n);
    offsets[f] = offset;
  }

  checkClosedBoundary(n, facets, { where, facets: label.facets, facet: label.facet });

  // mass properties, cones from the vertex mean (all positive for a convex mesh)
  const zero = new Float64Array(n);
  const acc = accumulateMeshMoments(n, x, facets, zero, createMoments(n));
  const volume = acc.volume;
  const g = new Float64Array(n);
  const K = new Float64Array(n * n);
  centreMoments(n, acc, g, K);
  for (let i = 0; i < n * n; i += 1) K[i] /= volume; // per unit mass
  const centroid = new Float64Array(n);
  for (let c = 0; c < n; c += 1) centroid[c] = mean[c] + g[c];

  const Q = new Float64Array(n * n);
  const unitCovariance = new Float64Array(n);
  principalFrame(n, Q, unitCovariance, K);
  for (let c = 0; c < n; c += 1) {
    if (!(unitCovariance[c] > 0 && unitCovariance[c] < Infinity) || !(volume > 0 && volume < Infinity)) {
      throw new RangeError(
        `${where}: the mesh has volume ${volume} and principal second moment ${unitCovariance[c]} m² along axis ${c}: too thin to have an inertia`,
      );
    }
  }
  const frameRotor = matrixToRotor(D, new Float64Array(D.r), Q);

  // principal frame: local = Qᵀ (x − g), normals N' = Qᵀ N
  const local = new Float64Array(x.length);
  for (let i = 0; i < count; i += 1) rotateInto(n, local, i * n, Q, x, i * n, g);
  const localNormals = new Float64Array(normals.length);
  for (let f = 0; f < facetCount; f += 1) {
    rotateInto(n, localNormals, f * n, Q, normals, f * n, zero);
    const a0 = facets[f * n] * n;
    let offset = 0;
    for (let c = 0; c < n; c += 1) offset += localNormals[f * n + c] * local[a0 + c];
    offsets[f] = offset;
  }

  return Object.freeze({
    // Collision pairs travel with the shape, so an unused shape leaves its collision code out of the bundle.
    colliders: meshColliders,
    // Its bounds too: a world of boxes, balls and half-spaces carries no code of other kinds.
    bounds: computeBoundsUnchecked,
    kind: 'mesh' as const,
    n,
    vertices: local,
    vertexCount: count,
    facets,
    facetCount,
    facetNormals: localNormals,
    facetOffsets: offsets,
    frameOffset: centroid,
    frameRotor,
    volume,
    tolerance,
    massProperties(Dm: Dims, mass: number): MassProperties {
      const c = checkMassArguments('ConvexMesh.massProperties', Dm, mass, n);
      return diagonalMassProperties(c, volume, unitCovariance, mass);
    },
  });
}

/** out[o..o+n) = Qᵀ (x[xo..xo+n) − shift). */
function rotateInto(
  n: number,
  out: Float64Array,
  o: number,
  Q: Float64Array,
  x: Float64Array,
  xo: number,
  shift: Float64Array,
): void {
  for (let c = 0; c < n; c += 1) {
    let s = 0;
    for (let r = 0; r < n; r += 1) s += Q[r * n + c] * (x[xo + r] - shift[r]);
    out[o + c] = s;
  }
}
