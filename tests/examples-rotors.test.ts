// The pure logic of the examples site's rotors page (examples/rotors): stepping, correction,
// diagnostics, the tesseract and its projection from 4D, URL settings and the plot's history.
import { dims, rotorApplyVector } from '@physin/algebra';
import { describe, expect, it } from 'vitest';
import {
  hypercubeEdges,
  hypercubeVertices,
  perspectiveScale,
  projectFromW,
  transformPoints,
  writeSegments,
} from '../examples/rotors/geometry.js';
import { LOG_FLOOR, LogHistory } from '../examples/rotors/history.js';
import { DEFAULT_SETTINGS, parseSettings, settingsToQuery } from '../examples/rotors/settings.js';
import { RotorDemo, orthonormalityError, predictedEulerDefect } from '../examples/rotors/sim.js';
import { seeded, uniform } from './support/random.js';

const REALISTIC = { step: 1 / 60, rateA: 1.5, rateB: 2.5, integrator: 'euler' as const };

describe('rotors page: uncorrected first-order update', () => {
  it('lets the 4D defect grow past 1e-6 at once and exactly as the closed form predicts', () => {
    const demo = new RotorDemo({ ...REALISTIC, correct: false });
    expect(demo.defect4).toBe(0);
    let firstAbove = -1;
    let previous = 0;
    for (let s = 1; s <= 600; s += 1) {
      demo.step();
      if (firstAbove < 0 && demo.defect4 > 1e-6) firstAbove = s;
      // The drift is systematic: it never shrinks.
      expect(demo.defect4).toBeGreaterThan(previous);
      previous = demo.defect4;
      // Closed form c_N = tanh(N atanh(β/α)), relative 1e-9.
      const c = predictedEulerDefect(demo.omega4, REALISTIC.step, s);
      expect(Math.abs(demo.defect4 - c)).toBeLessThanOrEqual(1e-9 * c);
      // |R| stays 1 (to 1e-15): the norm gives no warning at all.
      expect(Math.abs(demo.norm4 - 1)).toBeLessThan(1e-15);
      // The frame is √(1 − c²) times a rotation, so MᵀM − I = −c² on the diagonal (abs 1e-12).
      expect(Math.abs(demo.orthoError4 - c * c)).toBeLessThan(1e-12);
      expect(Math.abs(demo.frameScale4 - Math.sqrt(1 - c * c))).toBeLessThan(1e-12);
    }
    expect(firstAbove).toBe(1);
    // Ten seconds at 60 Hz: c ≈ N h² Pf / 2 = 600 · 3.75 / 7200 ≈ 0.31 (tanh of it: 0.30).
    expect(demo.defect4).toBeGreaterThan(0.29);
    expect(demo.defect4).toBeLessThan(0.31);
    expect(demo.corrections).toBe(0);
  });

  it('keeps the 3D cube a rotation: normalising is enough in 3D (defect < 1e-14 over 3000 steps)', () => {
    const demo = new RotorDemo({ ...REALISTIC, step: 0.05, correct: false });
    let worst = 0;
    for (let s = 0; s < 3000; s += 1) {
      demo.step();
      worst = Math.max(worst, demo.defect3, demo.orthoError3);
    }
    expect(worst).toBeLessThan(1e-14);
    expect(demo.defect4).toBeGreaterThan(0.99);
  });

  it('collapses the frame at a coarse step, and turning the correction on recovers a rotation', () => {
    const demo = new RotorDemo({ step: 0.2, rateA: 6, rateB: 6, correct: false });
    demo.run(400);
    expect(demo.defect4).toBeGreaterThan(1 - 1e-9);
    expect(demo.frameScale4).toBeLessThan(1e-3);
    demo.configure({ correct: true });
    demo.step();
    // Either rotorCorrect rebuilt it or the page restarted at the identity: a rotation either way.
    expect(demo.defect4).toBeLessThan(1e-12);
    expect(demo.orthoError4).toBeLessThan(1e-12);
    for (const x of demo.rotor4) expect(Number.isFinite(x)).toBe(true);
  });
});

