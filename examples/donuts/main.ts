/**
 * The donuts page: two solid 4D tori, the orange one fixed with its circle in xy, the blue one
 * (circle in xz) moved by the user along x and w. Linking them without cutting is possible in
 * 4D: lift the blue one in w, slide it along x, and bring it back. The page says at every frame
 * whether the two solids overlap (they never need to).
 */
import * as THREE from 'three';
import GUI from 'lil-gui';
import { HyperTorusMesh, Scene, createMaterial } from '@physin/three';
import { dressScene, startDemo, wantsWorker } from '../shared/demo.js';
import { mountRuler } from '../shared/ruler.js';

const MAJOR = 1;
const MINOR = 0.22;

const scene = new Scene({ dimensions: 4, gravity: [0, 0, 0, 0], worker: wantsWorker() });
dressScene(scene);
const orange = createMaterial(new THREE.MeshStandardMaterial({ color: 0xe9a23b, side: THREE.DoubleSide }), 0.5, 0);
const blue = createMaterial(new THREE.MeshStandardMaterial({ color: 0x4d96d9, side: THREE.DoubleSide }), 0.5, 0);
// static bodies (mass 0): the user places them; the engine keeps them where they are put
const fixed = new HyperTorusMesh(MAJOR, MINOR, [0, 1], orange, 0, { dimensions: 4 });
fixed.setPositionN([0, 1.2, 0, 0]);
const moving = new HyperTorusMesh(MAJOR, MINOR, [0, 2], blue, 0, { dimensions: 4 });
const place = { x: 2.6, w: 0, sliceW: 0 };
moving.setPositionN([place.x, 1.2, 0, place.w]);
scene.add(fixed, moving);


/**
 * The least distance between the two tori's solids (negative when they overlap): the closest
 * approach of the blue circle to the orange one, less both tube radii, sampled round the circle.
 */
function gap(): number {
  let least = Infinity;
  for (let k = 0; k < 720; k += 1) {
    const t = (2 * Math.PI * k) / 720;
    // a point of the blue circle (centre (x, 1.2, 0, w), in the xz plane)
    const px = place.x + MAJOR * Math.cos(t);
    const pz = MAJOR * Math.sin(t);
    const pw = place.w;
    // its distance to the orange circle (centre (0, 1.2, 0, 0), in the xy plane; y offset 0)
    const rho = Math.hypot(px, 0);
    const d = Math.sqrt((rho - MAJOR) ** 2 + pz * pz + pw * pw);
    least = Math.min(least, d);
  }
  return least - 2 * MINOR;
}

/** True when, both at w = 0, the blue circle passes through the orange one's disc once. */
function linked(): boolean {
  return Math.abs(place.w) < 1e-9 && Math.abs(place.x) < MAJOR + MAJOR && Math.abs(Math.abs(place.x) - MAJOR) < MAJOR;
}

const status = document.getElementById('status')!;
const move = (): void => {
  place.x = Math.min(3, Math.max(-3, place.x));
  place.w = Math.min(2, Math.max(-2, place.w));
  moving.setPositionN([place.x, 1.2, 0, place.w]);
  const g = gap();
  status.innerHTML =
    `<dt>blue at</dt><dd>x ${place.x.toFixed(2)}, w ${place.w.toFixed(2)}</dd>` +
    `<dt>gap</dt><dd>${g < 0 ? '<b style="color:#ff6b6b">the tubes cut each other</b>' : `${g.toFixed(3)} m`}</dd>` +
    `<dt>linked</dt><dd>${linked() ? 'yes (in the flat w = 0)' : 'no'}</dd>`;
  gui.controllersRecursive().forEach((c) => c.updateDisplay());
};

const gui = new GUI({ container: document.getElementById('gui')!, title: 'The blue donut' });
gui.add(place, 'x', -3, 3, 0.01).onChange(move);
gui.add(place, 'w', -2, 2, 0.01).onChange(move);
const setSlice = (w: number): void => {
  place.sliceW = w;
  scene.sliceW = w;
  scene.refreshSlice();
  gui.controllersRecursive().forEach((c) => c.updateDisplay());
};
gui.add(place, 'sliceW', -1, 1, 0.01).name('sliceW (the flat)').onChange(setSlice);

/** "Link them": lift in w, slide along x to the orange ring's tube, come back to w = 0. */
let script: { to: { x: number; w: number } }[] = [];
const linkScript = (): { to: { x: number; w: number } }[] => [{ to: { x: place.x, w: 0.8 } }, { to: { x: MAJOR, w: 0.8 } }, { to: { x: MAJOR, w: 0 } }];
gui.add({ link: () => (script = linkScript()) }, 'link').name('link them');
gui.add({ reset: () => ((script = []), (place.x = 2.6), (place.w = 0), move()) }, 'reset');
/** One frame of the scripted moves; the page plays "link them" once, shortly after it opens. */
function advance(frame: number): void {
  if (frame === 30 && !played) {
    played = true;
    script = linkScript();
  }
  const next = script[0];
  if (next === undefined) return;
  const dx = next.to.x - place.x;
  const dw = next.to.w - place.w;
  const step = 0.02;
  if (Math.abs(dx) < step && Math.abs(dw) < step) {
    place.x = next.to.x;
    place.w = next.to.w;
    script.shift();
  } else {
    place.x += Math.sign(dx) * Math.min(step, Math.abs(dx));
    place.w += Math.sign(dw) * Math.min(step, Math.abs(dw));
  }
  move();
}
let played = false;

window.addEventListener('keydown', (event) => {
  const key = event.key.toLowerCase();
  if (key === 'arrowleft') place.x -= 0.05;
  else if (key === 'arrowright') place.x += 0.05;
  else if (key === 'w') place.w += 0.05;
  else if (key === 's') place.w -= 0.05;
  else return;
  script = [];
  move();
});

mountRuler(document.getElementById('ruler') as HTMLCanvasElement, scene, [fixed, moving], setSlice);
move();

const canvas = document.getElementById('view') as HTMLCanvasElement;
// the scripted moves advance once per simulated frame (not per animation frame), so a run is the
// same in either thread
startDemo(scene, { canvas, eye: [2.4, 3.6, 6.2], target: [1.2, 1.1, 0], stats: document.getElementById('stats'), beforeFrame: (frame) => advance(frame) });
