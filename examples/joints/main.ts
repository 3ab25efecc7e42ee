/**
 * The joints page. 3D: a pendulum on a point joint, a chain of 10 links (point or distance
 * joints, rigid or soft: the scene is rebuilt), a door on a hinge with limits and a motor, and a
 * joint that breaks under a load that grows every frame. `?d=4`: a 4D hinge that turns in the
 * (x w) plane, and the 4D pin (a subspace joint holding w and the planes that hold w) moved along
 * w by `setAnchors`.
 */
import * as THREE from 'three';
import GUI from 'lil-gui';
import {
  BoxMesh,
  DistanceJoint,
  HingeJoint,
  HyperBoxMesh,
  HyperPlaneMesh,
  PlaneMesh,
  PointJoint,
  Scene,
  SphereMesh,
  SubspaceJoint,
  createMaterial,
} from '@physin/three';
import type { Joint, Mesh } from '@physin/three';
import { dressScene, linkSwitches, startDemo, wantsWorker } from '../shared/demo.js';

const params = new URLSearchParams(window.location.search);
const n = params.get('d') === '4' ? 4 : 3;
const paint = (color: number): THREE.Material => createMaterial(new THREE.MeshStandardMaterial({ color, side: THREE.DoubleSide }), 0.5, 0.1);
const stone = paint(0x9aa4ae);
const teal = paint(0x2a9d8f);
const amber = paint(0xe9a23b);
const plum = paint(0x8e5aa8);
const coral = paint(0xe76f51);

const settings = { chain: 'point' as 'point' | 'distance', soft: false, motorSpeed: 1.5, maxTorque: 40, limit: 1.2, pinW: 0, sliceW: 0 };
const status = document.getElementById('status')!;
let load = 0;
let broken = false;
let hinge: HingeJoint | null = null;
let pin: SubspaceJoint | null = null;
let breaker: Mesh | null = null;

/** The 3D scene of joints. */
function build3(): Scene {
  const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], worker: wantsWorker() });
  dressScene(scene);
  scene.add(new PlaneMesh(new THREE.BoxGeometry(30, 0.2, 30).translate(0, -0.1, 0), stone, [0, 1, 0], 0));

  // a pendulum: a ball 2 m from a fixed point, let go from the horizontal
  const bob = new SphereMesh(new THREE.SphereGeometry(0.3, 32, 16), amber, 1);
  bob.setPositionN([-5, 5, 0]);
  scene.add(bob);
  scene.addConstraint(new PointJoint(bob, null, [0, 0, 0], [-7, 5, 0]));

  // a chain of 10 links hanging from a fixed point, starting horizontal (so it whips)
  let previous: Mesh | null = null;
  const link = new THREE.BoxGeometry(0.4, 0.12, 0.12);
  for (let i = 0; i < 10; i += 1) {
    const box = new BoxMesh(link, teal, 0.5);
    box.setPositionN([-2 + 0.2 + i * 0.4, 6, 0]);
    scene.add(box);
    const options = settings.soft ? { hertz: 8, damping: 0.7 } : {};
    const joint: Joint =
      settings.chain === 'point'
        ? new PointJoint(box, previous, [-0.2, 0, 0], previous === null ? [-2, 6, 0] : [0.2, 0, 0], options)
        : new DistanceJoint(box, previous, [-0.2, 0, 0], previous === null ? [-2, 6, 0] : [0.2, 0, 0], { ...options, rest: 0.02 });
    scene.addConstraint(joint);
    previous = box;
  }

  // a door on a hinge: it turns about y (in the xz plane, index 1), within limits, by a motor
  const post = new BoxMesh(new THREE.BoxGeometry(0.2, 2.4, 0.2), stone, 0);
  post.setPositionN([4, 1.2, 0]);
  const door = new BoxMesh(new THREE.BoxGeometry(1.6, 2, 0.1), plum, 4);
  door.setPositionN([4.9, 1.15, 0]);
  scene.add(post, door);
  hinge = scene.addConstraint(
    new HingeJoint(post, door, [0.1, 0, 0], [-0.8, 0, 0], {
      plane: 1,
      lowerAngle: -settings.limit,
      upperAngle: settings.limit,
      motorSpeed: settings.motorSpeed,
      maxMotorTorque: settings.maxTorque,
    }),
  );

  // a joint that breaks: a box held by a point joint of 150 N, pulled down harder every frame
  const box = new BoxMesh(new THREE.BoxGeometry(0.6, 0.6, 0.6), coral, 2);
  box.setPositionN([1.5, 3, 3]);
  scene.add(box);
  const weak = scene.addConstraint(new PointJoint(box, null, [0, 0.3, 0], [1.5, 3.3, 3], { breakForce: 150 }));
  weak.addEventListener('broken', () => (broken = true));
  breaker = box;
  load = 0;
  broken = false;
  return scene;
}

