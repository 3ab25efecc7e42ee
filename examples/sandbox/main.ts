/**
 * The sandbox page: bodies that fall in 3D or (`?d=4`) in 4D. In 4D each mesh is the body's cut
 * with the flat w = sliceW, and a ruler shows the w interval each body covers; dragging it moves
 * the flat. Buttons drop more bodies of each shape. The starting bodies are placed by a seeded
 * generator, so every load (and the worker, `?worker=1`) starts alike.
 */
import * as THREE from 'three';
import GUI from 'lil-gui';
import {
  BoxMesh,
  HyperBoxMesh,
  HyperPlaneMesh,
  HyperSphereMesh,
  HyperTorusMesh,
  PlaneMesh,
  Scene,
  SphereMesh,
  TorusMesh,
  createMaterial,
} from '@physin/three';
import type { Mesh } from '@physin/three';
import { dressScene, linkSwitches, seeded, startDemo, wantsWorker } from '../shared/demo.js';
import { mountRuler } from '../shared/ruler.js';

const params = new URLSearchParams(window.location.search);
const n = params.get('d') === '4' ? 4 : 3;
const COLORS = [0x2a9d8f, 0xe9a23b, 0x8e5aa8, 0xe76f51, 0x4d96d9, 0x8ab17d, 0xd1495b, 0x00a6a6];

let rand = seeded(2026);
let colour = 0;
function material(): THREE.Material {
  const m = new THREE.MeshStandardMaterial({
    color: COLORS[colour++ % COLORS.length],
    flatShading: n === 4,
    side: THREE.DoubleSide,
  });
  return createMaterial(m, 0.6, 0.2);
}

const scene = new Scene({ dimensions: n, gravity: n === 4 ? [0, -9.81, 0, 0] : [0, -9.81, 0], worker: wantsWorker() });
dressScene(scene);
const floor = createMaterial(new THREE.MeshStandardMaterial({ color: 0x9aa4ae }), 0.7, 0.1);
const ground = new THREE.BoxGeometry(30, 0.2, 30).translate(0, -0.1, 0);
scene.add(n === 4 ? new HyperPlaneMesh([0, 1, 0, 0], 0, floor, ground) : new PlaneMesh(ground, floor, [0, 1, 0], 0));

/** Where a dropped body starts: above the floor, spread in x, z (and w in 4D). */
function spot(height: number): number[] {
  const p = [(rand() - 0.5) * 6, height, (rand() - 0.5) * 6];
  if (n === 4) p.push((rand() - 0.5) * 2.4);
  return p;
}

type Kind = 'box' | 'ball' | 'torus';
/** At most this many bodies (the floor aside). */
const MAX_BODIES = 22;
const bodies: Mesh[] = [];
function drop(kind: Kind, height = 4 + rand() * 4): Mesh {
  let mesh: Mesh;
  if (n === 4) {
    if (kind === 'box') {
      mesh = new HyperBoxMesh([0.45, 0.35, 0.4, 0.5], material(), 1);
      mesh.setPositionN(spot(height));
      // turned out of xyz: the flat cuts it into a polyhedron that changes as the flat moves
      mesh.rotateInPlane(0, 3, 0.4 + rand() * 0.8);
      mesh.rotateInPlane(2, 3, rand() * 0.9);
      mesh.rotateInPlane(1, 2, rand() * 0.8);
    } else if (kind === 'ball') {
      mesh = new HyperSphereMesh(0.5, material(), 1);
      mesh.setPositionN(spot(height));
    } else {
      mesh = new HyperTorusMesh(0.7, 0.25, [0, 2], material(), 1, { dimensions: 4 });
      const at = spot(height);
      at[3] = at[3]! * 0.1; // near the flat, so the page opens with a donut in view
      mesh.setPositionN(at);
    }
  } else if (kind === 'box') {
    mesh = new BoxMesh(new THREE.BoxGeometry(0.9, 0.7, 0.8), material(), 1);
    mesh.setPositionN(spot(height));
    mesh.rotateInPlane(0, 1, rand() * 1.2);
  } else if (kind === 'ball') {
    mesh = new SphereMesh(new THREE.SphereGeometry(0.5, 32, 16), material(), 1);
    mesh.setPositionN(spot(height));
  } else {
    // three's TorusGeometry lies in the xy plane: its body's circle is in axes [0, 1]
    mesh = new TorusMesh(new THREE.TorusGeometry(0.7, 0.25, 16, 48), material(), 1, 0.7, 0.25, [0, 1]);
    mesh.setPositionN(spot(height));
    mesh.rotateInPlane(1, 2, Math.PI / 2);
  }
  scene.add(mesh);
  bodies.push(mesh);
  // a modest count keeps the page quick (SwiftShader draws it too): the oldest body leaves
  while (bodies.length > MAX_BODIES) scene.remove(bodies.shift()!);
  return mesh;
}

/** The starting bodies: six boxes, four balls, two tori (the same at every start). */
function populate(): void {
  rand = seeded(2026);
  colour = 0;
  for (let i = 0; i < 6; i += 1) drop('box', 1 + i * 1.2);
  for (let i = 0; i < 4; i += 1) drop('ball', 2 + i * 1.5);
  drop('torus', 3);
  drop('torus', 6);
}
populate();

const canvas = document.getElementById('view') as HTMLCanvasElement;
const demo = startDemo(scene, { canvas, eye: [4.5, 3.6, 6.5], target: [0, 0.6, 0], stats: document.getElementById('stats') });

// --- controls ---------------------------------------------------------------------------------
const gui = new GUI({ container: document.getElementById('gui')!, title: n === 4 ? 'Sandbox, 4D' : 'Sandbox, 3D' });
const actions = {
  box: () => void drop('box'),
  ball: () => void drop('ball'),
  torus: () => void drop('torus'),
  reset: () => {
    scene.remove(...bodies);
    bodies.length = 0;
    populate();
  },
  paused: false,
  sliceW: 0,
};
gui.add(actions, 'box').name(n === 4 ? 'drop a hyperbox' : 'drop a box');
gui.add(actions, 'ball').name(n === 4 ? 'drop a hypersphere' : 'drop a ball');
gui.add(actions, 'torus').name(n === 4 ? 'drop a 4D torus' : 'drop a torus');
gui.add(actions, 'reset').name('start again');
gui
  .add(actions, 'paused')
  .name('pause')
  .onChange((value: boolean) => (demo.paused = value));

linkSwitches({ n, to3: 'Switch to 3D', to4: 'Switch to 4D' });

// --- the ruler (4D) ---------------------------------------------------------------------------
if (n === 4) {
  document.getElementById('explain-4')!.hidden = false;
  const slider = gui
    .add(actions, 'sliceW', -2.5, 2.5, 0.01)
    .decimals(2)
    .name('sliceW')
    .onChange((w: number) => setSlice(w));
  const setSlice = (w: number): void => {
    scene.sliceW = w;
    scene.refreshSlice();
    actions.sliceW = w;
    slider.updateDisplay();
  };
  mountRuler(document.getElementById('ruler') as HTMLCanvasElement, scene, bodies, setSlice);
} else {
  document.getElementById('explain-3')!.hidden = false;
}
