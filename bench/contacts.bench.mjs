// Contact scenes: PhysiN vs Rapier (@dimforge/rapier3d-compat) and cannon-es in the same run, on
// the same start positions (scenes/layouts.mjs), then PhysiN alone in n dimensions.
//
// Scenes (unit boxes, mass 1, friction 0.5, restitution 0, ground y = 0, dt = 1/60, sleep off,
// 600 steps = 10 s):
//   stack9     9 boxes in one column          stands: top box drift < 0.01, |y − 8.5| < 0.02
//   pyramid20  Box2D pyramid, 20 at the base   stands: every box within 0.05 of its start
//   pile1000   1000 boxes dropped from a seeded 10×10×10 grid (time, and boxes below ground)
//   PhysiN only: stack9 and a pile of 300 in 4D, a stack of 5 in n = 2..6.
// PhysiN: default parameters (iterations 10) but allowSleep false. Rapier: default integration
// parameters, timestep 1/60. cannon-es: GSSolver 10 iterations, SAPBroadphase, allowSleep false.
//
// Timing: every step is timed alone with performance.now(); a cell is the MEDIAN over the steps
// of one run (600, started right after building; the median ignores the JIT warm-up of the first
// steps and the GC pauses). Before each timed run the engine steps a small throwaway pile of the
// same n (27 boxes, up to 150 steps or 1 s, untimed), so that the first scene of an engine or of
// a dimension does not pay for the JIT alone. A PhysiN run that exceeds its time budget is cut short: the table
// gives the steps it ran, and the scene is marked "capped" (its state at the last step it ran is
// shown, but it does not count as standing).
//
// Exit status: 0 when everything ran, whether or not the targets are met (they are reported in
// the last table); 1 if a peer or the built engine cannot be loaded, or a scene throws.
//
// Run: node bench/contacts.bench.mjs    (after the build: it imports the BUILT packages)
import { performance } from 'node:perf_hooks';
import { medianTable } from './lib/table.mjs';
import { STEPS, judge, pileLayout, peerLayouts, stackLayout } from './scenes/layouts.mjs';
import { buildCannonScene, buildRapierScene, loadCannon, loadRapier } from './scenes/peer-scenes.mjs';

/** Wall-clock budget of one PhysiN run (ms); beyond it the run stops early (reported as capped). */
const PHYSIN_BUDGET_MS = { small: 12_000, pile: 25_000 };

let RAPIER;
let CANNON;
try {
  RAPIER = await loadRapier();
  CANNON = await loadCannon();
} catch (error) {
  console.error(`contacts.bench: a peer failed to load (install: \`node scripts/pnpm.mjs install\` at the root): ${error?.stack ?? error}`);
  process.exit(1);
}
let physin;
try {
  physin = await import('./scenes/physin-scenes.mjs');
} catch (error) {
  console.error(`contacts.bench: cannot load the built engine (build it first: npm run build): ${error?.stack ?? error}`);
  process.exit(1);
}
const { buildPhysinScene } = physin;

let failures = 0;

/** Untimed warm-up: a small pile of the same n (ground, falling, box-box and box-ground contacts). */
function warmUp(build, n) {
  const scene = build(pileLayout(27, n, 3, 77, `warm-up ${n}D`));
  const end = performance.now() + 1000;
  for (let i = 0; i < 150 && performance.now() < end; i += 1) scene.step();
  scene.dispose?.();
}

/**
 * Steps `scene` up to `steps` times, timing each step alone; stops early once `budgetMs` of wall
 * clock has passed. Judges the end state only when every step ran.
 */
function run(layout, build, budgetMs = Infinity, steps = STEPS) {
  let scene;
  try {
    warmUp(build, layout.n);
  } catch (error) {
    return failed(layout, error);
  }
  const t0 = performance.now();
  try {
    scene = build(layout);
  } catch (error) {
    return failed(layout, error);
  }
  const buildMs = performance.now() - t0;
  const times = new Float64Array(steps);
  let done = 0;
  const start = performance.now();
  try {
    while (done < steps) {
      const a = performance.now();
      scene.step();
      const b = performance.now();
      times[done] = b - a;
      done += 1;
      if (b - start > budgetMs) break;
    }
  } catch (error) {
    scene.dispose?.();
    return failed(layout, error, done);
  }
  const sorted = times.subarray(0, done).sort();
  const q = (p) => sorted[Math.round((done - 1) * p)];
  let verdict = judge(layout, scene.positions());
  if (done < steps) verdict = { ...verdict, stands: null, measure: `capped at step ${done}: ${verdict.measure}` };
  scene.dispose?.();
  return { median: q(0.5), p10: q(0.1), p90: q(0.9), steps: done, capped: done < steps, buildMs, ...verdict };
}

function failed(layout, error, steps = 0) {
  failures += 1;
  console.error(`contacts.bench: ${layout.name} threw after ${steps} steps: ${error?.stack ?? error}`);
  return { median: NaN, p10: NaN, p90: NaN, steps, capped: true, stands: false, measure: `error: ${error?.message ?? error}`, error: true };
}

const standsCell = (r) => (r.error ? 'error' : r.capped ? 'capped' : r.stands === null ? '—' : r.stands ? 'yes' : 'NO');

