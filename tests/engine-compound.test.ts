/**
 * Compound bodies: `Compound(D, parts)`, one rigid body of several shapes at offsets and rotors.
 *
 * - Mass properties of a dumbbell (two balls on a capsule bar) against the analytic sums (one
 *   density, parallel axis theorem) in n = 2, 3, 4, 5, also when the whole is given moved and
 *   turned (the principal frame is found again: frameOffset = the moved centre, same inertia).
 * - A dumbbell rolls on a half-space as one body (n = 3, 4, 5): once friction has done its work the balls roll
 *   without slipping (|v| = |ω|·ρ within 1e-9 relative), the centre stays at height ρ (within
 *   1e-9 m) and no part sinks past the penetration slop.
 * - An L of two boxes pushed into a box corner (floor and wall) rests still, with contacts from
 *   both parts of different normals, named by the collision events' `part`.
 * - castRay names the part it hits; queryBox lists a compound once.
 * - A snapshot round trip continues bit-identically; two runs give the same bits.
 * - Bad input throws TypeError / RangeError naming the argument.
 * - The step allocates nothing with compounds in the world (the built engine in a child process,
 *   tests/engine-compound-allocation.mjs): the least growth of new space over three windows of
 *   2000 steps of 12 compounds is below 16 KB (one 16-byte object per compound per step would be
 *   384 KB; measured 2.6 KB, the measuring's own).
 */
import { execFileSync } from 'node:child_process';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import {
  Body,
  Compound,
  ConvexMesh,
  HalfSpace,
  HyperBox,
  HyperCapsule,
  HyperSphere,
  World,
  castRay,
  dims,
  queryBox,
  restoreWorld,
  snapshotWorld,
} from '@physin/engine';
import type { CollisionEvent, Dims } from '@physin/engine';
import { rotorFromPlane } from '@physin/algebra';

/** The volume of the n-ball of radius ρ. */
function ballVolume(n: number, rho: number): number {
  // V_n = π^(n/2) ρⁿ / Γ(n/2 + 1), Γ by the recurrence from Γ(1) = 1 or Γ(1/2) = √π
  let gamma = n % 2 === 0 ? 1 : Math.sqrt(Math.PI);
  for (let x = n % 2 === 0 ? 1 : 0.5; x < n / 2 + 1 - 1e-9; x += 1) gamma *= x;
  return (Math.PI ** (n / 2) * rho ** n) / gamma;
}

function unit(n: number, axis: number, s = 1): number[] {
  const v = new Array<number>(n).fill(0);
  v[axis] = s;
  return v;
}

/**
 * A dumbbell along axis `axis`: balls of radius ρ at ±L on a capsule bar (core segment ±L, radius
 * `thin`), the capsule's own axis (local e1) turned onto e_axis.
 */
function dumbbell(D: Dims, axis: number, rho: number, L: number, thin: number) {
  const n = D.n;
  const turn = new Float64Array(D.r);
  turn[0] = 1;
  if (axis !== 1) rotorFromPlane(D, turn, 1, axis, Math.PI / 2);
  return Compound(D, [
    { shape: HyperSphere(D, rho), position: unit(n, axis, -L) },
    { shape: HyperSphere(D, rho), position: unit(n, axis, L) },
    { shape: HyperCapsule(D, L, thin), rotor: turn },
  ]);
}

/**
 * The analytic volume and covariance diagonal (kg·m²) of `dumbbell(D, 0, ρ, L, t)` of mass m. The
 * capsule bar: a cylinder 2L·V_(n−1)(t) and two half-balls (one ball V_n(t)); along its axis the
 * cylinder gives V_(n−1)·2L³/3, the caps L²V_n + 4L·V_(n−1)·t²/(n + 1) + V_n·t²/(n + 2); across,
 * 2L·V_(n−1)·t²/(n + 1) + V_n·t²/(n + 2).
 */
