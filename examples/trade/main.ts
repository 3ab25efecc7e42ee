/**
 * The trade page: runs a scene (scenes.ts) for 10 simulated seconds with the knobs the user picks
 * (sweep.ts: steps for a few milliseconds of each animation frame, or with `?worker=1` in the
 * page's worker), and plots its error against time, its milliseconds per step, and each run's
 * worst error against its cost (plot.ts). Earlier runs stay on the plots, faded, with a legend.
 * When the page opens it runs the three presets on the chain, so the trade shows at once.
 *
 * This page sets no `globalThis.physinDemo`: it has no @physin/three scene; the browser tests
 * check that it loads without errors and that its first canvas (the error plot) is not blank.
 */
import GUI from 'lil-gui';
import { wantsWorker } from '../shared/demo.js';
import { drawCosts, drawErrors, drawTrade, drawView } from './plot.js';
import { PRESETS, RATES, SCENES } from './scenes.js';
import type { Knobs, PresetName, SceneName } from './scenes.js';
import { Sweep } from './sweep.js';
import type { Progress } from './sweep.js';

const COLOURS = ['#ffa040', '#4ad8c8', '#ff5c8a', '#8ab4ff', '#c5e478', '#e0a0ff', '#ffd966', '#7fe0a0'];
/** Runs kept on the plots. */
const KEPT = 8;
/** Milliseconds of each animation frame the page's thread spends stepping. */
const BUDGET_MS = 10;

interface Run {
  readonly id: number;
  readonly scene: SceneName;
  readonly knobs: Knobs;
  readonly seconds: number;
  readonly colour: string;
  progress: Progress;
}
interface Order {
  readonly scene: SceneName;
  readonly knobs: Knobs;
  readonly seconds: number;
}

const query = new URLSearchParams(window.location.search);
const startScene = query.get('scene');
const state = {
  scene: (startScene !== null && startScene in SCENES ? startScene : 'chain of 10') as SceneName,
  preset: 'balanced' as PresetName | 'custom',
  ...PRESETS.balanced,
  seconds: 10,
};

const runs: Run[] = [];
const queue: Order[] = [];
let nextId = 1;
let colourIndex = 0;
/** The run under way, and (in the page's thread) its sweep. */
let current: Run | null = null;
let sweep: Sweep | null = null;
let dirty = true;

const worker = wantsWorker() ? new Worker(new URL('./sweep-worker.ts', import.meta.url), { type: 'module' }) : null;
worker?.addEventListener('message', (event: MessageEvent<{ id: number; progress: Progress }>) => {
  const run = runs.find((r) => r.id === event.data.id);
  if (run === undefined) return;
  run.progress = event.data.progress;
  dirty = true;
  if (run === current && run.progress.done) current = null;
});
worker?.addEventListener('error', (event) => {
  console.warn('trade: the worker failed', event.message);
});

function emptyProgress(order: Order): Progress {
  return {
    times: [],
    errors: [],
    costs: [],
    worst: 0,
    msPerStep: 0,
    msPerSecond: 0,
    total: Math.round(order.seconds * order.knobs.rate),
    done: false,
    bodies: [],
    links: [],
    frame: [0, 1, 0, 1],
    failure: null,
  };
}

function start(order: Order): void {
  const run: Run = { id: nextId, ...order, colour: COLOURS[colourIndex % COLOURS.length]!, progress: emptyProgress(order) };
  nextId += 1;
  colourIndex += 1;
  runs.push(run);
  while (runs.length > KEPT) runs.shift();
  current = run;
  if (worker !== null) {
    sweep = null;
    worker.postMessage({ id: run.id, scene: run.scene, knobs: run.knobs, seconds: run.seconds });
  } else {
    sweep = new Sweep(run.scene, run.knobs, run.seconds);
    run.progress = sweep.progress;
  }
  dirty = true;
}

/** Queues a run with the knobs as they are; it starts when the one under way ends. */
function order(knobs: Knobs = { iterations: state.iterations, subSteps: state.subSteps, rate: state.rate }): void {
  queue.push({ scene: state.scene, knobs: { ...knobs }, seconds: state.seconds });
}

