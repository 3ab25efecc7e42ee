/**
 * The base of every PhysiN mesh: a `THREE.Mesh` that owns a body of the scene's world.
 *
 * What Physijs users complained about is handled here: a command called before `scene.add` is
 * kept and applied at `add`, in order; moving the mesh after `add` (by `setPositionN`,
 * `rotateInPlane`, or in 3D by `mesh.position` / `mesh.quaternion`) teleports its body at the next
 * `simulate`, with no dirty flag to set.
 *
 * @module
 */
import * as THREE from 'three';
import {
  axisToBivector3,
  dims,
  quaternionToRotor,
  rotateInPlane as rotorRotateInPlane,
  rotorToQuaternion,
} from '@physin/algebra';
import type { Dims } from '@physin/algebra';
import type { BodyDescription, CommandMap, CommandName, HostId, ShapeDescription, WorldHost } from '@physin/worker';
import { describe, finite, integer, numbers } from './checks.js';

/** A collision of two meshes, as the `collision` event of each (a new object per event). */
export interface CollisionEvent {
  /** Always 'collision'. */
  readonly type: 'collision';
  /** 'begin' when the two start touching, 'end' when they stop. */
  readonly phase: 'begin' | 'end';
  /** The other mesh. */
  readonly other: Mesh;
  /** The deepest contact point, n world coordinates (zeros for 'end'). */
  readonly point: Float64Array;
  /** The contact normal, from this mesh toward `other` (zeros for 'end'). */
  readonly normal: Float64Array;
  /** Velocity of `other`'s material point at `point` minus this mesh's (zeros for 'end'). */
  readonly relativeVelocity: Float64Array;
  /** Total normal impulse of the first touching sub-step, N·s (0 for 'end'). */
  readonly impulse: number;
  /**
   * The mesh of this body that touched: a child mesh that is a part of this mesh's body (see
   * {@link Mesh}, compound bodies), or this mesh itself.
   */
  readonly part: Mesh;
  /** The mesh of the other body that touched: `other`, or one of its child meshes. */
  readonly otherPart: Mesh;
}

/** Events of a PhysiN mesh, on top of three's. */
export interface MeshEventMap extends THREE.Object3DEventMap {
  /** The body exists in the scene's world. */
  ready: object;
  /** A collision begins or ends. */
  collision: Omit<CollisionEvent, 'type'>;
}

/** What the specification calls `mesh._physiN`: the body's id (for `scene.execute`) and size. */
export interface MeshPhysics {
  /** The host id of the body, or null before `scene.add`. */
  readonly id: HostId | null;
  /** The count of dimensions, or null while it is not known yet. */
  readonly dimensions: number | null;
  /** The mass given to the constructor (0: static). */
  readonly mass: number;
}

/** A vector given to a mesh method: an array of n numbers, or in n ≤ 3 a `THREE.Vector3`. */
export type VectorInput = ArrayLike<number> | THREE.Vector3;
/** A bivector given to a mesh method: k numbers, or in 3D (and 2D) a `THREE.Vector3` axis. */
export type BivectorInput = ArrayLike<number> | THREE.Vector3;

/** @internal What a mesh needs from the scene that holds it. */
export interface SceneLink {
  readonly host: WorldHost;
  readonly D: Dims;
  markSliceDirty(mesh: Mesh): void;
}

type PendingCommand = { readonly cmd: CommandName; readonly params: Record<string, unknown> };

/**
 * A `THREE.Mesh` with a rigid body. Use one of its subclasses (`BoxMesh`, `HyperBoxMesh`, …).
 */
