/**
 * Early exit of the contact solver (`Params.solverTolerance`): once a pass changes no contact
 * row's velocity by more than the tolerance, the passes left are skipped. A resting stack then
 * costs a pass or two per sub-step instead of `iterations`, and ends where the full count of
 * passes puts it. n = 2..6.
 */
import { describe, expect, it } from 'vitest';
import type { Body, World } from '@physin/engine';
import type { ContactSolver } from '../packages/engine/src/solver/contact-solver.js';
import { addBox, addGround, addStack, axis, makeWorld, run } from './support/scenes.js';

const DIMS = [2, 3, 4, 5, 6];
const HALF = 0.5;

function solverOf(world: World): ContactSolver {
  return (world as unknown as { solver: ContactSolver }).solver;
}

function stack(n: number, solverTolerance: number): [World, Body[]] {
  const world = makeWorld(n, { solverTolerance });
  addGround(world, { friction: 0.5 });
  return [world, addStack(world, 3, HALF, { friction: 0.5 })];
}

describe('solverTolerance: the passes stop once they change nothing', () => {
  for (const n of DIMS) {
    it(`n = ${n}: a resting stack of 3 runs few passes, and ends within 1e-9 of the full count`, () => {
      const [fast, boxes] = stack(n, 1e-9);
      const [full, fullBoxes] = stack(n, 0);
      let fewest = Infinity;
      let most = 0;
      run(fast, 300, 1 / 60, (s) => {
        if (s <= 60) return; // settling
        const passes = solverOf(fast).passesRun;
        fewest = Math.min(fewest, passes);
        most = Math.max(most, passes);
      });
      run(full, 300);
      expect(most).toBeLessThan(10); // the default iterations: never all of them once at rest
      expect(fewest).toBeLessThanOrEqual(3);
      for (let i = 0; i < boxes.length; i += 1) {
        for (let d = 0; d < n; d += 1) expect(Math.abs(boxes[i]!.x[d]! - fullBoxes[i]!.x[d]!)).toBeLessThan(1e-9);
      }
    });
  }

  it('n = 3: a box sliding on the ground takes more than one pass while its friction works', () => {
    const world = makeWorld(3, { solverTolerance: 1e-9 });
    addGround(world, { friction: 0.2 });
    const box = addBox(world, axis(3, 1, HALF), HALF, { material: { friction: 0.2 }, velocity: axis(3, 0, 2) });
    const passes: number[] = [];
    run(world, 20, 1 / 60, () => passes.push(solverOf(world).passesRun));
    expect(box.v[0]!).toBeGreaterThan(1); // still sliding
    expect(Math.max(...passes)).toBeGreaterThan(1);
  });

  it('n = 3: a huge tolerance runs one pass per sub-step, and a stack then sinks: the exit is taken', () => {
    const [loose] = stack(3, 1e3);
    const [strict, strictBoxes] = stack(3, 1e-9);
    const looseBoxes = loose.bodies.filter((b) => b.name?.startsWith('box'));
    run(loose, 120, 1 / 60, () => expect(solverOf(loose).passesRun).toBe(1));
    run(strict, 120);
    let apart = 0;
    for (let i = 0; i < 3; i += 1) apart = Math.max(apart, Math.abs(looseBoxes[i]!.x[1]! - strictBoxes[i]!.x[1]!));
    expect(apart).toBeGreaterThan(1e-6);
  });
});
