/**
 * Body: construction and its checks, mass and inertia, the velocity and force calls, setMass,
 * and the principal frame of shapes that carry one (frameOffset / frameRotor).
 */
import { describe, expect, it } from 'vitest';
import { Body, dims, HalfSpace, HyperBox, HyperSphere, World } from '@physin/engine';
import type { Dims, Shape } from '@physin/engine';
import {
  rotorApplyBivector,
  rotorApplyBivectorInverse,
  rotorApplyVector,
  rotorFromPlane,
  rotorMul,
  wedge,
} from '@physin/algebra';
import { randomArray, seeded, uniform } from './support/random.js';

function close(a: ArrayLike<number>, b: ArrayLike<number>, tol: number): void {
  expect(a.length).toBe(b.length);
  for (let i = 0; i < a.length; i += 1)
    expect(Math.abs(a[i]! - b[i]!), `index ${i}: ${a[i]} vs ${b[i]}`).toBeLessThanOrEqual(tol);
}

/** A random unit rotor: a product of plane turns. */
function randomRotor(D: Dims, rand: () => number): Float64Array {
  const R = rotorFromPlane(D, new Float64Array(D.r), 0, 1, uniform(rand, -3, 3));
  const P = new Float64Array(D.r);
  for (let p = 0; p < D.k; p += 1) {
    rotorFromPlane(D, P, D.planeI[p]!, D.planeJ[p]!, uniform(rand, -3, 3));
    rotorMul(D, R, P, R);
  }
  return R;
}

