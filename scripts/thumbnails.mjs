// Takes the pictures of the examples site: a card picture per page (examples/public/thumbs/) and
// the README's picture (docs/images/). Needs the built site (examples/dist) and Debian's Chromium.
//   node scripts/thumbnails.mjs            every page
//   node scripts/thumbnails.mjs shapes     only the pages named
import { mkdirSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { serveStatic } from './lib/static-server.mjs';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const require = createRequire(join(root, 'package.json'));
const { chromium } = require('playwright-core');
const { pages } = await import(join(root, 'examples/pages.ts')).catch(async () => {
  // Node cannot import .ts: read the list's dirs from the source
  const { readFileSync } = await import('node:fs');
  const text = readFileSync(join(root, 'examples/pages.ts'), 'utf8');
  return { pages: [...text.matchAll(/dir: '([^']+)'/g)].map((m) => ({ dir: m[1] })) };
});

const { server, base } = await serveStatic(join(root, 'examples/dist'));
const browser = await chromium.launch({
  executablePath: process.env.PHYSIN_CHROMIUM ?? '/usr/bin/chromium',
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--no-sandbox'],
});
// the donuts page plays its moves first: take it once the two are linked
const waits = { donuts: 10000 };
const only = process.argv.slice(2);
const chosen = only.length > 0 ? pages.filter((p) => only.includes(p.dir)) : pages;
const shots = chosen.map((p) => ({
  url: `${base}/${p.dir}/`,
  out: join(root, 'examples/public/thumbs', `${p.dir}.png`),
  size: [480, 300],
  wait: waits[p.dir] ?? 4000,
}));
if (chosen.some((p) => p.dir === 'sandbox'))
  shots.push({ url: `${base}/sandbox/?d=4`, out: join(root, 'docs/images/sandbox-4d.png'), size: [1200, 675] });
for (const shot of shots) {
  mkdirSync(dirname(shot.out), { recursive: true });
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await page.goto(shot.url);
  await page.waitForTimeout(shot.wait ?? 4000);
  const png = (await page.locator('canvas').first().screenshot()).toString('base64');
  // scaled in the browser itself: draw the shot into a canvas of the wanted size (cropped to fit)
  const scaled = await page.evaluate(
    async ({ data, width, height }) => {
      /* global document, Image -- this function runs in the page (page.evaluate), not in Node */
      const image = new Image();
      image.src = `data:image/png;base64,${data}`;
      await image.decode();
      const canvas = document.createElement('canvas');
      canvas.width = width;
      canvas.height = height;
      const scale = Math.max(width / image.width, height / image.height);
      const w = width / scale;
      const h = height / scale;
      canvas.getContext('2d').drawImage(image, (image.width - w) / 2, (image.height - h) / 2, w, h, 0, 0, width, height);
      return canvas.toDataURL('image/png').split(',')[1];
    },
    { data: png, width: shot.size[0], height: shot.size[1] },
  );
  writeFileSync(shot.out, Buffer.from(scaled, 'base64'));
  console.log(shot.out);
  await page.close();
}
await browser.close();
server.close();
