/**
 * The trade page's scenes: the physics (the worlds and their errors) is trade-core.mjs's, the code
 * bench/trade.bench.mjs runs for docs/trade.md; this file adds what the small view draws. No DOM,
 * so the page's worker can build them too.
 */
import { rotorApplyVector } from '@physin/algebra';
import { dims } from '@physin/engine';
import type { Body, Dims, Params, World } from '@physin/engine';
import { PRESETS as CORE_PRESETS, SCENES as CORE_SCENES } from './trade-core.mjs';
import type { CoreScene, Knobs, PresetName, SceneName } from './trade-core.mjs';

export { paramsOf } from './trade-core.mjs';
export type { Knobs, PresetName, SceneName } from './trade-core.mjs';

/** What the view draws of one body, in the x-y plane (the side view): a polygon or a disc. */
export type Outline =
  | { readonly kind: 'poly'; readonly points: number[] }
  | { readonly kind: 'disc'; readonly x: number; readonly y: number; readonly r: number };

/** A scene to run. */
export interface TradeScene {
  readonly world: World;
  /** The scene's error now (m, or rad for the spinning body). */
  error(): number;
  /** The unit of the error. */
  readonly unit: string;
  /** The bodies in the x-y plane, and the joints as segments [x0, y0, x1, y1, ...]. */
  outline(): { bodies: Outline[]; links: number[] };
  /** The view's window in x and y: [xMin, xMax, yMin, yMax] (m). */
  readonly frame: readonly [number, number, number, number];
}

/** The presets of the knobs: `presets` of @physin/engine (balanced = the defaults). */
export const PRESETS: Readonly<Record<PresetName, Readonly<Knobs>>> = CORE_PRESETS;

/** The time steps offered (as rates, Hz): fixedTimeStep 1/30 … 1/240. */
export const RATES = { '1/30 s': 30, '1/60 s': 60, '1/120 s': 120, '1/240 s': 240 } as const;

/** The scenes of the page, by name. */
export const SCENES = Object.fromEntries(
  (Object.keys(CORE_SCENES) as SceneName[]).map((name) => [
    name,
    (p: Partial<Params>): TradeScene => withOutline(CORE_SCENES[name](p)),
  ]),
) as Record<SceneName, (p: Partial<Params>) => TradeScene>;

/** A scene of trade-core.mjs with the view's outline. */
export function withOutline(scene: CoreScene): TradeScene {
  const view = scene.view;
  let outline: TradeScene['outline'];
  if (view.kind === 'boxes') {
    const D = dims(view.n);
    const local = new Float64Array(view.n);
    const out = new Float64Array(view.n);
    outline = () => ({ bodies: view.boxes.map((b) => boxOutline(D, b, view.half, local, out)), links: [] });
  } else {
    outline = () => {
      const segments = [0, 0];
      for (const l of view.links) segments.push(l.x[0]!, l.x[1]!, l.x[0]!, l.x[1]!);
      segments.length -= 2;
      return {
        bodies: view.links.map((l, i) => ({
          kind: 'disc' as const,
          x: l.x[0]!,
          y: l.x[1]!,
          r: i === view.links.length - 1 && view.heavy ? 0.3 : 0.1,
        })),
        links: segments,
      };
    };
  }
  return { world: scene.world, unit: scene.unit, error: () => scene.error(), outline, frame: scene.frame };
}

/** The corners of a box (half extents `half`) of body `b`, projected on x-y, as a convex polygon. */
function boxOutline(D: Dims, b: Body, half: readonly number[], local: Float64Array, world: Float64Array): Outline {
  const pts: [number, number][] = [];
  for (let m = 0; m < 1 << D.n; m += 1) {
    for (let i = 0; i < D.n; i += 1) local[i] = (m >> i) & 1 ? half[i]! : -half[i]!;
    rotorApplyVector(D, world, b.R, local);
    pts.push([b.x[0]! + world[0]!, b.x[1]! + world[1]!]);
  }
  return { kind: 'poly', points: hull(pts) };
}

/** Convex hull (monotone chain), flattened [x0, y0, x1, y1, ...]. */
function hull(pts: [number, number][]): number[] {
  pts.sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const cross = (o: [number, number], a: [number, number], b: [number, number]): number =>
    (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lower: [number, number][] = [];
  for (const p of pts) {
    while (lower.length >= 2 && cross(lower[lower.length - 2]!, lower[lower.length - 1]!, p) <= 0) lower.pop();
    lower.push(p);
  }
  const upper: [number, number][] = [];
  for (let i = pts.length - 1; i >= 0; i -= 1) {
    const p = pts[i]!;
    while (upper.length >= 2 && cross(upper[upper.length - 2]!, upper[upper.length - 1]!, p) <= 0) upper.pop();
    upper.push(p);
  }
  return [...lower.slice(0, -1), ...upper.slice(0, -1)].flat();
}