function dumbbellCovariance(n: number, m: number, rho: number, L: number, t: number): { volume: number; C: number[] } {
  const vBall = ballVolume(n, rho);
  const disc = ballVolume(n - 1, t);
  const cap = ballVolume(n, t);
  const vBar = 2 * L * disc + cap;
  const barAlong = (disc * 2 * L ** 3) / 3 + L * L * cap + (4 * L * disc * t * t) / (n + 1) + (cap * t * t) / (n + 2);
  const barAcross = (2 * L * disc * t * t) / (n + 1) + (cap * t * t) / (n + 2);
  const volume = 2 * vBall + vBar;
  const mBall = (m * vBall) / volume;
  const density = m / volume;
  const C: number[] = [];
  for (let i = 0; i < n; i += 1) {
    C.push((2 * mBall * (rho * rho)) / (n + 2) + (i === 0 ? 2 * mBall * L * L + density * barAlong : density * barAcross));
  }
  return { volume, C };
}

describe('Compound mass properties: the analytic sums', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: a dumbbell's volume, centre of mass and inertia`, () => {
      const D = dims(n);
      const rho = 0.5;
      const L = 1.2;
      const thin = 0.1;
      const m = 3;
      const shape = dumbbell(D, 0, rho, L, thin);
      const { volume, C } = dumbbellCovariance(n, m, rho, L, thin);
      const mp = shape.massProperties(D, m);
      expect(Math.abs(mp.volume - volume) / volume).toBeLessThan(1e-14);
      for (let i = 0; i < n; i += 1) expect(Math.abs(mp.covariance[i]! - C[i]!) / C[i]!).toBeLessThan(1e-13);
      for (let p = 0; p < D.k; p += 1) {
        const I = C[D.planeI[p]!]! + C[D.planeJ[p]!]!;
        expect(Math.abs(mp.inertia[p]! - I) / I).toBeLessThan(1e-13);
      }
      // symmetric: the centre of mass is the origin, the frame the given axes
      for (let i = 0; i < n; i += 1) expect(Math.abs(shape.frameOffset[i]!)).toBeLessThan(1e-15);
      expect(1 - shape.frameRotor[0]!).toBeLessThan(1e-15);
      const body = new Body(D, { shape, mass: m });
      for (let p = 0; p < D.k; p += 1) {
        const I = C[D.planeI[p]!]! + C[D.planeJ[p]!]!;
        expect(Math.abs(body.inertia[p]! - I) / I).toBeLessThan(1e-13);
      }
      expect(body.boundingRadius).toBeCloseTo(L + rho, 14);
    });

    it(`n = ${n}: moved, turned and lopsided: the centre of mass and principal frame found again`, () => {
      const D = dims(n);
      const rho = 0.4;
      const L = 1;
      const t = Array.from({ length: n }, (_, i) => 0.3 * (i + 1) - 0.7);
      // a turn by 0.4 rad in the plane (0, 1): the dumbbell's axis e0 goes to R e0
      const c = Math.cos(0.2);
      const s = Math.sin(0.2);
      const R = new Float64Array(D.r);
      R[0] = c;
      R[1 + D.planeIndexOf[0 * n + 1]!] = -s;
      const axis = [Math.cos(0.4), Math.sin(0.4)];
      const at = (k: number): number[] => t.map((x, i) => x + (i < 2 ? k * axis[i]! : 0));
      // balls of different radii: the centre of mass is off the middle
      const big = 0.6;
      const shape = Compound(D, [
        { shape: HyperSphere(D, rho), position: at(-L) },
        { shape: HyperSphere(D, big), position: at(L) },
        { shape: HyperBox(D, [L, ...new Array<number>(n - 1).fill(0.1)]), position: t, rotor: R },
      ]);
      const v1 = ballVolume(n, rho);
      const v2 = ballVolume(n, big);
      const vb = 2 * L * 0.2 ** (n - 1);
      const V = v1 + v2 + vb;
      const along = (L * (v2 - v1)) / V; // the centre of mass along the axis from t
      for (let i = 0; i < n; i += 1) {
        const expected = t[i]! + (i < 2 ? along * axis[i]! : 0);
        expect(Math.abs(shape.frameOffset[i]! - expected)).toBeLessThan(1e-14);
      }
      // covariance along the axis and across it, about the centre of mass
      const m = 2;
      const w1 = (m * v1) / V;
      const w2 = (m * v2) / V;
      const wb = (m * vb) / V;
      const cAlong =
        w1 * ((rho * rho) / (n + 2) + (L + along) ** 2) +
        w2 * ((big * big) / (n + 2) + (L - along) ** 2) +
        wb * ((L * L) / 3 + along * along);
      const cAcross = (w1 * rho * rho + w2 * big * big) / (n + 2) + (wb * 0.01) / 3;
      const mp = shape.massProperties(D, m);
      const got = Array.from(mp.covariance).sort((a, b) => a - b);
      const want = [cAlong, ...new Array<number>(n - 1).fill(cAcross)].sort((a, b) => a - b);
      for (let i = 0; i < n; i += 1) expect(Math.abs(got[i]! - want[i]!) / want[i]!).toBeLessThan(1e-12);
      // the principal frame: its first axis is the dumbbell's axis
      const M = new Float64Array(n * n);
      D.kernels.toMatrix(M, shape.frameRotor);
      let big0 = 0;
      for (let c2 = 0; c2 < n; c2 += 1) {
        const dot = Math.abs(M[0 * n + c2]! * axis[0]! + M[1 * n + c2]! * axis[1]!);
        if (Math.abs(mp.covariance[c2]! - cAlong) / cAlong < 1e-12) big0 = Math.max(big0, dot);
      }
      expect(1 - big0).toBeLessThan(1e-12);
      // placed at the origin with the identity, the body's centre of mass is at frameOffset
      const body = new Body(D, { shape, mass: m });
      for (let i = 0; i < n; i += 1) expect(Math.abs(body.x[i]! - shape.frameOffset[i]!)).toBeLessThan(1e-15);
      const back = body.getPositionN();
      for (let i = 0; i < n; i += 1) expect(Math.abs(back[i]!)).toBeLessThan(1e-14);
    });
  }
});

