// PhysiN contact scenes, reusable by benchmarks and tests: build a World from a layout of
// scenes/layouts.mjs (unit boxes on the ground half-space y >= 0), step it, read the centres.
//
//   import { physinStack, physinPyramid, physinPile } from '../bench/scenes/physin-scenes.mjs';
//   const scene = physinStack(9, 4);       // 9 hyperboxes stacked in 4D
//   for (let i = 0; i < 600; i += 1) scene.step();
//   scene.judge();                         // { stands, measure }
//
// Imports the BUILT engine (@physin/engine's dist/), like every benchmark.

import { World, Body, HyperBox, HalfSpace, dims } from '@physin/engine';
import { rotorFromPlane } from '@physin/algebra';
import { DT, FRICTION, GRAVITY, HALF, MASS, RESTITUTION, judge, pileLayout, pyramidLayout, stackLayout } from './layouts.mjs';

/** Parameters of the benchmark worlds: sleep off (every body is timed every step); the rest default (iterations 10). */
export const PHYSIN_BENCH_PARAMS = Object.freeze({ allowSleep: false });

/**
 * Builds a PhysiN world from a layout: the ground HalfSpace (normal +y, offset 0: solid y <= 0,
 * static) and one HyperBox per layout entry.
 *
 * @param {import('./layouts.mjs').Layout} layout
 * @param {Partial<import('@physin/engine').Params>} [params] merged over PHYSIN_BENCH_PARAMS
 * @returns {{ layout, world: World, boxes: Body[], ground: Body, step: (dt?: number) => void,
 *   positions: () => number[][], judge: () => { stands: boolean | null, measure: string } }}
 */
export function buildPhysinScene(layout, params = {}) {
  const n = layout.n;
  const D = dims(n);
  const gravity = new Array(n).fill(0);
  gravity[1] = -GRAVITY;
  const world = new World({ dimensions: n, gravity, params: { ...PHYSIN_BENCH_PARAMS, ...params } });
  const up = new Array(n).fill(0);
  up[1] = 1;
  const ground = world.addBody(
    new Body(D, {
      shape: HalfSpace(D, up, 0),
      mass: 0,
      material: { friction: FRICTION, restitution: RESTITUTION },
      name: 'ground',
    }),
  );
  const shape = HyperBox(D, new Array(n).fill(HALF));
  const material = { friction: FRICTION, restitution: RESTITUTION };
  const rotor = new Float64Array(D.r);
  const boxes = layout.positions.map((position, i) => {
    const options = { shape, mass: MASS, position, material, name: `${layout.name}[${i}]` };
    const yaw = layout.yaws[i];
    if (yaw !== 0) {
      // The yaw turns +z toward +x: the plane (2, 0) in the algebra's "turn e_i toward e_j"
      // (layouts give n = 2 no yaw).
      options.rotor = rotorFromPlane(D, rotor, 2, 0, yaw);
    }
    return world.addBody(new Body(D, options));
  });
  return {
    layout,
    world,
    boxes,
    ground,
    step: (dt = DT) => world.step(dt),
    positions: () => boxes.map((b) => Array.from(b.x)),
    judge: () =>
      judge(
        layout,
        boxes.map((b) => Array.from(b.x)),
      ),
  };
}

/** `count` unit hyperboxes stacked on the ground in n dimensions. */
export function physinStack(count = 9, n = 3, params) {
  return buildPhysinScene(stackLayout(count, n, n === 3 ? `stack${count}` : `stack${count} ${n}D`), params);
}

/** The Box2D-style pyramid (base row of `base` boxes) in the x-y plane of a 3D world. */
export function physinPyramid(base = 20, params) {
  return buildPhysinScene(pyramidLayout(base, 3), params);
}

/** A seeded pile of `count` hyperboxes dropped from a grid `side` boxes wide along each horizontal axis. */
export function physinPile(count = 1000, n = 3, side = n === 3 ? 10 : 4, params) {
  return buildPhysinScene(pileLayout(count, n, side, 1000 + n, n === 3 ? `pile${count}` : `pile${count} ${n}D`), params);
}
