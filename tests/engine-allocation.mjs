// Measures what World.step allocates in steady state. Run by tests/engine-allocation.test.ts as
//   node --no-concurrent-recompilation --expose-gc --max-semi-space-size=256 --min-semi-space-size=64 \
//     tests/engine-allocation.mjs STEPS SCENE
// with SCENE one of 3, 4 (100 free bodies), stack3, stack4 (resting contacts), joints3, joints4,
// chains3 (point-joint chains only: the 3 × 3 joint-space path).
// It imports the BUILT engine (dist/), as an application would, and prints one JSON line.
//
// One scene per process: the step's functions are then optimised for one world, as in an
// application, and not re-optimised midway for the shapes of the next scene (the JIT's work,
// which is not the step's).
//
// Method: build the world, warm it up, then let the JIT settle (below); then for each window:
// gc() twice, read used_heap_size, run the measured steps, read it again without collecting. A
// PerformanceObserver counts the garbage collections whose start falls inside the window: with
// none there, the young generation was never emptied, so the heap difference is everything
// allocated during the window (by the steps, by the measuring — about 12 KB of new space — and by
// the JIT, see WINDOWS below). The big semi-space makes a scavenge during the window unlikely
// unless the step really allocates.
//
// --no-concurrent-recompilation makes the JIT's timeline the same on an idle and a busy machine
// (the compiler runs at once on the main thread instead of racing it); see the test's head.
//
// Settling: on a busy machine (CI runs test files in parallel) the optimising compiler runs late,
// and until its code is installed the step runs in the interpreter, which boxes every double it
// computes. So after the warm-up, short probes of 1 000 steps are repeated (a pause before each,
// for the compiler's thread) until one grows new space by less than 8 KB, at most SETTLE_PROBES
// times. This cannot hide an allocation of the step itself: that repeats in every probe and in
// every window, and the windows are what the test judges.
import { PerformanceObserver, performance } from 'node:perf_hooks';
import v8 from 'node:v8';

if (typeof globalThis.gc !== 'function') {
  console.error('engine-allocation.mjs: run node with --expose-gc');
  process.exit(2);
}

const engine = await import('@physin/engine');
const {
  World,
  Body,
  HyperBox,
  HyperSphere,
  HyperTorus,
  HalfSpace,
  dims,
  PointJoint,
  DistanceJoint,
  FixedJoint,
  HingeJoint,
  SubspaceJoint,
} = engine;

const steps = Number(process.argv[2] ?? 10_000);
const warmup = 3_000;
/** Probes of the settling phase (see the head of this file). */
const SETTLE_PROBES = 20;
const SETTLE_STEPS = 1_000;

// mulberry32, as tests/support/random.ts
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

function makeWorld(n) {
  const D = dims(n);
  const rand = seeded(1000 + n);
  const r = (lo, hi) => lo + (hi - lo) * rand();
  const gravity = new Array(n).fill(0);
  gravity[1] = -9.81;
  const world = new World({ dimensions: n, gravity });
  for (let b = 0; b < 100; b += 1) {
    const shape =
      b % 3 === 2
        ? HyperSphere(D, r(0.2, 0.8))
        : HyperBox(
            D,
            Array.from({ length: n }, () => r(0.1, 1)),
          );
    const type = b % 10 === 9 ? 'kinematic' : b % 10 === 8 ? 'static' : 'dynamic';
    world.addBody(
      new Body(D, {
        shape,
        type,
        mass: type === 'static' ? 0 : r(0.5, 5),
        position: Array.from({ length: n }, () => r(-10, 10)),
        velocity: type === 'static' ? undefined : Array.from({ length: n }, () => r(-1, 1)),
        angularVelocity: type === 'static' ? undefined : Array.from({ length: D.k }, () => r(-3, 3)),
      }),
    );
  }
  return world;
}

// A scene of resting contacts: a 9-box stack, a row of balls and a torus lying flat on a
// half-space, with sleep off so every contact is solved in every step (broadphase, narrowphase
// box–box, box–, sphere– and torus–half-space, solver with warm starting and shock propagation).
function makeStackWorld(n) {
  const D = dims(n);
  const gravity = new Array(n).fill(0);
  gravity[1] = -9.81;
  const world = new World({ dimensions: n, gravity, params: { allowSleep: false } });
  const up = new Array(n).fill(0);
  up[1] = 1;
  world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
  const at = (x, y) => {
    const p = new Array(n).fill(0);
    p[0] = x;
    p[1] = y;
    return p;
  };
  for (let i = 0; i < 9; i += 1)
    world.addBody(new Body(D, { shape: HyperBox(D, new Array(n).fill(0.5)), mass: 1, position: at(0, 0.5 + i) }));
  for (let i = 0; i < 4; i += 1) world.addBody(new Body(D, { shape: HyperSphere(D, 0.4), mass: 1, position: at(2 + i, 0.4) }));
  const torus = new Body(D, { shape: HyperTorus(D, 1, 0.25, [0, 2]), mass: 1, position: at(-3, 0.25) });
  world.addBody(torus);
  return world;
}

