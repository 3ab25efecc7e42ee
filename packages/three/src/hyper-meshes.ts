/**
 * The meshes of n-dimensional scenes: their size is given, not read from a geometry. For n ≥ 4 the
 * geometry is the body's cut by the 3-flat the viewer shows (coordinates 3..n−1 equal
 * `scene.slice`), written into buffers allocated once; for n ≤ 3 it is the body itself.
 *
 * @module
 */
import * as THREE from 'three';
import type { ShapeDescription } from '@physin/worker';
import { finite, integer, numbers, positive } from './checks.js';
import { Mesh } from './mesh.js';
import { BoxSlicer } from './slice/box-slice.js';
import { flatDistanceSquared } from './slice/sphere-slice.js';
import { TetraSlicer } from './slice/tetra-slice.js';
import { TorusSlicer } from './slice/torus-slice.js';
import type { TorusPose } from './slice/torus-slice.js';

function massOf(where: string, mass: unknown): number {
  return mass === undefined ? 1 : finite(where, 'mass', mass, 0, 'mass in kg');
}

/** A geometry whose buffers hold `maxVertices` and are rewritten in place at every slice. */
function sliceGeometry(maxVertices: number, bound: number): THREE.BufferGeometry {
  const g = new THREE.BufferGeometry();
  const position = new THREE.BufferAttribute(new Float32Array(3 * maxVertices), 3).setUsage(THREE.DynamicDrawUsage);
  const normal = new THREE.BufferAttribute(new Float32Array(3 * maxVertices), 3).setUsage(THREE.DynamicDrawUsage);
  g.setAttribute('position', position);
  g.setAttribute('normal', normal);
  g.setDrawRange(0, 0);
  // fixed bounds from the n-D bound, so three never recomputes them from the buffers
  g.boundingSphere = new THREE.Sphere(new THREE.Vector3(), bound);
  g.boundingBox = new THREE.Box3(new THREE.Vector3(-bound, -bound, -bound), new THREE.Vector3(bound, bound, bound));
  return g;
}

/** Marks a slice geometry's `count` vertices for upload. */
function commit(g: THREE.BufferGeometry, count: number): void {
  g.setDrawRange(0, count);
  g.getAttribute('position').needsUpdate = true;
  g.getAttribute('normal').needsUpdate = true;
}

/** A mesh whose shape is given in n dimensions; n ≥ 4 shows its slice. */
export abstract class HyperShapeMesh extends Mesh {
  /** @internal The slice must be computed again. */
  _sliceDirty = false;
  /** @internal The geometry was made by the mesh (not given by the user): `scene.dispose` frees it. */
  ownsGeometry = true;

  /** @internal Writes the slice by the flat `slice` (n − 3 numbers), M the rotation (n × n). */
  abstract updateSlice(slice: Float64Array, M: Float64Array): void;

  /** The position buffer the cut is written into. */
  protected positionsOf(): Float32Array {
    return this.geometry.getAttribute('position').array as Float32Array;
  }

  /** The normal buffer the cut is written into. */
  protected normalsOf(): Float32Array {
    return this.geometry.getAttribute('normal').array as Float32Array;
  }

  /** Shows `count` vertices; a body that stays out of the slice is left as it is (no upload). */
  protected show(count: number): void {
    if (count === 0 && !this.visible && this.geometry.drawRange.count === 0) return;
    this.visible = count > 0;
    commit(this.geometry, count);
  }
}

/** A box of `halfExtents` (n numbers: its count of dimensions). */
export class HyperBoxMesh extends HyperShapeMesh {
  /** The half extents. */
  readonly halfExtents: Float64Array;
  private readonly slicer: BoxSlicer | null;

  constructor(halfExtents: ArrayLike<number>, material?: THREE.Material | THREE.Material[], mass?: number) {
    const where = 'HyperBoxMesh';
    const he = numbers(where, 'halfExtents', halfExtents, null, 'half extents');
    if (he.length < 2 || he.length > 8)
      throw new RangeError(`${where}: argument 'halfExtents' must have 2 to 8 numbers, got ${he.length}`);
    for (let i = 0; i < he.length; i += 1) positive(where, `halfExtents[${i}]`, he[i], 'half extent in m');
    const m = massOf(where, mass);
    const n = he.length;
    const slicer = n >= 4 ? new BoxSlicer(n) : null;
    const geometry =
      slicer !== null
        ? sliceGeometry(slicer.maxTriangles * 3, Math.hypot(...he))
        : new THREE.BoxGeometry(2 * he[0]!, 2 * he[1]!, n === 3 ? 2 * he[2]! : 0.01);
    super(geometry, material, m, n);
    this.halfExtents = he;
    this.slicer = slicer;
  }

  /** @internal */
  describeShape(): ShapeDescription {
    return { kind: 'box', halfExtents: this.halfExtents };
  }

  /** @internal */
  updateSlice(slice: Float64Array, M: Float64Array): void {
    if (this.slicer === null) return;
    this.show(this.slicer.slice(this.positionsOf(), this.normalsOf(), this.halfExtents, this._x!, M, slice));
  }
}

