/**
 * Sleep and collision events of World.step:
 * - a settled pile sleeps as a whole (velocities exactly zero, the state frozen); a ray cast
 *   finds a sleeping body without waking it; an impulse wakes its island and not a pile far away;
 *   a box dropped on a sleeping pile wakes it; removing the box under a sleeping one wakes it and
 *   it falls (its touching pairs end in the next step's events); allowSleep false keeps every
 *   body awake;
 * - a ball dropped on the ground: one begin event (normal along the ground normal, point at the
 *   ground, impulse > 0), an end event when it bounces off; body listeners get the right other
 *   body and a normal from themselves to it; removeEventListener stops the calls.
 */
import { describe, expect, it } from 'vitest';
import { Body, dims, HalfSpace, HyperBox, HyperSphere, World, castRay, queryBox } from '@physin/engine';
import type { CollisionEvent } from '@physin/engine';

const G = 9.81;
const H = 1 / 60;

function at(n: number, values: Record<number, number>): number[] {
  const p = new Array<number>(n).fill(0);
  for (const [k, v] of Object.entries(values)) p[Number(k)] = v;
  return p;
}

function makeWorld(n: number, params: Record<string, unknown> = {}): { world: World; ground: Body } {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: at(n, { 1: -G }), params });
  const ground = world.addBody(
    new Body(D, {
      shape: HalfSpace(D, at(n, { 1: 1 }), 0),
      mass: 0,
      material: { friction: 0.6, restitution: 0 },
      name: 'ground',
    }),
  );
  return { world, ground };
}

/** A stack of `count` cubes (half side 0.25) at horizontal position x0, slightly apart; returns them bottom first. */
function stack(world: World, x0: number, count: number, name: string): Body[] {
  const D = world.D;
  const n = world.n;
  const out: Body[] = [];
  for (let i = 0; i < count; i += 1) {
    out.push(
      world.addBody(
        new Body(D, {
          shape: HyperBox(D, new Array(n).fill(0.25)),
          mass: 1,
          position: at(n, { 0: x0, 1: 0.26 + 0.52 * i }),
          material: { friction: 0.6, restitution: 0 },
          name: `${name}${i}`,
        }),
      ),
    );
  }
  return out;
}

function run(world: World, seconds: number, each?: (step: number) => void): void {
  const steps = Math.round(seconds / H);
  for (let i = 0; i < steps; i += 1) {
    world.step(H);
    each?.(i);
  }
}

function allZero(a: ArrayLike<number>): boolean {
  for (let i = 0; i < a.length; i += 1) if (a[i] !== 0) return false;
  return true;
}

function state(b: Body): number[] {
  return [...b.x, ...b.R, ...b.v, ...b.L, ...b.w];
}

// ---------------------------------------------------------------------------------------------