describe('Body construction', () => {
  it('defaults: dynamic, mass 1, identity rotor, at rest; ids unique and increasing; box inertia I_(ij) = m(a_i² + a_j²)/3', () => {
    const D = dims(4);
    const a = new Body(D, { shape: HyperBox(D, [0.5, 1, 1.5, 2]) });
    const b = new Body(D, { shape: HyperBox(D, [0.5, 1, 1.5, 2]), mass: 3, name: 'crate' });
    expect(a.type).toBe('dynamic');
    expect(a.mass).toBe(1);
    expect(Array.from(a.R)).toEqual([1, 0, 0, 0, 0, 0, 0, 0]);
    expect(Array.from(a.x)).toEqual([0, 0, 0, 0]);
    expect(Array.from(a.L)).toEqual([0, 0, 0, 0, 0, 0]);
    expect(b.id).toBeGreaterThan(a.id);
    expect(Number.isInteger(a.id)).toBe(true);
    expect(b.label).toBe(`body ${b.id} ('crate')`);
    const h = [0.5, 1, 1.5, 2];
    for (let p = 0; p < D.k; p += 1) {
      const i = D.planeI[p]!;
      const j = D.planeJ[p]!;
      expect(Math.abs(b.inertia[p]! - (3 * (h[i]! ** 2 + h[j]! ** 2)) / 3)).toBeLessThan(1e-14);
    }
  });

  it('mass 0 makes a body static; a half-space is static by default; a ball takes the n of D', () => {
    for (const n of [2, 3, 4, 5, 6]) {
      const D = dims(n);
      const ball = new Body(D, { shape: HyperSphere(D, 0.5), mass: 2 });
      // n-ball: C_ii = m ρ²/(n+2), I = 2 C_ii.
      for (let p = 0; p < D.k; p += 1) expect(Math.abs(ball.inertia[p]! - (2 * 2 * 0.25) / (n + 2))).toBeLessThan(1e-15);
      expect(new Body(D, { shape: HyperSphere(D, 0.5), mass: 0 }).type).toBe('static');
      const normal = new Array(n).fill(0);
      normal[1] = 1;
      expect(new Body(D, { shape: HalfSpace(D, normal, 0) }).type).toBe('static');
    }
  });

  it('kinematic: type kinematic keeps its mass for energy but has infinite mass (invMass 0)', () => {
    const D = dims(3);
    const k = new Body(D, { shape: HyperBox(D, [1, 1, 1]), type: 'kinematic', mass: 2, velocity: [1, 0, 0] });
    expect(k.type).toBe('kinematic');
    expect(k.invMass).toBe(0);
    expect(k.kineticEnergy()).toBeCloseTo(1, 15);
  });

  it('a given rotor is stored as an exact rotor (defect < 1e-15), one that is not a rotor is refused', () => {
    const D = dims(4);
    const R = randomRotor(D, seeded(4));
    const rough = Float32Array.from(R); // single precision: defect ~1e-7
    const body = new Body(D, { shape: HyperBox(D, [1, 1, 1, 1]), rotor: rough });
    expect(D.kernels.defect(body.R)).toBeLessThan(1e-15);
    close(body.R, R, 1e-6);
    expect(() => new Body(D, { shape: HyperBox(D, [1, 1, 1, 1]), rotor: [1, 0, 0, 0, 0, 0, 0, 1] })).toThrow(/'rotor'/);
    expect(() => new Body(D, { shape: HyperBox(D, [1, 1, 1, 1]), rotor: new Array(8).fill(0) })).toThrow(RangeError);
  });

  const D3 = dims(3);
  const box3 = HyperBox(D3, [1, 1, 1]);
  const badOptions: [string, () => unknown, 'TypeError' | 'RangeError', RegExp][] = [
    ['D not a Dims', () => new Body({} as Dims, { shape: box3 }), 'TypeError', /'D'/],
    ['options missing', () => new Body(D3, undefined as never), 'TypeError', /'options'/],
    ['no shape', () => new Body(D3, {} as never), 'TypeError', /'shape'/],
    ['shape of another n', () => new Body(D3, { shape: HyperBox(dims(4), [1, 1, 1, 1]) }), 'RangeError', /'shape'.*n = 4/],
    ['negative mass', () => new Body(D3, { shape: box3, mass: -1 }), 'RangeError', /'mass'/],
    ['NaN mass', () => new Body(D3, { shape: box3, mass: NaN }), 'RangeError', /'mass'/],
    ['mass as a string', () => new Body(D3, { shape: box3, mass: '1' as never }), 'TypeError', /'mass'/],
    ['dynamic with mass 0', () => new Body(D3, { shape: box3, mass: 0, type: 'dynamic' }), 'RangeError', /'mass'/],
    ['bad type', () => new Body(D3, { shape: box3, type: 'floating' as never }), 'RangeError', /'type'/],
    ['position of length 2', () => new Body(D3, { shape: box3, position: [0, 1] }), 'TypeError', /'position'/],
    ['position with Infinity', () => new Body(D3, { shape: box3, position: [0, Infinity, 0] }), 'RangeError', /'position'/],
    ['velocity with NaN', () => new Body(D3, { shape: box3, velocity: [0, NaN, 0] }), 'RangeError', /'velocity'/],
    [
      'angular velocity of length 4',
      () => new Body(D3, { shape: box3, angularVelocity: [0, 0, 0, 0] }),
      'TypeError',
      /'angularVelocity'/,
    ],
    ['rotor of length 3', () => new Body(D3, { shape: box3, rotor: [1, 0, 0] }), 'TypeError', /'rotor'/],
    [
      'half-space on a dynamic body',
      () => new Body(D3, { shape: HalfSpace(D3, [0, 1, 0], 0), mass: 1 }),
      'RangeError',
      /half-space/,
    ],
    [
      'half-space typed dynamic',
      () => new Body(D3, { shape: HalfSpace(D3, [0, 1, 0], 0), type: 'dynamic' }),
      'RangeError',
      /half-space|'mass'/,
    ],
    ['static with a velocity', () => new Body(D3, { shape: box3, mass: 0, velocity: [1, 0, 0] }), 'RangeError', /static/],
    ['unknown option', () => new Body(D3, { shape: box3, mas: 2 } as never), 'RangeError', /'mas'/],
    ['negative friction', () => new Body(D3, { shape: box3, material: { friction: -1 } }), 'RangeError', /friction/],
    ['restitution above 1', () => new Body(D3, { shape: box3, material: { restitution: 1.5 } }), 'RangeError', /restitution/],
    ['name not a string', () => new Body(D3, { shape: box3, name: 3 as never }), 'TypeError', /'name'/],
  ];
  for (const [what, make, kind, message] of badOptions) {
    it(`refuses ${what} with a ${kind} naming the option`, () => {
      let err: Error | null = null;
      try {
        make();
      } catch (e) {
        err = e as Error;
      }
      expect(err).not.toBeNull();
      expect(err!.constructor.name).toBe(kind);
      expect(err!.message).toMatch(message);
    });
  }
});

