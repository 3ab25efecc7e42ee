// Measures what World.step allocates in steady state. Run by tests/engine-allocation.test.ts as
//   node --expose-gc --max-semi-space-size=256 --min-semi-space-size=64 tests/engine-allocation.mjs [steps]
// It imports the BUILT engine (dist/), as an application would, and prints one JSON line.
//
// Method: build a 100-body world (boxes and balls, spinning, moving, under gravity), warm it up so
// every function of the step is optimised, then for each window: gc() twice, read used_heap_size,
// run the measured steps, read it again without collecting. A PerformanceObserver counts the
// garbage collections whose start falls inside the window: with none there, the young generation
// was never emptied, so the heap difference is everything allocated during the window (by the
// steps, by the measuring — about 12 KB of new space — and by the JIT, see WINDOWS below).
// The big semi-space makes a scavenge during the window unlikely unless the step really allocates.
import { PerformanceObserver, performance } from 'node:perf_hooks';
import v8 from 'node:v8';

if (typeof globalThis.gc !== 'function') {
  console.error('engine-allocation.mjs: run node with --expose-gc');
  process.exit(2);
}

const engine = await import('@physin/engine');
const { World, Body, HyperBox, HyperSphere, HyperTorus, HalfSpace, dims } = engine;

const steps = Number(process.argv[2] ?? 10_000);
const warmup = 3_000;

// mulberry32, as tests/support/random.ts
function seeded(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function makeWorld(n) {
  const D = dims(n);
  const rand = seeded(1000 + n);
  const r = (lo, hi) => lo + (hi - lo) * rand();
  const gravity = new Array(n).fill(0);
  gravity[1] = -9.81;
  const world = new World({ dimensions: n, gravity });
  for (let b = 0; b < 100; b += 1) {
    const shape = b % 3 === 2 ? HyperSphere(r(0.2, 0.8)) : HyperBox(D, Array.from({ length: n }, () => r(0.1, 1)));
    const type = b % 10 === 9 ? 'kinematic' : b % 10 === 8 ? 'static' : 'dynamic';
    world.addBody(
      new Body(D, {
        shape,
        type,
        mass: type === 'static' ? 0 : r(0.5, 5),
        position: Array.from({ length: n }, () => r(-10, 10)),
        velocity: type === 'static' ? undefined : Array.from({ length: n }, () => r(-1, 1)),
        angularVelocity: type === 'static' ? undefined : Array.from({ length: D.k }, () => r(-3, 3)),
      }),
    );
  }
  return world;
}

// A scene of resting contacts: a 9-box stack, a row of balls and a torus lying flat on a
// half-space, with sleep off so every contact is solved in every step (broadphase, narrowphase
// box–box, box–, sphere– and torus–half-space, solver with warm starting and shock propagation).
function makeStackWorld(n) {
  const D = dims(n);
  const gravity = new Array(n).fill(0);
  gravity[1] = -9.81;
  const world = new World({ dimensions: n, gravity, params: { allowSleep: false } });
  const up = new Array(n).fill(0);
  up[1] = 1;
  world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
  const at = (x, y) => {
    const p = new Array(n).fill(0);
    p[0] = x;
    p[1] = y;
    return p;
  };
  for (let i = 0; i < 9; i += 1) world.addBody(new Body(D, { shape: HyperBox(D, new Array(n).fill(0.5)), mass: 1, position: at(0, 0.5 + i) }));
  for (let i = 0; i < 4; i += 1) world.addBody(new Body(D, { shape: HyperSphere(0.4), mass: 1, position: at(2 + i, 0.4) }));
  const torus = new Body(D, { shape: HyperTorus(D, 1, 0.25, [0, 2]), mass: 1, position: at(-3, 0.25) });
  world.addBody(torus);
  return world;
}

const gcs = [];
const observer = new PerformanceObserver((list) => {
  for (const entry of list.getEntries()) gcs.push({ start: entry.startTime, kind: entry.detail?.kind ?? entry.kind });
});
observer.observe({ entryTypes: ['gc'] });

// Windows measured per dimension. Total heap growth also counts what the JIT leaves in old space
// when it finishes compiling in the window (seen: 0-220 KB now and then); that does not repeat, so
// the test takes the smallest total over the windows. Allocation by the step itself repeats in
// every window and lands in new space, which is reported per window too.
const WINDOWS = 3;

const results = {};
const scenes = [
  ['3', () => makeWorld(3)],
  ['4', () => makeWorld(4)],
  ['stack3', () => makeStackWorld(3)],
  ['stack4', () => makeStackWorld(4)],
];
for (const [name, make] of scenes) {
  const world = make();
  const dt = 1 / 60;
  for (let s = 0; s < warmup; s += 1) world.step(dt);
  // Let concurrent compilation jobs finish and install their code, then warm up once more, so
  // the windows measure the step and not the compiler.
  await new Promise((resolve) => setTimeout(resolve, 100));
  for (let s = 0; s < 1000; s += 1) world.step(dt);
  const windows = [];
  for (let w = 0; w < WINDOWS; w += 1) {
    globalThis.gc();
    globalThis.gc();
    // Let the concurrent sweeper finish, so old-space accounting does not move in the window.
    await new Promise((resolve) => setTimeout(resolve, 50));
    const spacesBefore = v8.getHeapSpaceStatistics();
    const t0 = performance.now();
    const before = v8.getHeapStatistics().used_heap_size;
    for (let s = 0; s < steps; s += 1) world.step(dt);
    const after = v8.getHeapStatistics().used_heap_size;
    const t1 = performance.now();
    const spacesAfter = v8.getHeapSpaceStatistics();
    // Let the observer deliver the entries of the window.
    await new Promise((resolve) => setTimeout(resolve, 20));
    const inWindow = gcs.filter((g) => g.start >= t0 && g.start <= t1);
    // Growth per heap space: new_space is what running code allocated.
    const spaces = {};
    for (let i = 0; i < spacesAfter.length; i += 1) {
      const grown = spacesAfter[i].space_used_size - spacesBefore[i].space_used_size;
      if (grown !== 0) spaces[spacesAfter[i].space_name] = grown;
    }
    windows.push({ bytes: after - before, newSpace: spaces.new_space ?? 0, spaces, collections: inWindow.length, kinds: inWindow.map((g) => g.kind), msPerStep: (t1 - t0) / steps });
  }
  results[name] = { steps, bodies: world.bodies.length, touching: world.touchingCount, windows };
}
observer.disconnect();
console.log(JSON.stringify(results));
