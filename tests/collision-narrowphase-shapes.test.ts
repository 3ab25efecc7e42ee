import { dims } from '@physin/algebra';
import { describe, expect, it } from 'vitest';
import { boxColliders } from '../packages/engine/src/collision/box-colliders.js';
import { collidePair } from '../packages/engine/src/collision/collide.js';
import { createManifold, createPose } from '../packages/engine/src/collision/manifold.js';
import type { CollidableShape } from '../packages/engine/src/collision/manifold.js';
import { meshColliders } from '../packages/engine/src/collision/mesh-colliders.js';
import { createNarrowphaseScratch } from '../packages/engine/src/collision/narrowphase-scratch-nd.js';
import { sphereColliders } from '../packages/engine/src/collision/sphere-colliders.js';
import { torusColliders } from '../packages/engine/src/collision/torus-colliders.js';
import { ConvexMesh, HalfSpace, HyperBox, HyperSphere, HyperTorus } from '../packages/engine/src/shapes/index.js';

// The engine's shape factories give the fields the narrowphase reads; the lead wires
// `colliders` into the factories, so here the tables are attached by spreading.
describe('narrowphase on the engine shapes (4D)', () => {
  const n = 4;
  const D = dims(n);
  const floor: CollidableShape = HalfSpace(D, [0, 2, 0, 0], 0); // a non-unit normal, normalised by the factory
  const scratch = createNarrowphaseScratch(n);
  const out = createManifold(n);
  const up = (y: number) => {
    const p = createPose(n);
    p.x[1] = y;
    return p;
  };

  it('box, ball, torus and cross-polytope mesh resting 0.01 into the floor', () => {
    const box: CollidableShape = { ...HyperBox(D, [0.5, 0.5, 0.5, 0.5]), colliders: boxColliders };
    const ball: CollidableShape = { ...HyperSphere(D, 0.5), colliders: sphereColliders };
    const torus: CollidableShape = { ...HyperTorus(D, 2, 0.7, [0, 2]), colliders: torusColliders };
    const vertices: number[][] = [];
    for (let i = 0; i < n; i += 1) for (const s of [1, -1]) vertices.push(Array.from({ length: n }, (_, c) => (c === i ? s : 0)));
    const facets: number[][] = [];
    for (let mask = 0; mask < 1 << n; mask += 1) facets.push(Array.from({ length: n }, (_, i) => 2 * i + ((mask >> i) & 1)));
    const mesh: CollidableShape = { ...ConvexMesh(D, vertices, facets), colliders: meshColliders };
    const cases: [CollidableShape, number, number][] = [
      [box, 0.49, 8],
      [ball, 0.49, 1],
      [torus, 0.69, 8],
      [mesh, 0.99, 1],
    ];
    for (const [shape, height, count] of cases) {
      expect(collidePair(out, n, floor, createPose(n), shape, up(height), 0.005, scratch)).toBe(true);
      expect(out.count).toBe(count);
      for (let p = 0; p < out.count; p += 1) expect(Math.abs(out.separations[p] + 0.01)).toBeLessThanOrEqual(1e-12);
      // from the floor (A) up to the shape (B)
      expect(Array.from(out.normal, (v) => v + 0)).toEqual([0, 1, 0, 0]);
    }
  });
});
