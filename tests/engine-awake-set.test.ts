/**
 * Issue 19, "pay only for awake bodies": a step visits the awake set alone. Counted through the
 * public `world.stats` (`bodiesVisited`, `pairsVisited`), exact numbers, not timings:
 * - a sleeping pile (200 balls in 3D, a small pile in 4D) is not visited: no body, no pair;
 * - waking one body of one island wakes exactly that island's bodies, not a second separate one,
 *   and the step then visits those bodies and their contacts alone;
 * - removing a body in the middle of a sleeping pile wakes what touched it (and its island);
 * - `stats.islands` counts the awake islands: contacts and joints link, a floor does not;
 * - a world that slept and woke steps bit-identically to its restored copy (whose awake set is
 *   built afresh), and the order in which bodies woke changes no bit.
 */
import { describe, expect, it } from 'vitest';
import type { Body as BodyType, Dims } from '@physin/engine';
import { Body, DistanceJoint, HalfSpace, HyperBox, HyperSphere, World, dims, restoreWorld, snapshotWorld } from '@physin/engine';

const DT = 1 / 60;
const R = 0.5;

/** A floor (half-space y ≥ 0) and `count` balls of radius R resting on it, touching in rows along x. */
function ballCarpet(n: number, count: number, perRow: number, origin: number[]): { world: World; balls: BodyType[]; D: Dims } {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: [0, -9.81, ...new Array<number>(n - 2).fill(0)] });
  const up = new Array<number>(n).fill(0);
  up[1] = 1;
  world.addBody(new Body(D, { shape: HalfSpace(D, up, 0), mass: 0 }));
  const balls: BodyType[] = [];
  for (let i = 0; i < count; i += 1) {
    const p = origin.slice();
    p[0] = p[0]! + (i % perRow) * 2 * R;
    p[1] = R;
    // Rows 3R apart: a row is one island (its balls touch), rows do not touch one another.
    p[2] = p[2]! + Math.floor(i / perRow) * 3 * R;
    balls.push(world.addBody(new Body(D, { shape: HyperSphere(D, R), mass: 1, position: p })));
  }
  return { world, balls, D };
}

/** A column of `count` unit boxes on the floor at `at` (x, z): one island. */
function column(world: World, D: Dims, count: number, at: number[]): BodyType[] {
  const n = D.n;
  const out: BodyType[] = [];
  for (let i = 0; i < count; i += 1) {
    const p = at.slice();
    p[1] = 0.5 + i;
    out.push(world.addBody(new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.5)), mass: 1, position: p })));
  }
  return out;
}

function stepUntilAsleep(world: World, limit: number): number {
  for (let s = 0; s < limit; s += 1) {
    world.step(DT);
    if (world.stats.awakeBodies === 0) return s + 1;
  }
  return -1;
}

