// The app the consumer tests build with Vite and with webpack 5 from the installed tarballs (see
// tests/consumers/apps.test.ts). A ground box and four boxes that fall onto it, stepped a fixed
// number of fixed steps, in the page's thread or, with `?worker=1`, in @physin/three's own
// worker; then `globalThis.physinApp` holds what the test reads.
import * as THREE from 'three';
import { BoxMesh, Scene, createMaterial } from '@physin/three';

const STEPS = 90;
const useWorker = new URLSearchParams(location.search).get('worker') === '1';

async function run() {
  const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], params: { fixedTimeStep: 1 / 60 }, worker: useWorker });
  scene.addEventListener('error', (event) => console.error('PhysiN step failed:', event.error));
  scene.addEventListener('died', (event) => console.error('PhysiN worker died:', event.error));
  scene.background = new THREE.Color(0xeef1f5);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x8899aa, 2));

  const stone = createMaterial(new THREE.MeshStandardMaterial({ color: 0x9aa4ae }), 0.8, 0.1);
  const teal = createMaterial(new THREE.MeshStandardMaterial({ color: 0x2a9d8f }), 0.6, 0.1);
  const ground = new BoxMesh(new THREE.BoxGeometry(20, 1, 20), stone, 0);
  ground.setPositionN([0, -0.5, 0]);
  scene.add(ground);
  const cube = new THREE.BoxGeometry(1, 1, 1);
  const boxes = [];
  for (let i = 0; i < 4; i += 1) {
    const box = new BoxMesh(cube, teal, 1);
    box.setPositionN([i * 0.3 - 0.45, 2 + 1.5 * i, i * 0.2 - 0.3]);
    box.rotateInPlane(0, 1, 0.3 * i);
    scene.add(box);
    boxes.push(box);
  }
  const start = boxes.map((box) => [...box.getPositionN()]);

  const canvas = document.getElementById('view');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
  renderer.setSize(480, 320, false);
  const camera = new THREE.PerspectiveCamera(50, 480 / 320, 0.1, 100);
  camera.position.set(6, 5, 10);
  camera.lookAt(0, 1.5, 0);

  await scene.host.ready;
  for (let step = 0; step < STEPS; step += 1) {
    await new Promise((resolve, reject) => {
      const done = () => {
        scene.removeEventListener('update', done);
        resolve(undefined);
      };
      scene.addEventListener('update', done);
      if (!scene.simulate(1 / 60, 1)) reject(new Error(`simulate refused step ${step}: the scene was busy`));
    });
    renderer.render(scene, camera);
  }

  globalThis.physinApp = {
    thread: scene.host.thread,
    steps: STEPS,
    start,
    // every box's position and rotor after STEPS fixed steps, as plain numbers
    end: boxes.map((box) => [...box.getPositionN(), ...box.getRotor()]),
  };
}

run().catch((error) => {
  console.error(error);
  globalThis.physinApp = { error: String(error && error.stack ? error.stack : error) };
});
