/**
 * @physin/three in Node with the real three.js, in the main thread and in a worker (the built
 * dist): the specification's 3D and 4D quick starts as written, the 3D conventions (quaternions,
 * axis vectors), commands before `add`, teleports, collision and broken events, add/remove
 * cycles, and bad input.
 */
import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import {
  BoxMesh,
  ConvexMesh,
  DistanceJoint,
  HingeJoint,
  HyperBoxMesh,
  HyperMesh,
  HyperTorusMesh,
  HyperPlaneMesh,
  HyperSphereMesh,
  PlaneMesh,
  PointJoint,
  Scene,
  SphereMesh,
  TorusMesh,
  createMaterial,
} from '@physin/three';
import type { CollisionEvent } from '@physin/three';
import { run } from './support/three-frames.js';

const threads = [false, true] as const;
const material = new THREE.MeshStandardMaterial({ color: 0x44aa88 });

/** Section 5 of the specification, with ES imports. */
function quickStart3D(worker: boolean): { scene: Scene; box: BoxMesh } {
  const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], worker });
  const ground = new PlaneMesh(new THREE.BoxGeometry(40, 0.2, 40), material, [0, 1, 0], 0);
  scene.add(ground);
  const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
  box.setPositionN([0, 5, 0]);
  scene.add(box);
  return { scene, box };
}

/** Section 6 of the specification, with ES imports. */
function quickStart4D(worker: boolean): { scene: Scene; cube: HyperBoxMesh } {
  const scene = new Scene({ dimensions: 4, gravity: [0, -9.81, 0, 0], worker });
  const floor = new HyperPlaneMesh([0, 1, 0, 0], 0, material, new THREE.BoxGeometry(30, 0.2, 30));
  scene.add(floor);
  const cube = new HyperBoxMesh([0.5, 0.5, 0.5, 0.5], material, 1);
  cube.setPositionN([0, 3, 0, 0]);
  cube.rotateInPlane(0, 3, 0.4);
  scene.add(cube);
  scene.sliceW = 0;
  return { scene, cube };
}

describe('the quick starts, main thread and worker', () => {
  it('3D: the box falls and rests on the ground at y = 0.5, the same in both threads', async () => {
    const ys: number[][] = [];
    for (const worker of threads) {
      const { scene, box } = quickStart3D(worker);
      await run(scene, 120);
      ys.push([box.position.x, box.position.y, box.position.z, box.quaternion.w]);
      expect(box.position.y).toBeCloseTo(0.5, 2);
      expect(Math.abs(box.position.x)).toBeLessThan(1e-4);
      scene.dispose();
    }
    expect(ys[1]).toEqual(ys[0]);
  });

  it('4D: the turned hypercube lands, its slice is visible and the same in both threads', async () => {
    const out: { position: number[]; slice: number[] }[] = [];
    for (const worker of threads) {
      const { scene, cube } = quickStart4D(worker);
      await run(scene, 120);
      const count = cube.geometry.drawRange.count;
      expect(count).toBeGreaterThan(0);
      expect(cube.visible).toBe(true);
      const positions = cube.geometry.getAttribute('position').array as Float32Array;
      out.push({ position: [...cube.getPositionN()], slice: [...positions.subarray(0, 3 * count)] });
      // a hypercube of half extent 0.5 turned in (x w) rests with its lowest y at 0: centre 0.5
      expect(cube.getPositionN()[1]).toBeCloseTo(0.5, 2);
      scene.dispose();
    }
    expect(out[1]).toEqual(out[0]);
  });
});

