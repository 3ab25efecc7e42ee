/**
 * Every page of the examples site in a real browser: Debian's Chromium driven by playwright-core
 * (no browser download), WebGL2 on SwiftShader. The site is built with Vite and served from
 * examples/dist by a small static server on the loopback.
 *
 * For each page: no console error, no failed request; the canvas is not blank (pixel variance);
 * for the physics pages (those that set `globalThis.physinDemo`) the world advances (positions
 * change between two reads) and, with `?worker=1`, the positions after the same number of fixed
 * steps are bit-identical to the main thread's. A screenshot of each page is saved in
 * test-artifacts/browser/.
 *
 * Without Chromium the file says so in one loud line and its tests do not run; under CI (CI=true)
 * a missing browser is a failure.
 */
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import type { Server } from 'node:http';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import type { Browser, Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { pages } from '../examples/pages.js';
import { serveStatic } from '../scripts/lib/static-server.mjs';
import { collectProblems } from './support/page-problems.js';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const site = join(root, 'examples/dist');
const artifacts = join(root, 'test-artifacts/browser');
const CHROMIUM = process.env.PHYSIN_CHROMIUM ?? '/usr/bin/chromium';
const present = existsSync(CHROMIUM);
/** Frames each physics page runs before it is compared across threads. */
const FRAMES = 60;

if (!present) {
  const line = `!!! BROWSER TESTS NOT RUN: no Chromium at ${CHROMIUM} (apt-get install -y chromium, or set PHYSIN_CHROMIUM) !!!`;
  if (process.env.CI === 'true') throw new Error(`${line} — under CI a missing browser is a failure`);
  console.warn(`\n${line}\n`);
}

let browser: Browser;
let server: Server;
let base = '';

/** Opens `url` and collects every console error, page error and failed request. */
async function open(url: string): Promise<{ page: Page; problems: string[] }> {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  const problems = collectProblems(page);
  await page.goto(url);
  return { page, problems };
}

/**
 * Variance of the luminance of the first canvas as the screen shows it (a screenshot, decoded by
 * the browser itself), sampled at 64 × 64: a blank canvas gives 0.
 */
async function canvasVariance(page: Page): Promise<number> {
  const png = (await page.locator('canvas').first().screenshot()).toString('base64');
  return page.evaluate(async (data) => {
    const image = new Image();
    image.src = `data:image/png;base64,${data}`;
    await image.decode();
    const small = document.createElement('canvas');
    small.width = 64;
    small.height = 64;
    const ctx = small.getContext('2d')!;
    ctx.drawImage(image, 0, 0, 64, 64);
    const pixels = ctx.getImageData(0, 0, 64, 64).data;
    let sum = 0;
    let sum2 = 0;
    for (let i = 0; i < pixels.length; i += 4) {
      const y = 0.2126 * pixels[i]! + 0.7152 * pixels[i + 1]! + 0.0722 * pixels[i + 2]!;
      sum += y;
      sum2 += y * y;
    }
    const count = pixels.length / 4;
    return sum2 / count - (sum / count) ** 2;
  }, png);
}

/** Every PhysiN mesh's n-D position and rotor, in the scene's order. */
function poses(page: Page): Promise<number[][]> {
  return page.evaluate(() => {
    const demo = (globalThis as { physinDemo?: { scene: { children: unknown[] } } }).physinDemo!;
    const out: number[][] = [];
    for (const child of demo.scene.children as {
      isPhysinMesh?: boolean;
      getPositionN(): Float64Array;
      getRotor(): Float64Array;
    }[]) {
      if (child.isPhysinMesh) out.push([...child.getPositionN(), ...child.getRotor()]);
    }
    return out;
  });
}

function hasDemo(page: Page): Promise<boolean> {
  return page.evaluate(() => (globalThis as { physinDemo?: unknown }).physinDemo !== undefined);
}

async function waitFrames(page: Page, frames: number): Promise<void> {
  await page.waitForFunction((n) => ((globalThis as { physinDemo?: { frame: number } }).physinDemo?.frame ?? 0) >= n, frames, {
    timeout: 120_000,
    polling: 50,
  });
}

describe.runIf(present)('the examples site in Chromium', () => {
  beforeAll(async () => {
    execFileSync(process.execPath, [join(root, 'examples/node_modules/vite/bin/vite.js'), 'build', '--logLevel', 'warn'], {
      cwd: join(root, 'examples'),
      stdio: 'inherit',
    });
    mkdirSync(artifacts, { recursive: true });
    ({ server, base } = await serveStatic(site));
    browser = await chromium.launch({
      executablePath: CHROMIUM,
      args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--no-sandbox'],
    });
  }, 300_000);

  afterAll(async () => {
    await browser?.close();
    await new Promise((resolve) => (server ? server.close(resolve) : resolve(undefined)));
  });

  it('the index lists every page, with no error', async () => {
    const { page, problems } = await open(`${base}/`);
    await page.waitForSelector('.card');
    expect(await page.locator('.card').count()).toBe(pages.length);
    await page.screenshot({ path: join(artifacts, 'index.png') });
    expect(problems).toEqual([]);
    await page.close();
  }, 60_000);

  const visits = pages.flatMap((entry) => [
    { dir: entry.dir, query: '', name: entry.dir },
    ...(entry.variants ?? []).map((query) => ({
      dir: entry.dir,
      query: `${query}&`,
      name: `${entry.dir}-${query.replace(/[^a-z0-9]+/gi, '')}`,
    })),
  ]);
  for (const entry of visits) {
    it(`${entry.name}: loads cleanly, draws, and (physics pages) advances and matches the worker`, async () => {
      const { page, problems } = await open(`${base}/${entry.dir}/?${entry.query}frames=${FRAMES}`);
      await page.waitForSelector('canvas');
      await page.waitForTimeout(500);
      const physics = await hasDemo(page);
      if (physics) {
        await waitFrames(page, 5);
        const early = await poses(page);
        await waitFrames(page, FRAMES);
        await page.waitForTimeout(300);
        const main = await poses(page);
        expect(main.length).toBeGreaterThan(0);
        expect(main).not.toEqual(early);
        await page.screenshot({ path: join(artifacts, `${entry.name}.png`) });
        expect(await canvasVariance(page)).toBeGreaterThan(20);
        const worker = await open(`${base}/${entry.dir}/?${entry.query}worker=1&frames=${FRAMES}`);
        await waitFrames(worker.page, FRAMES);
        await worker.page.waitForTimeout(300);
        expect(await worker.page.evaluate(() => (globalThis as { physinDemo?: { thread: string } }).physinDemo!.thread)).toBe(
          'worker',
        );
        expect(await poses(worker.page)).toEqual(main);
        await worker.page.screenshot({ path: join(artifacts, `${entry.name}-worker.png`) });
        expect(worker.problems).toEqual([]);
        await worker.page.close();
      } else {
        await page.waitForTimeout(2000);
        await page.screenshot({ path: join(artifacts, `${entry.name}.png`) });
        expect(await canvasVariance(page)).toBeGreaterThan(20);
      }
      expect(problems).toEqual([]);
      await page.close();
    }, 240_000);
  }

  it('classic build: plugin.html opened from file:// runs, in the main thread and in a Blob-URL worker, alike', async () => {
    const file = `file://${join(site, 'classic/plugin.html')}`;
    const main = await open(`${file}?frames=${FRAMES}`);
    await waitFrames(main.page, 5);
    const early = await poses(main.page);
    await waitFrames(main.page, FRAMES);
    await main.page.waitForTimeout(300);
    const last = await poses(main.page);
    expect(last).toHaveLength(7);
    expect(last).not.toEqual(early);
    expect(await canvasVariance(main.page)).toBeGreaterThan(20);
    await main.page.screenshot({ path: join(artifacts, 'classic-file.png') });
    const worker = await open(`${file}?worker=1&frames=${FRAMES}`);
    await waitFrames(worker.page, FRAMES);
    await worker.page.waitForTimeout(300);
    expect(await worker.page.evaluate(() => (globalThis as { physinDemo?: { thread: string } }).physinDemo!.thread)).toBe(
      'worker',
    );
    expect(await poses(worker.page)).toEqual(last);
    // over HTTP, PhysiN.scripts.worker = 'physin_worker.js' loads the file as the specification says
    const served = await open(`${base}/classic/plugin.html?worker=1&frames=${FRAMES}`);
    await waitFrames(served.page, FRAMES);
    await served.page.waitForTimeout(300);
    expect(await poses(served.page)).toEqual(last);
    for (const run of [main, worker, served]) {
      expect(run.problems).toEqual([]);
      await run.page.close();
    }
  }, 240_000);

  it('sandbox in 4D: dragging the ruler moves the flat, re-cuts the bodies and hides those it leaves', async () => {
    const { page, problems } = await open(`${base}/sandbox/?d=4&frames=${FRAMES}`);
    await waitFrames(page, FRAMES);
    await page.waitForTimeout(300);
    const seen = (): Promise<{ w: number; cuts: number[] }> =>
      page.evaluate(() => {
        const demo = (
          globalThis as {
            physinDemo?: {
              scene: {
                sliceW: number;
                children: {
                  isPhysinMesh?: boolean;
                  dimensions?: number | null;
                  visible: boolean;
                  geometry: { drawRange: { count: number } };
                  scale: { x: number };
                }[];
              };
            };
          }
        ).physinDemo!;
        const cuts = demo.scene.children
          .filter((o) => o.isPhysinMesh && o.dimensions === 4)
          .map((o) => (o.visible ? o.geometry.drawRange.count * 1000 + Math.round(o.scale.x * 1000) : -1));
        return { w: demo.scene.sliceW, cuts };
      });
    const before = await seen();
    expect(before.w).toBe(0);
    const ruler = page.locator('#ruler');
    const box = (await ruler.boundingBox())!;
    // from the middle (w = 0) to nine tenths of the way (w = 2)
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width * 0.9, box.y + box.height / 2, { steps: 8 });
    await page.mouse.up();
    const after = await seen();
    expect(after.w).toBeGreaterThan(1.5);
    // some body the flat cut at w = 0 is hidden now, and the cuts changed
    expect(before.cuts.some((c, i) => c >= 0 && after.cuts[i] === -1)).toBe(true);
    expect(after.cuts).not.toEqual(before.cuts);
    await page.screenshot({ path: join(artifacts, 'sandbox-ruler.png') });
    expect(problems).toEqual([]);
    await page.close();
  }, 120_000);
});
