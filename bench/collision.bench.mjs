// Collision scenes (issue 18): a pile of 500 icosahedra and a pile of 200 tori in a box bin, 3D,
// PhysiN beside Rapier (@dimforge/rapier3d-compat 0.21) in the same run. See docs/collision-bench.md.
//
// Scenes (scenes/collision-scenes.mjs): a static box floor and four static box walls (an 8 m × 8 m
// bin), bodies of mass 1, friction 0.5, restitution 0, seeded start poses on a grid with jitter and
// uniform random orientations, dropped from rest; dt 1/60, sleep off in both engines.
//   icosahedra500  circumradius 0.5: PhysiN ConvexMesh, Rapier ColliderDesc.convexHull of the
//                  same 12 vertices.
//   tori200        R 0.5, r 0.15: PhysiN HyperTorus; Rapier (no torus primitive) a compound of
//                  16 capsules round the core circle.
// PhysiN: default parameters, allowSleep false. Rapier: default integration parameters.
//
// Timing: as contacts.bench.mjs. Each engine first steps a small throwaway pile of the same kind
// (27 bodies, up to 150 steps or 1 s, untimed: the JIT warm-up), then the scene is built and run
// for STEPS steps, each timed alone; PhysiN and Rapier run in turns of 50 steps
// (lib/turns.mjs) so the drift of a shared machine falls on both, and the cell is the median over
// the steps of the median of ROUNDS runs. Penetration is measured after the last step by one
// function for both engines (scenes/collision-scenes.mjs: exact SAT depth for hulls, core-curve
// distance for tori, depth below the bin's inner faces).
//
// Options (environment): COLLISION_STEPS (default 600 = 10 s), COLLISION_ROUNDS (default 3),
// COLLISION_SCENES (comma list of scene names, default both).
//
// Exit status: 0 when everything ran; 1 if Rapier or the built engine cannot be loaded, or a
// scene throws.
//
// Run: node bench/collision.bench.mjs   (after the build: it imports the BUILT packages)
import { loadavg, cpus } from 'node:os';
import { performance } from 'node:perf_hooks';
import { medianTable } from './lib/table.mjs';
import { TURN_STEPS, runRoundsInTurns } from './lib/turns.mjs';
import { loadRapier } from './scenes/peer-scenes.mjs';

const STEPS = Number(process.env.COLLISION_STEPS ?? 600);
const ROUNDS = Number(process.env.COLLISION_ROUNDS ?? 3);
const ONLY = process.env.COLLISION_SCENES?.split(',').filter(Boolean);

let RAPIER;
try {
  RAPIER = await loadRapier();
} catch (error) {
  console.error(
    `collision.bench: Rapier failed to load (install: \`node scripts/pnpm.mjs install\` at the root): ${error?.stack ?? error}`,
  );
  process.exit(1);
}
let scenes;
try {
  scenes = await import('./scenes/collision-scenes.mjs');
} catch (error) {
  console.error(`collision.bench: cannot load the built engine (build it first: npm run build): ${error?.stack ?? error}`);
  process.exit(1);
}
const { buildPhysinBin, buildRapierBin, binLayout, icosahedronPile, torusPile, penetration } = scenes;

const load = () =>
  loadavg()
    .map((x) => x.toFixed(2))
    .join(' ');
console.log(`Machine: ${cpus().length} × ${cpus()[0]?.model ?? '?'}; load average (1, 5, 15 min) at the start: ${load()}`);
console.log(`Steps per run: ${STEPS} (dt 1/60), rounds: ${ROUNDS}, turns of ${TURN_STEPS} steps.`);

const SCENES = [
  { name: 'icosahedra500', layout: icosahedronPile(), warm: () => binLayout('icosahedra', 27, 1.2, 1, 77, 'warm-up') },
  { name: 'tori200', layout: torusPile(), warm: () => binLayout('tori', 27, 1.45, 1, 77, 'warm-up') },
].filter((s) => !ONLY || ONLY.includes(s.name));

const ENGINES = [
  { name: 'PhysiN', build: (layout) => buildPhysinBin(layout) },
  { name: 'Rapier', build: (layout) => buildRapierBin(RAPIER, layout) },
];

function warmUp(build, layout) {
  const scene = build(layout);
  const end = performance.now() + 1000;
  for (let i = 0; i < 150 && performance.now() < end; i += 1) scene.step();
  scene.dispose?.();
}

const lane = (scene, engine) => ({
  label: `${scene.name} ${engine.name}`,
  prepare: () => warmUp(engine.build, scene.warm()),
  build: () => engine.build(scene.layout),
  step: (s) => s.step(),
  finish: (s) => {
    const t0 = performance.now();
    const p = penetration(s);
    const speeds = s.speeds();
    return { ...p, maxSpeed: Math.max(...speeds), measureMs: performance.now() - t0 };
  },
});

let failures = 0;
const rows = [];
const ratios = [];
const mm = (x) => (Number.isFinite(x) ? x * 1000 : NaN);
for (const scene of SCENES) {
  const t0 = performance.now();
  const results = runRoundsInTurns(
    ENGINES.map((e) => lane(scene, e)),
    ROUNDS,
    { steps: STEPS },
  );
  results.forEach((r, i) => {
    if (r.error !== undefined) {
      failures += 1;
      console.error(
        `collision.bench: ${scene.name} ${ENGINES[i].name} threw after ${r.steps} steps: ${r.error?.stack ?? r.error}`,
      );
    }
    rows.push({
      scene: scene.name,
      engine: ENGINES[i].name,
      bodies: scene.layout.positions.length,
      rounds: r.rounds,
      steps: r.steps,
      'ms/step (median)': r.error ? NaN : r.median,
      p10: r.error ? NaN : r.p10,
      p90: r.error ? NaN : r.p90,
      'worst pen. (mm)': mm(r.worst),
      'mean pen. (mm)': mm(r.mean),
      'overlapping pairs': r.overlaps ?? NaN,
      'left the bin': r.lost ?? NaN,
      'max speed at the end (m/s)': r.maxSpeed ?? NaN,
    });
  });
  const [ours, theirs] = results;
  ratios.push({
    scene: scene.name,
    PhysiN: ours.median,
    Rapier: theirs.median,
    'PhysiN/Rapier': ours.error || theirs.error ? NaN : ours.median / theirs.median,
    'worst pen. PhysiN (mm)': mm(ours.worst),
    'worst pen. Rapier (mm)': mm(theirs.worst),
    'mean pen. PhysiN (mm)': mm(ours.mean),
    'mean pen. Rapier (mm)': mm(theirs.mean),
  });
  console.log(`(${scene.name}: ${((performance.now() - t0) / 1000).toFixed(1)} s, load average now ${load()})`);
}

medianTable(
  `Collision scenes: ms/step, median over the ${STEPS} steps of a run (each step timed alone; engines in turns of ${TURN_STEPS} steps; the median of \`rounds\` runs); penetration and the largest body speed after the last step of that run`,
  rows,
);
medianTable('Collision scenes: ratio of the median ms/step (below 1: PhysiN faster), and penetration', ratios);
console.log(`\nLoad average (1, 5, 15 min) at the end: ${load()}`);
if (SCENES.some((s) => s.name === 'tori200'))
  console.log('tori200: Rapier has no torus; its tori are compounds of 16 capsules (penetration measured on those capsules).');
if (failures > 0) {
  console.error(`\ncollision.bench: ${failures} run(s) threw (see above)`);
  process.exit(1);
}
