// Sleeping bodies cost nothing (issue 19, "pay only for awake bodies"): PhysiN vs Rapier
// (@dimforge/rapier3d-compat) in the same run, both with sleeping on, and the contact scenes
// stack9 / pile1000 (sleep off) to show that the awake set costs the awake scenes nothing.
//
// Scenes (3D, dt = 1/60):
//   sleeping16k  16,000 balls (radius 0.5, mass 1) resting on a floor in a 160 × 100 grid, 1.1 m
//                apart (each its own island), put to sleep before the timed steps: the build
//                steps each world until every ball sleeps (untimed). PhysiN: default parameters
//                (allowSleep true); Rapier: default integration parameters, bodies may sleep.
//                The target of issue 19: ≤ 0.1 ms per step.
//   stack9, pile1000  as in contacts.bench.mjs (scenes/layouts.mjs; sleep off in both engines).
//
// Timing: every step timed alone, the MEDIAN over the steps of a run; the engines run in turns of
// 50 steps (lib/turns.mjs) so that the drift of a shared machine falls on all alike.
//
// Before / after in one run: PHYSIN_BEFORE=<path to another build's packages/engine/dist/index.js>
// adds a lane "PhysiN (before)" that runs that build beside this one and Rapier, e.g.
//   PHYSIN_BEFORE=/path/to/old/packages/engine/dist/index.js node bench/sleeping.bench.mjs
//
// Run: node bench/sleeping.bench.mjs    (after the build: it imports the BUILT packages)
import { pathToFileURL } from 'node:url';
import { medianTable } from './lib/table.mjs';
import { TURN_STEPS, runRoundsInTurns } from './lib/turns.mjs';
import { DT, GRAVITY, judge, peerLayouts } from './scenes/layouts.mjs';
import { buildRapierScene, loadRapier } from './scenes/peer-scenes.mjs';

const BALLS = { count: 16_000, perRow: 160, radius: 0.5, spacing: 1.1 };
/** Timed steps of the sleeping scene, and most steps the build may take to put every ball to sleep. */
const SLEEP_STEPS = 600;
const SETTLE_LIMIT = 600;
const CONTACT_STEPS = 600;
/** Wall-clock budget of one PhysiN run of a contact scene (ms), as in contacts.bench.mjs. */
const BUDGET_MS = { stack: 12_000, pile: 25_000 };

let RAPIER;
try {
  RAPIER = await loadRapier();
} catch (error) {
  console.error(`sleeping.bench: Rapier failed to load (\`node scripts/pnpm.mjs install\`): ${error?.stack ?? error}`);
  process.exit(1);
}
const engines = [{ name: 'PhysiN', mod: await import('@physin/engine') }];
if (process.env.PHYSIN_BEFORE) {
  engines.push({ name: 'PhysiN (before)', mod: await import(pathToFileURL(process.env.PHYSIN_BEFORE).href) });
}
const { rotorFromPlane } = await import('@physin/algebra');

