/**
 * Frame helpers for the adapter tests: simulate and wait for the report, as a render loop would.
 */
import type { Scene } from '@physin/three';

/** Resolves when the scene's next `update` fires. */
export function nextUpdate(scene: Scene): Promise<void> {
  return new Promise((resolve, reject) => {
    const done = (): void => {
      scene.removeEventListener('update', done);
      scene.removeEventListener('error', fail);
      resolve();
    };
    const fail = (event: { error: Error }): void => {
      scene.removeEventListener('update', done);
      scene.removeEventListener('error', fail);
      reject(event.error);
    };
    scene.addEventListener('update', done);
    scene.addEventListener('error', fail);
  });
}

/** Waits until the scene is ready, then runs `frames` frames of `simulate(dt, max)`. */
export async function run(scene: Scene, frames: number, dt = 1 / 60, max = 2, each?: (frame: number) => void): Promise<void> {
  await scene.host.ready;
  for (let f = 0; f < frames; f += 1) {
    each?.(f);
    const update = nextUpdate(scene);
    if (!scene.simulate(dt, max)) throw new Error(`simulate refused frame ${f}`);
    await update;
  }
}
