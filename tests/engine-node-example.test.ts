/**
 * The Node examples of the documentation run as written and print what the documentation says.
 *
 * Each example is taken from the markdown itself (README.md: "The algebra from Node" and "The
 * engine from Node"; docs/engine.md: "Quick start", the specification's section 11 example) and
 * run in a plain Node process at the repository root, so `@physin/algebra` and `@physin/engine`
 * resolve as they do for a server user: through node_modules and the packages' `exports` maps to
 * the BUILT `dist/` files (`npm test` builds before it runs the tests). Its output is compared,
 * number by number, with the output block printed under the example (1e-12 relative: the runs are
 * deterministic, so in practice the numbers are equal).
 */
import { execFileSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';

const root = fileURLToPath(new URL('..', import.meta.url));
const read = (p: string) => readFileSync(fileURLToPath(new URL(`../${p}`, import.meta.url)), 'utf8');

/** The first fenced code block of language `lang` ('' = no language) after `from` in `text`. */
function fence(text: string, from: number, lang: string): { body: string; end: number } {
  const open = '```' + lang + '\n';
  const start = text.indexOf(open, from);
  expect(start, `a \`\`\`${lang} block after offset ${from}`).toBeGreaterThanOrEqual(0);
  const end = text.indexOf('\n```', start + open.length);
  return { body: text.slice(start + open.length, end + 1), end: end + 4 };
}

/** The example under `heading` and the output block after it (the next plain fence). */
function example(file: string, heading: string): { code: string; output: string } {
  const text = read(file);
  const at = text.indexOf(heading);
  expect(at, `${file} has the heading '${heading}'`).toBeGreaterThanOrEqual(0);
  const code = fence(text, at, 'js');
  const output = fence(text, code.end, '');
  // The output block must belong to this section (before the next heading).
  const nextHeading = text.indexOf('\n#', code.end);
  expect(nextHeading < 0 || output.end <= nextHeading, `${file}: an output block under '${heading}'`).toBe(true);
  return { code: code.body, output: output.body };
}

/** Runs an ES module in Node at the repository root and returns its stdout. */
function runNode(source: string): string {
  return execFileSync(process.execPath, ['--input-type=module', '-e', source], { cwd: root, encoding: 'utf8' });
}

const numbers = (s: string) => (s.match(/-?\d+(?:\.\d+)?(?:e[-+]?\d+)?/g) ?? []).map(Number);

/** Same printed shape (text without the numbers) and the same numbers to 1e-12 relative. */
function expectSameOutput(actual: string, documented: string, what: string): void {
  const shape = (s: string) =>
    s
      .replace(/-?\d+(?:\.\d+)?(?:e[-+]?\d+)?/g, '#')
      .replace(/\s+/g, ' ')
      .trim();
  expect(shape(actual), `${what}: printed shape`).toBe(shape(documented));
  const a = numbers(actual);
  const d = numbers(documented);
  expect(a.length, `${what}: count of numbers`).toBe(d.length);
  a.forEach((x, i) =>
    expect(Math.abs(x - d[i]!), `${what}: number ${i} (${x} vs ${d[i]})`).toBeLessThanOrEqual(
      1e-12 * Math.max(1, Math.abs(d[i]!)),
    ),
  );
}

describe('the documented Node examples run on the built packages and print what the docs say', () => {
  it('@physin/engine resolves to packages/engine/dist through its exports map', () => {
    const url = runNode("console.log(import.meta.resolve('@physin/engine'))").trim();
    expect(url).toMatch(/packages\/engine\/dist\/index\.js$/);
  });

  it('README "The algebra from Node": prints (cos 0.7, sin 0.7, −sin 1.1, cos 1.1) and a defect < 1e-15, as the README shows', () => {
    const { code, output } = example('README.md', '## The algebra from Node');
    const printed = runNode(code);
    expectSameOutput(printed, output, 'README algebra example');
    const [x, y, z, w, defect] = numbers(printed.replace(/Float64Array\(4\)/, ''));
    const expected = [Math.cos(0.7), Math.sin(0.7), -Math.sin(1.1), Math.cos(1.1)];
    [x, y, z, w].forEach((c, i) => expect(Math.abs(c! - expected[i]!)).toBeLessThan(1e-15));
    expect(defect).toBeLessThan(1e-15);
  });

  it('README "The engine from Node": the section 11 example prints the documented output, and x_y is the rest height the text quotes', () => {
    const { code, output } = example('README.md', '## The engine from Node');
    expect(code).toContain("from '@physin/engine'");
    const printed = runNode(code);
    expectSameOutput(printed, output, 'README engine example');
    const quoted = /x_y = (\d+\.\d+)/.exec(read('README.md'));
    expect(quoted).not.toBeNull();
    const y = numbers(printed.replace(/Float64Array\(\d\)/g, ''))[1]!;
    expect(y.toFixed(quoted![1]!.split('.')[1]!.length)).toBe(quoted![1]);
  });

  it('docs/engine.md "Quick start": the specification\'s example, verbatim, prints the "Output" block', () => {
    const { code, output } = example('docs/engine.md', '## Quick start');
    // The specification's section 11 lines, after its import line (PhysiN.nd → the package).
    expect(code).toContain("import { World, HyperBox, HalfSpace, Body, dims } from '@physin/engine';");
    expect(code).toContain('for (let i = 0; i < 120; i += 1) world.step(1 / 60);');
    expectSameOutput(runNode(code), output, 'docs/engine.md quick start');
  });
});
