/**
 * The narrowphase and the bounds kernel allocate nothing in steady state.
 *
 * Method (as tests/engine-allocation.test.ts): a child `node --expose-gc --max-semi-space-size=256
 * --min-semi-space-size=64` imports the BUILT engine and collides a fixed set of posed pairs of
 * every supported kind (box–box, box–ball, box–half-space, ball–ball, ball–half-space,
 * torus–half-space, torus–ball, mesh–half-space, mesh–ball, mesh–box, mesh–mesh, capsule–half-space,
 * capsule–ball, capsule–box, capsule–mesh, capsule–capsule; both orders; resting, tilted and
 * random poses; several margins) for n = 2..6 through the hot-path entry point collideScratch
 * (margin in scratch.scalars[NARROWPHASE_MARGIN]) and through collide (margin as an argument),
 * and takes the bounds of every kind of shape through computeBoundsUnchecked. After a warm-up it
 * measures five windows of about 100 000 calls each: a window with no garbage collection and
 * < 64 KB of new-space growth (the measuring itself costs about 12 KB) allocated less than one heap
 * number (16 B) per 2 000 calls. The JIT may leave old-space objects in a window, so the whole-heap bound applies
 * to the smallest window, and compiled code (a late compile on a loaded machine) is not counted.
 *
 * The script imports packages/engine/dist; it is rebuilt here when any source of the algebra or
 * the engine is newer than it.
 */
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { ensureBuiltEngine } from './support/built-engine.js';
import { beforeAll, describe, expect, it } from 'vitest';

const root = fileURLToPath(new URL('..', import.meta.url));
const dist = join(root, 'packages/engine/dist');

