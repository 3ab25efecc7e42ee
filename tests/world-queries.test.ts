/**
 * World queries: `world.rayCast` against every shape in n = 2..6 (analytic hits built from a
 * known surface point, normal and entry direction), the closest of several bodies, misses, the
 * maxDistance cut-off, bodies that moved; `world.queryBox` against a brute force over the bounding
 * boxes of seeded random scenes; bad arguments throw and change nothing.
 */
import { describe, expect, it } from 'vitest';
import { Body, ConvexMesh, dims, HalfSpace, HyperBox, HyperSphere, HyperTorus, World, castRay, queryBox } from '@physin/engine';
import type { ConvexMeshShape, Dims, Shape } from '@physin/engine';
import { randomArray, randomUnitVector, seeded, uniform } from './support/random.js';

const DIMS = [2, 3, 4, 5, 6];
const TOL = 1e-9;
const TORUS_TOL = 1e-6;

// ---------------------------------------------------------------------------------------------
// Small vector helpers

function dot(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let s = 0;
  for (let i = 0; i < a.length; i += 1) s += a[i]! * b[i]!;
  return s;
}

function axpy(x: ArrayLike<number>, t: number, d: ArrayLike<number>): Float64Array {
  const out = new Float64Array(x.length);
  for (let i = 0; i < x.length; i += 1) out[i] = x[i]! + t * d[i]!;
  return out;
}

function maxDiff(a: ArrayLike<number>, b: ArrayLike<number>): number {
  expect(a.length).toBe(b.length);
  let m = 0;
  for (let i = 0; i < a.length; i += 1) m = Math.max(m, Math.abs(a[i]! - b[i]!));
  return m;
}

/** The body's rotation matrix, row-major: M[i*n + c] = component i of local axis c. */
function matrixOf(body: Body): Float64Array {
  const n = body.D.n;
  const M = new Float64Array(n * n);
  body.D.kernels.toMatrix(M, body.R);
  return M;
}

/** world = x + M·local */
function toWorld(body: Body, local: ArrayLike<number>): Float64Array {
  const n = body.D.n;
  const M = matrixOf(body);
  const out = Float64Array.from(body.x);
  for (let i = 0; i < n; i += 1) for (let c = 0; c < n; c += 1) out[i] = out[i]! + M[i * n + c]! * local[c]!;
  return out;
}

/** M·local (a direction) */
function dirToWorld(body: Body, local: ArrayLike<number>): Float64Array {
  const n = body.D.n;
  const M = matrixOf(body);
  const out = new Float64Array(n);
  for (let i = 0; i < n; i += 1) for (let c = 0; c < n; c += 1) out[i] = out[i]! + M[i * n + c]! * local[c]!;
  return out;
}

/** Turns a body by seeded angles in every plane (before it joins a world). */
function randomTurn(body: Body, rand: () => number): Body {
  const n = body.D.n;
  for (let i = 0; i < n; i += 1) for (let j = i + 1; j < n; j += 1) body.rotateInPlane(i, j, uniform(rand, -Math.PI, Math.PI));
  return body;
}

/** A unit direction d with d·normal <= −0.2 (enters the surface whose outward normal is `normal`). */
function enteringDirection(rand: () => number, normal: ArrayLike<number>): Float64Array {
  for (;;) {
    const d = randomUnitVector(rand, normal.length);
    const c = dot(d, normal);
    if (c <= -0.2) return d;
    if (c >= 0.2) return d.map((x) => -x);
  }
}

/** The cross polytope |x|₁ <= s: vertices ±s e_i, one facet per orthant. */
function crossPolytope(D: Dims, s: number): ConvexMeshShape {
  const n = D.n;
  const vertices: number[][] = [];
  for (let i = 0; i < n; i += 1) {
    for (const sign of [1, -1]) {
      const v = new Array<number>(n).fill(0);
      v[i] = sign * s;
      vertices.push(v);
    }
  }
  const facets: number[][] = [];
  for (let mask = 0; mask < 1 << n; mask += 1) facets.push([...Array(n).keys()].map((i) => 2 * i + ((mask >> i) & 1)));
  return ConvexMesh(D, vertices, facets);
}

