/**
 * The trade page's pictures on 2D canvases: error against time (log scale), milliseconds per step
 * against time, each run's worst error against its cost, and a side view of the run's bodies.
 * The newest run is drawn bright, earlier ones faded.
 */
import type { Progress } from './sweep.js';

/** A run as the plots see it. */
export interface PlotRun {
  readonly colour: string;
  readonly progress: Progress;
}

const GRID = 'rgba(255,255,255,0.10)';
const LABEL = 'rgba(220,226,236,0.78)';
const LEFT = 52;
const RIGHT = 12;
const TOP = 24;
const BOTTOM = 26;
/** Errors below this (exact zeros included) are drawn on the floor. */
const LOG_FLOOR = -17;

interface Frame {
  ctx: CanvasRenderingContext2D;
  w: number;
  h: number;
}

/** Sizes the canvas to its CSS box and the device pixel ratio, clears it, and sets the font. */
function begin(canvas: HTMLCanvasElement): Frame {
  const ratio = window.devicePixelRatio || 1;
  const w = Math.max(1, canvas.clientWidth);
  const h = Math.max(1, canvas.clientHeight);
  if (canvas.width !== Math.round(w * ratio) || canvas.height !== Math.round(h * ratio)) {
    canvas.width = Math.round(w * ratio);
    canvas.height = Math.round(h * ratio);
  }
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('trade: this browser gives no 2D canvas context');
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.fillStyle = '#151b26';
  ctx.fillRect(0, 0, w, h);
  ctx.font = '11px ui-monospace, monospace';
  ctx.lineWidth = 1;
  ctx.globalAlpha = 1;
  return { ctx, w, h };
}

function title(f: Frame, text: string, xLabel: string): void {
  const { ctx, w, h } = f;
  ctx.fillStyle = LABEL;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'alphabetic';
  ctx.font = '12px system-ui, sans-serif';
  ctx.fillText(text, LEFT, 15);
  ctx.font = '11px ui-monospace, monospace';
  ctx.textAlign = 'right';
  ctx.fillText(`x: ${xLabel}`, w - RIGHT, 15);
  void h;
}

/** Horizontal grid lines at `ticks` (values in plot units) with labels. */
function yGrid(f: Frame, ticks: readonly number[], y: (v: number) => number, label: (v: number) => string): void {
  const { ctx, w } = f;
  ctx.textAlign = 'right';
  ctx.textBaseline = 'middle';
  for (const t of ticks) {
    const yy = Math.round(y(t)) + 0.5;
    ctx.strokeStyle = GRID;
    ctx.beginPath();
    ctx.moveTo(LEFT, yy);
    ctx.lineTo(w - RIGHT, yy);
    ctx.stroke();
    ctx.fillStyle = LABEL;
    ctx.fillText(label(t), LEFT - 6, yy);
  }
}

/** Vertical grid lines at `ticks` with labels under the plot. */
function xGrid(f: Frame, ticks: readonly number[], x: (v: number) => number, label: (v: number) => string): void {
  const { ctx, h } = f;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'top';
  for (const t of ticks) {
    const xx = Math.round(x(t)) + 0.5;
    ctx.strokeStyle = GRID;
    ctx.beginPath();
    ctx.moveTo(xx, TOP);
    ctx.lineTo(xx, h - BOTTOM);
    ctx.stroke();
    ctx.fillStyle = LABEL;
    ctx.fillText(label(t), xx, h - BOTTOM + 4);
  }
}

const log10 = (e: number): number => (e > 0 ? Math.max(LOG_FLOOR, Math.log10(e)) : e === 0 ? LOG_FLOOR : 2);

/** Evenly spaced ticks from lo to hi (at most about `most` of them) at a round step. */
function niceTicks(lo: number, hi: number, most: number): number[] {
  const raw = (hi - lo) / Math.max(1, most);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 5, 10].map((k) => k * mag).find((s) => s >= raw) ?? raw;
  const out: number[] = [];
  for (let v = Math.ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) out.push(Number(v.toPrecision(12)));
  return out;
}

/** Runs in drawing order: the earlier ones first and faded, the newest last and bright. */
function eachRun(ctx: CanvasRenderingContext2D, runs: readonly PlotRun[], draw: (run: PlotRun, newest: boolean) => void): void {
  runs.forEach((run, i) => {
    const newest = i === runs.length - 1;
    ctx.globalAlpha = newest ? 1 : 0.4;
    ctx.lineWidth = newest ? 2 : 1.25;
    draw(run, newest);
  });
  ctx.globalAlpha = 1;
  ctx.lineWidth = 1;
}