describe('a convex mesh part keeps its own principal frame', () => {
  it('n = 3: a compound of one off-centre, turned mesh is placed, weighed and turned as the mesh alone', () => {
    const D = dims(3);
    // a lopsided wedge far from its own origin: the mesh moves itself into its principal frame
    const mesh = ConvexMesh(
      D,
      [
        [2, 1, 0],
        [4, 1, 0],
        [2, 2.5, 0],
        [2, 1, 0.7],
        [4, 1, 0.7],
        [2, 2.5, 0.7],
      ],
      [
        [0, 2, 1],
        [3, 4, 5],
        [0, 1, 4],
        [0, 4, 3],
        [0, 3, 5],
        [0, 5, 2],
        [1, 2, 5],
        [1, 5, 4],
      ],
    );
    const turn = new Float64Array(D.r);
    rotorFromPlane(D, turn, 0, 2, 0.7);
    const place = [0.3, -0.2, 0.5];
    const whole = Compound(D, [{ shape: mesh, position: place, rotor: turn }]);
    const a = new Body(D, { shape: mesh, mass: 2, position: [1, 2, 3] });
    const b = new Body(D, { shape: whole, mass: 2, position: [1, 2, 3] });
    // b's part sits where a's mesh would with the placement applied: compare through the
    // mesh's centre, x + R·(place + turn·frameOffset)
    const centre = new Float64Array(3);
    D.kernels.applyVector(centre, turn, Float64Array.from(mesh.frameOffset));
    for (let i = 0; i < 3; i += 1) expect(Math.abs(b.x[i]! - (i + 1 + place[i]! + centre[i]!))).toBeLessThan(1e-13);
    // the same principal moments
    const ia = Array.from(a.inertia).sort((x, y) => x - y);
    const ib = Array.from(b.inertia).sort((x, y) => x - y);
    for (let p = 0; p < 3; p += 1) expect(Math.abs(ia[p]! - ib[p]!) / ia[p]!).toBeLessThan(1e-12);
    // a ray down through the centre of mass (inside the convex part) hits the part
    const world = new World({ dimensions: 3 });
    world.addBody(b);
    const hit = castRay(world, [b.x[0]!, 10, b.x[2]!], [0, -1, 0], 20);
    expect(hit).not.toBeNull();
    expect(hit!.part).toBe(0);
  });
});

/** A world with a floor half-space (y <= 0) and a dumbbell lying on it, its axis along z, rolling along x. */
function rollingScene(n: number, v0: number) {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: unit(n, 1, -9.81), params: { subSteps: 4 } });
  world.addBody(new Body(D, { shape: HalfSpace(D, unit(n, 1), 0), material: { friction: 0.8 }, name: 'floor' }));
  const rho = 0.5;
  const shape = dumbbell(D, 2, rho, 1, 0.1);
  const body = world.addBody(
    new Body(D, {
      shape,
      mass: 2,
      position: unit(n, 1, rho),
      velocity: unit(n, 0, v0),
      material: { friction: 0.8 },
      name: 'dumbbell',
    }),
  );
  return { D, world, body, rho };
}