interface Expected {
  point: Float64Array;
  normal: Float64Array;
}

/**
 * A ray with a known first hit: it reaches the surface point p (outward normal N) from outside,
 * travelling `t` along an entering direction. For a convex solid, a ray that meets the boundary
 * at p going inward enters there, so p is the first hit.
 */
function rayTo(rand: () => number, p: Float64Array, N: Float64Array): { origin: Float64Array; dir: Float64Array; t: number } {
  const dir = enteringDirection(rand, N);
  const t = uniform(rand, 0.5, 3);
  return { origin: axpy(p, -t, dir), dir, t };
}

function expectHit(
  world: World,
  origin: Float64Array,
  dir: Float64Array,
  t: number,
  body: Body,
  ex: Expected,
  tol: number,
): void {
  // scale the direction: rayCast normalises it
  const scaled = dir.map((x) => 2.5 * x);
  const hit = castRay(world, origin, scaled, t + 10);
  expect(hit).not.toBeNull();
  expect(hit!.body).toBe(body);
  expect(Math.abs(hit!.distance - t)).toBeLessThanOrEqual(tol);
  expect(maxDiff(hit!.point, ex.point)).toBeLessThanOrEqual(tol);
  expect(maxDiff(hit!.normal, ex.normal)).toBeLessThanOrEqual(tol);
}

// ---------------------------------------------------------------------------------------------

