/**
 * `CapsuleMesh` of @physin/three: its body is the engine's capsule sized from the
 * `THREE.CapsuleGeometry` (radius, and height = the straight part) times the object's scale, and
 * it rests where that capsule would, standing up and lying on its side, in both threads.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { CapsuleMesh, PlaneMesh, Scene } from '@physin/three';
import { defaultParams } from '@physin/engine';
import { run } from './support/three-frames.js';

const material = new THREE.MeshStandardMaterial({ color: 0x44aa88 });

describe('CapsuleMesh', () => {
  it('describes the capsule of its geometry times the scale', () => {
    const mesh = new CapsuleMesh(new THREE.CapsuleGeometry(0.3, 1.2, 4, 8), material, 2);
    expect(mesh.describeShape()).toEqual({ kind: 'capsule', halfHeight: 0.6, radius: 0.3 });
    mesh.scale.setScalar(2);
    expect(mesh.describeShape()).toEqual({ kind: 'capsule', halfHeight: 1.2, radius: 0.6 });
    mesh.scale.set(1, 2, 1);
    expect(() => mesh.describeShape()).toThrow(/uniform/);
  });

  it('refuses a geometry that is not a capsule, and bad parameters', () => {
    expect(() => new CapsuleMesh(new THREE.BufferGeometry(), material)).toThrow(/radius/);
    expect(() => new CapsuleMesh(new THREE.CapsuleGeometry(0.3, 0), material)).toThrow(/height/);
    expect(() => new CapsuleMesh({} as THREE.BufferGeometry, material)).toThrow(TypeError);
  });

  for (const worker of [false, true]) {
    it(`rests standing at height/2 + radius and lying at radius (${worker ? 'worker' : 'main thread'})`, async () => {
      const slop = defaultParams.penetrationSlop;
      const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], worker });
      scene.add(new PlaneMesh(new THREE.BoxGeometry(40, 0.2, 40), material, [0, 1, 0], 0));
      const standing = new CapsuleMesh(new THREE.CapsuleGeometry(0.25, 1, 4, 8), material, 1);
      standing.position.set(-2, 0.8, 0);
      scene.add(standing);
      // scaled by 2: radius 0.3, straight part 1.6; lying along x (a quarter turn about z)
      const lying = new CapsuleMesh(new THREE.CapsuleGeometry(0.15, 0.8, 4, 8), material, 1);
      lying.scale.setScalar(2);
      lying.position.set(2, 0.5, 0);
      lying.rotation.set(0, 0, Math.PI / 2);
      scene.add(lying);
      await run(scene, 180);
      expect(Math.abs(standing.position.y - (0.5 + 0.25))).toBeLessThan(slop);
      expect(Math.abs(lying.position.y - 0.3)).toBeLessThan(slop);
      expect(Math.abs(lying.position.x - 2)).toBeLessThan(1e-4);
      scene.dispose();
    });
  }
});
