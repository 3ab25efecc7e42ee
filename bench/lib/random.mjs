// Seeded random inputs for benchmarks (mulberry32, the generator of tests/support/random.ts),
// so every run measures the same data.

/** A generator of uniform numbers in [0, 1) from a 32-bit seed. */
export function seeded(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** A Float64Array of `len` uniform numbers in [lo, hi). */
export function randomArray(rand, len, lo = -1, hi = 1) {
  const out = new Float64Array(len);
  for (let i = 0; i < len; i += 1) out[i] = lo + (hi - lo) * rand();
  return out;
}
