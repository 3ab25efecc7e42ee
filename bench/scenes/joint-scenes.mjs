// Joint scenes for bench/joints.bench.mjs, in PhysiN (any n) and, in 3D, in Rapier and cannon-es,
// built from the same description so every engine simulates the same start.
//
// The chain (the specification's, section 8): `count` links of 1 kg, 1 m apart, the first joined to the
// world at the origin. A link is a ball of radius 0.1 whose two anchors are at ±0.5 along the
// chain (the midpoints between neighbouring centres). With these links Rapier 0.21 and cannon-es
// 0.20 reproduce the figures for the whipping chain (worst error 0.23 and 0.40); thin
// boxes 0.9 m long (more inertia at the anchors) gave them 0.03 and 0.17. Point joints (Rapier: spherical impulse joints; cannon-es: PointToPointConstraint) join
// the end of one link to the start of the next. 'horizontal': the links lie along +x (it whips);
// 'hanging': along −y. Contacts between the two bodies of a joint are off in every engine
// (PhysiN's default; Rapier setContactsEnabled(false); cannon-es collideConnected = false).
//
// The grid (Box2D's "joint grid", scaled down to side × side = 20 × 20): balls of radius 0.25 and
// 1 kg, 1 m apart, starting in the horizontal x-z plane; each ball is joined to its right (+x) and
// "down" (+z) neighbours by point joints at the midpoint; the "top" row (z = 0) is pinned to the
// world at the ball centres. Gravity −y: the grid swings down about the pinned row like a trap
// door and hangs.
//
// The error of a point joint is the distance between the world positions of its two anchors; the
// scenes report the largest over every joint (`error()`), and the total energy, kinetic (balls:
// I = 2/5 m r² in the peers) plus m g y (`energy()`, J). Gravity −9.81 e_1, sleep off everywhere.

import { World, Body, HyperSphere, PointJoint, dims } from '@physin/engine';
import { rotorApplyVector, rotorFromPlane } from '@physin/algebra';

export const GRAVITY = 9.81;
export const LINK_RADIUS = 0.1;
export const ANCHOR = 0.5;
export const BALL_RADIUS = 0.25;

function chainStarts(count, n, start) {
  return Array.from({ length: count }, (_, i) => {
    const p = new Array(n).fill(0);
    if (start === 'hanging') p[1] = -(i + 0.5);
    else p[0] = i + 0.5;
    return p;
  });
}

function worldAnchor(D, body, local, out) {
  rotorApplyVector(D, out, body.R, local);
  const x = body.x;
  for (let i = 0; i < D.n; i += 1) out[i] += x[i];
  return out;
}

function dist(a, b) {
  let s = 0;
  for (let i = 0; i < a.length; i += 1) s += (a[i] - b[i]) ** 2;
  return Math.sqrt(s);
}

/**
 * A PhysiN joint scene from a list of bodies and point joints. `joints[j] = [bodyIndexA,
 * localA, bodyIndexB | -1, localB]`.
 */
function physinScene(n, params, makeBodies, jointList) {
  const D = dims(n);
  const gravity = new Array(n).fill(0);
  gravity[1] = -GRAVITY;
  const world = new World({ dimensions: n, gravity, params: { allowSleep: false, ...params } });
  const bodies = makeBodies(D).map((b) => world.addBody(b));
  const joints = jointList.map(([ia, la, ib, lb]) =>
    world.addConstraint(new PointJoint(bodies[ia], ib < 0 ? null : bodies[ib], la, lb)),
  );
  const pa = new Float64Array(n);
  const pb = new Float64Array(n);
  const error = () => {
    let worst = 0;
    for (let j = 0; j < jointList.length; j += 1) {
      const [ia, la, ib, lb] = jointList[j];
      worldAnchor(D, bodies[ia], la, pa);
      if (ib < 0) for (let i = 0; i < n; i += 1) pb[i] = lb[i];
      else worldAnchor(D, bodies[ib], lb, pb);
      worst = Math.max(worst, dist(pa, pb));
    }
    return worst;
  };
  const energy = () => {
    let e = 0;
    for (const b of bodies) e += b.kineticEnergy() + b.mass * GRAVITY * b.x[1];
    return e;
  };
  return { world, bodies, joints, step: (dt) => world.step(dt), error, energy, dispose: () => {} };
}

function chainJoints(count, n) {
  const start = new Array(n).fill(0);
  start[0] = -ANCHOR;
  const end = new Array(n).fill(0);
  end[0] = ANCHOR;
  const list = [[0, start, -1, new Array(n).fill(0)]];
  for (let i = 1; i < count; i += 1) list.push([i - 1, end, i, start]);
  return list;
}

