/**
 * `presets` (packages/engine/src/presets.ts): each preset keeps, on each scene of the trade sweep
 * (examples/trade/trade-core.mjs, the code bench/trade.bench.mjs and the trade page run), its
 * worst error over the run within the bound docs/trade.md states for it. The errors are
 * deterministic (same inputs, same bits), so the bounds are the measured errors × 1.5, rounded
 * up, and at least 1e-12 (round-off).
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { World, defaultParams, presets } from '@physin/engine';
import { PRESETS, Run, SCENES, knobsOf } from '../examples/trade/trade-core.mjs';
import type { PresetName, SceneName } from '../examples/trade/trade-core.mjs';

/** The seconds each scene runs (as in the bench). */
const SECONDS = 10;

/** The bounds of docs/trade.md (m for the boxes and joints, rad for the spinning body). */
const BOUNDS: Record<SceneName, Record<PresetName, number>> = {
  'stack of 9': { fast: 0.0064, balanced: 0.0018, accurate: 1.8e-5 },
  pyramid: { fast: 9.7e-4, balanced: 6.0e-5, accurate: 1.2e-6 },
  'chain of 10': { fast: 5.8e-7, balanced: 3.7e-6, accurate: 1e-12 },
  'chain 1000:1': { fast: 7.1e-6, balanced: 5.4e-11, accurate: 1e-12 },
  '4D stack of 6': { fast: 3.7e-3, balanced: 4.8e-4, accurate: 7.0e-6 },
  'spinning body': { fast: 0.013, balanced: 3.3e-3, accurate: 5.0e-5 },
};

describe('presets', () => {
  it('are frozen, balanced is the defaults, and the page and bench run the same knobs', () => {
    expect(Object.isFrozen(presets)).toBe(true);
    for (const p of Object.values(presets)) expect(Object.isFrozen(p)).toBe(true);
    expect(Object.keys(presets)).toEqual(['fast', 'balanced', 'accurate']);
    expect(presets.balanced).toEqual({});
    for (const name of ['fast', 'balanced', 'accurate'] as const) {
      expect(knobsOf(presets[name])).toEqual(PRESETS[name]);
      const world = new World({ dimensions: 3, params: { ...presets[name] } });
      expect(world.params).toEqual({ ...defaultParams, ...presets[name] });
    }
    expect(PRESETS.fast).toEqual({ iterations: 4, subSteps: 1, rate: 30 });
    expect(PRESETS.accurate).toEqual({ iterations: 10, subSteps: 4, rate: 120 });
  });

  it('docs/trade.md states the bounds this test holds', () => {
    const doc = readFileSync(new URL('../docs/trade.md', import.meta.url), 'utf8');
    for (const [scene, bounds] of Object.entries(BOUNDS)) {
      for (const [preset, bound] of Object.entries(bounds)) {
        const row = doc
          .split('\n')
          .map((line) => line.split('|').map((cell) => cell.trim()))
          .find((cells) => cells[1] === scene && cells[2] === preset);
        expect(row, `${scene} ${preset}`).toBeDefined();
        expect(Number.parseFloat(row![4]!), `${scene} ${preset}`).toBe(bound);
      }
    }
  });

  for (const scene of Object.keys(BOUNDS) as SceneName[]) {
    it(`hold their error bounds on ${scene} for ${SECONDS} s, accurate the best`, () => {
      expect(SCENES[scene]).toBeTypeOf('function');
      const worst: Partial<Record<PresetName, number>> = {};
      for (const preset of ['fast', 'balanced', 'accurate'] as const) {
        const run = new Run(scene, PRESETS[preset], SECONDS);
        run.advance(Infinity);
        expect(run.failure, `${scene} ${preset}`).toBeNull();
        expect(run.steps).toBe(SECONDS * PRESETS[preset].rate);
        expect(run.worst, `${scene} ${preset}`).toBeLessThanOrEqual(BOUNDS[scene][preset]);
        worst[preset] = run.worst;
      }
      // Not balanced ≤ fast everywhere: over 10 s the whipping chain's worst gap is 2.4e-6 m at the
      // defaults and 3.9e-7 m at fast (docs/trade.md).
      expect(worst.accurate).toBeLessThanOrEqual(Math.min(worst.balanced!, worst.fast!));
    });
  }
});
