// Rotor kernels: product and vector sandwich for n = 2..6, the table-driven generic kernels
// against the kernels dims(n) selects (closed forms for n = 3 and 4), and the 3D closed forms
// against gl-matrix's quaternions in the same run. Prints ns/op medians and ratios, then checks
// the targets: 4D product ≤ 3× the 3D quaternion product; fast paths ≥ 3× the generic ones.
//
// Run: node bench/rotors.bench.mjs   (imports the BUILT @physin/algebra: build first)

import { createGenericKernels, dims } from '@physin/algebra';
import { quat, vec3 } from 'gl-matrix';
import { medianTable, timeOp } from './lib/table.mjs';
import { randomArray, seeded } from './lib/random.mjs';

const POOL = 64; // inputs cycled through per benchmark (a power of two)
const rand = seeded(20240601);

/** POOL unit rotors, vectors, bivectors and output buffers for dimension n. */
function inputs(n) {
  const D = dims(n);
  const gen = createGenericKernels(D);
  const pool = (f) => Array.from({ length: POOL }, f);
  return {
    D,
    gen,
    rotors: pool(() => gen.exp(new Float64Array(D.r), randomArray(rand, D.k, -2, 2), 1)),
    rotors2: pool(() => gen.exp(new Float64Array(D.r), randomArray(rand, D.k, -2, 2), 1)),
    vectors: pool(() => randomArray(rand, n)),
    bivectors: pool(() => randomArray(rand, D.k)),
    outRotor: pool(() => new Float64Array(D.r)),
    outVector: pool(() => new Float64Array(n)),
    outBivector: pool(() => new Float64Array(D.k)),
    outMatrix: pool(() => new Float64Array(n * n)),
    scales: pool(() => 1 / 60),
  };
}

const byN = new Map();
for (let n = 2; n <= 6; n += 1) byN.set(n, inputs(n));

// ---- product and vector sandwich, n = 2..6 -------------------------------------------------
const productRows = [];
const applyRows = [];
const measured = {};
for (const [n, I] of byN) {
  const sel = I.D.kernels;
  const name = sel.name ?? 'generic';
  const gMul = timeOp(I.gen.mul, [I.outRotor, I.rotors, I.rotors2]).median;
  const sMul = timeOp(sel.mul, [I.outRotor, I.rotors, I.rotors2]).median;
  const gApp = timeOp(I.gen.applyVector, [I.outVector, I.rotors, I.vectors]).median;
  const sApp = timeOp(sel.applyVector, [I.outVector, I.rotors, I.vectors]).median;
  measured[n] = { gMul, sMul, gApp, sApp, name };
  productRows.push({ n, r: I.D.r, 'selected kernels': name, 'generic ns': gMul, 'selected ns': sMul, 'speed-up ×': gMul / sMul });
  applyRows.push({ n, r: I.D.r, 'selected kernels': name, 'generic ns': gApp, 'selected ns': sApp, 'speed-up ×': gApp / sApp });
}
medianTable('Rotor product a·b, ns/op (median of 25 batches)', productRows);
medianTable('Rotor applied to a vector R v R~, ns/op (median of 25 batches)', applyRows);
console.log(
  '\nFor n = 2, 5 and 6, dims(n) selects the generic kernels, so both columns time the same code\n' +
    '(a fresh createGenericKernels instance vs the one dims(n) holds): their ratio shows the noise of the run.',
);

// ---- 3D: our closed forms against gl-matrix -------------------------------------------------
const I3 = byN.get(3);
// gl-matrix layout [x, y, z, w] of the same rotations: (w, x, y, z) = (s, −e12, e02, −e01).
const toGl = (R) => Float64Array.from([-R[3], R[2], -R[1], R[0]]);
const glA = I3.rotors.map(toGl);
const glB = I3.rotors2.map(toGl);
const glOut = I3.outRotor.map(() => new Float64Array(4));
// What calling gl-matrix on OUR storage would cost: shuffle in, call, shuffle out.
const qa = new Float64Array(4);
const qb = new Float64Array(4);
const qo = new Float64Array(4);
function glMulOnOurLayout(out, a, b) {
  qa[0] = -a[3];
  qa[1] = a[2];
  qa[2] = -a[1];
  qa[3] = a[0];
  qb[0] = -b[3];
  qb[1] = b[2];
  qb[2] = -b[1];
  qb[3] = b[0];
  quat.multiply(qo, qa, qb);
  out[0] = qo[3];
  out[1] = -qo[2];
  out[2] = qo[1];
  out[3] = -qo[0];
  return out;
}
function glApplyOnOurLayout(out, R, v) {
  qa[0] = -R[3];
  qa[1] = R[2];
  qa[2] = -R[1];
  qa[3] = R[0];
  return vec3.transformQuat(out, v, qa);
}
const glMul = timeOp(quat.multiply, [glOut, glA, glB]).median;
const glMulShuffled = timeOp(glMulOnOurLayout, [I3.outRotor, I3.rotors, I3.rotors2]).median;
const glApp = timeOp(vec3.transformQuat, [I3.outVector, I3.vectors, glA]).median;
const glAppShuffled = timeOp(glApplyOnOurLayout, [I3.outVector, I3.rotors, I3.vectors]).median;
medianTable('3D closed forms vs gl-matrix 3.4.4 (Float64Array), ns/op (median)', [
  {
    operation: 'product',
    'ours (fast3)': measured[3].sMul,
    'gl-matrix, its layout': glMul,
    'gl-matrix + shuffle to ours': glMulShuffled,
    'ours / gl-matrix': measured[3].sMul / glMul,
  },
  {
    operation: 'apply to vector',
    'ours (fast3)': measured[3].sApp,
    'gl-matrix, its layout': glApp,
    'gl-matrix + shuffle to ours': glAppShuffled,
    'ours / gl-matrix': measured[3].sApp / glApp,
  },
]);

