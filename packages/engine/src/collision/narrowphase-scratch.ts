/**
 * Preallocated working memory and tolerances of the narrowphase, one object per dimension
 * (per world, or per thread). The pair functions write only into it and into their output
 * manifold, so a step allocates nothing. Not re-entrant: one pair at a time per scratch.
 *
 * @module
 */
import { checkNarrowphaseDimension, createManifold } from './manifold.js';
import type { Manifold, Pose } from './manifold.js';
import type { CollisionBox } from './narrowphase-shapes.js';
import { trainShapeAccessors } from './shape-kind.js';
import type { PolytopeScratch } from './convex-polytope.js';

/** Tolerances of the narrowphase. Every threshold the pair functions use is one of these. */
export interface NarrowphaseOptions {
  /**
   * Box–box SAT: a candidate axis built from n−1 box axes whose generalised cross product has
   * length below this is skipped (dimensionless: the length is the (n−1)-volume spanned by the
   * unit axes, the sine of the angle between two edges in 3D). Default 1e-6.
   */
  readonly axisTolerance?: number;
  /**
   * Box–box: an edge-type axis (p, q >= 1) is used only when its separation exceeds the best face
   * axis by more than this, and B's face is the reference only when it beats A's by more than this
   * (m). Keeps the choice coherent from step to step near ties. Also: the exact deepest point of a
   * torus on a half-space is added to its ring points only when the height of the core circle
   * varies by more than this round it (a tilted torus). Default 5e-4 (a tenth of the default
   * penetrationSlop).
   */
  readonly featureTieTolerance?: number;
  /**
   * Box–box clipping: relative tolerance (fraction of the larger box's largest half extent) for
   * the inside tests and for merging clip points that coincide. Default 1e-9.
   */
  readonly clipTolerance?: number;
  /** Torus–half-space: count of points spread round the core circle (integer 3..32). Default 8. */
  readonly torusRingPoints?: number;
}

/** Default of {@link NarrowphaseOptions.axisTolerance}. */
export const DEFAULT_AXIS_TOLERANCE = 1e-6;
/** Default of {@link NarrowphaseOptions.featureTieTolerance} (m). */
export const DEFAULT_FEATURE_TIE_TOLERANCE = 5e-4;
/** Default of {@link NarrowphaseOptions.clipTolerance}. */
export const DEFAULT_CLIP_TOLERANCE = 1e-9;
/** Default of {@link NarrowphaseOptions.torusRingPoints}. */
export const DEFAULT_TORUS_RING_POINTS = 8;

/**
 * Index in `scratch.scalars` of the speculative margin (m) of the pair being collided: the
 * hot-path entry point collideScratch (collide.ts) and the internal kernels read the margin from
 * there rather than from an argument (a double argument of a call that V8 does not inline is
 * boxed into a fresh heap number). Write it before each call:
 * `scratch.scalars[NARROWPHASE_MARGIN] = margin`.
 */
export const NARROWPHASE_MARGIN = 4;
/** Index in `scratch.scalars` of the axis tolerance read by the mixed SAT axis kernel. */
export const SCALAR_AXIS_TOLERANCE = 5;
/** Index in `scratch.scalars` of the separation handed to candidateSlot. */
export const SCALAR_CANDIDATE = 6;
/** Indices in `scratch.scalars` of the face clipper's z0, tolerance and σ tolerance. */
export const SCALAR_CLIP_Z0 = 7;
export const SCALAR_CLIP_EPS = 8;
export const SCALAR_CLIP_EPS_SIGMA = 9;
/** Indices in `scratch.scalars` of a torus ring point's cos φ, sin φ and height. */
export const SCALAR_RING_COS = 10;
export const SCALAR_RING_SIN = 11;
export const SCALAR_RING_HEIGHT = 12;
/** Length of `scratch.scalars`. */
export const SCALAR_COUNT = 16;

