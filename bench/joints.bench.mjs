// Joint scenes: PhysiN vs Rapier (@dimforge/rapier3d-compat) and cannon-es in the same run, on the
// same starts (scenes/joint-scenes.mjs), then PhysiN alone in 4D.
//
// Scenes (gravity −9.81 e_1, dt 1/60, 600 steps = 10 s, sleep off):
//   chain10 whip   the specification's chain of 10 links (1 kg, 1 m apart, first link to the world), starting
//                  horizontal: it whips. The reference: worst joint error 0.23 in Rapier 0.21,
//                  0.40 in cannon-es 0.20, 0.114 claimed by the specification.
//   chain10 hang   the same chain starting hanging (it settles).
//   grid20         Box2D's "joint grid" scaled down: 20 × 20 balls (r 0.25, 1 kg, 1 m apart) in the
//                  horizontal x-z plane, point joints to the right and "down" (+z) neighbours, the row
//                  z = 0 pinned to the world; it swings down about that row.
//   chain10 4D     the whipping chain in 4D (PhysiN only).
// PhysiN: default parameters (iterations 10, subSteps 1) but allowSleep false; an extra row with
// subSteps 4 for the chains, and rows with constraintProjectionTolerance 1e-3 and 5e-3 (the position
// projection stops at 1 mm or 5 mm, a tenth or half of issue 19's goal of 0.01; the default, 0,
// projects to rounding). Rapier: default integration parameters, timestep 1/60, spherical
// impulse joints. cannon-es: GSSolver 10 iterations, SAPBroadphase, PointToPointConstraint.
// Contacts between the two bodies of a joint are off in every engine.
//
// Measures: ms/step is the MEDIAN over the individually timed steps of a run (p10 and p90 beside
// it). PhysiN runs in turns of 50 steps with one peer at a time (bench/lib/turns.mjs), so the drift
// of a shared machine's speed falls on both engines of a ratio; the 4D chains run in turns with the
// same 3D chains. The joint error (distance between the world positions of a joint's two anchors,
// computed from the bodies' poses after each step, outside the timing) is the worst over every
// joint and step, and its value at the last step. Before each timed run the engine steps a small
// chain untimed (60 steps) so the first scene does not pay for the JIT alone. The energy columns
// (kinetic + m g y, J) say what a method paid for its accuracy: ΔE at 10 s (negative: energy lost,
// e.g. to a position projection) and the largest rise above the start (positive: energy put in).
// Runs are cut short after a wall-clock budget (marked capped).
//
// Exit status: 0 when everything ran, whether or not the targets are met (they are reported in the
// last table); 1 if a peer or the built engine cannot be loaded, or a scene throws.
//
// Run: node bench/joints.bench.mjs    (after the build: it imports the BUILT packages)
// Env: JOINTS_BENCH_SCENES=<comma-separated list of chain10 whip, chain10 hang, grid20, 4D> runs only
// those groups (e.g. `JOINTS_BENCH_SCENES=grid20 node --cpu-prof bench/joints.bench.mjs` to profile
// one scene); the ratio and target tables then list only what ran.
import { medianTable } from './lib/table.mjs';
import { runRoundsInTurns } from './lib/turns.mjs';
import { loadCannon, loadRapier } from './scenes/peer-scenes.mjs';

const DT = 1 / 60;
const STEPS = 600;
const BUDGET_MS = 20_000;

let RAPIER;
let CANNON;
try {
  RAPIER = await loadRapier();
  CANNON = await loadCannon();
} catch (error) {
  console.error(
    `joints.bench: a peer failed to load (install: \`node scripts/pnpm.mjs install\` at the root): ${error?.stack ?? error}`,
  );
  process.exit(1);
}
let S;
try {
  S = await import('./scenes/joint-scenes.mjs');
} catch (error) {
  console.error(
    `joints.bench: cannot load the built engine with joints (build it first: npm run build): ${error?.stack ?? error}`,
  );
  process.exit(1);
}

let failures = 0;

/**
 * A lane of bench/lib/turns.mjs for a joint scene: warmed up on a small chain (60 steps, untimed);
 * after each step the joint error and the energy are read (untimed).
 */