/** The chain in PhysiN, n dimensions. */
export function physinChain({ n = 3, count = 10, start = 'horizontal', params = {} } = {}) {
  const positions = chainStarts(count, n, start);
  return physinScene(
    n,
    params,
    (D) => {
      const shape = HyperSphere(D, LINK_RADIUS);
      const rotor = start === 'hanging' ? rotorFromPlane(D, new Float64Array(D.r), 0, 1, -Math.PI / 2) : undefined;
      return positions.map(
        (position, i) => new Body(D, { shape, mass: 1, position, ...(rotor ? { rotor } : {}), name: `link${i}` }),
      );
    },
    chainJoints(count, n),
  );
}

function gridJoints(side, n) {
  const list = [];
  const idx = (row, col) => row * side + col;
  const v = (axis, s) => {
    const out = new Array(n).fill(0);
    out[axis] = s;
    return out;
  };
  for (let col = 0; col < side; col += 1) list.push([idx(0, col), new Array(n).fill(0), -1, gridPosition(0, col, n)]);
  for (let row = 0; row < side; row += 1) {
    for (let col = 0; col < side; col += 1) {
      if (col + 1 < side) list.push([idx(row, col), v(0, 0.5), idx(row, col + 1), v(0, -0.5)]);
      if (row + 1 < side) list.push([idx(row, col), v(2, 0.5), idx(row + 1, col), v(2, -0.5)]);
    }
  }
  return list;
}

function gridPosition(row, col, n) {
  const p = new Array(n).fill(0);
  p[0] = col;
  p[2] = row;
  return p;
}

/** The 20 × 20 joint grid in PhysiN (3D). */
export function physinGrid({ side = 20, params = {} } = {}) {
  const n = 3;
  return physinScene(
    n,
    params,
    (D) => {
      const shape = HyperSphere(D, BALL_RADIUS);
      const out = [];
      for (let row = 0; row < side; row += 1)
        for (let col = 0; col < side; col += 1) out.push(new Body(D, { shape, mass: 1, position: gridPosition(row, col, n) }));
      return out;
    },
    gridJoints(side, n),
  );
}

// ---- peers ----------------------------------------------------------------------------------

function quatRotate(q, v) {
  // v' = v + 2w (q × v) + 2 q × (q × v)
  const tx = 2 * (q.y * v[2] - q.z * v[1]);
  const ty = 2 * (q.z * v[0] - q.x * v[2]);
  const tz = 2 * (q.x * v[1] - q.y * v[0]);
  return [
    v[0] + q.w * tx + (q.y * tz - q.z * ty),
    v[1] + q.w * ty + (q.z * tx - q.x * tz),
    v[2] + q.w * tz + (q.x * ty - q.y * tx),
  ];
}

