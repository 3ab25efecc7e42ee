// Measures what writing and reading a report allocates in steady state, in the world's thread
// (WorldCore: the accumulator, the steps, the report written into the buffer it was given) and in
// the caller's (ReportView: the views over the buffer). Run by tests/worker-allocation.test.ts as
//   node --no-concurrent-recompilation --expose-gc --max-semi-space-size=256 --min-semi-space-size=64 \
//     tests/worker-allocation.mjs STEPS
// It imports the BUILT @physin/worker internals and prints one JSON line. The method is that of
// tests/engine-allocation.mjs; the young generation is read (the JIT's code goes elsewhere), over
// windows of STEPS / 5 and STEPS steps, least of three with no collection inside.
//
// This is the main-thread path, where one buffer is refilled in place. Across a worker the buffer
// is transferred, so each side sees a new ArrayBuffer object and makes new views over it (a few
// small objects a step, never the report's bytes); the promise `host.step` returns is the
// caller's interface and is not counted here either.
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { leastGrowth } from './support/young-generation.mjs';

if (typeof globalThis.gc !== 'function') {
  console.error('worker-allocation.mjs: run node with --expose-gc');
  process.exit(2);
}
const require = createRequire(import.meta.url);
const dist = join(dirname(require.resolve('@physin/worker/package.json')), 'dist');
const { WorldCore } = await import(join(dist, 'world-core.js'));
const { ReportView } = await import(join(dist, 'report.js'));

const steps = Number(process.argv[2] ?? 5000);

function build(n) {
  const core = WorldCore.create({
    dimensions: n,
    gravity: n === 3 ? [0, -9.81, 0] : [0, -9.81, 0, 0],
    params: { allowSleep: false },
  });
  let id = 0;
  const floor = new Array(n).fill(0);
  floor[1] = 1;
  core.apply({ op: 'addBody', id: id++, description: { shape: { kind: 'halfspace', normal: floor, offset: 0 }, mass: 0 } });
  for (let i = 0; i < 40; i += 1) {
    const position = new Array(n).fill(0);
    position[0] = (i % 5) * 1.1 - 2.2;
    position[1] = 0.5 + Math.floor(i / 5) * 1.0;
    core.apply({
      op: 'addBody',
      id: id++,
      description: { shape: { kind: 'box', halfExtents: new Array(n).fill(0.5) }, mass: 1, position },
    });
  }
  return core;
}

const results = {};
for (const n of [3, 4]) {
  const core = build(n);
  let buffer = null;
  let view = null;
  const run = (count) => {
    for (let s = 0; s < count; s += 1) {
      buffer = core.stepAndReport(core.takeSteps(1 / 60, 1), buffer);
      view = view === null ? new ReportView(core.D, buffer) : view.attach(buffer);
    }
  };
  // the pile lands and comes to rest (its collision events end), then the JIT settles
  run(600);
  for (let i = 0; i < 3; i += 1) {
    run(steps / 5);
    await new Promise((resolve) => setTimeout(resolve, 50));
  }
  const short = await leastGrowth(run, steps / 5);
  const long = await leastGrowth(run, steps);
  results[n] = {
    short,
    long,
    perStep: (long - short) / (steps - steps / 5),
    bodies: view.bodyCount,
    buffersCreated: view.buffersCreated,
    collisions: view.collisionCount,
  };
}
console.log(JSON.stringify({ steps, results }));
