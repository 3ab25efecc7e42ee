/**
 * The examples site: a multi-page Vite app rooted at examples/. Every page is a folder with an
 * index.html, registered in pages.ts; this file turns that list into build entries.
 *
 * @physin/* resolve through their package `exports` to the built dist/ files, as for any user of
 * the library (`npm start` builds them first).
 */
import { copyFileSync, mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { defineConfig } from 'vite';
import type { Plugin } from 'vite';
import { pages } from './pages.js';

const here = (path: string): string => fileURLToPath(new URL(path, import.meta.url));

const input: Record<string, string> = { index: here('./index.html') };
for (const page of pages) input[page.dir] = here(`./${page.dir}/index.html`);

/**
 * Copies the classic scripts of @physin/three (dist/classic: three.js, physin.js,
 * physin_worker.js) next to public/classic/plugin.html, so the page works served and from disk.
 */
function classicScripts(): Plugin {
  const copy = (): void => {
    const require = createRequire(import.meta.url);
    const from = join(dirname(require.resolve('@physin/three/package.json')), 'dist/classic');
    const to = here('./public/classic');
    mkdirSync(to, { recursive: true });
    for (const file of ['three.js', 'physin.js', 'physin_worker.js']) copyFileSync(join(from, file), join(to, file));
  };
  return { name: 'physin-classic-scripts', buildStart: copy, configureServer: copy };
}

/**
 * Builds the API reference (TypeDoc, scripts/api-docs.mjs) into public/api, served as /api/ by the
 * dev server and copied into dist by `vite build`. The script skips TypeDoc (about 8 s) when the
 * reference is newer than every source; a failure is logged and leaves the rest of the site up.
 */
function apiReference(): Plugin {
  const build = async (): Promise<void> => {
    // Imported at run time, not bundled into this config: the script loads TypeDoc itself.
    const script = pathToFileURL(here('../scripts/api-docs.mjs')).href;
    const { buildApiDocs } = (await import(script)) as {
      buildApiDocs: () => Promise<{ built: boolean; warnings: string[]; errors: string[]; ms: number }>;
    };
    try {
      const { built, warnings, errors, ms } = await buildApiDocs();
      if (built) {
        console.log(
          `API reference: public/api in ${(ms / 1000).toFixed(1)} s (${warnings.length} warnings, ${errors.length} errors)`,
        );
      }
    } catch (error) {
      console.error('API reference not built:', error);
    }
  };
  return {
    name: 'physin-api-reference',
    buildStart: build,
    async configureServer(server) {
      await build();
      // The dev server answers a folder with the site's index.html: /api/ must give the reference's.
      server.middlewares.use((request, response, next) => {
        const path = request.url?.split(/[?#]/)[0] ?? '';
        if (path === '/api') {
          response.writeHead(301, { location: '/api/' }).end();
          return;
        }
        if (path.startsWith('/api/') && path.endsWith('/')) request.url = `${path}index.html`;
        next();
      });
    },
  };
}

export default defineConfig({
  plugins: [classicScripts(), apiReference()],
  root: here('.'),
  base: './',
  build: {
    outDir: here('./dist'),
    emptyOutDir: true,
    target: 'es2022',
    rolldownOptions: {
      input,
      // three.js gets a chunk of its own, shared (and cached) by every page that draws.
      output: { codeSplitting: { groups: [{ name: 'three', test: /[\\/]node_modules[\\/].*three[\\/]/ }] } },
    },
    // That chunk alone is about 570 kB minified (145 kB gzipped); it cannot be split further.
    chunkSizeWarningLimit: 700,
  },
  server: { host: '127.0.0.1', port: 5173, strictPort: true },
  preview: { host: '127.0.0.1', port: 5173, strictPort: true },
});
