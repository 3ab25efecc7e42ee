/**
 * The meshes of 3D (and 2D) scenes: their size comes from the three.js geometry and the object's
 * scale at `scene.add`, as in Physijs.
 *
 * @module
 */
import * as THREE from 'three';
import type { ShapeDescription } from '@physin/worker';
import { finite, integer, numbers, positive } from './checks.js';
import { Mesh } from './mesh.js';

/** Mass given to a constructor: a number ≥ 0 (0: static), default 1. */
function massOf(where: string, mass: unknown): number {
  return mass === undefined ? 1 : finite(where, 'mass', mass, 0, 'mass in kg');
}

function geometryOf(where: string, geometry: unknown): THREE.BufferGeometry {
  if (!(geometry instanceof THREE.BufferGeometry)) {
    throw new TypeError(
      `${where}: argument 'geometry' must be a THREE.BufferGeometry, got ${geometry === null ? 'null' : typeof geometry}`,
    );
  }
  return geometry;
}

/** The object's scale, which must be uniform (a sphere or a torus cannot be stretched). */
function uniformScale(mesh: THREE.Object3D, where: string): number {
  const s = mesh.scale;
  const a = Math.abs(s.x);
  if (Math.abs(Math.abs(s.y) - a) > 1e-9 * a || Math.abs(Math.abs(s.z) - a) > 1e-9 * a || !(a > 0)) {
    throw new RangeError(`${where}: a ${mesh.constructor.name} needs a uniform, non-zero scale, got (${s.x}, ${s.y}, ${s.z})`);
  }
  return a;
}

/** A box; its half extents are half the geometry's bounding box, times the object's scale. */
export class BoxMesh extends Mesh {
  constructor(geometry: THREE.BufferGeometry, material?: THREE.Material | THREE.Material[], mass?: number) {
    const where = 'BoxMesh';
    super(geometryOf(where, geometry), material, massOf(where, mass), null);
  }

  /** @internal */
  override acceptsDimensions(n: number): boolean {
    return n === 2 || n === 3;
  }

  /** @internal */
  describeShape(n: number): ShapeDescription {
    const g = this.geometry;
    if (g.boundingBox === null) g.computeBoundingBox();
    const size = g.boundingBox!.getSize(new THREE.Vector3());
    const s = this.scale;
    const he = [(size.x * Math.abs(s.x)) / 2, (size.y * Math.abs(s.y)) / 2, (size.z * Math.abs(s.z)) / 2].slice(0, n);
    for (const h of he) {
      if (!(h > 0))
        throw new RangeError(
          `BoxMesh: the geometry's bounding box times the scale must have a positive size, got half extents (${he.join(', ')})`,
        );
    }
    return { kind: 'box', halfExtents: he };
  }
}

/** A ball; its radius is the geometry's bounding sphere's, times the (uniform) scale. */
export class SphereMesh extends Mesh {
  constructor(geometry: THREE.BufferGeometry, material?: THREE.Material | THREE.Material[], mass?: number) {
    const where = 'SphereMesh';
    super(geometryOf(where, geometry), material, massOf(where, mass), null);
  }

  /** @internal */
  override acceptsDimensions(n: number): boolean {
    return n === 2 || n === 3;
  }

  /** @internal */
  describeShape(): ShapeDescription {
    const g = this.geometry;
    if (g.boundingSphere === null) g.computeBoundingSphere();
    const radius = g.boundingSphere!.radius * uniformScale(this, 'SphereMesh');
    return { kind: 'sphere', radius };
  }
}

/**
 * A static half-space {x : normal·x ≤ offset}; the geometry only shows it. Its body stays where
 * `normal` and `offset` put it, whatever the mesh's position.
 */
export class PlaneMesh extends Mesh {
  private readonly normal: Float64Array;
  private readonly offset: number;

  constructor(
    geometry: THREE.BufferGeometry,
    material: THREE.Material | THREE.Material[] | undefined,
    normal: ArrayLike<number>,
    offset = 0,
  ) {
    const where = 'PlaneMesh';
    const N = numbers(where, 'normal', normal, null);
    if (N.length !== 2 && N.length !== 3)
      throw new RangeError(`${where}: argument 'normal' must have 2 or 3 numbers, got ${N.length}`);
    finite(where, 'offset', offset, undefined, 'distance in m');
    super(geometryOf(where, geometry), material, 0, N.length);
    this.normal = N;
    this.offset = offset;
    this.placedByShape = true;
  }

  /** @internal */
  describeShape(): ShapeDescription {
    return { kind: 'halfspace', normal: this.normal, offset: this.offset };
  }
}

