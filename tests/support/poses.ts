import { createPose } from '../../packages/engine/src/collision/manifold.js';
import type { Pose } from '../../packages/engine/src/collision/manifold.js';
import { randomArray, uniform } from './random.js';

/** Rotation by `angle` in the plane (i, j) applied after M, in place: M ← G M (e_i turns toward e_j). */
export function turn(n: number, M: Float64Array, i: number, j: number, angle: number): Float64Array {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  for (let col = 0; col < n; col += 1) {
    const a = M[i * n + col]!;
    const b = M[j * n + col]!;
    M[i * n + col] = c * a - s * b;
    M[j * n + col] = s * a + c * b;
  }
  return M;
}

/** A seeded random pose: a turn in every plane (i < j) by an angle in [−π, π), then x in [−spread, spread)ⁿ. */
export function randomPose(rand: () => number, n: number, spread: number): Pose {
  const pose = createPose(n);
  for (let i = 0; i < n; i += 1) for (let j = i + 1; j < n; j += 1) turn(n, pose.M, i, j, uniform(rand, -Math.PI, Math.PI));
  pose.x.set(randomArray(rand, n, -spread, spread));
  return pose;
}

/** A seeded random rotation: a product of Givens turns on the columns, in every plane (det = +1 by construction). */
export function randomRotation(rand: () => number, n: number): Float64Array {
  const M = new Float64Array(n * n);
  for (let i = 0; i < n; i += 1) M[i * n + i] = 1;
  for (let i = 0; i < n; i += 1) {
    for (let j = i + 1; j < n; j += 1) {
      const t = uniform(rand, -Math.PI, Math.PI);
      const c = Math.cos(t);
      const s = Math.sin(t);
      for (let r = 0; r < n; r += 1) {
        const a = M[r * n + i]!;
        const b = M[r * n + j]!;
        M[r * n + i] = c * a - s * b;
        M[r * n + j] = s * a + c * b;
      }
    }
  }
  return M;
}

/** world = x + M·local (M row-major n × n). */
export function toWorld(n: number, x: Float64Array, M: Float64Array, local: ArrayLike<number>): Float64Array {
  const out = new Float64Array(n);
  for (let i = 0; i < n; i += 1) {
    let s = x[i]!;
    for (let c = 0; c < n; c += 1) s += M[i * n + c]! * local[c]!;
    out[i] = s;
  }
  return out;
}
