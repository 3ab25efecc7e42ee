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
import { JointLines } from './links.js';

const params = new URLSearchParams(window.location.search);
const n = params.get('d') === '4' ? 4 : 3;
const paint = (color: number): THREE.Material =>
  createMaterial(new THREE.MeshStandardMaterial({ color, side: THREE.DoubleSide }), 0.5, 0.1);
const stone = paint(0x9aa4ae);
const teal = paint(0x2a9d8f);
const amber = paint(0xe9a23b);
const plum = paint(0x8e5aa8);
const coral = paint(0xe76f51);

const settings = {
  chain: 'point' as 'point' | 'distance',
  soft: false,
  motorSpeed: n === 4 ? 0.8 : 1.5,
  maxTorque: 40,
  limit: 1.2,
  pinW: 0,
  sliceW: 0,
};
const status = document.getElementById('status')!;
const message = document.getElementById('message')!;
let load = 0;
let broken = false;
let hinge: HingeJoint | null = null;
let pin: SubspaceJoint | null = null;
let breaker: Mesh | null = null;
let lines: JointLines | null = null;
let arm: Mesh | null = null;
let pinned: Mesh | null = null;
/** 4D: the arm's shadow on the flat (its far end with w dropped), a line from the hinge. */
let shadow: THREE.Line | null = null;
/** Where the 4D hinge holds the arm (in the world). */
const HINGE_4D = [-2, 3.3, 0, 0] as const;

/** The 3D scene of joints. */
function build3(): Scene {
  const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], worker: wantsWorker() });
  dressScene(scene);
  scene.add(new PlaneMesh(new THREE.BoxGeometry(30, 0.2, 30).translate(0, -0.1, 0), stone, [0, 1, 0], 0));
  lines = new JointLines(scene);
  message.hidden = true;

  // a pendulum: a ball 2 m from a fixed point, let go from the horizontal
  const bob = new SphereMesh(new THREE.SphereGeometry(0.3, 32, 16), amber, 1);
  bob.setPositionN([-4, 5.5, -2]);
  scene.add(bob);
  // the joint holds the point 2 m left of the ball's centre (in the ball's frame) on the pivot;
  // the line is drawn from the ball's centre
  scene.addConstraint(lines.add(new PointJoint(bob, null, [-2, 0, 0], [-6, 5.5, -2]), [0, 0, 0], [-6, 5.5, -2]));

  // a chain of 10 links hanging from a fixed point, starting horizontal (so it whips)
  let previous: Mesh | null = null;
  const link = new THREE.BoxGeometry(0.4, 0.12, 0.12);
  for (let i = 0; i < 10; i += 1) {
    const box = new BoxMesh(link, teal, 0.5);
    box.setPositionN([-2 + 0.2 + i * 0.4, 6, 0]);
    scene.add(box);
    const there = previous === null ? [-2, 6, 0] : [0.2, 0, 0];
    const joint: Joint =
      settings.chain === 'point'
        ? new PointJoint(box, previous, [-0.2, 0, 0], there)
        : new DistanceJoint(box, previous, [-0.2, 0, 0], there, { rest: 0.02 });
    // a spring of 8 Hz, damping ratio 0.7 (set before addConstraint: it becomes an option)
    if (settings.soft) joint.setSoftness(8, 0.7);
    scene.addConstraint(lines.add(joint, [-0.2, 0, 0], there));
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

  // a joint that breaks: a box hung 1.2 m under a hook by a distance joint that breaks above
  // 150 N, pulled down harder every frame
  const box = new BoxMesh(new THREE.BoxGeometry(0.6, 0.6, 0.6), coral, 2);
  box.setPositionN([1.5, 3, 3]);
  scene.add(box);
  const weak = new DistanceJoint(box, null, [0, 0.3, 0], [1.5, 4.5, 3]).setBreak(150, 0);
  weak.addEventListener('broken', () => {
    broken = true;
    message.textContent = `The joint broke: ${load} N of pull + ${(2 * 9.81).toFixed(0)} N of weight passed its 150 N.`;
    message.hidden = false;
  });
  scene.addConstraint(lines.add(weak, [0, 0.3, 0], [1.5, 4.5, 3]));
  breaker = box;
  load = 0;
  broken = false;
  lines.finish();
  return scene;
}

