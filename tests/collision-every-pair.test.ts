/**
 * Every pair of shapes a user can build collides (issue 18): for each unordered pair of kinds —
 * box, ball, half-space, torus, convex mesh, capsule, compound — in 3D and 4D (and n = 2, 5 for
 * the kinds that exist there), shape B is set down 2 cm into shape A (A static, B dynamic, no
 * gravity); one step must give a 'begin' event (one per touching part of a compound), push B out of A (upward: its y velocity > 0), and
 * write no "no collision between …" warning.
 */
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import {
  Body,
  Compound,
  ConvexMesh,
  dims,
  HalfSpace,
  HyperBox,
  HyperCapsule,
  HyperSphere,
  HyperTorus,
  World,
} from '@physin/engine';
import type { Dims, Shape } from '@physin/engine';
import { cubeBoundary } from './support/meshes.js';

/** A shape, with its highest point (as A, below) and its lowest point (as B, above): [x, y]. */
interface Kind {
  readonly name: string;
  /** Smallest n the kind exists in. */
  readonly minN: number;
  make(D: Dims): Shape;
  readonly top: readonly [number, number];
  readonly bottom: readonly [number, number];
}

const KINDS: readonly Kind[] = [
  { name: 'box', minN: 2, make: (D) => HyperBox(D, new Array<number>(D.n).fill(0.5)), top: [0, 0.5], bottom: [0, -0.5] },
  { name: 'ball', minN: 2, make: (D) => HyperSphere(D, 0.5), top: [0, 0.5], bottom: [0, -0.5] },
  {
    name: 'half-space',
    minN: 2,
    make: (D) => HalfSpace(D, [0, 1, ...new Array<number>(D.n - 2).fill(0)], 0),
    top: [0, 0],
    bottom: [NaN, NaN],
  },
  // the core circle in the x–z plane (axes 0 and 2): a ring lying flat, its tube 0.4 thick
  { name: 'torus', minN: 3, make: (D) => HyperTorus(D, 0.6, 0.2, [0, 2]), top: [0.6, 0.2], bottom: [0.6, -0.2] },
  {
    name: 'mesh',
    minN: 2,
    make: (D) => {
      const m = cubeBoundary(D.n, new Array<number>(D.n).fill(0.5));
      return ConvexMesh(D, m.vertices, m.facets);
    },
    top: [0, 0.5],
    bottom: [0, -0.5],
  },
  { name: 'capsule', minN: 2, make: (D) => HyperCapsule(D, 0.3, 0.2), top: [0, 0.5], bottom: [0, -0.5] },
  {
    name: 'compound',
    minN: 2,
    make: (D) => {
      const x = (v: number) => [v, ...new Array<number>(D.n - 1).fill(0)];
      return Compound(D, [
        { shape: HyperSphere(D, 0.25), position: x(-0.3) },
        { shape: HyperSphere(D, 0.25), position: x(0.3) },
      ]);
    },
    top: [0.3, 0.25],
    bottom: [0.3, -0.25],
  },
];

const DEPTH = 0.02;

function at(n: number, x: number, y: number): number[] {
  const p = new Array<number>(n).fill(0);
  p[0] = x;
  p[1] = y;
  return p;
}

let warn: ReturnType<typeof vi.spyOn>;
beforeEach(() => {
  warn = vi.spyOn(console, 'warn').mockImplementation(() => {});
});
afterEach(() => {
  warn.mockRestore();
});

for (const n of [2, 3, 4, 5]) {
  describe(`n = ${n}`, () => {
    for (let i = 0; i < KINDS.length; i += 1) {
      for (let j = 0; j < KINDS.length; j += 1) {
        const A = KINDS[i]!;
        const B = KINDS[j]!;
        if (B.name === 'half-space') continue; // a half-space is static: only ever the one below
        if (i > j && A.name !== 'half-space') continue; // unordered pairs (the half-space is below in each)
        if (n < A.minN || n < B.minN) continue;
        it(`${B.name} set into ${A.name}: a begin event, pushed out, no warning`, () => {
          const D = dims(n);
          const world = new World({ dimensions: n, gravity: new Array<number>(n).fill(0) });
          const a = world.addBody(new Body(D, { shape: A.make(D), mass: 0, position: at(n, 0, 0), name: A.name }));
          const b = world.addBody(
            new Body(D, {
              shape: B.make(D),
              mass: 1,
              position: at(n, A.top[0] - B.bottom[0], A.top[1] - B.bottom[1] - DEPTH),
              name: B.name,
            }),
          );
          const log: string[] = [];
          b.addEventListener('collision', (e) => log.push(`${e.type}:${e.other.name}`));
          world.step(1 / 60);
          // (a compound's parts each begin their own touch)
          expect(log.length).toBeGreaterThan(0);
          expect(new Set(log)).toEqual(new Set([`begin:${a.name}`]));
          expect(b.v[1]).toBeGreaterThan(0);
          expect(warn).not.toHaveBeenCalled();
        });
      }
    }
  });
}
