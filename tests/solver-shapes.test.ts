/**
 * The contact solver with the shapes beyond boxes and balls (seed test plan 9 and 10), and the
 * determinism of the whole step:
 * - a torus on the ground lying flat (centre at r) and on its rim (centre at R + r), 3D and 4D;
 *   a torus tipped off its rim falls flat; a ball falls through the hole of a static torus and
 *   rests on its tube at the analytic height;
 * - a convex mesh on the ground: a cross polytope on a facet (s/√n) and on a vertex (s), a box
 *   given as a mesh (its half height); a ball touches a static mesh at the nearest point of a
 *   facet (simplex);
 * - the same seeded pile stepped in two fresh worlds gives bit-identical states (3D, 4D).
 *
 * Every scene is built from exact or seeded inputs; allowSleep is false everywhere (sleep is the
 * subject of solver-sleep-events.test.ts).
 */
import { describe, expect, it } from 'vitest';
import { Body, ConvexMesh, dims, HalfSpace, HyperBox, HyperSphere, HyperTorus, World } from '@physin/engine';
import type { Shape } from '@physin/engine';
import { randomArray, seeded, uniform } from './support/random.js';
import { cubeBoundary } from './support/meshes.js';

const G = 9.81;
const SLOP = 0.005; // defaultParams.penetrationSlop
const H = 1 / 60;

function gravity(n: number): number[] {
  const g = new Array<number>(n).fill(0);
  g[1] = -G;
  return g;
}

function at(n: number, values: Record<number, number>): number[] {
  const p = new Array<number>(n).fill(0);
  for (const [k, v] of Object.entries(values)) p[Number(k)] = v;
  return p;
}

/** A world with gravity −G e_y, a static ground y <= 0, sleep off. */
function groundWorld(n: number, params: Record<string, unknown> = {}): World {
  const D = dims(n);
  const world = new World({ dimensions: n, gravity: gravity(n), params: { allowSleep: false, ...params } });
  world.addBody(
    new Body(D, {
      shape: HalfSpace(D, at(n, { 1: 1 }), 0),
      mass: 0,
      material: { friction: 0.6, restitution: 0 },
      name: 'ground',
    }),
  );
  return world;
}

function run(world: World, seconds: number, each?: () => void): void {
  const steps = Math.round(seconds / H);
  for (let i = 0; i < steps; i += 1) {
    world.step(H);
    each?.();
  }
}

function norm(a: ArrayLike<number>): number {
  let s = 0;
  for (let i = 0; i < a.length; i += 1) s += a[i]! * a[i]!;
  return Math.sqrt(s);
}

