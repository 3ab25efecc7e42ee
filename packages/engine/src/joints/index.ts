/**
 * The joints: point, distance, fixed, hinge and subspace, soft, motorised and breakable. See
 * docs/joints.md.
 *
 * @module
 */
export { Joint } from './joint.js';
export type { JointOptions, JointBrokenEvent, JointBrokenListener } from './joint.js';
export { PointJoint } from './point.js';
export { DistanceJoint } from './distance.js';
export type { DistanceJointOptions, DistanceMode } from './distance.js';
export { FixedJoint } from './fixed.js';
export { HingeJoint } from './hinge.js';
export type { HingeJointOptions } from './hinge.js';
export { SubspaceJoint } from './subspace.js';
export type { SubspaceJointOptions } from './subspace.js';
