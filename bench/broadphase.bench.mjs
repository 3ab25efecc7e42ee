// Broadphase update cost per step on pile-like scenes: 1000 boxes in 3D, 300 in 4D, resting on a
// half-space in touching columns and moving a little every step (each box sways about its rest
// place, some far enough to leave their fattened box now and then). The "stirred" scenes move
// every box by up to 0.05 per step, so most leave their fattened box every few steps. One step = moveProxy for every
// box + updatePairs. Both structures are measured in the same run: the dynamic AABB tree (the
// default) and sweep-and-prune on the axis of largest variance.
//
// Run: node bench/broadphase.bench.mjs    (after `npm run build`: it imports the BUILT engine)
// Prints a markdown table of per-step times (median, p10, p90 over the timed steps, ms).

const engine = await import('@physin/engine').catch(() => ({}));
const createBroadphase =
  engine.createBroadphase ??
  (
    await import('../packages/engine/dist/collision/broadphase.js').catch(() => {
      console.error('broadphase.bench: build the engine first (npm run build)');
      process.exit(1);
    })
  ).createBroadphase;

const WARMUP_STEPS = 200;
const TIMED_STEPS = 600;
const MARGIN = 0.1;

/** mulberry32, as tests/support/random.ts: the scenes are the same on every run. */
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

/**
 * A pile: columns on a grid of the n−1 horizontal axes, `height` boxes high along axis 1 (up),
 * unit spacing, half extents 0.5 ± 5 %, so neighbours touch. Returns rest centres, half extents
 * and per-box sway (amplitude and phase per axis).
 */
function makePile(n, columnsPerAxis, height, seed, stirred = false) {
  const rand = seeded(seed);
  const horizontal = [];
  for (let k = 0; k < n; k += 1) if (k !== 1) horizontal.push(k);
  const columns = columnsPerAxis ** horizontal.length;
  const boxes = [];
  for (let c = 0; c < columns; c += 1) {
    for (let level = 0; level < height; level += 1) {
      const centre = new Float64Array(n);
      let rest = c;
      for (const k of horizontal) {
        centre[k] = (rest % columnsPerAxis) * 1.0 + (rand() - 0.5) * 0.05;
        rest = Math.floor(rest / columnsPerAxis);
      }
      centre[1] = 0.5 + level * 1.0;
      const half = Float64Array.from({ length: n }, () => 0.5 * (0.95 + 0.1 * rand()));
      // Resting: most boxes sway by a few mm, one in five by up to 0.15 (beyond the 0.1 margin).
      // Stirred: every box sways by up to 1 (speed up to 0.05 per step), the tree's bad case.
      const big = rand() < 0.2;
      const reach = stirred ? 1 : big ? 0.15 : 0.02;
      const amplitude = Float64Array.from({ length: n }, () => reach * rand());
      const phase = Float64Array.from({ length: n }, () => 2 * Math.PI * rand());
      boxes.push({ centre, half, amplitude, phase });
    }
  }
  return boxes;
}

function median(sorted, q) {
  const i = Math.min(sorted.length - 1, Math.max(0, Math.round(q * (sorted.length - 1))));
  return sorted[i];
}

function run(kind, n, boxes) {
  const bp = createBroadphase(n, { margin: MARGIN }, kind);
  const lo = new Float64Array(n);
  const hi = new Float64Array(n);
  const place = (b, t) => {
    for (let k = 0; k < n; k += 1) {
      const c = b.centre[k] + b.amplitude[k] * Math.sin(0.05 * t + b.phase[k]);
      lo[k] = c - b.half[k];
      hi[k] = c + b.half[k];
    }
  };
  const ids = boxes.map((b) => {
    place(b, 0);
    return bp.createProxy(lo, hi);
  });
  const up = new Float64Array(n);
  up[1] = 1;
  bp.createHalfSpaceProxy(up, 0);
  let t = 0;
  const step = () => {
    t += 1;
    for (let i = 0; i < boxes.length; i += 1) {
      place(boxes[i], t);
      bp.moveProxy(ids[i], lo, hi);
    }
    return bp.updatePairs();
  };
  for (let s = 0; s < WARMUP_STEPS; s += 1) step();
  const times = new Float64Array(TIMED_STEPS);
  let moved = 0;
  let pairs = 0;
  let visited = 0;
  for (let s = 0; s < TIMED_STEPS; s += 1) {
    const t0 = performance.now();
    pairs = step();
    times[s] = performance.now() - t0;
    moved += bp.stats.moved;
    visited += bp.stats.nodesVisited;
  }
  times.sort();
  return {
    median: median(times, 0.5),
    p10: median(times, 0.1),
    p90: median(times, 0.9),
    pairs,
    movedPerStep: moved / TIMED_STEPS,
    visitedPerStep: visited / TIMED_STEPS,
  };
}

const scenes = [
  { name: '3D pile, 1000 boxes', n: 3, boxes: makePile(3, 10, 10, 3) },
  // 5×5×5 columns × 3 levels = 375 boxes; the first 300 are 100 whole columns.
  { name: '4D pile, 300 boxes', n: 4, boxes: makePile(4, 5, 3, 4).slice(0, 300) },
  { name: '3D stirred pile, 1000 boxes', n: 3, boxes: makePile(3, 10, 10, 3, true) },
  { name: '4D stirred pile, 300 boxes', n: 4, boxes: makePile(4, 5, 3, 4, true).slice(0, 300) },
];

console.log(`node ${process.version}; ${WARMUP_STEPS} warm-up steps, ${TIMED_STEPS} timed; margin ${MARGIN}`);
console.log('');
console.log('| scene | broadphase | median ms/step | p10 | p90 | pairs | proxies moved/step | nodes or entries visited/step |');
console.log('|---|---|---|---|---|---|---|---|');
for (const scene of scenes) {
  for (const kind of ['tree', 'sap']) {
    const r = run(kind, scene.n, scene.boxes);
    console.log(
      `| ${scene.name} | ${kind} | ${r.median.toFixed(3)} | ${r.p10.toFixed(3)} | ${r.p90.toFixed(3)} | ${r.pairs} | ${r.movedPerStep.toFixed(1)} | ${Math.round(r.visitedPerStep)} |`,
    );
  }
}
