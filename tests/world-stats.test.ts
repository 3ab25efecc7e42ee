/**
 * `world.stats`: what a world holds and what its last sub-step did, counted through the public
 * interface (issue 19 asks for counters in place of tests' casts into private fields), and adding
 * bodies in linear time (the list is no longer copied on every add).
 */
import { describe, expect, it } from 'vitest';
import { Body, HalfSpace, HyperBox, HyperSphere, PointJoint, World, dims } from '@physin/engine';

describe('world.stats', () => {
  it('counts bodies, awake bodies, joints, pairs, contacts, points and solver passes', () => {
    const D = dims(3);
    const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
    expect(world.stats).toEqual({
      bodies: 0,
      awakeBodies: 0,
      islands: 0,
      bodiesVisited: 0,
      pairsVisited: 0,
      joints: 0,
      pairs: 0,
      contacts: 0,
      touching: 0,
      contactPoints: 0,
      solverPasses: 0,
      stretchedJoints: 0,
    });
    world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
    const boxes = [0, 1, 2].map((i) =>
      world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5 + i, 0] })),
    );
    const ball = world.addBody(new Body(D, { shape: HyperSphere(D, 0.2), mass: 1, position: [5, 3, 0] }));
    world.addConstraint(new PointJoint(ball, null, [0, 0.5, 0], [5, 3.5, 0]));
    world.step(1 / 60);
    const s = world.stats;
    expect(s.bodies).toBe(5);
    expect(s.awakeBodies).toBe(4);
    // The stack of three boxes, and the ball on its joint to the world.
    expect(s.islands).toBe(2);
    expect(s.joints).toBe(1);
    // Floor–box, box–box, box–box: three pairs, each touching, four points a face.
    expect(s.pairs).toBe(3);
    expect(s.contacts).toBe(3);
    expect(s.touching).toBe(3);
    expect(s.contactPoints).toBe(12);
    expect(s.solverPasses).toBeGreaterThanOrEqual(1);
    expect(s.solverPasses).toBeLessThanOrEqual(world.params.iterations);
    expect(Object.isFrozen(s)).toBe(true);
    for (let i = 0; i < 240; i += 1) world.step(1 / 60);
    // The column sleeps, and so does the ball, hanging at rest below its pin.
    expect(world.stats.awakeBodies).toBe(0);
    // Waking one box wakes its island at once: the column (the ball hangs apart).
    boxes[2]!.wake();
    expect(world.stats.awakeBodies).toBe(3);
  });

  it('bodies is one frozen list until the world changes, then a new one; removal by index', () => {
    const D = dims(2);
    const world = new World({ dimensions: 2 });
    const bodies = Array.from({ length: 2000 }, (_, i) =>
      world.addBody(new Body(D, { shape: HyperSphere(D, 0.1), mass: 1, position: [i, 0] })),
    );
    const list = world.bodies;
    expect(world.bodies).toBe(list);
    expect(Object.isFrozen(list)).toBe(true);
    expect(list).toEqual(bodies);
    world.removeBody(bodies[7]!);
    expect(world.bodies).not.toBe(list);
    expect(world.bodies.length).toBe(1999);
    expect(world.bodies[7]).toBe(bodies[8]);
    expect(() => world.removeBody(bodies[7]!)).toThrow(/not in this world/);
    for (const body of bodies.slice(1000)) world.removeBody(body);
    expect(world.bodies).toEqual(bodies.slice(0, 1000).filter((_, i) => i !== 7));
    world.bodies.forEach((b, i) => expect(world.bodies[i]).toBe(b));
  });

  it('removing bodies from the front, the middle and the back keeps the order, and the world steps on', () => {
    const D = dims(3);
    const make = (): { world: World; balls: Body[] } => {
      const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
      world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
      const balls = Array.from({ length: 30 }, (_, i) =>
        world.addBody(
          new Body(D, { shape: HyperSphere(D, 0.25), mass: 1, position: [i % 5, 0.25 + Math.floor(i / 5) * 0.5, 0] }),
        ),
      );
      return { world, balls };
    };
    const a = make();
    const b = make();
    for (let s = 0; s < 30; s += 1) {
      a.world.step(1 / 60);
      b.world.step(1 / 60);
    }
    // a closes each hole at once (reading world.bodies compacts the list after every removal);
    // b leaves all five holes for the next step to close in one pass: the same world either way.
    const gone = [0, 29, 14, 15, 3];
    for (const i of gone) {
      a.world.removeBody(a.balls[i]!);
      expect(a.world.bodies.includes(a.balls[i]!)).toBe(false);
    }
    for (const i of gone) b.world.removeBody(b.balls[i]!);
    const kept = (balls: Body[]): Body[] => balls.filter((_, i) => !gone.includes(i));
    expect(a.world.bodies.slice(1)).toEqual(kept(a.balls));
    expect(a.world.bodies.map((body) => body.worldIndex)).toEqual(a.world.bodies.map((_, i) => i));
    for (let s = 0; s < 60; s += 1) {
      a.world.step(1 / 60);
      b.world.step(1 / 60);
    }
    expect(a.world.bodies.flatMap((body) => [...body.x])).toEqual(b.world.bodies.flatMap((body) => [...body.x]));
    expect(a.world.stats.bodies).toBe(26);
  });
});
