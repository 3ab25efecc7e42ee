// Builds the classic scripts into dist/classic/: three.js (the global THREE), physin.js (the
// global PhysiN, three.js external) and physin_worker.js (a classic worker script). Run after tsc
// (it reads dist/), by the package's build script.
import { readFileSync, rmSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { build } from 'vite';

const here = (path) => fileURLToPath(new URL(path, import.meta.url));
const outDir = here('../dist/classic');

async function iife(entry, name, fileName, options = {}, define = {}) {
  await build({
    configFile: false,
    logLevel: 'error',
    publicDir: false,
    define,
    build: {
      outDir,
      emptyOutDir: false,
      minify: true,
      target: 'es2022',
      lib: { entry: here(entry), name, formats: ['iife'], fileName: () => fileName },
      ...options,
    },
  });
}

await iife('./three.ts', 'THREE', 'three.js');
await iife('./worker.ts', 'PhysiNWorker', 'physin_worker.js');
const workerSource = readFileSync(`${outDir}/physin_worker.js`, 'utf8');
await iife(
  './physin.ts',
  'PhysiN',
  'physin.js',
  {
    rolldownOptions: { external: ['three'], output: { globals: { three: 'THREE' } } },
  },
  { __PHYSIN_WORKER_SOURCE__: JSON.stringify(workerSource) },
);
// the module build's own worker (new URL('./worker.js', import.meta.url)) is never started by
// physin.js, which always names its worker: drop the chunk the bundler emitted for it
rmSync(`${outDir}/assets`, { recursive: true, force: true });
