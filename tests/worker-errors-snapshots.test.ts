/**
 * @physin/worker: bad input throws in the caller's thread and changes nothing; errors in the
 * world's thread come back with their class; snapshots move a world without a jump; a dead worker
 * is reported and restarts.
 */
import { afterEach, describe, expect, it } from 'vitest';
import { NonFiniteStateError } from '@physin/engine';
import { COMMAND_NAMES, openWorld } from '@physin/worker';
import type { ThreadKind, WorldHost } from '@physin/worker';
import { build4D, reportBytes, script4D } from './support/worker-scenes.js';

const hosts: WorldHost[] = [];
async function open(dimensions: number, thread: ThreadKind): Promise<WorldHost> {
  const host = await openWorld({ dimensions, gravity: [0, -9.81, ...new Array<number>(dimensions - 2).fill(0)] }, { thread });
  hosts.push(host);
  return host;
}
afterEach(() => {
  for (const h of hosts.splice(0)) h.dispose();
});

/** Each bad call, with the error class it must throw. */
const badCalls: [string, (h: WorldHost, s: ReturnType<typeof build4D>) => unknown, ErrorConstructor][] = [
  ['a box of 3 half extents in 4D', (h) => h.addBody({ shape: { kind: 'box', halfExtents: [1, 1, 1] }, mass: 1 }), TypeError],
  ['a NaN radius', (h) => h.addBody({ shape: { kind: 'sphere', radius: NaN }, mass: 1 }), RangeError],
  ['an unknown shape kind', (h) => h.addBody({ shape: { kind: 'cone' } as never, mass: 1 }), RangeError],
  ['an unknown body property', (h) => h.addBody({ shape: { kind: 'sphere', radius: 1 }, colour: 'red' } as never), RangeError],
  ['a position with NaN', (h) => h.addBody({ shape: { kind: 'sphere', radius: 1 }, position: [0, NaN, 0, 0] }), RangeError],
  [
    'a joint on an unknown body',
    (h) => h.addJoint({ kind: 'point', a: 999, b: null, localA: [0, 0, 0, 0], localB: [0, 0, 0, 0] }),
    RangeError,
  ],
  [
    'a non-simple hinge plane',
    (h, s) =>
      h.addJoint({
        kind: 'hinge',
        a: s.boxes[0]!,
        b: s.boxes[1]!,
        localA: [0, 0, 0, 0],
        localB: [0, 0, 0, 0],
        options: { plane: [1, 0, 0, 0, 0, 1] },
      }),
    RangeError,
  ],
  ['an unknown command', (h) => h.execute('fly' as never, {} as never), RangeError],
  ['an impulse of the wrong length', (h, s) => h.execute('applyCentralImpulse', { id: s.boxes[0]!, impulse: [1, 2] }), TypeError],
  ['a velocity with NaN', (h, s) => h.execute('setLinearVelocity', { id: s.boxes[0]!, velocity: [0, NaN, 0, 0] }), RangeError],
  ['a command on an unknown id', (h) => h.execute('wake', { id: 12345 }), RangeError],
  ['a torque of n numbers', (h, s) => h.execute('applyTorque', { id: s.boxes[0]!, torque: [1, 2, 3, 4] }), TypeError],
  ['limits on a point joint', (h, s) => h.execute('setLimits', { joint: s.soft, lower: -1, upper: 1 }), RangeError],
  ['a negative mass', (h, s) => h.execute('setMass', { id: s.boxes[0]!, value: -1 }), RangeError],
  ['an unknown parameter', (h) => h.execute('setParams', { params: { iterationz: 3 } as never }), RangeError],
  ['removing an unknown body', (h) => h.removeBody(77), RangeError],
];

