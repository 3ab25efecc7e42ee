/**
 * Helpers for the joint tests (tests/joints-*.test.ts): world points of anchors, the error of a
 * point joint measured from the bodies' poses (not from the joint's own bookkeeping), the specification's
 * chain of 10 links, hinge angles and locked-plane errors from the relative rotor, and snapshots
 * of the whole body state (for "nothing changed" checks).
 *
 * Conventions: axis 1 ("y") is up, gravity −9.81 e_1; worlds from `makeWorld` (sleep off).
 */
import { rotorApplyVector, rotorFromPlane, rotorMul, rotorReverse } from '@physin/algebra';
import { Body, HyperSphere, PointJoint } from '@physin/engine';
import type { Dims, Joint, Params, Shape, World } from '@physin/engine';
import { makeWorld } from './scenes.js';

/** The world position of the body point `local` (body frame): x + R local R~. */
export function worldPoint(body: Body, local: ArrayLike<number>): Float64Array {
  const out = rotorApplyVector(body.D, new Float64Array(body.D.n), body.R, local);
  for (let i = 0; i < out.length; i += 1) out[i] = out[i]! + body.x[i]!;
  return out;
}

/** |p_B − p_A| for the anchors of a point joint; `b` null means `localB` is a world point. */
export function pointJointError(a: Body, localA: ArrayLike<number>, b: Body | null, localB: ArrayLike<number>): number {
  const pa = worldPoint(a, localA);
  const pb = b === null ? Float64Array.from(localB) : worldPoint(b, localB);
  let s = 0;
  for (let i = 0; i < pa.length; i += 1) s += (pb[i]! - pa[i]!) ** 2;
  return Math.sqrt(s);
}

/** The relative rotor Q = R_A~ R_B (B seen from A); a null A is the world (identity). */
export function relativeRotor(D: Dims, a: Body | null, b: Body): Float64Array {
  if (a === null) return Float64Array.from(b.R);
  const rev = rotorReverse(D, new Float64Array(D.r), a.R);
  return rotorMul(D, new Float64Array(D.r), rev, b.R);
}

/** Index (lexicographic) of the plane (i, j), i < j. */
export function planeIndexOf(n: number, i: number, j: number): number {
  return i * n - (i * (i + 1)) / 2 + (j - i - 1);
}

/** The pair (i, j) of plane index p in n dimensions. */
export function planePair(n: number, p: number): [number, number] {
  let q = 0;
  for (let i = 0; i < n; i += 1)
    for (let j = i + 1; j < n; j += 1) {
      if (q === p) return [i, j];
      q += 1;
    }
  throw new RangeError(`no plane ${p} in ${n} dimensions`);
}

/**
 * The hinge angle of Q in the free plane p = (i, j): θ = 2 atan2(−⟨Q⟩_F, ⟨Q⟩_0) (the brief's §8;
 * positive θ turns e_i toward e_j), in (−π, π].
 */
export function freePlaneAngle(Q: ArrayLike<number>, p: number): number {
  return 2 * Math.atan2(-Q[1 + p]!, Q[0]!);
}

/**
 * The locked-plane errors of Q for the free plane p: the free turn is undone,
 * Q' = Q · exp(+θ/2 F), and each plane q ≠ p reports 2|⟨Q'⟩_q| (≈ the angle in that plane, rad).
 * Returns the largest of them, and the largest grade-4 part (4D: e0123) times 2.
 */
export function lockedPlaneError(D: Dims, Q: ArrayLike<number>, p: number): number {
  const [i, j] = planePair(D.n, p);
  const theta = freePlaneAngle(Q, p);
  const undo = rotorFromPlane(D, new Float64Array(D.r), i, j, -theta);
  const Qp = rotorMul(D, new Float64Array(D.r), Q, undo);
  let worst = 0;
  for (let q = 0; q < D.k; q += 1) if (q !== p) worst = Math.max(worst, 2 * Math.abs(Qp[1 + q]!));
  for (let a = 1 + D.k; a < D.r; a += 1) worst = Math.max(worst, 2 * Math.abs(Qp[a]!));
  return worst;
}

/** θ_prev + wrap(θ_new − θ_prev): an angle tracked across turns. */
export function unwrap(prev: number, next: number): number {
  const d = next - prev;
  return prev + d - 2 * Math.PI * Math.round(d / (2 * Math.PI));
}

