import type { Dims } from '@physin/algebra';
import type { ShapeBounds } from '../collision/bounds.js';
import type { ColliderTable } from '../collision/manifold.js';

/** The kinds of shape the engine knows. */
export type ShapeKind = 'box' | 'sphere' | 'halfspace' | 'torus' | 'mesh' | 'capsule' | 'compound';

/**
 * Mass properties of a shape for a given mass, in the shape's own (principal) frame.
 *
 * Every shape is stored so that its centre of mass is at the local origin and its covariance
 * is diagonal: the inertia operator is then diagonal too, I_(ij) = C_ii + C_jj.
 */
export interface MassProperties {
  /** The n-volume of the shape (m^n). */
  readonly volume: number;
  /** The diagonal of the mass-weighted covariance C = ∫ x xᵀ dm about the centre of mass (n numbers, kg·m²). */
  readonly covariance: Float64Array;
  /** The diagonal inertia in the principal frame, k numbers (kg·m²): I_(ij) = C_ii + C_jj. */
  readonly inertia: Float64Array;
}

/**
 * A collision and mass shape. A shape is immutable once built and may be shared by bodies.
 *
 * `n` is the count of dimensions the shape was built for, or `null` for a shape that works in
 * any n (the ball), which takes the count of the world it is added to.
 */
export interface Shape {
  /** Which kind of shape this is. */
  readonly kind: ShapeKind;
  /** The count of dimensions, or null for a shape that fits any n (a ball). */
  readonly n: number | null;
  /**
   * Where the shape's own (principal) frame sits in the coordinates the shape was described in,
   * for shapes that were moved into a principal frame when built (convex meshes): the centre of
   * mass there (n numbers, m). A body placed at x with rotor R in the described coordinates puts
   * the shape at x + R·frameOffset. Absent: the frames coincide.
   */
  readonly frameOffset?: Float64Array;
  /**
   * The rotor (r numbers) taking the shape's own frame to the coordinates it was described in;
   * a body with rotor R uses R·frameRotor (first frameRotor, then R). Absent: identity.
   */
  readonly frameRotor?: Float64Array;
  /** Mass properties of this shape in `D`'s dimension for a total mass `mass` (kg, > 0). */
  massProperties(D: Dims, mass: number): MassProperties;
  /**
   * @internal The narrowphase pair colliders this shape's kind owns, keyed by the other shape's kind (see
   * collision/manifold.ts, ColliderTable). Absent: the kind owns no pair (a half-space: its pairs
   * live in the other shapes' tables).
   */
  readonly colliders?: ColliderTable;
  /**
   * @internal The world bounds of a posed shape of a kind the world does not bound itself (a torus,
   * mesh or capsule: see collision/bounds.ts, computeBoundsCommon). Absent for a box, a ball, a
   * half-space (bounded by the world) and a compound (its parts are).
   */
  readonly bounds?: ShapeBounds;
}
