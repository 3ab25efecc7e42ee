// Engine-neutral contact scenes: where the boxes start, and how to tell whether the scene
// "stands" after the run. PhysiN (scenes/physin-scenes.mjs) and the peers (scenes/peer-scenes.mjs)
// build their worlds from the same layouts, so every engine simulates the same start.
//
// Conventions: y (axis 1) is up, the ground is the plane y = 0 (solid below), every box is a
// unit (hyper)cube (half-extents 0.5), mass 1, friction 0.5, restitution 0; dt = 1/60, 600 steps.

import { seeded } from '../lib/random.mjs';

/** Half-extent of every box (m): unit boxes. */
export const HALF = 0.5;
export const MASS = 1;
export const FRICTION = 0.5;
export const RESTITUTION = 0;
export const GRAVITY = 9.81;
export const DT = 1 / 60;
/** Steps of one run: 10 s at 60 Hz. */
export const STEPS = 600;
/** Vertical gap left under every box of a stack or pyramid at the start (m): no initial overlap. */
export const START_GAP = 0.001;
/** Centre-to-centre spacing of the boxes of one pyramid row (m): 1 box + 5 cm, Box2D style. */
export const PYRAMID_SPACING = 1.05;
/** Grid spacing (m) and largest jitter (m, each way) of the piles. */
export const PILE_SPACING = 1.2;
export const PILE_JITTER = 0.09;
/** Height (m) of the centres of the lowest layer of a pile. */
export const PILE_BOTTOM = 1.0;

/** Stack criteria: top box drift (m) and height error (m) allowed at the end. */
export const STACK_MAX_DRIFT = 0.01;
export const STACK_MAX_HEIGHT_ERROR = 0.02;
/**
 * Pyramid criterion: largest displacement (m) of any box from its rest pose (its start with the
 * start gaps below it closed: a pyramid of 100 rows settles 0.1 m by its gaps alone).
 */
export const PYRAMID_MAX_DISPLACEMENT = 0.05;

/**
 * A layout: `positions[i]` (n numbers) is the start centre of box i, `yaws[i]` its start turn about
 * the vertical (rad; the turn carries +z toward +x, i.e. the rotation about +y by that angle in
 * 3D; in n > 3 the same turn in the plane of axes 2 and 0). `rest` (stacks) is the ideal centre
 * height of the top box once the gaps have closed; `rests` (pyramids) the ideal centre of every box.
 *
 * @typedef {{ name: string, kind: 'stack' | 'pyramid' | 'pile', n: number,
 *   positions: number[][], yaws: number[], rest?: number, rests?: number[][] }} Layout
 */

/** `count` boxes in one column on the ground: centres y = 0.5 + i + (i + 1)·START_GAP. */
export function stackLayout(count, n = 3, name = `stack${count}`) {
  const positions = [];
  for (let i = 0; i < count; i += 1) {
    const p = new Array(n).fill(0);
    p[1] = HALF + i * 2 * HALF + (i + 1) * START_GAP;
    positions.push(p);
  }
  return { name, kind: 'stack', n, positions, yaws: new Array(count).fill(0), rest: HALF + (count - 1) * 2 * HALF };
}

/**
 * A 2D pyramid in the x-y plane (z = 0): a base row of `base` boxes and rows of one box fewer
 * above, each row centred on the one below (so every box rests on two). base 20 = 210 boxes.
 */
export function pyramidLayout(base = 20, n = 3, name = `pyramid${base}`) {
  const positions = [];
  const rests = [];
  for (let row = 0; row < base; row += 1) {
    const count = base - row;
    const y = HALF + row * 2 * HALF;
    for (let j = 0; j < count; j += 1) {
      const p = new Array(n).fill(0);
      p[0] = (j - (count - 1) / 2) * PYRAMID_SPACING;
      p[1] = y;
      rests.push(p.slice());
      p[1] = y + (row + 1) * START_GAP;
      positions.push(p);
    }
  }
  return { name, kind: 'pyramid', n, positions, rests, yaws: new Array(positions.length).fill(0) };
}