// The child: builds the pairs, warms up, measures. Prints one JSON line.
const SCRIPT = String.raw`
import { PerformanceObserver, performance } from 'node:perf_hooks';
import v8 from 'node:v8';
const base = process.argv[process.argv.length - 1];
const E = await import(base + '/internal.js');
const { collideScratch, collide } = await import(base + '/collision/collide.js');
const { NARROWPHASE_MARGIN } = await import(base + '/collision/narrowphase-scratch.js');
const { computeBoundsUnchecked } = await import(base + '/collision/bounds.js');
const { dims, HyperBox, HyperSphere, HalfSpace, HyperTorus, ConvexMesh, HyperCapsule } = E;

let seed = 12345;
const rand = () => {
  seed = (seed + 0x6d2b79f5) >>> 0;
  let t = seed;
  t = Math.imul(t ^ (t >>> 15), t | 1);
  t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
  return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
};
function rotation(n, amount) {
  const M = new Float64Array(n * n);
  for (let i = 0; i < n; i += 1) for (let j = 0; j < n; j += 1) M[i * n + j] = (i === j ? 1 : 0) + amount * (2 * rand() - 1);
  for (let c = 0; c < n; c += 1) {
    for (let p = 0; p < c; p += 1) {
      let d = 0;
      for (let i = 0; i < n; i += 1) d += M[i * n + c] * M[i * n + p];
      for (let i = 0; i < n; i += 1) M[i * n + c] -= d * M[i * n + p];
    }
    let l = 0;
    for (let i = 0; i < n; i += 1) l += M[i * n + c] ** 2;
    for (let i = 0; i < n; i += 1) M[i * n + c] /= Math.sqrt(l);
  }
  return M; // orthonormal; the sign of the determinant does not matter to the colliders
}
function crossPolytope(D, s) {
  const n = D.n;
  const vertices = [];
  for (let i = 0; i < n; i += 1) for (const g of [1, -1]) vertices.push(Array.from({ length: n }, (_, c) => (c === i ? g * s : 0)));
  const facets = [];
  for (let mask = 0; mask < 1 << n; mask += 1) facets.push(Array.from({ length: n }, (_, i) => 2 * i + ((mask >> i) & 1)));
  return ConvexMesh(D, vertices, facets);
}
const KINDS = [['box', 'box'], ['box', 'cube'], ['box', 'ball'], ['ball', 'box'], ['box', 'floor'], ['floor', 'box'],
  ['box', 'slope'], ['ball', 'ball'], ['ball', 'floor'], ['ball', 'slope'], ['torus', 'floor'], ['torus', 'slope'],
  ['torus', 'ball'], ['ball', 'torus'], ['mesh', 'floor'], ['mesh', 'slope'], ['mesh', 'ball'], ['ball', 'mesh'],
  ['mesh', 'box'], ['box', 'mesh'], ['mesh', 'cube'], ['mesh', 'mesh'], ['capsule', 'floor'], ['capsule', 'slope'],
  ['capsule', 'ball'], ['ball', 'capsule'], ['capsule', 'capsule'], ['capsule', 'box'], ['box', 'capsule'], ['capsule', 'mesh']];
// GJK, EPA and face clipping cost 0.05 ms (4D) to 1.6 ms (6D) a pair: fewer poses of those kinds
const POLYTOPE_PAIR = (ka, kb) => ka === 'mesh' && kb !== 'floor' && kb !== 'slope' && kb !== 'ball' || kb === 'mesh' && ka === 'box' ||
  ka === 'capsule' && (kb === 'box' || kb === 'mesh') || kb === 'capsule' && ka === 'box';
const sets = [];
for (let n = 2; n <= 6; n += 1) {
  const D = dims(n);
  const up = new Array(n).fill(0);
  up[1] = 1;
  const shapes = {
    box: HyperBox(D, Array.from({ length: n }, (_, i) => 0.5 + 0.1 * i)),
    cube: HyperBox(D, new Array(n).fill(0.5)),
    ball: HyperSphere(D, 0.6),
    floor: HalfSpace(D, up, 0),
    slope: HalfSpace(D, Array.from({ length: n }, (_, i) => (i === 1 ? 1 : 0.1 * (i + 1))), 0.3),
    mesh: crossPolytope(D, 0.8),
    torus: n >= 3 ? HyperTorus(D, 1, 0.3, [0, 2]) : null,
    capsule: HyperCapsule(D, 0.5, 0.3),
  };
  const pairs = [];
  const per = n >= 5 ? 12 : 24;
  for (const [ka, kb] of KINDS) {
    if (!shapes[ka] || !shapes[kb]) continue;
    const count = POLYTOPE_PAIR(ka, kb) ? (n === 6 ? 1 : n === 5 ? 2 : 6) : per;
    for (let t = 0; t < count; t += 1) {
      const pa = E.createPose(n);
      const pb = E.createPose(n);
      const amount = [0, 0.05, 1.5, 0.3][t % 4];
      pa.M.set(rotation(n, amount));
      pb.M.set(rotation(n, amount));
      for (let i = 0; i < n; i += 1) {
        pa.x[i] = (rand() - 0.5) * 0.6;
        pb.x[i] = pa.x[i] + (rand() - 0.5) * (t % 4 === 0 ? 0.4 : 1.2);
      }
      pb.x[1] = pa.x[1] + 0.8 + (rand() - 0.5) * 0.8;
      pairs.push({ A: shapes[ka], pa, B: shapes[kb], pb, margin: new Float64Array([[0, 0.01, 0.05, 0.3][(t >> 2) % 4]]) });
    }
  }
  // Four kinds (the half-spaces of a world are static and not bounded each step): V8 keeps up to
  // four maps per inline cache, the case where a kind-specific number field could load boxed.
  const bodies = [shapes.box, shapes.ball, shapes.torus, shapes.mesh].filter((s) => s).map((s) => ({ s, pose: pairs[0].pa }));
  sets.push({ n, pairs, bodies, scratch: E.createNarrowphaseScratch(n), out: E.createManifold(n), lo: new Float64Array(n), hi: new Float64Array(n) });
}
const margins = [0, 0.01, 0.05, 0.3];
let hits = 0;
function pass() {
  for (let k = 0; k < sets.length; k += 1) {
    const { n, pairs, bodies, scratch, out, lo, hi } = sets[k];
    for (let i = 0; i < pairs.length; i += 1) {
      const p = pairs[i];
      scratch.scalars[NARROWPHASE_MARGIN] = p.margin[0];
      if (collideScratch(out, n, p.A, p.pa, p.B, p.pb, scratch)) hits += 1;
      if (collide(out, n, p.A, p.pa, p.B, p.pb, margins[i & 3], scratch)) hits += 1;
    }
    for (let r = 0; r < 50; r += 1) {
      for (let i = 0; i < bodies.length; i += 1) computeBoundsUnchecked(lo, hi, n, bodies[i].s, bodies[i].pose.x, bodies[i].pose.M, 0);
    }
  }
}
const gcs = [];
const observer = new PerformanceObserver((list) => {
  for (const entry of list.getEntries()) gcs.push(entry.startTime);
});
observer.observe({ entryTypes: ['gc'] });
for (let w = 0; w < 120; w += 1) pass();
await new Promise((resolve) => setTimeout(resolve, 100));
for (let w = 0; w < 30; w += 1) pass();
const PASSES = 30;
const windows = [];
for (let w = 0; w < 5; w += 1) {
  globalThis.gc();
  globalThis.gc();
  await new Promise((resolve) => setTimeout(resolve, 50));
  const spacesBefore = v8.getHeapSpaceStatistics();
  const t0 = performance.now();
  const before = v8.getHeapStatistics().used_heap_size;
  for (let p = 0; p < PASSES; p += 1) pass();
  const after = v8.getHeapStatistics().used_heap_size;
  const t1 = performance.now();
  const spacesAfter = v8.getHeapSpaceStatistics();
  await new Promise((resolve) => setTimeout(resolve, 20));
  const spaces = {};
  for (let i = 0; i < spacesAfter.length; i += 1) {
    const grown = spacesAfter[i].space_used_size - spacesBefore[i].space_used_size;
    if (grown !== 0) spaces[spacesAfter[i].space_name] = grown;
  }
  // compiled code is the JIT's, never the colliders': a late compile is left out of the total
  const code = (spaces.code_space ?? 0) + (spaces.code_large_object_space ?? 0);
  windows.push({ bytes: after - before - code, newSpace: spaces.new_space ?? 0, spaces, collections: gcs.filter((g) => g >= t0 && g <= t1).length });
}
observer.disconnect();
let calls = 0;
for (const s of sets) calls += 2 * s.pairs.length + 50 * s.bodies.length;
console.log(JSON.stringify({ calls: calls * PASSES, hits, windows }));
`;

