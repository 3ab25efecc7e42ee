/**
 * Reuse of the manifolds of polytope pairs (box–box, convex mesh–box, convex mesh–mesh) while the
 * two shapes have hardly moved relative to each other.
 *
 * Why: in a resting stack or pyramid, the separating-axis test and the face clipper find the same
 * faces and corners sub-step after sub-step, and they are the costliest part of the narrowphase
 * (a quarter of a resting pyramid's step in 3D, more in 4D). The manifold depends only on the
 * pose of B relative to A, so while that pose stays within a small tolerance of the one the
 * manifold was computed at, its points are carried along with the bodies instead: each point's
 * two surface points are kept in the local frames of A and B, the normal in A's frame, and a
 * reused manifold takes them to world space again and measures the separation along the normal
 * afresh. The feature ids (and with them the warm-start impulses) stay. Jolt's body pair cache
 * does the same; the test here bounds the motion of B's surface rather than of its centre.
 * Convex mesh pairs pay more for a fresh manifold than box pairs (GJK, EPA and face clipping:
 * mesh-polytope.ts), so a settled pile of meshes gains most.
 *
 * The tolerance (`Params.manifoldReuseTolerance`, m) bounds how far any point of B can have moved
 * relative to A since the manifold was computed: |Δx| + ‖ΔR‖_F·ρ_B, with Δx and ΔR the change of
 * B's position and rotation in A's frame and ρ_B the radius of B (‖ΔR‖₂ <= ‖ΔR‖_F). 0 computes
 * every manifold every sub-step.
 *
 * Allocates only when the slot arrays grow.
 *
 * @module
 */
import type { Manifold, Pose } from '../collision/manifold.js';
import { pointToLocal } from '../collision/manifold.js';
import { SAT_SEPARATED } from '../collision/narrowphase-scratch.js';
import type { SatResult } from '../collision/narrowphase-scratch.js';
import { growFloat64 } from './grow.js';

/** ManifoldCache.check: compute the manifold afresh. */
export const CACHE_MISS = 0;
/** ManifoldCache.check: reuse the cached manifold. */
export const CACHE_REUSE = 1;
/**
 * ManifoldCache.check: the box pair is still apart by its kept separation (the narrowphase would
 * give an empty manifold). Also ManifoldCache.valid's mark of a slot that keeps one (storeApart).
 */
export const CACHE_APART = 2;

/** The cached manifolds of a contact set's slots (n dimensions, `P` points per slot). */
export class ManifoldCache {
  protected readonly n: number;
  protected readonly P: number;
  /**
   * Per slot: 1 when it holds a cached manifold; CACHE_APART when it holds a box pair's separation
   * instead (see {@link ManifoldCache.storeApart}); 0 when nothing.
   */
  private valid = new Uint8Array(16);
  /**
   * Per slot, side by side (`S` numbers; a check and a reuse then read adjacent cache lines, where
   * three arrays cost a miss each in a pile): B's position (n) and rotation (n×n) in A's frame
   * when the manifold was computed; at `NO` the normal in A's frame (n); at `LO`, per point, the
   * surface point on A in A's frame, then the one on B in B's frame (2n).
   */
  protected data: Float64Array;
  /** Numbers per slot of `data`. */
  protected readonly S: number;
  /** Where the normal starts in a slot of `data`. */
  protected readonly NO: number;
  /** Where the surface points start in a slot of `data`. */
  protected readonly LO: number;
  /** The relative pose of the pair last checked (kept for `store`). */
  private readonly now: Float64Array;
  private readonly world: Float64Array;

  constructor(n: number, pointsPerSlot: number) {
    this.n = n;
    this.P = pointsPerSlot;
    this.NO = n + n * n;
    this.LO = this.NO + n;
    this.S = this.LO + pointsPerSlot * 2 * n;
    this.data = new Float64Array(16 * this.S);
    this.now = new Float64Array(n + n * n);
    this.world = new Float64Array(2 * n);
  }

