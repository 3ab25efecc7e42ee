/**
 * The solver's switches do what their names say: warm starting and shock propagation each keep a
 * 9-box stack in place (turned off, it drifts), and `maxContacts` caps the points solved per
 * sub-step (manifolds beyond the cap are not solved: their bodies fall through).
 */
import { describe, expect, it } from 'vitest';
import { Body, dims, HalfSpace, HyperBox, World } from '@physin/engine';
import type { Params } from '@physin/engine';

function stack9(params: Partial<Params>): { world: World; top: Body } {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: [0, -9.81, 0], params: { allowSleep: false, ...params } });
  world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0, material: { friction: 0.5 } }));
  let top: Body | null = null;
  for (let i = 0; i < 9; i += 1) {
    top = world.addBody(
      new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [0, 0.5 + i, 0], material: { friction: 0.5 } }),
    );
  }
  return { world, top: top! };
}

/** Largest sideways distance of the top box from its start over 10 s at 1/60. */
function topDrift(params: Partial<Params>): number {
  const { world, top } = stack9(params);
  let worst = 0;
  for (let s = 0; s < 600; s += 1) {
    world.step(1 / 60);
    worst = Math.max(worst, Math.hypot(top.x[0]!, top.x[2]!));
  }
  return worst;
}

describe('solver switches on a 3D stack of 9 unit boxes, 10 s at 1/60', () => {
  const base = topDrift({});

  it('with the defaults the top box stays within 0.01 m sideways', () => {
    expect(base).toBeLessThan(0.01);
  });

  it('useWarmStart: false — the top drifts at least 5× farther (and over 0.005 m): the impulses of the last step are what hold the stack still', () => {
    const cold = topDrift({ useWarmStart: false });
    expect(cold).toBeGreaterThan(0.005);
    expect(cold).toBeGreaterThan(5 * base);
  });

  it('useShockPropagation: false — the top drifts over 0.05 m: without the layered passes the stack leans', () => {
    const soft = topDrift({ useShockPropagation: false });
    expect(soft).toBeGreaterThan(0.05);
  });
});

describe('maxContacts caps the contact points solved per sub-step', () => {
  function twoBoxes(maxContacts: number): Body[] {
    const D = dims(3);
    const world = new World({ dimensions: 3, gravity: [0, -9.81, 0], params: { allowSleep: false, maxContacts } });
    world.addBody(new Body(D, { shape: HalfSpace(D, [0, 1, 0], 0), mass: 0 }));
    const a = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [-2, 0.5, 0] }));
    const b = world.addBody(new Body(D, { shape: HyperBox(D, [0.5, 0.5, 0.5]), mass: 1, position: [2, 0.5, 0] }));
    for (let s = 0; s < 60; s += 1) world.step(1 / 60);
    return [a, b];
  }

  it('0 (no cap): both boxes rest on the ground (y = 0.5 within penetrationSlop + 1e-3)', () => {
    for (const box of twoBoxes(0)) expect(Math.abs(box.x[1]! - 0.5)).toBeLessThan(0.006);
  });

  it('4 (one 3D face manifold): the first pair in pair order is solved and rests; the second box falls through the ground', () => {
    const [a, b] = twoBoxes(4);
    expect(Math.abs(a!.x[1]! - 0.5)).toBeLessThan(0.006);
    expect(b!.x[1]!).toBeLessThan(-1);
  });
});
