/**
 * Shapes in a snapshot: one rebuild function per shape kind, and a generic dump of every data
 * field of the shape object.
 *
 * A shape is written as its kind, the count of dimensions it was built for, its mass properties
 * per unit mass (volume and the diagonal covariance, when it has mass), and every own data field
 * (numbers, booleans, strings, null, typed arrays) by name. Reading rebuilds the shape with its
 * kind's public factory (which supplies the functions: the pair colliders and `massProperties`),
 * then puts back every saved data field bit for bit. A factory that does not reproduce the saved
 * numbers exactly (a convex mesh rebuilt from vertices already in its principal frame finds a
 * frame a rounding away from the identity; a half-space normalises its normal again) is thus
 * corrected, and `massProperties` is replaced by one on the saved per-unit-mass values when the
 * rebuilt one differs.
 *
 * Adding a shape kind: add an entry to `REBUILD` (the factory call from the saved fields), and
 * one `registerShapeFactory(kind, factory)` line to the kind's module (registry.ts says why). A
 * kind without an entry makes `snapshotWorld(world)` throw, naming the kind, rather than write a
 * shape the reader cannot rebuild.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import type { HyperBox } from '../shapes/box.js';
import type { HyperCapsule } from '../shapes/capsule.js';
import type { Compound } from '../shapes/compound.js';
import type { ConvexMesh } from '../shapes/convex-mesh.js';
import type { HalfSpace } from '../shapes/half-space.js';
import { diagonalMassProperties, checkMassArguments } from '../shapes/mass-properties.js';
import type { MassProperties, Shape } from '../shapes/shape.js';
import type { HyperSphere } from '../shapes/sphere.js';
import type { HyperTorus } from '../shapes/torus.js';
import type { SnapshotReader } from './reader.js';
import { shapeFactory } from './registry.js';
import type { SnapshotWriter } from './writer.js';

/** The saved data fields of a shape, by name. */
type Fields = Record<string, unknown>;

/** Field tags of the generic dump. */
const TAG_NUMBER = 0;
const TAG_BOOLEAN = 1;
const TAG_STRING = 2;
const TAG_NULL = 3;
const TAG_F64 = 4;
const TAG_I32 = 5;
const TAG_U32 = 6;
const TAG_U8 = 7;

/**
 * Whether a field is code, not data (functions, the pair collider table and a compound's
 * `worldOps`), or a compound's `parts` (written as shapes of their own before its fields): taken
 * from the rebuilt shape.
 */
function isCode(name: string, value: unknown): boolean {
  return typeof value === 'function' || name === 'colliders' || name === 'worldOps' || name === 'parts';
}

function hasOwn(object: object, name: string): boolean {
  return Object.prototype.hasOwnProperty.call(object, name);
}

function num(r: SnapshotReader, f: Fields, name: string): number {
  const v = f[name];
  if (typeof v !== 'number') r.fail(`a shape lacks the number field '${name}'`);
  return v;
}

function f64(r: SnapshotReader, f: Fields, name: string): Float64Array {
  const v = f[name];
  if (!(v instanceof Float64Array)) r.fail(`a shape lacks the Float64Array field '${name}'`);
  return v;
}

/**
 * The registered factory of `kind` (see registry.ts), typed as `F`. A program that never loaded
 * the kind's module cannot rebuild it: the error says which factory to reference.
 */
function factory<F>(kind: string, name: string): F {
  const f = shapeFactory(kind);
  if (typeof f !== 'function') {
    throw new Error(
      `restoreWorld: the snapshot holds a shape of kind '${kind}', and this program never loaded ${name}; reference ${name} from @physin/engine before restoring`,
    );
  }
  return f as F;
}

/**
 * The factory call of each shape kind, from the saved fields (the result is then corrected to the
 * saved fields exactly). One function per kind: a new kind needs one line here, and its module
 * one `registerShapeFactory` line (registry.ts).
 */
const REBUILD: Readonly<Record<string, (D: Dims, f: Fields, r: SnapshotReader) => Shape>> = {
  box: (D, f, r) => factory<typeof HyperBox>('box', 'HyperBox')(D, f64(r, f, 'halfExtents')),
  sphere: (D, f, r) => factory<typeof HyperSphere>('sphere', 'HyperSphere')(D, num(r, f, 'radius')),
  halfspace: (D, f, r) => factory<typeof HalfSpace>('halfspace', 'HalfSpace')(D, f64(r, f, 'normal'), num(r, f, 'offset')),
  torus: (D, f, r) =>
    factory<typeof HyperTorus>('torus', 'HyperTorus')(D, num(r, f, 'majorRadius'), num(r, f, 'minorRadius'), num(r, f, 'plane')),
  mesh: (D, f, r) => rebuildMesh(D, f, r),
  capsule: (D, f, r) => factory<typeof HyperCapsule>('capsule', 'HyperCapsule')(D, num(r, f, 'halfHeight'), num(r, f, 'radius')),
  compound: (D, f, r) => rebuildCompound(D, f, r),
};

