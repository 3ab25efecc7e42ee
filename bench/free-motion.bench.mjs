// Free motion: World.step for 1000 spinning bodies (boxes and balls, under gravity, no contacts),
// n = 2..6, and the share of it spent in the rotor update.
//
// "step" is World.step(1/60) with the default parameters (midpoint rotor step, one iteration).
// "rotor update" is the engine's own rotor step (advanceRotor: two exponentials, two products,
// two inertia transforms, the defect check) called for the same 1000 bodies, alone. "first
// order" is World.step with gyroscopic: false (one exponential, one product, one transform), to
// show what the second-order step costs.
//
// Run: node bench/free-motion.bench.mjs    (after `npm run build`: it imports the BUILT engine)
// Prints medians (ms per step) over several batches of steps.
import { performance } from 'node:perf_hooks';
import { medianTable } from './lib/table.mjs';
import { seeded } from './lib/random.mjs';

const engine = await import('@physin/engine').catch(() =>
  import('../packages/engine/dist/index.js').catch(() => {
    console.error('free-motion.bench: build the engine first (npm run build)');
    process.exit(1);
  }),
);
const { World, Body, HyperBox, HyperSphere, dims } = engine;
// The rotor step is internal (no public export): load it from the built module.
const { advanceRotor, createRotorStepScratch } = await import('../packages/engine/dist/integrator/rotor-step.js');
const { createStepConstants, STEP_H, STEP_ROTOR_ITERATIONS, STEP_ROTOR_TOLERANCE } =
  await import('../packages/engine/dist/integrator/step-constants.js');

const BODIES = 1000;
const DT = 1 / 60;

/**
 * Median, p10 and p90 of the time of one call of `run` (ms), over `samples` timed calls after
 * `warmup` untimed ones. (bench/lib's timeLoop starts at 16 calls per batch, which at 60 ms per
 * 6D step would keep this file running for a minute; one step here is already long enough to time.)
 */
function timeSteps(run, samples, warmup) {
  for (let i = 0; i < warmup; i += 1) run();
  const t = new Float64Array(samples);
  for (let s = 0; s < samples; s += 1) {
    const t0 = performance.now();
    run();
    t[s] = performance.now() - t0;
  }
  t.sort();
  const q = (p) => t[Math.round((samples - 1) * p)];
  return { median: q(0.5), p10: q(0.1), p90: q(0.9) };
}

function makeWorld(n, params) {
  const D = dims(n);
  const rand = seeded(4242 + n);
  const r = (lo, hi) => lo + (hi - lo) * rand();
  const gravity = new Array(n).fill(0);
  gravity[1] = -9.81;
  const world = new World({ dimensions: n, gravity, params });
  for (let b = 0; b < BODIES; b += 1) {
    const shape =
      b % 4 === 3
        ? HyperSphere(D, r(0.2, 0.6))
        : HyperBox(
            D,
            Array.from({ length: n }, () => r(0.1, 1)),
          );
    world.addBody(
      new Body(D, {
        shape,
        mass: r(0.5, 5),
        position: Array.from({ length: n }, () => r(-50, 50)),
        velocity: Array.from({ length: n }, () => r(-1, 1)),
        angularVelocity: Array.from({ length: D.k }, () => r(-3, 3)),
      }),
    );
  }
  return world;
}

