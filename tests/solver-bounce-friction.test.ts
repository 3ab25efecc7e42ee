/**
 * Contact solver against analytic results: restitution (identity 21), Coulomb friction on an
 * incline (identity 22) and elastic collisions of free balls (identity 25, momentum and energy).
 *
 * Axis 1 is up; gravity −9.81 e_1 where there is gravity; sleep is off; dt = 1/60. Inputs that are
 * not fixed by the identity (offsets, speeds) are seeded.
 */
import { describe, expect, it } from 'vitest';
import { defaultParams } from '@physin/engine';
import type { Body } from '@physin/engine';
import { seeded, uniform, randomUnitVector } from './support/random.js';
import { addBall, addBox, addGround, axis, dot, G, kinetic, makeWorld, momentum, run } from './support/scenes.js';

/** Largest distance of the sliding box's centre from the plane at half-extent 0.5: slop + 1e-3. */
const SLOP_PLUS = defaultParams.penetrationSlop + 1e-3;

const verbose = (s: string): void => {
  if (process.env.PHYSIN_VERBOSE) console.log(s);
};

/**
 * Drops a ball (radius 0.25, restitution e) whose lowest point starts `h` above the ground
 * (restitution 0, so the mixed restitution max(e, 0) = e). Returns the apex of the first bounce,
 * measured as centre height − radius at the end of each step between the first step that moves
 * up and the first step that moves down again (0 if it never moves up), and the largest downward
 * speed reached before that.
 */
function dropBall(n: number, h: number, e: number, subSteps: number): { apex: number; impactSpeed: number } {
  const world = makeWorld(n, { subSteps });
  addGround(world, { restitution: 0 });
  const r = 0.25;
  const ball = addBall(world, axis(n, 1, h + r), r, { material: { restitution: e } });
  let phase = 0;
  let apex = 0;
  let impactSpeed = 0;
  run(world, 300, 1 / 60, () => {
    const vy = ball.v[1]!;
    if (phase === 0) {
      impactSpeed = Math.max(impactSpeed, -vy);
      if (vy > 0) phase = 1;
    }
    if (phase === 1) {
      apex = Math.max(apex, ball.x[1]! - r);
      if (vy < 0) phase = 2;
    }
  });
  return { apex, impactSpeed };
}

describe('identity 21: a ball dropped from h with restitution e rises to e²h', () => {
  // The integrator is first order: a free flight of semi-implicit Euler from speed v rises
  // v²/2g − v·h_sub/2 + O(h²), a relative error of about g·h_sub/v_up. At 1/60 and one sub-step
  // that alone is ≈ 5 % for e = 0.5 from 2 m, so the 3 % test runs 4 sub-steps (≈ 1.3 %); the
  // default configuration is checked separately within 8 %.
  for (const n of [3, 4]) {
    for (const e of [0.5, 0.8]) {
      it(`identity 21: n = ${n}, e = ${e}, h = 2 m, 4 sub-steps: apex of the first bounce = e²h = ${(e * e * 2).toFixed(2)} m within 3 %`, () => {
        const { apex, impactSpeed } = dropBall(n, 2, e, 4);
        const want = e * e * 2;
        const report = `apex ${apex.toFixed(4)} m, want ${want.toFixed(4)} m (${(100 * (apex / want - 1)).toFixed(1)} %), largest fall speed ${impactSpeed.toFixed(3)} m/s`;
        verbose(`bounce n=${n} e=${e} sub 4: ${report}`);
        expect(Math.abs(apex / want - 1), report).toBeLessThan(0.03);
      });
    }
  }

  for (const e of [0.5, 0.8]) {
    it(`identity 21: n = 3, e = ${e}, h = 2 m, default parameters (1 sub-step): apex = e²h within 8 % (first-order integrator)`, () => {
      const { apex } = dropBall(3, 2, e, 1);
      const want = e * e * 2;
      const report = `apex ${apex.toFixed(4)} m, want ${want.toFixed(4)} m (${(100 * (apex / want - 1)).toFixed(1)} %)`;
      verbose(`bounce n=3 e=${e} sub 1: ${report}`);
      expect(Math.abs(apex / want - 1), report).toBeLessThan(0.08);
    });
  }

  it('below restitutionThreshold (drop 0.008 m: impact 0.40 m/s < 0.5 m/s, e = 0.8, 4 sub-steps) the ball does not bounce: apex after impact < 1e-3', () => {
    const h = 0.008;
    expect(Math.sqrt(2 * G * h)).toBeLessThan(0.5);
    for (const n of [3, 4]) {
      const { apex } = dropBall(n, h, 0.8, 4);
      verbose(`below threshold n=${n}: apex ${apex.toExponential(3)}`);
      expect(apex).toBeLessThan(1e-3);
    }
  });

  it('just above restitutionThreshold (drop 0.03 m: impact 0.77 m/s, e = 0.8, 4 sub-steps) the ball does bounce: apex = e²h = 0.0192 m within 15 %', () => {
    const h = 0.03;
    expect(Math.sqrt(2 * G * h)).toBeGreaterThan(0.5);
    for (const n of [3, 4]) {
      const { apex } = dropBall(n, h, 0.8, 4);
      const want = 0.64 * h;
      const report = `n = ${n}: apex ${apex.toExponential(3)} m, want ${want.toExponential(3)} m`;
      verbose(`above threshold ${report}`);
      expect(Math.abs(apex / want - 1), report).toBeLessThan(0.15);
    }
  });
});

