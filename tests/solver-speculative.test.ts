/**
 * Speculative contacts without ghosts (issue 17): a body flying past an edge is not touched, at
 * any speed, and a fast body still never passes a thin wall.
 *
 * A speculative point asks vn ≥ −gap/h along its normal; read linearly, that closes the gap of a
 * ball flying past a wall's edge long before the ball gets there, and used to slow it and kick it
 * up (10 m/s, 5 cm above the edge) or halve its speed (50 m/s, 10 cm). The contact set now sweeps
 * such a manifold along the relative velocity and drops it when the bodies do not meet in the
 * sub-step (docs/solver.md, Speculative contacts). No gravity in the fly-bys and walls; sleep off;
 * dt = 1/60, one sub-step (the defaults).
 */
import { describe, expect, it } from 'vitest';
import { Body, HyperBox } from '@physin/engine';
import { addBall, addGround, axis, makeWorld, run } from './support/scenes.js';

const verbose = (s: string): void => {
  if (process.env.PHYSIN_VERBOSE) console.log(s);
};

/**
 * A static wall (x half-width 0.05, top at y = 1, 2 m wide in the other axes) and a ball of radius
 * 0.1 flying along +x at `speed`, `clearance` above the top, from x = −3 to past the wall.
 */
function flyBy(n: number, speed: number, clearance: number): { v: number[]; begins: number; passed: boolean } {
  const world = makeWorld(n, {}, 0);
  const D = world.D;
  const half = new Array<number>(n).fill(1);
  half[0] = 0.05;
  half[1] = 0.5;
  world.addBody(new Body(D, { shape: HyperBox(D, half), mass: 0, position: axis(n, 1, 0.5), name: 'wall' }));
  const r = 0.1;
  const start = axis(n, 1, 1 + clearance + r);
  start[0] = -3;
  const ball = addBall(world, start, r, { velocity: axis(n, 0, speed) });
  let begins = 0;
  ball.addEventListener('collision', (e) => {
    if (e.type === 'begin') begins += 1;
  });
  run(world, Math.ceil((6 / speed) * 60) + 5);
  return { v: Array.from(ball.v), begins, passed: ball.x[0]! > 1 };
}

describe('no ghost collision: a ball flying past a wall’s edge keeps its velocity', () => {
  for (const n of [3, 4]) {
    for (const [speed, clearance] of [
      [10, 0.05],
      [50, 0.1],
      [200, 0.01],
    ] as const) {
      it(`n = ${n}: ${speed} m/s, ${clearance * 100} cm above the edge: velocity unchanged to 1e-12 m/s, no begin event`, () => {
        const { v, begins, passed } = flyBy(n, speed, clearance);
        const want = axis(n, 0, speed);
        const error = Math.max(...v.map((x, d) => Math.abs(x - want[d]!)));
        verbose(
          `fly-by n=${n} ${speed} m/s ${clearance} m: v ${v.join(', ')}, error ${error.toExponential(2)}, begins ${begins}`,
        );
        expect(passed).toBe(true);
        expect(error).toBeLessThan(1e-12);
        expect(begins).toBe(0);
      });
    }
  }
});

describe('no tunnelling: a 0.1 m ball at 200 m/s never passes a 0.1 m wall', () => {
  // The wall is 0.1 m thick in x (half-width 0.05) and 2 m in every other axis; the ball (radius
  // 0.05) starts 3 m before it. It moves 3.33 m a step: more than the wall and itself together.
  for (const n of [3, 4]) {
    for (const free of [false, true]) {
      it(`n = ${n}, ${free ? 'a free wall of 1 kg' : 'a static wall'}: the ball's centre never gets past the wall's near face − r + 1e-9`, () => {
        const world = makeWorld(n, {}, 0);
        const D = world.D;
        const half = new Array<number>(n).fill(1);
        half[0] = 0.05;
        const wall = world.addBody(
          new Body(D, { shape: HyperBox(D, half), mass: free ? 1 : 0, position: axis(n, 0, 0), name: 'wall' }),
        );
        const ball = addBall(world, axis(n, 0, -3), 0.05, { velocity: axis(n, 0, 200) });
        let worst = -Infinity;
        run(world, 120, 1 / 60, () => {
          worst = Math.max(worst, ball.x[0]! - (wall.x[0]! - 0.05 - 0.05));
        });
        verbose(`wall n=${n} free=${free}: deepest ${worst.toExponential(3)} m; ball v ${ball.v[0]}, wall v ${wall.v[0]}`);
        expect(worst).toBeLessThan(1e-9);
        // The ball ends on the near side of the wall and moving with it (restitution 0).
        expect(ball.x[0]!).toBeLessThan(wall.x[0]!);
        if (free) expect(Math.abs(ball.v[0]! - 100)).toBeLessThan(1e-9);
        else expect(Math.abs(ball.v[0]!)).toBeLessThan(1e-9);
      });
    }
  }
});

describe('a ball landing fast still stops at the surface', () => {
  for (const n of [3, 4]) {
    for (const floor of ['half-space', 'static box'] as const) {
      it(`n = ${n}, on a ${floor}: a ball of radius 0.1 at 100 m/s down stops without passing (lowest point ≥ −penetrationSlop), at rest after 1 s`, () => {
        const world = makeWorld(n);
        const D = world.D;
        if (floor === 'half-space') addGround(world);
        else {
          const half = new Array<number>(n).fill(2);
          half[1] = 0.05;
          world.addBody(new Body(D, { shape: HyperBox(D, half), mass: 0, position: axis(n, 1, -0.05), name: 'floor' }));
        }
        const ball = addBall(world, axis(n, 1, 5), 0.1, { velocity: axis(n, 1, -100) });
        let lowest = Infinity;
        run(world, 60, 1 / 60, () => {
          lowest = Math.min(lowest, ball.x[1]! - 0.1);
        });
        verbose(`landing n=${n} ${floor}: lowest ${lowest.toExponential(3)} m, v ${ball.v[1]}`);
        expect(lowest).toBeGreaterThan(-0.005);
        expect(Math.abs(ball.v[1]!)).toBeLessThan(1e-6);
      });
    }
  }
});
