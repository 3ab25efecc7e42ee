/**
 * The trade page's worker (`?worker=1`): runs one sweep at a time and posts its progress, so the
 * page stays free while the engine steps. A new message replaces the run under way.
 */
import { Sweep } from './sweep.js';
import type { Knobs, SceneName } from './scenes.js';

let sweep: Sweep | null = null;

self.onmessage = (event: MessageEvent<{ id: number; scene: SceneName; knobs: Knobs; seconds: number }>) => {
  const { id, scene, knobs, seconds } = event.data;
  sweep = new Sweep(scene, knobs, seconds);
  const mine = sweep;
  const tick = (): void => {
    if (sweep !== mine) return;
    const progress = mine.advance(40);
    self.postMessage({ id, progress });
    if (!progress.done) setTimeout(tick, 0);
  };
  tick();
};
