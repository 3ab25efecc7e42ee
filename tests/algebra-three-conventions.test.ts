/**
 * The three.js conversions of @physin/algebra against three's own Quaternion and Matrix4: the
 * same rotation of the same vectors, seeded random rotors, to 1e-12.
 */
import { describe, expect, it } from 'vitest';
import { Matrix4, Quaternion, Vector3 } from 'three';
import {
  axisToBivector3,
  bivectorToAxis3,
  dims,
  quaternionToRotor,
  rotorApplyVector,
  rotorFromPlane,
  rotorMul,
  rotorToMatrix4,
  rotorToQuaternion,
} from '@physin/algebra';
import { seeded } from './support/random.js';

const D = dims(3);

function randomRotor(rand: () => number): Float64Array {
  let R = rotorFromPlane(D, new Float64Array(4), 0, 1, (rand() * 2 - 1) * Math.PI);
  R = rotorMul(D, new Float64Array(4), rotorFromPlane(D, new Float64Array(4), 1, 2, (rand() * 2 - 1) * Math.PI), R);
  return rotorMul(D, new Float64Array(4), rotorFromPlane(D, new Float64Array(4), 0, 2, (rand() * 2 - 1) * Math.PI), R);
}

describe('rotor ↔ three.js quaternion and Matrix4', () => {
  it('rotorToQuaternion turns vectors as the rotor does (200 seeded rotors)', () => {
    const rand = seeded(7);
    let worst = 0;
    for (let t = 0; t < 200; t += 1) {
      const R = randomRotor(rand);
      const q = new Quaternion().fromArray(rotorToQuaternion([0, 0, 0, 0], R));
      const m = new Matrix4().fromArray(rotorToMatrix4(new Array<number>(16).fill(0), R));
      for (let s = 0; s < 3; s += 1) {
        const v = [rand() - 0.5, rand() - 0.5, rand() - 0.5];
        const expected = rotorApplyVector(D, new Float64Array(3), R, v);
        const a = new Vector3(...v).applyQuaternion(q);
        const b = new Vector3(...v).applyMatrix4(m);
        for (let i = 0; i < 3; i += 1)
          worst = Math.max(worst, Math.abs(a.getComponent(i) - expected[i]!), Math.abs(b.getComponent(i) - expected[i]!));
      }
      const back = quaternionToRotor(new Float64Array(4), [q.x, q.y, q.z, q.w]);
      for (let i = 0; i < 4; i += 1) worst = Math.max(worst, Math.abs(back[i]! - R[i]!));
    }
    expect(worst).toBeLessThan(1e-12);
  });

  it('a turn of θ in the xy plane is three.js rotation of θ about +z', () => {
    const R = rotorFromPlane(D, new Float64Array(4), 0, 1, 0.7);
    const q = new Quaternion().setFromAxisAngle(new Vector3(0, 0, 1), 0.7);
    const mine = rotorToQuaternion([0, 0, 0, 0], R);
    expect(mine[0]).toBeCloseTo(q.x, 14);
    expect(mine[1]).toBeCloseTo(q.y, 14);
    expect(mine[2]).toBeCloseTo(q.z, 14);
    expect(mine[3]).toBeCloseTo(q.w, 14);
  });

  it('axis ↔ bivector: ω about +y is ω_xz = −ω (x turns toward −z)', () => {
    expect(axisToBivector3([0, 0, 0], [0, 2, 0])).toEqual([0, -2, 0]);
    expect(axisToBivector3([0, 0, 0], [1, 0, 0]).map(Math.abs)).toEqual([0, 0, 1]);
    expect(axisToBivector3([0, 0, 0], [0, 0, 3]).map(Math.abs)).toEqual([3, 0, 0]);
    expect(bivectorToAxis3([0, 0, 0], axisToBivector3([0, 0, 0], [0.1, -0.2, 0.3]))).toEqual([0.1, -0.2, 0.3]);
    // The velocity of a point: ω × r (axis) equals r ⌋ ω (bivector).
    const axis = new Vector3(0.3, -1.2, 0.5);
    const r = new Vector3(1, 2, -0.5);
    const cross = new Vector3().crossVectors(axis, r);
    const B = axisToBivector3([0, 0, 0], [axis.x, axis.y, axis.z]);
    // v_j += ω_ij r_i, v_i −= ω_ij r_j over the planes (0,1), (0,2), (1,2)
    const v = [0, 0, 0];
    const planes = [
      [0, 1],
      [0, 2],
      [1, 2],
    ] as const;
    planes.forEach(([i, j], p) => {
      const rr = [r.x, r.y, r.z];
      v[j] += B[p]! * rr[i]!;
      v[i] -= B[p]! * rr[j]!;
    });
    expect(v[0]).toBeCloseTo(cross.x, 14);
    expect(v[1]).toBeCloseTo(cross.y, 14);
    expect(v[2]).toBeCloseTo(cross.z, 14);
  });

  it('bad input names the argument', () => {
    expect(() => rotorToQuaternion([0, 0, 0, 0], [1, 0, 0])).toThrow(/argument 'R' must have 4 numbers/);
    expect(() => axisToBivector3([0, 0, 0], [0, NaN, 0])).toThrow(RangeError);
  });
});