describe('a dumbbell rolls on a half-space as one body', () => {
  for (const n of [3, 4, 5]) {
    it(`n = ${n}: after friction has acted, v = ω·ρ (rolling without slipping) and the centre stays at ρ`, () => {
      const { D, world, body, rho } = rollingScene(n, 2);
      let lowest = Infinity;
      for (let s = 0; s < 120; s += 1) {
        world.step(1 / 60);
        lowest = Math.min(lowest, body.x[1]!);
      }
      const v = body.v;
      const w = body.w;
      // ω in the plane (x, y); the contact point's velocity v + ω·r with r = −ρ e_y
      const p01 = D.planeIndexOf[0 * n + 1]!;
      const speed = Math.abs(v[0]!);
      expect(speed).toBeGreaterThan(0.5);
      expect(Math.abs(speed - Math.abs(w[p01]!) * rho) / speed).toBeLessThan(1e-9); // measured 5e-13
      for (let p = 0; p < D.k; p += 1) if (p !== p01) expect(Math.abs(w[p]!)).toBeLessThan(1e-6);
      for (let i = 1; i < n; i += 1) expect(Math.abs(v[i]!)).toBeLessThan(1e-3);
      // the centre rests at ρ: no part sinks past the slop
      expect(Math.abs(body.x[1]! - rho)).toBeLessThan(1e-9); // measured 5e-13
      expect(lowest).toBeGreaterThan(rho - world.params.penetrationSlop);
      // both balls on the floor: the axis stays along z
      const M = new Float64Array(n * n);
      D.kernels.toMatrix(M, body.R);
      expect(Math.abs(M[1 * n + 2]!)).toBeLessThan(1e-6);
    });
  }
});

/**
 * An L of two boxes (a foot lying on the floor, a leg standing on its left end against the wall),
 * pushed into the corner by gravity tilted toward the wall; frictionless, so it slides 5 cm to the wall.
 */
function cornerScene(n: number) {
  const D = dims(n);
  const g = unit(n, 1, -9.81);
  g[0] = -1;
  const world = new World({ dimensions: n, gravity: g });
  const deep = (x: number, y: number): number[] => {
    const a = new Array<number>(n).fill(0.5);
    a[0] = x;
    a[1] = y;
    return a;
  };
  const at = (x: number, y: number): number[] => {
    const p = new Array<number>(n).fill(0);
    p[0] = x;
    p[1] = y;
    return p;
  };
  const wide = (x: number, y: number): number[] => {
    const a = new Array<number>(n).fill(3);
    a[0] = x;
    a[1] = y;
    return a;
  };
  const floor = world.addBody(new Body(D, { shape: HyperBox(D, wide(3, 0.5)), position: at(0, -0.5), mass: 0, name: 'floor' }));
  const wall = world.addBody(new Body(D, { shape: HyperBox(D, wide(0.5, 3)), position: at(-1.5, 2), mass: 0, name: 'wall' }));
  const L = Compound(D, [
    { shape: HyperBox(D, deep(1, 0.1)), position: at(0.2, 0.1) },
    { shape: HyperBox(D, deep(0.1, 1)), position: at(-0.9, 1.2) },
  ]);
  const body = world.addBody(new Body(D, { shape: L, mass: 1, position: at(0.05, 0.002), material: { friction: 0 }, name: 'L' }));
  return { world, body, floor, wall };
}

