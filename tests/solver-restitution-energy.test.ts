/**
 * Restitution never adds energy (issue 17): with restitution 1 a ball or a box dropped from 2 m
 * keeps its bounce height for 30 s; with e < 1 each apex is e² times the last; an elastic
 * head-on collision keeps the kinetic energy; a seeded heap of bodies with restitution ≤ 1 never
 * ends a step with more energy than it started with.
 *
 * Axis 1 is up; gravity −9.81 e_1; sleep off; dt = 1/60, one sub-step (the defaults).
 *
 * What "the energy" is here: semi-implicit Euler moves a body in free fall along a parabola whose
 * samples it hits exactly, but ½v² + g·y, read at the end of a step, is not its invariant (it
 * falls by g²h²/2 every step of a free flight and is made up at the bounce). The invariant of
 * the discrete flight is ½v² + g·y − ½·h·g·v_y per unit mass, and that is what the heap test
 * holds (the rotational energy is added as it is: a free rotation keeps it).
 */
import { describe, expect, it } from 'vitest';
import type { Body } from '@physin/engine';
import { seeded, uniform, randomUnitVector } from './support/random.js';
import { addBall, addBox, addGround, axis, G, kinetic, makeWorld, run } from './support/scenes.js';

const DT = 1 / 60;

const verbose = (s: string): void => {
  if (process.env.PHYSIN_VERBOSE) console.log(s);
};

/**
 * Drops a ball or a cube (radius or half-extent 0.25, restitution e; the ground has 0, so the pair
 * has e) whose lowest point starts `drop` above the ground, for `seconds`. Returns the apex of
 * every bounce: the largest height of the lowest point between a step that moves up and the
 * next step that moves down.
 */
function bounces(n: number, kind: 'ball' | 'box', e: number, drop: number, seconds: number): number[] {
  const world = makeWorld(n);
  addGround(world, { restitution: 0 });
  const r = 0.25;
  const options = { material: { restitution: e } };
  const body =
    kind === 'ball' ? addBall(world, axis(n, 1, drop + r), r, options) : addBox(world, axis(n, 1, drop + r), r, options);
  const apexes: number[] = [];
  let rising = false;
  let top = 0;
  run(world, Math.round(seconds / DT), DT, () => {
    const vy = body.v[1]!;
    const y = body.x[1]! - r;
    if (vy > 0) {
      top = rising ? Math.max(top, y) : y;
      rising = true;
    } else if (rising) {
      apexes.push(Math.max(top, y));
      rising = false;
    }
  });
  return apexes;
}

describe('restitution 1: the bounce height stays 2 m over 30 s', () => {
  // The discrete flight samples a parabola whose peak is g·h²/8 = 0.34 mm above the drop height,
  // and the apex read at the end of a step lies within g·h²/8 below that peak: every apex is in
  // [2, 2.00034] m. The bound is 5e-4 (1 mm); the issue asked for 2 %. (Before: +5 % a bounce,
  // 3.70 m by 30 s; a box landing flat tumbled.)
  for (const n of [3, 4]) {
    for (const kind of ['ball', 'box'] as const) {
      it(`n = ${n}, ${kind === 'ball' ? 'a ball' : 'a box falling flat'}: every apex within 5e-4 of 2 m, and it keeps bouncing (≥ 20 bounces in 30 s)`, () => {
        const apexes = bounces(n, kind, 1, 2, 30);
        const worst = Math.max(...apexes.map((a) => Math.abs(a / 2 - 1)));
        const report = `${apexes.length} bounces, apex ${Math.min(...apexes).toFixed(5)}..${Math.max(...apexes).toFixed(5)} m, worst ${(100 * worst).toFixed(4)} %`;
        verbose(`restitution 1 n=${n} ${kind}: ${report}`);
        // A flight from 2 m takes 2·√(2·2/g) = 1.277 s: 23 bounces in 30 s.
        expect(apexes.length, report).toBeGreaterThanOrEqual(20);
        expect(worst, report).toBeLessThan(5e-4);
      });
    }
  }
});

