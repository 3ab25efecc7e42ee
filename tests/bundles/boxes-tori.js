// The box world plus tori.
import { Body, HalfSpace, HyperBox, HyperTorus, World, dims } from '@physin/engine';

const D = dims(3);
const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
for (let i = 0; i < 5; i += 1)
  world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5 + i, 0] }));
world.addBody(new Body(D, { shape: HyperTorus(D, 1, 0.25, 0), mass: 1, position: [3, 1, 0] }));
world.step(1 / 60);
globalThis.result = world.bodies[6].x[1];
