/**
 * Joints: branching joint trees in joint space (docs/joints.md, "Trees in joint space").
 *
 * Bodies with three or more tree joints (a ragdoll's torso, the centre of a Y) are factored in
 * joint space, leaves first, without fill-in. Every row must be met to rounding:
 *
 * - a ragdoll of 11 balls (a torso, a neck and head, two arms and two legs of 2 links each; point
 *   joints at the shoulders, hips and neck, hinges about seeded axes at the elbows and knees)
 *   hanging by both hands from the world (the left hand hinged, the right pinned) swings for 3 s:
 *   7.0e-16 m and 1.5e-15 rad measured; the body + joint tree alone (main before) opened it 45 m
 *   and 1.14 rad (a leaf body whose folded joint pins a point leaves its parent joint's block
 *   singular, and the tree's LU drops a row the parent body could have met);
 * - a Y of three chains of 3 links pinned at its three ends: 1.9e-15 m in 3D, 3.7e-15 m in 4D
 *   (the tree: 1.06 m and 4.14 m);
 * - the same Y welded together and to the world at its three ends (72 rows on 60 unknowns, 12
 *   redundant; 4D: 120 on 100, 20): the dropped pivots hold it, 3.1e-16 m and 2.6e-16 rad in 3D,
 *   3.2e-16 m and 2.4e-16 rad in 4D (the tree: 3.7e-3 m and 6.8e-3 m);
 * - the ragdoll falling free and kicked (no redundant rows) as exact as the tree: 1.42e-14 m and
 *   3.4e-15 rad over 3 s (the tree: 1.42e-14 m and 3.43e-15 rad);
 * - every scene gives the same bits in two runs.
 */
import { describe, expect, it } from 'vitest';
import { FixedJoint, HingeJoint, PointJoint } from '@physin/engine';
import { jointTree, lockedAngleError, pointJointError, runJointScene, snapshot } from './support/joints.js';
import type { JointMaker, JointRun, JointTreeScene } from './support/joints.js';
import { randomUnitVector, seeded } from './support/random.js';
import { installedPoint3Path, setPoint3Path } from '../packages/engine/src/joints/joint-space.js';
import { usePoint3Path } from '../packages/engine/src/joints/joint-space-point.js';

const DT = 1 / 60;
const LOG = process.env.TREE_SPACE_LOG === '1';

/** A ragdoll of 11 balls: a torso with a neck and head, two arms and two legs of 2 links each. */
const RAGDOLL: number[][] = [
  [0, 0, 0],
  [0.05, 0.9, 0],
  [0.05, 1.8, 0.1],
  [-0.7, 0.6, 0],
  [-1.1, 1.5, 0.1],
  [0.7, 0.6, 0],
  [1.2, 1.4, -0.1],
  [-0.3, -0.95, 0],
  [-0.35, -1.95, 0.15],
  [0.3, -0.95, 0],
  [0.4, -1.9, -0.2],
];
const RAGDOLL_EDGES: [number, number][] = [
  [0, 1],
  [1, 2],
  [0, 3],
  [3, 4],
  [0, 5],
  [5, 6],
  [0, 7],
  [7, 8],
  [0, 9],
  [9, 10],
];
/** The hands' ends: each forearm's centre plus half of it, beyond the elbow. */
const HANDS: [number, number[]][] = [
  [4, [-1.3, 1.95, 0.15]],
  [6, [1.45, 1.8, -0.15]],
];
/** The joints (edge order, then the hands) that are hinges: elbows, knees, the left hand. */
const HINGED = new Set([3, 5, 7, 9, 10]);

interface Scene extends JointTreeScene {
  free: (Float64Array | null)[];
}