// A scene of joints (sleep off): a whipping chain of 8 point joints to the world (the tree solver),
// a closed loop of 4 (Gauss–Seidel), a hinge with a motor and limits, a soft rope, a weld, a
// subspace pin in the world frame (a box resting on a half-space, so contacts run alongside), far
// enough apart that no new pair of bodies meets after the warm-up.
function makeJointWorld(n) {
  const D = dims(n);
  const gravity = new Array(n).fill(0);
  gravity[1] = -9.81;
  const world = new World({ dimensions: n, gravity, params: { allowSleep: false } });
  const at = (x, y, z = 0) => {
    const p = new Array(n).fill(0);
    p[0] = x;
    p[1] = y;
    p[2] = z;
    return p;
  };
  const up = new Array(n).fill(0);
  up[1] = 1;
  world.addBody(new Body(D, { shape: HalfSpace(D, up, -20), mass: 0 }));
  const ball = () => HyperSphere(D, 0.1);
  const links = [];
  for (let i = 0; i < 8; i += 1) links.push(world.addBody(new Body(D, { shape: ball(), mass: 1, position: at(i + 0.5, 0) })));
  world.addConstraint(new PointJoint(links[0], null, at(-0.5, 0), at(0, 0)));
  for (let i = 1; i < 8; i += 1) world.addConstraint(new PointJoint(links[i - 1], links[i], at(0.5, 0), at(-0.5, 0)));
  const ring = [];
  for (let i = 0; i < 4; i += 1)
    ring.push(world.addBody(new Body(D, { shape: ball(), mass: 1, position: at(-30 + (i % 2), 2 + (i >> 1), 1) })));
  world.addConstraint(new PointJoint(ring[0], null, at(0, 0), at(-30, 2, 1)));
  for (let i = 0; i < 4; i += 1) world.addConstraint(new DistanceJoint(ring[i], ring[(i + 1) % 4], at(0, 0), at(0, 0)));
  const base = world.addBody(new Body(D, { shape: HyperBox(D, new Array(n).fill(0.3)), mass: 2, position: at(-40, 0, 3) }));
  const arm = world.addBody(new Body(D, { shape: HyperBox(D, new Array(n).fill(0.2)), mass: 1, position: at(-39, 0, 3) }));
  world.addConstraint(new FixedJoint(base, null, at(0, 0), at(-40, 0, 3)));
  world.addConstraint(
    new HingeJoint(base, arm, at(0.5, 0), at(-0.5, 0), {
      plane: 0,
      lowerAngle: -1,
      upperAngle: 1,
      motorSpeed: 2,
      maxMotorTorque: 5,
    }),
  );
  const bob = world.addBody(new Body(D, { shape: ball(), mass: 1, position: at(-50, -1, 3) }));
  world.addConstraint(new DistanceJoint(bob, null, at(0, 0), at(-50, 0, 3), { mode: 'rope', hertz: 4, damping: 0.5 }));
  const pinned = world.addBody(
    new Body(D, {
      shape: HyperBox(D, new Array(n).fill(0.25)),
      mass: 1,
      position: at(30, -19.75, -3),
      angularVelocity: Array.from({ length: D.k }, (_, p) => 0.5 + p),
    }),
  );
  const lock = [n - 1];
  const planes = [];
  for (let p = 0; p < D.k; p += 1) if (D.planeJ[p] === n - 1) planes.push(p);
  world.addConstraint(
    new SubspaceJoint(pinned, null, { lockAxes: lock, lockPlanes: planes, worldFrame: true, localB: at(0, 0, -3) }),
  );
  return world;
}

/**
 * Point-joint chains in 3D, and nothing else jointed: the forest is solved by the joint-space
 * path in 3 × 3 blocks (joints4's mixed widths take the general one). A chain of 10 pinned at one
 * end whips; a taut chain of 5 pinned at both ends has redundant rows (pivots dropped).
 */
function makeChainWorld() {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: [0, -9.81, 0], params: { allowSleep: false } });
  const ball = () => HyperSphere(D, 0.1);
  const whip = [];
  for (let i = 0; i < 10; i += 1) whip.push(world.addBody(new Body(D, { shape: ball(), mass: 1, position: [i + 0.5, 0, 0] })));
  world.addConstraint(new PointJoint(whip[0], null, [-0.5, 0, 0], [0, 0, 0]));
  for (let i = 1; i < 10; i += 1) world.addConstraint(new PointJoint(whip[i - 1], whip[i], [0.5, 0, 0], [-0.5, 0, 0]));
  const taut = [];
  for (let i = 0; i < 5; i += 1) taut.push(world.addBody(new Body(D, { shape: ball(), mass: 1, position: [i + 0.5, 0, 20] })));
  world.addConstraint(new PointJoint(taut[0], null, [-0.5, 0, 0], [0, 0, 20]));
  for (let i = 1; i < 5; i += 1) world.addConstraint(new PointJoint(taut[i - 1], taut[i], [0.5, 0, 0], [-0.5, 0, 0]));
  world.addConstraint(new PointJoint(taut[4], null, [0.5, 0, 0], [5, 0, 20]));
  return world;
}