/** Which kind of axis the last box–box SAT chose. */
export const SAT_SEPARATED = 0;
/** A face axis of box A (its axis `axis`). */
export const SAT_FACE_A = 1;
/** A face axis of box B (its axis `axis`). */
export const SAT_FACE_B = 2;
/** An axis normal to p face directions of A and q of B, p, q >= 1 (3D: an edge pair). */
export const SAT_EDGE = 3;

/** The result of a box–box separating-axis test (see boxBoxSat). */
export interface SatResult {
  /** SAT_SEPARATED, SAT_FACE_A, SAT_FACE_B or SAT_EDGE. */
  kind: number;
  /** Separation along the chosen axis (m); > margin when kind is SAT_SEPARATED. */
  separation: number;
  /**
   * Face kinds: the box axis of the face. SAT_SEPARATED from the box–box tests: the separating
   * face's axis, i for A's face i, n + j for B's face j, −1 for a mixed axis.
   */
  axis: number;
  /** Edge kind: bitmask of A's axes spanning the normal's orthogonal complement (p bits). */
  maskA: number;
  /** Edge kind: bitmask of B's axes (q bits). */
  maskB: number;
  /** Unit normal of the chosen axis in world coordinates, from A to B (n numbers). */
  readonly normal: Float64Array;
  /** The same normal in A's local frame (n numbers). */
  readonly localNormal: Float64Array;
}

/**
 * A box–box separating-axis test with the margin read from `scratch.scalars[NARROWPHASE_MARGIN]`
 * (box-box-sat.ts has the contract): the general one for any n, or the 3D one alone.
 */
export type BoxBoxSatKernel = (
  n: number,
  a: CollisionBox,
  poseA: Pose,
  b: CollisionBox,
  poseB: Pose,
  scratch: NarrowphaseScratch,
) => boolean;

/** Working memory and tolerances of the narrowphase for one n. See {@link buildNarrowphaseScratch}. */
export interface NarrowphaseScratch {
  readonly n: number;
  readonly axisTolerance: number;
  readonly featureTieTolerance: number;
  readonly clipTolerance: number;
  readonly torusRingPoints: number;
  /** Raw contact candidates before reduction; replaced by a larger one when a mesh needs it. */
  candidates: Manifold;
  /** Per-candidate distances of the reduction (as long as `candidates.capacity`). */
  reduceDistance: Float64Array;
  /**
   * The box–box SAT that box–box contacts run. It comes with the scratch, not by import, so a 3D
   * world (the 3D entry's scratch has the 3D test alone) does not bundle the general one.
   */
  readonly boxBoxSat: BoxBoxSatKernel;
  /** Result of the last box–box SAT. */
  readonly sat: SatResult;
  /**
   * Numbers passed between the narrowphase kernels (kept out of arguments and return values,
   * which V8 boxes into fresh heap numbers when the call is not inlined): [0] separation and
   * [1] cross-product length of a mixed SAT axis, [2] plane height of a half-space, [3] squared
   * distance of a simplex closest point, then the slots named by the NARROWPHASE_* and SCALAR_*
   * constants ({@link NARROWPHASE_MARGIN}: the margin of the pair being collided).
   */
  readonly scalars: Float64Array;
  // box–box, in A's frame: C[i*n + j] = A's axis i · B's axis j; t = Mᵀ(x_B − x_A)
  readonly C: Float64Array;
  readonly absC: Float64Array;
  readonly t: Float64Array;
  /** Orthonormalised rows for the generalised cross product (n×n). */
  readonly rows: Float64Array;
  /** Complement coordinates of an axis subset. */
  readonly cols: Int32Array;
  /** Small dense systems: matrix (n×n), permutation, right-hand sides. */
  readonly mat: Float64Array;
  readonly piv: Int32Array;
  readonly rhs: Float64Array;
  readonly sol: Float64Array;
  /** Face clipping: incident half-edge vectors (n−1 of n numbers), tangent axes (n−1 of n). */
  readonly clipH: Float64Array;
  readonly clipU: Float64Array;
  readonly clipG: Float64Array;
  readonly clipY0: Float64Array;
  readonly clipGz: Float64Array;
  readonly clipHalf: Float64Array;
  readonly clipCentre: Float64Array;
  readonly clipRadius: Float64Array;
  readonly clipSigma: Float64Array;
  readonly clipFree: Int32Array;
  readonly clipFixed: Int32Array;
  /** Face clipping: factorised systems, one per Q-face mask (2^(n−1) slots of (n−1)² numbers). */
  readonly clipLu: Float64Array;
  readonly clipLuPiv: Int32Array;
  readonly clipLuState: Int8Array;
  // general vectors of n numbers
  readonly v0: Float64Array;
  readonly v1: Float64Array;
  readonly v2: Float64Array;
  readonly v3: Float64Array;
  readonly v4: Float64Array;
  /** Simplex closest point: vertices (up to n+1 of n), Gram matrix, barycentric coordinates. */
  readonly simplexVerts: Float64Array;
  readonly simplexBary: Float64Array;
  readonly simplexBest: Float64Array;
  readonly simplexIndex: Int32Array;
  readonly simplexGram: Float64Array;
  /**
   * Convex mesh–box and mesh–mesh (GJK, EPA, face clipping; convex-polytope.ts): made on the
   * first such pair and grown with the largest meshes seen, so a scene without them pays nothing.
   */
  polytope: PolytopeScratch | null;
}