/** The 4D scene: a hinge that turns through w, and the pin that holds a body in a 3D slice. */
function build4(): Scene {
  const scene = new Scene({ dimensions: 4, gravity: [0, -9.81, 0, 0], worker: wantsWorker(), sliceW: settings.sliceW });
  dressScene(scene);
  scene.add(new HyperPlaneMesh([0, 1, 0, 0], 0, stone, new THREE.BoxGeometry(30, 0.2, 30).translate(0, -0.1, 0)));
  message.hidden = true;
  // a 4D hinge: the arm turns in the (x w) plane (index 2 of 01 02 03 12 13 23) about a point
  // above the post, out of the flat and back: its cut is long when the arm lies in the flat and a
  // short stub (its thickness in w) when the arm points along w
  const base = new HyperBoxMesh([0.25, 1.5, 0.25, 0.25], stone, 0);
  base.setPositionN([HINGE_4D[0], 1.5, 0, 0]);
  const swing = new HyperBoxMesh([1.2, 0.12, 0.25, 0.25], amber, 2);
  swing.setPositionN([HINGE_4D[0] + 1.2, HINGE_4D[1], 0, 0]);
  scene.add(base, swing);
  arm = swing;
  lines = null;
  const dot = new THREE.Mesh(new THREE.SphereGeometry(0.06, 12, 8), new THREE.MeshBasicMaterial({ color: 0x1d2630 }));
  dot.position.set(HINGE_4D[0], HINGE_4D[1], HINGE_4D[2]);
  shadow = new THREE.Line(
    new THREE.BufferGeometry().setFromPoints([dot.position, dot.position.clone().add(new THREE.Vector3(2.4, 0, 0))]),
    new THREE.LineDashedMaterial({ color: 0x1d2630, dashSize: 0.12, gapSize: 0.08 }),
  );
  shadow.computeLineDistances();
  shadow.frustumCulled = false;
  scene.add(dot, shadow);
  hinge = scene.addConstraint(
    new HingeJoint(base, swing, [0, HINGE_4D[1] - 1.5, 0, 0], [-1.2, 0, 0, 0], { plane: 2 }).setMotor(
      settings.motorSpeed,
      settings.maxTorque,
    ),
  );
  // the pin: a hypercube kept at w = pinW with its three w-planes locked, free in x, y, z
  const body = new HyperBoxMesh([0.4, 0.4, 0.4, 0.4], teal, 1);
  body.setPositionN([2, 3, 0, 0]);
  body.setAngularVelocity([1, 0, 0, 2, 0, 0]);
  scene.add(body);
  pinned = body;
  settings.pinW = 0;
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
  eye: n === 4 ? [0.6, 4.4, 6.2] : [-1, 5.5, 15],
  target: n === 4 ? [0, 2.2, 0] : [-1, 3, 0],
  stats: document.getElementById('stats'),
  beforeFrame: frameWork,
  afterUpdate: () => {
    lines?.update();
    if (n === 4 && shadow !== null && arm !== null) {
      // the far end is the hinge plus twice (centre − hinge); drop its w
      const c = arm.getPositionN();
      const ends = shadow.geometry.getAttribute('position') as THREE.BufferAttribute;
      ends.setXYZ(1, 2 * c[0]! - HINGE_4D[0], 2 * c[1]! - HINGE_4D[1], 2 * c[2]! - HINGE_4D[2]);
      ends.needsUpdate = true;
      shadow.computeLineDistances();
    }
    status.innerHTML = n === 3 ? status3() : status4();
  },
});

function status3(): string {
  return (
    `<dt>chain</dt><dd>${settings.chain} joints, ${settings.soft ? 'soft (8 Hz)' : 'rigid'}</dd>` +
    `<dt>door</dt><dd>within ±${settings.limit.toFixed(2)} rad, motor ${settings.motorSpeed.toFixed(1)} rad/s</dd>` +
    `<dt>pull</dt><dd>${broken ? `<b>broke</b> at ${load} N + weight` : `${load} N + weight (breaks above 150 N)`}</dd>`
  );
}