/**
 * A ball of `radius`. A ball of 3 dimensions and one of 5 have the same description: it takes its
 * count of dimensions from the first `setPositionN`, or from the scene at `add`.
 */
export class HyperSphereMesh extends HyperShapeMesh {
  /** The radius. */
  readonly radius: number;

  constructor(radius: number, material?: THREE.Material | THREE.Material[], mass?: number) {
    const where = 'HyperSphereMesh';
    positive(where, 'radius', radius, 'radius in m');
    super(new THREE.SphereGeometry(1, 32, 16), material, massOf(where, mass), null);
    this.radius = radius;
    this.scale.setScalar(radius);
  }

  /** @internal */
  describeShape(): ShapeDescription {
    return { kind: 'sphere', radius: this.radius };
  }

  /** @internal */
  override setDimensions(n: number, where: string): void {
    super.setDimensions(n, where);
    if (n < 4) this.scale.setScalar(this.radius);
  }

  /** @internal A 3-ball of radius √(r² − d²): the unit sphere scaled, nothing rewritten. */
  updateSlice(slice: Float64Array): void {
    if (this._x!.length < 4) return;
    const s = this.radius * this.radius - flatDistanceSquared(this._x!, slice);
    this.visible = s > 0;
    if (s > 0) {
      // field stores, not setScalar(r): a double passed to a call that is not inlined is boxed
      const r = Math.sqrt(s);
      this.scale.x = r;
      this.scale.y = r;
      this.scale.z = r;
    }
  }
}

/**
 * A static half-space {x : normal·x ≤ offset} of n = normal.length dimensions. `displayGeometry`
 * shows it while its boundary crosses the slice.
 */
export class HyperPlaneMesh extends HyperShapeMesh {
  private readonly normal: Float64Array;
  private readonly offset: number;

  constructor(
    normal: ArrayLike<number>,
    offset: number,
    material?: THREE.Material | THREE.Material[],
    displayGeometry?: THREE.BufferGeometry,
  ) {
    const where = 'HyperPlaneMesh';
    const N = numbers(where, 'normal', normal, null);
    if (N.length < 2 || N.length > 8)
      throw new RangeError(`${where}: argument 'normal' must have 2 to 8 numbers, got ${N.length}`);
    finite(where, 'offset', offset, undefined, 'distance in m');
    if (displayGeometry !== undefined && !(displayGeometry instanceof THREE.BufferGeometry)) {
      throw new TypeError(`${where}: argument 'displayGeometry' must be a THREE.BufferGeometry or undefined`);
    }
    super(displayGeometry ?? new THREE.PlaneGeometry(40, 40).rotateX(-Math.PI / 2), material, 0, N.length);
    this.normal = N;
    this.offset = offset;
    this.placedByShape = true;
    this.ownsGeometry = displayGeometry === undefined;
  }

  /** @internal */
  describeShape(): ShapeDescription {
    return { kind: 'halfspace', normal: this.normal, offset: this.offset };
  }

  /** @internal Visible while the boundary meets the flat: always, unless the normal is all in w. */
  updateSlice(slice: Float64Array): void {
    const N = this.normal;
    if (N.length < 4) return;
    if (N[0]! * N[0]! + N[1]! * N[1]! + N[2]! * N[2]! > 1e-18) {
      this.visible = true;
      return;
    }
    let at = 0;
    let len = 0;
    for (let a = 3; a < N.length; a += 1) {
      at += N[a]! * slice[a - 3]!;
      len += N[a]! * N[a]!;
    }
    this.visible = Math.abs(at - this.offset) <= 1e-9 * Math.max(1, Math.sqrt(len));
  }
}

/** Options of a `HyperTorusMesh`. */
export interface HyperTorusOptions {
  /** Count of dimensions (default 4). */
  readonly dimensions?: number;
}

/**
 * A solid n-torus: the points within `minorRadius` of the circle of `majorRadius` in the plane of
 * body axes `plane`. Its slice is the exact 3D torus while the major plane stays in xyz, else a
 * traced surface (see `TorusSlicer`).
 */
export class HyperTorusMesh extends HyperShapeMesh {
  /** Radius of the core circle (m). */
  readonly majorRadius: number;
  /** Distance from the core circle to the surface (m). */
  readonly minorRadius: number;
  /** The two body axes [i, j] of the core circle's plane. */
  readonly plane: readonly [number, number];
  private readonly slicer: TorusSlicer | null;
  private readonly pose: {
    majorRadius: number;
    minorRadius: number;
    planeI: number;
    planeJ: number;
    x: Float64Array;
    M: Float64Array;
  };

