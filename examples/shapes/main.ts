/**
 * The shapes page: every shape touches every shape. A pile of capsules, a dumbbell that is one
 * body of three meshes (its collision events name the part that touched), a chain of tori hanging
 * from a fixed one, icosahedra read from three's geometry falling through a sensor that changes
 * colour while something is inside it, and two columns of boxes: one that stacks, one whose
 * collision group leaves its boxes out of each other's mask, so they fall through one another.
 */
import * as THREE from 'three';
import { BoxMesh, CapsuleMesh, ConvexMesh, PlaneMesh, Scene, SphereMesh, TorusMesh, createMaterial } from '@physin/three';
import type { CollisionEvent, Mesh } from '@physin/three';
import { dressScene, linkSwitches, seeded, startDemo, wantsWorker } from '../shared/demo.js';

/** What the browser test reads (and what the read-out shows). */
export interface ShapesHook {
  /** 'begin' and 'end' events the sensor has seen, and the bodies inside it now. */
  sensorBegins: number;
  sensorEnds: number;
  inside: number;
  /** The dumbbell's collision events, as "phase part other" lines, oldest first. */
  dumbbellEvents: string[];
  /** The meshes the test measures. */
  links: Mesh[];
  ghosts: Mesh[];
  solids: Mesh[];
}
declare global {
  var physinShapes: ShapesHook | undefined;
}

const random = seeded(18);
const material = (color: number, friction: number, restitution: number, extra: THREE.MeshStandardMaterialParameters = {}) =>
  createMaterial(new THREE.MeshStandardMaterial({ color, ...extra }), friction, restitution);

const scene = new Scene({ dimensions: 3, gravity: [0, -9.81, 0], worker: wantsWorker() });
dressScene(scene);
const floor = new PlaneMesh(new THREE.BoxGeometry(40, 0.2, 40).translate(0, -0.1, 0), material(0xc9ced6, 0.8, 0.1), [0, 1, 0], 0);
floor.name = 'the floor';
scene.add(floor);

// --- 1. a pile of capsules in a bin -------------------------------------------------------------
// CapsuleMesh takes its radius and straight length from the CapsuleGeometry's parameters.
const capsuleGeometry = new THREE.CapsuleGeometry(0.2, 0.7, 4, 12);
const capsuleColours = [0x2a9d8f, 0x3d8bbf, 0x6b9e4e];
const BIN = { x: -5, z: 0.8, inner: 2.2, wall: 0.15, height: 0.7 };
const binLook = material(0xb0b8c2, 0.8, 0.1);
for (const [dx, dz, wx, wz] of [
  [-1, 0, BIN.wall, BIN.inner + 2 * BIN.wall],
  [1, 0, BIN.wall, BIN.inner + 2 * BIN.wall],
  [0, -1, BIN.inner, BIN.wall],
  [0, 1, BIN.inner, BIN.wall],
] as const) {
  const wall = new BoxMesh(new THREE.BoxGeometry(wx, BIN.height, wz), binLook, 0);
  wall.name = 'the bin';
  const off = (BIN.inner + BIN.wall) / 2;
  wall.position.set(BIN.x + dx * off, BIN.height / 2, BIN.z + dz * off);
  scene.add(wall);
}
for (let i = 0; i < 15; i += 1) {
  const capsule = new CapsuleMesh(capsuleGeometry, material(capsuleColours[i % 3]!, 0.6, 0.1), 1);
  capsule.name = `capsule ${i + 1}`;
  // layers of three side by side, each layer turned its own way, dropped into the bin
  const layer = Math.floor(i / 3);
  const yaw = layer * 1.1 + random() * 0.4;
  const across = ((i % 3) - 1) * 0.5;
  capsule.position.set(BIN.x + across * Math.cos(yaw), 0.5 + layer * 0.6, BIN.z - across * Math.sin(yaw));
  // a capsule's axis is its y: lay it down (a quarter turn about x), then turn it by the layer's yaw
  capsule.rotation.set(Math.PI / 2 + (random() - 0.5) * 0.2, 0, 0);
  capsule.rotateOnWorldAxis(new THREE.Vector3(0, 1, 0), yaw);
  scene.add(capsule);
}