describe('world.rayCast against each shape (analytic hits)', () => {
  for (const n of DIMS) {
    it(`n = ${n}: box, ball, half-space, convex mesh — distance, point, normal to 1e-9 (40 seeded rays each)`, () => {
      const D = dims(n);
      const rand = seeded(1000 + n);
      for (let trial = 0; trial < 40; trial += 1) {
        const world = new World({ dimensions: n });
        const kind = trial % 4;
        let body: Body;
        let p: Float64Array;
        let N: Float64Array;
        const x = randomArray(rand, n, -3, 3);
        if (kind === 0) {
          const a = randomArray(rand, n, 0.2, 1.2);
          body = world.addBody(randomTurn(new Body(D, { shape: HyperBox(D, a), mass: 1, position: x }), rand));
          // a point inside a random face
          const axis = Math.floor(rand() * n);
          const side = rand() < 0.5 ? -1 : 1;
          const local = new Float64Array(n);
          for (let c = 0; c < n; c += 1) local[c] = c === axis ? side * a[c]! : uniform(rand, -0.95, 0.95) * a[c]!;
          const nl = new Float64Array(n);
          nl[axis] = side;
          p = toWorld(body, local);
          N = dirToWorld(body, nl);
        } else if (kind === 1) {
          const rho = uniform(rand, 0.2, 1.5);
          body = world.addBody(new Body(D, { shape: HyperSphere(D, rho), mass: 1, position: x }));
          N = randomUnitVector(rand, n);
          p = axpy(x, rho, N);
        } else if (kind === 2) {
          const normal = randomUnitVector(rand, n);
          const offset = uniform(rand, -2, 2);
          body = world.addBody(new Body(D, { shape: HalfSpace(D, normal, offset), mass: 0 }));
          // a point of the plane normal·p = offset
          const q = randomArray(rand, n, -3, 3);
          p = axpy(q, offset - dot(normal, q), normal);
          N = Float64Array.from(normal);
        } else {
          const s = uniform(rand, 0.4, 1.5);
          const shape = crossPolytope(D, s);
          body = world.addBody(randomTurn(new Body(D, { shape, mass: 1, position: x }), rand));
          // a point inside a random facet (barycentric weights in [0.2, 1]); its normal from the
          // mesh's own planes in its principal frame
          const f = Math.floor(rand() * shape.facetCount);
          const w = randomArray(rand, n, 0.2, 1);
          const total = w.reduce((u, v) => u + v, 0);
          const local = new Float64Array(n);
          for (let k = 0; k < n; k += 1) {
            const v = shape.facets[f * n + k]!;
            for (let c = 0; c < n; c += 1) local[c] = local[c]! + (w[k]! / total) * shape.vertices[v * n + c]!;
          }
          p = toWorld(body, local);
          N = dirToWorld(body, shape.facetNormals.subarray(f * n, f * n + n));
          // sanity of the test's own geometry: the point is on that facet plane
          expect(
            Math.abs(dot(shape.facetNormals.subarray(f * n, f * n + n), local) - shape.facetOffsets[f]!),
          ).toBeLessThanOrEqual(1e-12);
        }
        const { origin, dir, t } = rayTo(rand, p, N);
        expectHit(world, origin, dir, t, body, { point: p, normal: N }, TOL);
      }
    });

    it(`n = ${n}: torus (core plane random, body turned) — rays along a non-core axis through the tube and radial rays in the core plane, outside in and from the hole out, to 1e-6`, () => {
      const D = dims(n);
      const rand = seeded(2000 + n);
      for (let trial = 0; trial < 30; trial += 1) {
        const world = new World({ dimensions: n });
        const R = uniform(rand, 0.8, 1.5);
        const r = uniform(rand, 0.1, 0.5);
        const i = Math.floor(rand() * n);
        let j = Math.floor(rand() * (n - 1));
        if (j >= i) j += 1;
        const x = randomArray(rand, n, -3, 3);
        const body = world.addBody(randomTurn(new Body(D, { shape: HyperTorus(D, R, r, [i, j]), mass: 1, position: x }), rand));
        const phi = uniform(rand, -Math.PI, Math.PI);
        const radial = new Float64Array(n);
        radial[i] = Math.cos(phi);
        radial[j] = Math.sin(phi);
        const others = [...Array(n).keys()].filter((k) => k !== i && k !== j);
        const family = others.length > 0 ? trial % 3 : 1 + (trial % 2);
        let originLocal: Float64Array;
        let dirLocal: Float64Array;
        let pLocal: Float64Array;
        let nLocal: Float64Array;
        let t: number;
        if (family === 0) {
          // parallel to a non-core axis k at radial offset s from the core circle: the line meets
          // the solid where (s)² + x_k² <= r², one interval
          const k = others[Math.floor(rand() * others.length)]!;
          const s = uniform(rand, -0.9, 0.9) * r;
          const top = Math.sqrt(r * r - s * s);
          const start = top + uniform(rand, 0.5, 2);
          originLocal = radial.map((c) => c * (R + s));
          originLocal[k] = start;
          dirLocal = new Float64Array(n);
          dirLocal[k] = -1;
          t = start - top;
          pLocal = Float64Array.from(originLocal);
          pLocal[k] = top;
          nLocal = radial.map((c) => (c * s) / r);
          nLocal[k] = top / r;
        } else if (family === 1) {
          // radially inward from outside, in the core plane: meets the outer equator
          const gap = uniform(rand, 0.3, 2);
          originLocal = radial.map((c) => c * (R + r + gap));
          dirLocal = radial.map((c) => -c);
          t = gap;
          pLocal = radial.map((c) => c * (R + r));
          nLocal = Float64Array.from(radial);
        } else {
          // from the centre of the hole outward: meets the inner equator at R − r
          originLocal = new Float64Array(n);
          dirLocal = Float64Array.from(radial);
          t = R - r;
          pLocal = radial.map((c) => c * (R - r));
          nLocal = radial.map((c) => -c);
        }
        const origin = toWorld(body, originLocal);
        const dir = dirToWorld(body, dirLocal);
        expectHit(world, origin, dir, t, body, { point: toWorld(body, pLocal), normal: dirToWorld(body, nLocal) }, TORUS_TOL);
      }
    });
  }
});

