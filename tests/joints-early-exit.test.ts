/**
 * Joints: the velocity passes stop early (`Params.solverTolerance`, docs/joints.md "The solver").
 * In a sub-step without contacts, once a joint pass moves no row's velocity by more than the
 * tolerance (|Δλ|·K for a Gauss–Seidel row, the whole right-hand side for a row of the tree's
 * exact solve), the passes left are skipped.
 *
 * - A pinned 8 × 8 joint grid (a spanning tree solved directly, the joints that close its cycles
 *   by Gauss–Seidel blocks): after its first second it runs few passes, its joints stay closed to
 *   rounding, and it ends within 1e-12 m of the grid that runs every pass (tolerance 0).
 * - A chain of 10 (a path, no cycle, nothing but the tree's rows): one pass a sub-step at tolerance
 *   1e-9 and 0 alike (the exact solve leaves nothing for another), the same bits. (That the passes
 *   skipped would change nothing was shown by hashing against the build that ran them all: the
 *   whipping and hanging chains of 10 in 3D and 4D, 600 steps, the same bits; docs/joints.md.)
 * - A joint and a contact in the same sub-step: every pass runs.
 */
import { describe, expect, it } from 'vitest';
import { Body, HyperSphere, PointJoint } from '@physin/engine';
import type { World } from '@physin/engine';
import { addGround, makeWorld, run } from './support/scenes.js';
import { pinnedGrid, snapshot } from './support/joints.js';

function chain(solverTolerance: number): World {
  const world = makeWorld(3, { solverTolerance });
  const D = world.D;
  const shape = HyperSphere(D, 0.1);
  let prev: Body | null = null;
  for (let i = 0; i < 10; i += 1) {
    const body = world.addBody(new Body(D, { shape, mass: 1, position: [i + 0.5, 0, 0] }));
    world.addConstraint(new PointJoint(body, prev, [-0.5, 0, 0], prev === null ? [0, 0, 0] : [0.5, 0, 0]));
    prev = body;
  }
  return world;
}

describe('solverTolerance: the joint passes stop once they move nothing', () => {
  it('a pinned 8 × 8 grid: few passes after its first second, joints closed, within 1e-12 m of every pass', () => {
    const fast = pinnedGrid(8, { solverTolerance: 1e-9 });
    const full = pinnedGrid(8, { solverTolerance: 0 });
    let most = 0;
    let fewest = Infinity;
    let worst = 0;
    let lowest = 0;
    run(fast.world, 180, 1 / 60, (s) => {
      worst = Math.max(worst, fast.error());
      lowest = Math.min(lowest, fast.bodies[63]!.x[1]!);
      if (s <= 60) return;
      most = Math.max(most, fast.world.stats.solverPasses);
      fewest = Math.min(fewest, fast.world.stats.solverPasses);
    });
    let passes = 0;
    run(full.world, 180, 1 / 60, () => (passes = Math.max(passes, full.world.stats.solverPasses)));
    let apart = 0;
    for (let i = 0; i < fast.bodies.length; i += 1) {
      const a = fast.bodies[i]!.x;
      const b = full.bodies[i]!.x;
      for (let d = 0; d < 3; d += 1) apart = Math.max(apart, Math.abs(a[d]! - b[d]!));
    }
    console.log(
      `pinned 8 × 8 grid: passes ${fewest}–${most} (tolerance 0: up to ${passes}), worst joint error ` +
        `${worst.toExponential(2)} m, ${apart.toExponential(2)} m from every pass, corner down to ${lowest.toFixed(2)} m`,
    );
    expect(fewest).toBeLessThanOrEqual(3);
    expect(most).toBeLessThanOrEqual(3); // 2 measured
    expect(worst).toBeLessThan(1e-12); // 3.3e-14 measured
    expect(apart).toBeLessThan(1e-12); // 4.1e-14 measured
    // The grid swung down (its far corner 7 m from the pinned row).
    expect(lowest).toBeLessThan(-6);
  });

  it('a chain of 10: one pass a sub-step at any tolerance (the tree alone), the same bits', () => {
    const fast = chain(1e-9);
    const full = chain(0);
    run(fast, 120, 1 / 60, () => expect(fast.stats.solverPasses).toBe(1));
    run(full, 120);
    expect(snapshot(fast)).toEqual(snapshot(full));
  });

  it('a joint and a contact in one sub-step: every pass runs', () => {
    const world = makeWorld(3, { solverTolerance: 1e-9 });
    addGround(world);
    const D = world.D;
    const shape = HyperSphere(D, 0.5);
    const a = world.addBody(new Body(D, { shape, mass: 1, position: [0, 0.5, 0] }));
    const b = world.addBody(new Body(D, { shape, mass: 1, position: [1.5, 0.5, 0] }));
    world.addConstraint(new PointJoint(a, b, [0.75, 0, 0], [-0.75, 0, 0]));
    run(world, 60);
    expect(world.stats.contactPoints).toBeGreaterThan(0);
    expect(world.stats.solverPasses).toBe(world.params.iterations);
  });
});
