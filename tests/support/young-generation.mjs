// The allocation windows of tests/three-allocation.mjs, tests/worker-allocation.mjs and
// tests/engine-compound-allocation.mjs: what a piece of work leaves in V8's young generation,
// where short-lived objects go (the JIT's code does not). Run node with --expose-gc.
import { PerformanceObserver } from 'node:perf_hooks';
import v8 from 'node:v8';

/** Bytes used in the young generation now. */
export function newSpace() {
  return v8.getHeapSpaceStatistics().find((s) => s.space_name === 'new_space').space_used_size;
}

/** A pause that lets the observer deliver the collections that ran before it. */
const settle = () => new Promise((resolve) => setTimeout(resolve, 20));

/**
 * The least growth of the young generation over three runs of `work(count)`, each after two
 * collections and counted only if no collection ran inside it (Infinity if every run had one).
 * The observer delivers its entries between tasks, hence the pauses around each run.
 */
export async function leastGrowth(work, count) {
  let gcs = 0;
  const observer = new PerformanceObserver((list) => (gcs += list.getEntries().length));
  observer.observe({ entryTypes: ['gc'] });
  let least = Infinity;
  for (let w = 0; w < 3; w += 1) {
    globalThis.gc();
    globalThis.gc();
    await settle();
    gcs = 0;
    const before = newSpace();
    work(count);
    const after = newSpace();
    await settle();
    if (gcs === 0) least = Math.min(least, after - before);
  }
  observer.disconnect();
  return least;
}
