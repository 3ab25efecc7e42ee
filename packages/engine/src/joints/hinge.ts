/**
 * The hinge: the point and every rotation plane but one, the free plane F (3D: 5 of 6 rows, the
 * door hinge; 4D: 9 of 10). F is simple — a plane index or a simple bivector in a's frame — and
 * the hinge angle θ is the turn in F, tracked across turns, with optional limits and a motor.
 *
 * @module
 */
import { isSimple } from '@physin/algebra';
import type { Body } from '../body.js';
import { currentAnchors, currentRelative, distance, planeFrameRotor, referenceFrame, turnAngle } from './frames.js';
import { Joint } from './joint.js';
import { JS_COMMON_COUNT, JS_H } from './joint-slots.js';
import type { JointOptions } from './joint.js';
import type { JointSolver } from './joint-solver.js';
import {
  KIND_ANGULAR,
  KIND_MOTOR,
  ROW_EQUAL,
  ROW_INEQUAL,
  ROW_MOTOR,
  SC_C,
  SC_H,
  SC_HI,
  SC_LO,
  SC_TARGET,
} from './joint-solver.js';
import { readFinite, readLimit, readNonNegative } from './options.js';
import { registerJointClass } from '../snapshot/registry.js';

/** Options of a {@link HingeJoint}. */
export interface HingeJointOptions extends JointOptions {
  /**
   * The free plane in a's frame: a plane index (integer, lexicographic order of the planes) or a
   * simple non-zero bivector of k numbers. Default 0 (the plane of the axes 0 and 1).
   */
  readonly plane?: number | ArrayLike<number>;
  /** Lower limit of the hinge angle (rad); default −Infinity (none). */
  readonly lowerAngle?: number;
  /** Upper limit of the hinge angle (rad); default +Infinity (none). */
  readonly upperAngle?: number;
  /** Target speed of the motor (rad/s); default 0. */
  readonly motorSpeed?: number;
  /** Largest torque of the motor (N·m, >= 0); default 0 = no motor. */
  readonly maxMotorTorque?: number;
}

const JS_ANGLE = JS_COMMON_COUNT;
const JS_LOWER = JS_COMMON_COUNT + 1;
const JS_UPPER = JS_COMMON_COUNT + 2;
const JS_SPEED = JS_COMMON_COUNT + 3;
const JS_MAX_TORQUE = JS_COMMON_COUNT + 4;

/** Relative tolerance of the simplicity test of a bivector plane: |F ∧ F| <= 1e-9 |F|². */
const SIMPLE_TOLERANCE = 1e-9;
const TWO_PI = 2 * Math.PI;

/**
 * A hinge between `a` and `b` (or `a` and the world): the anchors held together, every plane but
 * the free plane locked. Rows: n point rows and k − 1 locked planes (one block), then the motor
 * and the two limits.
 */
export class HingeJoint extends Joint {
  private readonly frameA: Float64Array;
  private readonly frameB: Float64Array;
  private readonly planeValue: Float64Array;

