/**
 * Joints: chains of joints of any width in joint space (docs/joints.md, "Chains in joint space").
 *
 * Hinges (5 rows in 3D), welds (6) and point joints in 2D and 4D (n rows) along a path are
 * factored block-tridiagonally in joint space, in blocks m_p × m_q, like the 3D point chains.
 * Every row must be met to rounding:
 *
 * - a U of 6 links pinned to the world at both ends by hinges about seeded random axes (7 hinges,
 *   35 independent rows on 36 unknowns: one degree of freedom) swings down under gravity: every
 *   point to 1e-14 m and every locked angle to 1e-14 rad over 3 s (9.2e-16 m and 5.8e-16 rad
 *   measured; the body + joint tree alone opened it 4.68 m and 1.94 rad: a leaf body whose folded
 *   hinge fixes a point leaves its parent joint's block singular, and the tree's LU drops a row
 *   the chain needed);
 * - the whipping chain of 10 hinges (the first to the world), their free plane tilted so that
 *   gravity loads the locked rows, over 10 s: 5.2e-13 m and 1.3e-15 rad, as the tree;
 * - a beam of 6 links welded together, hinged to the world at one end and kicked out of its
 *   plane (widths 5, 6, 6, …: mixed along the path), over 3 s: to 1e-14 m and rad;
 * - the whipping point chain of 10 in 4D and in 2D (4 and 2 rows a joint), over 10 s, as the tree;
 * - the same U with every hinge about z (a planar loop: 3 rows redundant out of the plane) and the U
 *   welded together and to the world at both ends (6 rows redundant; in 4D 10): the LDLᵀ drops the
 *   redundant pivots, every row to rounding over 3 s (9.2e-16, 3.2e-16 and 3.2e-16 m; the tree,
 *   which took them before, opened them 3.1 m, 2.7e-3 m and 9.4e10 m);
 * - every scene gives the same bits in two runs.
 */
import { describe, expect, it } from 'vitest';
import { FixedJoint, HingeJoint, PointJoint } from '@physin/engine';
import type { Joint } from '@physin/engine';
import { U_CHAIN_POINTS, jointPath, lockedAngleError, runJointScene, snapshot } from './support/joints.js';
import type { JointMaker, JointPath, JointRun } from './support/joints.js';
import { randomUnitVector, seeded } from './support/random.js';

const DT = 1 / 60;
// The whips' gaps, 5.2e-13 m (hinges) and 1.0e-12 m (4D) and 1.1e-12 m (2D) at 10 s, are the
// tree's too (5.18e-13, 1.03e-12, 1.11e-12): the step's, not the solve's.
const BOUND_WHIP_POINT = 1e-12;
const BOUND_WHIP_ANGLE = 5e-15;
const BOUND_4D = 2e-12;
const BOUND_2D = 2e-12;

/** Per joint: its free plane (unit bivector in a's frame), null for a joint without angular rows or a weld. */
interface Scene extends JointPath {
  free: (Float64Array | null)[];
  /** 1 for the joints whose angles are locked (hinges, welds). */
  angular: boolean[];
}

function scene(path: JointPath, free: (Float64Array | null)[]): Scene {
  return { ...path, free, angular: path.joints.map((j) => !(j instanceof PointJoint)) };
}

function hingeU(): Scene {
  const rand = seeded(7);
  const planes = Array.from({ length: 7 }, () => randomUnitVector(rand, 3));
  const make: JointMaker = (i, a, la, b, lb) => new HingeJoint(a, b, la, lb, { plane: planes[i]! });
  return scene(jointPath(U_CHAIN_POINTS, [0, 0, 0], [2, 0, 0], make), planes);
}

const X_PLANE = Float64Array.of(1, 0, 0); // the plane (x y): the hinges swing in the vertical plane

/** A free plane tilted out of the vertical (x y) toward (x z): gravity loads the locked rows too. */
const TILTED = Float64Array.of(1 / Math.hypot(1, 0.3), 0.3 / Math.hypot(1, 0.3), 0);

/** The same U with every hinge about z: a planar loop, 3 of its 35 rows redundant (out of the plane). */
function planarU(): Scene {
  const make: JointMaker = (_i, a, la, b, lb) => new HingeJoint(a, b, la, lb, { plane: X_PLANE });
  return scene(
    jointPath(U_CHAIN_POINTS, [0, 0, 0], [2, 0, 0], make),
    U_CHAIN_POINTS.concat([[0, 0, 0]]).map(() => X_PLANE),
  );
}

/**
 * The U of 6 links welded together and to the world at both ends, in n dimensions (3: 42 rows on
 * 36 unknowns, 6 redundant; 4: 70 on 60, 10 redundant).
 */
function weldedU(n = 3): Scene {
  const make: JointMaker = (_i, a, la, b, lb) => new FixedJoint(a, b, la, lb);
  const pad = (p: number[]): number[] => p.concat(new Array<number>(n - 3).fill(0));
  return scene(
    jointPath(U_CHAIN_POINTS.map(pad), pad([0, 0, 0]), pad([2, 0, 0]), make),
    U_CHAIN_POINTS.concat([[0, 0, 0]]).map(() => null),
  );
}

function hingeWhip(): Scene {
  const points = Array.from({ length: 10 }, (_, i) => [i + 0.5, 0, 0]);
  const make: JointMaker = (_i, a, la, b, lb) => new HingeJoint(a, b, la, lb, { plane: TILTED });
  return scene(
    jointPath(points, [0, 0, 0], null, make),
    points.map(() => TILTED),
  );
}