/**
 * The bodies' centres of a U of 6 links in 3D, to be pinned at (0, 0, 0) and (2, 0, 0): one
 * link set 0.2 m off the plane, so the U swings down out of its start.
 */
export const U_CHAIN_POINTS: number[][] = [
  [0, -0.5, 0],
  [0, -1.5, 0],
  [0.5, -2, 0],
  [1.5, -2, 0],
  [2, -1.5, 0.2],
  [2, -0.5, 0],
];

/** A joint scene: its world, bodies, and the worst joint error now (m). */
export interface JointScene {
  world: World;
  bodies: Body[];
  error: () => number;
}

/** A point joint to add: body A, its local anchor, body B (null: the world), its local anchor. */
export type PointJointSpec = [Body, number[], Body | null, number[]];

/** Adds `joints` as point joints to `world`; the scene's error is the worst of their gaps. */
export function pointJointScene(world: World, bodies: Body[], joints: PointJointSpec[]): JointScene {
  for (const [a, la, b, lb] of joints) world.addConstraint(new PointJoint(a, b, la, lb));
  const error = (): number => {
    let worst = 0;
    for (const [a, la, b, lb] of joints) worst = Math.max(worst, pointJointError(a, la, b, lb));
    return worst;
  };
  return { world, bodies, error };
}

/**
 * A side × side grid of balls (r 0.25, 1 kg, 1 m apart) in the x-z plane of a 3D world, point
 * joints to the right and +z neighbours, the row z = 0 pinned to the world where it starts.
 */
export function pinnedGrid(side: number, params: Partial<Params> = {}): JointScene {
  const world = makeWorld(3, params);
  const D = world.D;
  const shape = HyperSphere(D, 0.25);
  const bodies: Body[] = [];
  for (let row = 0; row < side; row += 1)
    for (let col = 0; col < side; col += 1) bodies.push(world.addBody(new Body(D, { shape, mass: 1, position: [col, 0, row] })));
  const joints: PointJointSpec[] = [];
  for (let col = 0; col < side; col += 1) joints.push([bodies[col]!, [0, 0, 0], null, [col, 0, 0]]);
  for (let row = 0; row < side; row += 1)
    for (let col = 0; col < side; col += 1) {
      const at = bodies[row * side + col]!;
      if (col + 1 < side) joints.push([at, [0.5, 0, 0], bodies[row * side + col + 1]!, [-0.5, 0, 0]]);
      if (row + 1 < side) joints.push([at, [0, 0, 0.5], bodies[(row + 1) * side + col]!, [0, 0, -0.5]]);
    }
  return pointJointScene(world, bodies, joints);
}

/** Every body's x, R, v, L, w, in world order, in one array (for bit-exact comparisons). */
export function snapshot(world: World): number[] {
  const out: number[] = [];
  for (const b of world.bodies) out.push(...b.x, ...b.R, ...b.v, ...b.L, ...b.w);
  return out;
}

/** One link of the specification's chain: 1 m between its anchors (local ±0.5 e_0), 1 kg. */
export const LINK_HALF_LENGTH = 0.5;
/** The radius of a link (a ball). */
export const LINK_RADIUS = 0.1;

export interface Chain {
  world: World;
  links: Body[];
  joints: PointJoint[];
  /** Largest anchor separation of the joints now (m). */
  error(): number;
}

export interface ChainOptions {
  /** Dimensions (default 3). */
  n?: number;
  /** true: the chain hangs straight down from the pivot; false: it starts horizontal along +x. */
  hanging: boolean;
  /** World parameters (merged over sleep off). */
  params?: Partial<Params>;
  /** Mass of the last link (default 1 kg: the specification's chain). */
  lastMass?: number;
  /** Number of links (default 10). */
  count?: number;
}

/**
 * The specification's chain: `count` links of 1 kg, 1 m apart, the first link joined to the world at the
 * origin. A link is a ball of radius 0.1 with its two anchors at local ±0.5 e_0 (the midpoints
 * between neighbouring centres); joints are point joints between the end of one link and the start
 * of the next. Horizontal: link i centred at ((i + 0.5), 0, …); hanging: centred at
 * (0, −(i + 0.5), 0, …), turned by −π/2 in the (x y) plane so that its local +x points down.
 * With these links Rapier 0.21 and cannon-es 0.20 reproduce the whipping-chain errors
 * (0.23 and 0.40: bench/joints.bench.mjs), so this is the scene those figures, and the specification's, are
 * most likely about.
 */