export abstract class Mesh extends THREE.Mesh<THREE.BufferGeometry, THREE.Material | THREE.Material[], MeshEventMap> {
  /** True for every PhysiN mesh (as three's `isMesh`). */
  readonly isPhysinMesh = true;
  /** The body's id, dimensions and mass (the specification's `mesh._physiN`). */
  readonly _physiN: MeshPhysics;
  /** @internal The scene whose world holds the body. */
  _link: SceneLink | null = null;
  /** @internal Position in n dimensions (the described origin), or null while n is unknown. */
  _x: Float64Array | null = null;
  /** @internal Rotor. */
  _R: Float64Array | null = null;
  /** @internal Linear velocity of the last report. */
  _v: Float64Array | null = null;
  /** @internal `position` and `quaternion` as the adapter last wrote them. */
  readonly _lastPosition = new THREE.Vector3();
  /** @internal */
  readonly _lastQuaternion = new THREE.Quaternion();
  /** @internal Commands called before `add`, in order. */
  readonly _pending: PendingCommand[] = [];
  /**
   * @internal The meshes of a compound body, in part order: this mesh, then its child PhysiN
   * meshes as they were at `add`; null for a body of one shape.
   */
  _parts: Mesh[] | null = null;
  /**
   * True for a half-space: its body is placed by its normal and offset, not by the mesh, so the
   * mesh's position neither moves the body nor follows it.
   */
  protected placedByShape = false;
  private readonly physics: { id: HostId | null; dimensions: number | null; mass: number };
  private readonly scratchQ = [0, 0, 0, 1];

  /**
   * @param dimensions the count of dimensions, or null when it comes from the first
   * `setPositionN` or from the scene at `add`
   */
  protected constructor(
    geometry: THREE.BufferGeometry,
    material: THREE.Material | THREE.Material[] | undefined,
    mass: number,
    dimensions: number | null,
  ) {
    super(geometry, material);
    this.physics = { id: null, dimensions: null, mass };
    this._physiN = this.physics;
    if (dimensions !== null) this.setDimensions(dimensions, this.constructor.name);
  }

  /** The count of dimensions of this mesh's body, or null while not known. */
  get dimensions(): number | null {
    return this.physics.dimensions;
  }

  /** @internal The counts of dimensions this kind of mesh can take. */
  acceptsDimensions(n: number): boolean {
    return n >= 2;
  }

  /** @internal Fixes the count of dimensions (once). */
  setDimensions(n: number, where: string): void {
    if (this.physics.dimensions === n) return;
    if (this.physics.dimensions !== null) {
      throw new RangeError(`${where}: this ${this.constructor.name} has ${this.physics.dimensions} dimensions, not ${n}`);
    }
    if (!this.acceptsDimensions(n)) throw new RangeError(`${where}: a ${this.constructor.name} cannot have ${n} dimensions`);
    const D = dims(n);
    this.physics.dimensions = n;
    this._x = new Float64Array(n);
    this._R = new Float64Array(D.r);
    this._R[0] = 1;
    this._v = new Float64Array(n);
    if (n <= 3) {
      // the pose lives in position/quaternion until add (three users set those)
      this._x[0] = this.position.x;
      this._x[1] = this.position.y;
      if (n === 3) {
        this._x[2] = this.position.z;
        this.writeRotorFromQuaternion();
      }
    }
  }

  /** @internal The shape of the body in `n` dimensions, the object's scale applied. */
  abstract describeShape(n: number): ShapeDescription;

  /**
   * @internal The body's description at `add`. Child PhysiN meshes (added to this mesh before it
   * is added to the scene, as in Physijs) become parts of this mesh's body, placed at their local
   * position and rotation (`position` and `quaternion`, or `setPositionN` / `rotateInPlane` in
   * n ≥ 4); the body has this mesh's mass alone, spread over the parts by volume.
   */
  describeBody(n: number): BodyDescription {
    this.readPoseFromObject();
    const children = this.children.filter((c): c is Mesh => c instanceof Mesh && c._link === null);
    this._parts = children.length > 0 ? [this, ...children] : null;
    const mass = this.physics.mass;
    const material = materialOf(this.material);
    let position = this._x!;
    let rotor = this._R!;
    if (this.placedByShape) {
      position = new Float64Array(n);
      rotor = new Float64Array(rotor.length);
      rotor[0] = 1;
    }
    return {
      shape: this._parts === null ? this.describeShape(n) : this.describeParts(n, children),
      ...(mass > 0 ? { mass, type: 'dynamic' as const } : { type: 'static' as const }),
      position,
      rotor,
      ...(material === null ? {} : { material }),
    };
  }

