/**
 * The plugin page: the specification's five steps with ES imports. A stack of boxes, a ball that
 * hits it, an octahedron from its geometry's triangles.
 */
import * as THREE from 'three';
import { BoxMesh, ConvexMesh, PlaneMesh, Scene, SphereMesh, createMaterial } from '@physin/three';
import { dressScene, linkSwitches, startDemo, wantsWorker } from '../shared/demo.js';

const stone = createMaterial(new THREE.MeshStandardMaterial({ color: 0x9aa4ae }), 0.8, 0.1);
const teal = createMaterial(new THREE.MeshStandardMaterial({ color: 0x2a9d8f }), 0.6, 0.1);
const amber = createMaterial(new THREE.MeshStandardMaterial({ color: 0xe9a23b }), 0.4, 0.3);
const plum = createMaterial(new THREE.MeshStandardMaterial({ color: 0x8e5aa8, flatShading: true }), 0.6, 0.2);

function build(): { scene: Scene; ball: SphereMesh } {
  const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], worker: wantsWorker() });
  dressScene(scene);
  scene.add(new PlaneMesh(new THREE.BoxGeometry(40, 0.2, 40).translate(0, -0.1, 0), stone, [0, 1, 0], 0));
  const cube = new THREE.BoxGeometry(1, 1, 1);
  for (let layer = 0; layer < 6; layer += 1) {
    for (let i = 0; i < 3 - (layer % 2); i += 1) {
      const box = new BoxMesh(cube, teal, 1);
      box.setPositionN([i * 1.02 - 1.02 + (layer % 2) * 0.51, 0.5 + layer * 1.0, 0]);
      scene.add(box);
    }
  }
  const octahedron = new ConvexMesh(new THREE.OctahedronGeometry(0.8), plum, 2);
  octahedron.setPositionN([3, 4, 1]);
  octahedron.setAngularVelocity(new THREE.Vector3(0.5, 2, 0));
  scene.add(octahedron);
  const ball = new SphereMesh(new THREE.SphereGeometry(0.45, 32, 16), amber, 3);
  scene.add(ball);
  throwBall(ball);
  return { scene, ball };
}

/** Puts the ball back on the left and throws it at the stack (a teleport, then a velocity). */
function throwBall(ball: SphereMesh): void {
  ball.setPositionN([-9, 2.5, 0]);
  ball.setLinearVelocity([12, 3, 0]);
  ball.setAngularVelocity([0, 0, 0]);
}

const { scene, ball } = build();
const canvas = document.getElementById('view') as HTMLCanvasElement;
startDemo(scene, { canvas, eye: [6, 5, 12], target: [0, 2, 0], stats: document.getElementById('stats') });
document.getElementById('again')!.addEventListener('click', () => throwBall(ball));
linkSwitches();