export function buildChain(options: ChainOptions): Chain {
  const n = options.n ?? 3;
  const count = options.count ?? 10;
  const world = makeWorld(n, options.params ?? {});
  const D = world.D;
  const shape = HyperSphere(D, LINK_RADIUS);
  const start = new Array<number>(n).fill(0);
  start[0] = -LINK_HALF_LENGTH;
  const end = new Array<number>(n).fill(0);
  end[0] = LINK_HALF_LENGTH;
  const rotor = options.hanging ? rotorFromPlane(D, new Float64Array(D.r), 0, 1, -Math.PI / 2) : undefined;
  const links: Body[] = [];
  for (let i = 0; i < count; i += 1) {
    const position = new Array<number>(n).fill(0);
    if (options.hanging) position[1] = -(i + 0.5);
    else position[0] = i + 0.5;
    const mass = i === count - 1 ? (options.lastMass ?? 1) : 1;
    links.push(world.addBody(new Body(D, { shape, mass, position, ...(rotor ? { rotor } : {}), name: `link${i}` })));
  }
  const joints: PointJoint[] = [];
  const pivot = new Array<number>(n).fill(0);
  joints.push(new PointJoint(links[0]!, null, start, pivot));
  for (let i = 1; i < count; i += 1) joints.push(new PointJoint(links[i - 1]!, links[i]!, end, start));
  for (const j of joints) world.addConstraint(j);
  const error = (): number => {
    let worst = pointJointError(links[0]!, start, null, pivot);
    for (let i = 1; i < count; i += 1) worst = Math.max(worst, pointJointError(links[i - 1]!, end, links[i]!, start));
    return worst;
  };
  return { world, links, joints, error };
}

/** Total energy of the chain: Σ kinetic + m g y (J; gravity 9.81 along −e_1). */
export function chainEnergy(chain: Chain): number {
  let e = 0;
  for (const b of chain.links) e += b.kineticEnergy() + b.mass * 9.81 * b.x[1]!;
  return e;
}

/**
 * Runs a chain for `steps` steps of dt and returns the worst joint error over every step end, and
 * the largest rise of the total energy above its start (J; > 0 means the solver put energy in).
 */
export function runChain(chain: Chain, steps: number, dt: number): { worst: number; energyRise: number; energyChange: number } {
  let worst = 0;
  const e0 = chainEnergy(chain);
  let eMax = e0;
  for (let s = 0; s < steps; s += 1) {
    chain.world.step(dt);
    worst = Math.max(worst, chain.error());
    eMax = Math.max(eMax, chainEnergy(chain));
    if (!Number.isFinite(worst)) return { worst: Infinity, energyRise: Infinity, energyChange: NaN };
  }
  return { worst, energyRise: eMax - e0, energyChange: chainEnergy(chain) - e0 };
}

/** Runs a chain for `steps` steps of dt and returns the worst joint error over every step end. */
export function worstChainError(chain: Chain, steps: number, dt: number): number {
  return runChain(chain, steps, dt).worst;
}

/** Makes the joint between `a` (anchor `la`) and `b` (anchor `lb`; null: the world, `lb` a world point); `i` counts the joints. */
export type JointMaker = (i: number, a: Body, la: number[], b: Body | null, lb: number[]) => Joint;

/** A chain of joints of any kind: its world, bodies and joints (in path order). */
export interface JointPath {
  world: World;
  bodies: Body[];
  joints: Joint[];
}

/** The links of a `jointPath` other than its 1 kg balls: a shape for all, a mass per link. */
export interface PathLinks {
  shape?: (D: Dims) => Shape;
  mass?: (i: number) => number;
}

/**
 * Balls of 1 kg at `points` (y up, n = points[0].length; other shapes and masses by `links`),
 * joined at the midpoints between neighbours by `make`, the first and (with `end`) the last joined
 * to the world at `start` and `end`. Every body starts unturned, so each joint's rest relative
 * rotor is the identity.
 */
