/**
 * The API reference: TypeDoc over the four packages (options in typedoc.json, run by
 * scripts/api-docs.mjs) must log no warning and no error. Its validation requires a comment on
 * every export and on every member of an exported class, interface or type (the members a class
 * inherits from three.js excepted), and every `{@link}` to resolve; there is no allow-list. On a
 * failure the message lists the undocumented names, package by package.
 *
 * Then the reference the examples site serves at /api/ (examples/public/api, copied into
 * examples/dist by `vite build`): its front page names and links the key exports.
 */
import { existsSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { describe, expect, it } from 'vitest';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');

interface TypedocRun {
  warnings: string[];
  errors: string[];
  ms: number;
}
interface ApiDocs {
  API_OUT: string;
  runTypedoc(options: { emit?: boolean; quiet?: boolean }): Promise<TypedocRun>;
  buildApiDocs(options: { force?: boolean; quiet?: boolean }): Promise<TypedocRun & { built: boolean }>;
}
const script = pathToFileURL(join(root, 'scripts/api-docs.mjs')).href;
const load = async (): Promise<ApiDocs> => (await import(script)) as ApiDocs;

/** "@physin/engine.Body.mass (Property), defined in …, does not have any documentation" → package: names. */
function undocumentedByPackage(warnings: string[]): string {
  const byPackage = new Map<string, string[]>();
  for (const warning of warnings) {
    const match = /^\[warning\] (\S+) \((\w+)\), defined in (@physin\/\w+)\/\S+, does not have any documentation/.exec(warning);
    if (!match) continue;
    const list = byPackage.get(match[3]!) ?? [];
    list.push(`${match[1]!} (${match[2]!})`);
    byPackage.set(match[3]!, list);
  }
  return [...byPackage].map(([name, list]) => `${name}: ${list.length} undocumented\n  ${list.join('\n  ')}`).join('\n');
}

describe('API reference (TypeDoc)', () => {
  it('every export of the four packages is documented, and TypeDoc warns of nothing', async () => {
    const { runTypedoc } = await load();
    const { warnings, errors, ms } = await runTypedoc({ emit: false, quiet: true });
    console.log(
      `TypeDoc conversion and validation: ${(ms / 1000).toFixed(1)} s, ${warnings.length} warnings, ${errors.length} errors`,
    );
    const undocumented = undocumentedByPackage(warnings);
    const others = warnings.filter((w) => !w.includes('does not have any documentation'));
    const report = [
      undocumented,
      others.length ? `other warnings:\n  ${others.join('\n  ')}` : '',
      errors.length ? `errors:\n  ${errors.join('\n  ')}` : '',
    ]
      .filter(Boolean)
      .join('\n');
    expect(warnings.length + errors.length, `TypeDoc:\n${report}`).toBe(0);
  });

  it('the reference built for /api/ has a front page naming World, Body, Scene, openWorld and dims', async () => {
    const { buildApiDocs, API_OUT } = await load();
    const { errors } = await buildApiDocs({ quiet: true }); // skipped when up to date
    expect(errors).toEqual([]);
    const index = join(API_OUT, 'index.html');
    expect(existsSync(index)).toBe(true);
    const html = readFileSync(index, 'utf8');
    for (const [name, page] of [
      ['World', 'classes/_physin_engine.World.html'],
      ['Body', 'classes/_physin_engine.Body.html'],
      ['Scene', 'classes/_physin_three.Scene.html'],
      ['openWorld', 'functions/_physin_worker.openWorld.html'],
      ['dims', 'functions/_physin_algebra.dims.html'],
    ] as const) {
      expect(html, `${name} on the front page`).toContain(`href="${page}"`);
      expect(existsSync(join(API_OUT, page)), page).toBe(true);
    }
    for (const pkg of ['algebra', 'engine', 'worker', 'three']) {
      expect(existsSync(join(API_OUT, `modules/_physin_${pkg}.html`)), `@physin/${pkg}`).toBe(true);
    }
    // Nothing inherited from three.js is listed: Mesh's page shows what PhysiN adds.
    const mesh = readFileSync(join(API_OUT, 'classes/_physin_three.Mesh.html'), 'utf8');
    expect(mesh).toContain('setPositionN');
    expect(mesh).not.toContain('updateMatrixWorld');
    // The Examples link at the top leads back to the site from any depth.
    expect(mesh).toContain('<a href="../../">Examples</a>');
  });
});