  /** The compound of this mesh's shape (at the body's origin) and its child meshes' shapes. */
  private describeParts(n: number, children: readonly Mesh[]): ShapeDescription {
    const where = `${this.constructor.name} (a compound body)`;
    const parts: { shape: ShapeDescription; position?: Float64Array; rotor?: Float64Array }[] = [
      { shape: this.describeShape(n) },
    ];
    for (const child of children) {
      if (child.dimensions === null) child.setDimensions(n, where);
      if (child.dimensions !== n)
        throw new RangeError(`${where}: its child ${child.constructor.name} has ${child.dimensions} dimensions, the scene ${n}`);
      child.readPoseFromObject();
      parts.push({ shape: child.describeShape(n), position: child._x!.slice(), rotor: child._R!.slice() });
    }
    return { kind: 'compound', parts };
  }

  /** @internal Called by the scene once the body exists. */
  bindBody(link: SceneLink, id: HostId): void {
    this._link = link;
    this.physics.id = id;
    this._lastPosition.copy(this.position);
    this._lastQuaternion.copy(this.quaternion);
    link.markSliceDirty(this);
  }

  /** @internal Called by the scene when the body is gone. */
  unbindBody(): void {
    this._link = null;
    this.physics.id = null;
  }

  // --- pose -------------------------------------------------------------------------------------

  /** Moves the body (before `add`, or a teleport after it). `p` has n numbers. */
  setPositionN(p: ArrayLike<number>): this {
    const where = `${this.constructor.name}.setPositionN`;
    const value = numbers(where, 'p', p, this.physics.dimensions);
    if (this.physics.dimensions === null) this.setDimensions(value.length, where);
    this._x!.set(value);
    this.writePositionFromX();
    this._lastPosition.copy(this.position);
    this.sendNow('setPositionN', { position: value });
    return this;
  }

  /** The position in n dimensions (a copy, or into `out`). */
  getPositionN(out?: Float64Array): Float64Array {
    this.readPoseFromObject();
    const x = this.requireX(`${this.constructor.name}.getPositionN`);
    return copyInto(out, x, `${this.constructor.name}.getPositionN`);
  }

  /** The rotor, 2^(n−1) numbers (a copy, or into `out`). */
  getRotor(out?: Float64Array): Float64Array {
    this.readPoseFromObject();
    this.requireX(`${this.constructor.name}.getRotor`);
    return copyInto(out, this._R!, `${this.constructor.name}.getRotor`);
  }

  /** Turns the body by `angle` radians in the plane of world axes i and j (e_i toward e_j). */
  rotateInPlane(i: number, j: number, angle: number): this {
    const where = `${this.constructor.name}.rotateInPlane`;
    const n = this.requireX(where).length;
    integer(where, 'i', i, 0, n - 1);
    integer(where, 'j', j, 0, n - 1);
    if (i === j) throw new RangeError(`${where}: arguments 'i' and 'j' must name two different axes, got ${i} twice`);
    finite(where, 'angle', angle, undefined, 'number of radians');
    this.readPoseFromObject();
    rotorRotateInPlane(dims(n), this._R!, this._R!, i, j, angle);
    this.writeQuaternionFromRotor();
    this._lastQuaternion.copy(this.quaternion);
    this.sendNow('rotateInPlane', { i, j, angle });
    return this;
  }

  // --- commands ---------------------------------------------------------------------------------