describe('world.rayCast over several bodies', () => {
  for (const n of DIMS) {
    it(`n = ${n}: the closest of 8 balls along a line; a miss is null; maxDistance cuts at the hit (t ± 1e-6); a ray starting inside hits at 0`, () => {
      const D = dims(n);
      const rand = seeded(3000 + n);
      const world = new World({ dimensions: n });
      const origin = randomArray(rand, n, -1, 1);
      const dir = randomUnitVector(rand, n);
      const balls: { body: Body; t: number; rho: number }[] = [];
      for (let i = 0; i < 8; i += 1) {
        const along = 2 + 3 * i + uniform(rand, 0, 1);
        const rho = uniform(rand, 0.3, 0.8);
        const body = new Body(D, { shape: HyperSphere(D, rho), mass: 1, position: axpy(origin, along, dir) });
        balls.push({ body, t: along - rho, rho });
      }
      // insert in a scrambled order so the nearest is not the first added
      for (const i of [5, 2, 7, 0, 3, 6, 1, 4]) world.addBody(balls[i]!.body);
      // plus a half-space far behind the origin
      world.addBody(new Body(D, { shape: HalfSpace(D, dir, -50), mass: 0 })); // far behind the origin
      const hit = castRay(world, origin, dir, 100);
      expect(hit!.body).toBe(balls[0]!.body);
      expect(Math.abs(hit!.distance - balls[0]!.t)).toBeLessThanOrEqual(TOL);
      expect(
        maxDiff(
          hit!.normal,
          dir.map((c) => -c),
        ),
      ).toBeLessThanOrEqual(TOL);
      // cut-off just before and just after the first hit
      expect(castRay(world, origin, dir, balls[0]!.t - 1e-6)).toBeNull();
      expect(castRay(world, origin, dir, balls[0]!.t + 1e-6)!.body).toBe(balls[0]!.body);
      expect(castRay(world, origin, dir, 0)).toBeNull();
      // from just past ball 2 toward ball 3
      const from = axpy(origin, balls[2]!.t + 2 * balls[2]!.rho + 0.05, dir);
      const next = castRay(world, from, dir, 100)!;
      expect(next.body).toBe(balls[3]!.body);
      expect(Math.abs(next.distance - (balls[3]!.t - (balls[2]!.t + 2 * balls[2]!.rho + 0.05)))).toBeLessThanOrEqual(TOL);
      // pointing away: only the half-space far behind, which it never reaches going forward...
      expect(
        castRay(
          world,
          origin,
          dir.map((c) => -c),
          40,
        ),
      ).toBeNull();
      // ...but a long enough ray does reach it: distance 50 + origin·dir
      const back = castRay(
        world,
        origin,
        dir.map((c) => -c),
        100,
      )!;
      expect(Math.abs(back.distance - (50 + dot(dir, origin)))).toBeLessThanOrEqual(TOL);
      // starting inside ball 4: distance 0 at the origin
      const inside = axpy(origin, balls[4]!.t + balls[4]!.rho * 0.5, dir);
      const hit0 = castRay(world, inside, randomUnitVector(rand, n), 10)!;
      expect(hit0.body).toBe(balls[4]!.body);
      expect(hit0.distance).toBe(0);
      expect(maxDiff(hit0.point, inside)).toBeLessThanOrEqual(TOL);
    });
  }

  for (const n of [2, 3, 4]) {
    it(`n = ${n}: bodies that moved are hit where they are now — after steps under gravity, after setPositionN, after removeBody (1e-9)`, () => {
      const D = dims(n);
      const g = new Array<number>(n).fill(0);
      g[1] = -9.81;
      const world = new World({ dimensions: n, gravity: g, params: { allowSleep: false } });
      const pos = new Array<number>(n).fill(0);
      pos[1] = 10;
      const ball = world.addBody(new Body(D, { shape: HyperSphere(D, 0.5), mass: 1, position: pos }));
      const box = world.addBody(
        new Body(D, { shape: HyperBox(D, new Array(n).fill(0.5)), mass: 1, position: pos.map((c, k) => (k === 0 ? 5 : c)) }),
      );
      const down = new Array<number>(n).fill(0);
      down[1] = -1;
      const above = new Array<number>(n).fill(0);
      above[1] = 20;
      expect(castRay(world, above, down, 100)!.distance).toBeCloseTo(20 - 10.5, 12);
      for (let i = 0; i < 45; i += 1) world.step(1 / 60);
      expect(ball.x[1]!).toBeLessThan(8); // fell 10 − g h² N(N+1)/2 = 7.18
      let hit = castRay(world, above, down, 100)!;
      expect(hit.body).toBe(ball);
      expect(Math.abs(hit.distance - (20 - ball.x[1]! - 0.5))).toBeLessThanOrEqual(TOL);
      // the old place is empty now: a ray ending above the ball's top misses
      expect(castRay(world, above, down, 20 - ball.x[1]! - 0.5 - 1e-6)).toBeNull();
      const aboveBox = above.map((c, k) => (k === 0 ? 5 : c));
      hit = castRay(world, aboveBox, down, 100)!;
      expect(hit.body).toBe(box);
      expect(Math.abs(hit.distance - (20 - box.x[1]! - 0.5))).toBeLessThanOrEqual(TOL);
      // moved by hand (no step since)
      const moved = new Array<number>(n).fill(0);
      moved[1] = 3;
      ball.setPositionN(moved);
      hit = castRay(world, above, down, 100)!;
      expect(Math.abs(hit.distance - (20 - 3.5))).toBeLessThanOrEqual(TOL);
      // queryBox sees it there too
      expect(
        queryBox(
          world,
          moved.map((c) => c - 0.1),
          moved.map((c) => c + 0.1),
        ),
      ).toEqual([ball]);
      world.removeBody(ball);
      expect(castRay(world, above, down, 100)).toBeNull();
      expect(
        queryBox(
          world,
          moved.map((c) => c - 0.1),
          moved.map((c) => c + 0.1),
        ),
      ).toEqual([]);
    });
  }
});

