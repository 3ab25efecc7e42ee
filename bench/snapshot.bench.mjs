// World snapshots: the cost of `snapshotWorld(world)` and `restoreWorld(bytes)`, and the size of the
// bytes, on the piles of the contact benchmark (1000 unit boxes in 3D, 300 hypercubes in 4D,
// dropped on the ground, dt = 1/60, sleep off) after 120 steps (falling and landing: many
// contacts, manifolds and warm-start impulses) and after 600 steps (at rest).
//
// Timing: each call is timed alone with performance.now(), 21 times; the cells are medians (ms).
// The step's own median over the 20 steps before the snapshot is shown for scale. Each restore
// is checked: its snapshot must have the bytes of the original's (exit 1 otherwise).
//
// Run: node bench/snapshot.bench.mjs    (after the build: it imports the BUILT packages)
import { performance } from 'node:perf_hooks';
import { medianTable } from './lib/table.mjs';

let physin;
let snapshotWorld;
let restoreWorld;
try {
  physin = await import('./scenes/physin-scenes.mjs');
  ({ snapshotWorld, restoreWorld } = await import('@physin/engine'));
} catch (error) {
  console.error(`snapshot.bench: cannot load the built engine (build it first: npm run build): ${error?.stack ?? error}`);
  process.exit(1);
}
if (typeof restoreWorld !== 'function') {
  console.error('snapshot.bench: the built engine has no restoreWorld (rebuild it: npm run build)');
  process.exit(1);
}

const REPEATS = 21;

function median(values) {
  const s = [...values].sort((a, b) => a - b);
  return s[s.length >> 1];
}

function sameBytes(a, b) {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i += 1) if (a[i] !== b[i]) return false;
  return true;
}

const rows = [];
let failures = 0;
for (const [count, n] of [
  [1000, 3],
  [300, 4],
]) {
  const scene = physin.physinPile(count, n);
  const world = scene.world;
  for (const at of [120, 600]) {
    const stepTimes = [];
    while (world.stepCount < at) {
      const t0 = performance.now();
      world.step();
      if (world.stepCount > at - 20) stepTimes.push(performance.now() - t0);
    }
    const snapTimes = [];
    const restoreTimes = [];
    let bytes = snapshotWorld(world);
    for (let i = 0; i < REPEATS; i += 1) {
      const t0 = performance.now();
      bytes = snapshotWorld(world);
      snapTimes.push(performance.now() - t0);
      const t1 = performance.now();
      const restored = restoreWorld(bytes);
      restoreTimes.push(performance.now() - t1);
      if (i === 0 && !sameBytes(snapshotWorld(restored), bytes)) {
        console.error(`snapshot.bench: pile${count} ${n}D at step ${at}: the restored world's snapshot differs`);
        failures += 1;
      }
    }
    rows.push({
      scene: `pile${count} ${n}D`,
      step: at,
      contacts: world.contactCount,
      'bytes (KiB)': bytes.length / 1024,
      'bytes / body': Math.round(bytes.length / world.bodies.length),
      'step (ms)': median(stepTimes),
      'snapshot (ms)': median(snapTimes),
      'restore (ms)': median(restoreTimes),
    });
  }
}
medianTable('World snapshots (medians of 21 calls; the step: median of the 20 steps before)', rows);
if (failures > 0) process.exit(1);