  /** Makes room for `capacity` slots (new slots hold nothing). */
  ensureSlots(capacity: number): void {
    if (capacity <= this.valid.length) return;
    const valid = new Uint8Array(capacity);
    valid.set(this.valid);
    this.valid = valid;
    this.data = growFloat64(this.data, capacity * this.S);
  }

  /** @internal Whether the slot holds a cached manifold (for world snapshots). */
  isValid(slot: number): boolean {
    return this.valid[slot] === 1;
  }

  /**
   * @internal Views of the slot's cached data, for world snapshots: B's pose in A's frame
   * (n + n² numbers), the normal in A's frame (n) and the surface points (2n per point, P points).
   */
  slotViews(slot: number): { pose: Float64Array; normal: Float64Array; local: Float64Array } {
    const base = slot * this.S;
    return {
      pose: this.data.subarray(base, base + this.NO),
      normal: this.data.subarray(base + this.NO, base + this.LO),
      local: this.data.subarray(base + this.LO, base + this.S),
    };
  }

  /** @internal Marks the slot's cache as holding a manifold (its views written first), for snapshots. */
  markValid(slot: number): void {
    this.valid[slot] = 1;
  }

  /** Drops the cached manifold of a slot. */
  forget(slot: number): void {
    this.valid[slot] = 0;
  }

  /**
   * Reads B's pose relative to A (kept for {@link ManifoldCache.store}) and returns what the
   * slot's cache allows: CACHE_REUSE when its manifold may be reused (no point of B, within
   * `numbers[1]` of its pose origin, has moved more than `numbers[0]` relative to A since it was
   * computed), CACHE_APART when its box pair is still apart by the kept separation (see
   * `stillApart`), else CACHE_MISS. (The numbers come in an array: a double argument of a call
   * V8 does not inline would be boxed.)
   */
  check(slot: number, poseA: Pose, poseB: Pose, numbers: Float64Array): number {
    const n = this.n;
    const now = this.now;
    const MA = poseA.M;
    const MB = poseB.M;
    // x_rel = M_Aᵀ (x_B − x_A) (into now[0, n)), R_rel = M_Aᵀ M_B
    if (n === 3) relativePose3(now, MA, MB, poseA.x, poseB.x);
    else pointToLocal(now, n, poseA, poseB.x);
    for (let r = 0; r < n && n !== 3; r += 1) {
      for (let c = 0; c < n; c += 1) {
        let s = 0;
        for (let i = 0; i < n; i += 1) s += MA[i * n + r] * MB[i * n + c];
        now[n + r * n + c] = s;
      }
    }
    const valid = this.valid[slot];
    if (valid === 0) return CACHE_MISS;
    const base = slot * this.S;
    const cached = this.data;
    if (valid === CACHE_APART) return this.stillApart(base, numbers) ? CACHE_APART : CACHE_MISS;
    let dx2 = 0;
    for (let c = 0; c < n; c += 1) {
      const d = now[c] - cached[base + c];
      dx2 += d * d;
    }
    let dr2 = 0;
    for (let e = n; e < n + n * n; e += 1) {
      const d = now[e] - cached[base + e];
      dr2 += d * d;
    }
    // NaN compares false: a non-finite pose is never served from the cache.
    return Math.sqrt(dx2) + Math.sqrt(dr2) * numbers[1] <= numbers[0] ? CACHE_REUSE : CACHE_MISS;
  }

