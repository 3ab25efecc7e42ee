/**
 * Collision filters and sensors (issue 18): groups and masks on a body, the world's pair filter,
 * and sensor bodies that report overlap and push nothing. n = 2, 3, 4, 5.
 *
 * - A filtered pair never makes a contact: no event, and a falling body passes through the other
 *   as if it were not there (its height follows free fall exactly, bit for bit against a world
 *   without the other body, until it meets what it does collide with).
 * - A sensor reports exactly one begin and one end for a body falling through it, and the body's
 *   motion is bit-identical to the same fall without the sensor.
 * - Groups, masks and the sensor flag survive a snapshot; bad values are refused by name.
 */
import { describe, expect, it } from 'vitest';
import { Body, dims, HalfSpace, HyperBox, HyperSphere, restoreWorld, snapshotWorld, World } from '@physin/engine';
import type { CollisionEvent } from '@physin/engine';

const G = 9.81;
const H = 1 / 60;

function at(n: number, values: Record<number, number>): number[] {
  const p = new Array<number>(n).fill(0);
  for (const [k, v] of Object.entries(values)) p[Number(k)] = v;
  return p;
}

function world(n: number): World {
  return new World({ dimensions: n, gravity: at(n, { 1: -G }) });
}

function floor(w: World, options: Record<string, unknown> = {}): Body {
  const D = w.D;
  return w.addBody(new Body(D, { shape: HalfSpace(D, at(D.n, { 1: 1 }), 0), mass: 0, name: 'floor', ...options }));
}

function ball(w: World, y: number, options: Record<string, unknown> = {}): Body {
  const D = w.D;
  return w.addBody(new Body(D, { shape: HyperSphere(D, 0.25), mass: 1, position: at(D.n, { 1: y }), name: 'ball', ...options }));
}

function events(body: Body): string[] {
  const log: string[] = [];
  body.addEventListener('collision', (e: CollisionEvent) => log.push(`${e.type}:${e.other.name}`));
  return log;
}

const DIMENSIONS = [2, 3, 4, 5];

