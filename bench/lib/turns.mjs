// Running several engines on one clock, in turns.
//
// Why: the machine is shared and its speed drifts (we measured the same scene 2× apart a few
// minutes later). Timed one after the other, one engine can meet a slow minute and its peer a fast
// one, and their ratio then measures the host. Run in turns of a few dozen steps, both meet the
// same minutes, while each keeps its data warm in the cache within its own turn.
import { performance } from 'node:perf_hooks';

/** Steps per turn. */
export const TURN_STEPS = 50;

/**
 * @typedef {object} Lane  One engine on one scene.
 * @property {string} label  For error messages.
 * @property {() => void} [prepare]  Untimed warm-up before the build (e.g. a small throwaway scene).
 * @property {() => any} build  Builds the scene (timed as buildMs).
 * @property {(scene: any) => void} step  One step of the scene (the only thing timed).
 * @property {(scene: any) => void} [observe]  After each step, untimed (e.g. a joint error).
 * @property {(scene: any, capped: boolean) => object} [finish]  After the last step: extra fields
 *   of the result (e.g. a verdict). The scene's `dispose()` is called after it, if it has one.
 * @property {number} [budgetMs]  Wall clock the lane may spend stepping; beyond it, it stops (capped).
 */

/**
 * Runs the lanes side by side: each is prepared and built, then they take turns of `turn` steps
 * until each has run `steps` or spent its budget. Every step is timed alone.
 *
 * Returns, per lane, `{ median, p10, p90, steps, capped, buildMs, ...finish() }`, or
 * `{ error, steps }` when the lane threw (the others go on).
 *
 * @param {Lane[]} lanes
 * @param {{ steps: number, turn?: number }} options
 */
export function runInTurns(lanes, { steps, turn = TURN_STEPS }) {
  const states = lanes.map((lane) => {
    try {
      lane.prepare?.();
      const t0 = performance.now();
      const scene = lane.build();
      return { lane, scene, buildMs: performance.now() - t0, times: new Float64Array(steps), done: 0, spent: 0, result: null };
    } catch (error) {
      return { lane, result: { error, steps: 0 } };
    }
  });
  let active = states.filter((st) => st.result === null);
  while (active.length > 0) {
    for (const st of active) {
      const { lane, scene, times } = st;
      const budget = lane.budgetMs ?? Infinity;
      try {
        const stop = Math.min(steps, st.done + turn);
        while (st.done < stop && st.spent <= budget) {
          const a = performance.now();
          lane.step(scene);
          const b = performance.now();
          times[st.done] = b - a;
          st.spent += b - a;
          st.done += 1;
          lane.observe?.(scene);
        }
        if (st.done === steps || st.spent > budget) st.result = finish(st, steps);
      } catch (error) {
        scene.dispose?.();
        st.result = { error, steps: st.done };
      }
    }
    active = active.filter((st) => st.result === null);
  }
  return states.map((st) => st.result);
}

function finish(st, steps) {
  const { done, scene, lane } = st;
  const sorted = st.times.subarray(0, done).sort();
  const q = (p) => sorted[Math.round((done - 1) * p)];
  const capped = done < steps;
  const extra = lane.finish?.(scene, capped) ?? {};
  scene.dispose?.();
  return { median: q(0.5), p10: q(0.1), p90: q(0.9), steps: done, capped, buildMs: st.buildMs, ...extra };
}

/**
 * `rounds` runs of runInTurns; each lane's result is that of its median round by median ms/step,
 * so its quantiles and extra fields come from one real run; a lane that threw in any round
 * returns that error (never hidden behind a median). `rounds` is recorded on each result.
 *
 * @param {Lane[]} lanes
 * @param {number} rounds
 * @param {{ steps: number, turn?: number }} options
 */
export function runRoundsInTurns(lanes, rounds, options) {
  const all = Array.from({ length: rounds }, () => runInTurns(lanes, options));
  return lanes.map((_, i) => {
    const mine = all.map((r) => r[i]);
    const failed = mine.find((r) => r.error !== undefined);
    if (failed) return { ...failed, rounds };
    mine.sort((x, y) => x.median - y.median);
    return { ...mine[Math.floor((mine.length - 1) / 2)], rounds };
  });
}
