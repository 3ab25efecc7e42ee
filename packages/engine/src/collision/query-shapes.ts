/**
 * The geometry the spatial queries (bounds, broadphase, ray casts) read from a shape.
 *
 * These are structural views: the shape classes in `../shapes/` satisfy them by having these
 * fields, so the queries depend on no shape class and no body. Every length is in metres, in
 * the shape's own (local, principal) frame. A pose (x, M) places the local frame in the world:
 * world = x + M·local, with M an n×n row-major rotation, `M[i*n + c]` = component i of the image
 * of local axis c.
 */

/** A hyperbox centred on its local origin: |local_c| <= halfExtents[c] for every axis c. */
export interface BoxGeometry {
  readonly kind: 'box';
  /** n half extents (m), each > 0. */
  readonly halfExtents: ArrayLike<number>;
}

/** A solid n-ball centred on its local origin. */
export interface SphereGeometry {
  readonly kind: 'sphere';
  /** Radius (m), > 0. */
  readonly radius: number;
}

/**
 * A half-space: the solid side is { local : normal·local <= offset }. `normal` need not be unit
 * length; the queries divide by its norm. It is infinite, so the broadphase keeps it aside.
 */
export interface HalfSpaceGeometry {
  readonly kind: 'halfspace';
  /** n components of the outward normal in the local frame (nonzero). */
  readonly normal: ArrayLike<number>;
  /** Offset (m, times |normal|) of the boundary plane along the normal. */
  readonly offset: number;
}

/**
 * A solid n-torus: the points within `minorRadius` of the circle of radius `majorRadius` centred
 * on the local origin in the plane of local axes (planeI, planeJ):
 * (√(x_i² + x_j²) − R)² + Σ_{k ∉ {i,j}} x_k² <= r².
 */
export interface TorusGeometry {
  readonly kind: 'torus';
  /** Radius R of the core circle (m), > minorRadius. */
  readonly majorRadius: number;
  /** Radius r of the tube (m), > 0. */
  readonly minorRadius: number;
  /** First axis of the core circle's plane (0 <= planeI < n). */
  readonly planeI: number;
  /** Second axis of the core circle's plane (0 <= planeJ < n, planeJ != planeI). */
  readonly planeJ: number;
}

/**
 * A convex polytope. The solid is the intersection of the facet half-spaces
 * { local : facetNormals[f]·local <= facetOffsets[f] }; its vertices are the corners.
 */
export interface ConvexMeshGeometry {
  readonly kind: 'mesh';
  /** Vertices, flat: vertex v is vertices[v*n .. v*n + n) (m, local frame). */
  readonly vertices: ArrayLike<number>;
  /** Outward facet normals, flat: facet f is facetNormals[f*n .. f*n + n) (unit length expected). */
  readonly facetNormals: ArrayLike<number>;
  /** Facet plane offsets (m): facet f's plane is facetNormals[f]·local = facetOffsets[f]. */
  readonly facetOffsets: ArrayLike<number>;
}

/**
 * A solid capsule: the points within `radius` of the segment from −halfHeight·e₁ to
 * +halfHeight·e₁ (local axis 1).
 */
export interface CapsuleGeometry {
  readonly kind: 'capsule';
  /** Half the length of the core segment (m), > 0. */
  readonly halfHeight: number;
  /** Radius (m), > 0. */
  readonly radius: number;
}

/** Every shape geometry the spatial queries understand. */
export type QueryShape = BoxGeometry | SphereGeometry | HalfSpaceGeometry | TorusGeometry | ConvexMeshGeometry | CapsuleGeometry;