  /**
   * @param a the first body.
   * @param b the second body, or null for the world.
   * @param localA anchor on a, in a's frame (n numbers).
   * @param localB anchor on b, in b's frame, or a world point when b is null (n numbers).
   * @param opts `plane`, `lowerAngle`, `upperAngle`, `motorSpeed`, `maxMotorTorque` and the common options.
   * @throws TypeError / RangeError for a bad argument: a plane index out of range, a bivector of
   *   the wrong length, zero or not simple (e.g. e_xy + e_zw), lowerAngle > upperAngle, ...
   */
  constructor(a: Body, b: Body | null, localA: ArrayLike<number>, localB: ArrayLike<number>, opts?: HingeJointOptions) {
    const names = ['plane', 'lowerAngle', 'upperAngle', 'motorSpeed', 'maxMotorTorque'];
    super('new HingeJoint', a, b, localA, localB, opts as Record<string, unknown> | undefined, names, 5, (D) => D.n + D.k + 2);
    const fn = 'new HingeJoint';
    const D = this.D;
    const o = (opts ?? {}) as Record<string, unknown>;
    const F = new Float64Array(D.k);
    if (o.plane === undefined) {
      F[0] = 1;
    } else if (typeof o.plane === 'number') {
      if (!Number.isInteger(o.plane) || o.plane < 0 || o.plane >= D.k) {
        throw new RangeError(
          `${fn}: argument 'opts.plane' must be a plane index, an integer in [0, ${D.k - 1}], or a simple bivector of ${D.k} numbers, got ${o.plane}`,
        );
      }
      F[o.plane] = 1;
    } else {
      const B = o.plane as ArrayLike<number>;
      if (B === null || typeof B !== 'object' || typeof B.length !== 'number' || B.length !== D.k) {
        throw new TypeError(`${fn}: argument 'opts.plane' must be a plane index or a bivector of ${D.k} numbers (n = ${D.n})`);
      }
      let norm2 = 0;
      for (let p = 0; p < D.k; p += 1) {
        const v = B[p];
        if (typeof v !== 'number' || !Number.isFinite(v))
          throw new RangeError(`${fn}: argument 'opts.plane[${p}]' must be a finite number, got ${v}`);
        norm2 += v * v;
      }
      if (!(norm2 > 0)) throw new RangeError(`${fn}: argument 'opts.plane' must not be the zero bivector`);
      if (!isSimple(D, B, SIMPLE_TOLERANCE)) {
        throw new RangeError(
          `${fn}: argument 'opts.plane' must be a simple bivector (one plane, B ∧ B = 0): a hinge turns in one plane; e.g. e_xy + e_zw turns in two planes at once and is refused`,
        );
      }
      const inv = 1 / Math.sqrt(norm2);
      for (let p = 0; p < D.k; p += 1) F[p] = B[p]! * inv;
    }
    const lower = o.lowerAngle === undefined ? -Infinity : readLimit(fn, 'opts.lowerAngle', o.lowerAngle);
    const upper = o.upperAngle === undefined ? Infinity : readLimit(fn, 'opts.upperAngle', o.upperAngle);
    if (lower > upper)
      throw new RangeError(`${fn}: argument 'opts.lowerAngle' (${lower}) must be <= 'opts.upperAngle' (${upper})`);
    const speed = o.motorSpeed === undefined ? 0 : readFinite(fn, 'opts.motorSpeed', o.motorSpeed);
    const maxTorque = o.maxMotorTorque === undefined ? 0 : readNonNegative(fn, 'opts.maxMotorTorque', o.maxMotorTorque);
    this.planeValue = F;
    this.frameA = planeFrameRotor(D, F);
    this.frameB = referenceFrame(this, this.frameA);
    this.state[JS_ANGLE] = 0;
    this.state[JS_LOWER] = lower;
    this.state[JS_UPPER] = upper;
    this.state[JS_SPEED] = speed;
    this.state[JS_MAX_TORQUE] = maxTorque;
  }

  /** Rows it takes away: n + k − 1 (the limits add one more while they hold). */
  get rowCount(): number {
    return this.D.n + this.D.k - 1;
  }

  /** The free plane, a unit bivector in a's frame (a copy). */
  get plane(): Float64Array {
    return Float64Array.from(this.planeValue);
  }

  /**
   * The hinge angle (rad): the turn of b relative to a in the free plane since construction,
   * tracked across turns (a wheel that turned 10 times reports 20π). Read from the bodies' current
   * rotors, unwrapped against the angle of the last sub-step.
   */
  get angle(): number {
    const Q = currentRelative(this, this.frameA, this.frameB, false);
    const local = 2 * Math.atan2(-Q[1]!, Q[0]!);
    const prev = this.state[JS_ANGLE]!;
    let d = local - prev;
    d -= TWO_PI * Math.round(d / TWO_PI);
    return prev + d;
  }

  /** Lower limit (rad; −Infinity = none). */
  get lowerAngle(): number {
    return this.state[JS_LOWER]!;
  }

  /** Upper limit (rad; +Infinity = none). */
  get upperAngle(): number {
    return this.state[JS_UPPER]!;
  }

  /** Target speed of the motor (rad/s). */
  get motorSpeed(): number {
    return this.state[JS_SPEED]!;
  }

  /** Largest torque of the motor (N·m); 0 = no motor. */
  get maxMotorTorque(): number {
    return this.state[JS_MAX_TORQUE]!;
  }

  /** The torque the motor gave in the last sub-step (N·m, signed along the free plane). */
  get motorTorque(): number {
    const h = this.state[JS_H]!;
    return h > 0 ? this.lambda[this.D.n + this.D.k - 1]! / h : 0;
  }