// ---- the other kernels, 3D and 4D ----------------------------------------------------------
const otherRows = [];
for (const n of [3, 4]) {
  const I = byN.get(n);
  const sel = I.D.kernels;
  const cases = [
    ['applyVectorInverse', (K) => timeOp(K.applyVectorInverse, [I.outVector, I.rotors, I.vectors])],
    ['applyBivector', (K) => timeOp(K.applyBivector, [I.outBivector, I.rotors, I.bivectors])],
    ['toMatrix', (K) => timeOp(K.toMatrix, [I.outMatrix, I.rotors])],
    ['exp', (K) => timeOp(K.exp, [I.outRotor, I.bivectors, I.scales])],
    ['defect', (K) => timeOp(K.defect, [I.rotors])],
    ['correct', (K) => timeOp(K.correct, [I.outRotor, I.rotors])],
  ];
  for (const [op, run] of cases) {
    const g = run(I.gen).median;
    const s = run(sel).median;
    otherRows.push({ n, kernel: op, 'generic ns': g, [`fast ns`]: s, 'speed-up ×': g / s });
  }
}
medianTable('Other rotor kernels, generic vs fast, ns/op (median)', otherRows);

// ---- 4D: one vector through the sandwich or through the matrix ------------------------------
{
  const I = byN.get(4);
  const K = I.D.kernels;
  const M = new Float64Array(16);
  function applyViaMatrix(out, R, v) {
    K.toMatrix(M, R);
    const v0 = v[0],
      v1 = v[1],
      v2 = v[2],
      v3 = v[3];
    for (let i = 0; i < 4; i += 1) out[i] = M[i * 4] * v0 + M[i * 4 + 1] * v1 + M[i * 4 + 2] * v2 + M[i * 4 + 3] * v3;
    return out;
  }
  const matrices = I.rotors.map((R) => K.toMatrix(new Float64Array(16), R));
  function matVec(out, Mx, v) {
    const v0 = v[0],
      v1 = v[1],
      v2 = v[2],
      v3 = v[3];
    for (let i = 0; i < 4; i += 1) out[i] = Mx[i * 4] * v0 + Mx[i * 4 + 1] * v1 + Mx[i * 4 + 2] * v2 + Mx[i * 4 + 3] * v3;
    return out;
  }
  const sandwich = measured[4].sApp;
  const viaMatrix = timeOp(applyViaMatrix, [I.outVector, I.rotors, I.vectors]).median;
  const matOnly = timeOp(matVec, [I.outVector, matrices, I.vectors]).median;
  medianTable('4D: rotating one vector, ns/op (median)', [
    { method: 'unrolled sandwich (fast4.applyVector)', ns: sandwich },
    { method: 'toMatrix, then matrix × vector', ns: viaMatrix },
    { method: 'matrix × vector, matrix already built', ns: matOnly },
  ]);
}

// ---- the floor: what the timing loop itself costs per call ---------------------------------
let floor;
{
  const I = byN.get(4);
  function copyOne(out, R, v) {
    out[0] = R[0] + v[0];
    return out;
  }
  floor = timeOp(copyOne, [I.outVector, I.rotors, I.vectors]).median;
  medianTable('Timing floor (loop, input cycling and one call doing one add), ns/op (median)', [
    { operation: 'out[0] = R[0] + v[0]', ns: floor },
  ]);
}

// ---- targets --------------------------------------------------------------------------------
const targets = [
  ['4D product ≤ 3× 3D product (ours)', measured[4].sMul / measured[3].sMul, 3, 'max'],
  ['4D product ≤ 3× gl-matrix quat.multiply', measured[4].sMul / glMul, 3, 'max'],
  ['3D product fast ≥ 3× generic', measured[3].gMul / measured[3].sMul, 3, 'min'],
  ['4D product fast ≥ 3× generic', measured[4].gMul / measured[4].sMul, 3, 'min'],
  ['3D apply fast ≥ 3× generic', measured[3].gApp / measured[3].sApp, 3, 'min'],
  ['4D apply fast ≥ 3× generic', measured[4].gApp / measured[4].sApp, 3, 'min'],
];
medianTable('Targets (ratios of medians)', [
  ...targets.map(([target, ratio, bound, kind]) => ({
    target,
    'measured ratio': ratio,
    met: (kind === 'max' ? ratio <= bound : ratio >= bound) ? 'yes' : 'NO',
  })),
  // Not a target: the same 4D/3D ratio on the arithmetic alone (each median minus the timing
  // floor above), since the floor is most of a 3D product's time. Noisy: the floor is small
  // differences of small numbers.
  {
    target: '(info) 4D / 3D product, timing floor subtracted',
    'measured ratio': (measured[4].sMul - floor) / Math.max(measured[3].sMul - floor, 1e-9),
    met: '-',
  },
]);
