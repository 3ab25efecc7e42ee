// The three.js adapter (@physin/three): what a frame costs the main thread with 1000 hypercubes.
//
// Scene: 1000 hypercubes of half extent 0.25 in 4D, in a seeded 10 × 10 grid of columns (x, z)
// ten high, each column at its own w in [−0.3, 0.3] and every cube turned by a seeded angle in
// the (x w) plane, so that the slice w = 0 cuts most of them and every cut is a real polyhedron;
// on a HyperPlaneMesh floor; sleep off (every body moves and is re-cut every frame). The scene is
// built through the adapter, as a user would, with real three.js (no renderer: the GPU upload is
// three's, not ours).
//
// Timed, each frame alone with performance.now(), after WARMUP untimed frames:
//   slices              `scene.slice[0]` moved and `scene.refreshSlice()`: every cube re-cut
//   main thread, worker simulate() (sends the frame's moves with the step request) plus applying
//                       the report when it arrives (poses, velocities, re-cutting the cubes that
//                       moved) — the adapter's main-thread time with the world in a worker
//   apply (main mode)   applying the report in main-thread mode, where the step itself also runs
//                       in the main thread (timed apart: "step")
// A cell is the median over RUNS runs of each run's median frame. The goal (issue 14): the slices
// under 3 ms a frame for 1000 hypercubes (reported, not asserted).
//
// Run: node bench/three.bench.mjs    (after the build: it imports the BUILT packages)
import { performance } from 'node:perf_hooks';
import { medianTable } from './lib/table.mjs';
import { seeded } from './lib/random.mjs';

let THREE;
let adapter;
try {
  THREE = await import('three');
  adapter = await import('@physin/three');
} catch (error) {
  console.error(`three.bench: cannot load the built packages (build them first: npm run build): ${error?.stack ?? error}`);
  process.exit(1);
}
const { Scene, HyperBoxMesh, HyperPlaneMesh } = adapter;

const WARMUP = 60;
const RUNS = 5;
const FRAMES = 40;
const GOAL_MS = 3;
const material = new THREE.MeshBasicMaterial();

function build(worker) {
  const scene = new Scene({ dimensions: 4, gravity: [0, -9.81, 0, 0], worker, params: { allowSleep: false } });
  scene.add(new HyperPlaneMesh([0, 1, 0, 0], 0, material));
  const rand = seeded(14);
  for (let cx = 0; cx < 10; cx += 1) {
    for (let cz = 0; cz < 10; cz += 1) {
      const w = (rand() - 0.5) * 0.6;
      for (let layer = 0; layer < 10; layer += 1) {
        const cube = new HyperBoxMesh([0.25, 0.25, 0.25, 0.25], material, 1);
        cube.setPositionN([(cx - 4.5) * 0.9, 0.3 + layer * 0.55, (cz - 4.5) * 0.9, w]);
        cube.rotateInPlane(0, 3, (rand() - 0.5) * 0.6);
        scene.add(cube);
      }
    }
  }
  return scene;
}

/** Runs one frame: simulate, then wait for the report; returns [simulate() ms, apply ms, wall ms]. */
function frame(scene, applyTime) {
  return new Promise((resolve) => {
    const t0 = performance.now();
    const onUpdate = () => {
      scene.removeEventListener('update', onUpdate);
      resolve([syncMs, applyTime.last, performance.now() - t0]);
    };
    scene.addEventListener('update', onUpdate);
    if (!scene.simulate(1 / 60, 1)) throw new Error('three.bench: simulate refused a frame');
    const syncMs = performance.now() - t0;
  });
}

/** Wraps the scene's report handler to time it (the adapter's own per-frame work). */
function timeApply(scene) {
  const applyTime = { last: 0 };
  const original = scene.applyReport.bind(scene);
  scene.applyReport = (report) => {
    const t = performance.now();
    original(report);
    applyTime.last = performance.now() - t;
  };
  // (the scene's promise handler calls this.applyReport at each report, so the wrapper is used)
  return applyTime;
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

const results = {};
for (const mode of ['worker', 'main']) {
  const scene = build(mode === 'worker');
  await scene.host.ready;
  const applyTime = timeApply(scene);
  for (let f = 0; f < WARMUP; f += 1) await frame(scene, applyTime);
  const runs = { sync: [], main: [], apply: [], wall: [], slices: [] };
  for (let run = 0; run < RUNS; run += 1) {
    const sync = [];
    const main = [];
    const apply = [];
    const wall = [];
    const slices = [];
    for (let f = 0; f < FRAMES; f += 1) {
      const [m, a, w] = await frame(scene, applyTime);
      sync.push(m);
      main.push(m + a);
      apply.push(a);
      wall.push(w);
      scene.slice[0] = 0.2 * Math.sin(f * 0.3);
      const t = performance.now();
      scene.refreshSlice();
      slices.push(performance.now() - t);
    }
    runs.sync.push(median(sync));
    runs.main.push(median(main));
    runs.apply.push(median(apply));
    runs.wall.push(median(wall));
    runs.slices.push(median(slices));
  }
  let visible = 0;
  scene.traverse((o) => (visible += o.isPhysinMesh && o.dimensions === 4 && o.visible && o.geometry.drawRange.count > 0 ? 1 : 0));
  results[mode] = { sync: median(runs.sync), main: median(runs.main), apply: median(runs.apply), wall: median(runs.wall), slices: median(runs.slices), visible, bodies: scene.bodyCount };
  scene.dispose();
}

medianTable(`Adapter, 1000 hypercubes in 4D, ms per frame: medians of ${RUNS} runs of ${FRAMES} frames (each run's median)`, [
  {
    mode: 'world in a worker',
    bodies: results.worker.bodies,
    'cut (visible)': results.worker.visible,
    'slices (refreshSlice)': results.worker.slices,
    'simulate()': results.worker.sync,
    'apply report': results.worker.apply,
    'main thread (simulate + apply)': results.worker.main,
    'frame, wall': results.worker.wall,
  },
  {
    mode: 'world in the main thread',
    bodies: results.main.bodies,
    'cut (visible)': results.main.visible,
    'slices (refreshSlice)': results.main.slices,
    'simulate()': results.main.sync,
    'apply report': results.main.apply,
    'main thread (simulate + apply)': results.main.main,
    'frame, wall': results.main.wall,
  },
]);
console.log('simulate() in main-thread mode holds the step itself; in worker mode it only sends the request.');
const worst = Math.max(results.worker.slices, results.main.slices);
medianTable('Goal: the slices of 1000 hypercubes under 3 ms a frame (reported, not asserted)', [
  { goal: 'refreshSlice, 1000 hypercubes', measured: `${worst.toFixed(2)} ms`, limit: `< ${GOAL_MS} ms`, met: worst < GOAL_MS ? 'yes' : 'no' },
]);