function work(): void {
  if (current === null && queue.length > 0) start(queue.shift()!);
  if (sweep !== null && current !== null) {
    const p = sweep.advance(BUDGET_MS);
    dirty = true;
    if (p.done) {
      sweep = null;
      current = null;
    }
  }
}

const errorCanvas = document.getElementById('error-plot') as HTMLCanvasElement;
const costCanvas = document.getElementById('cost-plot') as HTMLCanvasElement;
const tradeCanvas = document.getElementById('trade-plot') as HTMLCanvasElement;
const viewCanvas = document.getElementById('view') as HTMLCanvasElement;
const legend = document.getElementById('legend') as HTMLTableSectionElement;

function rateLabel(rate: number): string {
  return `1/${rate}`;
}

function fmtError(e: number): string {
  if (!Number.isFinite(e)) return 'apart';
  return e === 0 ? '0' : e.toExponential(1);
}

function drawLegend(): void {
  const rows = runs
    .map((r, i) => {
      const p = r.progress;
      const status =
        p.failure !== null
          ? `stopped: ${p.failure}`
          : p.done
            ? 'done'
            : r === current
              ? `running ${Math.round((100 * p.times.length) / Math.max(1, p.total))} %`
              : 'stopped';
      const faded = i === runs.length - 1 ? '' : ' class="faded"';
      return `<tr${faded}><td><span class="swatch" style="background:${r.colour}"></span>${r.scene}</td><td>${r.knobs.iterations}</td><td>${r.knobs.subSteps}</td><td>${rateLabel(r.knobs.rate)}</td><td>${fmtError(p.worst)}</td><td>${p.msPerStep.toFixed(3)}</td><td>${p.msPerSecond.toFixed(1)}</td><td class="status">${status}</td></tr>`;
    })
    .reverse();
  legend.innerHTML = rows.join('') || '<tr><td colspan="8">no runs yet</td></tr>';
}

function draw(): void {
  const seconds = Math.max(state.seconds, ...runs.map((r) => r.seconds));
  drawErrors(errorCanvas, runs, seconds);
  drawCosts(costCanvas, runs, seconds);
  drawTrade(tradeCanvas, runs);
  drawView(viewCanvas, current ?? runs[runs.length - 1]);
  drawLegend();
}

const frame = (): void => {
  requestAnimationFrame(frame);
  work();
  if (dirty) {
    dirty = false;
    draw();
  }
};

const gui = new GUI({ container: document.getElementById('gui')!, title: 'Scene and knobs', width: 360 });
gui.add(state, 'scene', Object.keys(SCENES));
const presetController = gui.add(state, 'preset', [...Object.keys(PRESETS), 'custom']).onChange((name: string) => {
  if (name in PRESETS) Object.assign(state, PRESETS[name as PresetName]);
  gui.controllersRecursive().forEach((c) => c.updateDisplay());
});
const custom = (): void => {
  state.preset = 'custom';
  presetController.updateDisplay();
};
gui.add(state, 'iterations', 1, 50, 1).onChange(custom);
gui.add(state, 'subSteps', 1, 16, 1).name('sub-steps').onChange(custom);
gui.add(state, 'rate', RATES).name('time step').onChange(custom);
gui.add(state, 'seconds', 1, 30, 1).name('simulated s');
gui.add({ run: () => order() }, 'run').name('▶ run');
gui
  .add({ compare: () => (Object.keys(PRESETS) as PresetName[]).forEach((name) => order(PRESETS[name])) }, 'compare')
  .name('▶ run the three presets');
gui
  .add(
    {
      clear: () => {
        queue.length = 0;
        runs.length = 0;
        if (current !== null) current = null;
        sweep = null;
        if (worker !== null)
          worker.postMessage({ id: 0, scene: state.scene, knobs: { iterations: 1, subSteps: 1, rate: 60 }, seconds: 0 });
        dirty = true;
      },
    },
    'clear',
  )
  .name('clear the plots');

window.addEventListener('resize', () => (dirty = true));

// The first picture: the three presets on the chosen scene.
(['fast', 'balanced', 'accurate'] as const).forEach((name) => order(PRESETS[name]));
draw();
frame();
