/** Types of trade-core.mjs (plain JavaScript, shared by the trade page and bench/trade.bench.mjs). */
import type { Body, Params, World } from '@physin/engine';

/** The knobs a run is made of. */
export interface Knobs {
  iterations: number;
  subSteps: number;
  /** Steps per second: fixedTimeStep is its inverse. */
  rate: number;
}

/** What the view of a scene draws. */
export type SceneView =
  | { readonly kind: 'boxes'; readonly n: number; readonly boxes: readonly Body[]; readonly half: readonly number[] }
  | { readonly kind: 'chain'; readonly links: readonly Body[]; readonly heavy: boolean };

/** A scene to run. */
export interface CoreScene {
  readonly world: World;
  /** The unit of the error: 'm' or 'rad'. */
  readonly unit: string;
  /** The scene's error now. */
  error(): number;
  readonly view: SceneView;
  /** The view's window in x and y: [xMin, xMax, yMin, yMax] (m). */
  readonly frame: readonly [number, number, number, number];
}

export type SceneName = 'stack of 9' | 'pyramid' | 'chain of 10' | 'chain 1000:1' | '4D stack of 6' | 'spinning body';
export type PresetName = 'fast' | 'balanced' | 'accurate';

export function paramsOf(knobs: Knobs): Partial<Params>;
export function knobsOf(params: Partial<Params>): Knobs;
export function stackCentres(n: number, count: number): number[][];
export function pyramidCentres(base: number): number[][];
export const SCENES: Readonly<Record<SceneName, (params: Partial<Params>) => CoreScene>>;
export const PEER_SCENES: Readonly<Record<'stack of 9' | 'pyramid', () => number[][]>>;
export const FRICTION: number;
export const PRESETS: Readonly<Record<PresetName, Readonly<Knobs>>>;
export const GRID: Readonly<{ iterations: readonly number[]; subSteps: readonly number[]; rate: readonly number[] }>;

/** One run: a scene stepped for a number of simulated seconds, recording every step. */
export class Run {
  constructor(name: SceneName, knobs: Knobs, seconds: number);
  readonly scene: CoreScene;
  readonly rate: number;
  readonly total: number;
  readonly steps: number;
  readonly ms: number;
  /** Simulated time after each step (s). */
  readonly times: number[];
  /** The scene's error after each step. */
  readonly errors: number[];
  /** Milliseconds each step took. */
  readonly costs: number[];
  /** Largest error so far (Infinity if a step threw or the error is not finite). */
  readonly worst: number;
  /** The engine's message if a step threw (the run stops there). */
  readonly failure: string | null;
  readonly done: boolean;
  /** Milliseconds of stepping per simulated second so far. */
  readonly msPerSecond: number;
  /** Steps for about `budgetMs` milliseconds (at least one step); returns whether the run is done. */
  advance(budgetMs: number): boolean;
}

export function warmUp(): void;
export function runSweepPoint(
  name: SceneName,
  knobs: Knobs,
  seconds: number,
): { worst: number; msPerSecond: number; failure: string | null };
export function paretoFront<P extends { error: number; cost: number }>(points: readonly P[]): P[];
