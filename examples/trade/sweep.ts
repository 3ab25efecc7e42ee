/**
 * One run of the trade page: a scene stepped for a number of simulated seconds, a few steps at a
 * time, recording after every step its error and the milliseconds `world.step` took
 * (performance.now around the call). The same code runs in the page or in its worker
 * (sweep-worker.ts).
 */
import { SCENES, paramsOf } from './scenes.js';
import type { Knobs, Outline, SceneName, TradeScene } from './scenes.js';

/** What a run has measured so far (plain data: the worker posts it). */
export interface Progress {
  /** Simulated time after each step (s). */
  readonly times: number[];
  /** The scene's error after each step (m). */
  readonly errors: number[];
  /** Milliseconds each step took. */
  readonly costs: number[];
  /** Largest error so far (m). */
  worst: number;
  /** Mean milliseconds per step. */
  msPerStep: number;
  /** Milliseconds of stepping per simulated second. */
  msPerSecond: number;
  /** The steps asked for. */
  total: number;
  done: boolean;
  /** The bodies now, for the view. */
  bodies: Outline[];
  links: number[];
  frame: readonly [number, number, number, number];
  /** The engine's message if a step threw (the run stops there). */
  failure: string | null;
}

let warm = false;

/**
 * Steps every scene a little, once per thread, before the first measured run: otherwise the first
 * run would also pay for compiling the engine's code, and look dearer than it is.
 */
export function warmUp(): void {
  if (warm) return;
  warm = true;
  for (const build of Object.values(SCENES)) {
    const scene = build(paramsOf({ iterations: 10, subSteps: 2, rate: 60 }));
    for (let i = 0; i < 120; i += 1) scene.world.step();
    scene.error();
    scene.outline();
  }
}

export class Sweep {
  readonly progress: Progress;
  private readonly scene: TradeScene;
  private readonly rate: number;
  private steps = 0;
  private ms = 0;

  constructor(name: SceneName, knobs: Knobs, seconds: number) {
    warmUp();
    this.scene = SCENES[name](paramsOf(knobs));
    this.rate = knobs.rate;
    const { bodies, links } = this.scene.outline();
    this.progress = {
      times: [],
      errors: [],
      costs: [],
      worst: 0,
      msPerStep: 0,
      msPerSecond: 0,
      total: Math.round(seconds * knobs.rate),
      done: false,
      bodies,
      links,
      frame: this.scene.frame,
      failure: null,
    };
  }

  /** Steps for about `budgetMs` milliseconds (at least one step) and returns the progress. */
  advance(budgetMs: number): Progress {
    const p = this.progress;
    if (p.done) return p;
    const until = performance.now() + budgetMs;
    const world = this.scene.world;
    do {
      if (this.steps >= p.total) break;
      const t0 = performance.now();
      try {
        world.step();
      } catch (e) {
        p.failure = e instanceof Error ? e.message : String(e);
        p.done = true;
        break;
      }
      const dt = performance.now() - t0;
      this.ms += dt;
      this.steps += 1;
      const error = this.scene.error();
      p.times.push(this.steps / this.rate);
      p.errors.push(error);
      p.costs.push(dt);
      if (error > p.worst || !Number.isFinite(error)) p.worst = Number.isFinite(error) ? error : Infinity;
    } while (performance.now() < until);
    if (this.steps > 0) {
      p.msPerStep = this.ms / this.steps;
      p.msPerSecond = this.ms / (this.steps / this.rate);
    }
    if (this.steps >= p.total) p.done = true;
    const { bodies, links } = this.scene.outline();
    p.bodies = bodies;
    p.links = links;
    return p;
  }
}
