// Installs what is missing (frozen lockfile) and builds every package into dist/.
// Used by `npm start`, `npm test` and `npm run bench`, so a fresh clone needs no other step.
import { pnpm } from './pnpm.mjs';

const steps = [
  ['install', '--frozen-lockfile', '--prefer-offline'],
  ['-r', '--filter', './packages/**', 'run', 'build'],
];
for (const args of steps) {
  const status = pnpm(args);
  if (status !== 0) {
    console.error(`setup: pnpm ${args.join(' ')} failed with exit code ${status}`);
    process.exit(status);
  }
}