/**
 * A unit box (half-extent 0.5, mass 1) resting flat on an incline of angle θ, both with friction μ
 * (mixed: sqrt(μ·μ) = μ). 3D: the ground's normal is (−sin θ, cos θ, 0), downhill (−cos θ, −sin θ,
 * 0). 4D: the incline tilts in the (y, w) plane: normal (0, cos θ, 0, −sin θ), downhill
 * (0, −sin θ, 0, −cos θ), so the box slides along −w. The box is turned to lie flat (its local e_1
 * onto the normal) and placed touching the plane.
 */
function incline(n: 3 | 4, theta: number, mu: number) {
  const world = makeWorld(n);
  const c = Math.cos(theta);
  const s = Math.sin(theta);
  const normal = n === 3 ? [-s, c, 0] : [0, c, 0, -s];
  const down = n === 3 ? [-c, -s, 0] : [0, -s, 0, -c];
  addGround(world, { friction: mu, restitution: 0 }, normal, 0);
  const box: Body = addBox(
    world,
    normal.map((x) => 0.5 * x),
    0.5,
    { material: { friction: mu, restitution: 0 } },
  );
  if (n === 3)
    box.rotateInPlane(0, 1, theta); // e_y → (−sin θ, cos θ, 0)
  else box.rotateInPlane(1, 3, -theta); // e_y → (0, cos θ, 0, −sin θ)
  return { world, box, normal, down };
}

