/**
 * Entry point of the rotors page: reads the settings from the URL, wires the controls to the
 * simulation (sim.ts), and on every animation frame advances it in fixed steps, projects the
 * tesseract (geometry.ts), draws it (view.ts) and the defect plot (plot.ts), and refreshes the
 * read-out.
 */
import { hypercubeEdges, hypercubeVertices, projectFromW, transformPoints } from './geometry.js';
import { LogHistory } from './history.js';
import { LogPlot } from './plot.js';
import { PLANE_PAIRS, parseSettings, planePairInfo, settingsToQuery } from './settings.js';
import type { Integrator, PlanePair, RotorSettings } from './settings.js';
import { RotorDemo } from './sim.js';
import { RotorsView } from './view.js';

/** Half-extent of the tesseract and the cube (their corners are at ±1). */
const HALF = 1;
/** Where the eye sits on the w axis for the 4D → 3D perspective (see `perspectiveScale`). */
const EYE_W = 4;
/** Smallest depth EYE_W − w used by the projection, so a runaway corner stays finite. */
const MIN_DEPTH = 0.5;
/** At most this many steps per frame; a slower machine then runs in slow motion instead of stalling. */
const MAX_STEPS_PER_FRAME = 400;
/** Steps shown by the plot. */
const PLOT_STEPS = 900;
/** Read-out refresh interval (ms): numbers that change every frame cannot be read anyway. */
const READOUT_MS = 120;
const AXES = 'xyzw';

function byId<T extends HTMLElement>(id: string, type: { new (): T }): T {
  const el = document.getElementById(id);
  if (!(el instanceof type)) throw new Error(`rotors page: element #${id} is missing or is not a ${type.name}`);
  return el;
}

function fmt(x: number): string {
  if (x === 0) return '0';
  if (!Number.isFinite(x)) return String(x);
  return Math.abs(x) >= 1e-3 && Math.abs(x) < 1e4 ? x.toPrecision(4) : x.toExponential(2);
}

function planeName(axes: readonly [number, number]): string {
  return AXES[axes[0]]! + AXES[axes[1]]!;
}

const settings: RotorSettings = parseSettings(window.location.search);
const demo = new RotorDemo(settings);
const samples = new LogHistory(3, PLOT_STEPS);

// Geometry buffers, sized once.
const tesseractRest = hypercubeVertices(4, HALF);
const cubeRest = hypercubeVertices(3, HALF);
const tesseractTurned = new Float64Array(tesseractRest.length);
const cubeTurned = new Float64Array(cubeRest.length);
const tesseract3 = new Float32Array(16 * 3);
const tesseractScale = new Float32Array(16);
const tesseractTint = new Float32Array(16);
const ghostMatrix = new Float64Array(16);
const ghostTurned = new Float64Array(tesseractRest.length);
const ghost3 = new Float32Array(16 * 3);
const ghostScale = new Float32Array(16);
const cube3 = new Float32Array(8 * 3);

const canvas = byId('view', HTMLCanvasElement);
// Without WebGL the numbers and the plot still tell the story, so the page goes on without the view.
let view: RotorsView | null = null;
let viewError = '';
try {
  view = new RotorsView(canvas, hypercubeEdges(4), hypercubeEdges(3));
} catch (err) {
  viewError = `No WebGL here (${err instanceof Error ? err.message : String(err)}); the read-out and the plot still run.`;
}
const plot = new LogPlot(byId('plot', HTMLCanvasElement));

// Controls.
const correctBox = byId('correct', HTMLInputElement);
const tolRange = byId('tol', HTMLInputElement);
const dtRange = byId('dt', HTMLInputElement);
const pairSelect = byId('pair', HTMLSelectElement);
const rateARange = byId('rateA', HTMLInputElement);
const rateBRange = byId('rateB', HTMLInputElement);
const integratorSelect = byId('integrator', HTMLSelectElement);
const speedRange = byId('speed', HTMLInputElement);
const pauseButton = byId('pause', HTMLButtonElement);
const stepButton = byId('step', HTMLButtonElement);
const resetButton = byId('reset', HTMLButtonElement);

