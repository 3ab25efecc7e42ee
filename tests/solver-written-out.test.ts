/**
 * The written-out manifold solves for n = 3 and n = 4 (ContactSolver3 and ContactSolverND) do the
 * general loop's arithmetic in the same order, so a scene stepped with them and the same scene
 * stepped with the general loop must agree bit for bit — every position, rotor component,
 * velocity and angular momentum, after 240 steps of tumbling, sliding and stacking contact.
 */
import { describe, expect, it } from 'vitest';
import type { Body, World } from '@physin/engine';
import { addBall, addBox, addGround, axis, makeWorld, run } from './support/scenes.js';
import { seeded } from './support/random.js';

/** A seeded heap of boxes and balls dropped spinning onto the ground and onto one another. */
function scene(n: number, writtenOut: boolean): { world: World; bodies: Body[] } {
  const world = makeWorld(n);
  (world as unknown as { solver: { writtenOut: boolean } }).solver.writtenOut = writtenOut;
  addGround(world, { friction: 0.5 });
  const rand = seeded(77 + n);
  const bodies: Body[] = [];
  for (let i = 0; i < 8; i += 1) {
    const p = axis(n, 1, 0.6 + 1.1 * i);
    for (let d = 0; d < n; d += 1) if (d !== 1) p[d] = (rand() - 0.5) * 0.2;
    const velocity = Array.from({ length: n }, () => (rand() - 0.5) * 0.5);
    const b =
      i % 3 === 2
        ? addBall(world, p, 0.4, { velocity })
        : addBox(world, p, 0.5, { velocity, material: { friction: 0.3 + 0.1 * (i % 4) } });
    b.setAngularVelocity(Array.from({ length: world.D.k }, () => (rand() - 0.5) * 2));
    bodies.push(b);
  }
  return { world, bodies };
}

/** Every number of every body's state, in order. */
function state(bodies: Body[]): number[] {
  const out: number[] = [];
  for (const b of bodies) out.push(...b.x, ...b.R, ...b.v, ...b.L);
  return out;
}

describe('written-out manifold solves are bit-identical to the general loop', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: 240 steps of a tumbling heap of boxes and balls give the same bits either way`, () => {
      const fast = scene(n, true);
      const general = scene(n, false);
      run(fast.world, 240);
      run(general.world, 240);
      const a = state(fast.bodies);
      const b = state(general.bodies);
      expect(a.length).toBe(b.length);
      let differ = 0;
      for (let i = 0; i < a.length; i += 1) if (!Object.is(a[i], b[i])) differ += 1;
      expect(differ).toBe(0);
      // The heap did collide: bodies came to rest on one another, not all at the ground's height.
      const heights = fast.bodies.map((body) => body.x[1]!);
      expect(Math.max(...heights)).toBeGreaterThan(1.2);
      expect(fast.world.touchingCount).toBeGreaterThan(4);
    });
  }
});
