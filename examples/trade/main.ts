/**
 * The trade page: runs a scene (scenes.ts) for 5 simulated seconds with the knobs the user picks
 * (sweep.ts: a few steps per animation frame, or with `?worker=1` in the page's worker), and plots
 * its error against time and each run's worst error against its cost. The first run starts when
 * the page opens.
 */
import GUI from 'lil-gui';
import { wantsWorker } from '../shared/demo.js';
import { PRESETS, SCENES } from './scenes.js';
import type { Knobs, SceneName } from './scenes.js';
import { Sweep } from './sweep.js';
import type { Progress } from './sweep.js';

const SECONDS = 5;
const COLOURS = ['#ffa040', '#4ad8c8', '#ff5c8a', '#8ab4ff', '#c5e478', '#e0a0ff'];

interface Run {
  readonly label: string;
  readonly colour: string;
  progress: Progress;
}

const runs: Run[] = [];
const state: { scene: SceneName; preset: string } & Knobs = { scene: 'chain of 10', preset: 'default', ...PRESETS.default! };
/** In the page's thread: the sweep being stepped. With ?worker=1: the worker that steps it. */
let local: Sweep | null = null;
const worker = wantsWorker() ? new Worker(new URL('./sweep-worker.ts', import.meta.url), { type: 'module' }) : null;
worker?.addEventListener('message', (event: MessageEvent<Progress>) => {
  const run = runs[runs.length - 1];
  if (run !== undefined) run.progress = event.data;
});

function start(): void {
  const knobs: Knobs = { iterations: state.iterations, subSteps: state.subSteps, rate: state.rate };
  const run: Run = {
    label: `${state.scene}: it ${knobs.iterations}, sub ${knobs.subSteps}, ${knobs.rate} Hz`,
    colour: COLOURS[runs.length % COLOURS.length]!,
    progress: { times: [], errors: [], worst: 0, cost: 0, done: false },
  };
  runs.push(run);
  if (runs.length > 6) runs.shift();
  if (worker !== null) {
    local = null;
    worker.postMessage({ scene: state.scene, knobs, seconds: SECONDS });
  } else {
    local = new Sweep(state.scene, knobs, SECONDS);
    run.progress = local.progress;
  }
}

/** In the page's thread, steps the current run for about 8 ms of this frame. */
function work(): void {
  if (local === null) return;
  if (local.advance(8).done) local = null;
}

const errorCanvas = document.getElementById('error-plot') as HTMLCanvasElement;
const costCanvas = document.getElementById('cost-plot') as HTMLCanvasElement;

function context(canvas: HTMLCanvasElement): { ctx: CanvasRenderingContext2D; w: number; h: number } {
  const ratio = window.devicePixelRatio || 1;
  const w = canvas.clientWidth;
  const h = canvas.clientHeight;
  if (canvas.width !== Math.round(w * ratio) || canvas.height !== Math.round(h * ratio)) {
    canvas.width = Math.round(w * ratio);
    canvas.height = Math.round(h * ratio);
  }
  const ctx = canvas.getContext('2d')!;
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  ctx.clearRect(0, 0, w, h);
  ctx.font = '11px ui-monospace, monospace';
  return { ctx, w, h };
}

const LOG_MIN = -8;
const LOG_MAX = 2;
const logOf = (e: number): number => Math.min(LOG_MAX, Math.max(LOG_MIN, Math.log10(Math.max(e, 1e-12))));

function axes(ctx: CanvasRenderingContext2D, w: number, h: number, title: string, xLabel: string): void {
  ctx.fillStyle = 'rgba(220,226,236,0.8)';
  ctx.fillText(title, 48, 14);
  ctx.fillText(xLabel, w - 8 - ctx.measureText(xLabel).width, h - 4);
  ctx.strokeStyle = 'rgba(255,255,255,0.10)';
  for (let e = LOG_MIN; e <= LOG_MAX; e += 2) {
    const y = 22 + ((LOG_MAX - e) / (LOG_MAX - LOG_MIN)) * (h - 44);
    ctx.beginPath();
    ctx.moveTo(44, y);
    ctx.lineTo(w - 8, y);
    ctx.stroke();
    ctx.fillText(`1e${e}`, 4, y + 4);
  }
}

function drawErrors(): void {
  const { ctx, w, h } = context(errorCanvas);
  axes(ctx, w, h, 'error (m) against time', `t (s), 0 … ${SECONDS}`);
  runs.forEach(({ colour, progress: run }, index) => {
    ctx.strokeStyle = colour;
    ctx.globalAlpha = index === runs.length - 1 ? 1 : 0.35;
    ctx.lineWidth = index === runs.length - 1 ? 2 : 1;
    ctx.beginPath();
    run.times.forEach((t, i) => {
      const x = 44 + (t / SECONDS) * (w - 52);
      const y = 22 + ((LOG_MAX - logOf(run.errors[i]!)) / (LOG_MAX - LOG_MIN)) * (h - 44);
      if (i === 0) ctx.moveTo(x, y);
      else ctx.lineTo(x, y);
    });
    ctx.stroke();
  });
  ctx.globalAlpha = 1;
  ctx.lineWidth = 1;
}

function drawCosts(): void {
  const { ctx, w, h } = context(costCanvas);
  const most = Math.max(1, ...runs.map((r) => r.progress.cost)) * 1.15;
  axes(ctx, w, h, 'worst error (m) against cost', `ms per simulated second, 0 … ${most.toFixed(0)}`);
  for (const { colour, progress: run } of runs) {
    const x = 44 + (run.cost / most) * (w - 52);
    const y = 22 + ((LOG_MAX - logOf(run.worst)) / (LOG_MAX - LOG_MIN)) * (h - 44);
    const front = runs.every(({ progress: o }) => o === run || !(o.done && o.cost <= run.cost && o.worst <= run.worst));
    ctx.fillStyle = colour;
    ctx.beginPath();
    ctx.arc(x, y, front ? 6 : 4, 0, 2 * Math.PI);
    ctx.fill();
    if (front && run.done) {
      ctx.strokeStyle = '#ffffff';
      ctx.stroke();
    }
  }
}

const legend = document.getElementById('legend')!;
function drawLegend(): void {
  legend.innerHTML = runs
    .map((r) => `<div><span style="background:${r.colour}"></span>${r.label} — worst ${r.progress.worst.toExponential(2)} m, ${r.progress.cost.toFixed(1)} ms/s${r.progress.done ? '' : ' (running)'}${worker ? ' · worker' : ''}</div>`)
    .join('');
}

const frame = (): void => {
  requestAnimationFrame(frame);
  work();
  drawErrors();
  drawCosts();
  drawLegend();
};

const gui = new GUI({ container: document.getElementById('gui')!, title: 'Run' });
gui.add(state, 'scene', Object.keys(SCENES));
gui
  .add(state, 'preset', Object.keys(PRESETS))
  .onChange((name: string) => {
    Object.assign(state, PRESETS[name]);
    gui.controllersRecursive().forEach((c) => c.updateDisplay());
  });
gui.add(state, 'iterations', 1, 50, 1);
gui.add(state, 'subSteps', 1, 16, 1).name('sub-steps');
gui.add(state, 'rate', [30, 60, 120, 240, 480]).name('rate (Hz)');
gui.add({ run: start }, 'run').name('run 5 s');
gui.add({ clear: () => (runs.length = 0) }, 'clear').name('clear the plots');

start();
frame();
