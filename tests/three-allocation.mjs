// Measures what the three.js adapter allocates per frame in steady state: applying a report to
// every mesh (positions, rotors, velocities, re-slicing the 4D bodies that moved) and moving the
// slice (`sliceW` + `refreshSlice`). Run by tests/three-allocation.test.ts as
//   node --no-concurrent-recompilation --expose-gc --max-semi-space-size=256 --min-semi-space-size=64 \
//     tests/three-allocation.mjs FRAMES [KINDS]
// with KINDS a comma list of boxes, spheres, tori, simplex (default: all of them).
// It imports the BUILT packages and prints one JSON line. The method is that of
// tests/engine-allocation.mjs: gc twice, read used_heap_size, run the frames, read it again;
// a PerformanceObserver makes sure no collection ran inside the window.
//
// The step itself is not measured here (see engine-allocation); nor are collision events, which
// are one new object per event by design.
import { leastGrowth } from './support/young-generation.mjs';
import * as THREE from 'three';

if (typeof globalThis.gc !== 'function') {
  console.error('three-allocation.mjs: run node with --expose-gc');
  process.exit(2);
}
const { Scene, HyperBoxMesh, HyperSphereMesh, HyperTorusMesh, HyperPlaneMesh, HyperMesh } = await import('@physin/three');

const frames = Number(process.argv[2] ?? 1000);
const kinds = new Set((process.argv[3] ?? 'boxes,spheres,tori,simplex').split(','));
const material = new THREE.MeshBasicMaterial();

/** A 4D scene of every sliced kind, stepped for real to get two different reports. */
async function build() {
  const scene = new Scene({ dimensions: 4, gravity: [0, -9.81, 0, 0] });
  scene.add(new HyperPlaneMesh([0, 1, 0, 0], 0, material));
  for (let i = 0; i < (kinds.has('boxes') ? 60 : 0); i += 1) {
    const box = new HyperBoxMesh([0.3, 0.2, 0.25, 0.35], material, 1);
    box.setPositionN([(i % 6) - 3, 1 + Math.floor(i / 6), 0.1 * (i % 3), 0.05 * (i % 4)]);
    box.rotateInPlane(0, 3, 0.1 * i);
    scene.add(box);
  }
  for (let i = 0; i < (kinds.has('spheres') ? 10 : 0); i += 1) {
    const ball = new HyperSphereMesh(0.3, material, 1);
    ball.setPositionN([i - 5, 4, 2, 0.1 * i]);
    scene.add(ball);
  }
  for (let i = 0; i < (kinds.has('tori') ? 2 : 0); i += 1) {
    const torus = new HyperTorusMesh(0.6, 0.2, i % 2 === 0 ? [0, 2] : [0, 3], material, 1);
    torus.setPositionN([2 * i - 4, 6, -2, 0]);
    scene.add(torus);
  }
  // the 4-simplex: 5 vertices, 5 boundary tetrahedra
  const v = [
    [1, 0, 0, -0.25],
    [-0.5, 0.87, 0, -0.25],
    [-0.5, -0.87, 0, -0.25],
    [0, 0, 0.9, -0.25],
    [0, 0, 0, 1],
  ];
  const cells = [
    [0, 1, 2, 3],
    [0, 1, 2, 4],
    [0, 1, 3, 4],
    [0, 2, 3, 4],
    [1, 2, 3, 4],
  ];
  if (kinds.has('simplex')) {
    const simplex = new HyperMesh(v, cells, material, 1);
    simplex.setPositionN([0, 8, 0, 0]);
    scene.add(simplex);
  }
  const copies = [];
  // frames through the host directly: no `update` listener is ever added (three's dispatchEvent
  // copies a type's listener array on every dispatch, which is three's cost, not ours)
  for (let f = 0; f < 40; f += 1) scene['applyReport'](await scene.host.step(1 / 60, 1));
  // two reports of consecutive frames, copied, without their events
  for (let f = 0; f < 2; f += 1) {
    const report = await scene.host.step(1 / 60, 1);
    copies.push({
      steps: 1,
      time: report.time,
      bodyCount: report.bodyCount,
      stride: report.stride,
      bodies: report.bodies.slice(),
      collisionCount: 0,
      collisionStride: report.collisionStride,
      collisions: new Float32Array(0),
      broken: new Int32Array(0),
      brokenCount: 0,
      slept: new Int32Array(0),
      sleptCount: 0,
      woke: new Int32Array(0),
      wokeCount: 0,
      buffersCreated: report.buffersCreated,
    });
  }
  return { scene, reports: copies };
}

/**
 * Bytes a frame, as the slope between windows of `frames / 5` and `frames` frames: the window's
 * fixed cost (the measuring, the JIT) cancels, an allocation per frame does not.
 */
async function measure(label, work) {
  const short = await leastGrowth(work, frames / 5);
  const long = await leastGrowth(work, frames);
  return { label, perFrame: (long - short) / (frames - frames / 5), short, long };
}

const { scene, reports } = await build();
const apply = (r) => scene['applyReport'](r);
let flip = 0;
const reportFrames = (count) => {
  for (let f = 0; f < count; f += 1) apply(reports[flip++ & 1]);
};
const flats = Array.from({ length: 16 }, (_, i) => Float64Array.of(0.3 * Math.sin(i * 0.4)));
const sliceFrames = (count) => {
  for (let f = 0; f < count; f += 1) {
    // the flat's values copied from a table, not computed here nor given to the sliceW setter: a
    // double made or passed by this loop (if it runs unoptimised) would be its own allocation
    scene.slice.set(flats[f & 15]);
    scene.refreshSlice();
  }
};
// warm up and let the JIT settle
for (let i = 0; i < 5; i += 1) {
  reportFrames(frames / 5);
  sliceFrames(frames / 5);
  await new Promise((resolve) => setTimeout(resolve, 50));
}
const out = [await measure('report', reportFrames), await measure('slice', sliceFrames)];
let visible = 0;
scene.traverse((o) => (visible += o.visible ? 1 : 0));
console.log(JSON.stringify({ frames, bodies: scene.bodyCount, visible, results: out }));
scene.dispose();
