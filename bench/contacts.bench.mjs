// Contact scenes: PhysiN vs Rapier (@dimforge/rapier3d-compat) and cannon-es in the same run, on
// the same start positions (scenes/layouts.mjs), then PhysiN alone in n dimensions.
//
// Scenes (unit boxes, mass 1, friction 0.5, restitution 0, ground y = 0, dt = 1/60, sleep off,
// 600 steps = 10 s):
//   stack9     9 boxes in one column          stands: top box drift < 0.01, |y − 8.5| < 0.02
//   pyramid20  Box2D pyramid, 20 at the base   stands: every box within 0.05 of its start
//   pile1000   1000 boxes dropped from a seeded 10×10×10 grid (time, and boxes below ground)
//   pyramid100 Box2D v3's large pyramid, 100 at the base = 5,050 boxes (beside Rapier alone, one
//              round; Box2D v3's published 3.9 ms/step, native and one thread, is printed beside it)
//   PhysiN only: stack9 and a pile of 300 in 4D, a stack of 5 in n = 2..6.
// PhysiN: default parameters (iterations 10) but allowSleep false. Rapier: default integration
// parameters, timestep 1/60. cannon-es: GSSolver 10 iterations, SAPBroadphase, allowSleep false.
//
// Timing: every step is timed alone with performance.now(); a cell is the MEDIAN over the steps
// of a run (600, started right after building; the median ignores the JIT warm-up of the first
// steps and the GC pauses). PhysiN and one peer run in turns of 50 steps (bench/lib/turns.mjs), so that
// the drift of a shared machine's speed falls on both alike and their ratio is not a measure of
// the host; each peer has its own pair (see ROUNDS below). stack9 and pyramid20 are run 3 times
// and the median run is reported. The n-D ratios are taken the same way (stack9 4D in turns with
// stack9 3D; the stacks of 5 together).
// Before each run an engine steps a small throwaway pile of the same n (27 boxes, up to 150 steps
// or 1 s, untimed), so that the first scene of an engine or of a dimension does not pay for the
// JIT alone. A PhysiN run that exceeds its time budget is cut short: the table gives the steps it
// ran, and the scene is marked "capped" (its state at the last step it ran is shown, but it does
// not count as standing).
//
// Exit status: 0 when everything ran, whether or not the targets are met (they are reported in
// the last table); 1 if a peer or the built engine cannot be loaded, or a scene throws.
//
// Run: node bench/contacts.bench.mjs    (after the build: it imports the BUILT packages)
// Only some scenes: CONTACTS_SCENES='stack9 4D' (comma-separated scene names) runs the 3D scenes
// named and the n-D groups holding a scene named (a group runs whole: its ratio needs its peers);
// CONTACTS_ROUNDS overrides the rounds of every scene run.
import { performance } from 'node:perf_hooks';
import { medianTable } from './lib/table.mjs';
import { TURN_STEPS, runRoundsInTurns } from './lib/turns.mjs';
import { STEPS, judge, pileLayout, peerLayouts, stackLayout } from './scenes/layouts.mjs';
import { buildCannonScene, buildRapierScene, loadCannon, loadRapier } from './scenes/peer-scenes.mjs';

/** CONTACTS_SCENES: the scene names to run (undefined: all). */
const ONLY = process.env.CONTACTS_SCENES?.split(',')
  .map((name) => name.trim())
  .filter(Boolean);
const wanted = (name) => ONLY === undefined || ONLY.includes(name);
/** CONTACTS_ROUNDS: rounds of every scene (undefined: each scene's own). */
const ROUNDS_OVERRIDE = process.env.CONTACTS_ROUNDS === undefined ? undefined : Number(process.env.CONTACTS_ROUNDS);

/** Wall-clock budget of one PhysiN run (ms); beyond it the run stops early (reported as capped). */
const PHYSIN_BUDGET_MS = { small: 12_000, pile: 25_000, large: 60_000 };
/** Box2D v3's published time for its large pyramid (ms/step, native, one thread): a reference, not a run. */
const BOX2D_LARGE_PYRAMID_MS = 3.9;

