/**
 * A report is neither allocated nor copied in steady state: writing it (WorldCore: the
 * accumulator, the steps, the records written into the buffer it was given) and reading it
 * (ReportView over that buffer) allocate nothing, by the method of tests/engine-allocation.test.ts
 * (a child `node --no-concurrent-recompilation --expose-gc ... tests/worker-allocation.mjs 5000`
 * on the BUILT package; the young generation over windows of 1000 and 5000 steps of a 41-body
 * resting pile, n = 3 and 4). One boxed number a step would be 80 KB; the budget is 16 KB, the
 * window's own cost being about 2 KB. tests/worker-host.test.ts counts the buffers on both sides
 * and checks that those sent to a worker are moved, not copied.
 */
import { execFileSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { beforeAll, describe, expect, it } from 'vitest';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');

interface Measure {
  readonly short: number;
  readonly long: number;
  readonly bodies: number;
  readonly buffersCreated: number;
  readonly collisions: number;
}

let results: Record<string, Measure> = {};

beforeAll(() => {
  const out = execFileSync(
    process.execPath,
    [
      '--no-concurrent-recompilation',
      '--expose-gc',
      '--max-semi-space-size=256',
      '--min-semi-space-size=64',
      join(root, 'tests/worker-allocation.mjs'),
      '5000',
    ],
    { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] },
  );
  results = (JSON.parse(out.trim().split('\n').pop()!) as { results: Record<string, Measure> }).results;
}, 300_000);

describe('writing and reading a report allocates nothing (built package, child process)', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: 5000 steps and reports of a resting 41-body pile grow the young generation by < 16 KB, in one buffer`, () => {
      const r = results[n]!;
      expect(r.bodies).toBe(41);
      expect(r.buffersCreated).toBe(1);
      expect(Number.isFinite(r.long)).toBe(true);
      expect(r.long).toBeLessThan(16 * 1024);
    });
  }
});
