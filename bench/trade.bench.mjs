// The trade between accuracy and cost (issue 17): sweeps iterations × sub-steps × time step over
// the scenes of examples/trade/trade-core.mjs (the code the examples site's trade page runs), with
// Rapier and cannon-es on the 3D box scenes and the chains, and writes docs/trade.md and docs/images/trade-*.svg.
//
// Error: each scene's own measure, the worst over the run (bit-identical from run to run). Cost:
// milliseconds of `step` per simulated second, the median of RUNS runs; every round runs every
// configuration once (ours and the peers'), so that the drift of a shared machine's speed falls on
// all of them alike.
//
//   node bench/trade.bench.mjs            # after a build; ≈ 75 s on 2 cores
import { writeFileSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { FRICTION, GRID, PEER_SCENES, PRESETS, Run, SCENES, paretoFront, warmUp } from '../examples/trade/trade-core.mjs';
import { medianTable } from './lib/table.mjs';
import { loadCannon, loadRapier } from './scenes/peer-scenes.mjs';
import { cannonChain, rapierChain } from './scenes/joint-scenes.mjs';

const SECONDS = 10;
const RUNS = 3;
const ROOT = join(dirname(fileURLToPath(import.meta.url)), '..');

const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s[s.length >> 1];
};
const fmt = (x) =>
  x === Infinity ? '∞' : x === 0 ? '0' : Math.abs(x) >= 0.01 && Math.abs(x) < 1000 ? x.toPrecision(3) : x.toExponential(2);
const dtName = (rate) => `1/${rate}`;
const presetOf = (k) =>
  Object.keys(PRESETS).find(
    (p) => PRESETS[p].iterations === k.iterations && PRESETS[p].subSteps === k.subSteps && PRESETS[p].rate === k.rate,
  );

/** The bound a test holds: 1.5 × the measured error rounded up to two digits, and at least 1e-12 (round-off). */
function boundOf(error) {
  const want = Math.max(error * 1.5, 1e-12);
  const unit = 10 ** (Math.floor(Math.log10(want)) - 1);
  return Number.parseFloat((Math.ceil(want / unit - 1e-9) * unit).toPrecision(2));
}

// ---- the peers, on the same box centres, friction and measure ----

function drift(starts, now) {
  let worst = 0;
  for (let b = 0; b < starts.length; b += 1) {
    const d = Math.hypot(now[b][0] - starts[b][0], now[b][1] - starts[b][1], now[b][2] - starts[b][2]);
    worst = Math.max(worst, Number.isFinite(d) ? d : Infinity);
  }
  return worst;
}

function rapierScene(RAPIER, centres, { iterations, rate }) {
  const world = new RAPIER.World({ x: 0, y: -9.81, z: 0 });
  world.timestep = 1 / rate;
  world.numSolverIterations = iterations;
  const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  world.createCollider(new RAPIER.ColliderDesc(new RAPIER.HalfSpace({ x: 0, y: 1, z: 0 })).setFriction(FRICTION), ground);
  const bodies = centres.map(([x, y, z]) => {
    const body = world.createRigidBody(RAPIER.RigidBodyDesc.dynamic().setTranslation(x, y, z).setCanSleep(false));
    world.createCollider(RAPIER.ColliderDesc.cuboid(0.5, 0.5, 0.5).setDensity(1).setFriction(FRICTION), body);
    return body;
  });
  return {
    step: () => world.step(),
    error: () =>
      drift(
        centres,
        bodies.map((b) => {
          const t = b.translation();
          return [t.x, t.y, t.z];
        }),
      ),
    dispose: () => world.free(),
  };
}