describe('identity 22: box on an incline θ = 30° with friction μ', () => {
  const theta = Math.PI / 6;
  for (const n of [3, 4] as const) {
    const where = n === 3 ? '3D' : '4D, tilted in the (y, w) plane';
    it(`identity 22: ${where}: μ = 0.7 > tan θ = 0.577: the box sticks (displacement < 1e-3 over 5 s)`, () => {
      const { world, box } = incline(n, theta, 0.7);
      const x0 = Float64Array.from(box.x);
      let worst = 0;
      run(world, 300, 1 / 60, () => {
        worst = Math.max(worst, Math.hypot(...box.x.map((x, d) => x - x0[d]!)));
      });
      verbose(`incline stick n=${n}: displacement ${worst.toExponential(3)}`);
      expect(worst).toBeLessThan(1e-3);
    });

    it(`identity 22: ${where}: μ = 0.2 < tan θ: it slides with a = g(sin θ − μ cos θ) = 3.206 m/s² within 2 % (from v along the slope at t = 1 s and 3 s), flat on the plane`, () => {
      const mu = 0.2;
      const { world, box, normal, down } = incline(n, theta, mu);
      const x0 = Float64Array.from(box.x);
      let v1 = NaN;
      let v3 = NaN;
      let lift = 0;
      let spin = 0;
      run(world, 180, 1 / 60, (s) => {
        if (s === 60) v1 = dot(box.v, down);
        if (s === 180) v3 = dot(box.v, down);
        lift = Math.max(lift, Math.abs(dot(box.x, normal) - 0.5));
        spin = Math.max(spin, Math.hypot(...box.w));
      });
      const a = (v3 - v1) / 2;
      const want = G * (Math.sin(theta) - mu * Math.cos(theta));
      expect(want).toBeCloseTo(3.206, 3);
      const report = `a = ${a.toFixed(5)} m/s², want ${want.toFixed(5)}; off-plane ${lift.toExponential(2)}, |ω| ${spin.toExponential(2)}`;
      verbose(`incline slide n=${n}: ${report}`);
      expect(Math.abs(a / want - 1), report).toBeLessThan(0.02);
      expect(lift, report).toBeLessThan(SLOP_PLUS);
      expect(spin, report).toBeLessThan(1e-3);
      if (n === 4) {
        // The slide stays in the (y, w) plane: x and z do not move.
        expect(Math.abs(box.x[0]! - x0[0]!), report).toBeLessThan(1e-6);
        expect(Math.abs(box.x[2]! - x0[2]!), report).toBeLessThan(1e-6);
      }
    });
  }
});
describe('identity 25 and momentum: collisions of free balls (no gravity, restitution 1, friction 0)', () => {
  const elastic = { restitution: 1, friction: 0 };

  for (const n of [2, 3, 4, 5, 6]) {
    it(`identity 25: n = ${n}: equal balls head-on (seeded speeds): velocities swap within 1e-6 relative; momentum conserved to 1e-12 relative`, () => {
      const rand = seeded(2500 + n);
      const world = makeWorld(n, {}, 0);
      const va = uniform(rand, 1, 3);
      const vb = -uniform(rand, 0.5, 2);
      const gap = uniform(rand, 0.3, 1.5);
      const a = addBall(world, axis(n, 0, -0.5 - gap / 2), 0.5, { material: elastic, velocity: axis(n, 0, va) });
      const b = addBall(world, axis(n, 0, 0.5 + gap / 2), 0.5, { material: elastic, velocity: axis(n, 0, vb) });
      const p0 = momentum([a, b]);
      run(world, 120); // 2 s: they meet within 0.75 s
      const p1 = momentum([a, b]);
      const scale = Math.abs(va) + Math.abs(vb);
      const dp = Math.hypot(...p1.map((x, d) => x - p0[d]!)) / scale;
      const report = `before (${va.toFixed(6)}, ${vb.toFixed(6)}), after (${a.v[0]!.toFixed(6)}, ${b.v[0]!.toFixed(6)}); |Δp| / (|p_a| + |p_b|) = ${dp.toExponential(2)}`;
      verbose(`head-on n=${n}: ${report}`);
      expect(dp, report).toBeLessThan(1e-12);
      expect(Math.abs(a.v[0]! - vb) / Math.abs(vb), report).toBeLessThan(1e-6);
      expect(Math.abs(b.v[0]! - va) / Math.abs(va), report).toBeLessThan(1e-6);
      for (let d = 1; d < n; d += 1) {
        expect(Math.abs(a.v[d]!), report).toBeLessThan(1e-12);
        expect(Math.abs(b.v[d]!), report).toBeLessThan(1e-12);
      }
    });
  }

  for (const n of [3, 4]) {
    it(`n = ${n}: an off-centre collision of unequal balls (seeded impact parameter) conserves momentum to 1e-12 relative and kinetic energy within 1 %`, () => {
      const rand = seeded(2600 + n);
      const world = makeWorld(n, {}, 0);
      // Impact parameter: a seeded direction perpendicular to x, length in [0.2, 0.8) < r_a + r_b = 1.1.
      const off = randomUnitVector(rand, n);
      off[0] = 0;
      const len = Math.hypot(...off);
      const b0 = uniform(rand, 0.2, 0.8);
      const pb = axis(n, 0, 2).map((x, d) => x + (off[d]! / len) * b0);
      // A common seeded drift; the relative velocity is along x, so they must meet.
      const drift = randomUnitVector(rand, n).map((x) => 0.3 * x);
      const va = drift.map((x, d) => (d === 0 ? x + 2 : x));
      const vb = drift.map((x, d) => (d === 0 ? x - 1.5 : x));
      const a = addBall(world, axis(n, 0, -2), 0.5, { material: elastic, velocity: va, mass: 1.3 });
      const b = addBall(world, pb, 0.6, { material: elastic, velocity: vb, mass: 0.8 });
      const p0 = momentum([a, b]);
      const E0 = kinetic([a, b]);
      run(world, 120); // 2 s: they meet at about 0.8 s
      const p1 = momentum([a, b]);
      const E1 = kinetic([a, b]);
      const dp = Math.hypot(...p1.map((x, d) => x - p0[d]!)) / Math.hypot(...p0);
      const dvA = Math.hypot(...a.v.map((x, d) => x - va[d]!));
      const report = `|Δp|/|p| = ${dp.toExponential(2)}, E ${E0.toFixed(6)} → ${E1.toFixed(6)} (${(100 * (E1 / E0 - 1)).toFixed(2)} %), |Δv_a| = ${dvA.toFixed(3)}`;
      verbose(`off-centre n=${n}: ${report}`);
      expect(dvA, `they collided: ${report}`).toBeGreaterThan(0.1);
      expect(dp, report).toBeLessThan(1e-12);
      expect(Math.abs(E1 / E0 - 1), report).toBeLessThan(0.01);
    });
  }
});