/**
 * `count` boxes on a grid of `side` boxes along every horizontal axis (n − 1 of them), layer by
 * layer upward from y = PILE_BOTTOM, PILE_SPACING apart, each moved by a seeded jitter of up to
 * ±PILE_JITTER along every axis and turned by a seeded yaw in [−0.4, 0.4] rad (none in 2D), then
 * dropped.
 */
export function pileLayout(count, n = 3, side = 10, seed = 1000 + n, name = `pile${count}`) {
  const rand = seeded(seed);
  const jitter = () => (2 * rand() - 1) * PILE_JITTER;
  const horizontal = [];
  for (let a = 0; a < n; a += 1) if (a !== 1) horizontal.push(a);
  const perLayer = side ** horizontal.length;
  const positions = [];
  const yaws = [];
  for (let i = 0; i < count; i += 1) {
    const layer = Math.floor(i / perLayer);
    let cell = i % perLayer;
    const p = new Array(n).fill(0);
    for (const a of horizontal) {
      p[a] = ((cell % side) - (side - 1) / 2) * PILE_SPACING + jitter();
      cell = Math.floor(cell / side);
    }
    p[1] = PILE_BOTTOM + layer * PILE_SPACING + jitter();
    positions.push(p);
    const yaw = 0.8 * (rand() - 0.5);
    yaws.push(n >= 3 ? yaw : 0); // n = 2 has no plane (2, 0)
  }
  return { name, kind: 'pile', n, positions, yaws };
}

/**
 * The 3D scenes the peers run. The large pyramid (Box2D v3's benchmark scene: 100 at the base,
 * 5,050 boxes) runs once, beside Rapier alone (`peers`, `rounds`): cannon-es would take minutes.
 */
export function peerLayouts() {
  return [stackLayout(9), pyramidLayout(20), pileLayout(1000, 3, 10), { ...pyramidLayout(100), peers: ['Rapier'], rounds: 1 }];
}

/**
 * Judges the end state. `final[i]` is the centre of box i after the run (n numbers).
 * Returns { stands: boolean | null (piles: not judged), measure: string (what was found),
 * below: number of boxes whose centre ended below the ground plane y = 0 }.
 */
export function judge(layout, final) {
  const finite = final.every((p) => p.every(Number.isFinite));
  if (!finite) return { stands: false, measure: 'non-finite state', below: NaN };
  const below = final.filter((p) => p[1] < 0).length;
  if (layout.kind === 'stack') {
    const top = final[final.length - 1];
    const start = layout.positions[final.length - 1];
    let drift = 0;
    for (let a = 0; a < layout.n; a += 1) if (a !== 1) drift = Math.hypot(drift, top[a] - start[a]);
    const dy = top[1] - layout.rest;
    const stands = drift < STACK_MAX_DRIFT && Math.abs(dy) < STACK_MAX_HEIGHT_ERROR;
    const contacts = final.length; // ground + box-on-box contacts under the top box
    return { stands, measure: `top drift ${fmtLen(drift)}, dy ${fmtLen(dy)} (${fmtLen(dy / contacts)}/contact)`, below };
  }
  if (layout.kind === 'pyramid') {
    let worst = 0;
    for (let i = 0; i < final.length; i += 1) {
      let d = 0;
      for (let a = 0; a < layout.n; a += 1) d = Math.hypot(d, final[i][a] - layout.rests[i][a]);
      worst = Math.max(worst, d);
    }
    return { stands: worst < PYRAMID_MAX_DISPLACEMENT, measure: `max displacement ${fmtLen(worst)}`, below };
  }
  // Pile: only count the boxes whose centre ended below the ground plane.
  return { stands: null, measure: `${below} below ground`, below };
}

/** A length (m) with a sign, 3 significant digits. */
function fmtLen(x) {
  if (x === 0) return '0';
  return Math.abs(x) >= 100 ? x.toFixed(0) : x.toPrecision(3);
}
