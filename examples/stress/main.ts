/**
 * The stress page: a pile of 1000 boxes in 3D, or 320 hypercubes in 4D (`?d=4`), in the page's
 * thread or in a worker (`?worker=1`), with live figures: bodies, ms per step, the main thread's
 * ms per frame, awake bodies.
 */
import * as THREE from 'three';
import { BoxMesh, HyperBoxMesh, HyperPlaneMesh, PlaneMesh, Scene, createMaterial } from '@physin/three';
import type { Mesh } from '@physin/three';
import { dressScene, linkSwitches, startDemo, wantsWorker } from '../shared/demo.js';

const params = new URLSearchParams(window.location.search);
const n = params.get('d') === '4' ? 4 : 3;

// in 4D the flat goes through the middle of one layer of the pile in w (the columns stand at
// w = ±0.375 and ±1.125), so a quarter of the hypercubes are cut
const scene = new Scene({
  dimensions: n,
  gravity: n === 4 ? [0, -9.81, 0, 0] : [0, -9.81, 0],
  worker: wantsWorker(),
  sliceW: n === 4 ? 0.375 : 0,
});
dressScene(scene);
const floor = createMaterial(new THREE.MeshStandardMaterial({ color: 0x9aa4ae }), 0.6, 0);
const ground = new THREE.BoxGeometry(40, 0.2, 40).translate(0, -0.1, 0);
scene.add(n === 4 ? new HyperPlaneMesh([0, 1, 0, 0], 0, floor, ground) : new PlaneMesh(ground, floor, [0, 1, 0], 0));

// one geometry and a few materials shared by every box (a 4D body owns its cut's geometry)
const shades = [0x2a9d8f, 0x3aa99b, 0x4db6a8, 0x249082].map((c) =>
  createMaterial(new THREE.MeshStandardMaterial({ color: c }), 0.5, 0),
);
const cube = new THREE.BoxGeometry(0.5, 0.5, 0.5);
const bodies: Mesh[] = [];
const columns = n === 4 ? 4 : 10;
const layers = n === 4 ? 5 : 10;
for (let layer = 0; layer < layers; layer += 1) {
  for (let i = 0; i < columns; i += 1) {
    for (let j = 0; j < columns; j += 1) {
      for (let k = 0; k < (n === 4 ? columns : 1); k += 1) {
        const material = shades[(i + j + layer) % shades.length]!;
        // columns a little apart and each box a little turned, so the pile tumbles as it lands
        const jitter = ((i * 7 + j * 13 + layer * 5 + k * 3) % 11) / 11 - 0.5;
        const p = [
          (i - (columns - 1) / 2) * 0.75 + 0.1 * jitter,
          0.4 + layer * 0.8,
          (j - (columns - 1) / 2) * 0.75 - 0.1 * jitter,
        ];
        if (n === 4) p.push((k - (columns - 1) / 2) * 0.75);
        const body = n === 4 ? new HyperBoxMesh([0.25, 0.25, 0.25, 0.25], material, 1) : new BoxMesh(cube, material, 1);
        body.setPositionN(p);
        body.rotateInPlane(0, 1, 0.5 * jitter);
        body.rotateInPlane(1, 2, 0.3 * jitter);
        if (n === 4) body.rotateInPlane(0, 3, 0.3 * jitter);
        scene.add(body);
        bodies.push(body);
      }
    }
  }
}

// figures: medians over the last 60 frames
const WINDOW = 60;
const stepMs: number[] = [];
const mainMs: number[] = [];
let frameStart = 0;
let simulateMs = 0;
let applyStart = 0;
let moved = 0;
let drawn = 0;
let lastDraw = 0;
const drawMs: number[] = [];
const reportTimes: number[] = [];
/** Ids of the bodies the engine put to sleep (from each report's slept and woke lists). */
const asleep = new Set<number>();
const last = new Float64Array(bodies.length * 3);
const push = (list: number[], value: number): void => {
  list.push(value);
  if (list.length > WINDOW) list.shift();
};
const median = (list: readonly number[]): number => {
  if (list.length === 0) return 0;
  const sorted = [...list].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)]!;
};

const canvas = document.getElementById('view') as HTMLCanvasElement;
const figures = document.getElementById('figures')!;
startDemo(scene, {
  canvas,
  eye: n === 4 ? [5, 4, 6] : [9.5, 8, 12.5],
  target: [0, 1, 0],
  stats: document.getElementById('stats'),
  eachDraw: () => {
    const now = performance.now();
    if (drawn > 0) push(drawMs, now - lastDraw);
    drawn += 1;
    lastDraw = now;
    if (!scene.busy) frameStart = now;
  },
  afterUpdate: (frame) => {
    const now = performance.now();
    // in this thread the step is done inside simulate() (the report is applied after the frame's
    // drawing, in a microtask); in a worker, from the request to the report's arrival
    push(stepMs, scene.host.thread === 'main' ? simulateMs : now - frameStart);
    push(mainMs, simulateMs + (now - applyStart));
    reportTimes.push(now);
    while (reportTimes.length > 0 && reportTimes[0]! < now - 1000) reportTimes.shift();
    moved = 0;
    bodies.forEach((body, i) => {
      const p = body.position;
      if (Math.abs(p.x - last[3 * i]!) + Math.abs(p.y - last[3 * i + 1]!) + Math.abs(p.z - last[3 * i + 2]!) > 1e-6) moved += 1;
      last[3 * i] = p.x;
      last[3 * i + 1] = p.y;
      last[3 * i + 2] = p.z;
    });
    if (frame % 10 === 0) {
      figures.innerHTML =
        `<dt>bodies</dt><dd>${bodies.length}${n === 4 ? ' hypercubes' : ' boxes'}</dd>` +
        `<dt>thread</dt><dd>${scene.host.thread}</dd>` +
        `<dt>step</dt><dd>${median(stepMs).toFixed(2)} ms</dd>` +
        `<dt>main thread</dt><dd>${median(mainMs).toFixed(2)} ms a frame</dd>` +
        `<dt>awake</dt><dd>${bodies.length - asleep.size} (${asleep.size} asleep)</dd>` +
        `<dt>moved</dt><dd>${moved} in the last report</dd>` +
        `<dt>rates</dt><dd>${reportTimes.length} steps/s, ${(1000 / Math.max(1e-3, median(drawMs))).toFixed(0)} frames/s drawn</dd>`;
    }
  },
});

// time simulate() itself, and the report's handling (from the host's answer to 'update')
const simulate = scene.simulate.bind(scene);
scene.simulate = (timeStep?: number, maxSubSteps?: number): boolean => {
  const t = performance.now();
  const ok = simulate(timeStep, maxSubSteps);
  simulateMs = performance.now() - t;
  return ok;
};
const apply = (scene as unknown as { applyReport(report: unknown): void }).applyReport.bind(scene);
interface SleepLists {
  readonly slept: Int32Array;
  readonly sleptCount: number;
  readonly woke: Int32Array;
  readonly wokeCount: number;
}
(scene as unknown as { applyReport(report: unknown): void }).applyReport = (report: unknown): void => {
  applyStart = performance.now();
  const r = report as SleepLists;
  for (let i = 0; i < r.sleptCount; i += 1) asleep.add(r.slept[i]!);
  for (let i = 0; i < r.wokeCount; i += 1) asleep.delete(r.woke[i]!);
  apply(report);
};

linkSwitches({ n, to3: '1000 boxes (3D)', to4: '320 hypercubes (4D)' });
