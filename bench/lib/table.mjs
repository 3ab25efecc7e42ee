// Shared helpers for the benchmarks in bench/*.bench.mjs: a median-of-batches timer for
// nanosecond-scale operations and a markdown table printer. See bench/README.md.
//
// Why our own timer: the operations measured here take 2–500 ns, so a timer that calls a
// callback per operation through one shared (megamorphic) call site measures its own overhead.
// `timeOp` compiles a fresh loop per benchmark, so the call inside it sees one target only and
// V8 optimises it as an engine hot loop would; it then reports the MEDIAN over many batches,
// which ignores the GC pauses and scheduler hiccups of a shared 2-core machine.

import { performance } from 'node:perf_hooks';

/** Default number of timed batches per operation (the median is taken over these). */
export const DEFAULT_SAMPLES = 25;
/** Default target duration of one batch, ms (long enough to dwarf timer resolution). */
export const DEFAULT_BATCH_MS = 2;

/**
 * Times a loop body. `body(iterations)` must run the operation `iterations` times and return
 * anything (returned values are kept, so the work cannot be optimised away).
 *
 * @param {(iterations: number) => unknown} body
 * @param {{ samples?: number, batchMs?: number, warmupMs?: number }} [options]
 * @returns {{ median: number, p10: number, p90: number, iterations: number, samples: number }}
 *   nanoseconds per operation.
 */
export function timeLoop(body, options = {}) {
  const samples = options.samples ?? DEFAULT_SAMPLES;
  const batchMs = options.batchMs ?? DEFAULT_BATCH_MS;
  const warmupMs = options.warmupMs ?? 30;
  let sink = 0;
  // Calibrate: grow the batch until it lasts batchMs (this also warms the code up).
  let iterations = 16;
  for (;;) {
    const t0 = performance.now();
    sink ^= keep(body(iterations));
    const dt = performance.now() - t0;
    if (dt >= batchMs) break;
    iterations = dt > 0 ? Math.max(iterations * 2, Math.ceil((iterations * batchMs * 1.2) / dt)) : iterations * 8;
  }
  const warmEnd = performance.now() + warmupMs;
  while (performance.now() < warmEnd) sink ^= keep(body(iterations));
  const perOp = new Float64Array(samples);
  for (let s = 0; s < samples; s += 1) {
    const t0 = process.hrtime.bigint();
    sink ^= keep(body(iterations));
    const t1 = process.hrtime.bigint();
    perOp[s] = Number(t1 - t0) / iterations;
  }
  globalSink ^= sink;
  perOp.sort();
  return {
    median: quantile(perOp, 0.5),
    p10: quantile(perOp, 0.1),
    p90: quantile(perOp, 0.9),
    iterations,
    samples,
  };
}

/**
 * Times `op(...args)` called in a tight loop compiled for this benchmark only (so `op` is the
 * only target of its call site). `args` are arrays of inputs the loop cycles through (length a
 * power of two, ≥ 1): iteration i calls op(args[0][i & m], args[1][i & m], ...). Use an
 * array of several inputs so no load can be hoisted out of the loop.
 *
 * @param {(...a: any[]) => unknown} op
 * @param {unknown[][]} args one array of inputs per argument of `op`
 * @param {{ samples?: number, batchMs?: number }} [options]
 * @returns {{ median: number, p10: number, p90: number, iterations: number, samples: number }} ns/op
 */
export function timeOp(op, args, options = {}) {
  const len = args[0]?.length ?? 1;
  for (const a of args) {
    if (a.length !== len || (len & (len - 1)) !== 0)
      throw new RangeError('timeOp: every input list must have the same power-of-two length');
  }
  const names = args.map((_, i) => `a${i}`);
  const call = `op(${names.map((a) => `${a}[j]`).join(', ')})`;
  // new Function gives each benchmark its own code and type feedback.
  const make = new Function(
    'op',
    ...names,
    `return function loop(iterations) {
      let last;
      for (let i = 0; i < iterations; i += 1) { const j = i & ${len - 1}; last = ${call}; }
      return last;
    };`,
  );
  return timeLoop(make(op, ...args), options);
}

/** Every result the timed loops computed, folded together; exported so the work stays observable. */
export let globalSink = 0;

/** Folds a benchmark result into an integer so the JIT must compute it. */
function keep(value) {
  if (typeof value === 'number') return value | 0;
  if (value && typeof value === 'object' && 'length' in value && value.length > 0) return (value[0] * 1e3) | 0;
  return 0;
}

function quantile(sorted, q) {
  const pos = (sorted.length - 1) * q;
  const lo = Math.floor(pos);
  const hi = Math.ceil(pos);
  return sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - lo);
}

/** Formats a number of nanoseconds (or any positive value) with 3 significant digits. */
export function fmt(x, digits = 3) {
  if (typeof x !== 'number') return String(x);
  if (!Number.isFinite(x)) return String(x);
  if (Number.isInteger(x)) return String(x);
  const abs = Math.abs(x);
  if (abs >= 10 ** digits) return x.toFixed(0);
  return x.toPrecision(digits);
}

/**
 * Prints a markdown table. `rows` is an array of plain objects; the columns are the keys of the
 * first row, in order. Numbers are printed with 3 significant digits, strings as they are.
 * Put medians in the cells (that is the convention of every PhysiN benchmark) and say so in the
 * title, e.g. `medianTable('Rotor product, ns/op (median of 25 batches)', rows)`.
 *
 * @param {string} title
 * @param {Record<string, unknown>[]} rows
 * @returns {string} the printed table
 */
export function medianTable(title, rows) {
  if (rows.length === 0) {
    console.log(`\n### ${title}\n\n(no rows)\n`);
    return '';
  }
  const cols = Object.keys(rows[0]);
  const cells = rows.map((row) => cols.map((c) => fmt(row[c])));
  const widths = cols.map((c, i) => Math.max(c.length, ...cells.map((r) => r[i].length)));
  const line = (vals) => `| ${vals.map((v, i) => v.padEnd(widths[i])).join(' | ')} |`;
  const out = [
    `### ${title}`,
    '',
    line(cols),
    `|${widths.map((w) => '-'.repeat(w + 2)).join('|')}|`,
    ...cells.map(line),
    '',
  ].join('\n');
  console.log(`\n${out}`);
  return out;
}
