/**
 * Joints: the pendulum on a point joint (identity 23 of the brief's §10).
 *
 * A bob hangs from a world point by a PointJoint whose anchor on the bob is l = 1 m from its
 * centre, so the bob is a physical pendulum: T = 2π √(I_pivot / (m g l)) · (1 + θ₀²/16) with
 * I_pivot = m l² + I_cm (the bob's own inertia in the swing plane). A ball of radius ρ in n
 * dimensions has I_cm = 2 m ρ²/(n + 2) (C_ii = m ρ²/(n+2), I_(ij) = C_ii + C_jj); a box of
 * half-extents a has I_cm = m (a_i² + a_j²)/3 in the plane (i, j).
 *
 * The period is measured from the zero crossings of the bob's centre along the swing direction
 * (linear interpolation between steps), averaged over every full period in 20 s. dt = 1/60, one
 * sub-step, default parameters (sleep off). The start angle θ₀ is seeded in [0.08, 0.12) rad.
 * Tolerance: 1 % of the formula (the issue's).
 */
import { describe, expect, it } from 'vitest';
import { Body, HyperBox, HyperSphere, PointJoint } from '@physin/engine';
import { seeded, uniform } from './support/random.js';
import { G, makeWorld } from './support/scenes.js';

const L = 1;
const DT = 1 / 60;
const STEPS = 1200; // 20 s

interface Swing {
  measured: number;
  expected: number;
  crossings: number;
  report: string;
}

/**
 * Swings a bob in the plane of axes 1 (down) and `side` (the swing direction), from θ₀, and
 * returns the measured and the expected period.
 */
function swing(n: number, side: number, bob: 'ball' | 'box', seed: number): Swing {
  const rand = seeded(seed);
  const theta0 = uniform(rand, 0.08, 0.12);
  const world = makeWorld(n);
  const D = world.D;
  const m = 1;
  const position = new Array<number>(n).fill(0);
  position[side] = L * Math.sin(theta0);
  position[1] = -L * Math.cos(theta0);
  let Icm: number;
  let shape;
  if (bob === 'ball') {
    const rho = 0.05;
    shape = HyperSphere(D, rho);
    Icm = (2 * m * rho * rho) / (n + 2);
  } else {
    const half = new Array<number>(n).fill(0.1);
    half[side] = 0.3;
    half[1] = 0.3;
    shape = HyperBox(D, half);
    Icm = (m * (half[side]! ** 2 + half[1]! ** 2)) / 3;
  }
  const body = world.addBody(new Body(D, { shape, mass: m, position }));
  // The anchor on the bob is the pivot (the origin) seen from the bob's centre (identity rotor).
  const localA = position.map((p) => -p);
  world.addConstraint(new PointJoint(body, null, localA, new Array<number>(n).fill(0)));
  const times: number[] = [];
  let prev = body.x[side]!;
  for (let s = 1; s <= STEPS; s += 1) {
    world.step(DT);
    const x = body.x[side]!;
    if ((prev > 0 && x <= 0) || (prev < 0 && x >= 0)) times.push((s - 1 + prev / (prev - x)) * DT);
    prev = x;
  }
  // Crossings are half a period apart: use the first and the last of an odd count of crossings
  // (a whole number of periods).
  const usable = times.length % 2 === 1 ? times.length : times.length - 1;
  const measured = (2 * (times[usable - 1]! - times[0]!)) / (usable - 1);
  const expected = 2 * Math.PI * Math.sqrt((m * L * L + Icm) / (m * G * L)) * (1 + theta0 ** 2 / 16);
  const report = `n = ${n}, ${bob} bob, swing plane (1, ${side}), θ₀ = ${theta0.toFixed(4)}: T = ${measured.toFixed(5)} s, formula ${expected.toFixed(5)} s (${(((measured - expected) / expected) * 100).toFixed(3)} %; the point-mass formula ${(2 * Math.PI * Math.sqrt(L / G) * (1 + theta0 ** 2 / 16)).toFixed(5)} s), ${times.length} crossings`;
  console.log(report);
  return { measured, expected, crossings: times.length, report };
}

describe("identity 23: a pendulum on a point joint, T = 2π√(l/g)(1 + θ₀²/16) (+ the bob's inertia)", () => {
  it('identity 23, 3D: a small ball (ρ 0.05) on l = 1 m swings with the period of the formula within 1 %', () => {
    const r = swing(3, 0, 'ball', 2301);
    expect(r.crossings, r.report).toBeGreaterThanOrEqual(17);
    expect(Math.abs(r.measured - r.expected) / r.expected, r.report).toBeLessThan(0.01);
  });

  it('identity 23, 4D: the same ball swinging in the (y w) plane has the period of the formula within 1 %', () => {
    const r = swing(4, 3, 'ball', 2302);
    expect(r.crossings, r.report).toBeGreaterThanOrEqual(17);
    expect(Math.abs(r.measured - r.expected) / r.expected, r.report).toBeLessThan(0.01);
  });

  it('identity 23, 4D: a ball swinging in the (x y) plane (no w) has the period of the formula within 1 %', () => {
    const r = swing(4, 0, 'ball', 2303);
    expect(Math.abs(r.measured - r.expected) / r.expected, r.report).toBeLessThan(0.01);
  });

  it("identity 23 with the bob's own inertia, 3D: a box bob (0.6 × 0.6 in the swing plane, I_cm = 0.06 m l²) within 1 % of the physical-pendulum period, which is 3 % above the point-mass one", () => {
    const r = swing(3, 0, 'box', 2304);
    expect(Math.abs(r.measured - r.expected) / r.expected, r.report).toBeLessThan(0.01);
  });
});
