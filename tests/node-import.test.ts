import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const root = fileURLToPath(new URL('..', import.meta.url));

/**
 * Runs an ES module snippet in a plain Node process at the repository root, so that
 * `@physin/*` resolves as it does for a server user: through node_modules and the
 * package's `exports` map to the built `dist/` files — never through Vitest's source aliases.
 */
function runNode(source: string): string {
  return execFileSync(process.execPath, ['--input-type=module', '-e', source], {
    cwd: root,
    encoding: 'utf8',
  }).trim();
}

describe('the built packages load in Node through their exports', () => {
  it('@physin/algebra resolves to dist/ and turns e_x toward e_w in 4D', () => {
    const out = runNode(`
      const url = import.meta.resolve('@physin/algebra');
      const A = await import('@physin/algebra');
      const D = A.dims(4);
      const R = A.rotorFromPlane(D, new Float64Array(D.r), 0, 3, Math.PI / 2);
      const v = A.rotorApplyVector(D, new Float64Array(4), R, new Float64Array([1, 0, 0, 0]));
      console.log(JSON.stringify({ url, v: Array.from(v), k: D.k, r: D.r }));
    `);
    const res = JSON.parse(out) as { url: string; v: number[]; k: number; r: number };
    expect(res.url).toMatch(/packages\/algebra\/dist\/index\.js$/);
    expect(res.k).toBe(6);
    expect(res.r).toBe(8);
    expect(res.v[0]).toBeCloseTo(0, 14);
    expect(res.v[3]).toBeCloseTo(1, 14);
  });
});
