/**
 * Rotation stability: the intermediate-plane instability in 3D (identity 18) and 4D, a 4D spin
 * confined to a 3D subspace that must stay there, and the 4D double rotation that needs the rotor
 * correction (the specification's section 10).
 */
import { describe, expect, it } from 'vitest';
import { angularVelocityFromMomentum, Body, dims, HyperBox, World } from '@physin/engine';
import type { Dims } from '@physin/engine';
import { rotorToMatrix } from '@physin/algebra';

/** |ω⊥L|: the part of the world angular velocity perpendicular to L (component-wise dot product). */
function perpendicular(D: Dims, w: Float64Array, L: Float64Array): number {
  let LL = 0;
  let wL = 0;
  for (let p = 0; p < D.k; p += 1) {
    LL += L[p]! * L[p]!;
    wL += w[p]! * L[p]!;
  }
  let q = 0;
  for (let p = 0; p < D.k; p += 1) q += (w[p]! - (wL / LL) * L[p]!) ** 2;
  return Math.sqrt(q);
}

/** Spins a box at `speed` rad/s in plane `plane`, with `eps` rad/s in every other plane; returns the peak |ω⊥L|. */
function peakPerpendicular(
  n: number,
  halfExtents: number[],
  plane: number,
  speed: number,
  eps: number,
  h: number,
  seconds: number,
): number {
  const D = dims(n);
  const world = new World({ dimensions: n });
  const omega = new Float64Array(D.k).fill(eps);
  omega[plane] = speed;
  const body = world.addBody(new Body(D, { shape: HyperBox(D, halfExtents), mass: 1, angularVelocity: omega }));
  let peak = 0;
  for (let s = 0; s < Math.round(seconds / h); s += 1) {
    world.step(h);
    peak = Math.max(peak, perpendicular(D, body.w, body.L));
  }
  return peak;
}

describe('identity 18: the intermediate-plane instability (Dzhanibekov), 3D', () => {
  // Box [1, 0.6, 0.3] at 5 rad/s, 0.01 rad/s in the other planes, 20 s at 1/240.
  // Planes (xy, xz, yz); xz (rotation about y) is the intermediate one.
  it('spun in xz it flips: peak |ω⊥L| = 2.66 rad/s within 5 %', () => {
    const peak = peakPerpendicular(3, [1, 0.6, 0.3], 1, 5, 0.01, 1 / 240, 20);
    expect(Math.abs(peak - 2.66) / 2.66).toBeLessThan(0.05);
  });
  it('spun in yz or xy it stays: peak |ω⊥L| < 0.03 rad/s', () => {
    expect(peakPerpendicular(3, [1, 0.6, 0.3], 2, 5, 0.01, 1 / 240, 20)).toBeLessThan(0.03);
    expect(peakPerpendicular(3, [1, 0.6, 0.3], 0, 5, 0.01, 1 / 240, 20)).toBeLessThan(0.03);
  });
});