describe('rotors page: corrected update', () => {
  it('keeps the 4D defect under the 1e-9 tolerance after every step', () => {
    const demo = new RotorDemo({ ...REALISTIC, correct: true, tolerance: 1e-9 });
    const perStep = (REALISTIC.step ** 2 * REALISTIC.rateA * REALISTIC.rateB) / 2;
    let worstDefect = 0;
    let worstOrtho = 0;
    for (let s = 0; s < 3000; s += 1) {
      const report = demo.step();
      // Each uncorrected update adds h²Pf/2 ≈ 5.2e-4 (relative 1e-3), which is over the tolerance.
      expect(Math.abs(report.updateDefect - perStep)).toBeLessThan(1e-3 * perStep);
      expect(report.corrected).toBe(true);
      worstDefect = Math.max(worstDefect, demo.defect4);
      worstOrtho = Math.max(worstOrtho, demo.orthoError4);
    }
    expect(worstDefect).toBeLessThanOrEqual(1e-9);
    // In fact at roundoff level.
    expect(worstDefect).toBeLessThan(1e-14);
    expect(worstOrtho).toBeLessThan(1e-13);
    expect(demo.corrections).toBe(3000);
    expect(demo.restarts).toBe(0);
  });

  it('corrects only when the defect passes a coarse tolerance, and never lets it exceed it', () => {
    const tolerance = 2e-3;
    const demo = new RotorDemo({ ...REALISTIC, correct: true, tolerance });
    let worst = 0;
    for (let s = 0; s < 600; s += 1) {
      demo.step();
      worst = Math.max(worst, demo.defect4);
    }
    expect(worst).toBeLessThanOrEqual(tolerance);
    // 5.2e-4 per step: a correction every fourth step.
    expect(demo.corrections).toBe(150);
  });

  it('turns in the right planes and the right sense (exp update: exact double rotation to 1e-12)', () => {
    for (const pair of ['xy-zw', 'xz-yw', 'xw-yz'] as const) {
      const demo = new RotorDemo({ pair, rateA: 1.3, rateB: -0.7, step: 0.01, integrator: 'exp', correct: false });
      demo.run(500);
      const t = demo.time;
      expect(Math.abs(t - 5)).toBeLessThan(1e-12);
      const [i, j, k, l] = pair === 'xy-zw' ? [0, 1, 2, 3] : pair === 'xz-yw' ? [0, 2, 1, 3] : [0, 3, 1, 2];
      const M = demo.matrix4;
      // Column i (image of e_i) = cos(a t) e_i + sin(a t) e_j: e_i turns toward e_j for a > 0.
      expect(Math.abs(M[i * 4 + i]! - Math.cos(1.3 * t))).toBeLessThan(1e-12);
      expect(Math.abs(M[j * 4 + i]! - Math.sin(1.3 * t))).toBeLessThan(1e-12);
      expect(Math.abs(M[k * 4 + k]! - Math.cos(-0.7 * t))).toBeLessThan(1e-12);
      expect(Math.abs(M[l * 4 + k]! - Math.sin(-0.7 * t))).toBeLessThan(1e-12);
      expect(demo.defect4).toBeLessThan(1e-13);
      // The cube turns by the 3D part of B: xy → a, xz → a, yz → b.
      const D3 = dims(3);
      const expected3 = pair === 'xy-zw' ? [1.3, 0, 0] : pair === 'xz-yw' ? [0, 1.3, 0] : [0, 0, -0.7];
      expect(Array.from(demo.omega3)).toEqual(expected3);
      expect(D3.k).toBe(3);
      expect(Math.abs(demo.pfaffian() - (pair === 'xz-yw' ? 0.91 : -0.91))).toBeLessThan(1e-15);
    }
  });
});

