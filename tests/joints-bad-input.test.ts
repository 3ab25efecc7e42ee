/**
 * Joints: bad input. Anchors of the wrong length, a non-simple hinge plane (e_xy + e_zw), lower >
 * upper, a negative hertz, an unknown distance mode, an unknown axis or plane, an unknown option:
 * each is refused with a TypeError or RangeError whose message names the argument, and nothing
 * changes — neither the joint (its getters read as before) nor the world.
 *
 * "Nothing changed" is checked twice: a snapshot of every body's x, R, v, L, w and the list of
 * constraints are equal before and after the bad calls; and the world that received them, stepped
 * 60 times, stays bit-identical to a twin that never did.
 */
import { describe, expect, it } from 'vitest';
import { Body, DistanceJoint, FixedJoint, HingeJoint, HyperBox, PointJoint, SubspaceJoint } from '@physin/engine';
import type { World } from '@physin/engine';
import { snapshot } from './support/joints.js';
import { makeWorld } from './support/scenes.js';

/** A world with two boxes, a motorised hinge with limits between them, and a soft point joint of the second box to the world. */
function scene(n: number) {
  const world = makeWorld(n);
  const D = world.D;
  const zero = new Array<number>(n).fill(0);
  const pa = [...zero];
  pa[1] = 1;
  const pb = [...zero];
  pb[0] = 1.2;
  pb[1] = 1;
  const a = world.addBody(new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.3)), mass: 1, position: pa, name: 'a' }));
  const b = world.addBody(new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.3)), mass: 2, position: pb, name: 'b' }));
  const la = [...zero];
  la[0] = 0.6;
  const lb = [...zero];
  lb[0] = -0.6;
  const hinge = world.addConstraint(
    new HingeJoint(a, b, la, lb, { plane: 0, lowerAngle: -1, upperAngle: 1, motorSpeed: 1, maxMotorTorque: 5 }),
  );
  const top = [...zero];
  top[1] = 2;
  const point = world.addConstraint(new PointJoint(a, null, zero, pa, { hertz: 4, damping: 0.7 }));
  const outsider = new Body(D, { shape: HyperBox(D, new Array<number>(n).fill(0.3)), mass: 1, position: top, name: 'outsider' });
  return { world, a, b, hinge, point, outsider, zero };
}

type Scene = ReturnType<typeof scene>;

/** Runs `bad` (which must throw TypeError or RangeError matching `message`) and checks that nothing changed. */
function refuses(n: number, label: string, message: RegExp, bad: (s: Scene) => unknown) {
  it(`${n}D: ${label} → TypeError/RangeError naming it (${message.source}), world and joints unchanged`, () => {
    const s = scene(n);
    const twin = scene(n);
    for (let i = 0; i < 10; i += 1) {
      s.world.step(1 / 60);
      twin.world.step(1 / 60);
    }
    const before = snapshot(s.world);
    const constraints = [...s.world.constraints];
    const hingeState = [
      s.hinge.lowerAngle,
      s.hinge.upperAngle,
      s.hinge.motorSpeed,
      s.hinge.maxMotorTorque,
      s.hinge.hertz,
      ...s.hinge.localA,
      ...s.hinge.localB,
    ];
    const pointState = [
      s.point.hertz,
      s.point.damping,
      s.point.breakForce,
      s.point.breakTorque,
      ...s.point.localA,
      ...s.point.localB,
    ];
    let error: unknown = null;
    try {
      bad(s);
    } catch (e) {
      error = e;
    }
    const text = error instanceof Error ? `${error.name}: ${error.message}` : String(error);
    console.log(`${label}: ${text}`);
    expect(error instanceof TypeError || error instanceof RangeError, text).toBe(true);
    expect((error as Error).message, text).toMatch(message);
    expect(snapshot(s.world)).toEqual(before);
    expect([...s.world.constraints]).toEqual(constraints);
    expect([
      s.hinge.lowerAngle,
      s.hinge.upperAngle,
      s.hinge.motorSpeed,
      s.hinge.maxMotorTorque,
      s.hinge.hertz,
      ...s.hinge.localA,
      ...s.hinge.localB,
    ]).toEqual(hingeState);
    expect([
      s.point.hertz,
      s.point.damping,
      s.point.breakForce,
      s.point.breakTorque,
      ...s.point.localA,
      ...s.point.localB,
    ]).toEqual(pointState);
    expect(s.world.bodies.includes(s.outsider)).toBe(false);
    for (let i = 0; i < 60; i += 1) {
      s.world.step(1 / 60);
      twin.world.step(1 / 60);
    }
    // Bit-identical to the twin that never saw the bad call.
    expect(snapshot(s.world)).toEqual(snapshot(twin.world));
  });
}