describe('the 4D Dzhanibekov effect', () => {
  // Box [1, 0.7, 0.45, 0.25]: plane inertias xy 0.50 > xz 0.40 > xw 0.35 > yz 0.23 > yw 0.18 > zw 0.09.
  // Spins in the largest plane (xy) and in yz stay; spins in the intermediate xw plane flip.
  const box = [1, 0.7, 0.45, 0.25];
  it('spun at 5 rad/s near the intermediate plane xw it flips: peak |ω⊥L| > 2 rad/s; near xy it stays < 0.03', () => {
    const flip = peakPerpendicular(4, box, 2, 5, 0.01, 1 / 240, 20);
    const stay = peakPerpendicular(4, box, 0, 5, 0.01, 1 / 240, 20);
    expect(flip).toBeGreaterThan(2);
    expect(stay).toBeLessThan(0.03);
  });

  it('a spin confined to the 3D subspace xyz stays there (w components of ω, L and R < 1e-9 over 20 s) and follows the 3D body (1e-7 through the flip)', () => {
    const D4 = dims(4);
    const D3 = dims(3);
    const h = 1 / 240;
    // Near the intermediate plane, so the motion inside the subspace is a full flip.
    const omega3 = [0.01, 5, 0.01]; // (xy, xz, yz)
    const world4 = new World({ dimensions: 4 });
    const body4 = world4.addBody(
      new Body(D4, {
        shape: HyperBox(D4, [1, 0.6, 0.3, 0.45]),
        mass: 1,
        angularVelocity: [omega3[0]!, omega3[1]!, 0, omega3[2]!, 0, 0],
      }),
    );
    const world3 = new World({ dimensions: 3 });
    const body3 = world3.addBody(new Body(D3, { shape: HyperBox(D3, [1, 0.6, 0.3]), mass: 1, angularVelocity: omega3 }));
    // 4D rotor components with an e3 factor: e03 (3), e13 (5), e23 (6), e0123 (7).
    const wPlanes = [2, 4, 5];
    const wBlades = [3, 5, 6, 7];
    let leak = 0;
    let differ = 0;
    let peak = 0;
    for (let s = 0; s < Math.round(20 / h); s += 1) {
      world4.step(h);
      world3.step(h);
      for (const p of wPlanes) leak = Math.max(leak, Math.abs(body4.w[p]!), Math.abs(body4.L[p]!));
      for (const a of wBlades) leak = Math.max(leak, Math.abs(body4.R[a]!));
      // 3D bivector (xy, xz, yz) = 4D planes (0, 1, 3); 3D rotor [1, e01, e02, e12] = 4D [0, 1, 2, 4].
      differ = Math.max(
        differ,
        Math.abs(body4.w[0]! - body3.w[0]!),
        Math.abs(body4.w[1]! - body3.w[1]!),
        Math.abs(body4.w[3]! - body3.w[2]!),
      );
      differ = Math.max(differ, ...[0, 1, 2, 4].map((a, i) => Math.abs(body4.R[a]! - body3.R[i]!)));
      peak = Math.max(peak, perpendicular(D3, body3.w, body3.L));
    }
    expect(peak).toBeGreaterThan(2); // it did flip inside the subspace
    expect(leak).toBeLessThan(1e-9); // measured: exactly 0
    // The 3D and 4D kernels round differently (~1e-16 per step); the flip is unstable and
    // amplifies that to a few 1e-9 by the end (measured 4.9e-9).
    expect(differ).toBeLessThan(1e-7);
  });
});

