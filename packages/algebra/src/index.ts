/**
 * @physin/algebra — n-dimensional geometric algebra for rigid bodies (n = 2..8): the tables of a
 * dimension, bivectors, rotors, inertia from covariance, small dense linear algebra, and the
 * argument checks shared by the PhysiN packages. See docs/nd-physics.md for the conventions.
 */
export { dims, planeIndex, bladeProductSign, popcount, isDims, MIN_DIMENSION, MAX_DIMENSION } from './dims.js';
export { dims3, dims4 } from './dims-fixed.js';
export type { Dims } from './dims.js';
export type { RotorKernels } from './kernels/types.js';
export { createGenericKernels } from './kernels/generic.js';
export {
  wedge,
  planeBivector,
  bivectorToMatrix,
  bivectorToMatrixUnchecked,
  matrixToBivector,
  bivectorCommutator,
  bivectorCommutatorUnchecked,
  bivectorApply,
  wedgeMatrix,
  bivectorDot,
  bivectorNorm,
  bivectorWedgeSelfNorm,
  pfaffian4,
  isSimple,
} from './bivector.js';
export {
  rotorIdentity,
  rotorMul,
  rotorReverse,
  rotorApplyVector,
  rotorApplyVectorInverse,
  rotorApplyBivector,
  rotorApplyBivectorInverse,
  rotorToMatrix,
  matrixToRotor,
  rotorFromPlane,
  rotateInPlane,
  rotorExp,
  rotorDefect,
  rotorCorrect,
  rotorNormalize,
  rotorNorm,
} from './rotor.js';
export {
  matrixToRotorUnchecked,
  createMatrixToRotorScratch,
  REFLECTION_THRESHOLD,
  ORTHOGONALITY_LIMIT,
} from './matrix-to-rotor.js';
export type { MatrixToRotorScratch } from './matrix-to-rotor.js';
export {
  inertiaFromCovariance,
  inertiaDiagonal,
  parallelAxisShift,
  inertiaWorldInverse,
  inertiaWorldInverseUnchecked,
} from './inertia.js';
export {
  symmetricEigen,
  symmetricEigenUnchecked,
  orthonormalize,
  orthonormalizeUnchecked,
  determinant,
  determinantUnchecked,
  matMul,
  matMulUnchecked,
} from './linalg.js';
export {
  checkArray,
  checkOut,
  checkFinite,
  checkNumber,
  checkInteger,
  checkDims,
  checkVector,
  checkBivector,
  checkRotor,
  checkMatrix,
  checkOperator,
  checkPlane,
  checkOutVector,
  checkOutBivector,
  checkOutRotor,
  checkOutMatrix,
  checkOutOperator,
} from './validate.js';
export { rotorToQuaternion, quaternionToRotor, rotorToMatrix4, axisToBivector3, bivectorToAxis3 } from './three-conventions.js';
