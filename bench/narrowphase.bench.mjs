// Narrowphase cost: the box–box separating-axis test (C(2n, n−1) candidate axes: 4, 15, 56, 210,
// 792) and the full box–box manifold (SAT + clipping + reduction) for n = 2..6, on seeded inputs:
//   resting   — a box on a larger one, tilted by up to 0.01 rad and shifted: a face contact, so
//               the SAT visits every axis and the clipper produces the whole face;
//   random    — overlapping boxes at random orientations (face and mixed axes);
//   separated — random orientations, apart along a random direction (early exit on some axis).
// In 3D the closed-form path (boxBoxSat3) and the general-n path (boxBoxSatGeneral) are both
// measured on the same inputs. Also: sphere–box and box–half-space for reference.
//
// Run: node bench/narrowphase.bench.mjs   (imports the BUILT @physin/engine: build first)
// Prints ns/call medians (25 batches of ≈ 2 ms).

import { medianTable, timeOp } from './lib/table.mjs';
import { randomArray, seeded } from './lib/random.mjs';

const engine = await import('@physin/engine').catch(() => ({}));
const np =
  typeof engine.collideBoxBox === 'function'
    ? engine
    : await import('../packages/engine/dist/collision/narrowphase.js').catch(() => {
        console.error('narrowphase.bench: build the engine first (npx --yes pnpm@12.21.0 -r --filter ./packages/** run build)');
        process.exit(1);
      });
const {
  boxBoxSat,
  boxBoxSat3,
  boxBoxSatGeneral,
  collideBoxBox,
  collideBoxHalfSpace,
  collideBoxSphere,
  createManifold,
  createNarrowphaseScratch,
  satAxisCount,
} = np;

const POOL = 16; // inputs cycled through per benchmark (a power of two)
const MARGIN = 0.02;
const rand = seeded(20240717);

function turn(n, M, i, j, angle) {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  for (let col = 0; col < n; col += 1) {
    const a = M[i * n + col];
    const b = M[j * n + col];
    M[i * n + col] = c * a - s * b;
    M[j * n + col] = s * a + c * b;
  }
}

function pose(n, tiltRange) {
  const M = new Float64Array(n * n);
  for (let i = 0; i < n; i += 1) M[i * n + i] = 1;
  for (let i = 0; i < n; i += 1) for (let j = i + 1; j < n; j += 1) turn(n, M, i, j, (rand() * 2 - 1) * tiltRange);
  return { x: new Float64Array(n), M };
}

const box = (half) => ({ kind: 'box', halfExtents: half });

function inputs(n, scene) {
  const A = [];
  const PA = [];
  const B = [];
  const PB = [];
  for (let k = 0; k < POOL; k += 1) {
    if (scene === 'resting') {
      A.push(box(new Float64Array(n).fill(2)));
      PA.push(pose(n, 0));
      const pb = pose(n, 0.01);
      pb.x.set(randomArray(rand, n, -0.5, 0.5));
      pb.x[1] = 2 + 0.5 - 0.01;
      B.push(box(new Float64Array(n).fill(0.5)));
      PB.push(pb);
    } else {
      A.push(box(randomArray(rand, n, 0.4, 1)));
      B.push(box(randomArray(rand, n, 0.4, 1)));
      PA.push(pose(n, Math.PI));
      const pb = pose(n, Math.PI);
      const dir = randomArray(rand, n, -1, 1);
      const len = Math.hypot(...dir);
      const dist = scene === 'random' ? 0.8 : 3 + rand();
      for (let c = 0; c < n; c += 1) pb.x[c] = (dist * dir[c]) / len;
      PB.push(pb);
    }
  }
  return { A, PA, B, PB };
}

const rows = [];
const manifoldRows = [];
for (let n = 2; n <= 6; n += 1) {
  const scratch = createNarrowphaseScratch(n);
  const outs = Array.from({ length: POOL }, () => createManifold(n));
  const ns = Array(POOL).fill(n);
  const margins = Array(POOL).fill(MARGIN);
  const scratches = Array(POOL).fill(scratch);
  const row = { n, axes: satAxisCount(n) };
  for (const scene of ['resting', 'random', 'separated']) {
    const { A, PA, B, PB } = inputs(n, scene);
    row[`SAT ${scene} ns`] = timeOp(boxBoxSat, [ns, A, PA, B, PB, margins, scratches]).median;
    if (n === 3) {
      row[`3D general ${scene} ns`] = timeOp(boxBoxSatGeneral, [ns, A, PA, B, PB, margins, scratches]).median;
    }
    const manifold = timeOp(collideBoxBox, [outs, ns, A, PA, B, PB, margins, scratches]).median;
    let points = 0;
    for (let k = 0; k < POOL; k += 1) {
      collideBoxBox(outs[k], n, A[k], PA[k], B[k], PB[k], MARGIN, scratch);
      points += outs[k].count;
    }
    if (scene !== 'separated') manifoldRows.push({ n, scene, 'collideBoxBox ns': manifold, 'mean points': points / POOL });
  }
  rows.push(row);
}
// the 3D columns only exist for n = 3: fill the others so the table stays rectangular
for (const row of rows) {
  for (const scene of ['resting', 'random', 'separated']) {
    const key = `3D general ${scene} ns`;
    if (!(key in row)) row[key] = '–';
  }
}
medianTable(
  'Box–box SAT, ns/call (median of 25 batches); n = 3 uses the closed form, the "3D general" columns the general-n path on the same inputs',
  rows,
);
medianTable('Box–box manifold (SAT + clip + reduce), ns/call (median of 25 batches)', manifoldRows);

// 3D closed form vs general on the resting and random inputs, directly
{
  const n = 3;
  const scratch = createNarrowphaseScratch(n);
  const { A, PA, B, PB } = inputs(n, 'random');
  const margins = Array(POOL).fill(MARGIN);
  const scratches = Array(POOL).fill(scratch);
  const fast = timeOp(boxBoxSat3, [A, PA, B, PB, margins, scratches]).median;
  const general = timeOp(boxBoxSatGeneral, [Array(POOL).fill(n), A, PA, B, PB, margins, scratches]).median;
  medianTable('3D SAT on random overlapping boxes, ns/call (median)', [
    { path: 'boxBoxSat3 (closed form)', ns: fast, 'ratio general / closed form': general / fast },
    { path: 'boxBoxSatGeneral', ns: general, 'ratio general / closed form': 1 },
  ]);
}

// simpler pairs for reference
{
  const other = [];
  for (let n = 2; n <= 6; n += 1) {
    const scratch = createNarrowphaseScratch(n);
    const outs = Array.from({ length: POOL }, () => createManifold(n));
    const { A, PA, B, PB } = inputs(n, 'resting');
    const spheres = Array.from({ length: POOL }, () => ({ kind: 'sphere', radius: 0.6 }));
    const normal = new Float64Array(n);
    normal[1] = 1;
    const floors = Array(POOL).fill({ kind: 'halfspace', normal, offset: 2.01 });
    const ns = Array(POOL).fill(n);
    const margins = Array(POOL).fill(MARGIN);
    const scratches = Array(POOL).fill(scratch);
    other.push({
      n,
      'box–sphere ns': timeOp(collideBoxSphere, [outs, ns, A, PA, spheres, PB, margins, scratches]).median,
      'box–half-space ns': timeOp(collideBoxHalfSpace, [outs, ns, B, PB, floors, PA, margins, scratches]).median,
    });
  }
  medianTable(
    'Other pairs, ns/call (median of 25 batches): box–sphere (ball overlapping a face), box–half-space (box resting flat)',
    other,
  );
}