export function jointPath(
  points: number[][],
  start: number[],
  end: number[] | null,
  make: JointMaker,
  params: Partial<Params> = {},
  links: PathLinks = {},
): JointPath {
  const world = makeWorld(points[0]!.length, params);
  const D = world.D;
  const shape = links.shape ? links.shape(D) : HyperSphere(D, LINK_RADIUS);
  const bodies = points.map((p, i) => world.addBody(new Body(D, { shape, mass: links.mass ? links.mass(i) : 1, position: p })));
  const local = (p: number[], at: number[]): number[] => at.map((v, i) => v - p[i]!);
  const joints: Joint[] = [];
  joints.push(make(0, bodies[0]!, local(points[0]!, start), null, start));
  for (let i = 1; i < points.length; i += 1) {
    const mid = points[i]!.map((v, d) => 0.5 * (v + points[i - 1]![d]!));
    joints.push(make(joints.length, bodies[i - 1]!, local(points[i - 1]!, mid), bodies[i]!, local(points[i]!, mid)));
  }
  if (end !== null)
    joints.push(make(joints.length, bodies[bodies.length - 1]!, local(points[points.length - 1]!, end), null, end));
  for (const j of joints) world.addConstraint(j);
  return { world, bodies, joints };
}

/**
 * The locked-angle error of a joint between `a` and `b` (null: the world) whose rest relative
 * rotor is the identity and whose free plane is the unit bivector `free` in a's frame (none: a
 * weld): 2|q − (q·F)F| for the bivector part q of Q = R_A~ R_B, about the angle (rad) the locked
 * planes turned, without the acos of the scalar part (which loses half the digits near 0).
 */
export function lockedAngleError(D: Dims, a: Body, b: Body | null, free: ArrayLike<number> | null): number {
  const Q = b === null ? rotorReverse(D, new Float64Array(D.r), a.R) : relativeRotor(D, a, b);
  let qf = 0;
  if (free !== null) for (let p = 0; p < D.k; p += 1) qf += Q[1 + p]! * free[p]!;
  let s = 0;
  for (let p = 0; p < D.k; p += 1) s += (Q[1 + p]! - (free === null ? 0 : qf * free[p]!)) ** 2;
  for (let i = 1 + D.k; i < D.r; i += 1) s += Q[i]! ** 2;
  return 2 * Math.sqrt(s);
}

/** A joint tree: its world, bodies, joints, and per joint its bodies and anchors (b null: the world, lb a world point). */
export interface JointTreeScene extends JointPath {
  ends: [Body, number[], Body | null, number[]][];
}

/**
 * Balls of 1 kg at `points` (y up, n = points[0].length), joined by `make` at the midpoints of the
 * pairs in `edges` (body indices), then each body of `pins` joined to the world at its world
 * point. Every body starts unturned, so each joint's rest relative rotor is the identity.
 */
export function jointTree(
  points: number[][],
  edges: [number, number][],
  pins: [number, number[]][],
  make: JointMaker,
  params: Partial<Params> = {},
): JointTreeScene {
  const world = makeWorld(points[0]!.length, params);
  const shape = HyperSphere(world.D, LINK_RADIUS);
  const bodies = points.map((p) => world.addBody(new Body(world.D, { shape, mass: 1, position: p })));
  const local = (i: number, at: number[]): number[] => at.map((v, d) => v - points[i]![d]!);
  const joints: Joint[] = [];
  const ends: [Body, number[], Body | null, number[]][] = [];
  for (const [a, b] of edges) {
    const mid = points[a]!.map((v, d) => 0.5 * (v + points[b]![d]!));
    ends.push([bodies[a]!, local(a, mid), bodies[b]!, local(b, mid)]);
  }
  for (const [a, at] of pins) ends.push([bodies[a]!, local(a, at), null, at]);
  ends.forEach(([a, la, b, lb], i) => joints.push(make(i, a, la, b, lb)));
  for (const j of joints) world.addConstraint(j);
  return { world, bodies, joints, ends };
}

/** What `runJointScene` measured: the worst point gap (m) and locked angle (rad), the lowest height (m). */
export interface JointRun {
  point: number;
  angle: number;
  lowest: number;
}

/**
 * Steps `world` `steps` times by `dt`; after each step, `errors` gives the scene's worst point gap
 * and locked angle. Returns the worst of each over every step and the lowest height (x₁) any of
 * `bodies` reached.
 */
export function runJointScene(
  world: World,
  bodies: readonly Body[],
  steps: number,
  dt: number,
  errors: () => [number, number],
): JointRun {
  let point = 0;
  let angle = 0;
  let lowest = Infinity;
  for (let t = 0; t < steps; t += 1) {
    world.step(dt);
    const [p, a] = errors();
    point = Math.max(point, p);
    angle = Math.max(angle, a);
    for (const b of bodies) lowest = Math.min(lowest, b.x[1]!);
  }
  return { point, angle, lowest };
}