// ---- 3D: PhysiN and the peers --------------------------------------------------------------
const engines = [
  { name: 'PhysiN', build: (layout) => buildPhysinScene(layout), budget: (layout) => (layout.kind === 'pile' ? PHYSIN_BUDGET_MS.pile : PHYSIN_BUDGET_MS.small) },
  { name: 'Rapier', build: (layout) => buildRapierScene(RAPIER, layout), budget: () => Infinity },
  { name: 'cannon-es', build: (layout) => buildCannonScene(CANNON, layout), budget: () => Infinity },
];
const results = {}; // results[scene][engine]
const rows = [];
for (const layout of peerLayouts()) {
  results[layout.name] = {};
  for (const engine of engines) {
    const r = run(layout, engine.build, engine.budget(layout));
    results[layout.name][engine.name] = r;
    rows.push({
      scene: layout.name,
      engine: engine.name,
      bodies: layout.positions.length,
      steps: r.steps,
      'ms/step (median)': r.median,
      p10: r.p10,
      p90: r.p90,
      stands: standsCell(r),
      'at the end': r.measure,
    });
  }
}
medianTable(`3D contact scenes: ms/step, median over the ${STEPS} steps of one run (each step timed alone)`, rows);

const ratio = (a, b) => (Number.isFinite(a) && Number.isFinite(b) && b > 0 ? a / b : NaN);
medianTable(
  '3D contact scenes: ratios of the median ms/step (below 1: PhysiN faster)',
  peerLayouts().map((layout) => {
    const r = results[layout.name];
    return {
      scene: layout.name,
      PhysiN: r.PhysiN.median,
      Rapier: r.Rapier.median,
      'cannon-es': r['cannon-es'].median,
      'PhysiN/Rapier': ratio(r.PhysiN.median, r.Rapier.median),
      'PhysiN/cannon-es': ratio(r.PhysiN.median, r['cannon-es'].median),
      note: r.PhysiN.capped ? `PhysiN capped at ${r.PhysiN.steps} steps` : '',
    };
  }),
);

// ---- PhysiN alone in n dimensions ------------------------------------------------------------
const physinOnly = [
  { layout: stackLayout(9, 4, 'stack9 4D'), versus: results.stack9.PhysiN, versusName: 'stack9 3D' },
  { layout: pileLayout(300, 4, 4, 1004, 'pile300 4D') },
  ...[2, 3, 4, 5, 6].map((n) => ({ layout: stackLayout(5, n, `stack5 ${n}D`) })),
];
const nRows = [];
const nResults = {};
for (const entry of physinOnly) {
  const { layout } = entry;
  const r = run(layout, (l) => buildPhysinScene(l), layout.kind === 'pile' ? PHYSIN_BUDGET_MS.pile : PHYSIN_BUDGET_MS.small);
  nResults[layout.name] = r;
  nRows.push({
    scene: layout.name,
    n: layout.n,
    bodies: layout.positions.length,
    steps: r.steps,
    'ms/step (median)': r.median,
    p10: r.p10,
    p90: r.p90,
    stands: standsCell(r),
    'at the end': r.measure,
  });
}
// Cost growth of the 5-box stack with n, relative to n = 3.
const base5 = nResults['stack5 3D'].median;
for (const row of nRows) {
  row['vs 3D'] = row.scene.startsWith('stack5') ? ratio(row['ms/step (median)'], base5) : row.scene === 'stack9 4D' ? ratio(row['ms/step (median)'], results.stack9.PhysiN.median) : '—';
}
medianTable(`PhysiN in n dimensions: ms/step, median over the ${STEPS} steps of one run ("vs 3D": the same scene in 3D)`, nRows);

// ---- Targets ----------------------------------------------------------------------------------
const P = (scene) => results[scene].PhysiN;
const yesNo = (ok) => (ok ? 'yes' : 'NO');
const fmtRatio = (x) => (Number.isFinite(x) ? `${x.toPrecision(3)}×` : 'n/a');
const targets = [];
const within = (label, a, b, limit) => {
  const x = ratio(a, b);
  targets.push({ target: label, measured: fmtRatio(x), limit: `≤ ${limit}×`, met: yesNo(x <= limit) });
};
const standing = (scene) => {
  const r = P(scene);
  targets.push({ target: `${scene} stands (PhysiN, 10 s)`, measured: r.measure, limit: 'stands', met: yesNo(r.stands === true && !r.capped) });
};
within('stack9: PhysiN / Rapier ms/step', P('stack9').median, results.stack9.Rapier.median, 2);
standing('stack9');
within('pyramid20: PhysiN / Rapier ms/step', P('pyramid20').median, results.pyramid20.Rapier.median, 2);
standing('pyramid20');
within('pile1000: PhysiN / Rapier ms/step', P('pile1000').median, results.pile1000.Rapier.median, 3);
for (const scene of ['stack9', 'pyramid20', 'pile1000']) {
  const x = ratio(P(scene).median, results[scene]['cannon-es'].median);
  targets.push({ target: `${scene}: faster than cannon-es`, measured: fmtRatio(x), limit: '< 1×', met: yesNo(x < 1) });
}
within('stack9 4D / stack9 3D (PhysiN ms/step)', nResults['stack9 4D'].median, P('stack9').median, 2);
medianTable('Targets (medians of ms/step; reported, not asserted)', targets);

const physinRuns = [...Object.values(results).map((r) => r.PhysiN), ...Object.values(nResults)];
const sunk = physinRuns.filter((r) => r.below > 0).length;
if (sunk > 0) console.log(`\nPhysiN: ${sunk} of ${physinRuns.length} runs ended with boxes below the ground (no contacts in World.step?): read their times as integration only.`);
const capped = [...Object.values(results).map((r) => r.PhysiN), ...Object.values(nResults)].some((r) => r.capped && !r.error);
if (capped) console.log(`\nSome PhysiN runs were cut short by their time budget (${PHYSIN_BUDGET_MS.small / 1000} s, piles ${PHYSIN_BUDGET_MS.pile / 1000} s): their medians cover the steps they ran.`);
if (failures > 0) {
  console.error(`\ncontacts.bench: ${failures} scene(s) threw (see above)`);
  process.exit(1);
}
