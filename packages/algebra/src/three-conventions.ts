/**
 * The 3D conventions of three.js, as conversions: rotors ↔ quaternions ([x, y, z, w]), a rotor as a
 * column-major Matrix4, and axis vectors ↔ bivectors. Allocation-free, `out` first.
 *
 * Rotor storage in 3D is [1, e01, e02, e12]; R = cos(θ/2) − sin(θ/2) B turns e_i toward e_j for
 * B = e_ij. The same rotation as a unit quaternion is w = R[0], x = −R[3], y = R[2], z = −R[1].
 * Bivector order is [xy, xz, yz]; as an axis vector ω = (ω_yz, −ω_xz, ω_xy).
 *
 * @module
 */

function check(fn: string, name: string, value: ArrayLike<number>, length: number): void {
  if (value === null || typeof value !== 'object' || typeof value.length !== 'number') {
    throw new TypeError(`${fn}: argument '${name}' must be an array of ${length} numbers`);
  }
  if (value.length !== length) throw new TypeError(`${fn}: argument '${name}' must have ${length} numbers, got ${value.length}`);
  for (let i = 0; i < length; i += 1) {
    const x = value[i];
    if (typeof x !== 'number') throw new TypeError(`${fn}: argument '${name}'[${i}] must be a number, got ${typeof x}`);
    if (!Number.isFinite(x)) throw new RangeError(`${fn}: argument '${name}'[${i}] must be finite, got ${x}`);
  }
}

/** out = the quaternion [x, y, z, w] (three.js order) of the 3D rotor R. */
export function rotorToQuaternion<
  T extends {
    [i: number]: number;
    /** Count of numbers. */
    length: number;
  },
>(out: T, R: ArrayLike<number>): T {
  check('rotorToQuaternion', 'R', R, 4);
  const r0 = R[0]!;
  const r1 = R[1]!;
  const r2 = R[2]!;
  const r3 = R[3]!;
  out[0] = -r3;
  out[1] = r2;
  out[2] = -r1;
  out[3] = r0;
  return out;
}

/** out = the 3D rotor of the quaternion q = [x, y, z, w] (three.js order). */
export function quaternionToRotor<
  T extends {
    [i: number]: number;
    /** Count of numbers. */
    length: number;
  },
>(out: T, q: ArrayLike<number>): T {
  check('quaternionToRotor', 'q', q, 4);
  const x = q[0]!;
  const y = q[1]!;
  const z = q[2]!;
  const w = q[3]!;
  out[0] = w;
  out[1] = -z;
  out[2] = y;
  out[3] = -x;
  return out;
}

/** out (16 numbers, column-major as three's Matrix4.elements) = the rotation of the 3D rotor R. */
export function rotorToMatrix4<
  T extends {
    [i: number]: number;
    /** Count of numbers. */
    length: number;
  },
>(out: T, R: ArrayLike<number>): T {
  check('rotorToMatrix4', 'R', R, 4);
  const w = R[0]!;
  const x = -R[3]!;
  const y = R[2]!;
  const z = -R[1]!;
  const x2 = x + x;
  const y2 = y + y;
  const z2 = z + z;
  const xx = x * x2;
  const xy = x * y2;
  const xz = x * z2;
  const yy = y * y2;
  const yz = y * z2;
  const zz = z * z2;
  const wx = w * x2;
  const wy = w * y2;
  const wz = w * z2;
  out[0] = 1 - (yy + zz);
  out[1] = xy + wz;
  out[2] = xz - wy;
  out[3] = 0;
  out[4] = xy - wz;
  out[5] = 1 - (xx + zz);
  out[6] = yz + wx;
  out[7] = 0;
  out[8] = xz + wy;
  out[9] = yz - wx;
  out[10] = 1 - (xx + yy);
  out[11] = 0;
  out[12] = 0;
  out[13] = 0;
  out[14] = 0;
  out[15] = 1;
  return out;
}

/** out = the 3D bivector [xy, xz, yz] of the axis vector a (ω about a, right-handed). */
export function axisToBivector3<
  T extends {
    [i: number]: number;
    /** Count of numbers. */
    length: number;
  },
>(out: T, a: ArrayLike<number>): T {
  check('axisToBivector3', 'a', a, 3);
  const ax = a[0]!;
  const ay = a[1]!;
  const az = a[2]!;
  out[0] = az;
  out[1] = -ay;
  out[2] = ax;
  return out;
}

/** out = the axis vector of the 3D bivector B = [xy, xz, yz]. */
export function bivectorToAxis3<
  T extends {
    [i: number]: number;
    /** Count of numbers. */
    length: number;
  },
>(out: T, B: ArrayLike<number>): T {
  check('bivectorToAxis3', 'B', B, 3);
  const xy = B[0]!;
  const xz = B[1]!;
  const yz = B[2]!;
  out[0] = yz;
  out[1] = -xz;
  out[2] = xy;
  return out;
}