function ragdoll(hanging: boolean): Scene {
  const rand = seeded(61);
  const planes = Array.from({ length: 12 }, () => randomUnitVector(rand, 3));
  const free = planes.map((p, i) => (HINGED.has(i) ? p : null));
  const make: JointMaker = (i, a, la, b, lb) =>
    HINGED.has(i) ? new HingeJoint(a, b, la, lb, { plane: planes[i]! }) : new PointJoint(a, b, la, lb);
  const s = jointTree(RAGDOLL, RAGDOLL_EDGES, hanging ? HANDS : [], make);
  return { ...s, free };
}

/** A Y of three chains of 3 links from a centre ball, lying about the horizontal, pinned at its three ends. */
function yTree(n: number, weld = false): Scene {
  const pad = (p: number[]): number[] => p.concat(new Array<number>(n - 3).fill(0));
  const points: number[][] = [pad([0, 0, 0])];
  const edges: [number, number][] = [];
  const pins: [number, number[]][] = [];
  for (let arm = 0; arm < 3; arm += 1) {
    const a = (2 * Math.PI * arm) / 3;
    const d = [Math.cos(a), 0, Math.sin(a)];
    let prev = 0;
    for (let i = 1; i <= 3; i += 1) {
      const p = pad(d.map((v, c) => 0.95 * i * v + (c === 1 ? 0.15 * (i % 2) : 0)));
      if (n > 3 && arm === 0 && i === 2) p[3] = 0.1;
      points.push(p);
      edges.push([prev, points.length - 1]);
      prev = points.length - 1;
    }
    pins.push([prev, pad(d.map((v, c) => (0.95 * 3 + 0.5) * v + (c === 1 ? 0.1 : 0)))]);
  }
  const make: JointMaker = (_i, a, la, b, lb) => (weld ? new FixedJoint(a, b, la, lb) : new PointJoint(a, b, la, lb));
  const s = jointTree(points, edges, pins, make);
  return { ...s, free: s.joints.map(() => (weld ? new Float64Array(s.world.D.k) : null)) };
}

function errors(s: Scene): [number, number] {
  let point = 0;
  let angle = 0;
  s.ends.forEach(([a, la, b, lb], i) => {
    point = Math.max(point, pointJointError(a, la, b, lb));
    const f = s.free[i];
    // A zero free plane: a weld, every plane locked.
    if (f) angle = Math.max(angle, lockedAngleError(s.world.D, a, b, f.some((x) => x !== 0) ? f : null));
  });
  return [point, angle];
}

/** Steps the scene; the worst point gap and locked angle over every step end, and the lowest height a body reached. */
const run = (s: Scene, steps: number): JointRun => runJointScene(s.world, s.bodies, steps, DT, () => errors(s));

function report(label: string, r: JointRun): void {
  if (LOG)
    console.log(
      `${label}: point ${r.point.toExponential(2)} m, angle ${r.angle.toExponential(2)} rad, lowest ${r.lowest.toFixed(3)}`,
    );
}

function kicked(s: Scene): Scene {
  s.bodies[2]!.v[2] = 3;
  s.bodies[4]!.v[0] = -2;
  s.bodies[10]!.v[1] = 4;
  return s;
}