interface Window {
  bytes: number;
  newSpace: number;
  spaces: Record<string, number>;
  collections: number;
}
let result: { calls: number; hits: number; windows: Window[] } | undefined;

beforeAll(() => {
  ensureBuiltEngine();
  const out = execFileSync(
    process.execPath,
    [
      // Compiled where it is asked for, not by a background job that a loaded machine (the test
      // files side by side) finishes inside a window: such a job left 100-160 KB of old space in
      // each of the three windows of a run of the whole suite (the young generation: 12 KB); the
      // whole-heap check takes the least of five windows.
      '--no-concurrent-recompilation',
      '--expose-gc',
      '--max-semi-space-size=256',
      '--min-semi-space-size=64',
      '--input-type=module',
      '-e',
      SCRIPT,
      pathToFileURL(dist).href,
    ],
    { cwd: root, encoding: 'utf8' },
  );
  result = JSON.parse(out.trim().split('\n').pop()!) as typeof result;
});

describe('narrowphase allocates nothing in steady state (built engine, child process)', () => {
  it('collideScratch / collide over every pair kind and computeBoundsUnchecked over every shape kind, n = 2..6', () => {
    const r = result!;
    expect(r.calls).toBeGreaterThan(90_000);
    expect(r.hits).toBeGreaterThan(0);
    expect(r.windows.length).toBe(5);
    for (const w of r.windows) {
      expect(w.collections).toBe(0);
      expect(w.newSpace).toBeLessThan(64 * 1024);
    }
    expect(Math.min(...r.windows.map((w) => w.bytes)), JSON.stringify(r.windows)).toBeLessThan(64 * 1024);
  });
});