describe('bad joint input: a clear error and nothing changed', () => {
  // Anchors of the wrong length.
  refuses(3, 'PointJoint with localA of 2 numbers in 3D', /localA/, (s) =>
    s.world.addConstraint(new PointJoint(s.a, s.b, [0, 0], [0, 0, 0])),
  );
  refuses(3, 'PointJoint to the world with localB of 4 numbers in 3D', /localB/, (s) =>
    s.world.addConstraint(new PointJoint(s.a, null, [0, 0, 0], [0, 0, 0, 0])),
  );
  refuses(4, 'FixedJoint with localB of 3 numbers in 4D', /localB/, (s) =>
    s.world.addConstraint(new FixedJoint(s.a, s.b, [0, 0, 0, 0], [0, 0, 0])),
  );
  refuses(4, 'setAnchors([0, 0, 0], null) on a live 4D hinge', /localA/, (s) => s.hinge.setAnchors([0, 0, 0], null));
  refuses(3, 'setAnchors(null, [NaN, 0, 0]) on a live point joint', /localB/, (s) =>
    s.point.setAnchors(null, [Number.NaN, 0, 0]),
  );
  // The hinge plane.
  refuses(4, 'HingeJoint with the non-simple plane e_xy + e_zw = [1, 0, 0, 0, 0, 1]', /plane/, (s) =>
    s.world.addConstraint(new HingeJoint(s.a, s.b, [0.6, 0, 0, 0], [-0.6, 0, 0, 0], { plane: [1, 0, 0, 0, 0, 1] })),
  );
  refuses(4, 'HingeJoint with plane index 6 (4D has planes 0..5)', /plane/, (s) =>
    s.world.addConstraint(new HingeJoint(s.a, s.b, [0.6, 0, 0, 0], [-0.6, 0, 0, 0], { plane: 6 })),
  );
  refuses(3, 'HingeJoint with a plane bivector of 6 numbers in 3D', /plane/, (s) =>
    s.world.addConstraint(new HingeJoint(s.a, s.b, [0.6, 0, 0], [-0.6, 0, 0], { plane: [1, 0, 0, 0, 0, 0] })),
  );
  // Limits.
  refuses(3, 'HingeJoint with lowerAngle 0.5 > upperAngle −0.5', /lower|upper/i, (s) =>
    s.world.addConstraint(new HingeJoint(s.a, s.b, [0.6, 0, 0], [-0.6, 0, 0], { lowerAngle: 0.5, upperAngle: -0.5 })),
  );
  refuses(4, 'setLimits(1, −1) on a live hinge', /lower|upper/i, (s) => s.hinge.setLimits(1, -1));
  refuses(4, 'setMotor(1, −5) (negative torque) on a live hinge', /maxMotorTorque|torque/i, (s) => s.hinge.setMotor(1, -5));
  // Softness.
  refuses(3, 'PointJoint with hertz −1', /hertz/, (s) =>
    s.world.addConstraint(new PointJoint(s.a, s.b, [0.6, 0, 0], [-0.6, 0, 0], { hertz: -1 })),
  );
  refuses(3, 'setSoftness(−5, 1) on a live joint', /hertz/, (s) => s.point.setSoftness(-5, 1));
  refuses(3, 'setSoftness(5, −1) on a live joint', /damping/, (s) => s.point.setSoftness(5, -1));
  refuses(3, 'setBreak(−1, 0) on a live joint', /force/i, (s) => s.point.setBreak(-1, 0));
  // Distance modes.
  refuses(3, "DistanceJoint with mode 'chain'", /mode/, (s) =>
    s.world.addConstraint(new DistanceJoint(s.a, s.b, [0, 0, 0], [0, 0, 0], { rest: 1, mode: 'chain' as unknown as 'rod' })),
  );
  refuses(3, 'DistanceJoint with rest −1', /rest/, (s) =>
    s.world.addConstraint(new DistanceJoint(s.a, s.b, [0, 0, 0], [0, 0, 0], { rest: -1 })),
  );
  // Subspace axes and planes.
  refuses(4, 'SubspaceJoint with lockAxes [4] in 4D (axes 0..3)', /lockAxes/, (s) =>
    s.world.addConstraint(new SubspaceJoint(s.a, null, { lockAxes: [4], worldFrame: true })),
  );
  refuses(4, 'SubspaceJoint with lockAxes [1.5]', /lockAxes/, (s) =>
    s.world.addConstraint(new SubspaceJoint(s.a, null, { lockAxes: [1.5] })),
  );
  refuses(4, 'SubspaceJoint with lockPlanes [6] in 4D (planes 0..5)', /lockPlanes/, (s) =>
    s.world.addConstraint(new SubspaceJoint(s.a, null, { lockAxes: [3], lockPlanes: [6] })),
  );
  refuses(4, 'SubspaceJoint with both lockAxes and freeAxes', /lockAxes|freeAxes/, (s) =>
    s.world.addConstraint(
      new SubspaceJoint(s.a, null, { lockAxes: [3], freeAxes: [0, 1, 2] } as unknown as { lockAxes: number[] }),
    ),
  );
  // Unknown options and misuse of the world.
  refuses(3, "PointJoint with an unknown option 'hertzz'", /hertzz/, (s) =>
    s.world.addConstraint(new PointJoint(s.a, s.b, [0, 0, 0], [0, 0, 0], { hertzz: 5 } as unknown as { hertz: number })),
  );
  refuses(3, 'addConstraint of a joint whose body is not in the world', /outsider|world/, (s) =>
    s.world.addConstraint(new PointJoint(s.a, s.outsider, [0, 0, 0], [0, 0, 0])),
  );
  refuses(3, 'addConstraint of a joint already in the world', /already|world/, (s) => s.world.addConstraint(s.hinge));
  refuses(3, 'removeConstraint of a joint not in the world', /world|constraint/i, (s) =>
    s.world.removeConstraint(new PointJoint(s.a, s.b, [0, 0, 0], [0, 0, 0])),
  );
  refuses(3, 'addConstraint of something that is not a joint', /joint/i, (s) =>
    (s.world as World).addConstraint({} as unknown as PointJoint),
  );
});