/** The error of every run against simulated time, on a log scale. */
export function drawErrors(canvas: HTMLCanvasElement, runs: readonly PlotRun[], seconds: number): void {
  const f = begin(canvas);
  const { ctx, w, h } = f;
  let lo = Infinity;
  let hi = -Infinity;
  for (const { progress: p } of runs) {
    for (const e of p.errors) {
      const l = log10(e);
      if (l < lo) lo = l;
      if (l > hi) hi = l;
    }
  }
  if (!Number.isFinite(lo)) {
    lo = -8;
    hi = 0;
  }
  lo = Math.floor(lo) - 0.3;
  hi = Math.max(Math.ceil(hi) + 0.3, lo + 3);
  const y = (l: number): number => TOP + ((hi - l) / (hi - lo)) * (h - TOP - BOTTOM);
  const x = (t: number): number => LEFT + (t / seconds) * (w - LEFT - RIGHT);
  const span = hi - lo;
  const every = span > 12 ? 4 : span > 6 ? 2 : 1;
  const decades: number[] = [];
  for (let e = Math.ceil(lo); e <= hi; e += 1) if (e % every === 0) decades.push(e);
  yGrid(f, decades, y, (e) => (e <= LOG_FLOOR ? '0' : `1e${e}`));
  xGrid(f, niceTicks(0, seconds, 10), x, (t) => `${t}`);
  title(f, 'error (m; rad for the spinning body) against time, log scale', 'time (s)');
  ctx.save();
  ctx.beginPath();
  ctx.rect(LEFT, TOP - 2, w - LEFT - RIGHT, h - TOP - BOTTOM + 4);
  ctx.clip();
  eachRun(ctx, runs, ({ colour, progress: p }) => {
    ctx.strokeStyle = colour;
    ctx.beginPath();
    // At most about one point per pixel column: the largest error of the column, so spikes stay.
    const n = p.times.length;
    const perPixel = Math.max(1, Math.floor(p.total / (w - LEFT - RIGHT)));
    for (let i = 0; i < n; i += perPixel) {
      let worst = p.errors[i]!;
      for (let k = i + 1; k < Math.min(n, i + perPixel); k += 1) worst = Math.max(worst, p.errors[k]!);
      const xx = x(p.times[Math.min(n - 1, i + perPixel - 1)]!);
      const yy = y(log10(worst));
      if (i === 0) ctx.moveTo(xx, yy);
      else ctx.lineTo(xx, yy);
    }
    ctx.stroke();
  });
  ctx.restore();
}

/** The mean of `costs[from, to)`. */
function mean(costs: readonly number[], from: number, to: number): number {
  let sum = 0;
  for (let i = from; i < to; i += 1) sum += costs[i]!;
  return to > from ? sum / (to - from) : 0;
}

/**
 * Milliseconds per step against simulated time: the mean over windows of 1/40 of the run, since a
 * browser's `performance.now()` ticks in steps of 0.1 ms or so (with jitter), coarser than a cheap
 * step; the mean of many such readings is still right.
 */
export function drawCosts(canvas: HTMLCanvasElement, runs: readonly PlotRun[], seconds: number): void {
  const f = begin(canvas);
  const { ctx, w, h } = f;
  const bins = 40;
  const curves = runs.map(({ progress: p }) => {
    const perSecond = p.total / seconds;
    const width = Math.max(1, Math.round((perSecond * seconds) / bins));
    const pts: [number, number][] = [];
    for (let i = 0; i < p.costs.length; i += width) {
      const to = Math.min(p.costs.length, i + width);
      pts.push([p.times[to - 1]!, mean(p.costs, i, to)]);
    }
    return pts;
  });
  let most = 0.05;
  for (const c of curves) for (const [, v] of c) most = Math.max(most, v);
  const ticks = niceTicks(0, most * 1.1, 4);
  const top = Math.max(most * 1.15, ticks[ticks.length - 1]!);
  const y = (v: number): number => TOP + ((top - v) / top) * (h - TOP - BOTTOM);
  const x = (t: number): number => LEFT + (t / seconds) * (w - LEFT - RIGHT);
  yGrid(f, ticks, y, (v) => (most < 0.5 ? v.toFixed(2) : most < 5 ? v.toFixed(1) : v.toFixed(0)));
  xGrid(f, niceTicks(0, seconds, 10), x, (t) => `${t}`);
  title(f, 'ms per step (World.step), window means', 'time (s)');
  eachRun(ctx, runs, (run) => {
    const pts = curves[runs.indexOf(run)]!;
    ctx.strokeStyle = run.colour;
    ctx.beginPath();
    pts.forEach(([t, v], i) => (i === 0 ? ctx.moveTo(x(t), y(v)) : ctx.lineTo(x(t), y(v))));
    ctx.stroke();
  });
}

