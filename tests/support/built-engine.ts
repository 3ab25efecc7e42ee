/**
 * The built engine for tests that run it in a child process (allocation measurements): rebuilds
 * the packages when any source of the algebra or the engine is newer than dist/.
 */
import { execFileSync } from 'node:child_process';
import { existsSync, readdirSync, statSync } from 'node:fs';
import { join } from 'node:path';
import { fileURLToPath } from 'node:url';

/** The repository root. */
export const root = fileURLToPath(new URL('../..', import.meta.url));

/** The newest modification time (ms) of any file below `dir`. */
function newest(dir: string): number {
  let t = 0;
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    const p = join(dir, entry.name);
    t = Math.max(t, entry.isDirectory() ? newest(p) : statSync(p).mtimeMs);
  }
  return t;
}

/** Builds every package (the pinned pnpm, as the README's commands do) when dist/ is stale. */
export function ensureBuiltEngine(): void {
  const built = join(root, 'packages/engine/dist/index.js');
  const sources = Math.max(newest(join(root, 'packages/algebra/src')), newest(join(root, 'packages/engine/src')));
  if (!existsSync(built) || statSync(built).mtimeMs < sources) {
    execFileSync('npx', ['--yes', 'pnpm@12.21.0', '-r', '--filter', './packages/**', 'run', 'build'], {
      cwd: root,
      stdio: 'pipe',
    });
  }
}