describe('joint trees in joint space', () => {
  it('a ragdoll hanging by both hands swings for 3 s, every joint closed to rounding', () => {
    const r = run(ragdoll(true), 180);
    report('ragdoll hanging', r);
    // Since contacts take the tree's stiffened inertia (2026-11-28): 1.04e-14 at one step end (step
    // 82, a contact in the passes; the projection may stop there, below its 1e-12 floor), the steps
    // around it at rounding (<= 4.6e-16). Before: 7.0e-16; main's tree: 45 m.
    expect(r.point).toBeLessThan(2e-14);
    expect(r.angle).toBeLessThan(1e-14); // 1.5e-15 (main's tree: 1.14 rad)
    expect(r.lowest).toBeGreaterThan(-2.5); // it hangs: the feet start at −1.95
  });

  it('a Y of three chains pinned at its three ends (3D, 4D), every joint closed to rounding over 3 s', () => {
    for (const n of [3, 4]) {
      const r = run(yTree(n), 180);
      report(`Y ${n}D`, r);
      expect(r.point).toBeLessThan(2e-14); // 1.9e-15 (3D), 3.7e-15 (4D) (main's tree: 1.06 m, 4.14 m)
      expect(r.lowest).toBeGreaterThan(-0.5); // it sags, held by its three ends
    }
  });

  it('the Y welded together and to the world at its three ends (3D: 72 rows on 60 unknowns) holds to rounding over 3 s', () => {
    for (const n of [3, 4]) {
      const s = yTree(n, true);
      const start = snapshot(s.world);
      const r = run(s, 180);
      let moved = 0;
      snapshot(s.world).forEach((x, i) => (moved = Math.max(moved, Math.abs(x - start[i]!))));
      report(`Y welded ${n}D (moved ${moved.toExponential(2)})`, r);
      expect(r.point).toBeLessThan(1e-14); // 3.1e-16 (3D), 3.2e-16 (4D) (main's tree: 3.7e-3 m, 6.8e-3 m)
      expect(r.angle).toBeLessThan(1e-14); // 2.6e-16, 2.4e-16 (main's tree: 6.0e-4 rad, 1.8e-4 rad)
      expect(moved).toBeLessThan(1e-14); // 1.4e-16, 1.1e-16: welded, nothing moves
    }
  });

  it('a free-falling ragdoll, kicked (no redundant rows), every joint closed to rounding over 3 s', () => {
    const r = run(kicked(ragdoll(false)), 180);
    report('ragdoll kicked', r);
    expect(r.point).toBeLessThan(5e-14); // 1.42e-14 (main's tree: 1.42e-14)
    expect(r.angle).toBeLessThan(1e-14); // 3.4e-15 (main's tree: 3.43e-15)
  });

  it('the written-out path of point joints in 3D gives the bits of the general path', () => {
    // The pinned Y and a 4 × 4 grid of point joints pinned along one side (joint-space-point.ts).
    const grid = (): Scene => {
      const points: number[][] = [];
      const edges: [number, number][] = [];
      const pins: [number, number[]][] = [];
      for (let r = 0; r < 4; r += 1)
        for (let c = 0; c < 4; c += 1) {
          const i = points.push([c, 0, r]) - 1;
          if (c > 0) edges.push([i - 1, i]);
          if (r > 0) edges.push([i - 4, i]);
          if (r === 0) pins.push([i, [c, 0, -0.5]]);
        }
      const s = jointTree(points, edges, pins, (_i, a, la, b, lb) => new PointJoint(a, b, la, lb));
      return { ...s, free: s.joints.map(() => null) };
    };
    const kickedY = (): Scene => {
      const s = yTree(3);
      s.bodies[2]!.v[2] = 3;
      s.bodies[5]!.v[0] = -2;
      return s;
    };
    const path = installedPoint3Path()!;
    for (const m of [() => yTree(3), kickedY, grid]) {
      // The written-out path, counted: it must be the one that ran.
      let factored = 0;
      setPoint3Path({ ...path, factor: (t) => ((factored += 1), path.factor(t)) });
      const a = m();
      run(a, 120);
      expect(factored).toBeGreaterThan(0);
      setPoint3Path(null);
      try {
        const b = m();
        run(b, 120);
        expect(snapshot(a.world)).toEqual(snapshot(b.world));
      } finally {
        usePoint3Path();
      }
    }
  });

  it('every scene gives the same bits in two runs', () => {
    const make = [() => ragdoll(true), () => yTree(3), () => yTree(4), () => yTree(3, true), () => kicked(ragdoll(false))];
    for (const m of make) {
      const a = m();
      const b = m();
      run(a, 90);
      run(b, 90);
      expect(snapshot(b.world)).toEqual(snapshot(a.world));
    }
  });
});
