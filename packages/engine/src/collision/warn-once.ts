/**
 * One warning per pair of shape kinds the narrowphase cannot collide.
 *
 * @module
 */
import type { ShapeKind } from '../shapes/shape.js';

const KIND_COUNT = 7;
/** Which unordered kind pairs have warned (index min·KIND_COUNT + max). No allocation after load. */
const warned = new Uint8Array(KIND_COUNT * KIND_COUNT);

function kindIndex(kind: ShapeKind): number {
  switch (kind) {
    case 'halfspace':
      return 0;
    case 'sphere':
      return 1;
    case 'box':
      return 2;
    case 'torus':
      return 3;
    case 'mesh':
      return 4;
    case 'capsule':
      return 5;
    case 'compound':
      return 6;
    default:
      return -1;
  }
}

/**
 * Warns (console.warn) the first time a pair of shape kinds with no collider meets, and does
 * nothing after that for the same two kinds in either order. Returns whether it warned now.
 * The supported pairs: sphere–sphere, sphere–box, box–box, and every one of sphere, box, torus,
 * convex mesh against a half-space, mesh–sphere, and a torus against every kind (torus-colliders.ts).
 * Mesh–box and mesh–mesh pass through each other, as the specification says.
 */
export function warnOnce(kindA: ShapeKind, kindB: ShapeKind): boolean {
  const ia = kindIndex(kindA);
  const ib = kindIndex(kindB);
  const index = ia < 0 || ib < 0 ? -1 : Math.min(ia, ib) * KIND_COUNT + Math.max(ia, ib);
  if (index >= 0) {
    if (warned[index]) return false;
    warned[index] = 1;
  }
  console.warn(
    `PhysiN: no collision between a ${String(kindA)} and a ${String(kindB)}; the two pass through each other (this warning is given once)`,
  );
  return true;
}

/** Forgets which pairs have warned (for tests, or a new scene). */
export function resetCollisionWarnings(): void {
  warned.fill(0);
}
