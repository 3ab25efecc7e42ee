/**
 * The knobs of the rotors page, their defaults and limits, and the parsing of a URL query into
 * them (so `?correct=0&dt=0.05` opens the page in a chosen state and a screenshot can show it).
 *
 * Pure: no DOM, no three.js, so the tests run it in Node.
 */

/** Which two orthogonal planes of 4D space the tesseract turns in. */
export type PlanePair = 'xy-zw' | 'xz-yw' | 'xw-yz';

/**
 * How the rotor is advanced by one step of length h under the angular velocity B.
 * - `euler`: R ← R − (h/2) B R, then R ← R / |R| — what a 3D engine does with quaternions.
 * - `exp`: R ← exp(−h B / 2) R with the exact exponential (`rotorExp`).
 */
export type Integrator = 'euler' | 'exp';

/** A plane pair: two planes (axis pairs i < j) that share no axis, and the label shown. */
export interface PlanePairInfo {
  readonly id: PlanePair;
  readonly label: string;
  /** Axes of the plane driven by `rateA`. */
  readonly a: readonly [number, number];
  /** Axes of the plane driven by `rateB`. */
  readonly b: readonly [number, number];
}

/** The three ways to split the four axes into two planes, in the order the page lists them. */
export const PLANE_PAIRS: readonly PlanePairInfo[] = [
  { id: 'xy-zw', label: 'xy and zw', a: [0, 1], b: [2, 3] },
  { id: 'xz-yw', label: 'xz and yw', a: [0, 2], b: [1, 3] },
  { id: 'xw-yz', label: 'xw and yz', a: [0, 3], b: [1, 2] },
];

/** Everything the user can set on the page. Angles in radians, times in seconds. */
export interface RotorSettings {
  /** The two planes of the double rotation. */
  pair: PlanePair;
  /** Angular velocity in the first plane of `pair` (rad/s; positive turns its first axis toward its second). */
  rateA: number;
  /** Angular velocity in the second plane of `pair` (rad/s). */
  rateB: number;
  /** Step length h of the integrator (s). */
  step: number;
  /** Whether `rotorCorrect` is applied when the defect exceeds `tolerance`. */
  correct: boolean;
  /** Defect above which the correction is applied (dimensionless, like `rotorTolerance`). */
  tolerance: number;
  /** The rotor update. */
  integrator: Integrator;
  /** Simulated seconds per real second (the step length stays `step`). */
  speed: number;
  /** Steps run before the first frame is drawn (0 = start from rest at the identity). */
  warmSteps: number;
}

/** Inclusive [min, max] of each numeric setting; out-of-range URL values are clamped into them. */
export const SETTING_LIMITS = {
  rate: [-6, 6],
  step: [0.001, 0.2],
  tolerance: [1e-15, 1e-1],
  speed: [0.1, 8],
  warmSteps: [0, 100_000],
} as const satisfies Record<string, readonly [number, number]>;

/**
 * What the page opens with: a double rotation at 1.5 and 2.5 rad/s, a 30 Hz step (a realistic to
 * slightly coarse game step), correction on with the engine's default tolerance 1e-9.
 */
export const DEFAULT_SETTINGS: Readonly<RotorSettings> = Object.freeze({
  pair: 'xy-zw',
  rateA: 1.5,
  rateB: 2.5,
  step: 1 / 30,
  correct: true,
  tolerance: 1e-9,
  integrator: 'euler',
  speed: 1,
  warmSteps: 0,
});

/** The plane pair record of an id. */
export function planePairInfo(id: PlanePair): PlanePairInfo {
  const info = PLANE_PAIRS.find((p) => p.id === id);
  if (!info) throw new RangeError(`planePairInfo: argument 'id' must be one of xy-zw, xz-yw, xw-yz, got '${String(id)}'`);
  return info;
}

function clamp(x: number, [lo, hi]: readonly [number, number]): number {
  return Math.min(hi, Math.max(lo, x));
}

function readNumber(q: URLSearchParams, names: readonly string[], limits: readonly [number, number], fallback: number): number {
  for (const name of names) {
    const raw = q.get(name);
    if (raw === null || raw.trim() === '') continue;
    const x = Number(raw);
    if (Number.isFinite(x)) return clamp(x, limits);
  }
  return fallback;
}

function readBoolean(q: URLSearchParams, name: string, fallback: boolean): boolean {
  const raw = q.get(name);
  if (raw === null) return fallback;
  const v = raw.trim().toLowerCase();
  if (v === '1' || v === 'true' || v === 'on' || v === 'yes') return true;
  if (v === '0' || v === 'false' || v === 'off' || v === 'no') return false;
  return fallback;
}

/**
 * Settings from a URL query (`location.search` or a URLSearchParams). Unknown or malformed values
 * fall back to `DEFAULT_SETTINGS`; numbers outside `SETTING_LIMITS` are clamped. Recognised keys:
 * `pair` (xy-zw | xz-yw | xw-yz), `a` / `rateA`, `b` / `rateB`, `dt` / `step`, `correct` (1/0,
 * on/off, true/false), `tol`, `integrator` (euler | exp), `speed`, `steps` (steps run before the
 * first frame).
 */
export function parseSettings(query: string | URLSearchParams): RotorSettings {
  const q = typeof query === 'string' ? new URLSearchParams(query) : query;
  const d = DEFAULT_SETTINGS;
  const pairRaw = q.get('pair');
  const pair = PLANE_PAIRS.some((p) => p.id === pairRaw) ? (pairRaw as PlanePair) : d.pair;
  const integratorRaw = q.get('integrator');
  const integrator: Integrator = integratorRaw === 'exp' || integratorRaw === 'euler' ? integratorRaw : d.integrator;
  return {
    pair,
    rateA: readNumber(q, ['a', 'rateA'], SETTING_LIMITS.rate, d.rateA),
    rateB: readNumber(q, ['b', 'rateB'], SETTING_LIMITS.rate, d.rateB),
    step: readNumber(q, ['dt', 'step'], SETTING_LIMITS.step, d.step),
    correct: readBoolean(q, 'correct', d.correct),
    tolerance: readNumber(q, ['tol'], SETTING_LIMITS.tolerance, d.tolerance),
    integrator,
    speed: readNumber(q, ['speed'], SETTING_LIMITS.speed, d.speed),
    warmSteps: Math.round(readNumber(q, ['steps'], SETTING_LIMITS.warmSteps, d.warmSteps)),
  };
}

/**
 * The query string that `parseSettings` turns back into `s` (only the keys that differ from the
 * defaults, so the address stays short). `warmSteps` is left out: it describes how a page was
 * opened, not a state to share.
 */
export function settingsToQuery(s: RotorSettings): string {
  const d = DEFAULT_SETTINGS;
  const q = new URLSearchParams();
  if (s.pair !== d.pair) q.set('pair', s.pair);
  if (s.rateA !== d.rateA) q.set('a', String(s.rateA));
  if (s.rateB !== d.rateB) q.set('b', String(s.rateB));
  if (s.step !== d.step) q.set('dt', String(s.step));
  if (s.correct !== d.correct) q.set('correct', s.correct ? '1' : '0');
  if (s.tolerance !== d.tolerance) q.set('tol', String(s.tolerance));
  if (s.integrator !== d.integrator) q.set('integrator', s.integrator);
  if (s.speed !== d.speed) q.set('speed', String(s.speed));
  return q.toString();
}