/** The world direction of local axis `axis` of a body (column of its rotation matrix). */
function localAxis(body: Body, axis: number): Float64Array {
  const n = body.D.n;
  const M = new Float64Array(n * n);
  body.D.kernels.toMatrix(M, body.R);
  const out = new Float64Array(n);
  for (let i = 0; i < n; i += 1) out[i] = M[i * n + axis]!;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Meshes built by the tests

/** The cross polytope |x|₁ <= s with vertices Q·(±s e_i) (Q a rotation, default identity); one facet per orthant. */
function crossPolytope(n: number, s: number, Q?: Float64Array): { vertices: number[][]; facets: number[][] } {
  const vertices: number[][] = [];
  for (let i = 0; i < n; i += 1) {
    for (const sign of [1, -1]) {
      const v = new Array<number>(n).fill(0);
      for (let r = 0; r < n; r += 1) v[r] = sign * s * (Q ? Q[r * n + i]! : r === i ? 1 : 0);
      vertices.push(v);
    }
  }
  const facets: number[][] = [];
  for (let mask = 0; mask < 1 << n; mask += 1) facets.push([...Array(n).keys()].map((i) => 2 * i + ((mask >> i) & 1)));
  return { vertices, facets };
}

/**
 * A rotation (det +1) that takes the unit vector u to −e_1 (down): the Householder reflection
 * u → −e_1 followed by the reflection x_0 → −x_0 (which fixes e_1).
 */
function rotationTakingToDown(u: number[]): Float64Array {
  const n = u.length;
  const w = u.slice();
  w[1] = w[1]! + 1; // u − (−e_1)
  const ww = w.reduce((s, x) => s + x * x, 0);
  const Q = new Float64Array(n * n);
  for (let r = 0; r < n; r += 1) {
    for (let c = 0; c < n; c += 1) Q[r * n + c] = (r === c ? 1 : 0) - (2 * w[r]! * w[c]!) / ww;
  }
  for (let c = 0; c < n; c += 1) Q[c] = -Q[c]!; // row 0 negated
  return Q;
}

// ---------------------------------------------------------------------------------------------

describe('torus on the ground (test plan 9)', () => {
  const R = 1;
  const r = 0.25;

  for (const n of [3, 4]) {
    it(`n = ${n}: lying flat (core plane (x, z)) it rests with its centre at r, within penetrationSlop + 1e-3, level (|normal_y| = 1 within 1e-9) and still (|v| < 1e-6)`, () => {
      const D = dims(n);
      const world = groundWorld(n);
      const torus = world.addBody(
        new Body(D, {
          shape: HyperTorus(D, R, r, [0, 2]),
          mass: 1,
          position: at(n, { 1: r + 0.1 }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      let lowest = Infinity;
      run(world, 3, () => (lowest = Math.min(lowest, torus.x[1]!)));
      expect(Math.abs(torus.x[1]! - r)).toBeLessThanOrEqual(SLOP + 1e-3);
      expect(lowest).toBeGreaterThanOrEqual(r - SLOP - 1e-3);
      // the axis normal to the core plane, local e_1 (y), stays vertical
      expect(Math.abs(Math.abs(localAxis(torus, 1)[1]!) - 1)).toBeLessThanOrEqual(1e-9);
      expect(norm(torus.v)).toBeLessThan(1e-6);
      expect(norm(torus.w)).toBeLessThan(1e-6);
    });

    it(`n = ${n}: on its rim (core plane (x, y) vertical) its centre rests at R + r within penetrationSlop + 1e-3 over 3 s; the core plane stays vertical (1e-9)`, () => {
      const D = dims(n);
      const world = groundWorld(n);
      const torus = world.addBody(
        new Body(D, {
          shape: HyperTorus(D, R, r, [0, 1]),
          mass: 1,
          position: at(n, { 1: R + r + 0.05 }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      run(world, 0.5);
      let worst = 0;
      run(world, 2.5, () => (worst = Math.max(worst, Math.abs(torus.x[1]! - (R + r)))));
      expect(worst).toBeLessThanOrEqual(SLOP + 1e-3);
      // the core plane's normal directions (local axes 2..n−1) stay horizontal: no tipping
      for (let k = 2; k < n; k += 1) expect(Math.abs(localAxis(torus, k)[1]!)).toBeLessThanOrEqual(1e-9);
    });

    it(`n = ${n}: standing still on its rim it stays still — rolling is neutral, nothing should start it (|v| < 1e-6 m/s after 20 s)`, () => {
      // Physically the rolling mode (x, y) of a torus on its rim is neutral and the start is
      // exactly symmetric: no force can start it. A rounding-size start (1e-15) must not grow.
      const D = dims(n);
      const world = groundWorld(n);
      const torus = world.addBody(
        new Body(D, {
          shape: HyperTorus(D, R, r, [0, 1]),
          mass: 1,
          position: at(n, { 1: R + r }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      const energy = (): number => torus.kineticEnergy() + G * torus.x[1]!;
      const e0 = energy();
      run(world, 20);
      expect(norm(torus.v)).toBeLessThan(1e-6);
      expect(energy() - e0).toBeLessThanOrEqual(1e-9);
    });

    it(`n = ${n}: tipped 0.2 rad off its rim it falls over and ends lying flat, centre at r (penetrationSlop + 1e-3)`, () => {
      const D = dims(n);
      const world = groundWorld(n, { angularDamping: 0 });
      const body = new Body(D, {
        shape: HyperTorus(D, R, r, [0, 1]),
        mass: 1,
        position: at(n, { 1: R + r + 0.01 }),
        material: { friction: 0.6, restitution: 0 },
      });
      body.rotateInPlane(1, 2, 0.2); // tips the core plane toward z
      const torus = world.addBody(body);
      run(world, 10);
      expect(Math.abs(torus.x[1]! - r)).toBeLessThanOrEqual(SLOP + 1e-3);
      // flat: the core plane is horizontal, so the up direction has no component in it
      const ui = localAxis(torus, 0)[1]!;
      const uj = localAxis(torus, 1)[1]!;
      expect(Math.hypot(ui, uj)).toBeLessThan(1e-2);
    });
  }

  for (const n of [3, 4]) {
    it(`n = ${n}: a ball (ρ = 0.3 < R − r) dropped on the axis of a static flat torus falls through the hole untouched (free fall to 1e-12, no contact event)`, () => {
      const D = dims(n);
      const world = new World({ dimensions: n, gravity: gravity(n), params: { allowSleep: false } });
      const H0 = 2;
      world.addBody(new Body(D, { shape: HyperTorus(D, R, r, [0, 2]), mass: 0, position: at(n, { 1: H0 }), name: 'ring' }));
      const y0 = H0 + 1.5;
      const ball = world.addBody(new Body(D, { shape: HyperSphere(D, 0.3), mass: 1, position: at(n, { 1: y0 }) }));
      let begins = 0;
      const steps = 60;
      for (let i = 0; i < steps; i += 1) {
        world.step(H);
        begins += world.contactEvents.beginCount;
      }
      // symplectic Euler: y_N = y0 − g h² N(N+1)/2
      const y = y0 - (G * H * H * steps * (steps + 1)) / 2;
      expect(ball.x[1]!).toBeLessThan(H0 - r - 0.3); // below the ring
      expect(Math.abs(ball.x[1]! - y)).toBeLessThanOrEqual(1e-12);
      expect(Math.abs(ball.v[1]! + G * H * steps)).toBeLessThanOrEqual(1e-12);
      for (let k = 0; k < n; k += 1) if (k !== 1) expect(ball.x[k]).toBe(0);
      expect(begins).toBe(0);
    });

    it(`n = ${n}: a ball dropped above the core circle comes to rest on the tube at H + r + ρ (penetrationSlop + 1e-3), directly above it`, () => {
      const D = dims(n);
      const world = new World({ dimensions: n, gravity: gravity(n), params: { allowSleep: false } });
      const H0 = 2;
      const rho = 0.2;
      world.addBody(
        new Body(D, {
          shape: HyperTorus(D, R, r, [0, 2]),
          mass: 0,
          position: at(n, { 1: H0 }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      const ball = world.addBody(
        new Body(D, {
          shape: HyperSphere(D, rho),
          mass: 1,
          position: at(n, { 0: R, 1: H0 + r + rho + 0.5 }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      run(world, 3);
      expect(Math.abs(ball.x[1]! - (H0 + r + rho))).toBeLessThanOrEqual(SLOP + 1e-3);
      expect(Math.abs(ball.x[0]! - R)).toBeLessThanOrEqual(1e-9);
      expect(norm(ball.v)).toBeLessThan(1e-6);
    });
  }
});

describe('convex mesh on the ground and against a ball (test plan 10)', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a cross polytope |x|₁ <= 0.5 resting on a facet has its centre at s/√n (penetrationSlop + 1e-3), the facet flat on the ground (1e-6)`, () => {
      const D = dims(n);
      const s = 0.5;
      const u = new Array<number>(n).fill(1 / Math.sqrt(n));
      const Q = rotationTakingToDown(u); // facet normal (1, …, 1)/√n points down
      const cp = crossPolytope(n, s, Q);
      const shape = ConvexMesh(D, cp.vertices, cp.facets);
      const world = groundWorld(n);
      const body = world.addBody(
        new Body(D, {
          shape,
          mass: 1,
          position: at(n, { 1: s / Math.sqrt(n) + 0.05 }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      run(world, 3);
      expect(Math.abs(body.x[1]! - s / Math.sqrt(n))).toBeLessThanOrEqual(SLOP + 1e-3);
      // the n vertices of the facet are all at the lowest height (within 1e-6 of each other)
      const M = new Float64Array(n * n);
      D.kernels.toMatrix(M, body.R);
      const heights: number[] = [];
      for (let v = 0; v < shape.vertexCount; v += 1) {
        let y = body.x[1]!;
        for (let c = 0; c < n; c += 1) y += M[n + c]! * shape.vertices[v * n + c]!;
        heights.push(y);
      }
      heights.sort((a, b) => a - b);
      expect(heights[n - 1]! - heights[0]!).toBeLessThanOrEqual(1e-6);
      expect(heights[n]! - heights[0]!).toBeGreaterThan(0.1);
      expect(norm(body.v)).toBeLessThan(1e-6);
    });

    it(`n = ${n}: a cross polytope balanced on its vertex −s e_y (symmetric start, friction 0.6) rests with its centre at s (penetrationSlop + 1e-3)`, () => {
      const D = dims(n);
      const s = 0.5;
      const cp = crossPolytope(n, s);
      const world = groundWorld(n);
      const body = world.addBody(
        new Body(D, {
          shape: ConvexMesh(D, cp.vertices, cp.facets),
          mass: 1,
          position: at(n, { 1: s + 0.05 }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      let worst = 0;
      run(world, 1);
      run(world, 2, () => (worst = Math.max(worst, Math.abs(body.x[1]! - s))));
      expect(worst).toBeLessThanOrEqual(SLOP + 1e-3);
    });

    it(`n = ${n}: a cross polytope tipped 0.3 rad off its vertex falls onto a facet: centre at s/√n (penetrationSlop + 1e-3)`, () => {
      const D = dims(n);
      const s = 0.5;
      const cp = crossPolytope(n, s);
      const world = groundWorld(n);
      const b = new Body(D, {
        shape: ConvexMesh(D, cp.vertices, cp.facets),
        mass: 1,
        position: at(n, { 1: s + 0.01 }),
        material: { friction: 0.6, restitution: 0 },
      });
      b.rotateInPlane(0, 1, 0.3);
      b.rotateInPlane(1, 2, 0.2);
      if (n > 3) b.rotateInPlane(1, 3, 0.1);
      const body = world.addBody(b);
      run(world, 6);
      expect(Math.abs(body.x[1]! - s / Math.sqrt(n))).toBeLessThanOrEqual(SLOP + 1e-3);
      expect(norm(body.v)).toBeLessThan(1e-3);
    });

    it(`n = ${n}: a box given as a mesh (Kuhn-triangulated facets) rests at its half height, like the HyperBox (penetrationSlop + 1e-3); no creep (1e-6)`, () => {
      const D = dims(n);
      const a = [0.4, 0.3, 0.5, 0.35].slice(0, n);
      const mesh = cubeBoundary(a.length, a);
      const shape = ConvexMesh(D, mesh.vertices, mesh.facets);
      const world = groundWorld(n);
      const asMesh = world.addBody(
        new Body(D, { shape, mass: 1, position: at(n, { 1: 0.4 }), material: { friction: 0.6, restitution: 0 } }),
      );
      const asBox = world.addBody(
        new Body(D, {
          shape: HyperBox(D, a),
          mass: 1,
          position: at(n, { 0: 3, 1: 0.4 }),
          material: { friction: 0.6, restitution: 0 },
        }),
      );
      run(world, 3);
      expect(Math.abs(asMesh.x[1]! - a[1]!)).toBeLessThanOrEqual(SLOP + 1e-3);
      expect(Math.abs(asBox.x[1]! - a[1]!)).toBeLessThanOrEqual(SLOP + 1e-3);
      // it lands flat and stays where it fell (no sideways creep beyond 1e-6 m), at rest
      for (let k = 0; k < n; k += 1) if (k !== 1) expect(Math.abs(asMesh.x[k]!)).toBeLessThanOrEqual(1e-6);
      expect(norm(asMesh.v)).toBeLessThan(1e-6);
      expect(norm(asMesh.w)).toBeLessThan(1e-6);
    });
  }

  for (const n of [3, 4]) {
    it(`n = ${n}: a ball lowered onto a static cross polytope touches a facet at the analytic nearest point (tangentially 1e-9, off the plane <= 1e-3); normal = the facet normal (1e-9)`, () => {
      const D = dims(n);
      const s = 1;
      const rho = 0.25;
      const cp = crossPolytope(n, s);
      const world = new World({ dimensions: n, gravity: gravity(n), params: { allowSleep: false } });
      const mesh = world.addBody(new Body(D, { shape: ConvexMesh(D, cp.vertices, cp.facets), mass: 0, name: 'mesh' }));
      // The facet x_k >= 0 for all k (normal (1, …, 1)/√n, offset s/√n). Put the ball's centre at
      // c = q + (ρ + gap) N, with q a point inside that facet, so its nearest mesh point is q.
      const N = new Array<number>(n).fill(1 / Math.sqrt(n));
      const rand = seeded(90 + n);
      const bary = randomArray(rand, n, 0.5, 1.5);
      const total = bary.reduce((x, y) => x + y, 0);
      const q = Array.from(bary, (b) => (s * b) / total); // Σ q = s, all > 0: interior of the facet
      const gap = 0.0005;
      const c0 = q.map((qi, i) => qi + (rho + gap) * N[i]!);
      const ball = world.addBody(new Body(D, { shape: HyperSphere(D, rho), mass: 1, position: c0, name: 'ball' }));
      let found = false;
      let prev = Float64Array.from(ball.x);
      for (let i = 0; i < 30 && !found; i += 1) {
        world.step(H);
        const ev = world.contactEvents;
        for (let e = 0; e < ev.beginCount; e += 1) {
          found = true;
          const meshFirst = ev.beginA[e] === mesh;
          expect(meshFirst || ev.beginB[e] === mesh).toBe(true);
          const p = Array.from(ev.beginPoint.subarray(e * n, e * n + n));
          const normal = Array.from(ev.beginNormal.subarray(e * n, e * n + n));
          // the manifold was computed at the ball's centre before this step: its analytic
          // nearest point is that centre projected onto the facet plane
          const dist = prev.reduce((acc, x, k) => acc + x * N[k]!, 0) - s / Math.sqrt(n);
          const nearest = Array.from(prev, (x, k) => x - dist * N[k]!);
          // p lies on the segment from the nearest point out along N: the same tangential part
          const off = p.reduce((acc, x, k) => acc + (x - nearest[k]!) * N[k]!, 0);
          for (let k = 0; k < n; k += 1) expect(Math.abs(p[k]! - off * N[k]! - nearest[k]!)).toBeLessThanOrEqual(1e-9);
          expect(Math.abs(off)).toBeLessThanOrEqual(1e-3);
          for (let k = 0; k < n; k += 1) expect(Math.abs(p[k]! - q[k]!)).toBeLessThanOrEqual(1e-3);
          // the point is inside the facet: barycentric coordinates p_k / Σ p all positive
          for (let k = 0; k < n; k += 1) expect(p[k]!).toBeGreaterThan(0);
          const sign = meshFirst ? 1 : -1; // normal from A to B: out of the mesh when the mesh is A
          for (let k = 0; k < n; k += 1) expect(Math.abs(normal[k]! - sign * N[k]!)).toBeLessThanOrEqual(1e-9);
        }
        if (!found) prev = Float64Array.from(ball.x);
      }
      expect(found).toBe(true);
    });
  }
});

// ---------------------------------------------------------------------------------------------

/** A seeded pile: `count` boxes and balls over a ground, spread in a column, random turns. */
function pile(n: number, seed: number, count: number): World {
  const D = dims(n);
  const rand = seeded(seed);
  const world = groundWorld(n);
  for (let i = 0; i < count; i += 1) {
    const position = randomArray(rand, n, -1.2, 1.2);
    position[1] = 0.6 + 0.55 * i;
    let shape: Shape;
    if (i % 2 === 0) shape = HyperBox(D, Array.from(randomArray(rand, n, 0.15, 0.3)));
    else shape = HyperSphere(D, uniform(rand, 0.15, 0.3));
    const b = new Body(D, {
      shape,
      mass: uniform(rand, 0.5, 2),
      position,
      velocity: randomArray(rand, n, -0.5, 0.5),
      angularVelocity: randomArray(rand, D.k, -1, 1),
      material: { friction: uniform(rand, 0.2, 0.8), restitution: uniform(rand, 0, 0.3) },
    });
    world.addBody(b);
  }
  return world;
}

describe('determinism', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: a seeded pile of 30 boxes and balls stepped 2 s in two fresh worlds gives bit-identical states (every x, R, v, L, w)`, () => {
      const a = pile(n, 600 + n, 30);
      const b = pile(n, 600 + n, 30);
      let touching = 0;
      for (let i = 0; i < 120; i += 1) {
        a.step(H);
        b.step(H);
        touching = Math.max(touching, a.touchingCount);
      }
      expect(touching).toBeGreaterThan(10); // the pile did collide
      expect(a.bodies.length).toBe(b.bodies.length);
      for (let i = 0; i < a.bodies.length; i += 1) {
        const x = a.bodies[i]!;
        const y = b.bodies[i]!;
        for (const field of ['x', 'R', 'v', 'L', 'w'] as const) {
          const u = x[field];
          const v = y[field];
          expect(u.length).toBe(v.length);
          // exact: compare the bit patterns (so −0 vs 0 and NaN payloads count too)
          expect(new Uint8Array(u.buffer, u.byteOffset, u.byteLength)).toEqual(
            new Uint8Array(v.buffer, v.byteOffset, v.byteLength),
          );
        }
      }
      expect(a.contactCount).toBe(b.contactCount);
      expect(a.touchingCount).toBe(b.touchingCount);
    });
  }
});
