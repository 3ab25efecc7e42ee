/**
 * Slicing in the scene (@physin/three, built dist, real three.js): moving the flat re-cuts exactly
 * the bodies it should; n = 5 cuts by the 3-flat of `scene.slice`; a hypersphere takes its n from
 * setPositionN or from the scene and shows a ball of radius √(r² − d²); a body the flat misses is
 * hidden; buffers are allocated once.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { HyperBoxMesh, HyperSphereMesh, HyperTorusMesh, Scene } from '@physin/three';
import type { HyperShapeMesh } from '@physin/three';
import { run } from './support/three-frames.js';

const material = new THREE.MeshBasicMaterial();

function version(mesh: HyperShapeMesh): number {
  return (mesh.geometry.getAttribute('position') as THREE.BufferAttribute).version;
}

describe('moving the flat', () => {
  it('refreshSlice after moving sliceW re-cuts exactly the bodies the old or the new flat meets', async () => {
    const scene = new Scene({ dimensions: 4, gravity: [0, 0, 0, 0] });
    const boxes = [-3, 0, 3, 6].map((w, i) => {
      const box = new HyperBoxMesh([0.5, 0.5, 0.5, 0.5], material, 1);
      box.setPositionN([2 * i, 0, 0, w]);
      scene.add(box);
      return box;
    });
    await run(scene, 1);
    expect(boxes.map((b) => b.visible)).toEqual([false, true, false, false]);
    const before = boxes.map(version);
    const array = boxes[1]!.geometry.getAttribute('position').array;
    scene.sliceW = 3.2;
    scene.refreshSlice();
    expect(boxes.map((b) => b.visible)).toEqual([false, false, true, false]);
    // the box at w = 0 was hidden and the one at w = 3 cut; the others were left alone
    expect(boxes.map((b, i) => version(b) !== before[i])).toEqual([false, true, true, false]);
    // the same buffers, written in place
    expect(boxes[1]!.geometry.getAttribute('position').array).toBe(array);
    // a box of half extent 0.5 cut 0.2 from its centre along w, unturned: a unit cube
    const box = boxes[2]!;
    box.geometry.computeBoundingBox();
    const size = box.geometry.boundingBox!.getSize(new THREE.Vector3());
    expect(size.x).toBeCloseTo(1, 6);
    expect(size.y).toBeCloseTo(1, 6);
    expect(size.z).toBeCloseTo(1, 6);
    expect(box.geometry.drawRange.count).toBe(36);
    scene.dispose();
  });

  it('sliceW set between frames re-cuts at the next report', async () => {
    const scene = new Scene({ dimensions: 4, gravity: [0, 0, 0, 0] });
    const ball = new HyperSphereMesh(1, material, 1);
    ball.setPositionN([0, 0, 0, 0]);
    scene.add(ball);
    await run(scene, 1);
    expect(ball.scale.x).toBeCloseTo(1, 12);
    scene.sliceW = 0.6;
    await run(scene, 1);
    expect(ball.scale.x).toBeCloseTo(0.8, 12);
    scene.sliceW = 1.5;
    await run(scene, 1);
    expect(ball.visible).toBe(false);
    scene.dispose();
  });
});

describe('n = 5: the flat of scene.slice', () => {
  it('a hyperbox away from the flat in the fifth coordinate is hidden until slice[1] reaches it', async () => {
    const scene = new Scene({ dimensions: 5, gravity: [0, 0, 0, 0, 0] });
    const box = new HyperBoxMesh([0.5, 0.4, 0.3, 0.5, 0.5], material, 1);
    box.setPositionN([0, 0, 0, 0, 1.2]);
    scene.add(box);
    await run(scene, 1);
    expect(box.visible).toBe(false);
    scene.slice[1] = 1.0;
    scene.refreshSlice();
    expect(box.visible).toBe(true);
    box.geometry.computeBoundingBox();
    const size = box.geometry.boundingBox!.getSize(new THREE.Vector3());
    expect([size.x, size.y, size.z].map((v) => +v.toFixed(6))).toEqual([1, 0.8, 0.6]);
    expect(() => scene.add(new HyperBoxMesh([1, 1, 1, 1], material, 1))).toThrow(/4 dimensions, the scene 5/);
    scene.dispose();
  });

  it('a 5D torus whose major plane is in xyz is cut by the exact formula', async () => {
    const scene = new Scene({ dimensions: 5, gravity: [0, 0, 0, 0, 0] });
    const torus = new HyperTorusMesh(1, 0.4, [0, 2], material, 1, { dimensions: 5 });
    torus.setPositionN([0, 0, 0, 0.1, -0.2]);
    scene.add(torus);
    await run(scene, 1);
    const tube = Math.sqrt(0.4 * 0.4 - 0.1 * 0.1 - 0.2 * 0.2);
    const p = torus.geometry.getAttribute('position');
    let worst = 0;
    for (let i = 0; i < torus.geometry.drawRange.count; i += 1) {
      // the circle lies in x z: distance from it
      const rho = Math.hypot(p.getX(i), p.getZ(i));
      worst = Math.max(worst, Math.abs(Math.hypot(rho - 1, p.getY(i)) - tube));
    }
    expect(torus.geometry.drawRange.count).toBeGreaterThan(1000);
    expect(worst).toBeLessThan(1e-6);
    scene.dispose();
  });
});

describe('a hypersphere takes its n late', () => {
  it('from the first setPositionN, or from the scene at add', () => {
    const a = new HyperSphereMesh(0.5, material, 1);
    expect(a.dimensions).toBe(null);
    a.setPositionN([0, 1, 0, 0, 0, 0]);
    expect(a.dimensions).toBe(6);
    const scene4 = new Scene({ dimensions: 4 });
    expect(() => scene4.add(a)).toThrow(/6 dimensions, the scene 4/);
    const b = new HyperSphereMesh(0.5, material, 1);
    scene4.add(b);
    expect(b.dimensions).toBe(4);
    expect(b.getPositionN()).toEqual(new Float64Array(4));
    scene4.dispose();
  });
});