const rows = [];
for (const n of [2, 3, 4, 5, 6]) {
  const D = dims(n);
  // Fewer samples for the slow high-n runs: the whole file stays within ~15 s.
  const samples = n >= 5 ? 7 : 41;
  const warmup = n >= 5 ? 5 : 100;
  const world = makeWorld(n);
  const step = timeSteps(() => world.step(DT), samples, warmup);
  const firstWorld = makeWorld(n, { gyroscopic: false });
  const first = timeSteps(() => firstWorld.step(DT), samples, warmup);

  // The rotor update alone, on copies of the same bodies' state.
  const bodies = makeWorld(n).bodies;
  const Rs = bodies.map((b) => Float64Array.from(b.R));
  const ws = bodies.map((b) => Float64Array.from(b.w));
  const Ls = bodies.map((b) => Float64Array.from(b.L));
  const invIs = bodies.map((b) => Float64Array.from(b.invInertia));
  const constants = createStepConstants();
  constants[STEP_H] = DT;
  constants[STEP_ROTOR_ITERATIONS] = 1;
  constants[STEP_ROTOR_TOLERANCE] = 1e-9;
  const scratch = createRotorStepScratch(D);
  const rotor = timeSteps(
    () => {
      for (let b = 0; b < BODIES; b += 1) advanceRotor(D, Rs[b], ws[b], Ls[b], invIs[b], constants, scratch);
    },
    samples,
    warmup,
  );

  const ms = (x) => x;
  rows.push({
    n,
    'r (rotor size)': D.r,
    'step, ms (median)': ms(step.median),
    p10: ms(step.p10),
    p90: ms(step.p90),
    'rotor update, ms': ms(rotor.median),
    'rotor share': `${((100 * rotor.median) / step.median).toFixed(0)} %`,
    'first-order step, ms': ms(first.median),
    'µs per body': (1e3 * step.median) / BODIES,
  });
}

medianTable(`Free motion of ${BODIES} bodies, World.step(1/60): medians (ms per step)`, rows);

// Fast tumbles (issue 17): 1000 boxes spun mostly in their intermediate plane (3D) or in every
// plane (4D) at the speed given, World.step(1/60) with the defaults; ms per step (median) and the
// worst relative kinetic-energy error of the 1000 bodies over 600 steps (10 s). The bodies sit on a
// 50 m lattice, so no two ever share a broad-phase pair: the error is the integrator's alone. (At
// 10 m, boxes spinning at 200 rad/s get speculative contacts with their neighbours, and the contact
// solver changes their energy by up to 40 %; at random places in a 1000 m cube a few pairs do.)
const fast = [];
for (const [n, speed] of [
  [3, 3],
  [3, 30],
  [3, 100],
  [4, 3],
  [4, 50],
  [4, 200],
]) {
  const D = dims(n);
  const rand = seeded(1717 + n * 1000 + speed);
  const r = (lo, hi) => lo + (hi - lo) * rand();
  const world = new World({ dimensions: n, gravity: new Array(n).fill(0) });
  for (let b = 0; b < BODIES; b += 1) {
    const half = n === 3 ? [r(0.9, 1.1), r(0.5, 0.65), r(0.2, 0.3)] : [r(0.9, 1.1), r(0.6, 0.75), r(0.4, 0.5), r(0.2, 0.3)];
    const dir = n === 3 ? [r(0.05, 0.2), 1, r(0.05, 0.2)] : Array.from({ length: 6 }, () => r(-1, 1));
    const norm = Math.hypot(...dir);
    world.addBody(
      new Body(D, {
        shape: HyperBox(D, half),
        mass: 1,
        position: Array.from({ length: n }, (_, i) => (i < 3 ? 50 * (Math.floor(b / 10 ** i) % 10) : 0)),
        angularVelocity: dir.map((x) => (x * speed) / norm),
      }),
    );
  }
  const E0 = world.bodies.map((b) => b.kineticEnergy());
  let worst = 0;
  const t = new Float64Array(600);
  for (let s = 0; s < 600; s += 1) {
    const t0 = performance.now();
    world.step(DT);
    t[s] = performance.now() - t0;
    if (s % 10 === 9) world.bodies.forEach((b, i) => (worst = Math.max(worst, Math.abs(b.kineticEnergy() - E0[i]) / E0[i])));
  }
  t.sort();
  fast.push({ n, 'speed, rad/s': speed, 'step, ms (median)': t[300], p90: t[540], 'worst energy error': worst.toExponential(1) });
}
medianTable(`Tumbling boxes, ${BODIES} bodies, World.step(1/60), defaults`, fast);