/** The 4D scene: a hinge that turns through w, and the pin that holds a body in a 3D slice. */
function build4(): Scene {
  const scene = new Scene({ dimensions: 4, gravity: [0, -9.81, 0, 0], worker: wantsWorker() });
  dressScene(scene);
  scene.add(new HyperPlaneMesh([0, 1, 0, 0], 0, stone, new THREE.BoxGeometry(30, 0.2, 30).translate(0, -0.1, 0)));
  // a 4D hinge: the arm turns in the (x w) plane (index 2 of 01 02 03 12 13 23), out of the flat
  // and back, so its cut grows, shrinks and vanishes while the arm swings
  const base = new HyperBoxMesh([0.3, 1.5, 0.3, 0.3], stone, 0);
  base.setPositionN([-2, 1.5, 0, 0]);
  const arm = new HyperBoxMesh([1, 0.15, 0.3, 0.3], amber, 2);
  arm.setPositionN([-0.7, 2.8, 0, 0]);
  scene.add(base, arm);
  hinge = scene.addConstraint(
    new HingeJoint(base, arm, [0.3, 1.3, 0, 0], [-1, 0, 0, 0], { plane: 2, motorSpeed: settings.motorSpeed, maxMotorTorque: settings.maxTorque }),
  );
  // the pin: a hypercube kept at w = pinW with its three w-planes locked, free in x, y, z
  const body = new HyperBoxMesh([0.4, 0.4, 0.4, 0.4], teal, 1);
  body.setPositionN([2, 3, 0, 0]);
  body.setAngularVelocity([1, 0, 0, 2, 0, 0]);
  scene.add(body);
  pin = scene.addConstraint(new SubspaceJoint(body, null, { lockAxes: [3], lockPlanes: [2, 4, 5], worldFrame: true }));
  return scene;
}

const canvas = document.getElementById('view') as HTMLCanvasElement;
const frameWork = (): void => {
  // the breaking load grows by 1 N a frame (once per simulated frame: the same in either thread)
  if (n === 3 && breaker !== null && !broken) {
    load += 1;
    breaker.applyCentralForce([0, -load, 0]);
  }
};
const demo = startDemo(n === 4 ? build4() : build3(), {
  canvas,
  eye: n === 4 ? [1, 3.5, 8] : [0, 5, 13],
  target: [0, 2.5, 0],
  stats: document.getElementById('stats'),
  beforeFrame: frameWork,
  afterUpdate: () => {
    status.innerHTML =
      n === 3
        ? `<dt>chain</dt><dd>${settings.chain} joints, ${settings.soft ? 'soft (8 Hz)' : 'rigid'}</dd>` +
          `<dt>load</dt><dd>${broken ? `<b>broke</b> at about ${load} N + weight` : `${load} N + weight`}</dd>`
        : `<dt>pin</dt><dd>w = ${settings.pinW.toFixed(2)}</dd>`;
  },
});

const gui = new GUI({ container: document.getElementById('gui')!, title: n === 4 ? 'Joints, 4D' : 'Joints' });
if (n === 3) {
  const rebuild = (): void => demo.setScene(build3());
  gui.add(settings, 'chain', ['point', 'distance']).name('chain joints').onChange(rebuild);
  gui.add(settings, 'soft').name('soft chain').onChange(rebuild);
  gui.add(settings, 'limit', 0.1, 3, 0.05).name('door limit (rad)').onChange((v: number) => hinge?.setLimits(-v, v));
}
gui.add(settings, 'motorSpeed', -4, 4, 0.1).name('motor (rad/s)').onChange(() => hinge?.setMotor(settings.motorSpeed, settings.maxTorque));
gui.add(settings, 'maxTorque', 0, 200, 1).name('motor torque (N·m)').onChange(() => hinge?.setMotor(settings.motorSpeed, settings.maxTorque));
if (n === 4) {
  gui.add(settings, 'pinW', -1.5, 1.5, 0.01).name('pin at w').onChange((w: number) => pin?.setAnchors(null, [0, 0, 0, w]));
  gui.add(settings, 'sliceW', -1.5, 1.5, 0.01).name('sliceW (the flat)').onChange((w: number) => {
    demo.hook.scene.sliceW = w;
    demo.hook.scene.refreshSlice();
  });
}
gui.add({ reset: () => demo.setScene(n === 4 ? build4() : build3()) }, 'reset');

document.getElementById('explain')!.innerHTML =
  n === 3
    ? `<p>On the left a pendulum: a point joint holds the ball 2 m from a fixed point. The chain of ten links starts horizontal and whips as it falls: switch its joints between point joints (each holds a point on a point) and distance joints (each holds only a length), and make them soft (a spring of 8 Hz) to see what each keeps and what it gives up.</p>
       <p>The door turns about y on a hinge: one plane of rotation free (xz), the others held, within limits, driven by a motor of bounded torque that stalls against a limit. The red box hangs from a joint that breaks above 150 N: the page pulls it down 1 N harder every frame until the joint lets go and leaves the scene (its <code>broken</code> event).</p>`
    : `<p>A 4D hinge leaves one plane of rotation free of six. Here it is the (x w) plane: the arm swings out of our flat and back, so its cut grows, thins and vanishes as it turns through w.</p>
       <p>The pin is a subspace joint that holds the teal hypercube's w and the three planes that hold w: it keeps a full 3D rotation and never turns out of the flat. Move it along w with the slider (<code>setAnchors(null, [0, 0, 0, w])</code>): the body slides there without a jump, and leaves the flat you see.</p>`;

linkSwitches({ n, to3: 'The 3D joints', to4: 'The 4D joints' });