// --- 2. boxes that stack, and ghosts that pass through one another -------------------------------
// Two bodies collide when each one's group meets the other's mask. Every body is in group 1 and
// sees every group by default; a ghost is in group 2 and sees every group but 2.
const GHOST = 0b10;
const boxGeometry = new THREE.BoxGeometry(0.8, 0.8, 0.8);
const solids: Mesh[] = [];
const ghosts: Mesh[] = [];
for (let i = 0; i < 5; i += 1) {
  const solid = new BoxMesh(boxGeometry, material(i % 2 === 0 ? 0x8e99a6 : 0x66717e, 0.7, 0), 1);
  solid.name = `box ${i + 1}`;
  solid.position.set(-3.4, 0.4 + i * 1.4, -1.2);
  scene.add(solid);
  solids.push(solid);
  const ghost = new BoxMesh(boxGeometry, material(0xd9534f, 0.7, 0, { transparent: true, opacity: 0.55, depthWrite: false }), 1);
  ghost.name = `ghost ${i + 1}`;
  // a little apart in x, so the boxes that end up inside one another can be told apart
  ghost.position.set(-2.2 + i * 0.08, 0.4 + i * 1.4, -0.6);
  // `>>> 0`: JavaScript's `~` gives a signed 32-bit number (−3); a mask is unsigned
  ghost.setCollisionFilter({ group: GHOST, mask: ~GHOST >>> 0 });
  scene.add(ghost);
  ghosts.push(ghost);
}

// --- 3. a sensor, and icosahedra falling through it ----------------------------------------------
// A sensor reports 'begin' and 'end' as bodies enter and leave it, and pushes nothing.
const idle = new THREE.Color(0x7a8da3);
const busy = new THREE.Color(0xf2b134);
const zoneLook = new THREE.MeshStandardMaterial({ color: idle, transparent: true, opacity: 0.28, depthWrite: false });
const sensor = new BoxMesh(new THREE.BoxGeometry(2.4, 1.4, 2.4), zoneLook, 0);
sensor.name = 'the sensor';
sensor.position.set(0.3, 2.6, 0);
sensor.setCollisionFilter({ sensor: true });
scene.add(sensor);
const edges = new THREE.LineSegments(
  new THREE.EdgesGeometry(sensor.geometry),
  new THREE.LineBasicMaterial({ color: 0x45566b, transparent: true, opacity: 0.6 }),
);
sensor.add(edges); // a plain three.js child: only PhysiN meshes become parts of a body

// ConvexMesh reads the geometry's triangles (three's polyhedra repeat their vertices; they are merged).
const icosahedron = new THREE.IcosahedronGeometry(0.36);
const plum = material(0x8e5aa8, 0.6, 0.2, { flatShading: true });
for (let i = 0; i < 7; i += 1) {
  const body = new ConvexMesh(icosahedron, plum, 1);
  body.name = `icosahedron ${i + 1}`;
  body.position.set(0.3 + (random() - 0.5) * 1.4, 4.6 + i * 1.3, (random() - 0.5) * 1.4);
  body.rotation.set(random() * 3, random() * 3, random() * 3);
  body.setAngularVelocity(new THREE.Vector3(random() * 4 - 2, random() * 4 - 2, random() * 4 - 2));
  scene.add(body);
}

// --- 4. a dumbbell: one body of three meshes -----------------------------------------------------
// Child PhysiN meshes added to a mesh before the mesh is added to the scene are parts of its body
// (as in Physijs): the bar is the body's mesh, the two balls are parts at their local positions.
const bar = new CapsuleMesh(new THREE.CapsuleGeometry(0.09, 1.3, 4, 12), material(0x5b6470, 0.6, 0.1), 3);
bar.name = 'the bar';
const ballGeometry = new THREE.SphereGeometry(0.32, 24, 12);
const leftBall = new SphereMesh(ballGeometry, material(0xe76f51, 0.6, 0.1), 1);
leftBall.name = 'ball A';
leftBall.position.set(0, 0.8, 0);
const rightBall = new SphereMesh(ballGeometry, material(0x3a86c8, 0.6, 0.1), 1);
rightBall.name = 'ball B';
rightBall.position.set(0, -0.8, 0);
bar.add(leftBall, rightBall);
const dumbbellParts: readonly Mesh[] = [bar, leftBall, rightBall];
/** Lifts the dumbbell, tilted and turning, above the step (a teleport, then velocities). */
function dropDumbbell(): void {
  bar.position.set(3.4, 4.2, 0.6);
  bar.quaternion.setFromEuler(new THREE.Euler(0.3, 0, Math.PI / 2 - 0.35));
  bar.setLinearVelocity([0, 0, 0]);
  bar.setAngularVelocity([0.4, 1.2, 0]);
}
dropDumbbell();
scene.add(bar);
// a step under one end, so each ball lands on something else
const step = new BoxMesh(new THREE.BoxGeometry(1.2, 0.8, 1.6), material(0xb0b8c2, 0.8, 0.1), 0);
step.name = 'the step';
step.position.set(3.0, 0.4, 0.6);
scene.add(step);

