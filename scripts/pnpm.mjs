// Runs the pinned pnpm through npx, so a fresh machine needs only Node and npm.
// (corepack's signature check fails against our registry, so we do not rely on it.)
import { spawnSync } from 'node:child_process';

export const PNPM_VERSION = '12.21.0';

export function pnpm(args, opts = {}) {
  const npx = process.platform === 'win32' ? 'npx.cmd' : 'npx';
  const res = spawnSync(npx, ['--yes', `pnpm@${PNPM_VERSION}`, ...args], { stdio: 'inherit', ...opts });
  if (res.error) throw res.error;
  return res.status ?? 1;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  process.exit(pnpm(process.argv.slice(2)));
}