/**
 * A compound from its saved parts (read before its fields, in `f.parts`): any valid placement
 * serves, since every data field (offsets, rotations, frame) is then put back as saved.
 */
function rebuildCompound(D: Dims, f: Fields, r: SnapshotReader): Shape {
  const parts = f.parts as Shape[];
  const offsets = f64(r, f, 'partOffsets');
  if (offsets.length !== parts.length * D.n) r.fail('a compound has the wrong count of part offsets');
  return factory<typeof Compound>('compound', 'Compound')(
    D,
    parts.map((shape, i) => ({ shape, position: offsets.subarray(i * D.n, (i + 1) * D.n) })),
  );
}

/**
 * A convex mesh from its saved vertices (already in the principal frame) and facets. The saved
 * `tolerance` is absolute (relative × size); the relative one is recovered from the size of the
 * saved vertices, a hair larger so that the convexity check passes as it did at first.
 */
function rebuildMesh(D: Dims, f: Fields, r: SnapshotReader): Shape {
  const vertices = f64(r, f, 'vertices');
  const facets = f.facets;
  if (!(facets instanceof Int32Array)) r.fail("a mesh lacks its Int32Array field 'facets'");
  const n = D.n;
  const count = vertices.length / n;
  const mean = new Float64Array(n);
  for (let i = 0; i < count; i += 1) for (let c = 0; c < n; c += 1) mean[c] += vertices[i * n + c]!;
  for (let c = 0; c < n; c += 1) mean[c] /= count;
  let size = 0;
  for (let i = 0; i < count; i += 1) {
    let d2 = 0;
    for (let c = 0; c < n; c += 1) d2 += (vertices[i * n + c]! - mean[c]!) ** 2;
    size = Math.max(size, Math.sqrt(d2));
  }
  const tolerance = (num(r, f, 'tolerance') / size) * (1 + 1e-6);
  return factory<typeof ConvexMesh>('mesh', 'ConvexMesh')(D, vertices, Int32Array.from(facets), { tolerance });
}

/** The kinds a snapshot can hold. */
export const SNAPSHOT_SHAPE_KINDS: readonly string[] = Object.freeze(Object.keys(REBUILD));

/** The shape's mass properties per unit mass, or null for a shape without mass (a half-space). */
function unitMass(D: Dims, shape: Shape): MassProperties | null {
  try {
    return shape.massProperties(D, 1);
  } catch {
    return null;
  }
}

/**
 * Writes one shape (see the module). `D` is the world's dimension tables.
 * @throws Error naming the kind if the snapshot code cannot rebuild it, or a field it cannot store.
 */
export function writeShape(w: SnapshotWriter, D: Dims, shape: Shape): void {
  const kind = String(shape.kind);
  if (!hasOwn(REBUILD, kind)) {
    throw new Error(
      `World.snapshot: a body has a shape of kind '${kind}', which snapshots do not support yet (known: ${SNAPSHOT_SHAPE_KINDS.join(', ')}); add it to packages/engine/src/snapshot/shapes.ts`,
    );
  }
  w.string(kind);
  if (kind === 'compound') {
    // The parts first, each a shape of its own (a compound holds no compound).
    const parts = (shape as unknown as { parts: readonly Shape[] }).parts;
    w.u32(parts.length);
    for (const part of parts) writeShape(w, D, part);
  }
  const mp = unitMass(D, shape);
  w.bool(mp !== null);
  if (mp !== null) {
    w.f64(mp.volume);
    w.f64s(mp.covariance, 0, D.n);
  }
  const names = Object.keys(shape).filter((name) => !isCode(name, (shape as unknown as Fields)[name]));
  w.u32(names.length);
  for (const name of names) {
    const value = (shape as unknown as Fields)[name];
    w.string(name);
    if (typeof value === 'number') {
      w.u8(TAG_NUMBER);
      w.f64(value);
    } else if (typeof value === 'boolean') {
      w.u8(TAG_BOOLEAN);
      w.bool(value);
    } else if (typeof value === 'string') {
      w.u8(TAG_STRING);
      w.string(value);
    } else if (value === null || value === undefined) {
      w.u8(TAG_NULL);
    } else if (value instanceof Float64Array) {
      w.u8(TAG_F64);
      w.u32(value.length);
      w.f64s(value);
    } else if (value instanceof Int32Array) {
      w.u8(TAG_I32);
      w.u32(value.length);
      w.i32s(value);
    } else if (value instanceof Uint32Array) {
      w.u8(TAG_U32);
      w.u32(value.length);
      w.u32s(value);
    } else if (value instanceof Uint8Array) {
      w.u8(TAG_U8);
      w.u32(value.length);
      w.u8s(value);
    } else {
      throw new Error(
        `World.snapshot: shape kind '${kind}' has a field '${name}' of a type snapshots cannot store (${typeof value}); extend packages/engine/src/snapshot/shapes.ts`,
      );
    }
  }
}