/**
 * A solid torus: the points within `minorRadius` of the circle of `majorRadius` in the plane of
 * body axes `plane` (default [0, 1], the plane of three's `TorusGeometry`). Sizes are times the
 * (uniform) scale.
 */
export class TorusMesh extends Mesh {
  private readonly major: number;
  private readonly minor: number;
  private readonly plane: readonly [number, number];

  constructor(
    geometry: THREE.BufferGeometry,
    material: THREE.Material | THREE.Material[] | undefined,
    mass: number | undefined,
    majorRadius: number,
    minorRadius: number,
    plane: readonly [number, number] = [0, 1],
  ) {
    const where = 'TorusMesh';
    positive(where, 'majorRadius', majorRadius, 'radius in m');
    positive(where, 'minorRadius', minorRadius, 'radius in m');
    if (!Array.isArray(plane) || plane.length !== 2)
      throw new TypeError(`${where}: argument 'plane' must be two axis numbers [i, j]`);
    integer(where, 'plane[0]', plane[0], 0, 2);
    integer(where, 'plane[1]', plane[1], 0, 2);
    if (plane[0] === plane[1])
      throw new RangeError(`${where}: argument 'plane' must name two different axes, got [${plane[0]}, ${plane[1]}]`);
    super(geometryOf(where, geometry), material, massOf(where, mass), 3);
    this.major = majorRadius;
    this.minor = minorRadius;
    this.plane = [plane[0], plane[1]];
  }

  /** @internal */
  describeShape(): ShapeDescription {
    const s = uniformScale(this, 'TorusMesh');
    return { kind: 'torus', majorRadius: this.major * s, minorRadius: this.minor * s, plane: this.plane };
  }
}

/**
 * A capsule: the points within `radius` of a segment along the object's y axis, sized from a
 * `THREE.CapsuleGeometry`'s parameters (`radius`, and `height`, the length of the straight part;
 * three.js before r170 called it `length`) times the object's (uniform) scale: the body's capsule
 * has half-height height·s/2 and radius radius·s (the engine's `HyperCapsule`, axis 1 = y).
 */
export class CapsuleMesh extends Mesh {
  constructor(geometry: THREE.BufferGeometry, material?: THREE.Material | THREE.Material[], mass?: number) {
    const where = 'CapsuleMesh';
    const g = geometryOf(where, geometry);
    capsuleParameters(where, g);
    super(g, material, massOf(where, mass), null);
  }

  /** @internal */
  override acceptsDimensions(n: number): boolean {
    return n === 2 || n === 3;
  }

  /** @internal */
  describeShape(): ShapeDescription {
    const { radius, height } = capsuleParameters('CapsuleMesh', this.geometry);
    const s = uniformScale(this, 'CapsuleMesh');
    return { kind: 'capsule', halfHeight: (height * s) / 2, radius: radius * s };
  }
}

/** The radius and straight height of a capsule geometry (its `parameters`), checked. */
function capsuleParameters(where: string, geometry: THREE.BufferGeometry): { radius: number; height: number } {
  const p = (geometry as { parameters?: { radius?: unknown; height?: unknown; length?: unknown } }).parameters;
  if (p === undefined || p === null || typeof p !== 'object') {
    throw new TypeError(`${where}: argument 'geometry' must be a THREE.CapsuleGeometry (with parameters radius and height)`);
  }
  const radius = positive(where, 'geometry.parameters.radius', p.radius, 'radius in m');
  const height = positive(where, 'geometry.parameters.height', p.height ?? p.length, 'length in m');
  return { radius, height };
}

/**
 * A convex body from the geometry's triangles (the position attribute, indexed or not; repeated
 * vertices are merged), times the object's scale. The geometry must be convex with the origin
 * inside.
 */
export class ConvexMesh extends Mesh {
  constructor(geometry: THREE.BufferGeometry, material?: THREE.Material | THREE.Material[], mass?: number) {
    const where = 'ConvexMesh';
    const g = geometryOf(where, geometry);
    if (g.getAttribute('position') === undefined) throw new RangeError(`${where}: the geometry has no 'position' attribute`);
    super(g, material, massOf(where, mass), 3);
  }

  /** @internal */
  describeShape(): ShapeDescription {
    const attribute = this.geometry.getAttribute('position');
    const s = this.scale;
    const positions = new Float64Array(attribute.count * 3);
    for (let i = 0; i < attribute.count; i += 1) {
      positions[3 * i] = attribute.getX(i) * s.x;
      positions[3 * i + 1] = attribute.getY(i) * s.y;
      positions[3 * i + 2] = attribute.getZ(i) * s.z;
    }
    const index = this.geometry.getIndex();
    return index === null ? { kind: 'triangles', positions } : { kind: 'triangles', positions, indices: Array.from(index.array) };
  }
}