  /**
   * Sets the limits (rad; ±Infinity = none).
   * @throws TypeError if not numbers; RangeError for NaN or lower > upper.
   */
  setLimits(lower: number, upper: number): this {
    const fn = 'HingeJoint.setLimits';
    const lo = readLimit(fn, 'lower', lower);
    const hi = readLimit(fn, 'upper', upper);
    if (lo > hi) throw new RangeError(`${fn}: argument 'lower' (${lo}) must be <= 'upper' (${hi})`);
    this.state[JS_LOWER] = lo;
    this.state[JS_UPPER] = hi;
    this.changed();
    return this;
  }

  /**
   * Sets the motor: target `speed` (rad/s) at most `maxTorque` (N·m; 0 = off). A torque, not an
   * impulse: its strength does not depend on the sub-step.
   * @throws TypeError / RangeError for a non-finite speed or a negative or non-finite torque.
   */
  setMotor(speed: number, maxTorque: number): this {
    const fn = 'HingeJoint.setMotor';
    const s = readFinite(fn, 'speed', speed);
    const t = readNonNegative(fn, 'maxTorque', maxTorque);
    this.state[JS_SPEED] = s;
    this.state[JS_MAX_TORQUE] = t;
    this.changed();
    return this;
  }

  /** The distance between the two anchors now (m). */
  error(): number {
    const { pA, pB } = currentAnchors(this);
    return distance(pA, pB);
  }

  /** The angle (rad) of the relative rotation left once the free turn is removed: 2·acos(⟨Q'⟩₀). */
  override angularError(): number {
    const D = this.D;
    const Q = currentRelative(this, this.frameA, this.frameB, false);
    const half = Math.atan2(-Q[1]!, Q[0]!);
    const T = new Float64Array(D.r);
    T[0] = Math.cos(half);
    T[1] = Math.sin(half);
    const Qp = D.kernels.mul(new Float64Array(D.r), Q, T);
    return turnAngle(Qp);
  }

  /** @internal */
  buildRows(js: JointSolver, j: number): void {
    const { n, k } = js;
    js.anchors(this);
    js.pointRows(j, 0);
    js.frames(this, this.frameA, this.frameB);
    const Q = js.Q;
    const st = this.state;
    // The free turn, then the angle tracked from the last sub-step.
    const half = Math.atan2(-Q[1], Q[0]);
    let d = 2 * half - st[JS_ANGLE];
    d -= TWO_PI * Math.round(d / TWO_PI);
    const angle = st[JS_ANGLE] + d;
    st[JS_ANGLE] = angle;
    // Q' = Q exp(+θ/2 F): the turn in F undone; its other planes are the locked error.
    const T = js.T;
    T.fill(0);
    T[0] = Math.cos(half);
    T[1] = Math.sin(half);
    js.D.kernels.mul(js.U, Q, T);
    const U = js.U;
    const sc = js.sc;
    for (let p = 1; p < k; p += 1) {
      js.framePlane(p, 1);
      sc[SC_C] = -2 * U[1 + p];
      js.addRow(j, n + p - 1, KIND_ANGULAR, ROW_EQUAL, 0);
    }
    const lam = this.lambda;
    const motorKey = n + k - 1;
    const maxTorque = st[JS_MAX_TORQUE];
    if (maxTorque > 0) {
      js.framePlane(0, 1);
      const h = sc[SC_H];
      sc[SC_C] = 0;
      sc[SC_LO] = -maxTorque * h;
      sc[SC_HI] = maxTorque * h;
      sc[SC_TARGET] = st[JS_SPEED];
      js.addRow(j, motorKey, KIND_MOTOR, ROW_MOTOR, 0);
    } else {
      lam[motorKey] = 0;
    }
    const lower = st[JS_LOWER];
    if (lower > -Infinity) {
      js.framePlane(0, 1);
      sc[SC_C] = angle - lower;
      js.addRow(j, motorKey + 1, KIND_ANGULAR, ROW_INEQUAL, 0);
    } else {
      lam[motorKey + 1] = 0;
    }
    const upper = st[JS_UPPER];
    if (upper < Infinity) {
      js.framePlane(0, -1);
      sc[SC_C] = upper - angle;
      js.addRow(j, motorKey + 2, KIND_ANGULAR, ROW_INEQUAL, 0);
    } else {
      lam[motorKey + 2] = 0;
    }
  }
}

// World snapshots rebuild saved joints of this type with this class (snapshot/registry.ts).
registerJointClass('hinge', HingeJoint);