describe('restitution e < 1: each apex is e² times the last, and none rises', () => {
  // Apex k (k = 1, 2, …) should be 2·e^(2k) m. Each apex is read within g·h²/8 = 0.34 mm of its
  // parabola's peak, and that peak is within the same of the ideal; bounces are compared while the
  // impact speed is above 1 m/s (twice the restitution threshold): 0.5 mm absolute (measured: 0.30 mm).
  for (const n of [3, 4]) {
    for (const e of [0.3, 0.6, 0.9]) {
      it(`n = ${n}, e = ${e}: apex k = 2·e^(2k) m within 0.5 mm while the impact is above 1 m/s; the apexes never rise`, () => {
        const apexes = bounces(n, 'ball', e, 2, 15);
        let worst = 0;
        let compared = 0;
        for (let k = 0; k < apexes.length; k += 1) {
          const want = 2 * e ** (2 * (k + 1));
          if (Math.sqrt(2 * G * want) / e < 1) break;
          worst = Math.max(worst, Math.abs(apexes[k]! - want));
          compared += 1;
        }
        const report = `${compared} bounces compared, worst ${(worst * 1000).toFixed(3)} mm; apexes ${apexes
          .slice(0, 6)
          .map((a) => a.toFixed(4))
          .join(' ')}`;
        verbose(`restitution ${e} n=${n}: ${report}`);
        expect(compared, report).toBeGreaterThanOrEqual(e === 0.3 ? 2 : 4);
        expect(worst, report).toBeLessThan(5e-4);
        for (let k = 1; k < apexes.length; k += 1) expect(apexes[k]!, report).toBeLessThanOrEqual(apexes[k - 1]!);
      });
    }
  }
});

describe('an elastic head-on collision keeps the kinetic energy', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: balls of 1 kg at +7 m/s and 2 kg at −5 m/s, e = 1, no gravity: velocities after = the elastic ones (−9, +3) within 1e-12, energy within 1e-12`, () => {
      const world = makeWorld(n, {}, 0);
      const a = addBall(world, axis(n, 0, -1), 0.25, { material: { restitution: 1 }, velocity: axis(n, 0, 7) });
      const b = addBall(world, axis(n, 0, 1), 0.25, { material: { restitution: 1 }, mass: 2, velocity: axis(n, 0, -5) });
      const k0 = kinetic([a, b]);
      run(world, 60, DT);
      const drift = Math.abs(kinetic([a, b]) / k0 - 1);
      verbose(`head-on n=${n}: v ${a.v[0]} ${b.v[0]}, energy change ${drift.toExponential(3)}`);
      expect(Math.abs(a.v[0]! + 9)).toBeLessThan(1e-12);
      expect(Math.abs(b.v[0]! - 3)).toBeLessThan(1e-12);
      expect(drift).toBeLessThan(1e-12);
    });
  }
});

describe('a heap with restitution ≤ 1 never gains energy', () => {
  // Six bodies (boxes turned at random, balls), each with a random restitution in [0, 1], friction
  // in [0, 0.8], velocity of 2 m/s in a random direction and a random spin, dropped one above the
  // other on the ground for 10 s. The discrete invariant (see the top of the file) never passes its
  // start by more than 1e-12 of it (rounding of the sum).
  for (const n of [3, 4]) {
    it(`n = ${n}: 6 seeded heaps of 6 bodies for 10 s: energy never above its start (+1e-12 relative)`, () => {
      for (let seed = 1; seed <= 6; seed += 1) {
        const rand = seeded(1000 * n + seed);
        const world = makeWorld(n);
        addGround(world, { restitution: 0 });
        const bodies: Body[] = [];
        for (let i = 0; i < 6; i += 1) {
          const position = axis(n, 1, 1 + 1.2 * i);
          position[0] = uniform(rand, -0.3, 0.3);
          const options = {
            material: { restitution: uniform(rand, 0, 1), friction: uniform(rand, 0, 0.8) },
            velocity: Array.from(randomUnitVector(rand, n), (x) => 2 * x),
            angularVelocity: Array.from({ length: (n * (n - 1)) / 2 }, () => uniform(rand, -3, 3)),
          };
          const body = i % 2 === 1 ? addBall(world, position, 0.3, options) : addBox(world, position, 0.3, options);
          if (i % 2 === 0) body.rotateInPlane(0, 1, uniform(rand, 0, 3));
          bodies.push(body);
        }
        const energy = (): number => {
          let s = kinetic(bodies);
          for (const b of bodies) s += b.mass * G * (b.x[1]! - 0.5 * DT * b.v[1]!);
          return s;
        };
        const e0 = energy();
        let worst = -Infinity;
        run(world, 600, DT, () => {
          worst = Math.max(worst, energy() - e0);
        });
        verbose(
          `heap n=${n} seed=${seed}: start ${e0.toFixed(3)} J, largest rise ${worst.toExponential(3)} J, end ${(energy() - e0).toFixed(3)} J`,
        );
        expect(worst, `seed ${seed}`).toBeLessThanOrEqual(1e-12 * e0);
      }
    });
  }
});
