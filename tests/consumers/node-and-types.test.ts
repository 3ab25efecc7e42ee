/**
 * PhysiN as users install it, from the tarballs of `npm run pack` (scripts/pack.mjs, here with
 * --no-build: `npm test` has just built dist/, and other test files load it while this one runs),
 * with plain npm into temporary folders that have their own node_modules:
 * - a Node server that installs @physin/engine alone (with the algebra it depends on): no three
 *   and no comlink in its node_modules, and a 4D world steps;
 * - a TypeScript program under `strict`, compiled with moduleResolution `bundler` and `node16`
 *   against the installed engine and worker: the types resolve, and wrong calls stay errors
 *   (`// @ts-expect-error` lines that compile would fail the check).
 */
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

const root = join(dirname(fileURLToPath(import.meta.url)), '../..');
// its own temporary pack folder: tests/consumers/apps.test.ts packs at the same time
const packs = mkdtempSync(join(tmpdir(), 'physin-packs-node-'));
const tsc = join(root, 'node_modules/typescript/bin/tsc');
const folders: string[] = [];

function npmInstall(dir: string, tarballs: string[]): void {
  writeFileSync(join(dir, 'package.json'), JSON.stringify({ name: 'consumer', private: true, type: 'module' }));
  execFileSync(
    'npm',
    ['install', '--no-audit', '--no-fund', '--prefer-offline', '--loglevel=error', ...tarballs.map((t) => join(packs, t))],
    {
      cwd: dir,
      stdio: ['ignore', 'ignore', 'inherit'],
    },
  );
}

function folder(): string {
  const dir = mkdtempSync(join(tmpdir(), 'physin-consumer-'));
  folders.push(dir);
  return dir;
}

beforeAll(() => {
  execFileSync(process.execPath, [join(root, 'scripts/pack.mjs'), '--no-build', '--out', packs], {
    cwd: root,
    stdio: ['ignore', 'ignore', 'inherit'],
  });
}, 300_000);

afterAll(() => {
  rmSync(packs, { recursive: true, force: true });
  for (const dir of folders) rmSync(dir, { recursive: true, force: true });
});

