/**
 * Friction and restitution on three.js materials, as the specification and Physijs put them.
 *
 * @module
 */
import type { Material } from 'three';
import { finite } from './checks.js';

/** What `material._physiN` holds. */
export interface PhysinMaterialValues {
  /** Friction coefficient (>= 0); missing: the engine's default. */
  friction?: number;
  /** Restitution, in [0, 1]; missing: the engine's default. */
  restitution?: number;
}

/**
 * Puts `{ friction, restitution }` on `material._physiN` (read by the meshes at `scene.add`) and
 * returns the material, as Physijs's `createMaterial`.
 */
export function createMaterial<M extends Material>(
  material: M,
  friction?: number,
  restitution?: number,
): M & {
  /** The values the meshes read at `scene.add`. */
  _physiN: PhysinMaterialValues;
} {
  const where = 'createMaterial';
  if (material === null || typeof material !== 'object' || (material as { isMaterial?: boolean }).isMaterial !== true) {
    throw new TypeError(`${where}: argument 'material' must be a THREE.Material`);
  }
  const values: PhysinMaterialValues = {};
  if (friction !== undefined) values.friction = finite(where, 'friction', friction, 0, 'friction coefficient');
  if (restitution !== undefined) {
    values.restitution = finite(where, 'restitution', restitution, 0, 'restitution coefficient');
    if (restitution > 1) throw new RangeError(`${where}: argument 'restitution' must be in [0, 1], got ${restitution}`);
  }
  const out = material as M & { _physiN: PhysinMaterialValues };
  out._physiN = values;
  return out;
}
