/**
 * A small seeded generator (mulberry32) so every random test input is reproducible.
 * Use `const rand = seeded(42)` and draw with `rand()` in [0, 1) or the helpers below.
 */
export function seeded(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Uniform number in [lo, hi). */
export function uniform(rand: () => number, lo: number, hi: number): number {
  return lo + (hi - lo) * rand();
}

/** A Float64Array of `len` uniform numbers in [lo, hi). */
export function randomArray(rand: () => number, len: number, lo = -1, hi = 1): Float64Array {
  const out = new Float64Array(len);
  for (let i = 0; i < len; i += 1) out[i] = uniform(rand, lo, hi);
  return out;
}

/** A seeded random unit vector: rejection from the cube [−1, 1)ⁿ (0.01 < |v|² <= 1), then v / |v|. */
export function randomUnitVector(rand: () => number, n: number): Float64Array {
  for (;;) {
    const v = randomArray(rand, n);
    let s = 0;
    for (const x of v) s += x * x;
    if (s > 0.01 && s <= 1) return v.map((x) => x / Math.sqrt(s));
  }
}
