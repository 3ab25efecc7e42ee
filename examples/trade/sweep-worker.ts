/**
 * The trade page's worker (`?worker=1`): runs one sweep at a time and posts its progress, so the
 * page stays free while the engine steps.
 */
import { Sweep } from './sweep.js';
import type { Knobs, SceneName } from './scenes.js';

let sweep: Sweep | null = null;

self.onmessage = (event: MessageEvent<{ scene: SceneName; knobs: Knobs; seconds: number }>) => {
  sweep = new Sweep(event.data.scene, event.data.knobs, event.data.seconds);
  const mine = sweep;
  const tick = (): void => {
    if (sweep !== mine) return;
    const progress = mine.advance(40);
    self.postMessage(progress);
    if (!progress.done) setTimeout(tick, 0);
  };
  tick();
};