function cannonScene(CANNON, centres, { iterations, rate }) {
  const world = new CANNON.World({ gravity: new CANNON.Vec3(0, -9.81, 0), allowSleep: false });
  world.broadphase = new CANNON.SAPBroadphase(world);
  const solver = new CANNON.GSSolver();
  solver.iterations = iterations;
  world.solver = solver;
  world.defaultContactMaterial.friction = FRICTION;
  world.defaultContactMaterial.restitution = 0;
  const ground = new CANNON.Body({ type: CANNON.Body.STATIC, mass: 0, shape: new CANNON.Plane() });
  ground.quaternion.setFromEuler(-Math.PI / 2, 0, 0);
  world.addBody(ground);
  const shape = new CANNON.Box(new CANNON.Vec3(0.5, 0.5, 0.5));
  const bodies = centres.map(([x, y, z]) => {
    const body = new CANNON.Body({ mass: 1, shape, position: new CANNON.Vec3(x, y, z), allowSleep: false });
    world.addBody(body);
    return body;
  });
  const dt = 1 / rate;
  return {
    step: () => world.step(dt),
    error: () =>
      drift(
        centres,
        bodies.map((b) => [b.position.x, b.position.y, b.position.z]),
      ),
    dispose: () => {},
  };
}

/** One run of a peer: worst error and ms per simulated second. */
function runPeer(make, knobs) {
  const scene = make(knobs);
  const total = Math.round(SECONDS * knobs.rate);
  let ms = 0;
  let worst = 0;
  for (let s = 0; s < total; s += 1) {
    const t0 = performance.now();
    scene.step();
    ms += performance.now() - t0;
    const e = scene.error();
    if (!(e <= worst)) worst = Number.isFinite(e) ? e : Infinity;
  }
  scene.dispose();
  return { worst, msPerSecond: ms / SECONDS };
}

// ---- the configurations ----

const configs = [];
for (const scene of Object.keys(SCENES)) {
  for (const iterations of GRID.iterations) {
    for (const subSteps of GRID.subSteps) {
      for (const rate of GRID.rate) configs.push({ engine: 'PhysiN', scene, knobs: { iterations, subSteps, rate }, costs: [] });
    }
  }
}
const RAPIER = await loadRapier();
const CANNON = await loadCannon();
// The chains are the joint benchmark's chain (bench/scenes/joint-scenes.mjs: the same
// links, anchors and start; the error is the largest gap a joint opens), at each peer's default
// iterations: those scenes do not take other counts.
const chainOf = (build, lib, ratio) => (knobs) => build(lib, { dt: 1 / knobs.rate, ratio });
const PEERS = [
  {
    engine: 'Rapier',
    build: rapierScene,
    lib: RAPIER,
    iterations: [4, 8],
    defaults: { iterations: 4, rate: 60 },
    chains: { 'chain of 10': chainOf(rapierChain, RAPIER, 1), 'chain 1000:1': chainOf(rapierChain, RAPIER, 1000) },
  },
  {
    engine: 'cannon-es',
    build: cannonScene,
    lib: CANNON,
    iterations: [10, 20],
    defaults: { iterations: 10, rate: 60 },
    chains: { 'chain of 10': chainOf(cannonChain, CANNON, 1), 'chain 1000:1': chainOf(cannonChain, CANNON, 1000) },
  },
];
for (const peer of PEERS) {
  for (const scene of Object.keys(PEER_SCENES)) {
    const make = (knobs) => peer.build(peer.lib, PEER_SCENES[scene](), knobs);
    for (const iterations of peer.iterations) {
      for (const rate of GRID.rate) {
        configs.push({ engine: peer.engine, peer, scene, make, knobs: { iterations, subSteps: 1, rate }, costs: [] });
      }
    }
  }
  for (const [scene, make] of Object.entries(peer.chains)) {
    for (const rate of GRID.rate) {
      const knobs = { iterations: peer.defaults.iterations, subSteps: 1, rate };
      configs.push({ engine: peer.engine, peer, scene, make, knobs, costs: [] });
    }
  }
}

// ---- the runs ----

const started = performance.now();
warmUp();
for (const c of configs) if (c.engine !== 'PhysiN' && c.knobs.rate === 60) runPeer(c.make, c.knobs);
for (let round = 0; round < RUNS; round += 1) {
  for (const c of configs) {
    if (c.engine === 'PhysiN') {
      const run = new Run(c.scene, c.knobs, SECONDS);
      run.advance(Infinity);
      c.worst = run.worst;
      c.failure = run.failure;
      c.costs.push(run.msPerSecond);
    } else {
      const r = runPeer(c.make, c.knobs);
      c.worst = r.worst;
      c.costs.push(r.msPerSecond);
    }
  }
}
for (const c of configs) c.cost = median(c.costs);
const elapsed = (performance.now() - started) / 1000;

