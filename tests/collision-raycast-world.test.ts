import { describe, expect, it } from 'vitest';
import { computeBounds } from '../packages/engine/src/collision/bounds.js';
import { createBroadphase } from '../packages/engine/src/collision/broadphase.js';
import type { Broadphase, BroadphaseKind } from '../packages/engine/src/collision/broadphase.js';
import { createRayCastResult, rayCastClosest } from '../packages/engine/src/collision/query.js';
import type { RayCastSource } from '../packages/engine/src/collision/query.js';
import type { QueryShape } from '../packages/engine/src/collision/query-shapes.js';
import { createRayHit, rayCastShape } from '../packages/engine/src/collision/raycast.js';
import type { AnyShape } from '../packages/engine/src/shapes/index.js';
import { randomArray, randomUnitVector, seeded, uniform } from './support/random.js';
import { randomRotation } from './support/poses.js';

const DIMS = [2, 3, 4, 5, 6];
const KINDS: BroadphaseKind[] = ['tree', 'sap'];

/** The cross polytope |x|₁ <= s as facet planes and vertices. */
function crossPolytope(n: number, s: number): QueryShape {
  const vertices: number[] = [];
  for (let k = 0; k < n; k += 1)
    for (const sign of [1, -1]) vertices.push(...Array.from({ length: n }, (_, c) => (c === k ? sign * s : 0)));
  const normals: number[] = [];
  const offsets: number[] = [];
  for (let mask = 0; mask < 1 << n; mask += 1) {
    for (let k = 0; k < n; k += 1) normals.push(((mask >> k) & 1 ? -1 : 1) / Math.sqrt(n));
    offsets.push(s / Math.sqrt(n));
  }
  return { kind: 'mesh', vertices, facetNormals: normals, facetOffsets: offsets };
}

interface Body {
  shape: QueryShape;
  x: Float64Array;
  M: Float64Array;
}

/** A random scene of every shape kind, registered in the broadphase by their exact bounds. */
function makeScene(
  kind: BroadphaseKind,
  n: number,
  seed: number,
  count: number,
): {
  bp: Broadphase;
  bodies: Map<number, Body>;
  source: RayCastSource;
  spread: number;
  rand: () => number;
} {
  const rand = seeded(seed);
  const bp = createBroadphase(n, { margin: 0.1 }, kind);
  const bodies = new Map<number, Body>();
  const spread = 1.5 * Math.pow(count, 1 / n);
  const lo = new Float64Array(n);
  const hi = new Float64Array(n);
  for (let i = 0; i < count; i += 1) {
    const x = randomArray(rand, n, -spread, spread);
    const M = randomRotation(rand, n);
    let shape: QueryShape;
    switch (i % 4) {
      case 0:
        shape = { kind: 'sphere', radius: uniform(rand, 0.2, 0.8) };
        break;
      case 1:
        shape = { kind: 'box', halfExtents: randomArray(rand, n, 0.2, 0.8) };
        break;
      case 2: {
        const R = uniform(rand, 0.4, 0.9);
        shape = { kind: 'torus', majorRadius: R, minorRadius: uniform(rand, 0.1, 0.6) * R, planeI: 0, planeJ: 1 };
        break;
      }
      default:
        shape = crossPolytope(n, uniform(rand, 0.3, 0.9));
    }
    computeBounds(lo, hi, n, shape, x, M, 0);
    bodies.set(bp.createProxy(lo, hi), { shape, x, M });
  }
  const I = new Float64Array(n * n);
  for (let k = 0; k < n; k += 1) I[k * n + k] = 1;
  const normal = randomUnitVector(rand, n);
  bodies.set(bp.createHalfSpaceProxy(normal, -1.2 * spread), {
    shape: { kind: 'halfspace', normal, offset: -1.2 * spread },
    x: new Float64Array(n),
    M: I,
  });
  bp.updatePairs();
  const source: RayCastSource = {
    shapeOf: (id) => bodies.get(id)!.shape,
    positionOf: (id) => bodies.get(id)!.x,
    rotationOf: (id) => bodies.get(id)!.M,
  };
  return { bp, bodies, source, spread, rand };
}

/** The closest hit by casting against every shape, ties to the smaller id. */
function bruteForce(
  n: number,
  bodies: Map<number, Body>,
  o: Float64Array,
  d: Float64Array,
  maxDistance: number,
): { id: number; distance: number } {
  let best = { id: -1, distance: -1 };
  const hit = createRayHit(n);
  for (const [id, b] of [...bodies].sort((p, q) => p[0] - q[0])) {
    const t = rayCastShape(n, b.shape, b.x, b.M, o, d, maxDistance, hit);
    if (t >= 0 && (best.id < 0 || t < best.distance)) best = { id, distance: t };
  }
  return best;
}

