/**
 * The per-dimension kernels behind the public rotor functions.
 *
 * `dims(n)` picks one implementation of this interface when it builds the tables of n
 * (quaternion closed forms for n = 3, 4D closed forms for n = 4, table-driven code otherwise),
 * so the choice is made once per dimension and never by a branch on every call.
 *
 * Kernels do not validate their arguments: they are the engine's hot path. The public
 * functions in `rotor.ts` validate and then call them.
 *
 * Storage conventions (shared with the whole library):
 * - vector: n numbers;
 * - bivector: k = n(n-1)/2 numbers, planes (i, j) with i < j in lexicographic order;
 *   a positive component turns e_i toward e_j;
 * - rotor: r = 2^(n-1) numbers, the even blades ordered by grade, then lexicographically
 *   (3D: [1, e01, e02, e12]; 4D: [1, e01, e02, e03, e12, e13, e23, e0123]);
 * - matrix: n*n numbers, row-major, `M[i * n + c]` = component i of the image of e_c.
 * A rotor acts by x' = R x R~; first R1 then R2 is R2 R1.
 */
export interface RotorKernels {
  /** Which implementation this is (e.g. 'generic', 'fast3', 'fast4'): for tests, benchmarks and logs only. */
  readonly name?: string;
  /** out = a b (geometric product of two even elements). `out` may alias `a` or `b`. */
  mul(out: Float64Array, a: Float64Array, b: Float64Array): Float64Array;
  /** out = R v R~ for a vector v. `out` may alias `v`. */
  applyVector(out: Float64Array, R: Float64Array, v: Float64Array): Float64Array;
  /** out = R~ v R (the inverse rotation) for a vector v. `out` may alias `v`. */
  applyVectorInverse(out: Float64Array, R: Float64Array, v: Float64Array): Float64Array;
  /** out = R B R~ for a bivector B (k components). `out` may alias `B`. */
  applyBivector(out: Float64Array, R: Float64Array, B: Float64Array): Float64Array;
  /** out = R~ B R for a bivector B. `out` may alias `B`. */
  applyBivectorInverse(out: Float64Array, R: Float64Array, B: Float64Array): Float64Array;
  /** out (n*n, row-major) = the rotation matrix of R. */
  toMatrix(out: Float64Array, R: Float64Array): Float64Array;
  /** out = exp(-scale * B / 2): the rotor that turns by the bivector B (angular velocity) over `scale` (time). */
  exp(out: Float64Array, B: Float64Array, scale: number): Float64Array;
  /** The defect ||R R~ - 1|| (largest absolute component): 0 for an exact rotor. */
  defect(R: Float64Array): number;
  /** out = the nearest exact rotor to R (see docs/nd-physics.md). `out` may alias `R`. */
  correct(out: Float64Array, R: Float64Array): Float64Array;
}
