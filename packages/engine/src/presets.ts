/**
 * Three points on the trade between accuracy and cost, chosen from the Pareto front that
 * `bench/trade.bench.mjs` measures (docs/trade.md: the sweep of iterations × sub-steps × time
 * step over six scenes, the error and cost of each preset on each scene, and the bounds that
 * tests/engine-presets.test.ts holds).
 *
 * ```ts
 * const world = new World({ dimensions: 3, params: { ...presets.accurate } });
 * ```
 *
 * @module
 */
import type { Params } from './params.js';

/** The parameters a preset sets; the rest keep their defaults (`defaultParams`). */
export type Preset = Readonly<Partial<Params>>;

/** The presets, by name. */
export interface Presets {
  /**
   * Cheapest: 4 iterations, one sub-step, a step of 1/30 s (call `world.step()` 30 times per
   * second). Measured (docs/trade.md, 10 s): 0.3–0.6 × the default's cost per simulated second;
   * a stack of 9 drifts by 4.3 mm, a 4D stack of 6 by 2.4 mm, a pyramid by 0.64 mm, the chains
   * open by 0.39 µm (1:1) and 4.7 µm (1000:1), a tumbling body's rotor is 8.5e-3 off.
   */
  readonly fast: Preset;
  /**
   * The defaults (10 iterations, one sub-step, 1/60 s): nothing is changed. Measured: a stack of
   * 9 drifts by 1.1 mm, a 4D stack of 6 by 0.31 mm, a pyramid by 40 µm, the chains open by 2.4 µm
   * (1:1) and 4e-11 m (1000:1), a tumbling body's rotor is 2.1e-3 off.
   */
  readonly balanced: Preset;
  /**
   * Most accurate: 10 iterations, 4 sub-steps, a step of 1/120 s (an eighth of the default's
   * sub-step). Measured: 6–8 × the default's cost; a stack of 9 drifts by 12 µm, a 4D stack of 6
   * by 4.6 µm, a pyramid by 0.74 µm, the chains hold to round-off (below 1e-13 m), a tumbling
   * body's rotor is 3.3e-5 off.
   */
  readonly accurate: Preset;
}

/** The presets, frozen: spread one into `World`'s `params` (`{ ...presets.fast }`). */
export const presets: Presets = Object.freeze({
  fast: Object.freeze({ iterations: 4, subSteps: 1, fixedTimeStep: 1 / 30 }),
  balanced: Object.freeze({}),
  accurate: Object.freeze({ iterations: 10, subSteps: 4, fixedTimeStep: 1 / 120 }),
});