function lane(label, build, warm) {
  let worst = 0;
  let last = NaN;
  let e0 = NaN;
  let eMax = -Infinity;
  return {
    label,
    prepare: () => {
      const w = warm();
      for (let i = 0; i < 60; i += 1) w.step(DT);
      w.dispose();
    },
    build: () => {
      const scene = build();
      worst = 0;
      last = NaN;
      e0 = scene.energy();
      eMax = -Infinity;
      return scene;
    },
    step: (scene) => scene.step(DT),
    observe: (scene) => {
      last = scene.error();
      if (!(last <= worst)) worst = Number.isFinite(last) ? Math.max(worst, last) : Infinity;
      eMax = Math.max(eMax, scene.energy());
    },
    finish: (scene) => ({ worst, last, gain: eMax - e0, change: scene.energy() - e0 }),
    budgetMs: BUDGET_MS,
  };
}

/** Rounds of a group: the chains are cheap, so the median of 3; the grid once. */
const roundsOf = (entries) => (entries.some((r) => r.scene === 'grid20') ? 1 : 3);

/**
 * Runs `entries` (see `runs` below) in turns, `roundsOf` times, each lane's median round kept; a
 * lane that threw is reported and counted.
 */
function runTogether(entries) {
  const lanes = entries.map((r) => lane(`${r.scene} ${r.engine}`, r.build, r.warm));
  return runRoundsInTurns(lanes, roundsOf(entries), { steps: STEPS }).map((x, i) => {
    if (x.error === undefined) return x;
    failures += 1;
    console.error(
      `joints.bench: ${entries[i].scene} ${entries[i].engine} threw after ${x.steps} steps: ${x.error?.stack ?? x.error}`,
    );
    return {
      median: NaN,
      p10: NaN,
      p90: NaN,
      steps: x.steps,
      worst: NaN,
      last: NaN,
      capped: true,
      error: true,
      rounds: x.rounds,
    };
  });
}

const warmPhysin = () => S.physinChain({ n: 3 });
const warmRapier = () => S.rapierChain(RAPIER);
const warmCannon = () => S.cannonChain(CANNON);

/**
 * The goal is a worst error of 0.01: PhysiN also runs with its position projection
 * stopped at 1 mm (constraintProjectionTolerance; the default, 0, is rounding), a tenth of that goal.
 */
const LOOSE_TOLERANCE = 1e-3;
const LOOSE = 'PhysiN projection 1e-3';
/** And at 5 mm, half the goal: the cheapest setting that still meets it with a margin. */
const HALF_TOLERANCE = 5e-3;
const HALF = 'PhysiN projection 5e-3';

const runs = [
  {
    scene: 'chain10 whip',
    engine: 'PhysiN',
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'horizontal' }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 whip',
    engine: 'PhysiN subSteps 4',
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'horizontal', params: { subSteps: 4 } }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 whip',
    engine: LOOSE,
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'horizontal', params: { constraintProjectionTolerance: LOOSE_TOLERANCE } }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 whip',
    engine: HALF,
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'horizontal', params: { constraintProjectionTolerance: HALF_TOLERANCE } }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 whip',
    engine: 'Rapier',
    bodies: 10,
    joints: 10,
    build: () => S.rapierChain(RAPIER, { start: 'horizontal' }),
    warm: warmRapier,
  },
  {
    scene: 'chain10 whip',
    engine: 'cannon-es',
    bodies: 10,
    joints: 10,
    build: () => S.cannonChain(CANNON, { start: 'horizontal' }),
    warm: warmCannon,
  },
  {
    scene: 'chain10 hang',
    engine: 'PhysiN',
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'hanging' }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 hang',
    engine: 'PhysiN subSteps 4',
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'hanging', params: { subSteps: 4 } }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 hang',
    engine: LOOSE,
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'hanging', params: { constraintProjectionTolerance: LOOSE_TOLERANCE } }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 hang',
    engine: HALF,
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ start: 'hanging', params: { constraintProjectionTolerance: HALF_TOLERANCE } }),
    warm: warmPhysin,
  },
  {
    scene: 'chain10 hang',
    engine: 'Rapier',
    bodies: 10,
    joints: 10,
    build: () => S.rapierChain(RAPIER, { start: 'hanging' }),
    warm: warmRapier,
  },
  {
    scene: 'chain10 hang',
    engine: 'cannon-es',
    bodies: 10,
    joints: 10,
    build: () => S.cannonChain(CANNON, { start: 'hanging' }),
    warm: warmCannon,
  },
  { scene: 'grid20', engine: 'PhysiN', bodies: 400, joints: 780, build: () => S.physinGrid(), warm: warmPhysin },
  {
    scene: 'grid20',
    engine: LOOSE,
    bodies: 400,
    joints: 780,
    build: () => S.physinGrid({ params: { constraintProjectionTolerance: LOOSE_TOLERANCE } }),
    warm: warmPhysin,
  },
  {
    scene: 'grid20',
    engine: HALF,
    bodies: 400,
    joints: 780,
    build: () => S.physinGrid({ params: { constraintProjectionTolerance: HALF_TOLERANCE } }),
    warm: warmPhysin,
  },
  { scene: 'grid20', engine: 'Rapier', bodies: 400, joints: 780, build: () => S.rapierGrid(RAPIER), warm: warmRapier },
  { scene: 'grid20', engine: 'cannon-es', bodies: 400, joints: 780, build: () => S.cannonGrid(CANNON), warm: warmCannon },
];
const fourD = [
  {
    scene: 'chain10 4D whip',
    engine: 'PhysiN',
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ n: 4, start: 'horizontal' }),
    warm: () => S.physinChain({ n: 4 }),
  },
  {
    scene: 'chain10 4D whip',
    engine: 'PhysiN subSteps 4',
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ n: 4, start: 'horizontal', params: { subSteps: 4 } }),
    warm: () => S.physinChain({ n: 4 }),
  },
  {
    scene: 'chain10 4D hang',
    engine: 'PhysiN',
    bodies: 10,
    joints: 10,
    build: () => S.physinChain({ n: 4, start: 'hanging' }),
    warm: () => S.physinChain({ n: 4 }),
  },
];

