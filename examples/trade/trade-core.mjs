/**
 * The trade between accuracy and cost, measured: the scenes and the sweep code shared by the
 * examples site's trade page (examples/trade/) and the bench (bench/trade.bench.mjs). Plain
 * JavaScript (types in trade-core.d.mts) so that Node runs it as it is.
 *
 * Every scene is a function of the engine's parameters returning a world and its error now:
 *
 * - `stack of 9`: nine unit boxes on the ground in 3D; error = the largest drift of a box from
 *   where it started (m).
 * - `pyramid`: a pyramid of unit boxes, base 4 (10 boxes) in 3D; error as the stack (m).
 * - `chain of 10`: the specification's chain (docs/joints.md): ten links of 1 kg, balls of radius
 *   0.1 whose anchors are at ±0.5 along the chain, the first pinned to the world at the origin; it
 *   starts horizontal, so it whips as it falls. Error = the largest gap a joint opens (m).
 * - `chain 1000:1`: the same, the last link 1000 kg.
 * - `4D stack of 6`: six unit hypercubes on the ground in 4D; error as the stack (m).
 * - `spinning body`: a free box (0.8 × 0.5 × 0.2 m) spinning near its unstable middle axis, no
 *   gravity, so that it tumbles; error = the distance of its rotor from a reference run (rate
 *   240 Hz, 16 sub-steps) at the same time, min ‖R ∓ R_ref‖ (≈ half the angle error, rad).
 *
 * @module
 */
import { Body, HalfSpace, HyperBox, HyperSphere, PointJoint, World, defaultParams, dims, presets } from '@physin/engine';

/** The engine's parameters for a set of knobs. Sleep is off: a sleeping body would hide its error. */
export function paramsOf(knobs) {
  return { iterations: knobs.iterations, subSteps: knobs.subSteps, fixedTimeStep: 1 / knobs.rate, allowSleep: false };
}

/** Friction of the boxes (the peers use the same). */
export const FRICTION = 0.6;

function gravity(n) {
  const g = new Array(n).fill(0);
  g[1] = -9.81;
  return g;
}

function ground(D, world) {
  const up = new Array(D.n).fill(0);
  up[1] = 1;
  world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
}

/** Unit (hyper)boxes at the given centres on the ground; error = the largest drift from the start. */
function boxes(params, n, centres, frame) {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: gravity(n), params });
  ground(D, world);
  const half = new Array(n).fill(0.5);
  const list = [];
  const starts = [];
  for (const position of centres) {
    const box = world.addBody(new Body(D, { shape: HyperBox(D, half), mass: 1, position, material: { friction: FRICTION } }));
    list.push(box);
    starts.push(Float64Array.from(box.x));
  }
  return {
    world,
    unit: 'm',
    error: () => {
      let worst = 0;
      for (let b = 0; b < list.length; b += 1) {
        const x = list[b].x;
        const s = starts[b];
        let d2 = 0;
        for (let i = 0; i < n; i += 1) d2 += (x[i] - s[i]) ** 2;
        worst = Math.max(worst, Math.sqrt(d2));
      }
      return worst;
    },
    view: { kind: 'boxes', n, boxes: list, half },
    frame,
  };
}

function stack(params, n, count) {
  return boxes(params, n, stackCentres(n, count), [-4, 4, -0.6, count + 0.6]);
}

/** The centres of a pyramid of unit boxes in 3D, `base` boxes in its lowest row, 1.05 m apart. */
export function pyramidCentres(base) {
  const centres = [];
  for (let row = 0; row < base; row += 1) {
    for (let i = 0; i < base - row; i += 1) centres.push([(i - (base - row - 1) / 2) * 1.05, 0.5 + row, 0]);
  }
  return centres;
}

/** The centres of a stack of `count` unit boxes in n dimensions. */
export function stackCentres(n, count) {
  const centres = [];
  for (let i = 0; i < count; i += 1) {
    const p = new Array(n).fill(0);
    p[1] = 0.5 + i;
    centres.push(p);
  }
  return centres;
}

function pyramid(params, base) {
  return boxes(params, 3, pyramidCentres(base), [-base, base, -0.6, base + 0.6]);
}

/** The specification's chain of 10, starting horizontal; the last link weighs `ratio` kg. */
function chain(params, ratio) {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: gravity(3), params });
  const shape = HyperSphere(D, 0.1);
  const links = [];
  const joints = [];
  for (let i = 0; i < 10; i += 1) {
    const link = world.addBody(new Body(D, { shape, mass: i === 9 ? ratio : 1, position: [i + 0.5, 0, 0] }));
    const previous = links[i - 1];
    joints.push(
      world.addConstraint(
        previous === undefined
          ? new PointJoint(link, null, [-0.5, 0, 0], [0, 0, 0])
          : new PointJoint(previous, link, [0.5, 0, 0], [-0.5, 0, 0]),
      ),
    );
    links.push(link);
  }
  return {
    world,
    unit: 'm',
    error: () => {
      let worst = 0;
      for (const j of joints) worst = Math.max(worst, j.error());
      return worst;
    },
    view: { kind: 'chain', links, heavy: ratio > 1 },
    frame: [-10.5, 10.5, -10.8, 1],
  };
}

const SPIN_HALF = [0.4, 0.25, 0.1];
/** Start angular velocity (bivector e12, e13, e23): mostly about the middle axis (y, the e13 plane). */
const SPIN_OMEGA = [0.05, 4, 0.05];
const REF_RATE = 240;
const REF_SUBSTEPS = 16;
/** The reference rotors, one per 1/240 s, computed once per thread and extended on demand. */
const reference = { world: null, body: null, rotors: [] };

