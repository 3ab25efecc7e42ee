/**
 * Compound bodies through the worker host and the three.js adapter (the built dist).
 *
 * - Host: a `{ kind: 'compound', parts }` description builds one body; collision records carry
 *   the parts that touched (6 + 3n numbers a record, partA and partB last); a bad part is refused
 *   by `addBody` naming it.
 * - Adapter, as in Physijs: child PhysiN meshes added to a mesh before the mesh is added to the
 *   scene become parts of its body at their local position and quaternion. A dumbbell (a bar
 *   with a ball child at each end) falls on the ground and rests on its balls (the bar's centre
 *   at the balls' radius, 0.5, within 1e-3), children move with it, and the parent's collision
 *   events name the child mesh that touched (`part`), in both threads, with the same numbers.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { BoxMesh, PlaneMesh, Scene, SphereMesh } from '@physin/three';
import type { CollisionEvent, Mesh } from '@physin/three';
import { createWorld } from '@physin/worker';
import { run } from './support/three-frames.js';

const material = new THREE.MeshStandardMaterial({ color: 0x44aa88 });

describe('the worker host builds compounds and reports the parts that touch', () => {
  for (const n of [3, 4]) {
    it(`n = ${n}: two balls on a bar land on a half-space; each landing names its ball`, async () => {
      const up = new Array<number>(n).fill(0);
      up[1] = 1;
      const g = up.map((x) => -9.81 * x);
      const host = createWorld({ dimensions: n, gravity: g }, { thread: 'main' });
      await host.ready;
      const ground = host.addBody({ shape: { kind: 'halfspace', normal: up, offset: 0 } });
      const at = (x: number, y: number): number[] => {
        const p = new Array<number>(n).fill(0);
        p[0] = x;
        p[1] = y;
        return p;
      };
      // the right ball lower: it lands first
      const body = host.addBody({
        shape: {
          kind: 'compound',
          parts: [
            { shape: { kind: 'box', halfExtents: [1, ...new Array<number>(n - 1).fill(0.1)] } },
            { shape: { kind: 'sphere', radius: 0.5 }, position: at(-1, 0.2) },
            { shape: { kind: 'sphere', radius: 0.5 }, position: at(1, 0) },
          ],
        },
        mass: 2,
        position: at(0, 1.5),
      });
      const landings: number[][] = [];
      for (let s = 0; s < 90; s += 1) {
        const r = await host.step(1 / 60)!;
        expect(r.collisionStride).toBe(6 + 3 * n);
        for (let c = 0; c < r.collisionCount; c += 1) {
          const rec = r.collisions.subarray(c * r.collisionStride, (c + 1) * r.collisionStride);
          if (rec[0] !== 0) continue;
          // A is the lower proxy id: the ground, added first
          expect(rec[1]).toBe(ground);
          expect(rec[2]).toBe(body);
          landings.push([s, rec[4 + 3 * n]!, rec[5 + 3 * n]!]);
        }
      }
      expect(landings.length).toBe(2);
      expect(landings[0]!.slice(1)).toEqual([0, 2]); // the right ball (part 2) first
      expect(landings[1]!.slice(1)).toEqual([0, 1]);
      expect(landings[0]![0]).toBeLessThan(landings[1]![0]!);
      expect(() =>
        host.addBody({ shape: { kind: 'compound', parts: [{ shape: { kind: 'halfspace', normal: up, offset: 0 } }] }, mass: 1 }),
      ).toThrow(/'parts\[0\]\.shape'/);
      expect(() => host.addBody({ shape: { kind: 'compound', parts: 'none' as never }, mass: 1 })).toThrow(TypeError);
      host.dispose();
    });
  }
});

/** A bar (2 × 0.2 × 0.2) with a ball child (radius 0.5) at each end, at height 3, over a ground plane. */
function dumbbellScene(worker: boolean): { scene: Scene; bar: BoxMesh; left: SphereMesh; right: SphereMesh; ground: PlaneMesh } {
  const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], worker });
  const ground = new PlaneMesh(new THREE.BoxGeometry(40, 0.2, 40), material, [0, 1, 0], 0);
  scene.add(ground);
  const bar = new BoxMesh(new THREE.BoxGeometry(2, 0.2, 0.2), material, 2);
  const left = new SphereMesh(new THREE.SphereGeometry(0.5, 16, 8), material);
  const right = new SphereMesh(new THREE.SphereGeometry(0.5, 16, 8), material);
  left.position.set(-1, 0, 0);
  right.position.set(1, 0, 0);
  bar.add(left, right);
  bar.position.set(0, 3, 0);
  // turned a little about z: the right ball lands first
  bar.quaternion.setFromAxisAngle(new THREE.Vector3(0, 0, 1), -0.1);
  scene.add(bar);
  return { scene, bar, left, right, ground };
}

describe('child meshes are parts of the parent body (Physijs compounds)', () => {
  it('a dumbbell of three meshes falls as one body, rests on both balls, and its events name the ball', async () => {
    const finals: number[][] = [];
    for (const worker of [false, true]) {
      const { scene, bar, left, right, ground } = dumbbellScene(worker);
      const events: CollisionEvent[] = [];
      bar.addEventListener('collision', (e) => events.push(e as unknown as CollisionEvent));
      const groundEvents: CollisionEvent[] = [];
      ground.addEventListener('collision', (e) => groundEvents.push(e as unknown as CollisionEvent));
      await run(scene, 180);
      // one body: the children have none of their own
      expect(scene.bodyCount).toBe(2);
      expect(left._physiN.id).toBeNull();
      // at rest on both balls: the bar level at the balls' radius
      expect(Math.abs(bar.position.y - 0.5)).toBeLessThan(1e-3);
      const up = new THREE.Vector3(1, 0, 0).applyQuaternion(bar.quaternion);
      expect(Math.abs(up.y)).toBeLessThan(1e-3);
      // the children follow in the scene graph
      const wl = left.getWorldPosition(new THREE.Vector3());
      const wr = right.getWorldPosition(new THREE.Vector3());
      expect(Math.abs(wl.y - 0.5)).toBeLessThan(1e-3);
      expect(Math.abs(wr.y - 0.5)).toBeLessThan(1e-3);
      expect(wl.distanceTo(wr)).toBeCloseTo(2, 6);
      // the events on the bar name the ball that touched, right first (it may bounce once and land
      // again); the ground's name them as otherPart
      const begins = events.filter((e) => e.phase === 'begin');
      expect(begins.slice(0, 2).map((e) => e.part)).toEqual([right, left]);
      expect(begins.every((e) => e.part === left || e.part === right)).toBe(true);
      expect(events.filter((e) => e.phase === 'end').every((e) => e.part === left || e.part === right)).toBe(true);
      for (const e of begins) {
        expect(e.other).toBe(ground);
        expect(e.otherPart).toBe(ground);
        expect(e.normal[1]).toBeLessThan(-0.99);
      }
      const onGround = groundEvents.filter((e) => e.phase === 'begin');
      expect(onGround.map((e) => e.otherPart as Mesh)).toEqual(begins.map((e) => e.part));
      expect(onGround.every((e) => e.part === ground && e.other === bar)).toBe(true);
      finals.push([bar.position.x, bar.position.y, bar.position.z, bar.quaternion.z]);
      scene.dispose();
    }
    expect(finals[1]).toEqual(finals[0]);
  });
});
