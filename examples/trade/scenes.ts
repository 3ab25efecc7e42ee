/**
 * The trade page's scenes, built on the engine directly (no DOM): each gives a world and an error
 * measure, the worst deviation that matters for it, in metres.
 */
import { Body, HalfSpace, HyperBox, HyperSphere, PointJoint, World, dims } from '@physin/engine';
import type { Params } from '@physin/engine';

/** A scene to run: its world, and its error now (m). */
export interface TradeScene {
  readonly world: World;
  error(): number;
}

/** The scenes of the page, by name. */
export const SCENES = {
  'stack of 10': stack,
  'chain of 10': (p: Partial<Params>) => chain(p, 1),
  'chain 1000:1': (p: Partial<Params>) => chain(p, 1000),
  '4D stack of 6': stack4,
} as const;
export type SceneName = keyof typeof SCENES;

/** Ten unit boxes stacked on the ground: error = the largest drift of a box from where it started. */
function stack(params: Partial<Params>): TradeScene {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: [0, -9.81, 0], params: { ...params, allowSleep: false } });
  world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
  const boxes: Body[] = [];
  const start: number[][] = [];
  for (let i = 0; i < 10; i += 1) {
    const box = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5 + i, 0], material: { friction: 0.6 } });
    world.addBody(box);
    boxes.push(box);
    start.push([...box.x]);
  }
  return {
    world,
    error: () => Math.max(...boxes.map((b, i) => Math.hypot(b.x[0]! - start[i]![0]!, b.x[1]! - start[i]![1]!, b.x[2]! - start[i]![2]!))),
  };
}

/** Six hypercubes stacked in 4D. */
function stack4(params: Partial<Params>): TradeScene {
  const D = dims(4);
  const world = new World({ dimensions: 4, gravity: [0, -9.81, 0, 0], params: { ...params, allowSleep: false } });
  world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0, 0], 0), mass: 0 }));
  const boxes: Body[] = [];
  const start: number[][] = [];
  for (let i = 0; i < 6; i += 1) {
    const box = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5 + i, 0, 0], material: { friction: 0.6 } });
    world.addBody(box);
    boxes.push(box);
    start.push([...box.x]);
  }
  return {
    world,
    error: () => Math.max(...boxes.map((b, i) => Math.hypot(...[0, 1, 2, 3].map((a) => b.x[a]! - start[i]![a]!)))),
  };
}

/**
 * Ten balls on point joints, 0.5 m apart, hanging from a fixed point and starting horizontal, so
 * the chain whips as it falls; the last ball weighs `ratio` times the others. Error = the largest
 * gap a joint opens.
 */
function chain(params: Partial<Params>, ratio: number): TradeScene {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: [0, -9.81, 0], params: { ...params, allowSleep: false } });
  const joints: PointJoint[] = [];
  let previous: Body | null = null;
  for (let i = 0; i < 10; i += 1) {
    const ball = new Body(D, { shape: HyperSphere(0.1), mass: i === 9 ? ratio : 1, position: [0.5 * (i + 1), 5, 0] });
    world.addBody(ball);
    const joint = new PointJoint(ball, previous, [-0.25, 0, 0], previous === null ? [0.25, 5, 0] : [0.25, 0, 0]);
    world.addConstraint(joint);
    joints.push(joint);
    previous = ball;
  }
  return { world, error: () => Math.max(...joints.map((j) => j.error())) };
}

/** The knobs, with presets. */
export interface Knobs {
  iterations: number;
  subSteps: number;
  /** Steps per second (the time step is its inverse). */
  rate: number;
}
export const PRESETS: Record<string, Knobs> = {
  fast: { iterations: 4, subSteps: 1, rate: 60 },
  default: { iterations: 10, subSteps: 1, rate: 60 },
  accurate: { iterations: 10, subSteps: 4, rate: 120 },
};

/** The engine's parameters of a set of knobs. */
export function paramsOf(knobs: Knobs): Partial<Params> {
  return { iterations: knobs.iterations, subSteps: knobs.subSteps, fixedTimeStep: 1 / knobs.rate };
}