describe('Body velocities, impulses, forces', () => {
  for (const n of [2, 3, 4, 5, 6]) {
    it(`n = ${n}: setAngularVelocity sets L = I_world ω (checked in the body frame, 1e-13) and kineticEnergy = ½mv² + ½ω·L`, () => {
      const D = dims(n);
      const rand = seeded(60 + n);
      const body = new Body(D, {
        shape: HyperBox(D, Array.from(randomArray(rand, n, 0.3, 1.5))),
        mass: 2.5,
        rotor: randomRotor(D, rand),
      });
      const omega = randomArray(rand, D.k, -2, 2);
      const v = randomArray(rand, n, -2, 2);
      body.setAngularVelocity(omega).setLinearVelocity(v);
      close(body.w, omega, 0);
      const Lb = rotorApplyBivectorInverse(D, new Float64Array(D.k), body.R, body.L);
      const wb = rotorApplyBivectorInverse(D, new Float64Array(D.k), body.R, omega);
      for (let p = 0; p < D.k; p += 1) expect(Math.abs(Lb[p]! - body.inertia[p]! * wb[p]!)).toBeLessThan(1e-13);
      let lin = 0;
      for (let i = 0; i < n; i += 1) lin += v[i]! * v[i]!;
      let ang = 0;
      for (let p = 0; p < D.k; p += 1) ang += body.inertia[p]! * wb[p]! * wb[p]!;
      expect(Math.abs(body.kineticEnergy() - 0.5 * (2.5 * lin + ang))).toBeLessThan(1e-12);
    });

    it(`n = ${n}: applyImpulse: v += j/m, L += r ∧ j, ω = I_world⁻¹ L (1e-13); applyCentralImpulse leaves L`, () => {
      const D = dims(n);
      const rand = seeded(80 + n);
      const body = new Body(D, {
        shape: HyperBox(D, Array.from(randomArray(rand, n, 0.3, 1.5))),
        mass: 4,
        rotor: randomRotor(D, rand),
      });
      const j = randomArray(rand, n);
      const r = randomArray(rand, n);
      body.applyImpulse(j, r);
      close(
        body.v,
        Array.from(j, (x) => x / 4),
        1e-15,
      );
      close(body.L, wedge(D, new Float64Array(D.k), r, j), 1e-15);
      // ω from L through the body frame.
      const Lb = rotorApplyBivectorInverse(D, new Float64Array(D.k), body.R, body.L);
      for (let p = 0; p < D.k; p += 1) Lb[p] = Lb[p]! / body.inertia[p]!;
      close(body.w, rotorApplyBivector(D, new Float64Array(D.k), body.R, Lb), 1e-13);
      const L = Float64Array.from(body.L);
      body.applyCentralImpulse(j);
      close(
        body.v,
        Array.from(j, (x) => x / 2),
        1e-15,
      );
      expect(Array.from(body.L)).toEqual(Array.from(L));
    });
  }

  it('applyForce and applyTorque act for one step (v = h F/m, L = h (r∧F + τ)) and are then cleared', () => {
    const D = dims(4);
    const world = new World({ dimensions: 4 });
    const body = world.addBody(new Body(D, { shape: HyperBox(D, [1, 0.5, 0.5, 0.25]), mass: 2 }));
    const f = [1, 2, 3, 4];
    const r = [0.5, 0, 0, -0.25];
    const t = [0, 0, 0, 0, 0, 6];
    body.applyForce(f, r).applyTorque(t).applyCentralForce([2, 0, 0, 0]);
    const h = 0.01;
    world.step(h);
    close(body.v, [(h * 3) / 2, (h * 2) / 2, (h * 3) / 2, (h * 4) / 2], 1e-15);
    const expected = wedge(D, new Float64Array(6), r, f);
    expected[5] = expected[5]! + 6;
    close(
      body.L,
      Array.from(expected, (x) => h * x),
      1e-15,
    );
    expect(Array.from(body.force)).toEqual([0, 0, 0, 0]);
    expect(Array.from(body.torque)).toEqual([0, 0, 0, 0, 0, 0]);
    const v = Float64Array.from(body.v);
    const L = Float64Array.from(body.L);
    world.step(h);
    close(body.v, v, 0);
    expect(Array.from(body.L)).toEqual(Array.from(L));
  });

  it('static and kinematic bodies ignore forces and impulses; a static body refuses a non-zero velocity', () => {
    const D = dims(3);
    const still = new Body(D, { shape: HyperBox(D, [1, 1, 1]), mass: 0 });
    const kin = new Body(D, { shape: HyperBox(D, [1, 1, 1]), type: 'kinematic', velocity: [1, 2, 3] });
    for (const b of [still, kin]) {
      const v = Array.from(b.v);
      b.applyImpulse([1, 1, 1], [0, 1, 0]).applyCentralImpulse([5, 0, 0]).applyForce([1, 0, 0], [0, 1, 0]).applyTorque([1, 1, 1]);
      expect(Array.from(b.v)).toEqual(v);
      expect(Array.from(b.force)).toEqual([0, 0, 0]);
      expect(Array.from(b.torque)).toEqual([0, 0, 0]);
    }
    expect(() => still.setLinearVelocity([0, 1, 0])).toThrow(/static/);
    expect(() => still.setAngularVelocity([0, 1, 0])).toThrow(/static/);
    expect(() => still.setLinearVelocity([0, 0, 0])).not.toThrow();
  });

  it('setMass: inertia scales, v and ω are kept, L rescales; 0 makes the body static; a half-space refuses a mass', () => {
    const D = dims(4);
    const body = new Body(D, {
      shape: HyperBox(D, [1, 0.7, 0.5, 0.3]),
      mass: 1,
      rotor: randomRotor(D, seeded(9)),
      velocity: [1, 0, 0, 0],
      angularVelocity: [0.3, 1, -0.2, 0.4, 0.1, 2],
    });
    const I = Float64Array.from(body.inertia);
    const L = Float64Array.from(body.L);
    const w = Float64Array.from(body.w);
    body.setMass(2);
    close(
      body.inertia,
      Array.from(I, (x) => 2 * x),
      1e-15,
    );
    close(
      body.L,
      Array.from(L, (x) => 2 * x),
      1e-13,
    );
    close(body.w, w, 0);
    expect(body.invMass).toBe(0.5);
    body.setMass(0);
    expect(body.type).toBe('static');
    expect(body.kineticEnergy()).toBe(0);
    expect(Array.from(body.v)).toEqual([0, 0, 0, 0]);
    body.setMass(3);
    expect(body.type).toBe('dynamic');
    expect(body.invMass).toBeCloseTo(1 / 3, 15);
    const ground = new Body(D, { shape: HalfSpace(D, [0, 1, 0, 0], 0) });
    expect(() => ground.setMass(1)).toThrow(/half-space/);
    expect(() => body.setMass(-1)).toThrow(RangeError);
    expect(() => body.setMass(NaN)).toThrow(/'m'/);
  });

  it('method arguments are checked before anything is written (length, finiteness, plane)', () => {
    const D = dims(4);
    const body = new Body(D, { shape: HyperBox(D, [1, 1, 1, 1]), velocity: [1, 2, 3, 4] });
    const before = Float64Array.from(body.storage);
    expect(() => body.setPositionN([1, 2, 3])).toThrow(TypeError);
    expect(() => body.setLinearVelocity([1, 2, NaN, 4])).toThrow(/'v'/);
    expect(() => body.setAngularVelocity([1, 2, 3, 4, 5])).toThrow(/'w'/);
    expect(() => body.applyImpulse([1, 2, 3, 4], [1, 2])).toThrow(/'r'/);
    expect(() => body.applyForce([Infinity, 0, 0, 0], [0, 0, 0, 0])).toThrow(/'f'/);
    expect(() => body.applyTorque([0, 0, 0])).toThrow(/'t'/);
    expect(() => body.rotateInPlane(1, 1, 0.3)).toThrow(RangeError);
    expect(() => body.rotateInPlane(0, 4, 0.3)).toThrow(/'j'/);
    expect(() => body.rotateInPlane(0, 1, NaN)).toThrow(/'angle'/);
    expect(Array.from(body.storage)).toEqual(Array.from(before));
  });
});

