/**
 * One run of the trade page: trade-core.mjs's `Run` (the code bench/trade.bench.mjs sweeps for
 * docs/trade.md) stepping a scene for a number of simulated seconds, a few steps at a time,
 * recording after every step its error and the milliseconds `world.step` took; this file adds
 * what the view needs. The same code runs in the page or in its worker (sweep-worker.ts).
 */
import { Run, warmUp } from './trade-core.mjs';
import { withOutline } from './scenes.js';
import type { Knobs, Outline, SceneName, TradeScene } from './scenes.js';

export { warmUp };

/** What a run has measured so far (plain data: the worker posts it). */
export interface Progress {
  /** Simulated time after each step (s). */
  readonly times: number[];
  /** The scene's error after each step (m, or rad for the spinning body). */
  readonly errors: number[];
  /** Milliseconds each step took. */
  readonly costs: number[];
  /** Largest error so far. */
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

export class Sweep {
  readonly progress: Progress;
  private readonly run: Run;
  private readonly scene: TradeScene;

  constructor(name: SceneName, knobs: Knobs, seconds: number) {
    warmUp();
    this.run = new Run(name, knobs, seconds);
    this.scene = withOutline(this.run.scene);
    const { bodies, links } = this.scene.outline();
    this.progress = {
      times: this.run.times,
      errors: this.run.errors,
      costs: this.run.costs,
      worst: 0,
      msPerStep: 0,
      msPerSecond: 0,
      total: this.run.total,
      done: this.run.done,
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
    const run = this.run;
    run.advance(budgetMs);
    p.worst = run.worst;
    p.failure = run.failure;
    p.done = run.done;
    if (run.steps > 0) {
      p.msPerStep = run.ms / run.steps;
      p.msPerSecond = run.msPerSecond;
    }
    const { bodies, links } = this.scene.outline();
    p.bodies = bodies;
    p.links = links;
    return p;
  }
}