  /**
   * Sets the body's collision group and mask (32-bit masks: two bodies collide only when each
   * one's group meets the other's mask) and whether it is a sensor (it reports `collision` events
   * while it overlaps and pushes nothing); entries left out keep their value. Before `add` it is
   * kept and applied at `add`, as every command.
   */
  setCollisionFilter(filter: { readonly group?: number; readonly mask?: number; readonly sensor?: boolean }): this {
    if (filter === null || typeof filter !== 'object') {
      throw new TypeError(
        `${this.constructor.name}.setCollisionFilter: argument 'filter' must be an object { group?, mask?, sensor? }, got ${describe(filter)}`,
      );
    }
    const where = `${this.constructor.name}.setCollisionFilter`;
    // checked here too, so a bad value throws at the call even before add
    if (filter.group !== undefined) integer(where, 'filter.group', filter.group, 0, 0xffffffff);
    if (filter.mask !== undefined) integer(where, 'filter.mask', filter.mask, 0, 0xffffffff);
    if (filter.sensor !== undefined && typeof filter.sensor !== 'boolean') {
      throw new TypeError(`${where}: entry 'filter.sensor' must be a boolean, got ${describe(filter.sensor)}`);
    }
    return this.command('setCollisionFilter', { ...filter });
  }

  /** Sets the linear velocity (n numbers). */
  setLinearVelocity(v: VectorInput): this {
    return this.command('setLinearVelocity', { velocity: this.vector('setLinearVelocity', 'v', v) });
  }

  /** Sets the angular velocity: a bivector (k numbers), or in 3D a `THREE.Vector3` axis. */
  setAngularVelocity(w: BivectorInput): this {
    return this.command('setAngularVelocity', { angularVelocity: this.bivector('setAngularVelocity', 'w', w) });
  }

  /** Applies an impulse at the centre of mass (n numbers). */
  applyCentralImpulse(j: VectorInput): this {
    return this.command('applyCentralImpulse', { impulse: this.vector('applyCentralImpulse', 'j', j) });
  }

  /** Applies an impulse `j` at offset `r` from the centre of mass (world directions). */
  applyImpulse(j: VectorInput, r: VectorInput): this {
    return this.command('applyImpulse', {
      impulse: this.vector('applyImpulse', 'j', j),
      offset: this.vector('applyImpulse', 'r', r),
    });
  }

  /** Applies a force at the centre of mass for the next step. */
  applyCentralForce(f: VectorInput): this {
    return this.command('applyCentralForce', { force: this.vector('applyCentralForce', 'f', f) });
  }

  /** Applies a force `f` at offset `r` from the centre of mass for the next step. */
  applyForce(f: VectorInput, r: VectorInput): this {
    return this.command('applyForce', { force: this.vector('applyForce', 'f', f), offset: this.vector('applyForce', 'r', r) });
  }

  /** Applies a torque for the next step: a bivector, or in 3D a `THREE.Vector3` axis. */
  applyTorque(t: BivectorInput): this {
    return this.command('applyTorque', { torque: this.bivector('applyTorque', 't', t) });
  }

  /** The linear velocity of the last report (zeros before the first). */
  getLinearVelocity(out?: Float64Array): Float64Array {
    const where = `${this.constructor.name}.getLinearVelocity`;
    this.requireX(where);
    return copyInto(out, this._v!, where);
  }

  /** The angular velocity bivector of the last report, ω = I⁻¹L (zeros before the first). */
  getAngularVelocity(out?: Float64Array): Float64Array {
    const where = `${this.constructor.name}.getAngularVelocity`;
    const n = this.requireX(where).length;
    const k = (n * (n - 1)) / 2;
    if (out !== undefined && (!(out instanceof Float64Array) || out.length !== k)) {
      throw new TypeError(`${where}: argument 'out' must be a Float64Array of length ${k}, got ${describe(out)}`);
    }
    const result = out ?? new Float64Array(k);
    if (this._link === null || this.physics.id === null) return result.fill(0);
    return this._link.host.angularVelocity(this.physics.id, result);
  }

  // --- internals --------------------------------------------------------------------------------

