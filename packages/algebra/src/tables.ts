/**
 * The tables of one dimension n: sizes, the plane order of bivectors, the blade order of rotors,
 * the product table of the even sub-algebra, and the cache that makes them one object per n.
 *
 * Which rotor kernels a dimension gets is chosen by the caller of {@link tablesWith}: `dims(n)`
 * (every dimension, dims.ts) or `dims3()` / `dims4()` (one dimension, dims-fixed.ts). Kept apart
 * so that a program that imports only `dims3` carries only the 3D kernels in its bundle.
 */
import type { RotorKernels } from './kernels/types.js';

/** Smallest supported dimension. */
export const MIN_DIMENSION = 2;
/** Largest supported dimension (a rotor then has 128 components and a product costs 16384 multiply-adds). */
export const MAX_DIMENSION = 8;

/**
 * The tables of dimension n (see `dims`). All arrays are owned by the library: read them, never
 * write them.
 */
export interface Dims {
  /** The dimension n (2..8). */
  readonly n: number;
  /** Number of bivector components (planes): k = n(n-1)/2. */
  readonly k: number;
  /** Number of rotor components (even blades): r = 2^(n-1). */
  readonly r: number;
  /** First axis of each plane: plane p is (planeI[p], planeJ[p]) with planeI[p] < planeJ[p], lexicographic order. */
  readonly planeI: Int32Array;
  /** Second axis of each plane (see `planeI`). */
  readonly planeJ: Int32Array;
  /**
   * `planeIndexOf[i*n + j]` = index of the plane of axes i and j in either order (the index of
   * (min, max)); -1 on the diagonal i == j. Unsigned: for i > j the bivector e_ij is MINUS the
   * stored basis bivector of that plane.
   */
  readonly planeIndexOf: Int32Array;
  /**
   * Rotor component → blade bitmask (e_i is bit i). Order: by grade, then lexicographic in the
   * axis indices. Component 0 is the scalar; components 1..k are the planes in bivector order,
   * so bivector component p is rotor component 1 + p.
   */
  readonly blades: Int32Array;
  /** Bitmask (0..2^n - 1) → rotor component, or -1 for odd blades. */
  readonly bladeIndex: Int32Array;
  /**
   * Product table of the even sub-algebra: blade a times blade b (rotor component indices) equals
   * `mulSign[a*r + b]` times blade `mulIndex[a*r + b]`.
   */
  readonly mulIndex: Int32Array;
  /** Signs (+1 or -1) of the product table, see `mulIndex`. */
  readonly mulSign: Float64Array;
  /** Reverse sign of each rotor component: (-1)^(g(g-1)/2) for a blade of grade g. */
  readonly reverseSign: Float64Array;
  /** The unchecked rotor kernels chosen for n (closed forms in 3D and 4D, table-driven otherwise). */
  readonly kernels: RotorKernels;
}

/**
 * Sign of the geometric product of two basis blades given as bitmasks (Euclidean metric):
 * e_a e_b = bladeProductSign(a, b) · e_(a XOR b). It counts the transpositions needed to sort the
 * vectors of the product (brief §1).
 */
export function bladeProductSign(a: number, b: number): number {
  let x = a >> 1;
  let swaps = 0;
  while (x !== 0) {
    swaps += popcount(x & b);
    x >>= 1;
  }
  return (swaps & 1) === 0 ? 1 : -1;
}

/** Number of set bits of a non-negative 32-bit integer (the grade of a blade bitmask). */
export function popcount(x: number): number {
  let c = 0;
  let v = x >>> 0;
  while (v !== 0) {
    v &= v - 1;
    c += 1;
  }
  return c;
}

/** Bitmasks of all blades of grade g over n axes, in lexicographic order of their axis lists. */
function bladesOfGrade(n: number, g: number, out: number[]): void {
  const idx: number[] = [];
  const rec = (start: number): void => {
    if (idx.length === g) {
      let m = 0;
      for (const i of idx) m |= 1 << i;
      out.push(m);
      return;
    }
    for (let i = start; i < n; i += 1) {
      idx.push(i);
      rec(i + 1);
      idx.pop();
    }
  };
  rec(0);
}

const cache: (Dims | undefined)[] = [];

function build(n: number, makeKernels: (D: Dims) => RotorKernels): Dims {
  const k = (n * (n - 1)) / 2;
  const r = 1 << (n - 1);
  const planeI = new Int32Array(k);
  const planeJ = new Int32Array(k);
  const planeIndexOf = new Int32Array(n * n).fill(-1);
  let p = 0;
  for (let i = 0; i < n; i += 1) {
    for (let j = i + 1; j < n; j += 1) {
      planeI[p] = i;
      planeJ[p] = j;
      planeIndexOf[i * n + j] = p;
      planeIndexOf[j * n + i] = p;
      p += 1;
    }
  }
  const list: number[] = [];
  for (let g = 0; g <= n; g += 2) bladesOfGrade(n, g, list);
  const blades = Int32Array.from(list);
  const bladeIndex = new Int32Array(1 << n).fill(-1);
  for (let a = 0; a < r; a += 1) bladeIndex[blades[a]!] = a;
  const mulIndex = new Int32Array(r * r);
  const mulSign = new Float64Array(r * r);
  for (let a = 0; a < r; a += 1) {
    for (let b = 0; b < r; b += 1) {
      mulIndex[a * r + b] = bladeIndex[blades[a]! ^ blades[b]!]!;
      mulSign[a * r + b] = bladeProductSign(blades[a]!, blades[b]!);
    }
  }
  const reverseSign = new Float64Array(r);
  for (let a = 0; a < r; a += 1) {
    const g = popcount(blades[a]!);
    reverseSign[a] = ((g * (g - 1)) / 2) % 2 === 0 ? 1 : -1;
  }
  const tables = { n, k, r, planeI, planeJ, planeIndexOf, blades, bladeIndex, mulIndex, mulSign, reverseSign };
  const D = tables as Dims & { kernels: RotorKernels };
  D.kernels = makeKernels(D);
  return D;
}

/**
 * @internal The tables of n (an integer in [2, 8], not checked), built with `makeKernels` the
 * first time n is asked for and cached: every caller gets the same object for the same n, so the
 * kernel choice must be the same for a given n whoever asks first.
 */
export function tablesWith(n: number, makeKernels: (D: Dims) => RotorKernels): Dims {
  return cache[n] ?? (cache[n] = build(n, makeKernels));
}

/**
 * Whether `D` is the tables object of its dimension (the one `dims(D.n)` returns), without
 * building anything.
 */
export function isDims(D: unknown): D is Dims {
  if (typeof D !== 'object' || D === null) return false;
  const n = (D as { n?: unknown }).n;
  return typeof n === 'number' && Number.isInteger(n) && n >= MIN_DIMENSION && n <= MAX_DIMENSION && cache[n] === D;
}