/** The sleeping carpet in PhysiN (engine module `E`): built, then stepped until every ball sleeps. */
function physinCarpet(E) {
  const D = E.dims(3);
  const world = new E.World({ dimensions: 3, gravity: [0, -GRAVITY, 0] });
  world.addBody(new E.Body(D, { shape: E.HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
  const shape = E.HyperSphere(D, BALLS.radius);
  const balls = [];
  for (let i = 0; i < BALLS.count; i += 1) {
    const x = (i % BALLS.perRow) * BALLS.spacing;
    const z = Math.floor(i / BALLS.perRow) * BALLS.spacing;
    balls.push(world.addBody(new E.Body(D, { shape, mass: 1, position: [x, BALLS.radius, z] })));
  }
  const awake = () => balls.reduce((c, b) => c + (b.isSleeping ? 0 : 1), 0);
  let settle = 0;
  while (settle < SETTLE_LIMIT && awake() > 0) {
    world.step(DT);
    settle += 1;
  }
  return { step: () => world.step(DT), awake, settle };
}

/** The sleeping carpet in Rapier: the same balls, bodies that may sleep, stepped until all sleep. */
function rapierCarpet() {
  const world = new RAPIER.World({ x: 0, y: -GRAVITY, z: 0 });
  world.timestep = DT;
  const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  world.createCollider(new RAPIER.ColliderDesc(new RAPIER.HalfSpace({ x: 0, y: 1, z: 0 })), ground);
  const density = 1 / ((4 / 3) * Math.PI * BALLS.radius ** 3);
  const balls = [];
  for (let i = 0; i < BALLS.count; i += 1) {
    const x = (i % BALLS.perRow) * BALLS.spacing;
    const z = Math.floor(i / BALLS.perRow) * BALLS.spacing;
    const body = world.createRigidBody(RAPIER.RigidBodyDesc.dynamic().setTranslation(x, BALLS.radius, z));
    world.createCollider(RAPIER.ColliderDesc.ball(BALLS.radius).setDensity(density), body);
    balls.push(body);
  }
  const awake = () => balls.reduce((c, b) => c + (b.isSleeping() ? 0 : 1), 0);
  let settle = 0;
  while (settle < SETTLE_LIMIT && awake() > 0) {
    world.step();
    settle += 1;
  }
  return { step: () => world.step(), awake, settle, dispose: () => world.free() };
}

const rows = [];
const ratios = [];

// ---- sleeping16k -------------------------------------------------------------------------------
{
  const lanes = [
    ...engines.map((e) => ({ label: e.name, build: () => physinCarpet(e.mod) })),
    { label: 'Rapier', build: () => rapierCarpet() },
  ].map((l) => ({
    ...l,
    step: (scene) => scene.step(),
    finish: (scene) => ({ settle: scene.settle, awakeAtEnd: scene.awake() }),
  }));
  const results = runRoundsInTurns(lanes, 1, { steps: SLEEP_STEPS });
  lanes.forEach((lane, i) => {
    const r = results[i];
    if (r.error !== undefined) throw r.error;
    rows.push({
      scene: 'sleeping16k',
      engine: lane.label,
      steps: r.steps,
      'ms/step (median)': r.median,
      p10: r.p10,
      p90: r.p90,
      'steps to sleep (untimed)': r.settle,
      'awake at the end': r.awakeAtEnd,
    });
  });
  ratios.push(ratioRow('sleeping16k (sleep on)', lanes, results));
}

// ---- stack9 and pile1000 (sleep off) -----------------------------------------------------------
function physinBoxes(E, layout) {
  const n = layout.n;
  const D = E.dims(n);
  const world = new E.World({ dimensions: n, gravity: [0, -GRAVITY, 0], params: { allowSleep: false } });
  const material = { friction: 0.5, restitution: 0 };
  world.addBody(new E.Body(D, { shape: E.HalfSpace(D, [0, 1, 0], 0), mass: 0, material }));
  const shape = E.HyperBox(D, [0.5, 0.5, 0.5]);
  const rotor = new Float64Array(D.r);
  const boxes = layout.positions.map((position, i) => {
    const options = { shape, mass: 1, position, material };
    if (layout.yaws[i] !== 0) options.rotor = rotorFromPlane(D, rotor, 2, 0, layout.yaws[i]);
    return world.addBody(new E.Body(D, options));
  });
  return { step: () => world.step(DT), positions: () => boxes.map((b) => Array.from(b.x)) };
}

for (const layout of peerLayouts().filter((l) => l.name === 'stack9' || l.name === 'pile1000')) {
  const budgetMs = layout.kind === 'pile' ? BUDGET_MS.pile : BUDGET_MS.stack;
  const lanes = [
    ...engines.map((e) => ({ label: e.name, build: () => physinBoxes(e.mod, layout), budgetMs })),
    { label: 'Rapier', build: () => buildRapierScene(RAPIER, layout) },
  ].map((l) => ({
    ...l,
    step: (scene) => scene.step(),
    finish: (scene, capped) => {
      const v = judge(layout, scene.positions());
      return { at: capped ? `capped: ${v.measure}` : v.measure };
    },
  }));
  const rounds = layout.kind === 'pile' ? 1 : 3;
  const results = runRoundsInTurns(lanes, rounds, { steps: CONTACT_STEPS });
  lanes.forEach((lane, i) => {
    const r = results[i];
    if (r.error !== undefined) throw r.error;
    rows.push({
      scene: `${layout.name} (sleep off)`,
      engine: lane.label,
      steps: r.steps,
      'ms/step (median)': r.median,
      p10: r.p10,
      p90: r.p90,
      'steps to sleep (untimed)': '—',
      'awake at the end': r.at,
    });
  });
  ratios.push(ratioRow(`${layout.name} (sleep off)`, lanes, results));
}

function ratioRow(scene, lanes, results) {
  const median = (label) => results[lanes.findIndex((l) => l.label === label)]?.median ?? NaN;
  const row = { scene, PhysiN: median('PhysiN'), Rapier: median('Rapier'), 'PhysiN/Rapier': median('PhysiN') / median('Rapier') };
  if (engines.length > 1) {
    row['PhysiN (before)'] = median('PhysiN (before)');
    row['before/Rapier'] = median('PhysiN (before)') / median('Rapier');
  }
  return row;
}

medianTable(`Sleeping and awake scenes: ms/step, median over the steps of a run (engines in turns of ${TURN_STEPS} steps)`, rows);
medianTable('Ratios of the median ms/step (same run, same turns; below 1: PhysiN faster)', ratios);
const sleeping = ratios[0].PhysiN;
medianTable('Target (issue 19; reported, not asserted)', [
  {
    target: 'sleeping16k: PhysiN ms/step',
    measured: sleeping,
    limit: '≤ 0.1',
    met: sleeping <= 0.1 ? 'yes' : 'NO',
  },
]);