describe('groups and masks', () => {
  for (const n of DIMENSIONS) {
    it(`n = ${n}: a ball whose mask leaves out the floor's group falls through it in free fall; one that does not rests`, () => {
      const w = world(n);
      floor(w, { collisionGroup: 0b10 });
      const through = ball(w, 1, { collisionMask: ~0b10 >>> 0 });
      const rests = ball(w, 1, { position: at(n, { 0: 3, 1: 1 }) });
      const log = events(through);
      const free = world(n);
      const alone = ball(free, 1);
      for (let i = 0; i < 120; i += 1) {
        w.step(H);
        free.step(H);
        expect(through.x[1]).toBe(alone.x[1]);
      }
      expect(through.x[1]).toBeLessThan(-3);
      expect(log).toEqual([]);
      // resting on the floor within the penetration slop (0.005 m)
      expect(Math.abs(rests.x[1] - 0.25)).toBeLessThan(0.005);
    });

    it(`n = ${n}: the floor's own mask refuses the ball just as well (the test is symmetric)`, () => {
      const w = world(n);
      floor(w, { collisionMask: 0 });
      const b = ball(w, 1);
      const log = events(b);
      for (let i = 0; i < 90; i += 1) w.step(H);
      expect(b.x[1]).toBeLessThan(-1);
      expect(log).toEqual([]);
    });
  }

  it('a box that filters out the box below passes through it and lands on the floor (3D, 4D)', () => {
    for (const n of [3, 4]) {
      const w = world(n);
      const D = w.D;
      floor(w);
      const he = new Array<number>(n).fill(0.5);
      const lower = w.addBody(
        new Body(D, { shape: HyperBox(D, he), mass: 1, position: at(n, { 1: 0.5 }), name: 'lower', collisionGroup: 4 }),
      );
      const upper = w.addBody(
        new Body(D, { shape: HyperBox(D, he), mass: 1, position: at(n, { 1: 2 }), name: 'upper', collisionMask: ~4 >>> 0 }),
      );
      const log = events(upper);
      for (let i = 0; i < 180; i += 1) w.step(H);
      expect(log).toEqual(['begin:floor']);
      expect(Math.abs(upper.x[1] - 0.5)).toBeLessThan(0.005);
      expect(Math.abs(lower.x[1] - 0.5)).toBeLessThan(0.005);
    }
  });

  it('changing the mask of a resting (sleeping) ball lets it fall, with an end event', () => {
    const w = world(3);
    floor(w, { collisionGroup: 2 });
    const b = ball(w, 0.3);
    const log = events(b);
    for (let i = 0; i < 240; i += 1) w.step(H);
    expect(log).toEqual(['begin:floor']);
    expect(Math.abs(b.x[1] - 0.25)).toBeLessThan(0.005);
    b.collisionMask = 1;
    expect(b.collisionMask).toBe(1);
    for (let i = 0; i < 60; i += 1) w.step(H);
    expect(log).toEqual(['begin:floor', 'end:floor']);
    expect(b.x[1]).toBeLessThan(-1);
  });

  it('bad groups and masks are refused by name, before anything changes', () => {
    const D = dims(3);
    const shape = HyperSphere(D, 1);
    expect(() => new Body(D, { shape, collisionGroup: -1 })).toThrow(RangeError);
    expect(() => new Body(D, { shape, collisionGroup: -1 })).toThrow(
      /option 'collisionGroup' must be an integer in 0\.\.0xffffffff/,
    );
    expect(() => new Body(D, { shape, collisionMask: 2 ** 32 })).toThrow(/option 'collisionMask'/);
    expect(() => new Body(D, { shape, collisionMask: 1.5 })).toThrow(RangeError);
    expect(() => new Body(D, { shape, collisionGroup: '1' as never })).toThrow(TypeError);
    expect(() => new Body(D, { shape, sensor: 1 as never })).toThrow(/option 'sensor' must be a boolean/);
    const b = new Body(D, { shape });
    expect([b.collisionGroup, b.collisionMask, b.sensor]).toEqual([1, 0xffffffff, false]);
    expect(() => (b.collisionGroup = NaN)).toThrow(/Body.collisionGroup: value 'collisionGroup'/);
    expect(() => (b.collisionMask = Infinity)).toThrow(RangeError);
    expect(() => ((b as { sensor: unknown }).sensor = 'yes')).toThrow(TypeError);
    expect([b.collisionGroup, b.collisionMask, b.sensor]).toEqual([1, 0xffffffff, false]);
  });
  it('setCollisionFilter sets group, mask and sensor together, or nothing when one entry is bad', () => {
    const D = dims(4);
    const b = new Body(D, { shape: HyperSphere(D, 1) });
    b.setCollisionFilter({ group: 6, sensor: true });
    expect([b.collisionGroup, b.collisionMask, b.sensor]).toEqual([6, 0xffffffff, true]);
    expect(() => b.setCollisionFilter({ group: 1, mask: -2 })).toThrow(
      /Body.setCollisionFilter: entry 'filter.mask' must be an integer/,
    );
    expect(() => b.setCollisionFilter({ group: 1, sensor: 0 as never })).toThrow(TypeError);
    expect(() => b.setCollisionFilter({ groups: 1 } as never)).toThrow(/unknown entry 'groups'/);
    expect(() => b.setCollisionFilter(null as never)).toThrow(/argument 'filter' must be an object/);
    expect([b.collisionGroup, b.collisionMask, b.sensor]).toEqual([6, 0xffffffff, true]);
  });
});

describe('the pair filter', () => {
  for (const n of DIMENSIONS) {
    it(`n = ${n}: a refused pair makes no contact; removing the filter brings contacts back`, () => {
      const w = world(n);
      const ground = floor(w);
      const a = ball(w, 1, { name: 'a' });
      const b = ball(w, 1, { position: at(n, { 0: 2, 1: 1 }), name: 'b' });
      const asked = new Set<string>();
      w.setPairFilter((p, q) => {
        asked.add([p.name, q.name].sort().join('+'));
        return p !== a && q !== a;
      });
      expect(w.pairFilter).not.toBe(null);
      for (let i = 0; i < 60; i += 1) w.step(H);
      expect(asked.has('a+floor')).toBe(true);
      expect(a.x[1]).toBeLessThan(-0.5);
      expect(Math.abs(b.x[1] - 0.25)).toBeLessThan(0.005);
      // without the filter, a (below the floor, inside its solid side) touches it again
      const log = events(a);
      w.setPairFilter(null);
      expect(w.pairFilter).toBe(null);
      w.step(H);
      expect(log).toEqual([`begin:${ground.name}`]);
      expect(() => w.setPairFilter(42 as never)).toThrow(/World.setPairFilter: argument 'filter' must be a function/);
    });
  }
});