function spinWorld(params) {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: [0, 0, 0], params });
  const body = world.addBody(new Body(D, { shape: HyperBox(D, SPIN_HALF), mass: 1, angularVelocity: SPIN_OMEGA }));
  return { world, body };
}

function referenceRotor(index) {
  if (reference.world === null) {
    const { world, body } = spinWorld(paramsOf({ iterations: 10, subSteps: REF_SUBSTEPS, rate: REF_RATE }));
    reference.world = world;
    reference.body = body;
    reference.rotors.push(Float64Array.from(body.R));
  }
  while (reference.rotors.length <= index) {
    reference.world.step();
    reference.rotors.push(Float64Array.from(reference.body.R));
  }
  return reference.rotors[index];
}

function spinning(params) {
  const { world, body } = spinWorld(params);
  return {
    world,
    unit: 'rad',
    error: () => {
      const ref = referenceRotor(Math.round(world.time * REF_RATE));
      let minus = 0;
      let plus = 0;
      for (let i = 0; i < ref.length; i += 1) {
        minus += (body.R[i] - ref[i]) ** 2;
        plus += (body.R[i] + ref[i]) ** 2;
      }
      return Math.sqrt(Math.min(minus, plus));
    },
    view: { kind: 'boxes', n: 3, boxes: [body], half: SPIN_HALF },
    frame: [-1.5, 1.5, -1.5, 1.5],
  };
}

/** The scenes, by name. */
export const SCENES = Object.freeze({
  'stack of 9': (p) => stack(p, 3, 9),
  pyramid: (p) => pyramid(p, 4),
  'chain of 10': (p) => chain(p, 1),
  'chain 1000:1': (p) => chain(p, 1000),
  '4D stack of 6': (p) => stack(p, 4, 6),
  'spinning body': (p) => spinning(p),
});

/** The 3D scenes that Rapier and cannon-es can also run (bench/scenes/peer-scenes.mjs). */
export const PEER_SCENES = Object.freeze({
  'stack of 9': () => stackCentres(3, 9),
  pyramid: () => pyramidCentres(4),
});

/** The knobs of a set of engine parameters (the defaults where it sets none). */
export function knobsOf(params) {
  const p = { ...defaultParams, ...params };
  return { iterations: p.iterations, subSteps: p.subSteps, rate: Math.round(1 / p.fixedTimeStep) };
}

/** The knobs of the engine's three presets (`presets` of @physin/engine); balanced = the defaults. */
export const PRESETS = Object.freeze({
  fast: Object.freeze(knobsOf(presets.fast)),
  balanced: Object.freeze(knobsOf(presets.balanced)),
  accurate: Object.freeze(knobsOf(presets.accurate)),
});

/** The grid the bench sweeps. */
export const GRID = Object.freeze({
  iterations: Object.freeze([4, 10, 20]),
  subSteps: Object.freeze([1, 2, 4]),
  rate: Object.freeze([30, 60, 120]),
});

const now = () => globalThis.performance.now();

/**
 * One run: a scene stepped for `seconds` simulated seconds, a few steps at a time, recording after
 * every step its error and the milliseconds `world.step` took (performance.now around the call).
 */
export class Run {
  constructor(name, knobs, seconds) {
    const build = SCENES[name];
    if (build === undefined) throw new RangeError(`Run: name: no scene "${name}"`);
    this.scene = build(paramsOf(knobs));
    this.rate = knobs.rate;
    this.total = Math.round(seconds * knobs.rate);
    this.steps = 0;
    this.ms = 0;
    this.times = [];
    this.errors = [];
    this.costs = [];
    this.worst = 0;
    this.failure = null;
    this.done = this.total === 0;
  }

  /** Milliseconds of stepping per simulated second so far. */
  get msPerSecond() {
    return this.steps > 0 ? this.ms / (this.steps / this.rate) : 0;
  }

  /** Steps for about `budgetMs` milliseconds (at least one step); returns whether the run is done. */
  advance(budgetMs) {
    if (this.done) return true;
    const until = now() + budgetMs;
    const world = this.scene.world;
    do {
      const t0 = now();
      try {
        world.step();
      } catch (e) {
        this.failure = e instanceof Error ? e.message : String(e);
        this.worst = Infinity;
        this.done = true;
        return true;
      }
      const dt = now() - t0;
      this.ms += dt;
      this.steps += 1;
      const error = this.scene.error();
      this.times.push(this.steps / this.rate);
      this.errors.push(error);
      this.costs.push(dt);
      if (!(error <= this.worst)) this.worst = Number.isFinite(error) ? error : Infinity;
      if (this.steps >= this.total) this.done = true;
    } while (!this.done && now() < until);
    return this.done;
  }
}

let warm = false;

/**
 * Steps every scene a little, once per thread, before the first measured run: otherwise the first
 * run would also pay for compiling the engine's code, and look dearer than it is.
 */
export function warmUp() {
  if (warm) return;
  warm = true;
  for (const name of Object.keys(SCENES)) new Run(name, { iterations: 10, subSteps: 2, rate: 60 }, 2).advance(Infinity);
}

/** One point of the sweep: the worst error of a run and its cost (ms per simulated second). */
export function runSweepPoint(name, knobs, seconds) {
  warmUp();
  const run = new Run(name, knobs, seconds);
  run.advance(Infinity);
  return { worst: run.worst, msPerSecond: run.msPerSecond, failure: run.failure };
}

/**
 * The Pareto front of points `{ error, cost }`: those that no other point beats on both (at most
 * as dear and at most as wrong, better on one). Returned sorted by cost.
 */
export function paretoFront(points) {
  const sorted = [...points].sort((a, b) => a.cost - b.cost || a.error - b.error);
  const front = [];
  let best = Infinity;
  for (const p of sorted) {
    if (p.error < best) {
      front.push(p);
      best = p.error;
    }
  }
  return front;
}