// ---------------------------------------------------------------------------------------------

/** The exact world bounding box of a posed shape (the test's own version). */
function boundsOf(body: Body): { lo: Float64Array; hi: Float64Array } | { plane: Float64Array; offset: number } {
  const n = body.D.n;
  const M = matrixOf(body);
  const shape = body.shape as Shape & Record<string, unknown>;
  const lo = new Float64Array(n);
  const hi = new Float64Array(n);
  switch (shape.kind) {
    case 'box': {
      const a = shape.halfExtents as Float64Array;
      for (let k = 0; k < n; k += 1) {
        let e = 0;
        for (let c = 0; c < n; c += 1) e += Math.abs(M[k * n + c]!) * a[c]!;
        lo[k] = body.x[k]! - e;
        hi[k] = body.x[k]! + e;
      }
      break;
    }
    case 'sphere': {
      const rho = shape.radius as number;
      for (let k = 0; k < n; k += 1) {
        lo[k] = body.x[k]! - rho;
        hi[k] = body.x[k]! + rho;
      }
      break;
    }
    case 'torus': {
      const R = shape.majorRadius as number;
      const r = shape.minorRadius as number;
      const i = shape.planeI as number;
      const j = shape.planeJ as number;
      for (let k = 0; k < n; k += 1) {
        const e = R * Math.hypot(M[k * n + i]!, M[k * n + j]!) + r;
        lo[k] = body.x[k]! - e;
        hi[k] = body.x[k]! + e;
      }
      break;
    }
    case 'mesh': {
      const vs = shape.vertices as Float64Array;
      lo.fill(Infinity);
      hi.fill(-Infinity);
      for (let v = 0; v < vs.length / n; v += 1) {
        const w = toWorld(body, vs.subarray(v * n, v * n + n));
        for (let k = 0; k < n; k += 1) {
          lo[k] = Math.min(lo[k]!, w[k]!);
          hi[k] = Math.max(hi[k]!, w[k]!);
        }
      }
      break;
    }
    case 'halfspace': {
      const plane = dirToWorld(body, shape.normal as Float64Array);
      return { plane, offset: (shape.offset as number) + dot(plane, body.x) };
    }
  }
  return { lo, hi };
}