// ---- the tables ----

const units = {};
for (const name of Object.keys(SCENES)) units[name] = SCENES[name]({ allowSleep: false }).unit;
const ours = (scene) => configs.filter((c) => c.engine === 'PhysiN' && c.scene === scene);
const fronts = {};
for (const scene of Object.keys(SCENES)) {
  const points = ours(scene).map((c) => ({ error: c.worst, cost: c.cost, c }));
  fronts[scene] = new Set(paretoFront(points.filter((p) => Number.isFinite(p.error))).map((p) => p.c));
}
const knobText = (k) => `${k.iterations} it × ${k.subSteps} sub × ${dtName(k.rate)} s`;

const md = [];
md.push('# The trade: accuracy against cost');
md.push('');
md.push('_Written by `bench/trade.bench.mjs` (`pnpm bench:trade` in bench/, after a build); do not edit by hand._');
md.push('');
md.push(
  `Each scene of \`examples/trade/trade-core.mjs\` (the code the examples site's trade page runs) is stepped for ${SECONDS} simulated seconds at every point of the grid iterations ${GRID.iterations.join(', ')} × sub-steps ${GRID.subSteps.join(', ')} × time step ${GRID.rate.map(dtName).join(', ')} s. **Error** is the scene's own measure, the worst over the run: for the box scenes the largest drift of a box from where it started (m), for the chains the largest gap a joint opens (m), for the spinning body the distance of its rotor from a reference run at 240 Hz × 16 sub-steps (≈ half the angle error, rad). **Cost** is the median over ${RUNS} runs of the milliseconds \`world.step\` took per simulated second (one thread of the machine below). Rapier ${'0.21.0'} and cannon-es 0.20.0 run the 3D box scenes in the same run, with the same boxes, friction ${FRICTION} and error measure, at their default iterations and twice that, and the two chains (the joint benchmark's chain: the same links, anchors and start; the last link 1 or 1000 kg) at their default iterations, over the same time steps (they have no sub-steps); the 4D stack has no peer, and the spinning body is measured against PhysiN's own fine run, so peers are not placed on it. Every round runs every configuration once, so a drift of the machine's speed falls on all alike.`,
);
md.push('');
md.push(
  `Machine: ${(await import('node:os')).cpus()[0]?.model ?? 'unknown'}, Node ${process.version}. The whole run took ${elapsed.toFixed(0)} s.`,
);
md.push('');
md.push('## Presets');
md.push('');
md.push(
  '`presets` of `@physin/engine` (`new World({ params: { ...presets.accurate } })`), chosen from the Pareto fronts below; `balanced` is the defaults.',
);
md.push('');
for (const [name, k] of Object.entries(PRESETS)) md.push(`- \`${name}\`: ${knobText(k)}`);
md.push('');
md.push(
  'How they were chosen. On every scene the error follows the sub-step (dt / sub-steps) first: 4 × 2 × 1/120 s and 4 × 4 × 1/60 s give the same error at the same cost. Iterations count only on the contact scenes, the pyramid most (4 iterations leave it 6 times the error of 10 at the smallest sub-step); the chains (solved directly as a tree) and the free body ignore them. `fast` is the cheapest point of every front. `balanced` is the defaults, unchanged; on the stacks it sits within the cost noise of the front (10 × 2 × 1/30 s has the same sub-step and error). `accurate` keeps the default iterations and takes a sub-step of 1/480 s, on or within a few per cent of the front on the contact scenes. Whether a point counts as on the front depends on costs measured on a shared machine, a few per cent apart; the errors are exact (the same bits on every run).',
);
md.push('');
md.push(
  'Measured error and cost of each preset per scene, and the bound tests/engine-presets.test.ts holds (the measured error × 1.5 rounded up to two digits, and at least 1e-12, the round-off of these sums):',
);
md.push('');
const presetRows = [];
md.push('| scene | preset | error | bound | ms / simulated s | on the front |');
md.push('|---|---|---|---|---|---|');
for (const scene of Object.keys(SCENES)) {
  for (const name of Object.keys(PRESETS)) {
    const c = ours(scene).find((x) => presetOf(x.knobs) === name);
    if (c === undefined) continue;
    const up = boundOf(c.worst);
    presetRows.push({ scene, preset: name, error: c.worst, bound: up, 'ms/s': c.cost });
    md.push(
      `| ${scene} | ${name} | ${fmt(c.worst)} ${units[scene]} | ${fmt(up)} | ${fmt(c.cost)} | ${fronts[scene].has(c) ? 'yes' : 'no'} |`,
    );
  }
}
md.push('');
for (const scene of Object.keys(SCENES)) {
  md.push(`## ${scene}`);
  md.push('');
  md.push(`![${scene}: error against cost](images/trade-${slug(scene)}.svg)`);
  md.push('');
  md.push(`| engine | iterations | sub-steps | dt (s) | error (${units[scene]}) | ms / simulated s | front | preset |`);
  md.push('|---|---|---|---|---|---|---|---|');
  const rows = configs
    .filter((c) => c.scene === scene)
    .sort((a, b) => (a.engine === b.engine ? a.cost - b.cost : a.engine === 'PhysiN' ? -1 : 1));
  for (const c of rows) {
    const k = c.knobs;
    const mine = c.engine === 'PhysiN';
    md.push(
      `| ${c.engine} | ${k.iterations} | ${mine ? k.subSteps : '—'} | ${dtName(k.rate)} | ${fmt(c.worst)}${c.failure ? ' (threw)' : ''} | ${fmt(c.cost)} | ${mine && fronts[scene].has(c) ? '●' : ''} | ${mine ? (presetOf(k) ?? '') : ''} |`,
    );
  }
  md.push('');
}
mkdirSync(join(ROOT, 'docs', 'images'), { recursive: true });
writeFileSync(join(ROOT, 'docs', 'trade.md'), md.join('\n'));

