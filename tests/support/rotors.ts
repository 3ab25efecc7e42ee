import { rotorExp, rotorMul } from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import { randomArray } from './random.js';

/** Reference exp(−scale·B/2) by the plain power series (`terms` terms), summed with the public even product. */
export function seriesExp(D: Dims, B: ArrayLike<number>, scale = 1, terms = 40): Float64Array {
  const X = new Float64Array(D.r);
  for (let p = 0; p < D.k; p += 1) X[1 + p] = -0.5 * scale * B[p]!;
  const sum = new Float64Array(D.r);
  const term = new Float64Array(D.r);
  term[0] = 1;
  sum[0] = 1;
  for (let m = 1; m < terms; m += 1) {
    rotorMul(D, term, term, X);
    for (let a = 0; a < D.r; a += 1) term[a] = term[a]! / m;
    for (let a = 0; a < D.r; a += 1) sum[a] = sum[a]! + term[a]!;
  }
  return sum;
}

/** Unit rotor exp(−B/2) of a seeded random bivector with components in [−spread, spread). */
export function randomRotor(D: Dims, rand: () => number, spread = 3): Float64Array {
  return rotorExp(D, new Float64Array(D.r), randomArray(rand, D.k, -spread, spread));
}
