/**
 * One run of the trade page: a scene stepped for a number of simulated seconds, a few steps at a
 * time, recording its error after every step and the time the steps took. The same code runs in
 * the page or in the page's worker (sweep-worker.ts).
 */
import { SCENES, paramsOf } from './scenes.js';
import type { Knobs, SceneName, TradeScene } from './scenes.js';

/** What a run has measured so far. */
export interface Progress {
  readonly times: number[];
  readonly errors: number[];
  worst: number;
  /** Milliseconds of stepping per simulated second. */
  cost: number;
  done: boolean;
}

export class Sweep {
  readonly progress: Progress = { times: [], errors: [], worst: 0, cost: 0, done: false };
  private readonly scene: TradeScene;
  private readonly rate: number;
  private readonly total: number;
  private steps = 0;
  private ms = 0;

  constructor(name: SceneName, knobs: Knobs, seconds: number) {
    this.scene = SCENES[name](paramsOf(knobs));
    this.rate = knobs.rate;
    this.total = Math.round(seconds * knobs.rate);
  }

  /** Steps for about `budgetMs` milliseconds (at least one step) and returns the progress. */
  advance(budgetMs: number): Progress {
    const p = this.progress;
    const until = performance.now() + budgetMs;
    do {
      if (this.steps >= this.total) break;
      const t0 = performance.now();
      this.scene.world.step();
      this.ms += performance.now() - t0;
      this.steps += 1;
      const error = this.scene.error();
      p.times.push(this.steps / this.rate);
      p.errors.push(error);
      p.worst = Math.max(p.worst, error);
    } while (performance.now() < until);
    p.cost = this.ms / (this.steps / this.rate);
    p.done = this.steps >= this.total;
    return p;
  }
}