describe('bad input throws in the caller, and nothing is sent', () => {
  for (const thread of ['main', 'worker'] as const) {
    it(`${thread}: every bad call throws its class and the next reports equal a run without it`, async () => {
      const clean = await open(4, thread);
      const sc = build4D(clean);
      const dirty = await open(4, thread);
      const sd = build4D(dirty);
      for (let f = 0; f < 40; f += 1) {
        script4D(clean, f, sc);
        script4D(dirty, f, sd);
        if (f === 10) {
          for (const [what, call, kind] of badCalls) {
            let thrown: unknown = null;
            try {
              call(dirty, sd);
            } catch (e) {
              thrown = e;
            }
            expect(thrown, what).toBeInstanceOf(kind);
            expect((thrown as Error).message.length, what).toBeGreaterThan(10);
          }
        }
        const a = reportBytes((await clean.step(1 / 60))!);
        const b = reportBytes((await dirty.step(1 / 60))!);
        expect(b).toBe(a);
      }
    });
  }

  it('an unknown command names the known ones', async () => {
    const host = await open(3, 'worker');
    expect(() => host.execute('fly' as never, {} as never)).toThrow(new RegExp(`known: ${COMMAND_NAMES.slice(0, 3).join(', ')}`));
  });

  it('a failure in the worker rejects the step with the same class, name and message; the world stays usable', async () => {
    const messages: string[] = [];
    for (const thread of ['main', 'worker'] as const) {
      const host = await open(3, thread);
      const id = host.addBody({ shape: { kind: 'sphere', radius: 0.5 }, mass: 1 });
      // a force of 1e308 is refused in this thread (Body.limits); the largest acceleration
      // (1e12 m/s² on the 1 kg ball) is accepted, but over one fixed step of 1e297 s it overflows v
      expect(() => host.execute('applyCentralForce', { id, force: [1e308, 0, 0] })).toThrow(RangeError);
      host.execute('applyCentralForce', { id, force: [1e12, 0, 0] });
      host.execute('setParams', { params: { fixedTimeStep: 1e297 } });
      const error = await host.step(1e297, 1)!.then(
        () => null,
        (e: unknown) => e,
      );
      expect(error).toBeInstanceOf(NonFiniteStateError);
      expect((error as Error).name).toBe('NonFiniteStateError');
      messages.push((error as Error).message);
    }
    // The engine's message, but for the body's process-wide number, which differs between threads.
    const mask = (m: string): string => m.replace(/body \d+/, 'body #');
    expect(messages).toHaveLength(2);
    expect(mask(messages[1]!)).toBe(mask(messages[0]!));
    expect(messages[0]).toMatch(/^World\.step: body \d+ got a non-finite v in sub-step 1 of 1/);
  });
});

describe('snapshots', () => {
  it('moving a world from the main thread to a worker mid-run gives the same reports as never moving it', async () => {
    const still = await open(4, 'main');
    const s1 = build4D(still);
    const moved = await open(4, 'main');
    const s2 = build4D(moved);
    for (let f = 0; f < 300; f += 1) {
      if (f === 120) await moved.moveTo('worker');
      if (f === 220) await moved.moveTo('main');
      script4D(still, f, s1);
      script4D(moved, f, s2);
      if (f === 120) expect(moved.thread).toBe('worker');
      const a = reportBytes((await still.step(1 / 50, 3))!);
      const b = reportBytes((await moved.step(1 / 50, 3))!);
      expect(b, `frame ${f}`).toBe(a);
    }
  });

  it('a worker that dies is reported, its step rejects, and restart() resumes from the last snapshot', async () => {
    const host = await open(3, 'worker');
    host.addBody({ shape: { kind: 'halfspace', normal: [0, 1, 0], offset: 0 }, mass: 0 });
    const ball = host.addBody({ shape: { kind: 'sphere', radius: 0.5 }, mass: 1, position: [0, 5, 0] });
    for (let i = 0; i < 20; i += 1) await host.step(1 / 60);
    const bytes = await host.snapshot();
    expect(bytes).toBeInstanceOf(Uint8Array);
    const at = (await host.step(0))!;
    const y = at.bodies[at.stride + 2]!;
    const died: unknown[] = [];
    host.addEventListener('died', (e) => died.push(e.type));
    const pending = host.step(1 / 60)!;
    (host as unknown as { terminateWorker(): void }).terminateWorker();
    // Termination is asynchronous: the step in flight either finished first (a whole report) or
    // rejects; which one depends on the machine's load, not on the host.
    const outcome = await pending.then(
      (report) => report.steps,
      (error: unknown) => error,
    );
    if (typeof outcome === 'number') expect(outcome).toBe(1);
    else expect(outcome).toBeInstanceOf(Error);
    for (let i = 0; i < 100 && died.length === 0; i += 1) await new Promise((r) => setTimeout(r, 10));
    expect(died).toEqual(['died']);
    // Once dead, a step rejects at once, before anything is sent.
    await expect(host.step(1 / 60)!).rejects.toThrow(/the worker died; call restart\(\)/);
    await host.restart();
    const r = (await host.step(0))!;
    expect(r.bodies[r.stride]).toBe(ball);
    expect(r.bodies[r.stride + 2]).toBe(y);
    expect((await host.step(1 / 60))!.steps).toBe(1);
  });
});
