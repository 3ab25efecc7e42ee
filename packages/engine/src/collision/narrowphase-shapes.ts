/**
 * The geometry the narrowphase reads from each shape kind, as structural types: the engine's
 * shapes (HyperBox, HyperSphere, HalfSpace, HyperTorus, ConvexMesh) have these fields, and tests
 * or other callers may pass plain objects with the same fields. All lengths are in metres, in the
 * shape's own (local) frame.
 *
 * @module
 */

/** A solid box centred on its local origin: |local_c| <= halfExtents[c]. */
export interface CollisionBox {
  readonly kind: 'box';
  /** n half extents (m), each > 0. */
  readonly halfExtents: ArrayLike<number>;
}

/** A solid ball centred on its local origin. */
export interface CollisionSphere {
  readonly kind: 'sphere';
  /** Radius (m), > 0. */
  readonly radius: number;
}

/**
 * A solid half-space {local : normal·local <= offset}. `normal` points out of the solid; it need
 * not be unit length (the colliders divide by its length, and the plane is normal·x = offset).
 */
export interface CollisionHalfSpace {
  readonly kind: 'halfspace';
  /** n components of the outward normal (nonzero). */
  readonly normal: ArrayLike<number>;
  /** Plane offset: the boundary is normal·local = offset. */
  readonly offset: number;
}

/**
 * A solid n-torus: the points within `minorRadius` of the circle of radius `majorRadius` centred
 * on the local origin in the plane of local axes (planeI, planeJ).
 */
export interface CollisionTorus {
  readonly kind: 'torus';
  /** Radius R of the core circle (m), > minorRadius. */
  readonly majorRadius: number;
  /** Radius r of the tube (m), > 0. */
  readonly minorRadius: number;
  /** First axis of the core plane. */
  readonly planeI: number;
  /** Second axis of the core plane (≠ planeI). */
  readonly planeJ: number;
}

/**
 * A convex polytope given by its vertices and boundary facets ((n−1)-simplices of n vertex
 * indices each), with the facet planes: the solid is {x : facetNormals[f]·x <= facetOffsets[f]}.
 */
export interface CollisionMesh {
  readonly kind: 'mesh';
  /** Vertices, flat, n numbers each (m, local frame). */
  readonly vertices: ArrayLike<number>;
  /** Facets, flat, n vertex indices each. */
  readonly facets: ArrayLike<number>;
  /** Unit outward facet normals, flat, n numbers each. */
  readonly facetNormals: ArrayLike<number>;
  /** Facet plane offsets (m), one per facet. */
  readonly facetOffsets: ArrayLike<number>;
}

/**
 * A solid capsule: the points within `radius` of the segment from −halfHeight·e₁ to
 * +halfHeight·e₁ (local axis 1, "y", as three.js's CapsuleGeometry and Rapier's capsule).
 */
export interface CollisionCapsule {
  readonly kind: 'capsule';
  /** Half the length of the core segment (m), > 0. */
  readonly halfHeight: number;
  /** Radius of the ball swept along the segment (m), > 0. */
  readonly radius: number;
}
