/**
 * Joints: the specification's chain of 10 links and the 1000:1 mass ratio.
 *
 * The chain (tests/support/joints.ts `buildChain`): 10 links of 1 kg, 1 m apart (balls of radius
 * 0.1 with their anchors at ±0.5 along the chain), point joints end to start, the
 * first link joined to the world at the origin; gravity −9.81 e_1, dt = 1/60, 600 steps (10 s),
 * sleep off. The error of a joint is the distance between its two anchors' world positions,
 * measured from the bodies' poses after every step; a cell is the worst over every joint and step.
 *
 * The specification's table (section 8, "The joints"): worst error over 10 s,
 *                                       iterations 10   iterations 100   4 sub-steps
 *   starts horizontal (whips)               0.114           0.115           0.014
 *   starts hanging (settles)                0.0014          0.00003         0.00009
 * Each of ours must be no worse (≤ the specification's figure). "4 sub-steps" is subSteps 4 with the default
 * 10 iterations. The test prints ours beside the specification's. A small joint error must not be bought with
 * energy: the total energy (kinetic + m g y) may never rise more than 0.01 J above its start (a
 * solver may lose energy — it is printed — but not put it in).
 *
 * The mass ratio: the same chain with a last link of 1000 kg, dt = 1/120, subSteps 8, starting
 * horizontal: the specification measured 0.45 (below is required); the goal is 0.05 (printed).
 */
import { afterAll, describe, expect, it } from 'vitest';
import { buildChain, runChain } from './support/joints.js';

const STEPS = 600;
const DT = 1 / 60;

const CONFIGS = [
  { label: 'iterations 10', params: { iterations: 10 } },
  { label: 'iterations 100', params: { iterations: 100 } },
  { label: '4 sub-steps', params: { subSteps: 4 } },
] as const;
const CLAIMED: Record<'horizontal' | 'hanging', readonly number[]> = {
  horizontal: [0.114, 0.115, 0.014],
  hanging: [0.0014, 0.00003, 0.00009],
};

const table: string[] = [];

describe("the specification's chain of 10 links (1 kg, 1 m apart, first link to the world), worst joint error over 10 s ≤ the specification's figure", () => {
  for (const start of ['horizontal', 'hanging'] as const) {
    CONFIGS.forEach((config, c) => {
      const claimed = CLAIMED[start][c]!;
      it(`starts ${start}, ${config.label}: worst joint error ≤ ${claimed} (the specification's), and the total energy never rises above its start by more than 0.01 J`, () => {
        const chain = buildChain({ hanging: start === 'hanging', params: config.params });
        const { worst, energyRise, energyChange } = runChain(chain, STEPS, DT);
        const line = `chain of 10, starts ${start}, ${config.label}: ours ${worst.toExponential(3)}, the specification ${claimed} (${worst <= claimed ? 'no worse' : 'WORSE'}); energy: largest rise ${energyRise.toExponential(2)} J, change over 10 s ${energyChange.toFixed(2)} J`;
        console.log(line);
        table.push(line);
        expect(worst, line).toBeLessThanOrEqual(claimed);
        expect(energyRise, line).toBeLessThanOrEqual(0.01);
      });
    });
  }

  afterAll(() => {
    if (table.length > 0)
      console.log(`\nchain of 10, worst joint error over 10 s (ours vs the specification's):\n${table.join('\n')}`);
  });
});

describe('a mass ratio of 1000:1 in the chain (last link 1000 kg), dt 1/120, subSteps 8', () => {
  it("starts horizontal: worst joint error over 10 s < 0.45 (the specification's; the goal 0.05 is printed)", () => {
    const chain = buildChain({ hanging: false, lastMass: 1000, params: { subSteps: 8 } });
    const { worst, energyRise, energyChange } = runChain(chain, 1200, 1 / 120);
    const line = `1000:1 chain, horizontal, 1/120, subSteps 8: ours ${worst.toExponential(3)}, the specification 0.45, goal 0.05 (${worst < 0.05 ? 'goal met' : 'goal NOT met'}); energy: largest rise ${energyRise.toExponential(2)} J, change ${energyChange.toFixed(1)} J`;
    console.log(line);
    expect(worst, line).toBeLessThan(0.45);
  });

  it('starts hanging: worst joint error over 10 s < 0.45 (printed against the goal 0.05)', () => {
    const chain = buildChain({ hanging: true, lastMass: 1000, params: { subSteps: 8 } });
    const { worst } = runChain(chain, 1200, 1 / 120);
    const line = `1000:1 chain, hanging, 1/120, subSteps 8: ours ${worst.toExponential(3)}, the specification 0.45, goal 0.05 (${worst < 0.05 ? 'goal met' : 'goal NOT met'})`;
    console.log(line);
    expect(worst, line).toBeLessThan(0.45);
  });
});