function status4(): string {
  const a = arm?.getPositionN();
  const p = pinned?.getPositionN();
  const angle = a ? (Math.atan2(a[3]!, a[0]! - HINGE_4D[0]) * 180) / Math.PI : 0;
  return (
    `<dt>arm</dt><dd>${angle.toFixed(0)}° from x towards w</dd>` +
    `<dt>pin</dt><dd>w = ${settings.pinW.toFixed(2)}; the body at w = ${p ? p[3]!.toFixed(2) : '–'}</dd>` +
    `<dt>flat</dt><dd>w = ${settings.sliceW.toFixed(2)}</dd>`
  );
}

const gui = new GUI({ container: document.getElementById('gui')!, title: n === 4 ? 'Joints, 4D' : 'Joints' });
if (n === 3) {
  const rebuild = (): void => demo.setScene(build3());
  gui.add(settings, 'chain', ['point', 'distance']).name('chain joints').onChange(rebuild);
  gui.add(settings, 'soft').name('soft chain').onChange(rebuild);
  gui
    .add(settings, 'limit', 0.1, 3, 0.05)
    .name('door limit (rad)')
    .onChange((v: number) => hinge?.setLimits(-v, v));
}
gui
  .add(settings, 'motorSpeed', -4, 4, 0.1)
  .name('motor (rad/s)')
  .onChange(() => hinge?.setMotor(settings.motorSpeed, settings.maxTorque));
gui
  .add(settings, 'maxTorque', 0, 200, 1)
  .name('motor torque (N·m)')
  .onChange(() => hinge?.setMotor(settings.motorSpeed, settings.maxTorque));
if (n === 4) {
  gui
    .add(settings, 'pinW', -1.5, 1.5, 0.01)
    .name('pin at w')
    .onChange((w: number) => pin?.setAnchors(null, [0, 0, 0, w]));
  gui
    .add(settings, 'sliceW', -1.5, 1.5, 0.01)
    .name('sliceW (the flat)')
    .onChange((w: number) => {
      demo.hook.scene.sliceW = w;
      demo.hook.scene.refreshSlice();
    });
}
gui.add(
  {
    reset: () => {
      demo.setScene(n === 4 ? build4() : build3());
      for (const controller of gui.controllersRecursive()) controller.updateDisplay();
    },
  },
  'reset',
);

document.getElementById('explain')!.innerHTML =
  n === 3
    ? `<p>On the left a <b>pendulum</b>: a <code>PointJoint</code> holds a point 2 m from the ball's centre on a fixed point (a dot), so the ball swings about it. The thin lines join each joint's two anchors.</p>
       <p>The <b>chain</b> of ten links starts horizontal and whips as it falls. Switch its joints between point joints (a point of one link on a point of the next) and distance joints (only a length: links may fold), rigid or soft (<code>setSoftness(8, 0.7)</code>, a spring of 8 Hz): soft links stretch, and the lines show it.</p>
       <p>The <b>door</b> turns about y on a <code>HingeJoint</code>: one of the three planes of rotation is free, xz (plane 1 of xy, xz, yz), within limits (<code>setLimits</code>), driven by a motor of bounded torque (<code>setMotor</code>) that stalls at a limit.</p>
       <p>The red box hangs from a hook by a joint that breaks above 150 N (<code>setBreak(150, 0)</code>). The page pulls it 1 N harder every frame until the joint lets go and fires <code>broken</code>.</p>`
    : `<p>A 4D <b>hinge</b> leaves one plane of rotation free of six. Here it is the (x w) plane (plane 2 of xy, xz, xw, yz, yw, zw): the motor turns the arm out of our flat and back. Its cut is the whole arm when it lies along x, and a short stub, its thickness in w, when it points along w; in between it is as long as the part of the arm that still crosses w = 0. The dashed line is the arm's shadow (w dropped): it shortens as the arm turns into w, while the cut stays by the hinge.</p>
       <p>The <b>pin</b> is a <code>SubspaceJoint</code> that holds the teal hypercube's w and the three planes that turn through w (xw, yw, zw): it moves and turns freely in x, y, z and never tips out of the flat. Move the pin along w with the slider (<code>setAnchors(null, [0, 0, 0, w])</code>): the body slides there. Held square to w, its cut stays the same whole cube until the pin passes w = ±0.4 (the body's half-width in w), then vanishes at once; move the flat (<code>scene.sliceW</code>) after it to find it again.</p>`;

linkSwitches({ n, to3: 'The 3D joints', to4: 'The 4D joints' });
