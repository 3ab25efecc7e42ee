// @physin/algebra alone: one 3D rotor product, with the 3D tables alone (dims3).
import { dims3, rotorFromPlane, rotorMul } from '@physin/algebra';

const D = dims3();
const a = rotorFromPlane(D, new Float64Array(D.r), 0, 1, 0.3);
const b = rotorFromPlane(D, new Float64Array(D.r), 1, 2, 0.2);
globalThis.result = rotorMul(D, new Float64Array(D.r), a, b);