describe('3D conventions', () => {
  it("mesh.quaternion is three's quaternion of the body: a Vector3 angular velocity spins about that axis", async () => {
    const scene = new Scene({ dimensions: 3, gravity: [0, 0, 0] });
    const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    scene.add(box);
    box.setAngularVelocity(new THREE.Vector3(0, 1, 0));
    await run(scene, 30, 1 / 60, 1);
    const expected = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 1, 0), 0.5);
    expect(box.quaternion.angleTo(expected)).toBeLessThan(1e-5);
    // the reported angular velocity is the bivector of +y: ω_xz = −1 (e_z toward e_x)
    const w = box.getAngularVelocity();
    expect([...w].map((v) => +v.toFixed(6))).toEqual([0, -1, 0]);
    scene.dispose();
  });

  it('a mesh turned by mesh.quaternion before add starts with that turn', async () => {
    const scene = new Scene({ dimensions: 3, gravity: [0, 0, 0] });
    const box = new BoxMesh(new THREE.BoxGeometry(2, 1, 1), material, 1);
    box.quaternion.setFromAxisAngle(new THREE.Vector3(0, 0, 1), 0.7);
    box.position.set(1, 2, 3);
    const turned = box.quaternion.clone();
    scene.add(box);
    await run(scene, 1);
    expect(box.quaternion.angleTo(turned)).toBeLessThan(1e-6);
    expect(box.position.toArray()).toEqual([1, 2, 3]);
    scene.dispose();
  });

  it('2D: bodies stay in the z = 0 plane and turn about z', async () => {
    const scene = new Scene({ dimensions: 2, gravity: [0, 0] });
    const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    box.setPositionN([1, 2]);
    scene.add(box);
    box.setAngularVelocity(new THREE.Vector3(0, 0, 2));
    await run(scene, 15, 1 / 60, 1);
    const expected = new THREE.Quaternion().setFromAxisAngle(new THREE.Vector3(0, 0, 1), 0.5);
    expect(box.quaternion.angleTo(expected)).toBeLessThan(1e-5);
    expect(box.position.z).toBe(0);
    scene.dispose();
  });
});

describe('past the specification', () => {
  it('commands called before add are kept and applied at add, in order', async () => {
    const scene = new Scene({ dimensions: 3, gravity: [0, 0, 0] });
    const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 2);
    box.setLinearVelocity([1, 0, 0]);
    box.applyCentralImpulse([0, 4, 0]);
    box.setLinearVelocity([3, 0, 0]);
    box.applyCentralImpulse([0, 2, 0]);
    scene.add(box);
    await run(scene, 1, 1 / 60, 1);
    const v = box.getLinearVelocity();
    // the first velocity and impulse were overwritten; 2 N·s on 2 kg is 1 m/s
    expect(v[0]).toBeCloseTo(3, 6);
    expect(v[1]).toBeCloseTo(1, 6);
    scene.dispose();
  });

  for (const worker of threads) {
    it(`moving mesh.position after add teleports the body and keeps its velocity (worker: ${worker})`, async () => {
      const scene = new Scene({ dimensions: 3, gravity: [0, 0, 0], worker });
      const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
      scene.add(box);
      box.setLinearVelocity([0.6, 0, 0]);
      await run(scene, 10, 1 / 60, 1);
      box.position.set(5, 2, -1);
      await run(scene, 1, 1 / 60, 1);
      expect(box.position.x).toBeCloseTo(5 + 0.6 / 60, 5);
      expect(box.position.y).toBeCloseTo(2, 6);
      expect(box.getLinearVelocity()[0]).toBeCloseTo(0.6, 6);
      scene.dispose();
    });
  }
});

describe('events', () => {
  it('a ball thrown at a box fires one collision begin on both meshes, with fresh event objects', async () => {
    const scene = new Scene({ dimensions: 3, gravity: [0, 0, 0] });
    const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    const ball = new SphereMesh(new THREE.SphereGeometry(0.25), material, 0.2);
    ball.setPositionN([-3, 0, 0]);
    scene.add(box, ball);
    ball.setLinearVelocity([6, 0, 0]);
    const onBox: CollisionEvent[] = [];
    const onBall: CollisionEvent[] = [];
    box.addEventListener('collision', (e) => onBox.push(e as unknown as CollisionEvent));
    ball.addEventListener('collision', (e) => onBall.push(e as unknown as CollisionEvent));
    await run(scene, 40, 1 / 60, 1);
    const begins = (list: CollisionEvent[]): CollisionEvent[] => list.filter((e) => e.phase === 'begin');
    expect(begins(onBox)).toHaveLength(1);
    expect(begins(onBall)).toHaveLength(1);
    expect(begins(onBox)[0]!.other).toBe(ball);
    expect(begins(onBall)[0]!.other).toBe(box);
    // normals point from the mesh to the other: from the ball (left) toward the box, +x
    expect(begins(onBall)[0]!.normal[0]).toBeCloseTo(1, 3);
    expect(begins(onBox)[0]!.normal[0]).toBeCloseTo(-1, 3);
    expect(begins(onBox)[0]!.point).not.toBe(begins(onBall)[0]!.point);
    scene.dispose();
  });

  it('a joint that breaks fires broken once and leaves the scene', async () => {
    const scene = new Scene({ dimensions: 3 });
    const bob = new SphereMesh(new THREE.SphereGeometry(0.2), material, 5);
    bob.setPositionN([0, 3, 0]);
    scene.add(bob);
    const joint = scene.addConstraint(new PointJoint(bob, null, [0, 0, 0], [0, 3, 0], { breakForce: 20 }));
    let broken = 0;
    joint.addEventListener('broken', () => (broken += 1));
    await run(scene, 20);
    expect(broken).toBe(1);
    expect(scene.jointCount).toBe(0);
    expect(joint.id).toBe(null);
    expect(bob.position.y).toBeLessThan(3);
    scene.dispose();
  });
});

