// Builds every package and writes tarballs that plain `npm install ./x.tgz` accepts into packs/
// (or into the folder given by `--out <dir>`). `pnpm pack` replaces `workspace:*` ranges with the
// real versions; LICENSE is copied into each package first so every tarball carries it.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readFileSync, renameSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
// --out <dir>: where the tarballs go (default packs/). The consumer tests each pack into their own
// temporary folder, so that two of them running at once never write the same files.
const at = process.argv.indexOf('--out');
if (at !== -1 && (process.argv[at + 1] === undefined || process.argv[at + 1].startsWith('--'))) {
  console.error('pack: --out needs a folder');
  process.exit(2);
}
const out = at === -1 ? join(root, 'packs') : resolve(process.argv[at + 1]);
// --no-build: pack the dist/ that is there (the consumer tests, which run beside tests that load
// dist/ and must not see it rewritten), without the build nor the packages' prepack scripts
const build = !process.argv.includes('--no-build');
const pnpm = (args, cwd) =>
  execFileSync(process.execPath, [join(root, 'scripts', 'pnpm.mjs'), ...args], { cwd, stdio: 'inherit' });

/**
 * Puts LICENSE into a package. Another pack may be reading it at the same moment (the consumer
 * tests run in parallel), so it is written only when it differs, and then by an atomic rename:
 * a reader sees the old file or the new one, never a half-written one.
 */
function copyLicense(dir) {
  const text = readFileSync(join(root, 'LICENSE'));
  const target = join(dir, 'LICENSE');
  if (existsSync(target) && readFileSync(target).equals(text)) return;
  const temporary = join(dir, `.LICENSE.${process.pid}`);
  writeFileSync(temporary, text);
  renameSync(temporary, target);
}

mkdirSync(out, { recursive: true });
if (build) pnpm(['-r', '--filter', './packages/**', 'run', 'build'], root);
for (const name of ['algebra', 'engine', 'worker', 'three']) {
  const dir = join(root, 'packages', name);
  copyLicense(dir);
  pnpm(['pack', '--pack-destination', out, ...(build ? [] : ['--ignore-scripts'])], dir);
}
console.log(`tarballs in ${out}`);