describe('installed from the tarballs', () => {
  it('a Node server with @physin/engine alone: no three, no comlink, and a 4D world steps', () => {
    const dir = folder();
    npmInstall(dir, ['physin-algebra-0.1.0.tgz', 'physin-engine-0.1.0.tgz']);
    expect(readdirSync(join(dir, 'node_modules/@physin')).sort()).toEqual(['algebra', 'engine']);
    expect(existsSync(join(dir, 'node_modules/three'))).toBe(false);
    expect(existsSync(join(dir, 'node_modules/comlink'))).toBe(false);
    expect(existsSync(join(dir, 'node_modules/@physin/engine/LICENSE'))).toBe(true);
    writeFileSync(
      join(dir, 'server.js'),
      `import { World, Body, HyperBox, HalfSpace, dims } from '@physin/engine';
const D = dims(4);
const world = new World({ dimensions: 4, gravity: [0, -9.81, 0, 0] });
world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0, 0], 0), mass: 0 }));
const box = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5, 0.5]), mass: 1, position: [0, 3, 0, 0] });
world.addBody(box);
for (let i = 0; i < 120; i += 1) world.step(1 / 60);
console.log(JSON.stringify([...box.x]));
`,
    );
    const x = JSON.parse(execFileSync(process.execPath, ['server.js'], { cwd: dir, encoding: 'utf8' })) as number[];
    expect(x[1]).toBeCloseTo(0.5, 3);
  }, 120_000);

  it('CommonJS require() of every engine entry works (Node 20.19+ loads ES modules through require)', () => {
    const dir = folder();
    npmInstall(dir, ['physin-algebra-0.1.0.tgz', 'physin-engine-0.1.0.tgz']);
    writeFileSync(
      join(dir, 'server.cjs'),
      `const { World, Body, HyperBox, HalfSpace, dims, castRay } = require('@physin/engine');
const three = require('@physin/engine/3d');
const internal = require('@physin/engine/internal');
const algebra = require('@physin/algebra');
const D = dims(3);
const world = new three.World({ dimensions: 3, gravity: [0, -9.81, 0] });
world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 2, 0] }));
for (let i = 0; i < 60; i += 1) world.step(1 / 60);
console.log(JSON.stringify({
  hit: castRay(world, [0, 5, 0], [0, -1, 0], 10) !== null,
  sameTables: three.dims(3) === algebra.dims(3),
  world: world instanceof World === false && typeof internal.collide === 'function',
  rootHasInternals: 'collide' in require('@physin/engine'),
}));
`,
    );
    const out = JSON.parse(execFileSync(process.execPath, ['server.cjs'], { cwd: dir, encoding: 'utf8' })) as Record<
      string,
      boolean
    >;
    expect(out).toEqual({ hit: true, sameTables: true, world: true, rootHasInternals: false });
  }, 120_000);

  for (const resolution of ['bundler', 'node16'] as const) {
    it(`TypeScript strict, moduleResolution ${resolution}: the types resolve and wrong calls stay errors`, () => {
      const dir = folder();
      npmInstall(dir, ['physin-algebra-0.1.0.tgz', 'physin-engine-0.1.0.tgz', 'physin-worker-0.1.0.tgz']);
      writeFileSync(
        join(dir, 'tsconfig.json'),
        JSON.stringify({
          compilerOptions: {
            strict: true,
            noEmit: true,
            target: 'ES2022',
            module: resolution === 'bundler' ? 'ESNext' : 'Node16',
            moduleResolution: resolution,
            lib: ['ES2022', 'DOM'],
            types: [],
            skipLibCheck: false,
          },
          files: ['main.ts'],
        }),
      );
      writeFileSync(
        join(dir, 'main.ts'),
        `import { World, Body, HyperBox, HyperSphere, dims, castRay, snapshotWorld } from '@physin/engine';
import type { Params, WorldRayHit } from '@physin/engine';
import { World as World3 } from '@physin/engine/3d';
import { collide } from '@physin/engine/internal';
import { dims3 } from '@physin/algebra';
import { openWorld } from '@physin/worker';
import type { WorldHost, StepReport } from '@physin/worker';
import { rotorFromPlane } from '@physin/algebra';

const D = dims(3);
const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
const body = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1 });
world.addBody(body);
world.step(1 / 60);
const speed: number = body.v[1]!;
const params: Partial<Params> = { fixedTimeStep: 1 / 120 };
const R: Float64Array = rotorFromPlane(D, new Float64Array(D.r), 0, 1, 0.5);
async function run(): Promise<number> {
  const host: WorldHost = await openWorld({ dimensions: 3, params });
  const report: StepReport | null = await host.step(1 / 60);
  return report === null ? 0 : report.bodyCount;
}
void run;
void speed;
void R;
const world3 = new World3({ dimensions: 3 });
const hit: WorldRayHit | null = castRay(world3, [0, 1, 0], [0, -1, 0], 2);
const bytes: Uint8Array = snapshotWorld(world);
void hit;
void bytes;
void collide;
void dims3;
void HyperSphere(D, 0.5);

// @ts-expect-error: a world needs its dimensions
new World({ gravity: [0, -9.81, 0] });
// @ts-expect-error: step takes seconds, not a string
world.step('fast');
// @ts-expect-error: unknown parameter
const wrong: Partial<Params> = { fixedTimestep: 1 / 60 };
void wrong;
// @ts-expect-error: a body's sleep state belongs to its world (read body.isSleeping)
body.sleeping = true;
// @ts-expect-error: a body's position is read-only; move it with setPositionN
body.x = new Float64Array(3);
// @ts-expect-error: the tables of a world do not change
world.D = D;
// @ts-expect-error: the world keeps its broadphase to itself
void world.broadphase;
// @ts-expect-error: every shape factory takes the dimensions first
HyperSphere(0.5);
// @ts-expect-error: an unknown shape kind
openWorld({ dimensions: 3 }).then((h) => h.addBody({ shape: { kind: 'cone', radius: 1 } }));
// @ts-expect-error: an unknown command
openWorld({ dimensions: 3 }).then((h) => h.execute('explode', {}));
`,
      );
      const out = (() => {
        try {
          return execFileSync(process.execPath, [tsc, '-p', dir], { cwd: dir, encoding: 'utf8' });
        } catch (error) {
          return (error as { stdout?: string }).stdout ?? String(error);
        }
      })();
      expect(out.trim()).toBe('');
    }, 120_000);
  }
});
