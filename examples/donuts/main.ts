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

/** True when, both at w = 0, the blue circle passes once through the orange one's disc, the tubes apart. */
function linked(): boolean {
  // solids that overlap are not a chain link (one would have to be cut)
  return (
    gap() >= 0 && Math.abs(place.w) < 1e-9 && Math.abs(place.x) < MAJOR + MAJOR && Math.abs(Math.abs(place.x) - MAJOR) < MAJOR
  );
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
gui
  .add(place, 'x', -3, 3, 0.01)
  .decimals(2)
  .onChange(() => ((script = []), move()));
gui
  .add(place, 'w', -2, 2, 0.01)
  .decimals(2)
  .onChange(() => ((script = []), move()));
const setSlice = (w: number): void => {
  place.sliceW = w;
  scene.sliceW = w;
  scene.refreshSlice();
  gui.controllersRecursive().forEach((c) => c.updateDisplay());
};
gui.add(place, 'sliceW', -1, 1, 0.01).decimals(2).name('sliceW (the flat)').onChange(setSlice);

/** "Link them": lift in w, slide along x to the orange ring's tube, come back to w = 0. */
let script: { to: { x: number; w: number } }[] = [];
const linkScript = (): { to: { x: number; w: number } }[] => [
  { to: { x: place.x, w: 0.8 } },
  { to: { x: MAJOR, w: 0.8 } },
  { to: { x: MAJOR, w: 0 } },
];
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
  if (event.target instanceof HTMLInputElement) return; // typing in a slider's box
  const key = event.key.toLowerCase();
  if (key === 'arrowleft') place.x -= 0.05;
  else if (key === 'arrowright') place.x += 0.05;
  else if (key === 'w') place.w += 0.05;
  else if (key === 's') place.w -= 0.05;
  else return;
  event.preventDefault();
  script = [];
  move();
});

mountRuler(document.getElementById('ruler') as HTMLCanvasElement, scene, [fixed, moving], setSlice);
move();

const canvas = document.getElementById('view') as HTMLCanvasElement;
// the scripted moves advance once per simulated frame (not per animation frame), so a run is the
// same in either thread
const demo = startDemo(scene, {
  canvas,
  eye: [2.4, 3.6, 6.2],
  target: [1.2, 1.1, 0],
  stats: document.getElementById('stats'),
  beforeFrame: (frame) => advance(frame),
});

// --- dragging the blue donut in the picture -----------------------------------------------------
// A press on the blue cut grabs it (the camera stops orbiting): moving the pointer slides it along
// x; with Shift held, up and down move it along w instead. Elsewhere the pointer turns the camera.
const raycaster = new THREE.Raycaster();
const pointer = new THREE.Vector2();
const grabPlane = new THREE.Plane();
const grabbed = { on: false, from: new THREE.Vector3(), x: 0, w: 0 };
function rayAt(event: PointerEvent): THREE.Ray {
  const box = canvas.getBoundingClientRect();
  pointer.set(((event.clientX - box.left) / box.width) * 2 - 1, -((event.clientY - box.top) / box.height) * 2 + 1);
  raycaster.setFromCamera(pointer, demo.camera);
  return raycaster.ray;
}
canvas.addEventListener(
  'pointerdown',
  (event) => {
    if (!moving.visible) return;
    rayAt(event);
    const hit = raycaster.intersectObject(moving, false)[0];
    if (hit === undefined) return;
    // a plane through the grabbed point, facing the camera: the pointer moves on it
    grabPlane.setFromNormalAndCoplanarPoint(demo.camera.getWorldDirection(new THREE.Vector3()), hit.point);
    grabbed.on = true;
    grabbed.from.copy(hit.point);
    grabbed.x = place.x;
    grabbed.w = place.w;
    demo.controls.enabled = false;
    canvas.setPointerCapture(event.pointerId);
    script = [];
  },
  { capture: true },
);
canvas.addEventListener('pointermove', (event) => {
  if (!grabbed.on) return;
  const at = rayAt(event).intersectPlane(grabPlane, new THREE.Vector3());
  if (at === null) return;
  if (event.shiftKey) place.w = grabbed.w + (at.y - grabbed.from.y);
  else place.x = grabbed.x + (at.x - grabbed.from.x);
  move();
});
const release = (): void => {
  grabbed.on = false;
  demo.controls.enabled = true;
};
canvas.addEventListener('pointerup', release);
canvas.addEventListener('pointercancel', release);

// --- each ring's circle, dashed, when the flat misses the ring ----------------------------------
// The circle a torus is built around, drawn where it is in x, y and z whatever its w: it says
// where a ring is while the flat does not cut it (its shadow in the flat, not a cut).
function shadowOf(mesh: HyperTorusMesh, colour: number, plane: 'xy' | 'xz'): THREE.LineLoop {
  const points: THREE.Vector3[] = [];
  for (let k = 0; k < 96; k += 1) {
    const t = (2 * Math.PI * k) / 96;
    points.push(
      plane === 'xy'
        ? new THREE.Vector3(MAJOR * Math.cos(t), MAJOR * Math.sin(t), 0)
        : new THREE.Vector3(MAJOR * Math.cos(t), 0, MAJOR * Math.sin(t)),
    );
  }
  const line = new THREE.LineLoop(
    new THREE.BufferGeometry().setFromPoints(points),
    new THREE.LineDashedMaterial({ color: colour, dashSize: 0.08, gapSize: 0.06 }),
  );
  line.computeLineDistances();
  const follow = (): void => {
    requestAnimationFrame(follow);
    const x = mesh.getPositionN();
    line.position.set(x[0]!, x[1]!, x[2]!);
    line.visible = !mesh.visible;
  };
  follow();
  return line;
}
scene.add(shadowOf(fixed, 0xe9a23b, 'xy'), shadowOf(moving, 0x4d96d9, 'xz'));
