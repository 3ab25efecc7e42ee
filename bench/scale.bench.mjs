// Building and emptying a world at scale (issue 19): add 32,000 balls, step once, remove them all,
// step once; PhysiN beside Rapier (@dimforge/rapier3d-compat 0.21) in the same run, in turns.
//
// Scene: 3D, gravity −9.81, no floor; balls of radius 0.2, mass 1, on a 40 × 40 × 20 grid of
// spacing 1 m (apart: no contacts, so the cost is the bookkeeping of bodies and broadphase
// proxies alone). PhysiN: `new Body(D, { shape, mass, position })` + `world.addBody` per ball, one
// shared shape, then `world.removeBody` per ball, in the order added. Rapier:
// `createRigidBody(RigidBodyDesc.dynamic().setTranslation(…))` + `createCollider(ColliderDesc.ball)`,
// then `removeRigidBody`. Rapier defers its broadphase work to the step, so each phase is followed
// by one step and the step is timed with it: "add" is add + step, "remove" is remove + step.
//
// Timing: performance.now() around each phase, and the process's CPU time (process.cpuUsage, user +
// system: less sensitive than the wall clock to other jobs on a shared machine) around the whole
// round; ROUNDS rounds (default 5), PhysiN and Rapier alternating within each round so that the
// drift of a shared machine falls on both; the cells are medians over the rounds. The target of issue 19 is ≤ 0.2 s for add and remove together.
//
// Options (environment): SCALE_BODIES (default 32000), SCALE_ROUNDS (default 5), SCALE_RAPIER=0 to
// leave Rapier out (its removal is quadratic: 50 to 150 s a round for 32,000 on the shared machine).
//
// Run: node bench/scale.bench.mjs   (after the build: it imports the BUILT packages)
import { performance } from 'node:perf_hooks';
import { medianTable } from './lib/table.mjs';
import { loadRapier } from './scenes/peer-scenes.mjs';

let engine;
let RAPIER;
try {
  engine = await import('@physin/engine');
  RAPIER = await loadRapier();
} catch (error) {
  console.error(`scale.bench: cannot load the built engine or Rapier (build first: npm run build): ${error?.stack ?? error}`);
  process.exit(1);
}

const BODIES = Number(process.env.SCALE_BODIES ?? 32000);
const ROUNDS = Number(process.env.SCALE_ROUNDS ?? 5);
const PEERS = process.env.SCALE_RAPIER === '0' ? ['PhysiN'] : ['PhysiN', 'Rapier'];
const RADIUS = 0.2;
const SPACING = 1;
const DT = 1 / 60;

/** The process's CPU time so far (ms, user + system). */
function cpuMs() {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
}

/** Position of ball i on the 40 × 40 × k grid. */
function place(i, out) {
  out[0] = (i % 40) * SPACING;
  out[1] = 1 + (Math.floor(i / 1600) % 1000) * SPACING;
  out[2] = (Math.floor(i / 40) % 40) * SPACING;
  return out;
}

function physinRound() {
  const { Body, HyperSphere, World, dims } = engine;
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
  const shape = HyperSphere(D, RADIUS);
  const bodies = new Array(BODIES);
  const p = [0, 0, 0];
  const c0 = cpuMs();
  const t0 = performance.now();
  for (let i = 0; i < BODIES; i += 1) bodies[i] = world.addBody(new Body(D, { shape, mass: 1, position: place(i, p) }));
  world.step(DT);
  const t1 = performance.now();
  for (let i = 0; i < BODIES; i += 1) world.removeBody(bodies[i]);
  world.step(DT);
  const t2 = performance.now();
  const c2 = cpuMs();
  if (world.bodies.length !== 0) throw new Error(`PhysiN: ${world.bodies.length} bodies left after removal`);
  return { add: t1 - t0, remove: t2 - t1, cpu: c2 - c0 };
}

function rapierRound() {
  const world = new RAPIER.World({ x: 0, y: -9.81, z: 0 });
  world.timestep = DT;
  const bodies = new Array(BODIES);
  const p = [0, 0, 0];
  const c0 = cpuMs();
  const t0 = performance.now();
  for (let i = 0; i < BODIES; i += 1) {
    place(i, p);
    const body = world.createRigidBody(RAPIER.RigidBodyDesc.dynamic().setTranslation(p[0], p[1], p[2]));
    world.createCollider(RAPIER.ColliderDesc.ball(RADIUS).setDensity(1 / ((4 / 3) * Math.PI * RADIUS ** 3)), body);
    bodies[i] = body;
  }
  world.step();
  const t1 = performance.now();
  for (let i = 0; i < BODIES; i += 1) world.removeRigidBody(bodies[i]);
  world.step();
  const t2 = performance.now();
  const c2 = cpuMs();
  if (world.bodies.len() !== 0) throw new Error(`Rapier: ${world.bodies.len()} bodies left after removal`);
  world.free();
  return { add: t1 - t0, remove: t2 - t1, cpu: c2 - c0 };
}

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  const m = s.length >> 1;
  return s.length % 2 === 1 ? s[m] : (s[m - 1] + s[m]) / 2;
};

// One untimed round each: the JIT warm-up.
physinRound();
if (PEERS.length > 1) rapierRound();
const results = { PhysiN: { add: [], remove: [], cpu: [] }, Rapier: { add: [], remove: [], cpu: [] } };
for (let r = 0; r < ROUNDS; r += 1) {
  const order = r % 2 === 0 ? PEERS : [...PEERS].reverse();
  for (const name of order) {
    const t = name === 'PhysiN' ? physinRound() : rapierRound();
    results[name].add.push(t.add);
    results[name].remove.push(t.remove);
    results[name].cpu.push(t.cpu);
  }
}

const rows = PEERS.map((name) => {
  const add = median(results[name].add);
  const remove = median(results[name].remove);
  return {
    engine: name,
    bodies: BODIES,
    rounds: ROUNDS,
    'add + step (ms)': add,
    'remove + step (ms)': remove,
    'total (ms)': add + remove,
    'CPU total (ms)': median(results[name].cpu),
  };
});
medianTable(`Add ${BODIES} balls, step, remove them all, step: ms, median of ${ROUNDS} rounds (engines alternating)`, rows);
const total = rows[0]['total (ms)'];
medianTable('Targets', [
  { target: `PhysiN add + remove of ${BODIES} ≤ 200 ms`, measured: total, met: total <= 200 ? 'yes' : 'NO' },
  ...(rows.length > 1 ? [{ target: 'PhysiN / Rapier (total)', measured: total / rows[1]['total (ms)'], met: '—' }] : []),
]);