  /** Sends a command now when the body exists, else keeps it for `add`. */
  private command<C extends CommandName>(cmd: C, params: Record<string, unknown>): this {
    if (this._link !== null && this.physics.id !== null) {
      this._link.host.execute(cmd, { ...params, id: this.physics.id } as unknown as CommandMap[C]);
    } else {
      this._pending.push({ cmd, params });
    }
    return this;
  }

  /** Sends a pose command only when the body exists (before add the pose is read at add). */
  private sendNow<C extends CommandName>(cmd: C, params: Record<string, unknown>): void {
    if (this._link !== null && this.physics.id !== null) {
      this._link.host.execute(cmd, { ...params, id: this.physics.id } as unknown as CommandMap[C]);
      this._link.markSliceDirty(this);
    }
  }

  /** @internal Applies the commands kept before add; throws the first failure. */
  flushPending(host: WorldHost, id: HostId): void {
    for (const { cmd, params } of this._pending) host.execute(cmd, { ...params, id } as never);
    this._pending.length = 0;
  }

  private vector(method: string, name: string, value: VectorInput): Float64Array {
    const where = `${this.constructor.name}.${method}`;
    const n = this.physics.dimensions;
    if (value instanceof THREE.Vector3) {
      if (n !== null && n > 3)
        throw new TypeError(
          `${where}: argument '${name}' must be an array of ${n} numbers in ${n} dimensions, got a THREE.Vector3`,
        );
      const out = numbers(where, name, [value.x, value.y, value.z], 3);
      return n === 2 ? out.subarray(0, 2).slice() : out;
    }
    return numbers(where, name, value, n);
  }

  private bivector(method: string, name: string, value: BivectorInput): Float64Array {
    const where = `${this.constructor.name}.${method}`;
    const n = this.physics.dimensions;
    if (value instanceof THREE.Vector3) {
      if (n !== null && n > 3)
        throw new TypeError(
          `${where}: argument '${name}' must be a bivector of ${(n * (n - 1)) / 2} numbers in ${n} dimensions, got a THREE.Vector3`,
        );
      const axis = numbers(where, name, [value.x, value.y, value.z], 3);
      // in 2D the only plane is e01, the turn about z
      return n === 2 ? Float64Array.of(axis[2]!) : axisToBivector3(new Float64Array(3), axis);
    }
    return numbers(where, name, value, n === null ? null : (n * (n - 1)) / 2, 'bivector components');
  }

  private requireX(where: string): Float64Array {
    if (this._x === null) {
      throw new RangeError(
        `${where}: this ${this.constructor.name} has no count of dimensions yet; call setPositionN or add it to a scene first`,
      );
    }
    return this._x;
  }

  /** @internal For n ≤ 3 before add, the pose the user gave by `position` / `quaternion`. */
  readPoseFromObject(): void {
    const n = this.physics.dimensions;
    if (n === null || this._link !== null) return;
    this._x![0] = this.position.x;
    this._x![1] = this.position.y;
    if (n >= 3) this._x![2] = this.position.z;
    if (n <= 3) this.writeRotorFromQuaternion();
  }

  /** @internal The move the user made since the adapter last wrote the pose: teleport the body. */
  sendMoves(): void {
    if (this.placedByShape || this._link === null || this.physics.id === null || this._x === null) return;
    const n = this._x.length;
    const host = this._link.host;
    const id = this.physics.id;
    if (!this.position.equals(this._lastPosition)) {
      if (!Number.isFinite(this.position.x + this.position.y + this.position.z)) {
        throw new RangeError(
          `${this.constructor.name}: mesh.position must be finite, got (${this.position.x}, ${this.position.y}, ${this.position.z})`,
        );
      }
      this._x[0] = this.position.x;
      this._x[1] = this.position.y;
      if (n >= 3) this._x[2] = this.position.z;
      host.execute('setPositionN', { id, position: this._x });
      this._lastPosition.copy(this.position);
      this._link.markSliceDirty(this);
    }
    if (n <= 3 && !this.quaternion.equals(this._lastQuaternion)) {
      this.writeRotorFromQuaternion();
      host.execute('setRotor', { id, rotor: this._R! });
      this._lastQuaternion.copy(this.quaternion);
    }
  }