describe('the awake set: a step visits awake bodies and their contacts alone', () => {
  it('n = 3: a sleeping carpet of 200 balls is not visited (0 bodies, 0 pairs); waking one island wakes exactly it', () => {
    // 10 rows of 20 touching balls: 10 islands.
    const { world, balls, D } = ballCarpet(3, 200, 20, [0, 0, 0]);
    const colA = column(world, D, 3, [-10, 0, 0]);
    const colB = column(world, D, 3, [-20, 0, 0]);
    world.step(DT);
    // Every dynamic body is visited (the static floor is not); every pair has a moving body.
    expect(world.stats.bodiesVisited).toBe(206);
    expect(world.stats.pairsVisited).toBe(world.stats.contacts);
    // 10 rows of balls and 2 columns: the floor links nothing.
    expect(world.stats.islands).toBe(12);
    expect(stepUntilAsleep(world, 600)).toBeGreaterThan(0);
    world.step(DT);
    let s = world.stats;
    expect(s.awakeBodies).toBe(0);
    expect(s.islands).toBe(0);
    expect(s.bodiesVisited).toBe(0);
    expect(s.pairsVisited).toBe(0);
    // The contacts stand, untouched: ball–floor 200, ball–ball 10 × 19, box–floor 2, box–box 4.
    expect(s.contacts).toBe(200 + 190 + 2 + 4);
    expect(s.touching).toBe(200 + 190 + 2 + 4);

    // Wake the top box of column A: its island (column A) wakes at once, nothing else.
    colA[2]!.wake();
    expect(colA.every((b) => !b.isSleeping)).toBe(true);
    expect(colB.every((b) => b.isSleeping)).toBe(true);
    expect(balls.every((b) => b.isSleeping)).toBe(true);
    expect(world.stats.awakeBodies).toBe(3);
    world.step(DT);
    s = world.stats;
    expect(colB.every((b) => b.isSleeping)).toBe(true);
    expect(balls.every((b) => b.isSleeping)).toBe(true);
    expect(s.bodiesVisited).toBe(3);
    expect(s.islands).toBe(1);
    // Floor–box and two box–box contacts.
    expect(s.pairsVisited).toBe(3);

    // Wake one ball in the middle of row 4: its row (20 balls) wakes, the other rows sleep on.
    balls[4 * 20 + 7]!.wake();
    expect(world.stats.awakeBodies).toBe(3 + 20);
    for (let i = 0; i < 200; i += 1) expect(balls[i]!.isSleeping, `ball ${i}`).toBe(Math.floor(i / 20) !== 4);
    world.step(DT);
    s = world.stats;
    expect(s.bodiesVisited).toBe(23);
    expect(s.islands).toBe(2);
    // Row 4: 20 ball–floor and 19 ball–ball contacts; column A: 3.
    expect(s.pairsVisited).toBe(20 + 19 + 3);

    // Everything sleeps again, and a sleeping world stays free.
    expect(stepUntilAsleep(world, 600)).toBeGreaterThan(0);
    for (let i = 0; i < 10; i += 1) {
      world.step(DT);
      expect(world.stats.bodiesVisited).toBe(0);
      expect(world.stats.pairsVisited).toBe(0);
    }
  });

  it('n = 4: a small sleeping pile is not visited; waking one of two columns wakes that column only', () => {
    const { world, balls, D } = ballCarpet(4, 8, 4, [0, 0, 0, 0]);
    const colA = column(world, D, 2, [-6, 0, 0, 0]);
    const colB = column(world, D, 2, [-6, 0, 0, 6]);
    expect(stepUntilAsleep(world, 600)).toBeGreaterThan(0);
    world.step(DT);
    expect(world.stats.bodiesVisited).toBe(0);
    expect(world.stats.pairsVisited).toBe(0);
    colA[0]!.applyCentralImpulse([0, 0.01, 0, 0]);
    expect(colA.every((b) => !b.isSleeping)).toBe(true);
    expect(colB.every((b) => b.isSleeping)).toBe(true);
    expect(balls.every((b) => b.isSleeping)).toBe(true);
    world.step(DT);
    expect(world.stats.bodiesVisited).toBe(2);
    expect(world.stats.pairsVisited).toBe(2);
    expect(colB.every((b) => b.isSleeping)).toBe(true);
    expect(balls.every((b) => b.isSleeping)).toBe(true);
  });

  it('n = 3: removing a ball in the middle of a sleeping row wakes the balls it touched and their row, no other row', () => {
    const { world, balls } = ballCarpet(3, 60, 20, [0, 0, 0]);
    expect(stepUntilAsleep(world, 600)).toBeGreaterThan(0);
    world.removeBody(balls[20 + 10]!);
    expect(balls[20 + 9]!.isSleeping).toBe(false);
    expect(balls[20 + 11]!.isSleeping).toBe(false);
    for (let i = 0; i < 60; i += 1) {
      if (i === 30) continue;
      expect(balls[i]!.isSleeping, `ball ${i}`).toBe(Math.floor(i / 20) !== 1);
    }
    expect(world.stats.awakeBodies).toBe(19);
    world.step(DT);
    expect(world.stats.bodiesVisited).toBe(19);
    // The row is cut in two: balls 20..29 and 31..39.
    expect(world.stats.islands).toBe(2);
    // 19 ball–floor, 17 ball–ball (the row is cut in two).
    expect(world.stats.pairsVisited).toBe(19 + 17);
  });

  it('a world that slept and was woken steps bit-identically to its restored copy', () => {
    const { world, balls, D } = ballCarpet(3, 40, 10, [0, 0, 0]);
    const col = column(world, D, 3, [-6, 0, 0]);
    expect(stepUntilAsleep(world, 600)).toBeGreaterThan(0);
    col[2]!.applyCentralImpulse([0.5, 0, 0]);
    balls[15]!.applyCentralImpulse([0, 0, -0.3]);
    const copy = restoreWorld(snapshotWorld(world));
    for (let s = 0; s < 120; s += 1) {
      world.step(DT);
      copy.step(DT);
    }
    expect(snapshotWorld(copy)).toEqual(snapshotWorld(world));
  });

  it('the order in which bodies woke changes no bit: the awake set is processed by world index', () => {
    const build = (): { world: World; balls: BodyType[]; col: BodyType[] } => {
      const { world, balls, D } = ballCarpet(3, 40, 10, [0, 0, 0]);
      const col = column(world, D, 3, [-6, 0, 0]);
      expect(stepUntilAsleep(world, 600)).toBeGreaterThan(0);
      return { world, balls, col };
    };
    const a = build();
    const b = build();
    expect(snapshotWorld(b.world)).toEqual(snapshotWorld(a.world));
    // The same pushes, in opposite orders.
    a.col[2]!.applyCentralImpulse([0.5, 0, 0]);
    a.balls[35]!.applyCentralImpulse([0, 0, -0.3]);
    a.balls[2]!.applyCentralImpulse([0.2, 0, 0]);
    b.balls[2]!.applyCentralImpulse([0.2, 0, 0]);
    b.balls[35]!.applyCentralImpulse([0, 0, -0.3]);
    b.col[2]!.applyCentralImpulse([0.5, 0, 0]);
    for (let s = 0; s < 120; s += 1) {
      a.world.step(DT);
      b.world.step(DT);
    }
    expect(snapshotWorld(b.world)).toEqual(snapshotWorld(a.world));
  });

  it.each([2, 3, 4, 5, 6])('n = %i: stats.islands counts groups linked by contacts and joints, never through the floor', (n) => {
    const { world } = ballCarpet(n, 0, 1, new Array<number>(n).fill(0));
    const D = dims(n);
    // Three pairs of touching balls along x, 3 m apart: three islands.
    const balls: BodyType[] = [];
    for (let i = 0; i < 6; i += 1) {
      const p = new Array<number>(n).fill(0);
      p[0] = Math.floor(i / 2) * 3 + (i % 2) * 2 * R;
      p[1] = R;
      balls.push(world.addBody(new Body(D, { shape: HyperSphere(D, R), mass: 1, position: p })));
    }
    world.step(DT);
    expect(world.stats.islands).toBe(3);
    // A distance joint between the first and the last pair links them: two islands.
    const zero = new Array<number>(n).fill(0);
    world.addConstraint(new DistanceJoint(balls[0]!, balls[5]!, zero, zero));
    world.step(DT);
    expect(world.stats.islands).toBe(2);
    // A joint to the world links nothing else: still two.
    world.addConstraint(new DistanceJoint(balls[2]!, null, zero, balls[2]!.x));
    world.step(DT);
    expect(world.stats.islands).toBe(2);
  });
});
