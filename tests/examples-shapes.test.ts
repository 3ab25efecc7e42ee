/**
 * The shapes page in a real browser (Debian's Chromium through playwright-core, WebGL2 on
 * SwiftShader): after a fixed count of frames, what the page teaches has happened, in the page's
 * thread and in the worker alike. The sensor saw every icosahedron come in and go out, the
 * dumbbell's collision events named its balls, the chain of tori hangs linked from the fixed one,
 * the red boxes (a group left out of its own mask) lie inside one another on the floor while the
 * grey ones stack. (tests/examples-browser.test.ts checks, as for every page, that it loads
 * cleanly, draws, moves, and matches the worker bit for bit.)
 *
 * The site is built into a folder of this test's own (not examples/dist, which that file builds
 * at the same time). Without Chromium the file says so in one loud line and its tests do not run;
 * under CI (CI=true) a missing browser is a failure.
 */
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import type { Server } from 'node:http';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import type { Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { serveStatic } from '../scripts/lib/static-server.mjs';
import { collectProblems } from './support/page-problems.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const CHROMIUM = process.env.PHYSIN_CHROMIUM ?? '/usr/bin/chromium';
const present = existsSync(CHROMIUM);
/** Frames (of 1/60 s) the page runs before it is measured: 2.5 s, every icosahedron through the sensor. */
const FRAMES = 150;
/** The chain's torus radii and the height of its fixed link, as on the page. */
const MAJOR = 0.45;
const MINOR = 0.1;
const TOP = 6.4;
/** Half the edge of the page's boxes. */
const HALF = 0.4;

if (!present) {
  const line = `!!! BROWSER TESTS NOT RUN: no Chromium at ${CHROMIUM} (apt-get install -y chromium, or set PHYSIN_CHROMIUM) !!!`;
  if (process.env.CI === 'true') throw new Error(`${line} — under CI a missing browser is a failure`);
  console.warn(`\n${line}\n`);
}

/** What the page says after FRAMES frames. */
interface Seen {
  thread: string;
  sensorBegins: number;
  sensorEnds: number;
  inside: number;
  dumbbellEvents: string[];
  links: number[][];
  ghosts: number[][];
  solids: number[][];
}

let browser: Browser;
let server: Server;
let base = '';
let site = '';

async function run(query: string): Promise<{ seen: Seen; problems: string[] }> {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const problems = collectProblems(page);
  await page.goto(`${base}/shapes/?${query}frames=${FRAMES}`);
  await page.waitForFunction((n) => ((globalThis as { physinDemo?: { frame: number } }).physinDemo?.frame ?? 0) >= n, FRAMES, {
    timeout: 200_000,
    polling: 100,
  });
  await page.waitForTimeout(300);
  const seen = await page.evaluate(() => {
    type Posed = { getPositionN(): Float64Array };
    const hook = (
      globalThis as unknown as {
        physinShapes: {
          sensorBegins: number;
          sensorEnds: number;
          inside: number;
          dumbbellEvents: string[];
          links: Posed[];
          ghosts: Posed[];
          solids: Posed[];
        };
      }
    ).physinShapes;
    const at = (list: Posed[]): number[][] => list.map((m) => [...m.getPositionN()]);
    return {
      thread: (globalThis as unknown as { physinDemo: { thread: string } }).physinDemo.thread,
      sensorBegins: hook.sensorBegins,
      sensorEnds: hook.sensorEnds,
      inside: hook.inside,
      dumbbellEvents: [...hook.dumbbellEvents],
      links: at(hook.links),
      ghosts: at(hook.ghosts),
      solids: at(hook.solids),
    };
  });
  await page.screenshot({ path: join(root, 'test-artifacts/browser', `shapes-measured${query === '' ? '' : '-worker'}.png`) });
  await page.close();
  return { seen, problems };
}

describe.runIf(present)('the shapes page in Chromium', () => {
  beforeAll(async () => {
    site = mkdtempSync(join(tmpdir(), 'physin-shapes-site-'));
    execFileSync(
      process.execPath,
      [join(root, 'examples/node_modules/vite/bin/vite.js'), 'build', '--logLevel', 'warn', '--outDir', site, '--emptyOutDir'],
      { cwd: join(root, 'examples'), stdio: 'inherit' },
    );
    ({ server, base } = await serveStatic(site));
    browser = await chromium.launch({
      executablePath: CHROMIUM,
      args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--no-sandbox'],
    });
  }, 300_000);

  afterAll(async () => {
    await browser?.close();
    await new Promise((resolve) => (server ? server.close(resolve) : resolve(undefined)));
    if (site !== '') rmSync(site, { recursive: true, force: true });
  });

  it('the sensor, the dumbbell, the chain and the filters do what the page says, in both threads alike', async () => {
    const main = await run('');
    const worker = await run('worker=1&');
    expect(main.problems).toEqual([]);
    expect(worker.problems).toEqual([]);
    expect(main.seen.thread).toBe('main');
    expect(worker.seen.thread).toBe('worker');
    const { thread: _m, ...a } = main.seen;
    const { thread: _w, ...b } = worker.seen;
    expect(b).toEqual(a);
    const seen = main.seen;

    // the sensor: each of the 7 icosahedra came in and went out again (one begin and one end each)
    expect(seen.sensorBegins).toBe(7);
    expect(seen.sensorEnds).toBe(7);
    expect(seen.inside).toBe(0);

    // the dumbbell's events name the part that touched: a ball first (the bar is the body's own mesh)
    expect(seen.dumbbellEvents.length).toBeGreaterThan(0);
    expect(seen.dumbbellEvents[0]).toMatch(/^begin ball [AB] · the step$/);

    // the chain hangs: the fixed link has not moved, and each link is within 2(R − r) of the one
    // above (linked rings hanging straight, tubes touching) plus 5 mm of penetration slop
    // (the report carries poses in 32-bit floats)
    expect(seen.links[0]).toEqual([Math.fround(6.2), Math.fround(TOP), 0]);
    for (let i = 1; i < seen.links.length; i += 1) {
      const [x0, y0, z0] = seen.links[i - 1]!;
      const [x1, y1, z1] = seen.links[i]!;
      expect(Math.hypot(x1! - x0!, y1! - y0!, z1! - z0!)).toBeLessThan(2 * (MAJOR - MINOR) + 0.005);
      expect(y1!).toBeLessThan(y0!);
    }

    // the red boxes went through one another: all five lie on the floor, at half an edge (within
    // 2 mm: the penetration slop; measured 3e-8)
    for (const [, y] of seen.ghosts) expect(Math.abs(y! - HALF)).toBeLessThan(0.002);
    // the grey ones did not: a stack, one edge apart (within 2 mm a box; measured 0.4 mm at the top)
    seen.solids.forEach(([, y], i) => expect(Math.abs(y! - HALF * (2 * i + 1))).toBeLessThan(0.002 * (i + 1)));
  }, 480_000);
});