function bruteQuery(world: World, min: ArrayLike<number>, max: ArrayLike<number>): Body[] {
  const n = world.n;
  return world.bodies.filter((b) => {
    const bb = boundsOf(b);
    if ('plane' in bb) {
      // the box reaches the solid side: its lowest corner along the normal is on or below the plane
      let s = 0;
      for (let k = 0; k < n; k += 1) s += bb.plane[k]! * (bb.plane[k]! > 0 ? min[k]! : max[k]!);
      return s <= bb.offset;
    }
    for (let k = 0; k < n; k += 1) if (bb.lo[k]! > max[k]! || min[k]! > bb.hi[k]!) return false;
    return true;
  });
}

function randomScene(n: number, seed: number, count: number): World {
  const D = dims(n);
  const rand = seeded(seed);
  const g = new Array<number>(n).fill(0);
  g[1] = -9.81;
  const world = new World({ dimensions: n, gravity: g, params: { allowSleep: false } });
  const spread = 1.5 * Math.pow(count, 1 / n);
  const cp = crossPolytope(D, 0.5);
  for (let i = 0; i < count; i += 1) {
    const x = randomArray(rand, n, -spread, spread);
    let body: Body;
    switch (i % 5) {
      case 0:
        body = new Body(D, { shape: HyperSphere(D, uniform(rand, 0.2, 0.8)), mass: 1, position: x });
        break;
      case 1:
        body = new Body(D, { shape: HyperBox(D, randomArray(rand, n, 0.2, 0.8)), mass: 1, position: x });
        break;
      case 2: {
        const i0 = Math.floor(rand() * n);
        const j0 = (i0 + 1 + Math.floor(rand() * (n - 1))) % n;
        body = new Body(D, {
          shape: HyperTorus(D, uniform(rand, 0.5, 1), uniform(rand, 0.1, 0.3), [i0, j0]),
          mass: 1,
          position: x,
        });
        break;
      }
      case 3:
        body = new Body(D, { shape: cp, mass: 1, position: x });
        break;
      default:
        if (i % 10 === 4) {
          // a half-space: alternately axis-aligned (bounded on one axis) and tilted
          const normal = i % 20 === 4 ? randomUnitVector(rand, n) : Float64Array.from({ length: n }, (_, k) => (k === 1 ? 1 : 0));
          body = new Body(D, { shape: HalfSpace(D, normal, -spread - uniform(rand, 0, 2)), mass: 0 });
        } else {
          body = new Body(D, { shape: HyperBox(D, randomArray(rand, n, 0.1, 0.5)), mass: 0, position: x });
        }
    }
    if (body.type !== 'static' || body.shape.kind !== 'halfspace') randomTurn(body, rand);
    world.addBody(body);
  }
  return world;
}

describe('world.queryBox', () => {
  for (const n of DIMS) {
    it(`n = ${n}: 60 seeded query boxes over a random scene of 40 bodies (every shape, half-spaces included) equal the brute force over bounding boxes, in insertion order; again after 30 steps`, () => {
      const world = randomScene(n, 4000 + n, 40);
      const rand = seeded(5000 + n);
      const spread = 1.5 * Math.pow(40, 1 / n);
      let nonEmpty = 0;
      let total = 0;
      const check = (): void => {
        for (let q = 0; q < 60; q += 1) {
          const c = randomArray(rand, n, -spread - 2, spread + 2);
          const half = randomArray(rand, n, 0, q % 3 === 0 ? 3 : 0.8);
          const min = c.map((v, k) => v - half[k]!);
          const max = c.map((v, k) => v + half[k]!);
          const got = queryBox(world, min, max);
          const want = bruteQuery(world, min, max);
          expect(got).toEqual(want);
          for (let i = 1; i < got.length; i += 1)
            expect(world.bodies.indexOf(got[i]!)).toBeGreaterThan(world.bodies.indexOf(got[i - 1]!));
          if (got.length > 0) nonEmpty += 1;
          total += got.length;
        }
      };
      check();
      for (let i = 0; i < 30; i += 1) world.step(1 / 60);
      check();
      // the queries were not trivial
      expect(nonEmpty).toBeGreaterThan(30);
      expect(total).toBeGreaterThan(60);
    });
  }

  it('closed intervals: a query box that only touches a bounding box (or a half-space plane) finds it; one 1e-9 away does not', () => {
    const n = 3;
    const D = dims(n);
    const world = new World({ dimensions: n });
    const box = world.addBody(new Body(D, { shape: HyperBox(D, [1, 0.5, 0.25]), mass: 1, position: [2, 0, 0] }));
    const floor = world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], -3), mass: 0 }));
    expect(queryBox(world, [3, 0, 0], [4, 1, 1])).toEqual([box]);
    expect(queryBox(world, [3 + 1e-9, 0, 0], [4, 1, 1])).toEqual([]);
    expect(queryBox(world, [10, -5, 0], [11, -3, 0])).toEqual([floor]);
    expect(queryBox(world, [10, -3 + 1e-9, 0], [11, 0, 0])).toEqual([]);
    // a degenerate (point) query inside the box
    expect(queryBox(world, [2, 0, 0], [2, 0, 0])).toEqual([box]);
  });
});