describe('sleep', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a stack of 3 cubes settles and sleeps as a whole within 4 s; v, L, ω exactly 0; asleep the state does not change (bit-exact over 1 s)`, () => {
      const { world } = makeWorld(n);
      const boxes = stack(world, 0, 3, 'b');
      let firstAllAsleep = -1;
      run(world, 4, (i) => {
        if (firstAllAsleep < 0 && boxes.every((b) => b.isSleeping)) firstAllAsleep = i;
        // one island: never some of it asleep while the rest is awake
        const asleep = boxes.filter((b) => b.isSleeping).length;
        expect(asleep === 0 || asleep === boxes.length).toBe(true);
      });
      expect(firstAllAsleep).toBeGreaterThan(0);
      // it cannot sleep before it has been still for sleepTime (0.6 s)
      expect((firstAllAsleep + 1) * H).toBeGreaterThanOrEqual(0.6);
      for (const b of boxes) {
        expect(b.isSleeping).toBe(true);
        expect(allZero(b.v) && allZero(b.L) && allZero(b.w)).toBe(true);
      }
      // stacked where they should be (top of the stack at 5 half sides)
      expect(Math.abs(boxes[2]!.x[1]! - 1.25)).toBeLessThanOrEqual(0.005 * 3 + 1e-3);
      const before = boxes.map(state);
      run(world, 1);
      expect(boxes.map(state)).toEqual(before);
      expect(boxes.every((b) => b.isSleeping)).toBe(true);
    });
  }

  it('allowSleep false: the same stack stays awake for 6 s (every step), and still rests at the same place', () => {
    const { world } = makeWorld(3, { allowSleep: false });
    const boxes = stack(world, 0, 3, 'b');
    run(world, 6, () => {
      for (const b of boxes) expect(b.isSleeping).toBe(false);
    });
    expect(Math.abs(boxes[2]!.x[1]! - 1.25)).toBeLessThanOrEqual(0.005 * 3 + 1e-3);
  });

  it('a ray cast that hits a sleeping body returns it and does not wake it (nor any other body)', () => {
    const { world } = makeWorld(3);
    const boxes = stack(world, 0, 3, 'b');
    run(world, 4);
    expect(boxes.every((b) => b.isSleeping)).toBe(true);
    const top = boxes[2]!;
    const hit = castRay(world, [0, 5, 0], [0, -1, 0], 10);
    expect(hit).not.toBeNull();
    expect(hit!.body).toBe(top);
    expect(Math.abs(hit!.distance - (5 - (top.x[1]! + 0.25)))).toBeLessThanOrEqual(1e-9);
    const side = castRay(world, [-3, boxes[0]!.x[1]!, 0], [1, 0, 0], 10);
    expect(side!.body).toBe(boxes[0]);
    const found = queryBox(world, [-1, -1, -1], [1, 2, 1]);
    expect(found.length).toBe(4);
    for (const b of boxes) expect(b.isSleeping).toBe(true);
    const before = boxes.map(state);
    world.step(H);
    for (const b of boxes) expect(b.isSleeping).toBe(true);
    expect(boxes.map(state)).toEqual(before);
  });

  for (const n of [3, 4]) {
    it(`n = ${n}: an impulse on one box wakes its island (the boxes it touches) at the next step, but not a sleeping pile 10 m away on the same ground`, () => {
      const { world, ground } = makeWorld(n);
      const near = stack(world, 0, 3, 'near');
      const far = stack(world, 10, 3, 'far');
      run(world, 4);
      expect([...near, ...far].every((b) => b.isSleeping)).toBe(true);
      const farBefore = far.map(state);
      near[2]!.applyCentralImpulse(at(n, { 0: 0.3 }));
      expect(near[2]!.isSleeping).toBe(false); // the impulse wakes the body at once
      world.step(H);
      for (const b of near) expect(b.isSleeping).toBe(false);
      for (const b of far) expect(b.isSleeping).toBe(true);
      expect(ground.isSleeping).toBe(false);
      // the far pile stays asleep and untouched while the near one moves
      run(world, 0.5);
      for (const b of far) expect(b.isSleeping).toBe(true);
      expect(far.map(state)).toEqual(farBefore);
    });
  }

  for (const n of [3, 4]) {
    it(`n = ${n}: removing the bottom box of a sleeping stack wakes the boxes above, which fall and rest on the ground (centres 0.25 and 0.75 within 0.01); the touching pairs end in the next step's events (not appended to the last step's); a far pile sleeps on`, () => {
      const { world, ground } = makeWorld(n);
      const near = stack(world, 0, 3, 'near');
      const far = stack(world, 10, 3, 'far');
      run(world, 4);
      expect([...near, ...far].every((b) => b.isSleeping)).toBe(true);
      const [bottom, middle, top] = near as [Body, Body, Body];
      const heard: string[] = [];
      middle.addEventListener('collision', (e: CollisionEvent) => heard.push(`${e.type} ${e.other.name}`));
      const endsBefore = world.contactEvents.endCount;
      world.removeBody(bottom);
      // The last step's list is what it was; the bodies that touched the removed one are awake.
      expect(world.contactEvents.endCount).toBe(endsBefore);
      expect(middle.isSleeping).toBe(false);
      world.step(H);
      const ev = world.contactEvents;
      const ends = new Set<string>();
      for (let i = 0; i < ev.endCount; i += 1) ends.add([ev.endA[i]!.name, ev.endB[i]!.name].sort().join('-'));
      expect(ends).toEqual(new Set(['ground-near0', 'near0-near1']));
      expect(heard).toEqual(['end near0']);
      expect(top.isSleeping).toBe(false); // its island woke with the middle box
      run(world, 3);
      expect(Math.abs(middle.x[1]! - 0.25)).toBeLessThan(0.01);
      expect(Math.abs(top.x[1]! - 0.75)).toBeLessThan(0.01);
      for (const b of far) expect(b.isSleeping).toBe(true);
      expect(ground.isSleeping).toBe(false);
      // the end is reported once: no further end events of the removed body
      world.step(H);
      for (let i = 0; i < world.contactEvents.endCount; i += 1) {
        expect([world.contactEvents.endA[i], world.contactEvents.endB[i]]).not.toContain(bottom);
      }
    });
  }

  for (const n of [3, 4]) {
    it(`n = ${n}: a box dropped on a sleeping pile wakes the pile when it lands, not before; later everything sleeps again`, () => {
      const { world } = makeWorld(n);
      const pile = stack(world, 0, 2, 'pile');
      run(world, 4);
      expect(pile.every((b) => b.isSleeping)).toBe(true);
      const D = world.D;
      const dropY = 3;
      const box = world.addBody(
        new Body(D, {
          shape: HyperBox(D, new Array(n).fill(0.25)),
          mass: 1,
          position: at(n, { 1: dropY }),
          material: { friction: 0.6, restitution: 0 },
          name: 'dropped',
        }),
      );
      // top of the pile at 1.0; the box's bottom reaches it after falling dropY − 0.25 − 1.0
      let wokeAt = -1;
      let touchedAt = -1;
      run(world, 2, (i) => {
        if (wokeAt < 0 && pile.some((b) => !b.isSleeping)) wokeAt = i;
        if (touchedAt < 0 && world.contactEvents.beginCount > 0) touchedAt = i;
      });
      const fall = dropY - 0.25 - 1.0;
      const tLand = Math.sqrt((2 * fall) / G);
      expect(wokeAt).toBeGreaterThanOrEqual(0);
      expect(touchedAt).toBeGreaterThanOrEqual(0);
      expect(Math.abs(wokeAt * H - tLand)).toBeLessThanOrEqual(3 * H);
      expect(Math.abs(wokeAt - touchedAt)).toBeLessThanOrEqual(1);
      run(world, 4);
      expect([...pile, box].every((b) => b.isSleeping)).toBe(true);
      expect(Math.abs(box.x[1]! - 1.25)).toBeLessThanOrEqual(0.005 * 3 + 1e-3);
    });
  }
});

// ---------------------------------------------------------------------------------------------

interface Seen {
  type: 'begin' | 'end';
  body: Body;
  other: Body;
  point: number[];
  normal: number[];
  impulse: number;
  step: number;
}

describe('collision events', () => {
  for (const n of [2, 3, 4]) {
    it(`n = ${n}: a ball dropped on the ground: one begin (normal ±e_y from A to B, point at the ground within contactMargin, impulse > 0), an end when it bounces off (restitution 0.8), then a second begin`, () => {
      const { world, ground } = makeWorld(n, { allowSleep: false });
      const D = world.D;
      const rho = 0.3;
      const x0 = at(n, { 0: 0.4, 1: 1.5 });
      if (n > 2) x0[2] = -0.2;
      const ball = world.addBody(
        new Body(D, {
          shape: HyperSphere(D, rho),
          mass: 2,
          position: x0,
          material: { friction: 0.5, restitution: 0.8 },
          name: 'ball',
        }),
      );
      const begins: { step: number; A: Body; B: Body; point: number[]; normal: number[]; impulse: number }[] = [];
      const ends: { step: number; A: Body; B: Body }[] = [];
      for (let i = 0; i < 120; i += 1) {
        world.step(H);
        const ev = world.contactEvents;
        for (let e = 0; e < ev.beginCount; e += 1) {
          begins.push({
            step: i,
            A: ev.beginA[e]!,
            B: ev.beginB[e]!,
            point: Array.from(ev.beginPoint.subarray(e * n, e * n + n)),
            normal: Array.from(ev.beginNormal.subarray(e * n, e * n + n)),
            impulse: ev.beginImpulse[e]!,
          });
        }
        for (let e = 0; e < ev.endCount; e += 1) ends.push({ step: i, A: ev.endA[e]!, B: ev.endB[e]! });
      }
      expect(begins.length).toBeGreaterThanOrEqual(2);
      expect(ends.length).toBeGreaterThanOrEqual(1);
      const first = begins[0]!;
      // the first begin comes when the ball reaches the ground: t = sqrt(2 (1.5 − ρ) / g)
      const tHit = Math.sqrt((2 * (1.5 - rho)) / G);
      expect(Math.abs((first.step + 1) * H - tHit)).toBeLessThanOrEqual(2 * H);
      expect(new Set([first.A, first.B])).toEqual(new Set([ground, ball]));
      const sign = first.A === ground ? 1 : -1; // from A to B: up when the ground is A
      for (let k = 0; k < n; k += 1) expect(Math.abs(first.normal[k]! - (k === 1 ? sign : 0))).toBeLessThanOrEqual(1e-12);
      expect(Math.abs(first.point[1]!)).toBeLessThanOrEqual(0.02);
      for (let k = 0; k < n; k += 1) if (k !== 1) expect(Math.abs(first.point[k]! - x0[k]!)).toBeLessThanOrEqual(1e-9);
      expect(first.impulse).toBeGreaterThan(0);
      // The pair touches from the sub-step in which a speculative contact stops the ball at the
      // surface (gap < contactMargin); that stop removes part of the momentum and the bounce
      // follows in the next sub-step, so the impulse of the first touching sub-step is at most
      // the whole bounce, m (1 + e) |v| with v = g t at the hit (+ one step of g).
      expect(first.impulse).toBeLessThanOrEqual(2 * 1.8 * G * (tHit + 2 * H));
      // the end follows the first begin, for the same pair, and the ball then rose again
      const end = ends[0]!;
      expect(end.step).toBeGreaterThan(first.step);
      expect(new Set([end.A, end.B])).toEqual(new Set([ground, ball]));
      expect(begins[1]!.step).toBeGreaterThan(end.step);
      // between the first begin and the first end exactly one begin: no chatter
      expect(begins.filter((b) => b.step <= end.step).length).toBe(1);
    });
  }

  it('body listeners: each side gets the other body, the normal from itself to the other, the same point and impulse; end events too; removeEventListener stops the calls', () => {
    const n = 3;
    const { world, ground } = makeWorld(n, { allowSleep: false });
    const D = world.D;
    const ball = world.addBody(
      new Body(D, {
        shape: HyperSphere(D, 0.3),
        mass: 1,
        position: [0.1, 1.2, 0.2],
        material: { friction: 0.5, restitution: 0.9 },
        name: 'ball',
      }),
    );
    const box = world.addBody(
      new Body(D, {
        shape: HyperBox(D, [0.5, 0.25, 0.5]),
        mass: 1,
        position: [5, 0.26, 0],
        material: { friction: 0.5, restitution: 0 },
        name: 'box',
      }),
    );
    const seenBall: Seen[] = [];
    const seenGround: Seen[] = [];
    let step = 0;
    const copy =
      (into: Seen[]) =>
      (e: CollisionEvent): void => {
        into.push({
          type: e.type,
          body: e.body,
          other: e.other,
          point: Array.from(e.point),
          normal: Array.from(e.normal),
          impulse: e.impulse,
          step,
        });
      };
    const onBall = copy(seenBall);
    const onGround = copy(seenGround);
    ball.addEventListener('collision', onBall);
    ground.addEventListener('collision', onGround);
    for (step = 0; step < 90; step += 1) world.step(H);

    const ballBegins = seenBall.filter((s) => s.type === 'begin' && s.other === ground);
    const ballEnds = seenBall.filter((s) => s.type === 'end');
    expect(ballBegins.length).toBeGreaterThanOrEqual(1);
    expect(ballEnds.length).toBeGreaterThanOrEqual(1);
    for (const s of seenBall) {
      expect(s.body).toBe(ball);
      expect(s.other).toBe(ground);
    }
    // the ground hears about the ball and about the box (which touches it at the start)
    expect(seenGround.every((s) => s.body === ground)).toBe(true);
    expect(seenGround.some((s) => s.other === box && s.type === 'begin')).toBe(true);
    const groundBegins = seenGround.filter((s) => s.type === 'begin' && s.other === ball);
    expect(groundBegins.length).toBe(ballBegins.length);
    for (let i = 0; i < ballBegins.length; i += 1) {
      const a = ballBegins[i]!;
      const g = groundBegins[i]!;
      expect(a.step).toBe(g.step);
      // from the ball to the ground: down; from the ground to the ball: up
      expect(a.normal[1]).toBe(-1);
      expect(g.normal[1]).toBe(1);
      for (let k = 0; k < n; k += 1) {
        expect(a.normal[k]).toBe(-g.normal[k]!);
        expect(a.point[k]).toBe(g.point[k]);
      }
      expect(a.impulse).toBe(g.impulse);
      expect(a.impulse).toBeGreaterThan(0);
      expect(a.point[0]).toBeCloseTo(0.1, 9);
      expect(a.point[2]).toBeCloseTo(0.2, 9);
    }
    // the end events carry zeros
    for (const s of ballEnds) {
      expect(s.impulse).toBe(0);
      expect(s.normal.every((x) => x === 0)).toBe(true);
    }
    // the events match world.contactEvents: here checked by count over a fresh listener run
    ball.removeEventListener('collision', onBall);
    const count = seenBall.length;
    const groundCount = seenGround.length;
    let worldEvents = 0;
    ball.setPositionN([0.1, 1.2, 0.2]); // drop it again
    ball.setLinearVelocity([0, 0, 0]);
    for (step = 90; step < 240; step += 1) {
      world.step(H);
      const ev = world.contactEvents;
      for (let e = 0; e < ev.beginCount; e += 1) if (ev.beginA[e] === ball || ev.beginB[e] === ball) worldEvents += 1;
      for (let e = 0; e < ev.endCount; e += 1) if (ev.endA[e] === ball || ev.endB[e] === ball) worldEvents += 1;
    }
    expect(worldEvents).toBeGreaterThan(0); // the ball landed again
    expect(seenBall.length).toBe(count); // but its removed listener heard nothing
    expect(seenGround.length - groundCount).toBe(worldEvents); // the ground's listener still hears each one
    // removing a listener that is not there is no error; a bad type is
    expect(() => ball.removeEventListener('collision', onBall)).not.toThrow();
    expect(() => ball.addEventListener('contact' as 'collision', onBall)).toThrow(TypeError);
  });

  it('two balls that collide in the air: each listener gets the other ball and a normal along the line of centres, from itself', () => {
    const n = 4;
    const D = dims(n);
    const world = new World({ dimensions: n, params: { allowSleep: false } });
    const a = world.addBody(
      new Body(D, {
        shape: HyperSphere(D, 0.5),
        mass: 1,
        position: [-1, 0, 0, 0],
        velocity: [2, 0, 0, 0],
        material: { restitution: 1 },
        name: 'a',
      }),
    );
    const b = world.addBody(
      new Body(D, {
        shape: HyperSphere(D, 0.5),
        mass: 1,
        position: [1, 0, 0, 0],
        velocity: [-2, 0, 0, 0],
        material: { restitution: 1 },
        name: 'b',
      }),
    );
    const got: Seen[] = [];
    const listener = (e: CollisionEvent): void => {
      got.push({
        type: e.type,
        body: e.body,
        other: e.other,
        point: Array.from(e.point),
        normal: Array.from(e.normal),
        impulse: e.impulse,
        step: 0,
      });
    };
    a.addEventListener('collision', listener);
    b.addEventListener('collision', listener);
    run(world, 1);
    const begins = got.filter((s) => s.type === 'begin');
    expect(begins.length).toBe(2);
    const fromA = begins.find((s) => s.body === a)!;
    const fromB = begins.find((s) => s.body === b)!;
    expect(fromA.other).toBe(b);
    expect(fromB.other).toBe(a);
    const plus0 = (v: number[]): number[] => v.map((x) => x + 0); // −0 and 0 alike
    expect(plus0(fromA.normal)).toEqual([1, 0, 0, 0]);
    expect(plus0(fromB.normal)).toEqual([-1, 0, 0, 0]);
    expect(Math.abs(fromA.point[0]!)).toBeLessThanOrEqual(0.02);
    expect(fromA.impulse).toBeGreaterThan(0);
    const ends = got.filter((s) => s.type === 'end');
    expect(ends.length).toBe(2); // restitution 1: they bounce apart and stop touching
  });

  it('restitution 1: two equal balls meeting head on (no gravity) leave at their approach speed, whatever the phase of the step at which they meet (|v| = 2 m/s within 1e-6)', () => {
    // the gap at the step before contact differs with the start; the bounce must not
    const n = 3;
    const D = dims(n);
    const speeds: number[] = [];
    for (const start of [1.0, 1.01, 1.03, 1.05, 1.065]) {
      const world = new World({ dimensions: n, params: { allowSleep: false } });
      const a = world.addBody(
        new Body(D, {
          shape: HyperSphere(D, 0.5),
          mass: 1,
          position: [-start, 0, 0],
          velocity: [2, 0, 0],
          material: { restitution: 1 },
        }),
      );
      const b = world.addBody(
        new Body(D, {
          shape: HyperSphere(D, 0.5),
          mass: 1,
          position: [start, 0, 0],
          velocity: [-2, 0, 0],
          material: { restitution: 1 },
        }),
      );
      run(world, 1);
      // momentum is conserved in every case
      expect(Math.abs(a.v[0]! + b.v[0]!)).toBeLessThanOrEqual(1e-9);
      speeds.push(b.v[0]!);
    }
    for (const v of speeds)
      expect(Math.abs(v - 2), `exit speeds ${speeds.map((x) => x.toFixed(4)).join(', ')}`).toBeLessThanOrEqual(1e-6);
  });

  it('restitution 0.8: a ball dropped on the ground leaves it at e·|v_in| and rises to e²·drop (±10%), whatever the phase of the step at impact (drops 1.2, 1.22, 1.25, 1.3 m)', () => {
    const rises: number[] = [];
    const ratios: number[] = [];
    for (const drop of [1.2, 1.22, 1.25, 1.3]) {
      const { world } = makeWorld(3, { allowSleep: false });
      const rho = 0.3;
      const ball = world.addBody(
        new Body(world.D, {
          shape: HyperSphere(world.D, rho),
          mass: 2,
          position: [0, drop + rho, 0],
          material: { friction: 0.5, restitution: 0.8 },
        }),
      );
      let up = false;
      let top = -Infinity;
      for (let i = 0; i < 90; i += 1) {
        world.step(H);
        if (ball.v[1]! > 0) up = true;
        if (up && ball.v[1]! <= 0) break;
        if (up) top = Math.max(top, ball.x[1]!);
      }
      rises.push(top - rho);
      ratios.push((top - rho) / (0.64 * drop));
    }
    // (the ratios are reported in the message when this fails)
    for (const ratio of ratios)
      expect(ratio, `rise / (e² drop) = ${ratios.map((x) => x.toFixed(3)).join(', ')}`).toBeGreaterThanOrEqual(0.9);
    for (const ratio of ratios) expect(ratio).toBeLessThanOrEqual(1.1);
    expect(rises.length).toBe(4);
  });
});