  /**
   * Caches manifold `m` of the slot, computed at the poses given (the relative pose is the one
   * the last {@link ManifoldCache.check} of this pair read). An empty manifold is not cached.
   */
  store(slot: number, m: Manifold, poseA: Pose, poseB: Pose): void {
    const n = this.n;
    const count = m.count;
    if (count === 0) {
      this.valid[slot] = 0;
      return;
    }
    const data = this.data;
    const base = slot * this.S;
    for (let e = 0; e < n + n * n; e += 1) data[base + e] = this.now[e];
    const N = m.normal;
    const MA = poseA.M;
    const MB = poseB.M;
    const xA = poseA.x;
    const xB = poseB.x;
    for (let c = 0; c < n; c += 1) {
      let s = 0;
      for (let i = 0; i < n; i += 1) s += MA[i * n + c] * N[i];
      data[base + this.NO + c] = s;
    }
    const world = this.world;
    for (let p = 0; p < count; p += 1) {
      const half = 0.5 * m.separations[p];
      // The two surface points: the manifold point lies midway between them along the normal.
      for (let i = 0; i < n; i += 1) {
        const q = m.points[p * n + i];
        world[i] = q - half * N[i] - xA[i];
        world[n + i] = q + half * N[i] - xB[i];
      }
      const o = base + this.LO + p * 2 * n;
      for (let c = 0; c < n; c += 1) {
        let sa = 0;
        let sb = 0;
        for (let i = 0; i < n; i += 1) {
          sa += MA[i * n + c] * world[i];
          sb += MB[i * n + c] * world[n + i];
        }
        data[o + c] = sa;
        data[o + n + c] = sb;
      }
    }
    this.valid[slot] = 1;
  }

  /**
   * Keeps, for a box pair the separating-axis test found apart by more than the margin (its
   * manifold empty), the face it found and the separation (`sat`, as the box–box tests leave it),
   * with the relative pose the last {@link ManifoldCache.check} read. A mixed axis is not kept.
   */
  storeApart(slot: number, sat: SatResult): void {
    const face = sat.axis;
    if (sat.kind !== SAT_SEPARATED || face < 0) {
      this.valid[slot] = 0;
      return;
    }
    const n = this.n;
    const data = this.data;
    const base = slot * this.S;
    for (let e = 0; e < n + n * n; e += 1) data[base + e] = this.now[e];
    data[base + this.NO] = sat.separation;
    data[base + this.NO + 1] = face;
    this.valid[slot] = CACHE_APART;
  }

  /**
   * Whether the box pair kept by storeApart is still apart by more than the margin: along the face
   * axis it was found on, the separation falls at most by how far the other box's points moved in
   * that box's frame since, |Δx| + ‖ΔR‖·ρ_B for A's face, |Δx| + ‖ΔR‖·(ρ_A + |x|) for B's (x, R:
   * B's pose in A's frame; ‖·‖ the Frobenius norm, above the spectral one). The separating-axis
   * test visits the face axes first and stops at the first that separates, so it would find the
   * pair apart again: the narrowphase would give the same empty manifold. `numbers`: [reuse
   * tolerance, ρ_B, ρ_A, margin]. The slack of 1e-9 of the scale covers the rounding.
   */
  private stillApart(base: number, numbers: Float64Array): boolean {
    const n = this.n;
    const now = this.now;
    const data = this.data;
    let dx2 = 0;
    let x2 = 0;
    for (let c = 0; c < n; c += 1) {
      const d = now[c] - data[base + c];
      dx2 += d * d;
      x2 += now[c] * now[c];
    }
    let dr2 = 0;
    for (let e = n; e < n + n * n; e += 1) {
      const d = now[e] - data[base + e];
      dr2 += d * d;
    }
    const separation = data[base + this.NO];
    const x = Math.sqrt(x2);
    const arm = data[base + this.NO + 1] < n ? numbers[1] : numbers[2] + x;
    const slack = 1e-9 * (Math.abs(separation) + x + numbers[1] + numbers[2]);
    // NaN compares false: a non-finite pose runs the narrowphase.
    return separation - Math.sqrt(dx2) - Math.sqrt(dr2) * arm - slack > numbers[3];
  }

