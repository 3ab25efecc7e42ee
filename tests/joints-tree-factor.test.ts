/**
 * Joints: the tree's block factorisation where its blocks are singular.
 *
 * The tree factors each node's block by an LDLᵀ without pivoting (body blocks positive definite,
 * joint blocks negative definite) and falls back to the LU with complete pivoting where a pivot
 * has the wrong sign or is not clearly nonzero (docs/joints.md, "The blocks' factorisation"). These
 * scenes have redundant rows, so some blocks are singular and take the fallback; the rows must
 * still be met to rounding, the bodies must stay finite, and two runs must give the same bits.
 *
 * - A ball welded to the world twice (the same weld: 2 × 6 rows on 6 unknowns), a chain of three
 *   links hanging from it: the welded ball stays where it was, the chain's joints stay closed.
 * - A 4 × 4 joint grid (the bench's grid20, smaller) whose first row is pinned to the world at the
 *   ball centres: the joints between two pinned balls have a row along their line that the pins
 *   already hold, so their blocks are singular; it swings down about the pinned row.
 */
import { describe, expect, it } from 'vitest';
import { Body, FixedJoint, HyperSphere, PointJoint } from '@physin/engine';
import { makeWorld } from './support/scenes.js';
import { pinnedGrid, pointJointError, snapshot } from './support/joints.js';
import type { JointScene } from './support/joints.js';

const DT = 1 / 60;

function doubleWeld(): JointScene {
  const world = makeWorld(3, {});
  const D = world.D;
  const shape = HyperSphere(D, 0.1);
  const bodies: Body[] = [];
  for (let i = 0; i < 4; i += 1) bodies.push(world.addBody(new Body(D, { shape, mass: 1, position: [i, 0, 0] })));
  world.addConstraint(new FixedJoint(bodies[0]!, null, [0, 0, 0], [0, 0, 0]));
  world.addConstraint(new FixedJoint(bodies[0]!, null, [0, 0, 0], [0, 0, 0]));
  const list: [number, number][] = [];
  for (let i = 1; i < 4; i += 1) {
    world.addConstraint(new PointJoint(bodies[i - 1]!, bodies[i]!, [0.5, 0, 0], [-0.5, 0, 0]));
    list.push([i - 1, i]);
  }
  const error = (): number => {
    let worst = 0;
    for (const [a, b] of list) worst = Math.max(worst, pointJointError(bodies[a]!, [0.5, 0, 0], bodies[b]!, [-0.5, 0, 0]));
    return worst;
  };
  return { world, bodies, error };
}

/** Steps the scene; returns the worst joint error and the lowest height the last body reached. */
function run(scene: JointScene, steps: number): { worst: number; lowest: number } {
  let worst = 0;
  let lowest = Infinity;
  const last = scene.bodies[scene.bodies.length - 1]!;
  for (let s = 0; s < steps; s += 1) {
    scene.world.step(DT);
    worst = Math.max(worst, scene.error());
    lowest = Math.min(lowest, last.x[1]!);
  }
  return { worst, lowest };
}

describe('the tree where its blocks are singular (the LU fallback of the LDLᵀ)', () => {
  it('a ball welded to the world twice, a chain of 3 hanging from it: the ball stays (|Δx| < 1e-9 m), the joints stay closed (≤ 1e-9 m) over 2 s', () => {
    const scene = doubleWeld();
    const x0 = Float64Array.from(scene.bodies[0]!.x);
    const { worst, lowest } = run(scene, 120);
    let moved = 0;
    for (let i = 0; i < 3; i += 1) moved = Math.max(moved, Math.abs(scene.bodies[0]!.x[i]! - x0[i]!));
    console.log(`double weld: the welded ball moved ${moved.toExponential(2)} m, worst joint error ${worst.toExponential(2)} m`);
    expect(moved).toBeLessThan(1e-9);
    expect(worst).toBeLessThan(1e-9);
    // The chain swung: its last link went well below its start.
    expect(lowest).toBeLessThan(-1);
  });

  it('a 4 × 4 grid pinned along its first row: every joint closed to 1e-9 m over 3 s, and the grid swings down', () => {
    const scene = pinnedGrid(4);
    const { worst, lowest } = run(scene, 180);
    console.log(`pinned 4 × 4 grid: worst joint error ${worst.toExponential(2)} m`);
    expect(worst).toBeLessThan(1e-9);
    for (const b of scene.bodies) for (let i = 0; i < 3; i += 1) expect(Number.isFinite(b.x[i]!)).toBe(true);
    expect(lowest).toBeLessThan(-1);
  });

  it('both scenes give the same bits in two runs', () => {
    for (const make of [doubleWeld, () => pinnedGrid(4)]) {
      const a = make();
      const b = make();
      run(a, 90);
      run(b, 90);
      expect(snapshot(b.world)).toEqual(snapshot(a.world));
    }
  });
});
