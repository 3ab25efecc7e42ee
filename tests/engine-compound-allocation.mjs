// Measures what World.step allocates in steady state with compound bodies: dumbbells (two balls on
// a capsule) and L-shaped pairs of boxes rolling and tumbling on a half-space, with a collision
// listener on each. Run by tests/engine-compound.test.ts as
//   node --no-concurrent-recompilation --expose-gc --max-semi-space-size=256 --min-semi-space-size=64 \
//     tests/engine-compound-allocation.mjs N
// It imports the BUILT engine (dist/) and prints one JSON line: the least growth of the young
// generation over three windows of STEPS steps (tests/support/young-generation.mjs). Only the
// young generation counts: what the step allocates lands there, while the code the JIT compiles
// late in a window (100-250 KB of old and code space, seen in every window on a loaded machine)
// does not.
import { leastGrowth } from './support/young-generation.mjs';

if (typeof globalThis.gc !== 'function') {
  console.error('engine-compound-allocation.mjs: run node with --expose-gc');
  process.exit(2);
}
const { World, Body, HyperBox, HyperSphere, HyperCapsule, HalfSpace, Compound, dims } = await import('@physin/engine');

const n = Number(process.argv[2] ?? 3);
const STEPS = 2_000;
const D = dims(n);
const up = new Array(n).fill(0);
up[1] = 1;
const world = new World({ dimensions: n, gravity: up.map((x) => -9.81 * x), params: { allowSleep: false } });
world.addBody(new Body(D, { shape: HalfSpace(D, up, 0) }));
const at = (x, y, z) => {
  const p = new Array(n).fill(0);
  p[0] = x;
  p[1] = y;
  p[2] = z;
  return p;
};
const turn = new Float64Array(D.r);
turn[0] = Math.SQRT1_2;
turn[1 + D.planeIndexOf[1 * n + 2]] = -Math.SQRT1_2; // e1 toward e2 by a quarter turn
const dumbbell = Compound(D, [
  { shape: HyperSphere(D, 0.5), position: at(0, 0, -1) },
  { shape: HyperSphere(D, 0.5), position: at(0, 0, 1) },
  { shape: HyperCapsule(D, 1, 0.1), rotor: turn },
]);
const ell = Compound(D, [
  { shape: HyperBox(D, new Array(n).fill(0.3)) },
  { shape: HyperBox(D, new Array(n).fill(0.2)), position: at(0.5, 0.5, 0) },
]);
let events = 0;
for (let i = 0; i < 12; i += 1) {
  const body = world.addBody(
    new Body(D, {
      shape: i % 2 ? dumbbell : ell,
      mass: 1,
      position: at((i % 4) * 1.5, 1 + Math.floor(i / 4) * 1.5, (i % 3) * 2.5),
      velocity: at(0.5, 0, 0),
    }),
  );
  body.addEventListener('collision', () => {
    events += 1;
  });
}
for (let i = 0; i < 3_000; i += 1) world.step(1 / 60);
const least = await leastGrowth((count) => {
  for (let i = 0; i < count; i += 1) world.step(1 / 60);
}, STEPS);
console.log(JSON.stringify({ n, steps: STEPS, least, contacts: world.stats.contacts, events }));
