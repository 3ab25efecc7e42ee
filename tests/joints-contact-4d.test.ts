/**
 * A chain whipping onto a floor: joints and contacts in the same passes (docs/joints.md,
 * "Contacts and the geometric stiffness").
 *
 * Scene: the specification's chain of 10 (tests/support/joints.ts: 1 kg balls of radius 0.1,
 * anchors at ±0.5, the first joined to the world at the origin), starting horizontal, gravity
 * −9.81 e_1, 1/60, the defaults, sleep off; a static half-space floor at y = −3; with or without
 * five 1 kg balls of radius 0.3 resting on it at x = 1, 2.7, …, 7.8. 600 steps.
 *
 * Before: the 4D chain threw NonFiniteStateError at step 427 (at step 64 with the five balls),
 * its links past 1e100 m/s; 5D and 6D failed the same way, and with a last link of 1000 kg so did
 * 2D and 3D. The tree solved the joints with the geometric stiffness on the links' inertia (M̃),
 * the contacts in the same passes with the bare inertia (M): passes that project in two metrics
 * in turn are no contraction, and the light links gained energy every sub-step. The contacts and
 * Gauss–Seidel rows on the tree's bodies now take the tree's M̃ too.
 *
 * Measured (worst over every step end): joint error ≤ 7.6e-13 m, a ball or link below the floor
 * by ≤ 5.7 mm (1 kg links) and ≤ 26 mm (1000 kg last link), the total energy never above its start.
 */
import { describe, expect, it } from 'vitest';
import { Body, HyperSphere } from '@physin/engine';
import { buildChain, chainEnergy } from './support/joints.js';
import { addGround, axis } from './support/scenes.js';

const FLOOR = -3;
const STEPS = 600;

function whipOntoFloor(n: number, balls: number, lastMass: number) {
  const chain = buildChain({ n, hanging: false, lastMass });
  const world = chain.world;
  const D = world.D;
  addGround(world, {}, axis(n, 1), FLOOR);
  const free: Body[] = [];
  for (let i = 0; i < balls; i += 1) {
    const p = new Array<number>(n).fill(0);
    p[0] = 1 + 1.7 * i;
    p[1] = FLOOR + 0.5;
    free.push(world.addBody(new Body(D, { shape: HyperSphere(D, 0.3), mass: 1, position: p, name: `ball${i}` })));
  }
  const energy = (): number => {
    let e = chainEnergy(chain);
    for (const b of free) e += b.kineticEnergy() + b.mass * 9.81 * b.x[1]!;
    return e;
  };
  const e0 = energy();
  let worst = 0;
  let below = 0;
  let rise = 0;
  for (let s = 0; s < STEPS; s += 1) {
    world.step(1 / 60);
    worst = Math.max(worst, chain.error());
    for (const b of chain.links) below = Math.max(below, FLOOR - (b.x[1]! - 0.1));
    for (const b of free) below = Math.max(below, FLOOR - (b.x[1]! - 0.3));
    rise = Math.max(rise, energy() - e0);
  }
  let finite = true;
  for (const b of world.bodies) for (const a of [b.x, b.v, b.L]) for (const x of a) if (!Number.isFinite(x)) finite = false;
  return { worst, below, rise, finite };
}

describe('a chain of 10 whipping onto a floor at y = −3 (600 steps at 1/60, the defaults)', () => {
  for (const lastMass of [1, 1000]) {
    const belowBound = lastMass === 1 ? 0.01 : 0.05;
    for (const n of [2, 3, 4, 5, 6]) {
      for (const balls of [0, 5]) {
        it(`${n}D, last link ${lastMass} kg, ${balls} balls on the floor: finite, joints within 5e-12 m, nothing below the floor by more than ${belowBound} m, no energy gained`, () => {
          const r = whipOntoFloor(n, balls, lastMass);
          const report = `${n}D last ${lastMass} kg, ${balls} balls: worst joint error ${r.worst.toExponential(2)} m, below the floor ${r.below.toExponential(2)} m, energy rise ${r.rise.toExponential(2)} J`;
          console.log(report);
          expect(r.finite, report).toBe(true);
          expect(r.worst, report).toBeLessThanOrEqual(5e-12); // worst measured 7.6e-13
          expect(r.below, report).toBeLessThanOrEqual(belowBound);
          expect(r.rise, report).toBeLessThanOrEqual(1e-6);
        });
      }
    }
  }
});