function weldBeam(): Scene {
  const points = Array.from({ length: 6 }, (_, i) => [i + 0.5, 0, 0]);
  const make: JointMaker = (i, a, la, b, lb) =>
    i === 0 ? new HingeJoint(a, b, la, lb, { plane: 0 }) : new FixedJoint(a, b, la, lb);
  const s = scene(
    jointPath(points, [0, 0, 0], null, make),
    points.map((_, i) => (i === 0 ? X_PLANE : null)),
  );
  s.bodies[5]!.v[2] = 2; // a kick out of the hinge's plane: the hinge's locked rows take it
  return s;
}

function pointWhip(n: number): Scene {
  const points = Array.from({ length: 10 }, (_, i) => {
    const p = new Array<number>(n).fill(0);
    p[0] = i + 0.5;
    return p;
  });
  const make: JointMaker = (_i, a, la, b, lb) => new PointJoint(a, b, la, lb);
  return scene(
    jointPath(points, new Array<number>(n).fill(0), null, make),
    points.map(() => null),
  );
}

/** The worst point gap (m) and locked angle (rad) of the scene's joints now. */
function errors(s: Scene): [number, number] {
  let point = 0;
  let angle = 0;
  s.joints.forEach((j: Joint, i) => {
    point = Math.max(point, j.error());
    if (s.angular[i]) angle = Math.max(angle, lockedAngleError(s.world.D, j.a, j.b, s.free[i]!));
  });
  return [point, angle];
}

/** Steps the scene; the worst point gap and locked angle over every step end, and the lowest height a body reached. */
const run = (s: Scene, steps: number): JointRun => runJointScene(s.world, s.bodies, steps, DT, () => errors(s));

function report(label: string, r: JointRun): void {
  console.log(
    `${label}: worst point gap ${r.point.toExponential(2)} m, locked angle ${r.angle.toExponential(2)} rad, lowest ${r.lowest.toFixed(3)} m`,
  );
}

describe('chains of joints of any width in joint space', () => {
  it('a U of 6 links hinged to the world at both ends swings down, every joint closed to rounding over 3 s', () => {
    const r = run(hingeU(), 180);
    report('hinge U', r);
    expect(r.point).toBeLessThan(1e-14);
    expect(r.angle).toBeLessThan(1e-14);
    expect(r.lowest).toBeLessThan(-2.02); // it moved: its one degree of freedom fell
  });

  it('the U with every hinge about z (3 redundant rows): it swings down, every joint closed to rounding over 3 s', () => {
    // The joint-space LDLᵀ drops the last joint's 3 redundant pivots (|d| below 7e-15 of their size,
    // every kept one above 1.5e-3): 9.2e-16 m and 4.7e-25 rad measured; when redundant rows failed the
    // factorisation, these sub-steps went to the tree, which opened the U 3.1 m.
    const r = run(planarU(), 180);
    report('planar hinge U', r);
    expect(r.point).toBeLessThan(2e-15);
    expect(r.angle).toBeLessThan(1e-15);
    expect(r.lowest).toBeLessThan(-2.05);
  });

  it('the U welded together and to the world at both ends (3D, 4D: all of the last weld redundant) holds to rounding over 3 s', () => {
    // The last weld's pivots are dropped. 3D: 3.2e-16 m and 2.4e-16 rad measured, no body moves
    // more than 3.1e-16 m (before, the tree took these sub-steps: 2.7e-3 m); 4D: 3.2e-16 m and
    // 2.3e-16 rad, no body moves more than 2.5e-16 m (the tree: 9.4e10 m, the U thrown apart).
    for (const n of [3, 4]) {
      const s = weldedU(n);
      const start = s.bodies.map((b) => Float64Array.from(b.x));
      const r = run(s, 180);
      const moved = Math.max(...s.bodies.map((b, i) => Math.hypot(...b.x.map((v, d) => v - start[i]![d]!))));
      report(`welded U, n = ${n}`, r);
      console.log(`welded U, n = ${n}: largest displacement ${moved.toExponential(2)} m`);
      expect(r.point).toBeLessThan(2e-15);
      expect(r.angle).toBeLessThan(1e-15);
      expect(moved).toBeLessThan(1e-15);
    }
  });

  it('the whipping chain of 10 hinges: every joint closed to rounding over 10 s', () => {
    const r = run(hingeWhip(), 600);
    report('hinge whip', r);
    expect(r.point).toBeLessThan(BOUND_WHIP_POINT);
    expect(r.angle).toBeLessThan(BOUND_WHIP_ANGLE);
    expect(r.lowest).toBeLessThan(-8);
  });

  it('a welded beam hinged to the world and kicked out of its plane: every joint closed to rounding over 3 s', () => {
    const r = run(weldBeam(), 180);
    report('weld beam', r);
    expect(r.point).toBeLessThan(1e-14);
    expect(r.angle).toBeLessThan(1e-14);
    expect(r.lowest).toBeLessThan(-5);
  });

  it('the whipping point chain of 10 in 4D and in 2D: every joint closed to rounding over 10 s', () => {
    for (const n of [4, 2]) {
      const r = run(pointWhip(n), 600);
      report(`point whip, n = ${n}`, r);
      expect(r.point).toBeLessThan(n === 4 ? BOUND_4D : BOUND_2D);
      expect(r.lowest).toBeLessThan(-9);
    }
  });

  it('every scene gives the same bits in two runs', () => {
    for (const make of [
      hingeU,
      planarU,
      () => weldedU(3),
      () => weldedU(4),
      hingeWhip,
      weldBeam,
      () => pointWhip(4),
      () => pointWhip(2),
    ]) {
      const a = make();
      const b = make();
      run(a, 90);
      run(b, 90);
      expect(snapshot(b.world)).toEqual(snapshot(a.world));
    }
  });
});
