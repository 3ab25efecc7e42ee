/**
 * Scripted scenes for the world host tests: the same calls, frame by frame, whatever the thread.
 */
import type { WorldHost } from '@physin/worker';

/** A 4D scene: hyperboxes, a hypersphere, a torus on a half-space, a hinge and a soft point joint. */
export function build4D(host: WorldHost): { boxes: number[]; hinge: number; soft: number } {
  host.addBody({ shape: { kind: 'halfspace', normal: [0, 1, 0, 0], offset: 0 }, mass: 0, material: { friction: 0.6 } });
  const boxes: number[] = [];
  for (let i = 0; i < 3; i += 1) {
    boxes.push(
      host.addBody({
        shape: { kind: 'box', halfExtents: [0.4, 0.3, 0.35, 0.25] },
        mass: 1 + i,
        position: [i * 0.9 - 1, 0.5 + i * 0.7, 0.1 * i, 0.05 * i],
        angularVelocity: [0.3, 0, 0.2 * i, 0, 0.1, 0],
      }),
    );
  }
  host.addBody({ shape: { kind: 'sphere', radius: 0.3 }, mass: 0.5, position: [0.2, 2.5, 0, 0.1], velocity: [0.5, 0, 0, 0] });
  host.addBody({ shape: { kind: 'torus', majorRadius: 0.6, minorRadius: 0.2, plane: [0, 2] }, mass: 2, position: [2, 1, 0, 0] });
  const arm = host.addBody({ shape: { kind: 'box', halfExtents: [0.5, 0.1, 0.1, 0.1] }, mass: 1, position: [-2, 3, 0, 0] });
  const hinge = host.addJoint({
    kind: 'hinge',
    a: boxes[0]!,
    b: arm,
    localA: [0, 0.3, 0, 0],
    localB: [-0.5, 0, 0, 0],
    options: { plane: 2 },
  });
  const bob = host.addBody({ shape: { kind: 'sphere', radius: 0.2 }, mass: 1, position: [3, 4, 0, 0.2] });
  const soft = host.addJoint({
    kind: 'point',
    a: bob,
    b: null,
    localA: [0, 0, 0, 0],
    localB: [3, 5, 0, 0],
    options: { hertz: 4, damping: 0.5 },
  });
  return { boxes, hinge, soft };
}

/** The commands of frame `f` of the 4D script. */
export function script4D(host: WorldHost, f: number, s: { boxes: number[]; hinge: number; soft: number }): void {
  if (f === 30) host.execute('applyCentralImpulse', { id: s.boxes[1]!, impulse: [0.5, 1, 0, 0.2] });
  if (f === 90) host.execute('setMotor', { joint: s.hinge, speed: 1.5, maxTorque: 20 });
  if (f === 150) host.execute('setAngularVelocity', { id: s.boxes[2]!, angularVelocity: [0, 1, 0, 0, 0, 2] });
  if (f === 200) host.execute('setSoftness', { joint: s.soft, hertz: 2, damping: 1 });
  if (f === 300) host.execute('setGravity', { gravity: [0, -9.81, 0, -0.5] });
  if (f === 400) host.execute('setMaterial', { id: s.boxes[0]!, friction: 0.2 });
  if (f % 50 === 25) host.execute('applyTorque', { id: s.boxes[0]!, torque: [0, 0, 0.3, 0, 0, 0.1] });
}

/** A 3D scene: a stack, a ball, a distance joint, a fixed joint. */
export function build3D(host: WorldHost): number[] {
  host.addBody({ shape: { kind: 'halfspace', normal: [0, 1, 0], offset: 0 }, mass: 0 });
  const ids: number[] = [];
  for (let i = 0; i < 4; i += 1)
    ids.push(host.addBody({ shape: { kind: 'box', halfExtents: [0.5, 0.5, 0.5] }, mass: 1, position: [0, 0.5 + i * 1.0, 0] }));
  ids.push(host.addBody({ shape: { kind: 'sphere', radius: 0.25 }, mass: 0.3, position: [-4, 1.5, 0], velocity: [8, 1, 0] }));
  const a = host.addBody({ shape: { kind: 'box', halfExtents: [0.2, 0.2, 0.2] }, mass: 1, position: [3, 4, 0] });
  const b = host.addBody({ shape: { kind: 'box', halfExtents: [0.2, 0.2, 0.2] }, mass: 1, position: [4, 4, 0] });
  host.addJoint({ kind: 'distance', a, b: null, localA: [0, 0, 0], localB: [3, 6, 0], options: { mode: 'rope' } });
  host.addJoint({ kind: 'fixed', a, b, localA: [0.5, 0, 0], localB: [-0.5, 0, 0] });
  ids.push(a, b);
  return ids;
}

/** The bytes of a report's body, collision and id sections, as hex. */
export function reportBytes(r: {
  bodies: Float32Array;
  collisions: Float32Array;
  broken: Int32Array;
  slept: Int32Array;
  woke: Int32Array;
}): string {
  const hex = (a: Float32Array | Int32Array): string => Buffer.from(a.buffer, a.byteOffset, a.byteLength).toString('hex');
  return `${hex(r.bodies)}|${hex(r.collisions)}|${hex(r.broken)}|${hex(r.slept)}|${hex(r.woke)}`;
}