const out = {
  tolValue: byId('tol-value', HTMLElement),
  dtValue: byId('dt-value', HTMLElement),
  rateALabel: byId('rateA-label', HTMLElement),
  rateBLabel: byId('rateB-label', HTMLElement),
  rateAValue: byId('rateA-value', HTMLElement),
  rateBValue: byId('rateB-value', HTMLElement),
  speedValue: byId('speed-value', HTMLElement),
  time: byId('r-time', HTMLElement),
  norm4: byId('r-norm4', HTMLElement),
  defect4: byId('r-defect4', HTMLElement),
  ortho4: byId('r-ortho4', HTMLElement),
  scale4: byId('r-scale4', HTMLElement),
  update4: byId('r-update4', HTMLElement),
  predicted4: byId('r-predicted4', HTMLElement),
  corrections: byId('r-corrections', HTMLElement),
  defect3: byId('r-defect3', HTMLElement),
  ortho3: byId('r-ortho3', HTMLElement),
  status: byId('status', HTMLElement),
  cubeLabel: byId('cube-label', HTMLElement),
  tolLegend: byId('tol-legend', HTMLElement),
};

for (const p of PLANE_PAIRS) pairSelect.add(new Option(p.label, p.id));

function showSettings(): void {
  const s = demo.settings;
  correctBox.checked = s.correct;
  tolRange.value = String(Math.round(Math.log10(s.tolerance)));
  out.tolValue.textContent = s.tolerance.toExponential(0);
  out.tolLegend.textContent = `tolerance ${s.tolerance.toExponential(0)}`;
  dtRange.value = String(s.step);
  out.dtValue.textContent = `${s.step.toFixed(4)} s (${(1 / s.step).toFixed(1)} Hz)`;
  pairSelect.value = s.pair;
  const pair = planePairInfo(s.pair);
  out.rateALabel.textContent = `ω in ${planeName(pair.a)}`;
  out.rateBLabel.textContent = `ω in ${planeName(pair.b)}`;
  rateARange.value = String(s.rateA);
  rateBRange.value = String(s.rateB);
  out.rateAValue.textContent = `${s.rateA.toFixed(1)} rad/s`;
  out.rateBValue.textContent = `${s.rateB.toFixed(1)} rad/s`;
  integratorSelect.value = s.integrator;
  speedRange.value = String(s.speed);
  out.speedValue.textContent = `${s.speed}×`;
  const plane3 = pair.a[1] < 3 ? pair.a : pair.b;
  const rate3 = pair.a[1] < 3 ? s.rateA : s.rateB;
  out.cubeLabel.textContent = `3D cube: the ${planeName(plane3)} part of the motion (${rate3.toFixed(1)} rad/s), same update`;
}

function change(update: Partial<RotorSettings>): void {
  demo.configure(update);
  showSettings();
  const query = settingsToQuery(demo.settings);
  window.history.replaceState(null, '', query ? `?${query}` : window.location.pathname);
}

correctBox.addEventListener('change', () => change({ correct: correctBox.checked }));
tolRange.addEventListener('input', () => change({ tolerance: 10 ** Number(tolRange.value) }));
dtRange.addEventListener('input', () => change({ step: Number(dtRange.value) }));
pairSelect.addEventListener('change', () => change({ pair: pairSelect.value as PlanePair }));
rateARange.addEventListener('input', () => change({ rateA: Number(rateARange.value) }));
rateBRange.addEventListener('input', () => change({ rateB: Number(rateBRange.value) }));
integratorSelect.addEventListener('change', () => change({ integrator: integratorSelect.value as Integrator }));
speedRange.addEventListener('input', () => change({ speed: Number(speedRange.value) }));

let paused = false;
pauseButton.addEventListener('click', () => {
  paused = !paused;
  pauseButton.textContent = paused ? 'Run' : 'Pause';
});
stepButton.addEventListener('click', () => {
  paused = true;
  pauseButton.textContent = 'Run';
  stepOnce();
});
resetButton.addEventListener('click', () => {
  demo.reset();
  samples.clear();
  samples.push(demo.defect4, demo.orthoError4, demo.defect3);
});

function stepOnce(): void {
  demo.step();
  samples.push(demo.defect4, demo.orthoError4, demo.defect3);
}