// ---------------------------------------------------------------------------------------------

describe('bad arguments throw and change nothing', () => {
  function snapshot(world: World): string {
    return JSON.stringify(
      world.bodies.map((b) => [Array.from(b.x), Array.from(b.R), Array.from(b.v), Array.from(b.w), b.isSleeping]),
    );
  }

  for (const n of [2, 4, 6]) {
    it(`n = ${n}: rayCast (wrong lengths, zero / non-finite direction, negative / NaN maxDistance, non-arrays) and queryBox (wrong lengths, min > max, NaN)`, () => {
      const world = randomScene(n, 6000 + n, 12);
      for (let i = 0; i < 5; i += 1) world.step(1 / 60);
      const before = snapshot(world);
      const o = new Array<number>(n).fill(0);
      const d = new Array<number>(n).fill(0);
      d[0] = 1;
      const reference = castRay(world, o, d, 50);
      const lo = new Array<number>(n).fill(-2);
      const hi = new Array<number>(n).fill(2);
      const refQuery = queryBox(world, lo, hi);

      const expectBad = (f: () => unknown, kind?: typeof TypeError | typeof RangeError): void => {
        let error: unknown = null;
        try {
          f();
        } catch (e) {
          error = e;
        }
        expect(error instanceof TypeError || error instanceof RangeError).toBe(true);
        if (kind) expect(error).toBeInstanceOf(kind);
      };
      expectBad(() => castRay(world, o.slice(1), d, 10));
      expectBad(() => castRay(world, [...o, 0], d, 10));
      expectBad(() => castRay(world, o, d.slice(1), 10));
      expectBad(() => castRay(world, o, new Array(n).fill(0), 10), RangeError);
      expectBad(() =>
        castRay(
          world,
          o,
          d.map((c, k) => (k === 1 ? NaN : c)),
          10,
        ),
      );
      expectBad(() =>
        castRay(
          world,
          o.map(() => Infinity),
          d,
          10,
        ),
      );
      expectBad(() => castRay(world, o, d, -1), RangeError);
      expectBad(() => castRay(world, o, d, NaN));
      expectBad(() => castRay(world, o, d, '10' as unknown as number), TypeError);
      expectBad(() => castRay(world, null as unknown as number[], d, 10), TypeError);
      expectBad(() => queryBox(world, lo.slice(1), hi));
      expectBad(() => queryBox(world, lo, [...hi, 0]));
      expectBad(() => queryBox(world, hi, lo), RangeError);
      expectBad(
        () =>
          queryBox(
            world,
            lo.map((c, k) => (k === n - 1 ? 3 : c)),
            hi,
          ),
        RangeError,
      );
      expectBad(() =>
        queryBox(
          world,
          lo.map(() => NaN),
          hi,
        ),
      );
      expectBad(() => queryBox(world, 'ab' as unknown as number[], hi), TypeError);

      expect(snapshot(world)).toBe(before);
      const again = castRay(world, o, d, 50);
      expect(again === null ? null : [again.body, again.distance]).toEqual(
        reference === null ? null : [reference.body, reference.distance],
      );
      expect(queryBox(world, lo, hi)).toEqual(refQuery);
    });
  }
});
