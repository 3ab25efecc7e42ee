import { matrixToRotor, rotorReverse } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { ROTOR_INPUT_TOLERANCE } from '../params.js';
import { registerShapeFactory } from '../snapshot/registry.js';
import { checkDims, checkVector } from './checks.js';
import { compoundWorldOps } from './compound-world.js';
import type { CompoundWorldOps } from './compound-world.js';
import { checkComponents, inputLimits } from './limits.js';
import { checkMassArguments, diagonalMassProperties } from './mass-properties.js';
import { principalFrame } from './principal-frame.js';
import type { MassProperties, Shape } from './shape.js';

/** Most parts a compound may hold. */
export const MAX_COMPOUND_PARTS = 4096;

/** One part of a {@link Compound} as given: a shape placed at an offset and turned by a rotor. */
export interface CompoundPart {
  /** The part's shape: any shape of the engine but a half-space or another compound. */
  readonly shape: Shape;
  /**
   * Where the origin of the coordinates the part's shape was described in sits in the compound's
   * coordinates (n numbers, m); default the origin.
   */
  readonly position?: ArrayLike<number>;
  /** The part's orientation in the compound's coordinates (a unit rotor, r numbers); default identity. */
  readonly rotor?: ArrayLike<number>;
}

/**
 * A body of several shapes: each part keeps its own shape (and its own collision pairs), placed
 * rigidly in the compound's own frame. The compound has no geometry of its own: the world gives
 * each part a broadphase proxy and collides part with part (docs/collision.md, "Compound bodies").
 *
 * It is stored in its principal frame, as a convex mesh is: the centre of mass of all the parts
 * (one density: each part's mass is proportional to its volume) at the local origin and the
 * summed covariance diagonal. `frameOffset` and `frameRotor` say where that frame sits in the
 * coordinates the parts were given in, so a body placed at x with rotor R (in those coordinates)
 * puts part i where the user expects: at x + R·position_i, turned by R·rotor_i.
 */
export interface CompoundShape extends Shape {
  readonly kind: 'compound';
  readonly n: number;
  /** The parts' shapes, in the order given (a frozen array). */
  readonly parts: readonly Shape[];
  /** Count of parts. */
  readonly partCount: number;
  /**
   * Per part, n numbers: where the part shape's own (principal) origin sits in the compound's
   * principal frame (m). Read only.
   */
  readonly partOffsets: Float64Array;
  /**
   * Per part, n×n numbers (row-major): the rotation from the part shape's own frame to the
   * compound's principal frame, the matrix of `partRotors`. Read only.
   */
  readonly partRotations: Float64Array;
  /** Per part, r numbers: the rotor of `partRotations`. Read only. */
  readonly partRotors: Float64Array;
  /** The centre of mass in the coordinates the parts were given in (n numbers, m). Read only. */
  readonly frameOffset: Float64Array;
  /** The rotor taking the principal frame to the coordinates the parts were given in (r numbers). Read only. */
  readonly frameRotor: Float64Array;
  /** The summed n-volume of the parts (m^n; overlaps count twice). */
  readonly volume: number;
  /** The largest distance of a point of any part from the centre of mass (m). */
  readonly boundingRadius: number;
  /** @internal What a world does with a compound body (part poses and proxies; compound-world.ts). */
  readonly worldOps: CompoundWorldOps;
}

const PART_KEYS = new Set(['shape', 'position', 'rotor']);

function describe(value: unknown): string {
  if (value === null) return 'null';
  if (Array.isArray(value)) return `an array of length ${value.length}`;
  return typeof value;
}

/** The largest distance of a point of `shape` from its own origin (m). */
function partRadius(n: number, shape: Shape): number {
  const g = shape as unknown as Record<string, unknown>;
  switch (shape.kind) {
    case 'box': {
      const a = g.halfExtents as Float64Array;
      let s = 0;
      for (let i = 0; i < n; i += 1) s += a[i]! * a[i]!;
      return Math.sqrt(s);
    }
    case 'sphere':
      return g.radius as number;
    case 'torus':
      return (g.majorRadius as number) + (g.minorRadius as number);
    case 'capsule':
      return (g.halfHeight as number) + (g.radius as number);
    case 'mesh': {
      const v = g.vertices as Float64Array;
      let best = 0;
      for (let o = 0; o < v.length; o += n) {
        let s = 0;
        for (let i = 0; i < n; i += 1) s += v[o + i]! * v[o + i]!;
        if (s > best) best = s;
      }
      return Math.sqrt(best);
    }
    default:
      throw new RangeError(`Compound: a part of kind '${String(shape.kind)}' is not supported`);
  }
}