/** The scene groups to run (JOINTS_BENCH_SCENES, see the header); all when unset. */
const ONLY = process.env.JOINTS_BENCH_SCENES?.split(',').map((x) => x.trim());
const wanted = (scene) => ONLY === undefined || ONLY.includes(scene);

const results = {};
const row = (r, x) => ({
  scene: r.scene,
  engine: r.engine,
  bodies: r.bodies,
  joints: r.joints,
  rounds: x.rounds,
  steps: x.capped ? `${x.steps} (capped)` : x.steps,
  'ms/step (median)': x.median,
  p10: x.p10,
  p90: x.p90,
  'worst joint error (m)': x.worst,
  'error at 10 s (m)': x.last,
  'ΔE at 10 s (J)': x.change,
  'max E − E0 (J)': x.gain,
});
// PhysiN runs in turns with one peer at a time (bench/lib/turns.mjs): first its rows with Rapier,
// then PhysiN again with cannon-es; each time ratio comes from the pair that shared the clock.
const rows3 = [];
const scenes3 = ['chain10 whip', 'chain10 hang', 'grid20'].filter(wanted);
for (const scene of scenes3) {
  const mine = runs.filter((r) => r.scene === scene && r.engine.startsWith('PhysiN'));
  const peer = (name) => runs.find((r) => r.scene === scene && r.engine === name);
  const withRapier = [...mine, peer('Rapier')];
  const withCannon = [mine[0], peer('cannon-es')];
  runTogether(withRapier).forEach((x, i) => {
    results[`${scene}|${withRapier[i].engine}`] = x;
    rows3.push({ ...row(withRapier[i], x), 'in turns with': i < mine.length ? 'Rapier' : 'PhysiN' });
  });
  runTogether(withCannon).forEach((x, i) => {
    const key = i === 0 ? 'PhysiN (2)' : 'cannon-es';
    results[`${scene}|${key}`] = x;
    rows3.push({ ...row({ ...withCannon[i], engine: key }, x), 'in turns with': i === 0 ? 'cannon-es' : 'PhysiN' });
  });
}
medianTable(
  `3D joint scenes: ms/step, median over the ${STEPS} steps of a run (each step timed alone; PhysiN and one peer in turns); worst joint error over 10 s`,
  rows3,
);

const ratio = (a, b) => (Number.isFinite(a) && Number.isFinite(b) && b > 0 ? a / b : NaN);
medianTable(
  '3D joint scenes: ratios of the median ms/step (below 1: PhysiN faster) and of the worst joint error (below 1: PhysiN more accurate)',
  scenes3.map((scene) => {
    const p = results[`${scene}|PhysiN`];
    const p2 = results[`${scene}|PhysiN (2)`];
    const ra = results[`${scene}|Rapier`];
    const ca = results[`${scene}|cannon-es`];
    return {
      scene,
      'time PhysiN/Rapier': ratio(p.median, ra.median),
      [`time ${LOOSE}/Rapier`]: ratio(results[`${scene}|${LOOSE}`]?.median, ra.median),
      [`error ${LOOSE}`]: results[`${scene}|${LOOSE}`]?.worst,
      [`time ${HALF}/Rapier`]: ratio(results[`${scene}|${HALF}`]?.median, ra.median),
      [`error ${HALF}`]: results[`${scene}|${HALF}`]?.worst,
      'time PhysiN/cannon-es': ratio(p2.median, ca.median),
      'error PhysiN/Rapier': ratio(p.worst, ra.worst),
      'error PhysiN/cannon-es': ratio(p.worst, ca.worst),
    };
  }),
);