describe('plan 7: a 4D double rotation stays a rotation', () => {
  const D = dims(4);
  const box = [1, 0.6, 0.3, 0.45];
  // Two planes at once (xy at 2 rad/s, zw at 3 rad/s) plus a little of every other plane.
  const omega = [2, 0.1, 0.05, 0.1, 0.05, 3];

  function orthonormalityError(R: Float64Array): number {
    const M = rotorToMatrix(D, new Float64Array(16), R);
    let worst = 0;
    for (let a = 0; a < 4; a += 1) {
      for (let b = 0; b < 4; b += 1) {
        let d = 0;
        for (let i = 0; i < 4; i += 1) d += M[i * 4 + a]! * M[i * 4 + b]!;
        worst = Math.max(worst, Math.abs(d - (a === b ? 1 : 0)));
      }
    }
    return worst;
  }

  it('the engine: 1e5 steps of 1/60 keep defect < rotorTolerance and the matrix orthonormal to 1e-9; L bit-exact; energy within 1e-3', () => {
    const world = new World({ dimensions: 4 });
    const body = world.addBody(new Body(D, { shape: HyperBox(D, box), mass: 1, angularVelocity: omega }));
    const L0 = Float64Array.from(body.L);
    const E0 = body.kineticEnergy();
    let worstDefect = 0;
    let worstOrtho = 0;
    let worstEnergy = 0;
    for (let s = 1; s <= 100_000; s += 1) {
      world.step(1 / 60);
      worstDefect = Math.max(worstDefect, D.kernels.defect(body.R));
      worstEnergy = Math.max(worstEnergy, Math.abs(body.kineticEnergy() - E0) / E0);
      if (s % 1000 === 0) worstOrtho = Math.max(worstOrtho, orthonormalityError(body.R));
    }
    expect(worstDefect).toBeLessThan(world.params.rotorTolerance);
    expect(worstOrtho).toBeLessThan(1e-9);
    expect(worstEnergy).toBeLessThan(1e-3);
    for (let p = 0; p < D.k; p += 1) expect(body.L[p]).toBe(L0[p]);
  });

  /*
   * What goes wrong without the correction. The engine's own rotor step multiplies by an exact
   * exponential, so its defect only grows by rounding (the test above): there is nothing for the
   * correction to do in 1e5 steps. The failure the specification describes comes from an update that leaves
   * the rotation group — the first-order update R ← (1 − h B/2) R followed by a normalisation,
   * which is what an engine ported from quaternions does. For a double rotation B² has a grade-4
   * part, so each step adds about (h²/2)·Pf(B) to the I component of R R~; normalising fixes the
   * norm and not that. This test runs that update with the engine's inertia transform twice: once
   * with the engine's correction rule (rotorCorrect when the defect exceeds rotorTolerance) and
   * once without it.
   *
   * What it shows with our kernels: without the correction |R| stays 1 to rounding while the frame
   * stops being a rotation (orthonormality error ~1 by step 400) and the energy computed through
   * that frame is off by a factor of several; with the correction the frame stays orthonormal to
   * rounding and only the (first-order) integration error of the energy remains. The specification reports
   * 3.3e+143 at step 400 for its implementation; ours cannot overflow, because a sandwich with a
   * unit-norm even element is bounded, so the blow-up shows as a bounded but wrong energy.
   */
  it('without the correction a normalised first-order update leaves the group (|R| = 1, orthonormality error > 0.5, energy x2+); with it, error < 1e-12', () => {
    const body = new Body(D, { shape: HyperBox(D, box), mass: 1, angularVelocity: omega });
    const h = 1 / 60;
    const run = (correct: boolean) => {
      const R = Float64Array.from(body.R);
      const L = Float64Array.from(body.L);
      const w = Float64Array.from(body.w);
      const tmp = new Float64Array(D.k);
      const step = new Float64Array(D.r);
      const energy = () => 0.5 * L.reduce((acc, l, p) => acc + l * w[p]!, 0);
      const E0 = energy();
      const log: { norm: number; ortho: number; energy: number }[] = [];
      for (let s = 0; s <= 400; s += 1) {
        if (s % 50 === 0) log.push({ norm: Math.hypot(...R), ortho: orthonormalityError(R), energy: energy() / E0 });
        step.fill(0);
        step[0] = 1;
        for (let p = 0; p < D.k; p += 1) step[1 + p] = -0.5 * h * w[p]!;
        D.kernels.mul(R, step, R);
        const norm = Math.hypot(...R);
        for (let a = 0; a < D.r; a += 1) R[a] = R[a]! / norm;
        if (correct && D.kernels.defect(R) > 1e-9) D.kernels.correct(R, R);
        angularVelocityFromMomentum(D, w, R, body.invInertia, L, tmp);
      }
      return log;
    };
    const off = run(false);
    const on = run(true);
    for (const row of off) expect(Math.abs(row.norm - 1)).toBeLessThan(1e-12);
    expect(off[1]!.ortho).toBeGreaterThan(1e-3); // step 50: already visible (seed: 1.45e-3)
    expect(off[8]!.ortho).toBeGreaterThan(0.5); // step 400
    expect(off[8]!.energy).toBeGreaterThan(2);
    for (const row of on) expect(row.ortho).toBeLessThan(1e-12);
    expect(Math.abs(on[8]!.energy - 1)).toBeLessThan(0.01);
  });
});