/** Reads one shape written by {@link writeShape}. */
export function readShape(r: SnapshotReader, D: Dims): Shape {
  const kind = r.string();
  const rebuild = hasOwn(REBUILD, kind) ? REBUILD[kind]! : null;
  if (rebuild === null) r.fail(`unknown shape kind '${kind}'`);
  let parts: Shape[] | null = null;
  if (kind === 'compound') {
    const count = r.count('the part count of a compound', 1 << 20, 10);
    parts = [];
    for (let i = 0; i < count; i += 1) {
      const part = readShape(r, D);
      if (part.kind === 'compound') r.fail('a compound holds a compound');
      parts.push(part);
    }
  }
  let volume = 0;
  let covariance: Float64Array | null = null;
  if (r.bool()) {
    volume = r.f64();
    covariance = r.f64s(D.n);
  }
  const count = r.count('the field count of a shape', 64, 6);
  const fields: Fields = Object.create(null) as Fields; // names come from the bytes: no prototype to hit
  for (let i = 0; i < count; i += 1) {
    const name = r.string();
    const tag = r.u8();
    const limit = 1 << 26;
    switch (tag) {
      case TAG_NUMBER:
        fields[name] = r.f64();
        break;
      case TAG_BOOLEAN:
        fields[name] = r.bool();
        break;
      case TAG_STRING:
        fields[name] = r.string();
        break;
      case TAG_NULL:
        fields[name] = null;
        break;
      case TAG_F64:
        fields[name] = r.f64s(r.count('an array length', limit, 8));
        break;
      case TAG_I32:
        fields[name] = r.i32s(r.count('an array length', limit, 4));
        break;
      case TAG_U32:
        fields[name] = r.u32s(r.count('an array length', limit, 4));
        break;
      case TAG_U8:
        fields[name] = r.u8s(r.count('an array length', limit, 1));
        break;
      default:
        r.fail(`a shape field has the unknown tag ${tag}`);
    }
  }
  let built: Shape;
  try {
    if (parts !== null) fields.parts = parts;
    built = rebuild(D, fields, r);
    delete fields.parts;
  } catch (error) {
    if (error instanceof Error && error.message.startsWith('restoreWorld')) throw error;
    return r.fail(`the saved ${kind} shape cannot be rebuilt (${(error as Error).message})`);
  }
  // The rebuilt shape, its data fields replaced by the saved ones.
  const out: Record<string, unknown> = { ...(built as unknown as Fields) };
  for (const name of Object.keys(out)) {
    if (!isCode(name, out[name]) && !hasOwn(fields, name)) r.fail(`a ${kind} shape lacks its field '${name}'`);
  }
  for (const name of Object.keys(fields)) {
    if (!hasOwn(out, name) || isCode(name, out[name])) r.fail(`a ${kind} shape has the unknown field '${name}'`);
    out[name] = fields[name] === null && (built as unknown as Fields)[name] === undefined ? undefined : fields[name];
  }
  if (covariance !== null) {
    const mp = built.massProperties(D, 1);
    let same = mp.volume === volume || (Number.isNaN(mp.volume) && Number.isNaN(volume));
    for (let i = 0; i < D.n; i += 1) if (!Object.is(mp.covariance[i], covariance[i])) same = false;
    if (!same) {
      const shapeN = built.n;
      const v = volume;
      const unit = covariance;
      out.massProperties = (Dm: Dims, mass: number): MassProperties =>
        diagonalMassProperties(checkMassArguments(`${kind}.massProperties`, Dm, mass, shapeN), v, unit, mass);
    }
  }
  return Object.freeze(out) as unknown as Shape;
}
