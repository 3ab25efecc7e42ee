/**
 * The engine's three entries: `@physin/engine` (every dimension), `@physin/engine/3d` (the same
 * interface, 3D alone, a smaller bundle: tests/bundle-size.test.ts) and `@physin/engine/internal`
 * (the parts behind the interface, for tools, tests and the worker).
 */
import { describe, expect, it } from 'vitest';
import { dims as dimsAny, dims3, dims4 } from '@physin/algebra';
import * as engine from '@physin/engine';
import * as engine3 from '@physin/engine/3d';
import * as internal from '@physin/engine/internal';

/** What a user calls: the root export, name by name. A name added here is a promise. */
const PUBLIC = [
  'Body',
  'Compound',
  'ConvexMesh',
  'DistanceJoint',
  'FixedJoint',
  'HalfSpace',
  'HingeJoint',
  'HyperBox',
  'HyperCapsule',
  'HyperSphere',
  'HyperTorus',
  'Joint',
  'NonFiniteStateError',
  'PointJoint',
  'SubspaceJoint',
  'World',
  'WorldBase',
  'angularVelocityFromMomentum',
  'castRay',
  'defaultParams',
  'dims',
  'momentumFromAngularVelocity',
  'presets',
  'queryBox',
  'restoreWorld',
  'snapshotWorld',
  'validateParams',
];

/** A falling stack of three boxes on a floor, built with one entry's names; the state after 90 steps. */
function run(E: typeof engine | typeof engine3): Float64Array[] {
  const D = E.dims(3);
  const world = new E.World({ dimensions: 3, gravity: [0, -9.81, 0] });
  world.addBody(new E.Body(D, { shape: E.HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
  for (let i = 0; i < 3; i += 1) {
    world.addBody(
      new E.Body(D, {
        shape: E.HyperBox(D, [0.5, 0.4, 0.3]),
        mass: 1,
        position: [0.1 * i, 0.5 + 1.1 * i, 0],
        angularVelocity: [0.3, 0, 0.2],
      }),
    );
  }
  for (let s = 0; s < 90; s += 1) world.step(1 / 60);
  return world.bodies.map((b) => Float64Array.from([...b.x, ...b.R, ...b.v, ...b.L]));
}

describe('the engine entries', () => {
  it('the root export is exactly the public interface', () => {
    expect(Object.keys(engine).sort()).toEqual([...PUBLIC].sort());
  });

  it('@physin/engine/3d exports the same names; internal adds to them and keeps them identical', () => {
    expect(Object.keys(engine3).sort()).toEqual(Object.keys(engine).sort());
    for (const name of PUBLIC) {
      if (name === 'World' || name === 'dims') continue;
      expect((engine3 as Record<string, unknown>)[name], name).toBe((engine as Record<string, unknown>)[name]);
      expect((internal as Record<string, unknown>)[name], name).toBe((engine as Record<string, unknown>)[name]);
    }
    expect(Object.keys(internal)).toEqual(
      expect.arrayContaining(['collide', 'boxBoxSat', 'createBroadphase', 'mergeParams', 'ContactEvents']),
    );
  });

  it('the 3D entry steps bit-identically to the root entry', () => {
    expect(run(engine3)).toEqual(run(engine));
  });

  it('one tables object per dimension, whichever function builds it', () => {
    expect(engine3.dims(3)).toBe(dimsAny(3));
    expect(dims3()).toBe(dimsAny(3));
    expect(dims4()).toBe(dimsAny(4));
    expect(engine.dims).toBe(dimsAny);
  });

  it('the 3D entry refuses other dimensions, naming the argument', () => {
    expect(() => new engine3.World({ dimensions: 4 })).toThrow(RangeError);
    expect(() => new engine3.World({ dimensions: 4 })).toThrow(/'dimensions' must be 3/);
    expect(() => engine3.dims(4 as 3)).toThrow(/'n' must be 3/);
    expect(() => new engine3.World({ dimensions: 9 })).toThrow(/'dimensions'/);
  });

  it('functions that take a world take one from either entry', () => {
    const D = engine3.dims(3);
    const world = new engine3.World({ dimensions: 3, gravity: [0, -9.81, 0] });
    expect(world).toBeInstanceOf(engine.WorldBase);
    world.addBody(new engine3.Body(D, { shape: engine3.HyperBox(D, [0.5, 0.5, 0.5]), mass: 0 }));
    const hit = engine.castRay(world, [0, 5, 0], [0, -1, 0], 10);
    expect(hit?.distance).toBe(4.5);
    expect(engine.queryBox(world, [-1, -1, -1], [1, 1, 1])).toEqual([world.bodies[0]]);
    const copy = engine.restoreWorld(engine.snapshotWorld(world));
    expect(copy.bodies.length).toBe(1);
    expect(() => engine.castRay({} as engine.WorldBase, [0, 0, 0], [0, -1, 0], 1)).toThrow(/argument 'world' must be a World/);
    expect(() => engine.snapshotWorld(null as unknown as engine.WorldBase)).toThrow(TypeError);
  });
});