const gcs = [];
const observer = new PerformanceObserver((list) => {
  for (const entry of list.getEntries()) gcs.push({ start: entry.startTime, kind: entry.detail?.kind ?? entry.kind });
});
observer.observe({ entryTypes: ['gc'] });

// Windows measured per dimension. Total heap growth also counts what the JIT leaves in old space
// when it finishes compiling in the window (seen: 0-220 KB now and then); that does not repeat, so
// the test takes the smallest total over the windows. Allocation by the step itself repeats in
// every window and lands in new space, which is reported per window too. A branch first taken
// late also costs one window: in chains3 `finishJoint` deoptimises at about step 12,900 (V8:
// "insufficient type feedback for binary operation", a branch its rows first take there) and runs
// in the interpreter, boxing doubles (about 460 KB), until it is optimised again; a fourth window
// keeps two clean ones after it.
const WINDOWS = 4;

const results = {};
const scenes = [
  ['3', () => makeWorld(3)],
  ['4', () => makeWorld(4)],
  ['stack3', () => makeStackWorld(3)],
  ['stack4', () => makeStackWorld(4)],
  ['joints3', () => makeJointWorld(3)],
  ['joints4', () => makeJointWorld(4)],
  ['chains3', () => makeChainWorld()],
];
const only = process.argv[3];
if (!scenes.some(([name]) => name === only)) {
  console.error(`engine-allocation.mjs: SCENE must be one of ${scenes.map(([name]) => name).join(', ')}`);
  process.exit(2);
}
for (const [name, make] of scenes) {
  if (name !== only) continue;
  const world = make();
  const dt = 1 / 60;
  for (let s = 0; s < warmup; s += 1) world.step(dt);
  let probes = 0;
  let probeGrowth = Infinity;
  while (probes < SETTLE_PROBES && probeGrowth >= 8 * 1024) {
    // Let concurrent compilation jobs finish and install their code.
    await new Promise((resolve) => setTimeout(resolve, 100));
    globalThis.gc();
    const before = v8.getHeapSpaceStatistics().find((sp) => sp.space_name === 'new_space').space_used_size;
    for (let s = 0; s < SETTLE_STEPS; s += 1) world.step(dt);
    probeGrowth = v8.getHeapSpaceStatistics().find((sp) => sp.space_name === 'new_space').space_used_size - before;
    probes += 1;
  }
  const windows = [];
  for (let w = 0; w < WINDOWS; w += 1) {
    globalThis.gc();
    globalThis.gc();
    // Let the concurrent sweeper finish, so old-space accounting does not move in the window.
    await new Promise((resolve) => setTimeout(resolve, 50));
    const spacesBefore = v8.getHeapSpaceStatistics();
    const t0 = performance.now();
    const before = v8.getHeapStatistics().used_heap_size;
    for (let s = 0; s < steps; s += 1) world.step(dt);
    const after = v8.getHeapStatistics().used_heap_size;
    const t1 = performance.now();
    const spacesAfter = v8.getHeapSpaceStatistics();
    // Let the observer deliver the entries of the window.
    await new Promise((resolve) => setTimeout(resolve, 20));
    const inWindow = gcs.filter((g) => g.start >= t0 && g.start <= t1);
    // Growth per heap space: new_space is what running code allocated.
    const spaces = {};
    for (let i = 0; i < spacesAfter.length; i += 1) {
      const grown = spacesAfter[i].space_used_size - spacesBefore[i].space_used_size;
      if (grown !== 0) spaces[spacesAfter[i].space_name] = grown;
    }
    windows.push({
      // Compiled code is the JIT's, never the step's: a late compile of a large function (150 KB of
      // code space, seen in two windows of three on a loaded machine) is left out of the total.
      bytes: after - before - (spaces.code_space ?? 0) - (spaces.code_large_object_space ?? 0),
      newSpace: spaces.new_space ?? 0,
      spaces,
      collections: inWindow.length,
      kinds: inWindow.map((g) => g.kind),
      msPerStep: (t1 - t0) / steps,
    });
  }
  results[name] = {
    steps,
    settleProbes: probes,
    bodies: world.bodies.length,
    joints: world.constraints?.length ?? 0,
    touching: world.touchingCount,
    windows,
  };
}
observer.disconnect();
console.log(JSON.stringify(results));
