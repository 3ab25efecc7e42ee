/**
 * PhysiN as users install it, in a bundled web app: the tarballs of `npm run pack`
 * (scripts/pack.mjs --no-build, into a temporary folder of this file's own), installed with plain
 * npm, with three@0.187.0, into one temporary folder per app, and the app of tests/consumers/apps/
 * built there:
 * - with Vite (the repo's, through its JS API, no config file);
 * - with webpack 5 (the repo's, through its Node API, with apps/webpack/webpack.config.cjs: no
 *   plugin, modules resolved from the app's node_modules only).
 * Each build must succeed and bundle only what npm installed in the app's folder. Then in Chromium
 * (playwright-core, as tests/examples-browser.test.ts) each app runs twice, with the physics in the
 * page's thread and with `?worker=1` in @physin/three's own worker: no console error and no failed
 * request, every box fell, and after the same fixed steps the worker's positions and rotors equal
 * the main thread's bit for bit.
 *
 * Without Chromium the file says so in one loud line and the browser tests do not run (the builds
 * still do); under CI (CI=true) a missing browser is a failure.
 */
import { execFileSync } from 'node:child_process';
import { copyFileSync, existsSync, mkdirSync, mkdtempSync, readdirSync, realpathSync, rmSync, writeFileSync } from 'node:fs';
import type { Server } from 'node:http';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { dirname, join, sep } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';
import type { Browser } from 'playwright-core';
import type { Configuration, Stats } from 'webpack';
import webpack from 'webpack';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { serveStatic } from '../../scripts/lib/static-server.mjs';
import { collectProblems } from '../support/page-problems.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
const apps = join(root, 'tests/consumers/apps');
const artifacts = join(root, 'test-artifacts/consumers');
const CHROMIUM = process.env.PHYSIN_CHROMIUM ?? '/usr/bin/chromium';
const present = existsSync(CHROMIUM);
const TARBALLS = ['algebra', 'engine', 'worker', 'three'].map((name) => `physin-${name}-0.1.0.tgz`);
/** The fixed steps the app takes (apps/main.js) and the least each box must have fallen by then (m). */
const STEPS = 90;
const MIN_FALL = 1;

if (!present) {
  const line = `!!! BROWSER TESTS NOT RUN: no Chromium at ${CHROMIUM} (apt-get install -y chromium, or set PHYSIN_CHROMIUM) !!!`;
  if (process.env.CI === 'true') throw new Error(`${line} — under CI a missing browser is a failure`);
  console.warn(`\n${line}\n`);
}

const folders: string[] = [];
let packs = '';
/** Each app's built site, once its build passed. */
const sites: Partial<Record<'vite' | 'webpack', string>> = {};

function folder(prefix: string): string {
  // realpath: /tmp may be a symbolic link, and the bundlers report real paths
  const dir = realpathSync(mkdtempSync(join(tmpdir(), prefix)));
  folders.push(dir);
  return dir;
}

/** A new folder with the four tarballs and three installed, and the app's sources copied in. */
function appFolder(kind: 'vite' | 'webpack'): string {
  const dir = folder(`physin-${kind}-app-`);
  writeFileSync(join(dir, 'package.json'), JSON.stringify({ name: `physin-${kind}-app`, private: true, type: 'module' }));
  execFileSync(
    'npm',
    [
      'install',
      '--no-audit',
      '--no-fund',
      '--prefer-offline',
      '--loglevel=error',
      ...TARBALLS.map((t) => join(packs, t)),
      'three@0.187.0',
    ],
    {
      cwd: dir,
      stdio: ['ignore', 'ignore', 'inherit'],
    },
  );
  expect(readdirSync(join(dir, 'node_modules/@physin')).sort()).toEqual(['algebra', 'engine', 'three', 'worker']);
  copyFileSync(join(apps, 'main.js'), join(dir, 'main.js'));
  for (const file of readdirSync(join(apps, kind))) copyFileSync(join(apps, kind, file), join(dir, file));
  return dir;
}

/** The bundled modules that do not come from the app's folder (virtual modules aside). */
function foreign(dir: string, ids: string[]): string[] {
  return ids.filter((id) => !id.startsWith('\0') && !id.startsWith(dir + sep) && id !== '');
}

beforeAll(() => {
  packs = folder('physin-packs-apps-');
  execFileSync(process.execPath, [join(root, 'scripts/pack.mjs'), '--no-build', '--out', packs], {
    cwd: root,
    stdio: ['ignore', 'ignore', 'inherit'],
  });
}, 120_000);

afterAll(() => {
  for (const dir of folders) rmSync(dir, { recursive: true, force: true });
});