  /** @internal Reads one body record of a report: `id | x (n) | R (r) | v (n) | L (k)`. */
  readRecord(bodies: Float32Array, at: number, n: number, r: number): void {
    if (this.placedByShape) return;
    const x = this._x!;
    const R = this._R!;
    const v = this._v!;
    let moved = false;
    for (let a = 0; a < n; a += 1) {
      const value = bodies[at + 1 + a]!;
      if (x[a] !== value) moved = true;
      x[a] = value;
    }
    for (let a = 0; a < r; a += 1) {
      const value = bodies[at + 1 + n + a]!;
      if (R[a] !== value) moved = true;
      R[a] = value;
    }
    for (let a = 0; a < n; a += 1) v[a] = bodies[at + 1 + n + r + a]!;
    if (!moved) return;
    this.writePositionFromX();
    this.writeQuaternionFromRotor();
    this._lastPosition.copy(this.position);
    this._lastQuaternion.copy(this.quaternion);
    if (n >= 4) this._link?.markSliceDirty(this);
  }

  private writePositionFromX(): void {
    const x = this._x!;
    // field stores rather than set(x, y, z): no boxed double arguments on the per-frame path
    const p = this.position;
    p.x = x[0]!;
    p.y = x[1]!;
    p.z = x.length >= 3 ? x[2]! : 0;
  }

  /** n = 3: the quaternion of the rotor; n = 2: the turn about z; n ≥ 4: the slice carries the turn. */
  private writeQuaternionFromRotor(): void {
    const R = this._R!;
    const q = this.scratchQ;
    if (R.length === 4) {
      rotorToQuaternion(q, R);
      this.quaternion.set(q[0]!, q[1]!, q[2]!, q[3]!);
    } else if (R.length === 2) {
      // e01 turns x toward y: the rotor cos(θ/2) − sin(θ/2) e01 is the quaternion about +z
      this.quaternion.set(0, 0, -R[1]!, R[0]!);
    }
  }

  private writeRotorFromQuaternion(): void {
    const R = this._R!;
    const q = this.quaternion;
    if (R.length === 4) {
      const len = Math.sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
      if (!(len > 0) || !Number.isFinite(len))
        throw new RangeError(`${this.constructor.name}: mesh.quaternion must be a finite non-zero quaternion`);
      const s = this.scratchQ;
      s[0] = q.x / len;
      s[1] = q.y / len;
      s[2] = q.z / len;
      s[3] = q.w / len;
      quaternionToRotor(R, s);
    } else if (R.length === 2) {
      const len = Math.sqrt(q.z * q.z + q.w * q.w);
      if (!(len > 0) || !Number.isFinite(len))
        throw new RangeError(`${this.constructor.name}: mesh.quaternion must turn about z in 2D`);
      R[0] = q.w / len;
      R[1] = -q.z / len;
    }
  }
}

/** The `_physiN` material values of a three.js material (the first of an array), or null. */
export function materialOf(
  material: THREE.Material | THREE.Material[] | undefined,
): { friction?: number; restitution?: number } | null {
  const m = Array.isArray(material) ? material[0] : material;
  const values = (m as { _physiN?: { friction?: number; restitution?: number } } | undefined)?._physiN;
  if (values === undefined || values === null) return null;
  const out: { friction?: number; restitution?: number } = {};
  if (values.friction !== undefined) out.friction = values.friction;
  if (values.restitution !== undefined) out.restitution = values.restitution;
  return out;
}

function copyInto(out: Float64Array | undefined, source: Float64Array, where: string): Float64Array {
  if (out === undefined) return source.slice();
  if (!(out instanceof Float64Array) || out.length !== source.length) {
    throw new TypeError(`${where}: argument 'out' must be a Float64Array of length ${source.length}, got ${describe(out)}`);
  }
  out.set(source);
  return out;
}