  /**
   * Writes the slot's cached manifold into `m` at the current poses: the normal turned with A,
   * each point midway between its two surface points, the separation measured along the normal.
   * The count and the ids are those `m` already holds (the manifold the cache was stored from).
   */
  reuse(slot: number, m: Manifold, poseA: Pose, poseB: Pose): void {
    const n = this.n;
    const data = this.data;
    const base = slot * this.S;
    if (n === 3) {
      reuse3(m, poseA, poseB, data, base + this.NO, base + this.LO);
      return;
    }
    const N = m.normal;
    const MA = poseA.M;
    const MB = poseB.M;
    const xA = poseA.x;
    const xB = poseB.x;
    for (let i = 0; i < n; i += 1) {
      let s = 0;
      for (let c = 0; c < n; c += 1) s += MA[i * n + c] * data[base + this.NO + c];
      N[i] = s;
    }
    const local = data;
    const world = this.world;
    for (let p = 0; p < m.count; p += 1) {
      const o = base + this.LO + p * 2 * n;
      for (let i = 0; i < n; i += 1) {
        let sa = xA[i];
        let sb = xB[i];
        for (let c = 0; c < n; c += 1) {
          sa += MA[i * n + c] * local[o + c];
          sb += MB[i * n + c] * local[o + n + c];
        }
        world[i] = sa;
        world[n + i] = sb;
      }
      let s = 0;
      for (let i = 0; i < n; i += 1) {
        s += (world[n + i] - world[i]) * N[i];
        m.points[p * n + i] = 0.5 * (world[i] + world[n + i]);
      }
      m.separations[p] = s;
    }
  }
}

/**
 * {@link ManifoldCache.check}'s relative pose for n = 3, written out: x_rel = M_Aᵀ (x_B − x_A)
 * into now[0, 3), R_rel = M_Aᵀ M_B into now[3, 12). The same sums in the same order as the
 * general loops (each from 0), so bit-identical; the pairs of a 3D pile check thousands a step.
 */
function relativePose3(now: Float64Array, MA: Float64Array, MB: Float64Array, xA: Float64Array, xB: Float64Array): void {
  const d0 = xB[0] - xA[0];
  const d1 = xB[1] - xA[1];
  const d2 = xB[2] - xA[2];
  for (let r = 0; r < 3; r += 1) {
    const a0 = MA[r];
    const a1 = MA[3 + r];
    const a2 = MA[6 + r];
    now[r] = 0 + a0 * d0 + a1 * d1 + a2 * d2;
    for (let c = 0; c < 3; c += 1) now[3 + 3 * r + c] = 0 + a0 * MB[c] + a1 * MB[3 + c] + a2 * MB[6 + c];
  }
}

/**
 * {@link ManifoldCache.reuse} for n = 3, written out (the same sums in the same order as the
 * general loops, so bit-identical). `c`: the slot's normal at `data[c]`; `o`: its points at `data[o]`.
 */
function reuse3(m: Manifold, poseA: Pose, poseB: Pose, data: Float64Array, c: number, o: number): void {
  const normal = data;
  const local = data;
  const N = m.normal;
  const A = poseA.M;
  const B = poseB.M;
  const xA = poseA.x;
  const xB = poseB.x;
  const pts = m.points;
  for (let i = 0; i < 3; i += 1) N[i] = 0 + A[3 * i] * normal[c] + A[3 * i + 1] * normal[c + 1] + A[3 * i + 2] * normal[c + 2];
  for (let p = 0, q = o; p < m.count; p += 1, q += 6) {
    let s = 0;
    for (let i = 0, r = 0; i < 3; i += 1, r += 3) {
      const wa = xA[i] + A[r] * local[q] + A[r + 1] * local[q + 1] + A[r + 2] * local[q + 2];
      const wb = xB[i] + B[r] * local[q + 3] + B[r + 1] * local[q + 4] + B[r + 2] * local[q + 5];
      s += (wb - wa) * N[i];
      pts[p * 3 + i] = 0.5 * (wa + wb);
    }
    m.separations[p] = s;
  }
}