function peerError(list, pose) {
  let worst = 0;
  for (const [ia, la, ib, lb] of list) {
    const a = pose(ia, la);
    const b = ib < 0 ? lb : pose(ib, lb);
    worst = Math.max(worst, Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  }
  return worst;
}

/**
 * A Rapier scene: default integration parameters (timestep set to dt), a fixed body at the origin
 * for the world joints, spherical impulse joints with contacts between the joined bodies off.
 * `kind`: 'chain' (boxes) or 'grid' (balls).
 */
function rapierScene(RAPIER, dt, positions, shapeDesc, list, rotation, radius) {
  const world = new RAPIER.World({ x: 0, y: -GRAVITY, z: 0 });
  world.timestep = dt;
  const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  const bodies = positions.map(([x, y, z], i) => {
    const desc = RAPIER.RigidBodyDesc.dynamic().setTranslation(x, y, z).setCanSleep(false);
    if (rotation) desc.setRotation(rotation);
    const body = world.createRigidBody(desc);
    world.createCollider(shapeDesc(i), body);
    return body;
  });
  const vec = (a) => ({ x: a[0], y: a[1], z: a[2] });
  for (const [ia, la, ib, lb] of list) {
    const data = RAPIER.JointData.spherical(vec(la), vec(lb));
    const joint =
      ib < 0
        ? world.createImpulseJoint(RAPIER.JointData.spherical(vec(la), vec(lb)), bodies[ia], ground, true)
        : world.createImpulseJoint(data, bodies[ia], bodies[ib], true);
    joint.setContactsEnabled(false);
  }
  const pose = (i, local) => {
    const t = bodies[i].translation();
    const r = quatRotate(bodies[i].rotation(), local);
    return [t.x + r[0], t.y + r[1], t.z + r[2]];
  };
  const energy = () => {
    let e = 0;
    for (const b of bodies) {
      const m = b.mass();
      const v = b.linvel();
      const w = b.angvel();
      e +=
        0.5 * m * (v.x * v.x + v.y * v.y + v.z * v.z) +
        0.5 * 0.4 * m * radius * radius * (w.x * w.x + w.y * w.y + w.z * w.z) +
        m * GRAVITY * b.translation().y;
    }
    return e;
  };
  return { step: () => world.step(), error: () => peerError(list, pose), energy, dispose: () => world.free() };
}

/** The chain in Rapier; the last link weighs `ratio` kg (the others 1 kg). */
export function rapierChain(RAPIER, { count = 10, start = 'horizontal', dt = 1 / 60, ratio = 1 } = {}) {
  const volume = (4 / 3) * Math.PI * LINK_RADIUS ** 3;
  const rotation = start === 'hanging' ? { w: Math.cos(-Math.PI / 4), x: 0, y: 0, z: Math.sin(-Math.PI / 4) } : null;
  return rapierScene(
    RAPIER,
    dt,
    chainStarts(count, 3, start),
    (i) => RAPIER.ColliderDesc.ball(LINK_RADIUS).setDensity((i === count - 1 ? ratio : 1) / volume),
    chainJoints(count, 3),
    rotation,
    LINK_RADIUS,
  );
}

/** The joint grid in Rapier. */
export function rapierGrid(RAPIER, { side = 20, dt = 1 / 60 } = {}) {
  const positions = [];
  for (let row = 0; row < side; row += 1) for (let col = 0; col < side; col += 1) positions.push(gridPosition(row, col, 3));
  const volume = (4 / 3) * Math.PI * BALL_RADIUS ** 3;
  return rapierScene(
    RAPIER,
    dt,
    positions,
    () => RAPIER.ColliderDesc.ball(BALL_RADIUS).setDensity(1 / volume),
    gridJoints(side, 3),
    null,
    BALL_RADIUS,
  );
}

/** A cannon-es scene: GSSolver 10 iterations, NaiveBroadphase replaced by SAP, PointToPointConstraint (collideConnected false). */
function cannonScene(CANNON, dt, positions, makeShape, list, quaternion, masses = null) {
  const world = new CANNON.World({ gravity: new CANNON.Vec3(0, -GRAVITY, 0), allowSleep: false });
  world.broadphase = new CANNON.SAPBroadphase(world);
  const solver = new CANNON.GSSolver();
  solver.iterations = 10;
  world.solver = solver;
  const ground = new CANNON.Body({ mass: 0, type: CANNON.Body.STATIC });
  world.addBody(ground);
  const shape = makeShape();
  const bodies = positions.map(([x, y, z], i) => {
    const body = new CANNON.Body({ mass: masses?.[i] ?? 1, shape, position: new CANNON.Vec3(x, y, z), allowSleep: false });
    if (quaternion) body.quaternion.set(quaternion.x, quaternion.y, quaternion.z, quaternion.w);
    world.addBody(body);
    return body;
  });
  const vec = (a) => new CANNON.Vec3(a[0], a[1], a[2]);
  for (const [ia, la, ib, lb] of list) {
    const c = new CANNON.PointToPointConstraint(bodies[ia], vec(la), ib < 0 ? ground : bodies[ib], vec(lb));
    c.collideConnected = false;
    world.addConstraint(c);
  }
  const pose = (i, local) => {
    const b = bodies[i];
    const r = quatRotate(b.quaternion, local);
    return [b.position.x + r[0], b.position.y + r[1], b.position.z + r[2]];
  };
  const energy = () => {
    let e = 0;
    for (const b of bodies) {
      const r = b.shapes[0].radius;
      e +=
        0.5 * b.mass * b.velocity.lengthSquared() +
        0.5 * 0.4 * b.mass * r * r * b.angularVelocity.lengthSquared() +
        b.mass * GRAVITY * b.position.y;
    }
    return e;
  };
  return { step: () => world.step(dt), error: () => peerError(list, pose), energy, dispose: () => {} };
}

/** The chain in cannon-es; the last link weighs `ratio` kg (the others 1 kg). */
export function cannonChain(CANNON, { count = 10, start = 'horizontal', dt = 1 / 60, ratio = 1 } = {}) {
  const q = start === 'hanging' ? { w: Math.cos(-Math.PI / 4), x: 0, y: 0, z: Math.sin(-Math.PI / 4) } : null;
  const masses = Array.from({ length: count }, (_, i) => (i === count - 1 ? ratio : 1));
  return cannonScene(
    CANNON,
    dt,
    chainStarts(count, 3, start),
    () => new CANNON.Sphere(LINK_RADIUS),
    chainJoints(count, 3),
    q,
    masses,
  );
}

/** The joint grid in cannon-es. */
export function cannonGrid(CANNON, { side = 20, dt = 1 / 60 } = {}) {
  const positions = [];
  for (let row = 0; row < side; row += 1) for (let col = 0; col < side; col += 1) positions.push(gridPosition(row, col, 3));
  return cannonScene(CANNON, dt, positions, () => new CANNON.Sphere(BALL_RADIUS), gridJoints(side, 3), null);
}