/**
 * Builds a compound shape: one rigid body of several shapes at offsets and rotors, in the n
 * dimensions of `D` (2..8).
 *
 * Mass properties: with one density ρ = m / Σ V_i, part i has mass m_i = m V_i / Σ V_j; the centre
 * of mass is g = Σ m_i c_i / m (c_i the part's centre), and the covariance about it is
 * C = Σ m_i (Q_i diag(C_i) Q_iᵀ + (c_i − g)(c_i − g)ᵀ) (the parallel axis theorem, with Q_i the
 * part's rotation and C_i its own principal covariance per unit mass); its principal frame
 * (shapes/principal-frame.ts) is the compound's frame, and the inertia is diagonal there.
 * Overlapping parts count their common volume twice.
 *
 * @param D - the dimensions (from `dims(n)`).
 * @param parts - at least one part, each `{ shape, position?, rotor? }` (see {@link CompoundPart}).
 * @throws TypeError when `D` is not a Dims, `parts` is not an array, a part is not an object, its
 *   shape is not a shape, or a position or rotor has the wrong length or type; RangeError for an
 *   empty list, a half-space or compound part, a shape built for another n, a non-finite or too
 *   large position, or a rotor that is not a unit rotor. Every message names the argument.
 */
export function Compound(D: Dims, parts: readonly CompoundPart[]): CompoundShape {
  const where = 'Compound';
  const checked = checkDims(where, D);
  const { n, r } = checked;
  if (!Array.isArray(parts)) {
    throw new TypeError(`${where}: argument 'parts' must be an array of { shape, position?, rotor? }, got ${describe(parts)}`);
  }
  const count = parts.length;
  if (count === 0) throw new RangeError(`${where}: argument 'parts' must hold at least one part, got an empty array`);
  if (count > MAX_COMPOUND_PARTS) {
    throw new RangeError(`${where}: argument 'parts' may hold at most ${MAX_COMPOUND_PARTS} parts, got ${count}`);
  }
  const K = checked.kernels;
  const shapes: Shape[] = [];
  /** Per part: its centre (n) and rotor (r) in the given coordinates. */
  const centres = new Float64Array(count * n);
  const rotors = new Float64Array(count * r);
  const volumes = new Float64Array(count);
  const covariances = new Float64Array(count * n);
  const rotor = new Float64Array(r);
  const frame = new Float64Array(r);
  const shifted = new Float64Array(n);
  for (let i = 0; i < count; i += 1) {
    const name = `parts[${i}]`;
    const part = parts[i] as unknown;
    if (typeof part !== 'object' || part === null || Array.isArray(part)) {
      throw new TypeError(`${where}: argument '${name}' must be an object { shape, position?, rotor? }, got ${describe(part)}`);
    }
    for (const key of Object.keys(part)) {
      if (!PART_KEYS.has(key))
        throw new RangeError(`${where}: argument '${name}' has the unknown key '${key}' (known: shape, position, rotor)`);
    }
    const { shape, position, rotor: given } = part as CompoundPart;
    if (
      typeof shape !== 'object' ||
      shape === null ||
      typeof (shape as { kind?: unknown }).kind !== 'string' ||
      typeof (shape as { massProperties?: unknown }).massProperties !== 'function'
    ) {
      throw new TypeError(
        `${where}: argument '${name}.shape' must be a shape (HyperBox, HyperSphere, ...), got ${describe(shape)}`,
      );
    }
    if (shape.kind === 'halfspace') {
      throw new RangeError(`${where}: argument '${name}.shape' is a half-space, which has no finite mass and cannot be a part`);
    }
    if (shape.kind === 'compound') {
      throw new RangeError(`${where}: argument '${name}.shape' is a compound; compounds do not nest (give its parts instead)`);
    }
    if (shape.n !== null && shape.n !== n) {
      throw new RangeError(`${where}: argument '${name}.shape' was built for n = ${shape.n} but argument 'D' has n = ${n}`);
    }
    const p = position === undefined ? new Float64Array(n) : checkVector(where, position, `${name}.position`, n);
    if (position !== undefined) checkComponents(where, `argument '${name}.position'`, p, inputLimits.maxPosition, 'm');
    if (given === undefined) {
      rotor.fill(0);
      rotor[0] = 1;
    } else {
      rotor.set(checkVector(where, given, `${name}.rotor`, r));
      const defect = K.defect(rotor);
      if (!(defect <= ROTOR_INPUT_TOLERANCE)) {
        throw new RangeError(
          `${where}: argument '${name}.rotor' must be a unit rotor (defect |R R~ - 1| <= ${ROTOR_INPUT_TOLERANCE}), got defect ${defect}`,
        );
      }
    }
    // The part shape's own frame: its centre at position + rotor·frameOffset, turned by rotor·frameRotor.
    if (shape.frameOffset !== undefined) {
      K.applyVector(shifted, rotor, Float64Array.from(shape.frameOffset));
      for (let c = 0; c < n; c += 1) p[c] = p[c]! + shifted[c]!;
    }
    if (shape.frameRotor !== undefined) {
      frame.set(shape.frameRotor);
      K.mul(rotor, Float64Array.from(rotor), frame);
    }
    const mp = shape.massProperties(checked, 1);
    shapes.push(shape);
    centres.set(p, i * n);
    rotors.set(rotor, i * r);
    volumes[i] = mp.volume;
    covariances.set(mp.covariance, i * n);
  }

  // Centre of mass and covariance per unit mass of the whole, in the given coordinates.
  let volume = 0;
  for (let i = 0; i < count; i += 1) volume += volumes[i]!;
  if (!(volume > 0 && volume < Infinity))
    throw new RangeError(`${where}: the parts' summed volume is ${volume}: too small or too large`);
  const g = new Float64Array(n);
  for (let i = 0; i < count; i += 1) {
    const w = volumes[i]! / volume;
    for (let c = 0; c < n; c += 1) g[c] = g[c]! + w * centres[i * n + c]!;
  }
  const C = new Float64Array(n * n);
  const Qi = new Float64Array(n * n);
  const d = new Float64Array(n);
  for (let i = 0; i < count; i += 1) {
    const w = volumes[i]! / volume;
    K.toMatrix(Qi, rotors.subarray(i * r, i * r + r));
    for (let c = 0; c < n; c += 1) d[c] = centres[i * n + c]! - g[c]!;
    for (let a = 0; a < n; a += 1) {
      for (let b = 0; b < n; b += 1) {
        // Q diag(C_i) Qᵀ: Σ_c Q[a][c] C_c Q[b][c]
        let s = 0;
        for (let c = 0; c < n; c += 1) s += Qi[a * n + c]! * covariances[i * n + c]! * Qi[b * n + c]!;
        C[a * n + b] = C[a * n + b]! + w * (s + d[a]! * d[b]!);
      }
    }
  }
  const Q = new Float64Array(n * n);
  const unitCovariance = new Float64Array(n);
  principalFrame(n, Q, unitCovariance, C);
  const frameRotor = matrixToRotor(checked, new Float64Array(r), Q);
  // The frame's matrix from its rotor, so parts, offsets and rotor agree to the last bit.
  K.toMatrix(Q, frameRotor);
  const inverse = rotorReverse(checked, new Float64Array(r), frameRotor);

  const partOffsets = new Float64Array(count * n);
  const partRotors = new Float64Array(count * r);
  const partRotations = new Float64Array(count * n * n);
  let boundingRadius = 0;
  for (let i = 0; i < count; i += 1) {
    for (let c = 0; c < n; c += 1) d[c] = centres[i * n + c]! - g[c]!;
    // offset = Qᵀ (c_i − g)
    for (let c = 0; c < n; c += 1) {
      let s = 0;
      for (let a = 0; a < n; a += 1) s += Q[a * n + c]! * d[a]!;
      partOffsets[i * n + c] = s;
    }
    const local = partRotors.subarray(i * r, i * r + r);
    K.mul(local, inverse, rotors.slice(i * r, i * r + r));
    const norm = Math.sqrt(local.reduce((s, x) => s + x * x, 0));
    for (let c = 0; c < r; c += 1) local[c] = local[c]! / norm;
    K.toMatrix(partRotations.subarray(i * n * n, (i + 1) * n * n), local);
    let o2 = 0;
    for (let c = 0; c < n; c += 1) o2 += partOffsets[i * n + c]! ** 2;
    boundingRadius = Math.max(boundingRadius, Math.sqrt(o2) + partRadius(n, shapes[i]!));
  }
  return Object.freeze({
    kind: 'compound' as const,
    n,
    parts: Object.freeze(shapes),
    partCount: count,
    partOffsets,
    partRotations,
    partRotors,
    frameOffset: g,
    frameRotor,
    volume,
    boundingRadius,
    worldOps: compoundWorldOps,
    massProperties(Dm: Dims, mass: number): MassProperties {
      const c = checkMassArguments('Compound.massProperties', Dm, mass, n);
      return diagonalMassProperties(c, volume, unitCovariance, mass);
    },
  });
}

// World snapshots rebuild saved compounds with this factory (snapshot/registry.ts).
registerShapeFactory('compound', Compound);
