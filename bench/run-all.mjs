// Runs every bench/*.bench.mjs in turn, each in its own Node process (so one benchmark's JIT
// state and garbage cannot disturb the next), and exits non-zero if any of them failed.
//
// Usage: node bench/run-all.mjs [name-filter ...]
//   e.g. `node bench/run-all.mjs rotors` runs only files whose name contains "rotors".
// The benchmarks import the BUILT packages: `pnpm bench` at the root builds them first.

import { spawnSync } from 'node:child_process';
import { readdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const filters = process.argv.slice(2);
const files = readdirSync(here)
  .filter((f) => f.endsWith('.bench.mjs'))
  .filter((f) => filters.length === 0 || filters.some((s) => f.includes(s)))
  .sort();

if (files.length === 0) {
  console.error(`run-all: no bench/*.bench.mjs file matches ${filters.join(', ') || '(any)'}`);
  process.exit(1);
}

console.log(`# PhysiN benchmarks — Node ${process.version}, ${process.platform}/${process.arch}`);
console.log('Every table shows medians (see bench/README.md).');
const failed = [];
for (const file of files) {
  console.log(`\n## ${file}`);
  const t0 = Date.now();
  const res = spawnSync(process.execPath, [join(here, file)], { cwd: here, stdio: 'inherit' });
  const seconds = ((Date.now() - t0) / 1000).toFixed(1);
  if (res.status !== 0) {
    failed.push(file);
    console.error(`run-all: ${file} failed (exit ${res.status ?? res.signal}) after ${seconds} s`);
  } else {
    console.log(`\n(${file}: ${seconds} s)`);
  }
}
if (failed.length > 0) {
  console.error(`\nrun-all: ${failed.length} of ${files.length} benchmark(s) failed: ${failed.join(', ')}`);
  process.exit(1);
}