describe('an L in a box corner rests on two faces, each touched by its own part', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: still after 2 s; the floor touches part 0 (normal along y), the wall part 1 (along x)`, () => {
      const { world, body, floor, wall } = cornerScene(n);
      const seen: { other: string; part: number; otherPart: number; normal: number[] }[] = [];
      body.addEventListener('collision', (e: CollisionEvent) => {
        if (e.type === 'begin')
          seen.push({ other: e.other.name!, part: e.part, otherPart: e.otherPart, normal: Array.from(e.normal) });
      });
      for (let s = 0; s < 120; s += 1) world.step(1 / 60);
      let speed = 0;
      for (const x of body.v) speed = Math.max(speed, Math.abs(x));
      for (const x of body.w) speed = Math.max(speed, Math.abs(x));
      expect(speed).toBeLessThan(1e-3);
      const onFloor = seen.filter((e) => e.other === floor.name);
      const onWall = seen.filter((e) => e.other === wall.name);
      expect(onFloor.length).toBeGreaterThan(0);
      expect(onWall.length).toBeGreaterThan(0);
      for (const e of onFloor) {
        expect(e.part).toBe(0);
        expect(e.otherPart).toBe(0);
        expect(e.normal[1]).toBeLessThan(-0.999); // from the L into the floor
      }
      for (const e of onWall) {
        expect(e.part).toBe(1);
        expect(e.normal[0]).toBeLessThan(-0.999); // from the L into the wall
      }
      // resting (asleep): the foot's bottom on the floor, the leg's left face on the wall (measured
      // within 1e-8 m), where the described origin is 0
      expect(body.sleeping).toBe(true);
      const x0 = body.getPositionN();
      for (let i = 0; i < n; i += 1) expect(Math.abs(x0[i]!)).toBeLessThan(1e-7);
    });
  }
});

describe('queries see every part', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}: castRay names the part it hits, at the distance of that part's surface`, () => {
      const D = dims(n);
      const world = new World({ dimensions: n });
      const rho = 0.5;
      const body = world.addBody(new Body(D, { shape: dumbbell(D, 0, rho, 1.5, 0.1), mass: 1, position: unit(n, 1, 2) }));
      for (const [x, part, top] of [
        [-1.5, 0, 2 + rho],
        [1.5, 1, 2 + rho],
        [0, 2, 2 + 0.1],
      ] as const) {
        const origin = unit(n, 1, 10);
        origin[0] = x;
        const hit = castRay(world, origin, unit(n, 1, -1), 20);
        expect(hit).not.toBeNull();
        expect(hit!.body).toBe(body);
        expect(hit!.part).toBe(part);
        expect(Math.abs(hit!.distance - (10 - top))).toBeLessThan(1e-12);
      }
      // between the bar and a ball, above the bar: the ball at x = −1.5 + 0.3 is hit, not the bar
      const origin = unit(n, 1, 10);
      origin[0] = -1.2;
      expect(castRay(world, origin, unit(n, 1, -1), 20)!.part).toBe(0);
      // a box around everything finds the body once
      const min = new Array<number>(n).fill(-5);
      const max = new Array<number>(n).fill(5);
      expect(queryBox(world, min, max)).toEqual([body]);
    });
  }
});