// --- 5. a chain of tori hanging from a fixed one ------------------------------------------------
// Each link's circle is at right angles to the next one's; the fixed top link has mass 0.
const MAJOR = 0.45;
const MINOR = 0.1;
const torusGeometry = new THREE.TorusGeometry(MAJOR, MINOR, 12, 40);
const steel = material(0x9aa4ae, 0.4, 0.05, { metalness: 0.4, roughness: 0.45 });
const gold = material(0xd4a017, 0.4, 0.05, { metalness: 0.4, roughness: 0.45 });
const TOP = 6.4;
/** Centre spacing of two links hanging straight, their tubes touching: 2(R − r); a little less at the start. */
const SPACING = 2 * (MAJOR - MINOR) - 0.04;
const links: Mesh[] = [];
for (let i = 0; i <= 5; i += 1) {
  const link = new TorusMesh(torusGeometry, i === 0 ? gold : steel, i === 0 ? 0 : 1, MAJOR, MINOR);
  link.name = i === 0 ? 'the fixed link' : `link ${i}`;
  link.position.set(6.2, TOP - i * SPACING, 0);
  // TorusGeometry's circle is in xy; turn every other link a quarter about y (the first one too,
  // by an eighth, so both kinds are seen at a slant)
  link.rotation.y = Math.PI / 4 + (i % 2) * (Math.PI / 2);
  if (i === 5) link.setLinearVelocity([1.2, 0, 0.8]); // a push, so the chain swings
  scene.add(link);
  links.push(link);
}

// --- events ----------------------------------------------------------------------------------------
const hook: ShapesHook = { sensorBegins: 0, sensorEnds: 0, inside: 0, dumbbellEvents: [], links, ghosts, solids };
globalThis.physinShapes = hook;

sensor.addEventListener('collision', (event) => {
  if (event.phase === 'begin') {
    hook.sensorBegins += 1;
    hook.inside += 1;
  } else {
    hook.sensorEnds += 1;
    hook.inside -= 1;
  }
  zoneLook.color.copy(hook.inside > 0 ? busy : idle);
});

/** Frames each part of the dumbbell stays lit after it touched something. */
const glow = new Map<Mesh, number>(dumbbellParts.map((part) => [part, 0]));
const log = document.getElementById('log')!;
bar.addEventListener('collision', (event: Omit<CollisionEvent, 'type'>) => {
  const line = `${event.phase} ${event.part.name} · ${event.otherPart.name}`;
  hook.dumbbellEvents.push(line);
  const item = document.createElement('li');
  item.textContent =
    event.phase === 'begin'
      ? `${event.part.name} hits ${event.otherPart.name}`
      : `${event.part.name} leaves ${event.otherPart.name}`;
  item.className = event.phase;
  log.prepend(item);
  while (log.childElementCount > 8) log.lastElementChild!.remove();
  if (event.phase === 'begin') glow.set(event.part, 40);
});

/** Once a frame: fade the lit parts of the dumbbell. */
function fade(): void {
  for (const [part, left] of glow) {
    if (left <= 0) continue;
    glow.set(part, left - 1);
    const look = part.material as THREE.MeshStandardMaterial;
    look.emissive.setRGB(0.55 * (left / 40), 0.45 * (left / 40), 0.05 * (left / 40));
  }
}

const status = document.getElementById('status')!;
function readout(): void {
  status.innerHTML =
    `<dt>sensor</dt><dd>${hook.inside > 0 ? `<b>${hook.inside} inside</b>` : 'empty'} · ${hook.sensorBegins} begin, ${hook.sensorEnds} end</dd>` +
    `<dt>chain</dt><dd>bottom link at y ${links[5]!.position.y.toFixed(2)} m</dd>`;
}

startDemo(scene, {
  canvas: document.getElementById('view') as HTMLCanvasElement,
  eye: [0.4, 6.2, 13.4],
  target: [0.4, 2.3, 0],
  stats: document.getElementById('stats'),
  afterUpdate: (frame) => {
    fade();
    if (frame % 6 === 0) readout();
  },
});
document.getElementById('drop')!.addEventListener('click', dropDumbbell);
readout();
linkSwitches();
