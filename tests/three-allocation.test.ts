/**
 * The adapter allocates nothing per frame in steady state: applying a report to every mesh (the
 * pose, the velocity, re-slicing each 4D body that moved) and moving the slice (`slice` +
 * `refreshSlice`).
 *
 * Method: a child `node --no-concurrent-recompilation --expose-gc --max-semi-space-size=256
 * --min-semi-space-size=64 tests/three-allocation.mjs 1000` builds a 4D scene of 60 hyperboxes, 10
 * hyperspheres, two tori (one sliced by the exact formula, one turned out of xyz and traced) and a
 * 4-simplex `HyperMesh` on a half-space, imports the BUILT packages, warms up, then measures the
 * growth of the young generation over windows of 200 and 1000 frames (least of three windows with
 * no collection inside). A frame that allocated one object per body would grow it by > 1 MB in
 * 1000 frames; the budget is 16 KB, the window's own cost being about 2 KB.
 *
 * Not measured: the step (tests/engine-allocation.test.ts), collision events (one new object per
 * event, by design), and three's `dispatchEvent`, which copies a type's listener array on each
 * dispatch once a listener was added (three's cost, one small array for `update` a frame).
 */
import { execFileSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');

interface Window {
  readonly label: string;
  readonly perFrame: number;
  readonly short: number;
  readonly long: number;
}

let result: { frames: number; bodies: number; visible: number; results: Window[] };

beforeAll(() => {
  const out = execFileSync(
    process.execPath,
    [
      '--no-concurrent-recompilation',
      '--expose-gc',
      '--max-semi-space-size=256',
      '--min-semi-space-size=64',
      join(root, 'tests/three-allocation.mjs'),
      '1000',
    ],
    { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] },
  );
  result = JSON.parse(out.trim().split('\n').pop()!);
}, 300_000);

describe('the adapter allocates nothing per frame (built packages, child process)', () => {
  it('the scene holds every sliced kind, most of them cut by the flat', () => {
    expect(result.frames).toBe(1000);
    expect(result.bodies).toBe(74);
    expect(result.visible).toBeGreaterThan(50);
  });

  for (const label of ['report', 'slice']) {
    it(`${label}: 1000 frames grow the young generation by < 16 KB`, () => {
      const w = result.results.find((r) => r.label === label)!;
      expect(Number.isFinite(w.long)).toBe(true);
      expect(w.long).toBeLessThan(16 * 1024);
    });
  }
});