let RAPIER;
let CANNON;
try {
  RAPIER = await loadRapier();
  CANNON = await loadCannon();
} catch (error) {
  console.error(
    `contacts.bench: a peer failed to load (install: \`node scripts/pnpm.mjs install\` at the root): ${error?.stack ?? error}`,
  );
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
 * A lane of bench/lib/turns.mjs: `build(layout)` of one engine, warmed up on a small pile of the
 * same n, judged at the end (a capped run does not count as standing).
 */
function lane(layout, build, budgetMs) {
  return {
    label: layout.name,
    prepare: () => warmUp(build, layout.n),
    build: () => build(layout),
    step: (scene) => scene.step(),
    finish: (scene, capped) => {
      const verdict = judge(layout, scene.positions());
      return capped ? { ...verdict, stands: null, measure: `capped: ${verdict.measure}` } : verdict;
    },
    budgetMs,
  };
}

/** runRoundsInTurns over `lanes` (one per layout), with the failures reported by layout. */
function runRounds(lanes, rounds) {
  return runRoundsInTurns(lanes, rounds, { steps: STEPS }).map((r, i) =>
    r.error !== undefined ? { ...failed(lanes[i].label, r.error, r.steps), rounds } : r,
  );
}

function failed(label, error, steps = 0) {
  failures += 1;
  console.error(`contacts.bench: ${label} threw after ${steps} steps: ${error?.stack ?? error}`);
  return {
    median: NaN,
    p10: NaN,
    p90: NaN,
    steps,
    capped: true,
    stands: false,
    measure: `error: ${error?.message ?? error}`,
    error: true,
  };
}

/** The cells of a table row that describe one run's result. */
const resultCells = (layout, r) => ({
  bodies: layout.positions.length,
  rounds: r.rounds,
  steps: r.steps,
  'ms/step (median)': r.median,
  p10: r.p10,
  p90: r.p90,
  stands: standsCell(r),
  'at the end': r.measure,
});
const standsCell = (r) => (r.error ? 'error' : r.capped ? 'capped' : r.stands === null ? '—' : r.stands ? 'yes' : 'NO');

// ---- 3D: PhysiN and the peers --------------------------------------------------------------
const engines = [
  {
    name: 'PhysiN',
    build: (layout) => buildPhysinScene(layout),
    budget: (layout) =>
      layout.positions.length > 1000
        ? PHYSIN_BUDGET_MS.large
        : layout.kind === 'pile'
          ? PHYSIN_BUDGET_MS.pile
          : PHYSIN_BUDGET_MS.small,
  },
  { name: 'Rapier', build: (layout) => buildRapierScene(RAPIER, layout), budget: () => Infinity },
  { name: 'cannon-es', build: (layout) => buildCannonScene(CANNON, layout), budget: () => Infinity },
];
/** Rounds per 3D scene: the median round is reported. The pile takes a minute a round, so one. */
const ROUNDS = { stack: 3, pyramid: 3, pile: 1 };
// PhysiN runs in turns with one peer at a time: cannon-es makes much garbage, and its collection
// slowed whatever ran beside it (Rapier and PhysiN alike, up to 1.6×), so each ratio comes from a
// pair that shares nothing else. PhysiN's row beside cannon-es is reported as "PhysiN (2)".
const [PHYSIN, ...PEERS] = engines;
const results = {}; // results[scene][engine]; results[scene]['PhysiN vs ' + peer]
const rows = [];
const layouts3D = peerLayouts().filter((layout) => wanted(layout.name));
for (const layout of layouts3D) {
  results[layout.name] = {};
  const laneOf = (engine) => lane(layout, engine.build, engine.budget(layout));
  PEERS.filter((peer) => layout.peers === undefined || layout.peers.includes(peer.name)).forEach((peer, p) => {
    const rounds = ROUNDS_OVERRIDE ?? layout.rounds ?? ROUNDS[layout.kind] ?? 1;
    const [mine, theirs] = runRounds([laneOf(PHYSIN), laneOf(peer)], rounds);
    results[layout.name][`PhysiN vs ${peer.name}`] = mine;
    if (p === 0) results[layout.name].PhysiN = mine;
    results[layout.name][peer.name] = theirs;
    for (const [label, r] of [
      [p === 0 ? 'PhysiN' : `PhysiN (${p + 1})`, mine],
      [peer.name, theirs],
    ]) {
      rows.push({
        scene: layout.name,
        engine: label,
        'in turns with': label === peer.name ? 'PhysiN' : peer.name,
        ...resultCells(layout, r),
      });
    }
  });
}
if (rows.length > 0)
  medianTable(
    `3D contact scenes: ms/step, median over the ${STEPS} steps of a run (each step timed alone; engines in turns of ${TURN_STEPS} steps; the median of \`rounds\` runs)`,
    rows,
  );

const ratio = (a, b) => (Number.isFinite(a) && Number.isFinite(b) && b > 0 ? a / b : NaN);
if (layouts3D.length > 0)
  medianTable(
    '3D contact scenes: ratios of the median ms/step, each against the PhysiN run that shared its turns (below 1: PhysiN faster)',
    layouts3D.map((layout) => {
      const r = results[layout.name];
      const capped = [r['PhysiN vs Rapier'], r['PhysiN vs cannon-es']].filter((x) => x?.capped);
      const notes = capped.length > 0 ? [`PhysiN capped at ${capped[0].steps} steps`] : [];
      if (layout.name === 'pyramid100') notes.push(`Box2D v3 (published, native, 1 thread): ${BOX2D_LARGE_PYRAMID_MS} ms`);
      return {
        scene: layout.name,
        'PhysiN (turns with Rapier)': r['PhysiN vs Rapier']?.median ?? NaN,
        Rapier: r.Rapier?.median ?? NaN,
        'PhysiN/Rapier': ratio(r['PhysiN vs Rapier']?.median, r.Rapier?.median),
        'PhysiN (turns with cannon-es)': r['PhysiN vs cannon-es']?.median ?? NaN,
        'cannon-es': r['cannon-es']?.median ?? NaN,
        'PhysiN/cannon-es': ratio(r['PhysiN vs cannon-es']?.median, r['cannon-es']?.median),
        note: notes.join('; '),
      };
    }),
  );

// ---- PhysiN alone in n dimensions ------------------------------------------------------------
// Each group runs in turns (bench/lib/turns.mjs), so a ratio inside a group compares the same minutes:
// stack9 4D beside a fresh stack9 3D, and the five stacks of 5 together.
const physinLane = (layout) =>
  lane(layout, (l) => buildPhysinScene(l), layout.kind === 'pile' ? PHYSIN_BUDGET_MS.pile : PHYSIN_BUDGET_MS.small);
const nGroups = [
  { layouts: [stackLayout(9, 4, 'stack9 4D'), stackLayout(9, 3, 'stack9 3D')], rounds: 3 },
  { layouts: [pileLayout(300, 4, 4, 1004, 'pile300 4D')], rounds: 1 },
  { layouts: [2, 3, 4, 5, 6].map((n) => stackLayout(5, n, `stack5 ${n}D`)), rounds: 3 },
];
const nRows = [];
const nResults = {};
for (const group of nGroups.filter((g) => g.layouts.some((layout) => wanted(layout.name)))) {
  const groupResults = runRounds(group.layouts.map(physinLane), ROUNDS_OVERRIDE ?? group.rounds);
  group.layouts.forEach((layout, i) => {
    const r = groupResults[i];
    nResults[layout.name] = r;
    nRows.push({ scene: layout.name, n: layout.n, ...resultCells(layout, r) });
  });
}
// Cost growth of the 5-box stack with n, relative to n = 3.
const base5 = nResults['stack5 3D']?.median;
for (const row of nRows) {
  row['vs 3D'] = row.scene.startsWith('stack5')
    ? ratio(row['ms/step (median)'], base5)
    : row.scene === 'stack9 4D'
      ? ratio(row['ms/step (median)'], nResults['stack9 3D']?.median)
      : '—';
}
if (nRows.length > 0)
  medianTable(
    `PhysiN in n dimensions: ms/step, median over the ${STEPS} steps of a run ("vs 3D": the same scene in 3D, run in the same turns)`,
    nRows,
  );

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
  targets.push({
    target: `${scene} stands (PhysiN, 10 s)`,
    measured: r.measure,
    limit: 'stands',
    met: yesNo(r.stands === true && !r.capped),
  });
};
// the goals of the scale work: Rapier's time or less on every 3D scene, 4D at most 1.5× our 3D
const limits3D = { stack9: 1, pyramid20: 1, pile1000: 1, pyramid100: 1 };
for (const layout of layouts3D) {
  const scene = layout.name;
  within(
    `${scene}: PhysiN / Rapier ms/step`,
    results[scene]['PhysiN vs Rapier'].median,
    results[scene].Rapier.median,
    limits3D[scene],
  );
  if (layout.kind !== 'pile') standing(scene);
}
for (const { name: scene } of layouts3D) {
  if (results[scene]['PhysiN vs cannon-es'] === undefined) continue;
  const x = ratio(results[scene]['PhysiN vs cannon-es'].median, results[scene]['cannon-es'].median);
  targets.push({ target: `${scene}: faster than cannon-es`, measured: fmtRatio(x), limit: '< 1×', met: yesNo(x < 1) });
}
if (nResults['stack9 4D'] !== undefined)
  within('stack9 4D / stack9 3D (PhysiN ms/step, same turns)', nResults['stack9 4D'].median, nResults['stack9 3D'].median, 1.5);
medianTable('Targets (medians of ms/step; reported, not asserted)', targets);

const physinRuns = [...Object.values(results).map((r) => r.PhysiN), ...Object.values(nResults)];
const sunk = physinRuns.filter((r) => r.below > 0).length;
if (sunk > 0)
  console.log(
    `\nPhysiN: ${sunk} of ${physinRuns.length} runs ended with boxes below the ground (no contacts in World.step?): read their times as integration only.`,
  );
const capped = [...Object.values(results).map((r) => r.PhysiN), ...Object.values(nResults)].some((r) => r.capped && !r.error);
if (capped)
  console.log(
    `\nSome PhysiN runs were cut short by their time budget (${PHYSIN_BUDGET_MS.small / 1000} s, piles ${PHYSIN_BUDGET_MS.pile / 1000} s): their medians cover the steps they ran.`,
  );
if (failures > 0) {
  console.error(`\ncontacts.bench: ${failures} scene(s) threw (see above)`);
  process.exit(1);
}