describe('a shape with a principal frame (frameOffset, frameRotor)', () => {
  // A stand-in for a convex mesh described off-centre and turned: its principal frame sits at
  // frameOffset and is turned by frameRotor in the described coordinates.
  const D = dims(3);
  const frameOffset = Float64Array.from([0.4, -0.2, 0.1]);
  const frameRotor = rotorFromPlane(D, new Float64Array(4), 0, 1, 0.6);
  const shape: Shape = {
    kind: 'mesh',
    n: 3,
    frameOffset,
    frameRotor,
    massProperties: (_D, mass) => HyperBox(D, [1, 0.5, 0.25]).massProperties(D, mass),
  };

  it('the body state is the principal frame: x = p + R_u·frameOffset, R = R_u·frameRotor (1e-15); getPositionN gives p back', () => {
    const Ru = rotorFromPlane(D, new Float64Array(4), 1, 2, 0.9);
    const p = [1, 2, 3];
    const body = new Body(D, { shape, position: p, rotor: Ru });
    const off = rotorApplyVector(D, new Float64Array(3), Ru, frameOffset);
    close(body.x, [1 + off[0]!, 2 + off[1]!, 3 + off[2]!], 1e-15);
    close(body.R, rotorMul(D, new Float64Array(4), Ru, frameRotor), 1e-15);
    close(body.getPositionN(), p, 1e-15);
  });

  it('setPositionN moves the described origin; rotateInPlane turns about it (it stays put)', () => {
    const body = new Body(D, { shape });
    body.setPositionN([5, 0, 0]);
    close(body.getPositionN(), [5, 0, 0], 1e-15);
    body.rotateInPlane(0, 2, 1.1);
    close(body.getPositionN(), [5, 0, 0], 1e-15);
    // The centre of mass turned about the origin with the body.
    const expected = rotorApplyVector(D, new Float64Array(3), rotorFromPlane(D, new Float64Array(4), 0, 2, 1.1), frameOffset);
    close(body.x, [5 + expected[0]!, expected[1]!, expected[2]!], 1e-15);
  });
});