describe('sensors', () => {
  for (const n of DIMENSIONS) {
    it(`n = ${n}: a ball falling through a static sensor box reports one begin and one end and falls freely`, () => {
      const w = world(n);
      const D = w.D;
      const zone = w.addBody(
        new Body(D, {
          shape: HyperBox(D, new Array<number>(n).fill(0.5)),
          mass: 0,
          position: at(n, { 1: 0 }),
          sensor: true,
          name: 'zone',
        }),
      );
      const b = ball(w, 2);
      const seen: CollisionEvent[] = [];
      const log = events(b);
      zone.addEventListener('collision', (e) => seen.push({ ...e, point: e.point.slice(), normal: e.normal.slice() }));
      const free = world(n);
      const alone = ball(free, 2);
      for (let i = 0; i < 90; i += 1) {
        w.step(H);
        free.step(H);
        expect(b.x[1]).toBe(alone.x[1]);
        expect(b.v[1]).toBe(alone.v[1]);
      }
      expect(log).toEqual(['begin:zone', 'end:zone']);
      expect(seen.map((e) => `${e.type}:${e.other.name}`)).toEqual(['begin:ball', 'end:ball']);
      expect(seen[0]!.impulse).toBe(0);
      expect(zone.sensor).toBe(true);
    });

    it(`n = ${n}: a dynamic sensor falls through the floor, reporting the overlap; two sensors do not see each other`, () => {
      const w = world(n);
      floor(w);
      const s = ball(w, 1, { sensor: true, name: 's' });
      const t = ball(w, 1, { sensor: true, name: 't', position: at(n, { 0: 0.1, 1: 1.2 }) });
      const log = events(s);
      const other = events(t);
      for (let i = 0; i < 90; i += 1) w.step(H);
      expect(s.x[1]).toBeLessThan(-1);
      expect(log).toEqual(['begin:floor']); // still overlapping the (infinite) solid side
      expect(other).toEqual(['begin:floor']);
    });
  }

  it('a sensor holds nothing up and wakes nothing: a box resting beside a sensor falls asleep', () => {
    const w = world(3);
    const D = w.D;
    floor(w);
    const zone = w.addBody(
      new Body(D, { shape: HyperBox(D, [1, 1, 1]), mass: 0, position: [0, 1, 0], sensor: true, name: 'zone' }),
    );
    const box = w.addBody(new Body(D, { shape: HyperBox(D, [0.25, 0.25, 0.25]), mass: 1, position: [0, 0.3, 0], name: 'box' }));
    const log = events(box);
    for (let i = 0; i < 300; i += 1) w.step(H);
    expect(log.sort()).toEqual(['begin:floor', 'begin:zone']);
    expect(Math.abs(box.x[1] - 0.25)).toBeLessThan(0.005);
    expect(w.stats.awakeBodies).toBe(0);
    expect(zone.sensor).toBe(true);
  });
});

describe('snapshots', () => {
  it('groups, masks and sensors survive a snapshot, and the restored world steps bit-identically', () => {
    const w = world(4);
    floor(w, { collisionGroup: 8 });
    ball(w, 1, { collisionMask: 0xfffffff7 });
    ball(w, 1, { position: [2, 1, 0, 0], sensor: true, collisionGroup: 0x80000000 });
    ball(w, 1, { position: [4, 1, 0, 0] });
    for (let i = 0; i < 20; i += 1) w.step(H);
    const bytes = snapshotWorld(w);
    const r = restoreWorld(bytes);
    expect(r.bodies.map((b) => [b.collisionGroup, b.collisionMask, b.sensor])).toEqual(
      w.bodies.map((b) => [b.collisionGroup, b.collisionMask, b.sensor]),
    );
    for (let i = 0; i < 60; i += 1) {
      w.step(H);
      r.step(H);
    }
    expect(r.bodies.map((b) => Array.from(b.x))).toEqual(w.bodies.map((b) => Array.from(b.x)));
  });
});