/** Each run's worst error against its cost in ms per simulated second; the runs no other run beats on both are ringed. */
export function drawTrade(canvas: HTMLCanvasElement, runs: readonly PlotRun[]): void {
  const f = begin(canvas);
  const { ctx, w, h } = f;
  const shown = runs.filter((r) => r.progress.times.length > 0);
  let most = 1;
  let lo = Infinity;
  let hi = -Infinity;
  for (const { progress: p } of shown) {
    most = Math.max(most, p.msPerSecond);
    lo = Math.min(lo, log10(p.worst));
    hi = Math.max(hi, log10(p.worst));
  }
  if (!Number.isFinite(lo)) {
    lo = -8;
    hi = 0;
  }
  lo = Math.floor(lo) - 0.5;
  hi = Math.max(Math.ceil(hi) + 0.5, lo + 3);
  const xt = niceTicks(0, most * 1.1, 5);
  const right = Math.max(most * 1.15, xt[xt.length - 1]!);
  const x = (v: number): number => LEFT + (v / right) * (w - LEFT - RIGHT);
  const y = (l: number): number => TOP + ((hi - l) / (hi - lo)) * (h - TOP - BOTTOM);
  const span = hi - lo;
  const every = span > 12 ? 4 : span > 6 ? 2 : 1;
  const decades: number[] = [];
  for (let e = Math.ceil(lo); e <= hi; e += 1) if (e % every === 0) decades.push(e);
  yGrid(f, decades, y, (e) => (e <= LOG_FLOOR ? '0' : `1e${e}`));
  xGrid(f, xt, x, (v) => `${v}`);
  title(f, 'worst error against cost', 'ms per simulated s');
  eachRun(ctx, shown, ({ colour, progress: p }, newest) => {
    const front =
      p.done && shown.every(({ progress: o }) => o === p || !o.done || o.msPerSecond > p.msPerSecond || o.worst > p.worst);
    ctx.fillStyle = colour;
    ctx.beginPath();
    ctx.arc(x(p.msPerSecond), y(log10(p.worst)), newest ? 6 : 5, 0, 2 * Math.PI);
    ctx.fill();
    if (front) {
      ctx.globalAlpha = 0.9;
      ctx.strokeStyle = '#ffffff';
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.arc(x(p.msPerSecond), y(log10(p.worst)), 9, 0, 2 * Math.PI);
      ctx.stroke();
    }
  });
}

/** A side view (x across, y up) of the newest run's bodies as they are now. */
export function drawView(canvas: HTMLCanvasElement, run: PlotRun | undefined): void {
  const f = begin(canvas);
  const { ctx, w, h } = f;
  if (run === undefined) return;
  const p = run.progress;
  const [x0, x1, y0, y1] = p.frame;
  const scale = Math.min((w - 16) / (x1 - x0), (h - 16) / (y1 - y0));
  const cx = w / 2 - ((x0 + x1) / 2) * scale;
  const cy = h / 2 + ((y0 + y1) / 2) * scale;
  const X = (v: number): number => cx + v * scale;
  const Y = (v: number): number => cy - v * scale;
  // The ground, where the scene has one (the stacks).
  if (y0 < 0 && y0 > -1) {
    ctx.fillStyle = 'rgba(255,255,255,0.06)';
    ctx.fillRect(0, Y(0), w, h - Y(0));
    ctx.strokeStyle = 'rgba(255,255,255,0.3)';
    ctx.beginPath();
    ctx.moveTo(0, Y(0) + 0.5);
    ctx.lineTo(w, Y(0) + 0.5);
    ctx.stroke();
  }
  ctx.strokeStyle = 'rgba(220,226,236,0.6)';
  ctx.lineWidth = 1.5;
  ctx.beginPath();
  for (let i = 0; i + 3 < p.links.length; i += 4) {
    ctx.moveTo(X(p.links[i]!), Y(p.links[i + 1]!));
    ctx.lineTo(X(p.links[i + 2]!), Y(p.links[i + 3]!));
  }
  ctx.stroke();
  ctx.fillStyle = run.colour;
  ctx.strokeStyle = 'rgba(0,0,0,0.55)';
  ctx.lineWidth = 1;
  for (const b of p.bodies) {
    ctx.beginPath();
    if (b.kind === 'disc') ctx.arc(X(b.x), Y(b.y), Math.max(3, b.r * scale), 0, 2 * Math.PI);
    else
      for (let i = 0; i + 1 < b.points.length; i += 2)
        (i === 0 ? ctx.moveTo : ctx.lineTo).call(ctx, X(b.points[i]!), Y(b.points[i + 1]!));
    ctx.closePath();
    ctx.fill();
    ctx.stroke();
  }
  ctx.fillStyle = LABEL;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'top';
  const t = p.times[p.times.length - 1] ?? 0;
  ctx.fillText(`side view (x, y), t = ${t.toFixed(2)} s`, 8, 6);
}
