// The 3D contact scenes of scenes/layouts.mjs in the peer engines, set up as a user would:
//
// - Rapier (@dimforge/rapier3d-compat): `await RAPIER.init()`, a World with its default
//   integration parameters (4 solver iterations, 1 internal PGS iteration), timestep 1/60; ground
//   a fixed body with a HalfSpace collider (normal +y); boxes ColliderDesc.cuboid(0.5, 0.5, 0.5),
//   density 1 (mass 1), friction 0.5, restitution 0, setCanSleep(false).
// - cannon-es: a World with gravity, allowSleep false, SAPBroadphase (what its docs suggest for
//   many bodies; the default NaiveBroadphase is O(N²)), GSSolver with 10 iterations, one Material
//   and a ContactMaterial friction 0.5, restitution 0 (also set as the default contact material);
//   ground a static Plane turned to face +y; boxes CANNON.Box(0.5³), mass 1.
//
// Each builder returns { step(), positions(), dispose() } with the same meaning as
// buildPhysinScene (positions() gives the box centres in layout order).

import { DT, FRICTION, GRAVITY, HALF, MASS, RESTITUTION } from './layouts.mjs';

/** Loads and initialises Rapier; throws with a readable message if it cannot. */
export async function loadRapier() {
  const mod = await import('@dimforge/rapier3d-compat');
  const RAPIER = mod.default ?? mod;
  await RAPIER.init();
  return RAPIER;
}

/** Loads cannon-es; throws if it cannot. */
export async function loadCannon() {
  const CANNON = await import('cannon-es');
  if (typeof CANNON.World !== 'function') throw new Error('cannon-es: no World export');
  return CANNON;
}

/** Builds a 3D layout in Rapier. */
export function buildRapierScene(RAPIER, layout) {
  if (layout.n !== 3) throw new RangeError(`buildRapierScene: ${layout.name} is ${layout.n}D; the peers are 3D`);
  const world = new RAPIER.World({ x: 0, y: -GRAVITY, z: 0 });
  world.timestep = DT;
  const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  world.createCollider(
    new RAPIER.ColliderDesc(new RAPIER.HalfSpace({ x: 0, y: 1, z: 0 })).setFriction(FRICTION).setRestitution(RESTITUTION),
    ground,
  );
  const density = MASS / (8 * HALF * HALF * HALF);
  const bodies = layout.positions.map(([x, y, z], i) => {
    const yaw = layout.yaws[i];
    const body = world.createRigidBody(
      RAPIER.RigidBodyDesc.dynamic()
        .setTranslation(x, y, z)
        .setRotation({ w: Math.cos(yaw / 2), x: 0, y: Math.sin(yaw / 2), z: 0 })
        .setCanSleep(false),
    );
    world.createCollider(
      RAPIER.ColliderDesc.cuboid(HALF, HALF, HALF).setDensity(density).setFriction(FRICTION).setRestitution(RESTITUTION),
      body,
    );
    return body;
  });
  return {
    step: () => world.step(),
    positions: () =>
      bodies.map((b) => {
        const t = b.translation();
        return [t.x, t.y, t.z];
      }),
    dispose: () => world.free(),
  };
}

/** Builds a 3D layout in cannon-es. */
export function buildCannonScene(CANNON, layout) {
  if (layout.n !== 3) throw new RangeError(`buildCannonScene: ${layout.name} is ${layout.n}D; the peers are 3D`);
  const world = new CANNON.World({ gravity: new CANNON.Vec3(0, -GRAVITY, 0), allowSleep: false });
  world.broadphase = new CANNON.SAPBroadphase(world);
  const solver = new CANNON.GSSolver();
  solver.iterations = 10;
  world.solver = solver;
  const material = new CANNON.Material('box');
  world.addContactMaterial(new CANNON.ContactMaterial(material, material, { friction: FRICTION, restitution: RESTITUTION }));
  world.defaultContactMaterial.friction = FRICTION;
  world.defaultContactMaterial.restitution = RESTITUTION;
  const ground = new CANNON.Body({ type: CANNON.Body.STATIC, mass: 0, shape: new CANNON.Plane(), material });
  ground.quaternion.setFromEuler(-Math.PI / 2, 0, 0); // the plane's normal +z turned to +y
  world.addBody(ground);
  const shape = new CANNON.Box(new CANNON.Vec3(HALF, HALF, HALF));
  const up = new CANNON.Vec3(0, 1, 0);
  const bodies = layout.positions.map(([x, y, z], i) => {
    const body = new CANNON.Body({ mass: MASS, shape, material, position: new CANNON.Vec3(x, y, z), allowSleep: false });
    body.quaternion.setFromAxisAngle(up, layout.yaws[i]);
    world.addBody(body);
    return body;
  });
  return {
    step: () => world.step(DT),
    positions: () => bodies.map((b) => [b.position.x, b.position.y, b.position.z]),
    dispose: () => {},
  };
}
