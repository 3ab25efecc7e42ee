// The API reference of the four packages (TypeDoc, options in /typedoc.json), written to
// examples/public/api/ so that the examples site serves it at /api/ (the dev server and
// `vite build` alike: see examples/vite.config.ts).
//
//   node scripts/api-docs.mjs            builds the reference if a source changed since the last build
//   node scripts/api-docs.mjs --force    builds it again whatever the dates
//   node scripts/api-docs.mjs --check    builds nothing; validates and exits 1 on any warning
//
// TypeDoc also loads this file as a plugin (the `plugin` option of typedoc.json): `load` drops
// the members a class only inherits from a package outside PhysiN (three.js's Object3D has
// ~150), so each page shows what PhysiN adds, with its "Hierarchy" linking to three.js's docs.
// The packages are read from their sources, their dependencies from the built dist/ (the
// packages must be built: `npm start` and `npm test` do it first).
import { existsSync, readdirSync, statSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { stripVTControlCharacters } from 'node:util';
import * as td from 'typedoc';

const root = join(dirname(fileURLToPath(import.meta.url)), '..');
/** Where the reference is written: served by Vite as /api/. */
export const API_OUT = join(root, 'examples/public/api');
const PACKAGES = ['algebra', 'engine', 'worker', 'three'];

/** The front page of the reference: where to start, in each package. */
const FRONT_PAGE = `# PhysiN API reference

Rigid body physics in any number of dimensions (n = 2 to 8), in four packages
(the Examples link at the top leads back to the pages that show them at work). Where to start in each:

- {@link @physin/algebra! | @physin/algebra}: {@link @physin/algebra!dims | dims(n)}, the tables of a
  dimension; rotors ({@link @physin/algebra!rotorExp | rotorExp}, {@link @physin/algebra!rotorCorrect | rotorCorrect}) and bivectors.
- {@link @physin/engine! | @physin/engine}: {@link @physin/engine!World | World} and {@link @physin/engine!Body | Body};
  shapes such as {@link @physin/engine!HyperBox | HyperBox}, joints such as {@link @physin/engine!HingeJoint | HingeJoint},
  every tolerance in {@link @physin/engine!defaultParams | defaultParams}.
- {@link @physin/worker! | @physin/worker}: {@link @physin/worker!openWorld | openWorld}, the engine in this
  thread or in a worker behind one {@link @physin/worker!WorldHost | WorldHost}.
- {@link @physin/three! | @physin/three}: {@link @physin/three!Scene | Scene}, a three.js scene whose meshes
  ({@link @physin/three!BoxMesh | BoxMesh}, {@link @physin/three!HyperBoxMesh | HyperBoxMesh}, …) are bodies.
`;

/**
 * The TypeDoc plugin: writes the front page (the merged project of \`entryPointStrategy:
 * "packages"\` has no readme of its own) and removes the reflections of class and interface members declared only in
 * node_modules (inherited from three.js), before links are resolved and the project validated.
 */
export function load(app) {
  const external = [];
  app.converter.on('createDeclaration', (context, reflection) => {
    const parent = reflection.parent;
    if (!parent || !parent.kindOf(/* Class | Interface */ 128 | 256)) return;
    const symbol = context.getSymbolFromReflection(reflection);
    const declarations = symbol?.declarations ?? [];
    if (declarations.length === 0) return;
    if (declarations.every((d) => /[\\/]node_modules[\\/]/.test(d.getSourceFile().fileName))) external.push(reflection);
  });
  app.converter.on('resolveBegin', (context) => {
    for (const reflection of external.splice(0)) {
      if (context.project.getReflectionById(reflection.id) === reflection) context.project.removeReflection(reflection);
    }
  });
  // typedoc.json's `navigationLinks` leads back to the examples site with "../", which TypeDoc
  // writes as it is on every page: made relative to each page (classes/x.html needs "../../").
  app.renderer.on('endPage', (page) => {
    if (!page.contents) return;
    const up = '../'.repeat(page.url.split('/').length);
    page.contents = page.contents.replace(
      /<a href="\.\.\/"((?: class="tsd-nav-link")?)>Examples<\/a>/g,
      `<a href="${up}"$1>Examples</a>`,
    );
  });
  // Before TypeDoc resolves the links of the merged project (its own listener has priority -300).
  app.on('reviveProject', (project) => {
    const file = new td.MinimalSourceFile(FRONT_PAGE, join(root, 'typedoc.json'));
    project.readme = app.converter.parseRawComment(file, project.files).content;
  });
}

/** The newest modification time (ms) of the files under `dir`, skipping node_modules and dist. */
function newest(dir) {
  let t = 0;
  for (const entry of readdirSync(dir, { withFileTypes: true })) {
    if (entry.name === 'node_modules' || entry.name === 'dist') continue;
    const path = join(dir, entry.name);
    t = Math.max(t, entry.isDirectory() ? newest(path) : statSync(path).mtimeMs);
  }
  return t;
}

/** True when the reference on disk is older than a source, a package.json or README.md, or the options. */
export function apiDocsStale() {
  const index = join(API_OUT, 'index.html');
  if (!existsSync(index)) return true;
  const built = statSync(index).mtimeMs;
  const inputs = [join(root, 'typedoc.json'), fileURLToPath(import.meta.url)];
  for (const name of PACKAGES)
    inputs.push(join(root, 'packages', name, 'package.json'), join(root, 'packages', name, 'README.md'));
  if (inputs.some((file) => statSync(file).mtimeMs > built)) return true;
  return PACKAGES.some((name) => newest(join(root, 'packages', name, 'src')) > built);
}

/**
 * Runs TypeDoc with /typedoc.json. `emit: false` only converts and validates; `quiet` prints
 * errors only. Resolves to the warnings and errors TypeDoc logged (validation included: every
 * export must be documented), without colours, and the time taken.
 */
export async function runTypedoc({ emit = true, quiet = false } = {}) {
  const start = performance.now();
  const cwd = process.cwd();
  if (cwd !== root) process.chdir(root); // TypeDoc resolves the packages' paths against the working directory.
  try {
    const app = await td.Application.bootstrapWithPlugins(
      { options: join(root, 'typedoc.json'), ...(emit ? {} : { emit: 'none' }), ...(quiet ? { logLevel: 'Warn' } : {}) },
      [new td.TypeDocReader(), new td.PackageJsonReader(), new td.TSConfigReader()],
    );
    const warnings = [];
    const errors = [];
    const log = app.logger.log.bind(app.logger);
    app.logger.log = (message, level) => {
      const plain = stripVTControlCharacters(message);
      // TSDoc complaints about comments inside node_modules (three.js's Layers has two @returns)
      // are not ours to fix: dropped. Every warning about a PhysiN file is kept.
      if (level === td.LogLevel.Warn && /comment at \S*node_modules[\\/]/.test(plain)) return;
      if (level === td.LogLevel.Warn) warnings.push(plain);
      if (level === td.LogLevel.Error) errors.push(plain);
      if (!quiet || level >= td.LogLevel.Error) log(message, level);
    };
    const project = await app.convert();
    if (!project)
      return { warnings, errors: errors.length ? errors : ['TypeDoc: conversion failed'], ms: performance.now() - start };
    app.validate(project);
    if (emit) await app.generateOutputs(project);
    return { warnings, errors, ms: performance.now() - start };
  } finally {
    if (cwd !== root) process.chdir(cwd);
  }
}

/** Builds the reference into examples/public/api unless it is up to date (or `force`). */
export async function buildApiDocs({ force = false, quiet = true } = {}) {
  if (!force && !apiDocsStale()) return { built: false, warnings: [], errors: [], ms: 0 };
  const result = await runTypedoc({ emit: true, quiet });
  return { built: true, ...result };
}

/** The command line (see the top of the file). */
async function main(args) {
  if (args.includes('--check')) {
    const { warnings, errors, ms } = await runTypedoc({ emit: false, quiet: true });
    for (const warning of warnings) console.log(warning);
    console.log(`TypeDoc check: ${errors.length} errors, ${warnings.length} warnings (${(ms / 1000).toFixed(1)} s)`);
    return warnings.length + errors.length > 0 ? 1 : 0;
  }
  const { built, warnings, errors, ms } = await buildApiDocs({ force: args.includes('--force'), quiet: true });
  console.log(
    built
      ? `API reference written to examples/public/api (${(ms / 1000).toFixed(1)} s, ${warnings.length} warnings)`
      : 'API reference up to date (examples/public/api)',
  );
  return errors.length ? 1 : 0;
}

// No top-level await: TypeDoc imports this module as its plugin while main() runs, and an import
// of a module still awaiting at top level would never settle.
if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  main(process.argv.slice(2)).then(
    (code) => (process.exitCode = code),
    (error) => {
      console.error(error);
      process.exitCode = 1;
    },
  );
}