describe.each(KINDS)('rayCastClosest (%s)', (kind) => {
  it.each(DIMS)('%iD: the same closest hit as casting against every shape', (n) => {
    const scene = makeScene(kind, n, 900 + n, 60);
    const { bp, bodies, source, spread, rand } = scene;
    const out = createRayCastResult(n);
    let hits = 0;
    let misses = 0;
    let inside = 0;
    for (let q = 0; q < 80; q += 1) {
      const o = randomArray(rand, n, -1.3 * spread, 1.3 * spread);
      // Half the rays aim at a body's centre, so most of them hit something.
      const target =
        q % 2 === 0 ? [...bodies.values()][Math.floor(rand() * (bodies.size - 1))]!.x : randomArray(rand, n, -spread, spread);
      const d = target.map((v, k) => v - o[k]!);
      if (Math.hypot(...d) < 1e-9) continue;
      const maxDistance = q % 5 === 0 ? uniform(rand, 0.5, 3) : Infinity;
      const expected = bruteForce(n, bodies, o, d, maxDistance);
      const id = rayCastClosest(bp, source, o, d, maxDistance, out);
      expect(id).toBe(expected.id);
      expect(out.id).toBe(expected.id);
      if (expected.id < 0) {
        misses += 1;
        expect(out.distance).toBe(-1);
        continue;
      }
      expect(Math.abs(out.distance - expected.distance)).toBeLessThanOrEqual(1e-12);
      if (out.distance === 0) inside += 1;
      else hits += 1;
      // The point is on the ray at that distance.
      const len = Math.hypot(...d);
      for (let k = 0; k < n; k += 1) {
        expect(Math.abs(out.point[k]! - (o[k]! + (out.distance * d[k]!) / len))).toBeLessThanOrEqual(1e-12);
      }
    }
    expect(hits).toBeGreaterThan(20);
    expect(misses + inside).toBeGreaterThan(0);
  });
});

describe('the tree prunes the ray walk', () => {
  it('a short ray in a 3D scene of 800 shapes casts against a small fraction of them', () => {
    const scene = makeScene('tree', 3, 4321, 800);
    const { bp, bodies, source, rand, spread } = scene;
    let casts = 0;
    const counting: RayCastSource = {
      shapeOf: (id) => {
        casts += 1;
        return source.shapeOf(id);
      },
      positionOf: source.positionOf,
      rotationOf: source.rotationOf,
    };
    const out = createRayCastResult(3);
    let total = 0;
    for (let q = 0; q < 50; q += 1) {
      casts = 0;
      const o = randomArray(rand, 3, -spread, spread);
      const d = randomUnitVector(rand, 3);
      const id = rayCastClosest(bp, counting, o, d, 3, out);
      expect(id).toBe(bruteForce(3, bodies, o, d, 3).id);
      total += casts;
    }
    // Every one of 801 proxies would be 40 050 casts.
    expect(total / 50).toBeLessThan(801 / 20);
  });
});

describe('the shape classes fit the query views', () => {
  it('every engine shape type is assignable to QueryShape (checked by tsc)', () => {
    // Compiles only if each of HyperBox, HyperSphere, HalfSpace, HyperTorus and ConvexMesh has
    // the fields the queries read, with compatible types.
    const fits: AnyShape extends QueryShape ? true : false = true;
    expect(fits).toBe(true);
  });
});

describe('rayCastClosest argument checks', () => {
  it('rejects bad rays and outputs', () => {
    const { bp, source } = makeScene('tree', 3, 1, 4);
    const out = createRayCastResult(3);
    expect(() => rayCastClosest(bp, source, [0, 0], [1, 0, 0], 1, out)).toThrow(/origin must have length 3/);
    expect(() => rayCastClosest(bp, source, [0, 0, 0], [0, 0, 0], 1, out)).toThrow(/direction/);
    expect(() => rayCastClosest(bp, source, [0, 0, 0], [1, 0, 0], NaN, out)).toThrow(/maxDistance/);
    expect(() => rayCastClosest(bp, source, [0, 0, 0], [1, 0, 0], 1, createRayCastResult(2))).toThrow(TypeError);
  });
});
