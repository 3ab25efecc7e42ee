/**
 * The trade page's scenes, built on the engine directly (no DOM, so the page's worker can build
 * them too): each gives a world, its error now (m) and what the small view draws.
 *
 * - stack of 10: ten unit boxes on the ground; error = the largest drift of a box from where it
 *   started.
 * - chain of 10: the specification's chain (docs/joints.md): ten links of 1 kg, balls of radius 0.1
 *   whose anchors are at ±0.5 along the chain, the first pinned to the world at the origin; it
 *   starts horizontal, so it whips as it falls. Error = the largest gap a joint opens
 *   (`PointJoint.error()`).
 * - chain 1000:1: the same, the last link 1000 kg.
 * - 4D stack of 6: six unit hypercubes on the ground in 4D; error as the stack.
 */
import { rotorApplyVector } from '@physin/algebra';
import { Body, HalfSpace, HyperBox, HyperSphere, PointJoint, World, dims } from '@physin/engine';
import type { Dims, Params } from '@physin/engine';

/** What the view draws of one body, in the x-y plane (the side view): a polygon or a disc. */
export type Outline =
  | { readonly kind: 'poly'; readonly points: number[] }
  | { readonly kind: 'disc'; readonly x: number; readonly y: number; readonly r: number };

/** A scene to run. */
export interface TradeScene {
  readonly world: World;
  /** The scene's error now (m). */
  error(): number;
  /** The bodies in the x-y plane, and the joints as segments [x0, y0, x1, y1, ...]. */
  outline(): { bodies: Outline[]; links: number[] };
  /** The view's window in x and y: [xMin, xMax, yMin, yMax] (m). */
  readonly frame: readonly [number, number, number, number];
}

/** The knobs a run is made of. */
export interface Knobs {
  iterations: number;
  subSteps: number;
  /** Steps per second: fixedTimeStep is its inverse. */
  rate: number;
}

/** The presets of the knobs. */
export const PRESETS: Readonly<Record<'fast' | 'default' | 'accurate', Knobs>> = {
  fast: { iterations: 4, subSteps: 1, rate: 30 },
  default: { iterations: 10, subSteps: 1, rate: 60 },
  accurate: { iterations: 20, subSteps: 8, rate: 120 },
};
export type PresetName = keyof typeof PRESETS;

/** The time steps offered (as rates, Hz): fixedTimeStep 1/30 … 1/240. */
export const RATES = { '1/30 s': 30, '1/60 s': 60, '1/120 s': 120, '1/240 s': 240 } as const;

/** The engine's parameters for a set of knobs. Sleep is off: a sleeping body would hide its error. */
export function paramsOf(knobs: Knobs): Partial<Params> {
  return { iterations: knobs.iterations, subSteps: knobs.subSteps, fixedTimeStep: 1 / knobs.rate, allowSleep: false };
}

/** The scenes of the page, by name. */
export const SCENES = {
  'chain of 10': (p: Partial<Params>) => chain(p, 1),
  'chain 1000:1': (p: Partial<Params>) => chain(p, 1000),
  'stack of 10': (p: Partial<Params>) => stack(p, 3, 10),
  '4D stack of 6': (p: Partial<Params>) => stack(p, 4, 6),
} as const;
export type SceneName = keyof typeof SCENES;

function gravity(n: number): number[] {
  const g = new Array<number>(n).fill(0);
  g[1] = -9.81;
  return g;
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

/** `count` unit (hyper)boxes stacked on the ground in n dimensions. */
function stack(params: Partial<Params>, n: 3 | 4, count: number): TradeScene {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: gravity(n), params });
  const up = new Array<number>(n).fill(0);
  up[1] = 1;
  world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
  const half = new Array<number>(n).fill(0.5);
  const boxes: Body[] = [];
  const starts: Float64Array[] = [];
  for (let i = 0; i < count; i += 1) {
    const position = new Array<number>(n).fill(0);
    position[1] = 0.5 + i;
    const box = world.addBody(new Body(D, { shape: HyperBox(D, half), mass: 1, position, material: { friction: 0.6 } }));
    boxes.push(box);
    starts.push(Float64Array.from(box.x));
  }
  const local = new Float64Array(n);
  const out = new Float64Array(n);
  return {
    world,
    error: () => {
      let worst = 0;
      for (let b = 0; b < boxes.length; b += 1) {
        const x = boxes[b]!.x;
        const s = starts[b]!;
        let d2 = 0;
        for (let i = 0; i < n; i += 1) d2 += (x[i]! - s[i]!) ** 2;
        worst = Math.max(worst, Math.sqrt(d2));
      }
      return worst;
    },
    outline: () => ({ bodies: boxes.map((b) => boxOutline(D, b, half, local, out)), links: [] }),
    frame: [-4, 4, -0.6, count + 0.6],
  };
}

/** The specification's chain of 10, starting horizontal; the last link weighs `ratio` kg. */
function chain(params: Partial<Params>, ratio: number): TradeScene {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: gravity(3), params });
  const shape = HyperSphere(D, 0.1);
  const links: Body[] = [];
  const joints: PointJoint[] = [];
  for (let i = 0; i < 10; i += 1) {
    const link = world.addBody(new Body(D, { shape, mass: i === 9 ? ratio : 1, position: [i + 0.5, 0, 0] }));
    const previous = links[i - 1];
    joints.push(
      world.addConstraint(
        previous === undefined
          ? new PointJoint(link, null, [-0.5, 0, 0], [0, 0, 0])
          : new PointJoint(previous, link, [0.5, 0, 0], [-0.5, 0, 0]),
      ),
    );
    links.push(link);
  }
  return {
    world,
    error: () => {
      let worst = 0;
      for (const j of joints) worst = Math.max(worst, j.error());
      return worst;
    },
    outline: () => {
      const segments = [0, 0];
      for (const l of links) segments.push(l.x[0]!, l.x[1]!, l.x[0]!, l.x[1]!);
      segments.length -= 2;
      return {
        bodies: links.map((l, i) => ({ kind: 'disc', x: l.x[0]!, y: l.x[1]!, r: i === 9 && ratio > 1 ? 0.3 : 0.1 })),
        links: segments,
      };
    },
    frame: [-10.5, 10.5, -10.8, 1],
  };
}