// ---- the plots ----

function slug(s) {
  return s
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-|-$/g, '');
}

function svgPlot(scene) {
  const W = 640;
  const H = 420;
  const L = 70;
  const R = 150;
  const T = 30;
  const B = 50;
  const all = configs.filter((c) => c.scene === scene && Number.isFinite(c.worst));
  const floor = 1e-16;
  const ys = all.map((c) => Math.max(c.worst, floor));
  const xs = all.map((c) => c.cost);
  const lx0 = Math.floor(Math.log10(Math.min(...xs)));
  const lx1 = Math.ceil(Math.log10(Math.max(...xs)));
  const ly0 = Math.floor(Math.log10(Math.min(...ys)));
  const ly1 = Math.ceil(Math.log10(Math.max(...ys)));
  const X = (v) => L + ((Math.log10(v) - lx0) / Math.max(lx1 - lx0, 1)) * (W - L - R);
  const Y = (v) => H - B - ((Math.log10(Math.max(v, floor)) - ly0) / Math.max(ly1 - ly0, 1)) * (H - T - B);
  const o = [];
  o.push(
    `<svg xmlns="http://www.w3.org/2000/svg" width="${W}" height="${H}" viewBox="0 0 ${W} ${H}" font-family="sans-serif" font-size="12">`,
  );
  o.push(`<rect width="${W}" height="${H}" fill="white"/>`);
  o.push(`<text x="${L}" y="18" font-size="14" font-weight="bold">${scene}: error against cost (log–log)</text>`);
  for (let e = lx0; e <= lx1; e += 1) {
    const x = X(10 ** e).toFixed(1);
    o.push(
      `<line x1="${x}" y1="${T}" x2="${x}" y2="${H - B}" stroke="#eee"/><text x="${x}" y="${H - B + 16}" text-anchor="middle">1e${e}</text>`,
    );
  }
  const step = Math.max(1, Math.ceil((ly1 - ly0) / 8));
  for (let e = ly0; e <= ly1; e += step) {
    const y = Y(10 ** e).toFixed(1);
    o.push(
      `<line x1="${L}" y1="${y}" x2="${W - R}" y2="${y}" stroke="#eee"/><text x="${L - 6}" y="${y}" text-anchor="end" dominant-baseline="middle">1e${e}</text>`,
    );
  }
  o.push(`<rect x="${L}" y="${T}" width="${W - L - R}" height="${H - T - B}" fill="none" stroke="#888"/>`);
  o.push(`<text x="${(L + W - R) / 2}" y="${H - 12}" text-anchor="middle">ms of step per simulated second</text>`);
  o.push(
    `<text transform="translate(16 ${(T + H - B) / 2}) rotate(-90)" text-anchor="middle">worst error (${units[scene]})</text>`,
  );
  const mine = all.filter((c) => c.engine === 'PhysiN');
  for (const c of mine)
    o.push(
      `<circle cx="${X(c.cost).toFixed(1)}" cy="${Y(c.worst).toFixed(1)}" r="3" fill="#999"><title>${knobText(c.knobs)}: ${fmt(c.worst)}, ${fmt(c.cost)} ms/s</title></circle>`,
    );
  const front = mine.filter((c) => fronts[scene].has(c)).sort((a, b) => a.cost - b.cost);
  o.push(
    `<polyline fill="none" stroke="#1565c0" stroke-width="2" points="${front.map((c) => `${X(c.cost).toFixed(1)},${Y(c.worst).toFixed(1)}`).join(' ')}"/>`,
  );
  const colours = { fast: '#e65100', balanced: '#2e7d32', accurate: '#6a1b9a' };
  for (const c of mine) {
    const p = presetOf(c.knobs);
    if (p === undefined) continue;
    o.push(
      `<circle cx="${X(c.cost).toFixed(1)}" cy="${Y(c.worst).toFixed(1)}" r="7" fill="none" stroke="${colours[p]}" stroke-width="2.5"/>`,
    );
  }
  const peerStyle = { Rapier: '#c62828', 'cannon-es': '#00838f' };
  for (const c of all.filter((x) => x.engine !== 'PhysiN')) {
    const x = X(c.cost);
    const y = Y(c.worst);
    o.push(
      `<rect x="${(x - 4).toFixed(1)}" y="${(y - 4).toFixed(1)}" width="8" height="8" fill="${peerStyle[c.engine]}"><title>${c.engine} ${c.knobs.iterations} it × 1/${c.knobs.rate} s: ${fmt(c.worst)}, ${fmt(c.cost)} ms/s</title></rect>`,
    );
  }
  const legend = [
    ['point', '#999', 'PhysiN grid'],
    ['line', '#1565c0', 'Pareto front'],
    ['ring', colours.fast, 'fast'],
    ['ring', colours.balanced, 'balanced'],
    ['ring', colours.accurate, 'accurate'],
  ];
  if (all.some((c) => c.engine === 'Rapier'))
    legend.push(['square', peerStyle.Rapier, 'Rapier'], ['square', peerStyle['cannon-es'], 'cannon-es']);
  legend.forEach(([kind, colour, label], i) => {
    const x = W - R + 16;
    const y = T + 10 + i * 20;
    if (kind === 'point') o.push(`<circle cx="${x}" cy="${y}" r="3" fill="${colour}"/>`);
    if (kind === 'line') o.push(`<line x1="${x - 8}" y1="${y}" x2="${x + 8}" y2="${y}" stroke="${colour}" stroke-width="2"/>`);
    if (kind === 'ring') o.push(`<circle cx="${x}" cy="${y}" r="6" fill="none" stroke="${colour}" stroke-width="2.5"/>`);
    if (kind === 'square') o.push(`<rect x="${x - 4}" y="${y - 4}" width="8" height="8" fill="${colour}"/>`);
    o.push(`<text x="${x + 14}" y="${y}" dominant-baseline="middle">${label}</text>`);
  });
  o.push('</svg>');
  return o.join('\n') + '\n';
}
for (const scene of Object.keys(SCENES)) writeFileSync(join(ROOT, 'docs', 'images', `trade-${slug(scene)}.svg`), svgPlot(scene));

medianTable(`Presets: worst error and cost (median of ${RUNS} runs, ms per simulated second), ${SECONDS} s`, presetRows);
console.log(`\nwrote docs/trade.md and ${Object.keys(SCENES).length} plots in ${elapsed.toFixed(1)} s of runs`);