describe('web apps built from the tarballs', () => {
  it('a Vite app installs and builds, bundling only what npm installed', async () => {
    const dir = appFolder('vite');
    const vite = (await import(pathToFileURL(join(root, 'examples/node_modules/vite/dist/node/index.js')).href)) as {
      build(
        config: object,
      ): Promise<
        | { output: { type: string; fileName: string; moduleIds?: string[] }[] }
        | { output: { type: string; fileName: string; moduleIds?: string[] }[] }[]
      >;
    };
    const result = await vite.build({
      root: dir,
      configFile: false,
      logLevel: 'warn',
      build: { outDir: join(dir, 'dist'), emptyOutDir: true, chunkSizeWarningLimit: 4096 },
    });
    const output = (Array.isArray(result) ? result : [result]).flatMap((r) => r.output);
    const ids = output.flatMap((o) => (o.type === 'chunk' ? (o.moduleIds ?? []) : []));
    expect(ids.some((id) => id.startsWith(join(dir, 'node_modules/@physin/three/dist') + sep))).toBe(true);
    // vite's own preload polyfill is the one module that is not the app's
    expect(foreign(dir, ids).filter((id) => !id.includes('modulepreload-polyfill'))).toEqual([]);
    // the package's worker became a file of its own
    expect(output.some((o) => /(^|\/)worker-[\w-]+\.js$/.test(o.fileName))).toBe(true);
    expect(existsSync(join(dir, 'dist/index.html'))).toBe(true);
    sites.vite = join(dir, 'dist');
  }, 120_000);

  it('a webpack 5 app installs and builds, bundling only what npm installed', async () => {
    const dir = appFolder('webpack');
    const config = createRequire(join(dir, 'package.json'))(join(dir, 'webpack.config.cjs')) as Configuration;
    const stats = await new Promise<Stats>((resolve, reject) =>
      webpack(config, (error, result) =>
        error || !result ? reject(error ?? new Error('webpack gave no stats')) : resolve(result),
      ),
    );
    const json = stats.toJson({ all: false, errors: true, warnings: true, modules: true, nestedModules: true, assets: true });
    expect(json.errors ?? []).toEqual([]);
    expect(json.warnings ?? []).toEqual([]);
    const files = (json.modules ?? [])
      .flatMap((m) => [m, ...(m.modules ?? [])])
      .flatMap((m) => (m.nameForCondition ? [m.nameForCondition] : []));
    expect(files.some((f) => f.startsWith(join(dir, 'node_modules/@physin/worker/dist') + sep))).toBe(true);
    expect(foreign(dir, files)).toEqual([]);
    copyFileSync(join(dir, 'index.html'), join(dir, 'dist/index.html'));
    sites.webpack = join(dir, 'dist');
    // minifying three takes most of it: ~12 s alone, ~25 s beside the other consumer tests
  }, 180_000);
});

describe.runIf(present)('the built apps in Chromium', () => {
  let browser: Browser;
  const servers: Server[] = [];

  beforeAll(async () => {
    mkdirSync(artifacts, { recursive: true });
    browser = await chromium.launch({
      executablePath: CHROMIUM,
      args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--no-sandbox'],
    });
  }, 60_000);

  afterAll(async () => {
    await browser?.close();
    await Promise.all(servers.map((server) => new Promise((resolve) => server.close(resolve))));
  });

  type Result = { thread: string; steps: number; start: number[][]; end: number[][]; error?: string };

  /** Opens the app, waits for its result, and collects every console error and failed request. */
  async function run(url: string, shot: string): Promise<{ result: Result; problems: string[]; workers: number }> {
    const page = await browser.newPage({ viewport: { width: 640, height: 400 } });
    const problems = collectProblems(page);
    let workers = 0;
    page.on('worker', () => void (workers += 1));
    await page.goto(url);
    await page.waitForFunction(() => (globalThis as { physinApp?: unknown }).physinApp !== undefined, undefined, {
      timeout: 60_000,
      polling: 50,
    });
    const result = await page.evaluate(() => (globalThis as { physinApp?: unknown }).physinApp as Result);
    await page.screenshot({ path: join(artifacts, `${shot}.png`) });
    await page.close();
    return { result, problems, workers };
  }

  for (const kind of ['vite', 'webpack'] as const) {
    it(`${kind} app: the boxes fall, and in the package's worker they end where they do in the page's thread`, async () => {
      const site = sites[kind];
      if (site === undefined) throw new Error(`the ${kind} app did not build (see the test above)`);
      const { server, base } = (await serveStatic(site)) as { server: Server; base: string };
      servers.push(server);

      const main = await run(`${base}/`, `${kind}-main`);
      expect(main.result.error).toBeUndefined();
      expect(main.problems).toEqual([]);
      expect(main.result.thread).toBe('main');
      expect(main.workers).toBe(0);
      expect(main.result.steps).toBe(STEPS);
      expect(main.result.end).toHaveLength(4);
      main.result.end.forEach((pose, i) => {
        expect(pose.every(Number.isFinite)).toBe(true);
        // fell by at least MIN_FALL and came to the ground, not through it
        expect(pose[1]!).toBeLessThan(main.result.start[i]![1]! - MIN_FALL);
        expect(pose[1]!).toBeGreaterThan(0.3);
      });

      const worker = await run(`${base}/?worker=1`, `${kind}-worker`);
      expect(worker.result.error).toBeUndefined();
      expect(worker.problems).toEqual([]);
      expect(worker.result.thread).toBe('worker');
      expect(worker.workers).toBe(1);
      // bit-identical: toEqual on numbers is Object.is-exact, so a difference in the last bit fails
      expect(worker.result.end).toEqual(main.result.end);
    }, 90_000);
  }
});