/** Largest count of raw box–box clip candidates kept before reduction. */
export const MAX_CLIP_CANDIDATES = 1024;

/**
 * The count of candidate points the box–box clipper can produce in n dimensions: one per pair
 * (a-face of the incident face, (n−1−a)-face of the reference face), i.e. 2^(n−1)·C(2n−2, n−1),
 * capped at {@link MAX_CLIP_CANDIDATES}.
 */
export function clipCandidateBound(n: number): number {
  const d = n - 1;
  let binom = 1;
  for (let i = 1; i <= d; i += 1) binom = (binom * (d + i)) / i;
  return Math.min(MAX_CLIP_CANDIDATES, 2 ** d * Math.round(binom));
}

/**
 * Builds the narrowphase scratch for n dimensions with the given box–box SAT (the general one:
 * `createNarrowphaseScratch` of narrowphase-scratch-nd.ts). Allocates (a few kB; 1024·n numbers
 * of candidates at n >= 5); call once per world and dimension.
 *
 * @param boxBoxSat - the box–box SAT for n (see {@link NarrowphaseScratch.boxBoxSat}).
 * @param n - count of dimensions (2..8).
 * @param options - tolerances; see {@link NarrowphaseOptions}.
 * @throws TypeError for a non-integer n or a non-number option; RangeError for n out of range,
 *   a negative or non-finite tolerance, or a ring point count outside 3..32.
 */
export function buildNarrowphaseScratch(
  boxBoxSat: BoxBoxSatKernel,
  n: number,
  options: NarrowphaseOptions = {},
): NarrowphaseScratch {
  checkNarrowphaseDimension(n, 'n');
  if (typeof options !== 'object' || options === null) {
    throw new TypeError(
      `createNarrowphaseScratch: 'options' must be an object, got ${options === null ? 'null' : typeof options}`,
    );
  }
  const axisTolerance = readTolerance(options.axisTolerance, DEFAULT_AXIS_TOLERANCE, 'options.axisTolerance');
  const featureTieTolerance = readTolerance(
    options.featureTieTolerance,
    DEFAULT_FEATURE_TIE_TOLERANCE,
    'options.featureTieTolerance',
  );
  const clipTolerance = readTolerance(options.clipTolerance, DEFAULT_CLIP_TOLERANCE, 'options.clipTolerance');
  const ring = options.torusRingPoints ?? DEFAULT_TORUS_RING_POINTS;
  if (typeof ring !== 'number' || !Number.isInteger(ring)) {
    throw new TypeError(`createNarrowphaseScratch: 'options.torusRingPoints' must be an integer, got ${String(ring)}`);
  }
  if (ring < 3 || ring > 32) {
    throw new RangeError(`createNarrowphaseScratch: 'options.torusRingPoints' must be in 3..32, got ${ring}`);
  }
  return narrowphaseScratchOf(boxBoxSat, n, axisTolerance, featureTieTolerance, clipTolerance, ring);
}

