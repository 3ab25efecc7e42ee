/**
 * Reading a shape's kind and collider table in hot code without teaching V8 the shape's map.
 *
 * Why. The step hands the collision kernels shapes of several kinds. A plain `shape.kind` in
 * optimised code compiles to a check of the shape's map against the (up to four) maps its
 * inline cache saw, and TurboFan then takes those maps as known for every later property load
 * from the same shape in that function and in the functions inlined into it. A kind-specific
 * branch that reads a number field (a ball's `radius`, a half-space's `offset`) is then compiled
 * as a load over all those maps, `undefined` for the maps that lack the field, and the number
 * loaded for the right map is boxed into a fresh heap number to merge with that `undefined`:
 * one allocation per call (measured: computeBoundsUnchecked allocated 16 B per ball per step).
 *
 * The accessors below read the field through a property load whose inline cache is made
 * megamorphic when this module loads (by reading it from more object layouts than V8 keeps in a
 * polymorphic cache). A megamorphic load compiles to a generic lookup that proves no map, so the
 * kind-specific loads that follow use their own (single-map) feedback and load numbers unboxed.
 * The result is the same `shape.kind` / `shape.colliders`; only the machine code differs.
 * {@link trainShapeAccessors} runs again whenever a narrowphase scratch is made (once per world),
 * in case V8 dropped the feedback of a function unused for a long time.
 *
 * @module
 */
import type { ShapeKind } from '../shapes/shape.js';
import type { ColliderTable } from './manifold.js';

/** `shape.kind`, read by a load kept megamorphic (see the module comment). Allocates nothing. */
export function shapeKind(shape: { readonly kind: ShapeKind }): ShapeKind {
  return shape.kind;
}

/** `shape.colliders`, read by a load kept megamorphic (see the module comment). Allocates nothing. */
export function shapeColliders(shape: { readonly colliders?: ColliderTable }): ColliderTable | undefined {
  return shape.colliders;
}

/**
 * Objects of six different layouts (V8 keeps at most four maps in a polymorphic inline cache).
 * Their kinds are no real kind, so nothing else would ever match them.
 */
const TRAINING: readonly { readonly kind: ShapeKind; readonly colliders?: ColliderTable }[] = [
  { kind: 'train0' as ShapeKind },
  { t1: 0, kind: 'train1' as ShapeKind, colliders: undefined },
  { t2: 0, t3: 0, kind: 'train2' as ShapeKind, colliders: undefined },
  { colliders: undefined, kind: 'train3' as ShapeKind },
  { t4: '', colliders: undefined, kind: 'train4' as ShapeKind },
  { t5: null, t6: null, colliders: undefined, kind: 'train5' as ShapeKind },
] as never;

/**
 * Makes the loads of {@link shapeKind} and {@link shapeColliders} megamorphic by calling them on
 * objects of six layouts, enough times for V8 to have allocated their feedback (it does so
 * lazily, after a few calls). Costs a few microseconds; runs at load and per narrowphase scratch.
 */
export function trainShapeAccessors(): void {
  for (let round = 0; round < 64; round += 1) {
    for (let i = 0; i < TRAINING.length; i += 1) {
      shapeKind(TRAINING[i]!);
      shapeColliders(TRAINING[i]!);
    }
  }
}

trainShapeAccessors();
