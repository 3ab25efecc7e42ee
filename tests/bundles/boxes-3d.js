// The box world from @physin/engine/3d: 3D alone, no 4D or generic kernels.
import { Body, HalfSpace, HyperBox, World, dims } from '@physin/engine/3d';

const D = dims(3);
const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
for (let i = 0; i < 5; i += 1)
  world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5 + i, 0] }));
world.step(1 / 60);
globalThis.result = world.bodies[1].x[1];
