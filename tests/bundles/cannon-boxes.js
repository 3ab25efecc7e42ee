// cannon-es's box world, the same scene, bundled the same way.
import { Body, Box, Plane, Vec3, World } from 'cannon-es';

const world = new World({ gravity: new Vec3(0, -9.81, 0) });
const ground = new Body({ mass: 0, shape: new Plane() });
ground.quaternion.setFromEuler(-Math.PI / 2, 0, 0);
world.addBody(ground);
for (let i = 0; i < 5; i += 1)
  world.addBody(new Body({ mass: 1, shape: new Box(new Vec3(0.5, 0.5, 0.5)), position: new Vec3(0, 0.5 + i, 0) }));
world.step(1 / 60);
globalThis.result = world.bodies[1].position.y;