describe('add and remove', () => {
  it('1000 cycles of add and remove leave no body, joint or map entry behind', async () => {
    const scene = new Scene({ dimensions: 3 });
    const anchor = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 0);
    scene.add(anchor);
    for (let i = 0; i < 1000; i += 1) {
      const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
      box.setPositionN([0, 2 + (i % 5), 0]);
      scene.add(box);
      scene.addConstraint(new HingeJoint(anchor, box, [0, 1, 0], [0, -1, 0], { plane: 0 }));
      if (i % 100 === 0) await run(scene, 1);
      scene.remove(box);
    }
    expect(scene.bodyCount).toBe(1);
    expect(scene.jointCount).toBe(0);
    scene.remove(anchor);
    expect(scene.bodyCount).toBe(0);
    expect(scene.children).toHaveLength(0);
    const world = (scene.host as unknown as { core: { world: { bodies: unknown[]; jointList: unknown[] } } }).core.world;
    expect(world.bodies).toHaveLength(0);
    expect(world.jointList).toHaveLength(0);
    scene.dispose();
  });
});

describe('a Physijs scene ported with renames only', () => {
  it('a tower of 16 layers of 3 blocks at fixedTimeStep 1/120 stands for 10 s', async () => {
    const scene = new Scene({ dimensions: 3, params: { fixedTimeStep: 1 / 120 } });
    const wood = createMaterial(new THREE.MeshLambertMaterial(), 0.6, 0.1);
    scene.add(new PlaneMesh(new THREE.BoxGeometry(50, 1, 50), wood, [0, 1, 0], 0));
    const blocks: BoxMesh[] = [];
    const geometry = new THREE.BoxGeometry(3, 0.5, 1);
    for (let layer = 0; layer < 16; layer += 1) {
      for (let i = 0; i < 3; i += 1) {
        const block = new BoxMesh(geometry, wood, 1);
        block.position.y = 0.25 + layer * 0.5;
        if (layer % 2 === 0) block.position.z = (i - 1) * 1.0;
        else {
          block.position.x = (i - 1) * 1.0;
          block.rotation.y = Math.PI / 2;
        }
        blocks.push(block);
        scene.add(block);
      }
    }
    const start = blocks.map((b) => b.position.clone());
    await run(scene, 600, 1 / 60, 2);
    let worst = 0;
    blocks.forEach((b, i) => (worst = Math.max(worst, b.position.distanceTo(start[i]!))));
    expect(worst).toBeLessThan(0.02);
    scene.dispose();
  });
});

