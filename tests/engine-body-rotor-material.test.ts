/**
 * Body.getRotor / setRotor (the orientation of the coordinates a shape was described in) and
 * Body.setMaterial (friction and restitution changed on a live body, contacts included).
 */
import { describe, expect, it } from 'vitest';
import { rotorFromPlane, rotorMul } from '@physin/algebra';
import { Body, ConvexMesh, HalfSpace, HyperBox, World, dims } from '@physin/engine';

const close = (a: ArrayLike<number>, b: ArrayLike<number>, tol: number): void => {
  expect(a.length).toBe(b.length);
  for (let i = 0; i < a.length; i += 1) expect(Math.abs(a[i]! - b[i]!)).toBeLessThan(tol);
};

describe('getRotor and setRotor', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a box's rotor round-trips, keeps the position and the world angular velocity`, () => {
      const D = dims(n);
      const body = new Body(D, {
        shape: HyperBox(D, new Array(n).fill(0.5)),
        mass: 1,
        position: new Array(n).fill(0).map((_, i) => i + 1),
      });
      const w = new Float64Array(D.k).map((_, i) => 0.1 * (i + 1));
      body.setAngularVelocity(w);
      const R = rotorMul(
        D,
        new Float64Array(D.r),
        rotorFromPlane(D, new Float64Array(D.r), 0, 1, 0.7),
        rotorFromPlane(D, new Float64Array(D.r), 1, 2, -0.4),
      );
      const x = [...body.x];
      body.setRotor(R);
      close(body.getRotor(), R, 1e-15);
      expect([...body.x]).toEqual(x);
      close(body.w, w, 1e-14);
    });
  }

  it('a convex mesh off its centre of mass: the described origin stays put and the rotor round-trips', () => {
    const D = dims(3);
    // an irregular tetrahedron around the origin: its principal frame is offset and turned
    const positions = [1.2, -0.3, -0.4, -0.5, 0.9, -0.3, -0.4, -0.6, 0.8, 0.1, 0.2, -1.1];
    const indices = [0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2];
    const body = new Body(D, { shape: ConvexMesh.fromTriangles(D, positions, indices), mass: 2, position: [3, 1, -2] });
    const origin = [...body.getPositionN()];
    const R = rotorFromPlane(D, new Float64Array(D.r), 0, 2, 1.1);
    body.setRotor(R);
    close(body.getRotor(), R, 1e-14);
    close(body.getPositionN(), origin, 1e-14);
  });

  it('refuses a rotor that is not a unit rotor, and changes nothing', () => {
    const D = dims(3);
    const body = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1 });
    const before = [...body.R];
    expect(() => body.setRotor([2, 0, 0, 0])).toThrow(/unit rotor/);
    expect(() => body.setRotor([1, 0, 0])).toThrow(/argument 'R'/);
    expect([...body.R]).toEqual(before);
  });
});

describe('setMaterial', () => {
  it('friction raised on a box sliding on a frictionless floor stops it; the contact takes the new value at once', () => {
    const D = dims(3);
    const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
    world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0, material: { friction: 1 } }));
    const box = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5, 0], material: { friction: 0 } });
    world.addBody(box);
    box.setLinearVelocity([3, 0, 0]);
    for (let i = 0; i < 30; i += 1) world.step(1 / 60);
    // frictionless (the pair mixes to 0): the speed is kept
    expect(box.v[0]).toBeCloseTo(3, 6);
    box.setMaterial({ friction: 0.5 });
    expect(box.material.friction).toBe(0.5);
    expect(box.material.restitution).toBe(0);
    world.step(1 / 60);
    // the next step already slows it by μ g h, μ the pair's friction √(0.5 · 1)
    const slowed = 3 - box.v[0]!;
    expect(Math.abs(slowed - (Math.SQRT1_2 * 9.81) / 60) / ((Math.SQRT1_2 * 9.81) / 60)).toBeLessThan(0.01);
    for (let i = 0; i < 120; i += 1) world.step(1 / 60);
    expect(Math.abs(box.v[0]!)).toBeLessThan(1e-6);
  });

  it('refuses bad values by name and keeps the material', () => {
    const D = dims(3);
    const box = new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, material: { friction: 0.3, restitution: 0.2 } });
    expect(() => box.setMaterial({ friction: -1 })).toThrow(/friction/);
    expect(() => box.setMaterial({ restitution: Number.NaN })).toThrow(/restitution/);
    expect(() => box.setMaterial(null as never)).toThrow(TypeError);
    expect(box.material.friction).toBe(0.3);
    expect(box.material.restitution).toBe(0.2);
  });
});
