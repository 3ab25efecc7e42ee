import type {
  CollisionBox,
  CollisionHalfSpace,
  CollisionSphere,
} from '../../packages/engine/src/collision/narrowphase-shapes.js';

/** A narrowphase sphere of the given radius. */
export const sphere = (radius: number): CollisionSphere => ({ kind: 'sphere', radius });

/** A narrowphase box with the given half-extents (copied). */
export const box = (half: ArrayLike<number>): CollisionBox => ({ kind: 'box', halfExtents: Float64Array.from(half) });

/** A narrowphase half-space {x : normal·x <= offset} (normal copied as given). */
export const plane = (normal: ArrayLike<number>, offset: number): CollisionHalfSpace => ({
  kind: 'halfspace',
  normal: Float64Array.from(normal),
  offset,
});