  constructor(
    majorRadius: number,
    minorRadius: number,
    plane: readonly [number, number] = [0, 2],
    material?: THREE.Material | THREE.Material[],
    mass?: number,
    options: HyperTorusOptions = {},
  ) {
    const where = 'HyperTorusMesh';
    positive(where, 'majorRadius', majorRadius, 'radius in m');
    positive(where, 'minorRadius', minorRadius, 'radius in m');
    if (options === null || typeof options !== 'object')
      throw new TypeError(`${where}: argument 'options' must be an object { dimensions? }`);
    const n = options.dimensions === undefined ? 4 : integer(where, 'options.dimensions', options.dimensions, 3, 8);
    if (!Array.isArray(plane) || plane.length !== 2)
      throw new TypeError(`${where}: argument 'plane' must be two axis numbers [i, j]`);
    integer(where, 'plane[0]', plane[0], 0, n - 1);
    integer(where, 'plane[1]', plane[1], 0, n - 1);
    if (plane[0] === plane[1])
      throw new RangeError(`${where}: argument 'plane' must name two different axes, got [${plane[0]}, ${plane[1]}]`);
    const m = massOf(where, mass);
    const slicer = n >= 4 ? new TorusSlicer(n) : null;
    const geometry =
      slicer !== null
        ? sliceGeometry(slicer.maxVertices, majorRadius + minorRadius)
        : torusGeometry3(majorRadius, minorRadius, plane);
    super(geometry, material, m, n);
    this.majorRadius = majorRadius;
    this.minorRadius = minorRadius;
    this.plane = [plane[0], plane[1]];
    this.slicer = slicer;
    this.pose = { majorRadius, minorRadius, planeI: plane[0], planeJ: plane[1], x: this._x!, M: new Float64Array(0) };
  }

  /** @internal */
  describeShape(): ShapeDescription {
    return { kind: 'torus', majorRadius: this.majorRadius, minorRadius: this.minorRadius, plane: this.plane };
  }

  /** @internal */
  updateSlice(slice: Float64Array, M: Float64Array): void {
    if (this.slicer === null) return;
    this.pose.M = M;
    this.show(this.slicer.slice(this.positionsOf(), this.normalsOf(), this.pose as TorusPose, slice));
  }
}

/** three's TorusGeometry turned so its circle lies in the plane of axes `plane` (3D). */
function torusGeometry3(major: number, minor: number, plane: readonly [number, number]): THREE.BufferGeometry {
  const g = new THREE.TorusGeometry(major, minor, 24, 48);
  const key = [Math.min(plane[0], plane[1]), Math.max(plane[0], plane[1])].join('');
  if (key === '02') g.rotateX(Math.PI / 2);
  else if (key === '12') g.rotateY(Math.PI / 2);
  return g;
}

/**
 * A 4D convex body given by its vertices (4 numbers each, flat or nested) and its boundary
 * tetrahedra (`cells`, 4 vertex indices each). The origin must be inside.
 */
export class HyperMesh extends HyperShapeMesh {
  private readonly vertices: Float64Array;
  private readonly cells: Uint32Array;
  private readonly slicer: TetraSlicer;

  constructor(
    vertices: ArrayLike<number> | ArrayLike<ArrayLike<number>>,
    cells: ArrayLike<number> | ArrayLike<ArrayLike<number>>,
    material?: THREE.Material | THREE.Material[],
    mass?: number,
  ) {
    const where = 'HyperMesh';
    const flatV = numbers(where, 'vertices', flatten(vertices), null, 'coordinates');
    if (flatV.length < 20 || flatV.length % 4 !== 0)
      throw new RangeError(
        `${where}: argument 'vertices' must hold 5 or more 4D points (4 numbers each), got ${flatV.length} numbers`,
      );
    const flatC = numbers(where, 'cells', flatten(cells), null, 'vertex indices');
    if (flatC.length < 20 || flatC.length % 4 !== 0)
      throw new RangeError(
        `${where}: argument 'cells' must hold 5 or more tetrahedra (4 indices each), got ${flatC.length} numbers`,
      );
    const nv = flatV.length / 4;
    for (let i = 0; i < flatC.length; i += 1) integer(where, `cells[${i}]`, flatC[i], 0, nv - 1);
    const slicer = new TetraSlicer(flatV, flatC);
    let bound = 0;
    for (let i = 0; i < nv; i += 1)
      bound = Math.max(bound, Math.hypot(flatV[4 * i]!, flatV[4 * i + 1]!, flatV[4 * i + 2]!, flatV[4 * i + 3]!));
    super(sliceGeometry(slicer.maxVertices, bound), material, massOf(where, mass), 4);
    this.vertices = flatV;
    this.cells = Uint32Array.from(flatC);
    this.slicer = slicer;
  }

  /** @internal */
  describeShape(): ShapeDescription {
    return { kind: 'convex', vertices: this.vertices, facets: this.cells };
  }

  /** @internal */
  updateSlice(slice: Float64Array, M: Float64Array): void {
    this.show(this.slicer.slice(this.positionsOf(), this.normalsOf(), this._x!, M, slice));
  }
}

function flatten(value: unknown): unknown {
  if (Array.isArray(value) && value.length > 0 && (Array.isArray(value[0]) || ArrayBuffer.isView(value[0]))) {
    const out: unknown[] = [];
    for (const row of value as ArrayLike<unknown>[]) for (let i = 0; i < row.length; i += 1) out.push(row[i]);
    return out;
  }
  return value;
}