describe('bad input: a clear error, nothing changed', () => {
  it('scene and meshes refuse bad arguments before anything changes', async () => {
    const scene = new Scene({ dimensions: 3, gravity: [0, 0, 0] });
    const box = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    scene.add(box);
    expect(() => new Scene({ dimensions: 9 })).toThrow(RangeError);
    expect(() => new Scene({ gravity: [0, 1] })).toThrow(/gravity/);
    expect(() => box.setPositionN([0, Number.NaN, 0])).toThrow(RangeError);
    expect(() => box.setPositionN([0, 1])).toThrow(/3 numbers/);
    expect(() => box.setLinearVelocity('fast' as never)).toThrow(TypeError);
    expect(() => box.setAngularVelocity([1, 2])).toThrow(/3 bivector components/);
    expect(() => box.rotateInPlane(0, 0, 1)).toThrow(/two different axes/);
    expect(() => box.rotateInPlane(0, 3, 1)).toThrow(RangeError);
    expect(() => scene.simulate(-1)).toThrow(/timeStep/);
    expect(() => scene.simulate(1 / 60, 0)).toThrow(/maxSubSteps/);
    expect(() => scene.setGravity([0, Infinity, 0])).toThrow(RangeError);
    expect(() => scene.execute('explode' as never, {} as never)).toThrow(/unknown command 'explode' \(known: setGravity/);
    expect(() => scene.add(new HyperBoxMesh([1, 1, 1, 1], material, 1))).toThrow(/4 dimensions, the scene 3/);
    const loose = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    expect(() => scene.addConstraint(new PointJoint(box, loose))).toThrow(/not in this scene/);
    expect(() => new HyperSphereMesh(-1)).toThrow(/radius/);
    const stretched = new SphereMesh(new THREE.SphereGeometry(1), material, 1);
    stretched.scale.set(1, 2, 1);
    expect(() => scene.add(stretched)).toThrow(/uniform/);
    expect(scene.bodyCount).toBe(1);
    expect(scene.children).toHaveLength(1);
    await run(scene, 5, 1 / 60, 1);
    expect(box.position.toArray()).toEqual([0, 0, 0]);
    scene.dispose();
  });

  it('joints, materials and n-D meshes refuse bad arguments; a bad command kept before add fails the add and leaves nothing', async () => {
    const scene = new Scene({ dimensions: 3, gravity: [0, 0, 0] });
    const a = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    const b = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    b.setPositionN([2, 0, 0]);
    scene.add(a, b);
    const hinge = scene.addConstraint(new HingeJoint(a, b, [1, 0, 0], [-1, 0, 0], { plane: 0 }));
    expect(() => hinge.setSoftness(-1, 1)).toThrow(/hertz/);
    expect(() => hinge.setBreak(Number.NaN, 0)).toThrow(/force/);
    expect(() => hinge.setLimits(0, Infinity)).toThrow(/upper/);
    expect(() => hinge.setMotor(1, -2)).toThrow(/maxTorque/);
    expect(() => hinge.setAnchors([0, 0], null)).toThrow(/localA/);
    expect(() => new PointJoint({} as never, null)).toThrow(TypeError);
    expect(() => new DistanceJoint(a, b).setMode('spring' as never)).toThrow(/'rod', 'rope' or 'strut'/);
    expect(() => scene.addConstraint(new HingeJoint(a, b, [0, 0, 0], [0, 0, 0], { plane: 7 }))).toThrow(RangeError);
    expect(scene.jointCount).toBe(1);
    expect(() => createMaterial({} as never, 0.5)).toThrow(/THREE.Material/);
    expect(() => createMaterial(new THREE.MeshBasicMaterial(), 0.5, 2)).toThrow(/restitution/);
    expect(() => new HyperTorusMesh(1, 0.2, [0, 0])).toThrow(/two different axes/);
    expect(() => new HyperTorusMesh(1, 0.2, [0, 1], material, 1, { dimensions: 9 })).toThrow(/dimensions/);
    expect(() => new HyperMesh([[0, 0, 0, 0]], [[0, 1, 2, 3]])).toThrow(/vertices/);
    expect(() => new TorusMesh(new THREE.TorusGeometry(1, 0.2), material, 1, 1, -0.2)).toThrow(/minorRadius/);
    expect(() => new ConvexMesh(new THREE.BufferGeometry(), material, 1)).toThrow(/position/);
    const late = new BoxMesh(new THREE.BoxGeometry(1, 1, 1), material, 1);
    late.setLinearVelocity([1, 2]);
    expect(() => scene.add(late)).toThrow(/Body.setLinearVelocity: argument 'v'/);
    expect(scene.bodyCount).toBe(2);
    expect(late._physiN.id).toBe(null);
    expect(scene.children).toHaveLength(2);
    await run(scene, 3, 1 / 60, 1);
    expect(a.position.toArray()).toEqual([0, 0, 0]);
    scene.dispose();
  });
});
