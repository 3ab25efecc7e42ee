/**
 * @physin/worker: the same world in the main thread and in a real worker (Node worker_threads,
 * the built dist), byte for byte; the accumulator; reports reused; events.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { openWorld } from '@physin/worker';
import type { StepReport, ThreadKind, WorldHost } from '@physin/worker';
import { build3D, build4D, reportBytes, script4D } from './support/worker-scenes.js';

const hosts: WorldHost[] = [];
async function open(dimensions: number, thread: ThreadKind, gravity?: number[]): Promise<WorldHost> {
  const host = await openWorld(
    { dimensions, gravity: gravity ?? [0, -9.81, ...new Array<number>(dimensions - 2).fill(0)] },
    { thread },
  );
  hosts.push(host);
  return host;
}
afterEach(() => {
  for (const h of hosts.splice(0)) h.dispose();
});

async function run4D(thread: ThreadKind, frames: number): Promise<string[]> {
  const host = await open(4, thread);
  const s = build4D(host);
  const out: string[] = [];
  for (let f = 0; f < frames; f += 1) {
    script4D(host, f, s);
    const r = (await host.step(1 / 60, 2))!;
    out.push(reportBytes(r));
  }
  return out;
}

describe('main thread and worker give the same bytes', () => {
  it('4D: hyperboxes, a hypersphere, a torus, a hinge with a motor, a soft point joint, commands — 600 frames', async () => {
    const [main, worker] = await Promise.all([run4D('main', 600), run4D('worker', 600)]);
    expect(main.length).toBe(600);
    let first = -1;
    for (let i = 0; i < 600 && first < 0; i += 1) if (main[i] !== worker[i]) first = i;
    expect(first).toBe(-1);
    // The scene moved: the last report differs from the first.
    expect(main[599]).not.toBe(main[0]);
  });

  it('3D: a stack, a thrown ball, a rope and a weld — 600 frames with varying frame deltas', async () => {
    const run = async (thread: ThreadKind): Promise<string[]> => {
      const host = await open(3, thread);
      const ids = build3D(host);
      const out: string[] = [];
      for (let f = 0; f < 600; f += 1) {
        if (f === 100) host.execute('applyImpulse', { id: ids[2]!, impulse: [2, 0, 0], offset: [0, 0.4, 0] });
        const r = (await host.step(f % 3 === 0 ? 1 / 30 : 1 / 90, 3))!;
        out.push(reportBytes(r));
      }
      return out;
    };
    const [main, worker] = await Promise.all([run('main'), run('worker')]);
    expect(main).toEqual(worker);
  });
});

describe('the report', () => {
  it('holds the specification record id | x | R | v | L for every body', async () => {
    const host = await open(4, 'main');
    host.addBody({ shape: { kind: 'halfspace', normal: [0, 1, 0, 0], offset: 0 }, mass: 0 });
    const id = host.addBody({
      shape: { kind: 'box', halfExtents: [0.5, 0.5, 0.5, 0.5] },
      mass: 2,
      position: [1, 3, 0, -1],
      velocity: [1, 0, 0, 0],
      angularVelocity: [0, 0, 0.5, 0, 0, 0],
    });
    const r = (await host.step(0))!;
    expect(r.stride).toBe(1 + 4 + 8 + 4 + 6);
    expect(r.bodyCount).toBe(2);
    const at = r.stride;
    expect(r.bodies[at]).toBe(id);
    expect(Array.from(r.bodies.subarray(at + 1, at + 5))).toEqual([1, 3, 0, -1]);
    expect(r.bodies[at + 5]).toBe(1); // identity rotor
    expect(Array.from(r.bodies.subarray(at + 13, at + 17))).toEqual([1, 0, 0, 0]);
    // L = I ω for a hypercube of mass 2, side 1: I = m (a² + b²) / 3 with a = b = 0.5 → 1/3 per plane
    expect(r.bodies[at + 17 + 2]).toBeCloseTo(((2 * (0.25 + 0.25)) / 3) * 0.5, 6);
  });

  it('accumulator: step(1/30, 2) takes two steps, step(0.2, 3) three and drops the rest, step(0) none', async () => {
    for (const thread of ['main', 'worker'] as const) {
      const host = await open(3, thread);
      host.addBody({ shape: { kind: 'sphere', radius: 0.5 }, mass: 1 });
      expect((await host.step(1 / 30, 2))!.steps).toBe(2);
      const r = (await host.step(0.2, 3))!;
      expect(r.steps).toBe(3);
      expect(r.time).toBeCloseTo(5 / 60, 12);
      expect((await host.step(0))!.steps).toBe(0);
      // The rest was dropped, not carried: 1/120 s is half a step.
      expect((await host.step(1 / 120))!.steps).toBe(0);
      expect((await host.step(1 / 120))!.steps).toBe(1);
    }
  });

  it('in steady state no report buffer is created on either side; a second step in flight is refused', async () => {
    for (const thread of ['main', 'worker'] as const) {
      const host = await open(3, thread);
      host.addBody({ shape: { kind: 'halfspace', normal: [0, 1, 0], offset: 0 }, mass: 0 });
      for (let i = 0; i < 50; i += 1)
        host.addBody({
          shape: { kind: 'box', halfExtents: [0.2, 0.2, 0.2] },
          mass: 1,
          position: [(i % 7) * 0.5, 0.3 + 0.45 * Math.floor(i / 7), 0],
        });
      let r: StepReport = (await host.step(1 / 60))!;
      for (let i = 0; i < 120; i += 1) r = (await host.step(1 / 60))!;
      const warm = r.buffersCreated;
      const buffers = new Set<ArrayBufferLike>();
      const seen: ArrayBufferLike[] = [];
      for (let i = 0; i < 300; i += 1) {
        const p = host.step(1 / 60)!;
        if (thread === 'worker') {
          expect(host.busy).toBe(true);
          expect(host.step(1 / 60)).toBeNull();
        }
        r = await p;
        buffers.add(r.bodies.buffer);
        seen.push(r.bodies.buffer);
      }
      // worker: each report's buffer went back with the step after next, moved (detached here),
      // not copied
      if (thread === 'worker') expect(seen.slice(0, -2).filter((b) => b.byteLength !== 0)).toHaveLength(0);
      expect(r.buffersCreated).toBe(warm);
      expect(warm).toBeLessThanOrEqual(thread === 'main' ? 2 : 4);
      if (thread === 'main') expect(buffers.size).toBe(1);
    }
  });
});

describe('events', () => {
  it('a box dropped on the floor begins touching once; lifted, it ends once; a breaking joint reports its id', async () => {
    for (const thread of ['main', 'worker'] as const) {
      const host = await open(3, thread);
      const floor = host.addBody({ shape: { kind: 'halfspace', normal: [0, 1, 0], offset: 0 }, mass: 0 });
      const box = host.addBody({ shape: { kind: 'box', halfExtents: [0.5, 0.5, 0.5] }, mass: 1, position: [0, 1, 0] });
      const begins: number[][] = [];
      const ends: number[][] = [];
      const collect = (r: StepReport): void => {
        for (let c = 0; c < r.collisionCount; c += 1) {
          const at = c * r.collisionStride;
          (r.collisions[at] === 0 ? begins : ends).push(Array.from(r.collisions.subarray(at, at + r.collisionStride)));
        }
      };
      for (let i = 0; i < 60; i += 1) collect((await host.step(1 / 60))!);
      expect(begins.length).toBe(1);
      expect(ends.length).toBe(0);
      const b = begins[0]!;
      expect([b[1], b[2]].sort()).toEqual([floor, box].sort());
      expect(b[3]).toBeGreaterThan(0); // impulse
      expect(Math.abs(b[4 + 3 + 1]!)).toBeCloseTo(1, 5); // the normal is ±y
      expect(b[4 + 6 + 1]).toBeGreaterThan(-1e-3); // relative velocity after the solve: no closing speed left (B = box or floor)
      host.execute('setLinearVelocity', { id: box, velocity: [0, 6, 0] });
      for (let i = 0; i < 30; i += 1) collect((await host.step(1 / 60))!);
      expect(begins.length).toBe(1);
      expect(ends.length).toBe(1);
      // a joint that breaks
      const weight = host.addBody({ shape: { kind: 'sphere', radius: 0.2 }, mass: 50, position: [5, 5, 0] });
      const joint = host.addJoint({
        kind: 'point',
        a: weight,
        b: null,
        localA: [0, 0, 0],
        localB: [5, 5, 0],
        options: { breakForce: 100 },
      });
      const broken: number[] = [];
      for (let i = 0; i < 10; i += 1) {
        const r = (await host.step(1 / 60))!;
        for (let k = 0; k < r.brokenCount; k += 1) broken.push(r.broken[k]!);
      }
      expect(broken).toEqual([joint]);
      // gone on both sides: removing it again is an error in the caller's thread
      expect(() => host.removeJoint(joint)).toThrow(RangeError);
    }
  });

  it('bodies that fall asleep and wake are reported', async () => {
    const host = await open(3, 'worker');
    host.addBody({ shape: { kind: 'halfspace', normal: [0, 1, 0], offset: 0 }, mass: 0 });
    const box = host.addBody({ shape: { kind: 'box', halfExtents: [0.5, 0.5, 0.5] }, mass: 1, position: [0, 0.5, 0] });
    const slept: number[] = [];
    for (let i = 0; i < 120; i += 1) {
      const r = (await host.step(1 / 60))!;
      for (let k = 0; k < r.sleptCount; k += 1) slept.push(r.slept[k]!);
    }
    expect(slept).toEqual([box]);
    host.execute('wake', { id: box });
    const r = (await host.step(1 / 60))!;
    expect(Array.from(r.woke.subarray(0, r.wokeCount))).toEqual([box]);
  });
});