describe('snapshots and determinism', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a rolling dumbbell restored mid-roll continues bit-identically`, () => {
      const a = rollingScene(n, 2);
      for (let s = 0; s < 30; s += 1) a.world.step(1 / 60);
      const bytes = snapshotWorld(a.world);
      const b = restoreWorld(bytes);
      expect(Array.from(snapshotWorld(b))).toEqual(Array.from(bytes));
      const bodyB = b.bodies[1]!;
      expect(bodyB.shape.kind).toBe('compound');
      for (let s = 0; s < 60; s += 1) {
        a.world.step(1 / 60);
        b.step(1 / 60);
      }
      expect(Array.from(bodyB.x)).toEqual(Array.from(a.body.x));
      expect(Array.from(bodyB.R)).toEqual(Array.from(a.body.R));
      expect(Array.from(bodyB.v)).toEqual(Array.from(a.body.v));
      expect(Array.from(snapshotWorld(b))).toEqual(Array.from(snapshotWorld(a.world)));
      // a fresh run gives the same bits
      const c = rollingScene(n, 2);
      for (let s = 0; s < 90; s += 1) c.world.step(1 / 60);
      expect(Array.from(snapshotWorld(c.world))).toEqual(Array.from(snapshotWorld(a.world)));
    });
  }

  it('n = 3: the L in the corner restored with its touching parts continues bit-identically', () => {
    const a = cornerScene(3);
    for (let s = 0; s < 20; s += 1) a.world.step(1 / 60);
    const b = restoreWorld(snapshotWorld(a.world));
    for (let s = 0; s < 40; s += 1) {
      a.world.step(1 / 60);
      b.step(1 / 60);
    }
    expect(Array.from(snapshotWorld(b))).toEqual(Array.from(snapshotWorld(a.world)));
  });

  it('removing a compound body frees every part proxy; adding it again works', () => {
    const { world, body } = rollingScene(3, 1);
    world.step(1 / 60);
    const before = world.stats.pairs;
    expect(before).toBeGreaterThan(0);
    world.removeBody(body);
    world.step(1 / 60);
    expect(world.stats.pairs).toBe(0);
    world.addBody(body);
    world.step(1 / 60);
    expect(world.stats.pairs).toBe(before);
    expect(restoreWorld(snapshotWorld(world)).bodies.length).toBe(2);
  });
});

describe('Compound refuses bad input, naming the argument', () => {
  for (const n of [2, 3, 4, 5]) {
    it(`n = ${n}`, () => {
      const D = dims(n);
      const ball = HyperSphere(D, 1);
      expect(() => Compound(D, [])).toThrow(RangeError);
      expect(() => Compound(D, [])).toThrow(/'parts'/);
      expect(() => Compound(D, null as never)).toThrow(TypeError);
      expect(() => Compound(D, [null as never])).toThrow(/'parts\[0\]'/);
      expect(() => Compound(D, [{ shape: HalfSpace(D, unit(n, 1), 0) }])).toThrow(RangeError);
      expect(() => Compound(D, [{ shape: HalfSpace(D, unit(n, 1), 0) }])).toThrow(/'parts\[0\]\.shape'.*half-space/);
      const inner = Compound(D, [{ shape: ball }]);
      expect(() => Compound(D, [{ shape: ball }, { shape: inner }])).toThrow(RangeError);
      expect(() => Compound(D, [{ shape: ball }, { shape: inner }])).toThrow(/'parts\[1\]\.shape'.*compound/);
      const other = dims(n === 2 ? 3 : 2);
      expect(() => Compound(D, [{ shape: HyperSphere(other, 1) }])).toThrow(RangeError);
      expect(() => Compound(D, [{ shape: HyperSphere(other, 1) }])).toThrow(/'parts\[0\]\.shape'.*n = /);
      expect(() => Compound(other, [{ shape: ball }])).toThrow(/'parts\[0\]\.shape'/);
      const bad = new Array<number>(n).fill(0);
      bad[n - 1] = NaN;
      expect(() => Compound(D, [{ shape: ball, position: bad }])).toThrow(RangeError);
      expect(() => Compound(D, [{ shape: ball, position: bad }])).toThrow(/'parts\[0\]\.position'/);
      expect(() => Compound(D, [{ shape: ball, position: [1] }])).toThrow(TypeError);
      expect(() => Compound(D, [{ shape: ball, rotor: new Array<number>(D.r).fill(1) }])).toThrow(/'parts\[0\]\.rotor'/);
      expect(() => Compound(D, [{ shape: ball, rotor: [1] }])).toThrow(TypeError);
      expect(() => Compound(D, [{ shape: 'ball' as never }])).toThrow(TypeError);
      expect(() => Compound(D, [{ shape: ball, offset: [0] } as never])).toThrow(/unknown key 'offset'/);
      expect(() => Compound({ n } as never, [{ shape: ball }])).toThrow(TypeError);
    });
  }
});

describe('the step allocates nothing with compound bodies (built engine, child process)', () => {
  const root = join(dirname(fileURLToPath(import.meta.url)), '..');
  for (const n of [3, 4]) {
    it(`n = ${n}: 12 dumbbells and Ls rolling on a half-space, with collision listeners`, () => {
      const out = execFileSync(
        process.execPath,
        [
          '--no-concurrent-recompilation',
          '--expose-gc',
          '--max-semi-space-size=256',
          '--min-semi-space-size=64',
          join(root, 'tests/engine-compound-allocation.mjs'),
          String(n),
        ],
        { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] },
      );
      const r = JSON.parse(out.trim().split('\n').pop()!) as { least: number | null; contacts: number; events: number };
      expect(r.contacts).toBeGreaterThan(12);
      expect(r.events).toBeGreaterThan(12);
      // A window in which something deoptimises and runs boxed in the interpreter costs about
      // 300 KB; the least of three leaves it out.
      expect(r.least).not.toBeNull(); // null: JSON's Infinity, a collection in every window
      expect(r.least).toBeLessThan(16 * 1024);
    });
  }
});