/**
 * @internal {@link buildNarrowphaseScratch} with its tolerances given (as that function checks
 * them; the world gives its own, already valid): only n is checked.
 */
export function narrowphaseScratchOf(
  boxBoxSat: BoxBoxSatKernel,
  n: number,
  axisTolerance: number,
  featureTieTolerance: number,
  clipTolerance: number,
  ring: number,
): NarrowphaseScratch {
  checkNarrowphaseDimension(n, 'n');
  // keeps the hot path's shape reads megamorphic (see shape-kind.ts), in case V8 dropped them
  trainShapeAccessors();
  const d = n - 1;
  const m = n + 1;
  const candidateCapacity = Math.max(2 ** n, clipCandidateBound(n), ring + 1, 16);
  const vec = () => new Float64Array(n);
  return {
    n,
    axisTolerance,
    featureTieTolerance,
    clipTolerance,
    torusRingPoints: ring,
    boxBoxSat,
    candidates: createManifold(n, candidateCapacity),
    reduceDistance: new Float64Array(candidateCapacity),
    sat: {
      kind: SAT_SEPARATED,
      separation: 0,
      axis: -1,
      maskA: 0,
      maskB: 0,
      normal: vec(),
      localNormal: vec(),
    },
    scalars: new Float64Array(SCALAR_COUNT),
    C: new Float64Array(n * n),
    absC: new Float64Array(n * n),
    t: vec(),
    rows: new Float64Array(n * n),
    cols: new Int32Array(n),
    mat: new Float64Array(m * m),
    piv: new Int32Array(m),
    rhs: new Float64Array(m),
    sol: new Float64Array(m),
    clipH: new Float64Array(d * n),
    clipU: new Float64Array(d * n),
    clipG: new Float64Array(d * d),
    clipY0: new Float64Array(d),
    clipGz: new Float64Array(d),
    clipHalf: new Float64Array(d),
    clipCentre: new Float64Array(d),
    clipRadius: new Float64Array(d),
    clipSigma: new Float64Array(d),
    clipFree: new Int32Array(d),
    clipFixed: new Int32Array(d),
    clipLu: new Float64Array((1 << d) * d * d),
    clipLuPiv: new Int32Array((1 << d) * d),
    clipLuState: new Int8Array(1 << d),
    v0: vec(),
    v1: vec(),
    v2: vec(),
    v3: vec(),
    v4: vec(),
    simplexVerts: new Float64Array(m * n),
    simplexBary: new Float64Array(m),
    simplexBest: new Float64Array(m),
    simplexIndex: new Int32Array(m),
    simplexGram: new Float64Array(m * m),
    polytope: null,
  };
}

/**
 * Makes sure `scratch.candidates` can hold `count` points, replacing it by a larger buffer when
 * it cannot (the only allocation of the narrowphase, once per larger mesh seen). Returns it.
 */
export function ensureCandidateCapacity(scratch: NarrowphaseScratch, count: number): Manifold {
  if (scratch.candidates.capacity < count) {
    const capacity = Math.max(count, 2 * scratch.candidates.capacity);
    scratch.candidates = createManifold(scratch.n, capacity);
    scratch.reduceDistance = new Float64Array(capacity);
  }
  return scratch.candidates;
}

function readTolerance(value: unknown, fallback: number, name: string): number {
  if (value === undefined) return fallback;
  if (typeof value !== 'number') throw new TypeError(`createNarrowphaseScratch: '${name}' must be a number, got ${typeof value}`);
  if (!Number.isFinite(value) || value < 0) {
    throw new RangeError(`createNarrowphaseScratch: '${name}' must be finite and >= 0, got ${value}`);
  }
  return value;
}