describe('rotors page: tesseract geometry and projection', () => {
  it('has 16 vertices at (±1, ±1, ±1, ±1) and 32 unit-axis edges, 4 at each vertex', () => {
    const V = hypercubeVertices(4, 1);
    const E = hypercubeEdges(4);
    expect(V.length).toBe(64);
    expect(E.length).toBe(64);
    const seen = new Set<string>();
    for (let v = 0; v < 16; v += 1) {
      const p = Array.from(V.subarray(4 * v, 4 * v + 4));
      for (const x of p) expect(Math.abs(x)).toBe(1);
      seen.add(p.join(','));
    }
    expect(seen.size).toBe(16);
    const degree = new Array<number>(16).fill(0);
    for (let e = 0; e < 32; e += 1) {
      const a = E[2 * e]!;
      const b = E[2 * e + 1]!;
      degree[a]! += 1;
      degree[b]! += 1;
      let differing = 0;
      for (let i = 0; i < 4; i += 1) if (V[4 * a + i] !== V[4 * b + i]) differing += 1;
      expect(differing).toBe(1);
    }
    expect(degree.every((d) => d === 4)).toBe(true);
    expect(hypercubeEdges(3).length / 2).toBe(12);
    expect(hypercubeVertices(3, 0.5).length / 3).toBe(8);
  });

  it('projects from w as (x, y, z) · d / (d − w): the unturned tesseract is a cube of 4/3 around one of 4/5', () => {
    const d = 4;
    const V = hypercubeVertices(4, 1);
    const out = new Float64Array(48);
    const scale = new Float64Array(16);
    projectFromW(out, scale, V, 16, d, 0.5);
    for (let v = 0; v < 16; v += 1) {
      const w = V[4 * v + 3]!;
      const s = w > 0 ? 4 / 3 : 4 / 5;
      expect(scale[v]).toBe(s);
      for (let i = 0; i < 3; i += 1) expect(out[3 * v + i]).toBe(s * V[4 * v + i]!);
    }
    // The depth is clamped: a point at the eye (w = d) is scaled by d / minDepth, not infinity.
    expect(perspectiveScale(4, 4, 0.5)).toBe(8);
    expect(perspectiveScale(10, 4, 0.5)).toBe(8);
  });

  it('transforms by the rotor matrix and projects exactly like R v R~ followed by the formula (1e-14)', () => {
    const rand = seeded(7);
    const demo = new RotorDemo({
      rateA: uniform(rand, -3, 3),
      rateB: uniform(rand, -3, 3),
      step: 0.05,
      integrator: 'exp',
      correct: true,
    });
    demo.run(37);
    const D = dims(4);
    const V = hypercubeVertices(4, 1);
    const turned = transformPoints(4, new Float64Array(64), demo.matrix4, V, 16);
    const out3 = new Float32Array(48);
    const scale = new Float32Array(16);
    projectFromW(out3, scale, turned, 16, 4, 0.5);
    const segs = writeSegments(new Float32Array(32 * 6), out3, hypercubeEdges(4));
    const v = new Float64Array(4);
    const E = hypercubeEdges(4);
    for (let p = 0; p < 16; p += 1) {
      rotorApplyVector(D, v, demo.rotor4, V.subarray(4 * p, 4 * p + 4));
      for (let i = 0; i < 4; i += 1) expect(Math.abs(turned[4 * p + i]! - v[i]!)).toBeLessThan(1e-14);
      const s = 4 / (4 - v[3]!);
      // Float32 storage: relative 1e-6.
      for (let i = 0; i < 3; i += 1)
        expect(Math.abs(out3[3 * p + i]! - s * v[i]!)).toBeLessThan(1e-6 * Math.max(1, Math.abs(s * v[i]!)));
    }
    for (let e = 0; e < 32; e += 1) {
      for (let i = 0; i < 3; i += 1) {
        expect(segs[6 * e + i]).toBe(out3[3 * E[2 * e]! + i]);
        expect(segs[6 * e + 3 + i]).toBe(out3[3 * E[2 * e + 1]! + i]);
      }
    }
    // The exp update drifts only by roundoff, well under the 1e-9 tolerance that would trigger a correction.
    expect(orthonormalityError(4, demo.matrix4)).toBeLessThan(1e-12);
  });
});

describe('rotors page: URL settings and plot history', () => {
  it('reads ?correct=0&dt=0.05, clamps out-of-range numbers and ignores garbage', () => {
    const s = parseSettings('?correct=0&dt=0.05');
    expect(s).toEqual({ ...DEFAULT_SETTINGS, correct: false, step: 0.05 });
    const t = parseSettings('dt=5&a=-100&b=abc&tol=0&pair=xw-yz&integrator=exp&steps=12.4&correct=maybe');
    expect(t.step).toBe(0.2);
    expect(t.rateA).toBe(-6);
    expect(t.rateB).toBe(DEFAULT_SETTINGS.rateB);
    expect(t.tolerance).toBe(1e-15);
    expect(t.pair).toBe('xw-yz');
    expect(t.integrator).toBe('exp');
    expect(t.warmSteps).toBe(12);
    expect(t.correct).toBe(DEFAULT_SETTINGS.correct);
    expect(parseSettings('pair=nope&integrator=rk4')).toEqual({ ...DEFAULT_SETTINGS });
    const back = parseSettings(settingsToQuery({ ...t, warmSteps: 0 }));
    expect(back).toEqual({ ...t, warmSteps: 0 });
    expect(settingsToQuery({ ...DEFAULT_SETTINGS })).toBe('');
  });

  it('keeps the last rows of log10 samples in order, with zero at the floor', () => {
    const h = new LogHistory(2, 4);
    for (let i = 1; i <= 6; i += 1) h.push(10 ** -i, i === 6 ? 0 : 1);
    expect(h.length).toBe(4);
    const first = [];
    for (let i = 0; i < 4; i += 1) first.push(h.get(i, 0));
    expect(first.map((x) => Math.round(x * 1e9) / 1e9)).toEqual([-3, -4, -5, -6]);
    expect(h.get(3, 1)).toBe(LOG_FLOOR);
    expect(h.get(2, 1)).toBe(0);
    h.clear();
    expect(h.length).toBe(0);
  });
});
