// The box world plus one hinge joint.
import { Body, HalfSpace, HingeJoint, HyperBox, World, dims } from '@physin/engine';

const D = dims(3);
const world = new World({ dimensions: 3, gravity: [0, -9.81, 0] });
world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
const a = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5, 0] }));
const b = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [1, 0.5, 0] }));
world.addConstraint(new HingeJoint(a, b, [0.5, 0, 0], [-0.5, 0, 0], { plane: 0 }));
world.step(1 / 60);
globalThis.result = b.x[1];
