// Builds every package and writes tarballs that plain `npm install ./x.tgz` accepts into packs/.
// `pnpm pack` replaces `workspace:*` ranges with the real versions; LICENSE is copied into each
// package first so every tarball carries it.
import { execFileSync } from 'node:child_process';
import { copyFileSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const out = join(root, 'packs');
// --no-build: pack the dist/ that is there (the consumer tests, which run beside tests that load
// dist/ and must not see it rewritten), without the build nor the packages' prepack scripts
const build = !process.argv.includes('--no-build');
const pnpm = (args, cwd) =>
  execFileSync(process.execPath, [join(root, 'scripts', 'pnpm.mjs'), ...args], { cwd, stdio: 'inherit' });

mkdirSync(out, { recursive: true });
if (build) pnpm(['-r', '--filter', './packages/**', 'run', 'build'], root);
for (const name of ['algebra', 'engine', 'worker', 'three']) {
  const dir = join(root, 'packages', name);
  copyFileSync(join(root, 'LICENSE'), join(dir, 'LICENSE'));
  pnpm(['pack', '--pack-destination', out, ...(build ? [] : ['--ignore-scripts'])], dir);
}
console.log(`tarballs in ${out}`);