function updateGeometry(view: RotorsView): void {
  transformPoints(4, tesseractTurned, demo.matrix4, tesseractRest, 16);
  projectFromW(tesseract3, tesseractScale, tesseractTurned, 16, EYE_W, MIN_DEPTH);
  for (let v = 0; v < 16; v += 1) tesseractTint[v] = tesseractTurned[4 * v + 3]! / HALF;
  view.setTesseract(tesseract3, tesseractScale, tesseractTint);
  // The outline of the nearest true rotation, only where it differs visibly from the frame drawn.
  if (demo.orthoError4 > 1e-3 && demo.nearestRotationMatrix(ghostMatrix)) {
    transformPoints(4, ghostTurned, ghostMatrix, tesseractRest, 16);
    projectFromW(ghost3, ghostScale, ghostTurned, 16, EYE_W, MIN_DEPTH);
    view.setGhost(ghost3);
  } else {
    view.setGhost(null);
  }
  transformPoints(3, cubeTurned, demo.matrix3, cubeRest, 8);
  for (let i = 0; i < cube3.length; i += 1) cube3[i] = cubeTurned[i]!;
  view.setCube(cube3);
}

function updateReadout(): void {
  const s = demo.settings;
  out.time.textContent = `${demo.time.toFixed(2)} s, ${demo.steps} steps`;
  out.norm4.textContent = fmt(demo.norm4);
  out.defect4.textContent = fmt(demo.defect4);
  out.ortho4.textContent = fmt(demo.orthoError4);
  out.scale4.textContent = fmt(demo.frameScale4);
  const expected = (s.step * s.step * Math.abs(demo.pfaffian())) / 2;
  out.update4.textContent = fmt(demo.updateDefect4);
  // Only the first-order update has this systematic growth; the exponential one adds roundoff.
  out.predicted4.textContent = s.integrator === 'euler' ? fmt(expected) : '— (exact rotors)';
  out.corrections.textContent = demo.restarts > 0 ? `${demo.corrections} (${demo.restarts} restarts)` : String(demo.corrections);
  out.defect3.textContent = fmt(demo.defect3);
  out.ortho3.textContent = fmt(demo.orthoError3);
  let status: string;
  if (s.correct) {
    status = `rotorCorrect is on: the tesseract stays a rotation (defect ≤ ${s.tolerance.toExponential(0)}).`;
  } else if (demo.defect4 < 1e-12) {
    status = 'rotorCorrect is off, but the defect is still at rounding level.';
  } else {
    const shrink = (1 - demo.frameScale4) * 100;
    status =
      shrink >= 0.1
        ? `rotorCorrect is off: the frame is no longer a rotation; it has shrunk by ${shrink.toFixed(1)} %.`
        : 'rotorCorrect is off: the defect grows with every step (watch the plot).';
  }
  out.status.textContent = viewError ? `${status} ${viewError}` : status;
  out.status.dataset['state'] = s.correct ? 'ok' : demo.defect4 > 1e-6 ? 'bad' : 'ok';
}

function resize(): void {
  view?.resize();
  plot.resize();
}
window.addEventListener('resize', resize);

// Start: optional warm-up steps (for a screenshot of a later moment), then the animation loop.
showSettings();
samples.push(demo.defect4, demo.orthoError4, demo.defect3);
for (let i = 0; i < settings.warmSteps; i += 1) stepOnce();

let last = -1;
let carry = 0;
let lastReadout = -Infinity;
function frame(now: number): void {
  window.requestAnimationFrame(frame);
  const elapsed = last < 0 ? 0 : Math.min(0.1, (now - last) / 1000);
  last = now;
  if (!paused) {
    // Fixed steps of length h; simulated time follows real time × speed.
    carry += elapsed * demo.settings.speed;
    let n = 0;
    while (carry >= demo.settings.step && n < MAX_STEPS_PER_FRAME) {
      stepOnce();
      carry -= demo.settings.step;
      n += 1;
    }
    if (n === MAX_STEPS_PER_FRAME) carry = 0;
  }
  if (view) {
    updateGeometry(view);
    view.render();
  }
  plot.draw(samples, demo.settings.tolerance);
  if (now - lastReadout >= READOUT_MS) {
    lastReadout = now;
    updateReadout();
  }
}
if (view) updateGeometry(view);
updateReadout();
window.requestAnimationFrame(frame);
