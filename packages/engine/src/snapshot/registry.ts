/**
 * Which shape factories and joint classes a snapshot can rebuild, registered by their own modules
 * when those load (one line at the end of each).
 *
 * Why a registry and not imports: the world's `snapshot` and `restore` would otherwise import
 * every shape factory and joint class, and with them every pair collider, into every bundle that
 * uses a World (a box-only 3D app grew by 20 kB gzip). Registered this way, an app carries only
 * the shapes and joints it uses, and a snapshot can only hold those. A worker that restores any
 * world references every factory and class anyway (it builds them from descriptions).
 *
 * Nothing here depends on anything: the registering modules stay free of snapshot code.
 *
 * @module
 */

const shapeFactories = new Map<string, unknown>();
const jointClasses = new Map<string, unknown>();
const jointNames = new Map<unknown, string>();

/** @internal Registers the factory of a shape kind (called once by the kind's module). */
export function registerShapeFactory(kind: string, factory: unknown): void {
  shapeFactories.set(kind, factory);
}

/** @internal The registered factory of a shape kind, or undefined. */
export function shapeFactory(kind: string): unknown {
  return shapeFactories.get(kind);
}

/** @internal Registers a joint class under a type name (called once by the class's module). */
export function registerJointClass(name: string, ctor: unknown): void {
  jointClasses.set(name, ctor);
  jointNames.set(ctor, name);
}

/** @internal The registered class of a joint type name, or undefined. */
export function jointClass(name: string): unknown {
  return jointClasses.get(name);
}

/** @internal The type name a joint's class was registered under (by its exact class), or undefined. */
export function jointTypeName(ctor: unknown): string | undefined {
  return jointNames.get(ctor);
}