// The 4D chains in turns with the same 3D chains, for the "time vs 3D" column.
const rows4 = [];
const pairs4 = fourD
  .filter(() => wanted('4D'))
  .map((r) => [r, runs.find((q) => q.scene === r.scene.replace(' 4D', '') && q.engine === r.engine)]);
const done4 = pairs4.length > 0 ? runTogether(pairs4.flat()) : [];
pairs4.forEach(([r], i) => {
  const x = done4[2 * i];
  const same3 = done4[2 * i + 1];
  results[`${r.scene}|${r.engine}`] = x;
  const out = row(r, x);
  out['time vs 3D'] = ratio(x.median, same3.median);
  rows4.push(out);
});
medianTable(
  `PhysiN in 4D: ms/step, median over the ${STEPS} steps of one run; worst joint error over 10 s ("time vs 3D": the same scene and settings in 3D, run in the same turns)`,
  rows4,
);

// ---- Targets ----------------------------------------------------------------------------------
if (!wanted('chain10 whip')) {
  if (failures > 0) {
    console.error(`\njoints.bench: ${failures} run(s) threw (see above)`);
    process.exit(1);
  }
  process.exit(0);
}
const yesNo = (ok) => (ok ? 'yes' : 'NO');
const whip = results['chain10 whip|PhysiN'].worst;
const fmt = (x) => (Number.isFinite(x) ? x.toPrecision(3) : String(x));
const targets = [
  {
    target: "chain10 whip, worst error (PhysiN defaults) below Rapier 0.21 (the issue's figure)",
    measured: fmt(whip),
    limit: '< 0.23',
    met: yesNo(whip < 0.23),
  },
  {
    target: "chain10 whip, worst error below cannon-es 0.20 (the issue's figure)",
    measured: fmt(whip),
    limit: '< 0.40',
    met: yesNo(whip < 0.4),
  },
  {
    target: "chain10 whip, worst error below the specification's claim",
    measured: fmt(whip),
    limit: '< 0.114',
    met: yesNo(whip < 0.114),
  },
  {
    target: 'chain10 whip, worst error below Rapier in this run',
    measured: fmt(whip),
    limit: `< ${fmt(results['chain10 whip|Rapier'].worst)}`,
    met: yesNo(whip < results['chain10 whip|Rapier'].worst),
  },
  {
    target: 'chain10 whip, worst error below cannon-es in this run',
    measured: fmt(whip),
    limit: `< ${fmt(results['chain10 whip|cannon-es'].worst)}`,
    met: yesNo(whip < results['chain10 whip|cannon-es'].worst),
  },
];
// Issue 19's time goals: the chains at ≤ 1× Rapier with a worst error ≤ 0.01, the grid at ≤ 1.5×.
for (const [scene, limit] of [
  ['chain10 whip', 1],
  ['chain10 hang', 1],
  ['grid20', 1.5],
]) {
  const ra = results[`${scene}|Rapier`];
  for (const engine of ['PhysiN', LOOSE, HALF]) {
    const x = results[`${scene}|${engine}`];
    if (x === undefined || ra === undefined) continue;
    const t = ratio(x.median, ra.median);
    targets.push({
      target: `${scene}, ${engine}: time/Rapier in the same turns, worst error ≤ 0.01`,
      measured: `${fmt(t)}×, ${fmt(x.worst)} m`,
      limit: `≤ ${limit}×`,
      met: yesNo(t <= limit && x.worst <= 0.01),
    });
  }
}
medianTable('Targets (worst joint error of the whipping chain; time against Rapier; reported, not asserted)', targets);

if (Object.values(results).some((r) => r.capped && !r.error))
  console.log(
    `\nSome runs were cut short by the ${BUDGET_MS / 1000} s budget: their medians and errors cover the steps they ran.`,
  );
if (failures > 0) {
  console.error(`\njoints.bench: ${failures} run(s) threw (see above)`);
  process.exit(1);
}
