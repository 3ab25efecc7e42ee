/**
 * Small scene builders for the contact-physics tests (tests/solver-*.test.ts).
 *
 * Convention: axis 1 ("y") is up; gravity is −g e_1. Every world built here turns sleep off unless
 * the caller asks otherwise, so a test measures the solver and not the sleep heuristic.
 */
import { Body, dims, HalfSpace, HyperBox, HyperSphere, World } from '@physin/engine';
import type { Material, Params } from '@physin/engine';

/** Standard gravity used by every scene here (m/s²). */
export const G = 9.81;

/** The vector −g e_1 in n dimensions (or zero with g = 0). */
export function gravity(n: number, g = G): number[] {
  const out = new Array<number>(n).fill(0);
  out[1] = -g;
  return out;
}

/** e_axis · scale, n components. */
export function axis(n: number, a: number, scale = 1): number[] {
  const out = new Array<number>(n).fill(0);
  out[a] = scale;
  return out;
}

/** A world of n dimensions with gravity −g e_1 and `allowSleep: false` unless `params` says otherwise. */
export function makeWorld(n: number, params: Partial<Params> = {}, g = G): World {
  return new World({ dimensions: n, gravity: gravity(n, g), params: { allowSleep: false, ...params } });
}

/** Adds the static ground {x : x_1 <= 0} (or a half-space of the given normal and offset). */
export function addGround(
  world: World,
  material: Partial<Material> = {},
  normal: ArrayLike<number> = axis(world.n, 1),
  offset = 0,
): Body {
  const D = world.D;
  return world.addBody(new Body(D, { shape: HalfSpace(D, normal, offset), mass: 0, material, name: 'ground' }));
}

/** Adds a dynamic hyperbox with the given half-extents (a number means a hypercube). */
export function addBox(
  world: World,
  position: ArrayLike<number>,
  half: number | ArrayLike<number>,
  options: { mass?: number; material?: Partial<Material>; name?: string; velocity?: ArrayLike<number> } = {},
): Body {
  const D = world.D;
  const he = typeof half === 'number' ? new Array<number>(world.n).fill(half) : Array.from(half);
  return world.addBody(new Body(D, { shape: HyperBox(D, he), mass: options.mass ?? 1, position, ...options }));
}

/** Adds a dynamic hypersphere. */
export function addBall(
  world: World,
  position: ArrayLike<number>,
  radius: number,
  options: {
    mass?: number;
    material?: Partial<Material>;
    name?: string;
    velocity?: ArrayLike<number>;
    angularVelocity?: ArrayLike<number>;
  } = {},
): Body {
  return world.addBody(
    new Body(dims(world.n), { shape: HyperSphere(dims(world.n), radius), mass: options.mass ?? 1, position, ...options }),
  );
}

/** Steps the world `steps` times at dt, calling `each(stepIndex)` after every step (1-based). */
export function run(world: World, steps: number, dt = 1 / 60, each?: (step: number) => void): void {
  for (let s = 1; s <= steps; s += 1) {
    world.step(dt);
    if (each) each(s);
  }
}

/**
 * A vertical stack of `count` hypercubes of half-extent `half`, resting on the ground x_1 = 0,
 * each placed exactly touching the one below (box i centred at height half·(2i + 1)). Returns the
 * boxes, bottom first.
 */
export function addStack(world: World, count: number, half: number, material: Partial<Material> = {}): Body[] {
  const out: Body[] = [];
  for (let i = 0; i < count; i += 1) {
    out.push(addBox(world, axis(world.n, 1, half * (2 * i + 1)), half, { material, name: `box${i}` }));
  }
  return out;
}

/**
 * A pyramid in the x-y plane of 3D: a base row of `rows` unit boxes 1.05 m apart, each row one box
 * shorter and centred on the one below, touching it. Returns the boxes, base row first.
 */
export function addPyramid(world: World, rows: number): Body[] {
  const boxes: Body[] = [];
  for (let row = 0; row < rows; row += 1) {
    const count = rows - row;
    for (let i = 0; i < count; i += 1) boxes.push(addBox(world, [(i - (count - 1) / 2) * 1.05, 0.5 + row, 0], 0.5));
  }
  return boxes;
}

/** Largest |x_d − ref_d| over the non-vertical axes d != 1. */
export function horizontalDrift(x: ArrayLike<number>, ref: ArrayLike<number>): number {
  let m = 0;
  for (let d = 0; d < x.length; d += 1) if (d !== 1) m = Math.max(m, Math.abs(x[d]! - ref[d]!));
  return m;
}

/** Euclidean distance |a − b|. */
export function distance(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let s = 0;
  for (let d = 0; d < a.length; d += 1) s += (a[d]! - b[d]!) ** 2;
  return Math.sqrt(s);
}

/** a·b. */
export function dot(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let s = 0;
  for (let d = 0; d < a.length; d += 1) s += a[d]! * b[d]!;
  return s;
}

/** Σ m v over the bodies (total linear momentum). */
export function momentum(bodies: readonly Body[]): Float64Array {
  const out = new Float64Array(bodies[0]!.D.n);
  for (const b of bodies) for (let d = 0; d < out.length; d += 1) out[d] = out[d]! + b.mass * b.v[d]!;
  return out;
}

/** Σ kinetic energy over the bodies. */
export function kinetic(bodies: readonly Body[]): number {
  let s = 0;
  for (const b of bodies) s += b.kineticEnergy();
  return s;
}
