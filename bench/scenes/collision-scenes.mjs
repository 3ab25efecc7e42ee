// The collision benchmark's scenes (bench/collision.bench.mjs): piles of convex bodies and of tori
// in a bin, in PhysiN and in Rapier, built from one engine-neutral layout, and a penetration
// measure that judges both engines alike, each on its own geometry.
//
// The bin: a static box floor (top face y = 0) and four static box walls whose inner faces are
// x = ±BIN_HALF, z = ±BIN_HALF, BIN_HEIGHT tall (higher than any body starts, so nothing leaves).
// Bodies: mass 1, friction 0.5, restitution 0 (scenes/layouts.mjs), seeded start centres on a
// grid with jitter and seeded uniform orientations, dropped from rest; dt 1/60, gravity 9.81.
//
// - Icosahedra: circumradius ICO_RADIUS (the vertices and faces of three.js's
//   IcosahedronGeometry(ICO_RADIUS, 0)); PhysiN ConvexMesh, Rapier ColliderDesc.convexHull of the
//   same 12 vertices.
// - Tori: HyperTorus(R = TORUS_R, r = TORUS_TUBE) in PhysiN (core circle in the body's x-z
//   plane). Rapier has no torus: a compound of TORUS_SEGMENTS capsules of radius r along a closed
//   polygon round the core circle (its corners at radius R' = 2R / (1 + cos(π/m)), so the polygon
//   strays at most R'(1 − cos(π/m))/2 from the circle: 4.8 mm for R = 0.5, m = 16), mass 1/m each.
//
// Penetration (`penetration(scene)`), after the last step, from the poses alone:
// - convex–convex: the exact depth by the separating-axis theorem (face normals of both, and
//   every cross product of an edge of one with an edge of the other): the smallest translation
//   that separates the two hulls;
// - torus–torus: 2r − the distance between the two core curves (PhysiN: circles, by sampling and
//   golden-section refinement; Rapier: its capsule polygons, segment to segment);
// - body–bin: the depth of the body below each inner face of the bin (floor top, four walls).
// Returns the worst and the mean depth over the overlapping pairs, their count, and the bodies
// that left the bin (centre below the floor or beyond a wall; counted apart, not in the depths).

import { World, Body, ConvexMesh, HyperBox, HyperTorus, dims } from '@physin/engine';
import { quaternionToRotor, rotorToQuaternion } from '@physin/algebra';
import { seeded } from '../lib/random.mjs';
import { DT, FRICTION, GRAVITY, MASS, RESTITUTION } from './layouts.mjs';

/** Inner half-width of the bin (m): an 8 m × 8 m floor. */
export const BIN_HALF = 4;
/** Height of the walls above the floor (m). */
export const BIN_HEIGHT = 30;
/** Thickness of the floor and walls (m). */
export const BIN_THICKNESS = 1;
/** Circumradius of the icosahedra (m). */
export const ICO_RADIUS = 0.5;
/** Major and minor (tube) radius of the tori (m). */
export const TORUS_R = 0.5;
export const TORUS_TUBE = 0.15;
/** Capsules of a Rapier torus. */
export const TORUS_SEGMENTS = 16;

/** PhysiN world parameters: the defaults, sleep off. */
export const PHYSIN_PARAMS = Object.freeze({ allowSleep: false });

// ---- geometry ------------------------------------------------------------------------------

/** The 12 vertices (flat) and 20 triangles of three.js's IcosahedronGeometry(radius, 0). */
export function icosahedron(radius = ICO_RADIUS) {
  const t = (1 + Math.sqrt(5)) / 2;
  // prettier-ignore
  const raw = [-1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, 0, 0, -1, t, 0, 1, t, 0, -1, -t, 0, 1, -t, t, 0, -1, t, 0, 1, -t, 0, -1, -t, 0, 1];
  // prettier-ignore
  const faces = [0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8,
    3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1];
  const scale = radius / Math.hypot(1, t);
  return { vertices: raw.map((x) => x * scale), faces };
}

/**
 * What the penetration measure needs of a convex hull, in its body frame: vertices (flat),
 * outward face normals (flat) and edge directions (flat, one per undirected edge).
 */
function hullData(vertices, facets, normals) {
  const edges = [];
  const seen = new Set();
  for (let f = 0; f < facets.length; f += 3) {
    for (let e = 0; e < 3; e += 1) {
      const a = facets[f + e];
      const b = facets[f + ((e + 1) % 3)];
      const key = Math.min(a, b) * 1000 + Math.max(a, b);
      if (seen.has(key)) continue;
      seen.add(key);
      edges.push(
        vertices[3 * b] - vertices[3 * a],
        vertices[3 * b + 1] - vertices[3 * a + 1],
        vertices[3 * b + 2] - vertices[3 * a + 2],
      );
    }
  }
  return { vertices: Float64Array.from(vertices), normals: Float64Array.from(normals), edges: Float64Array.from(edges) };
}

// ---- layouts -------------------------------------------------------------------------------

/** A uniform random unit quaternion [x, y, z, w] (Shoemake). */
function randomQuaternion(rand) {
  const u1 = rand();
  const u2 = rand() * 2 * Math.PI;
  const u3 = rand() * 2 * Math.PI;
  const a = Math.sqrt(1 - u1);
  const b = Math.sqrt(u1);
  return [a * Math.sin(u2), a * Math.cos(u2), b * Math.sin(u3), b * Math.cos(u3)];
}

/**
 * `count` start poses on a grid of `spacing` inside the bin (as many per layer as fit), from
 * height `bottom` up, jittered by up to 10% of the spacing, with uniform random orientations.
 *
 * @returns {{ name: string, kind: 'icosahedra' | 'tori', positions: number[][], quaternions: number[][] }}
 */
export function binLayout(kind, count, spacing, bottom, seed, name = `${kind}${count}`) {
  const rand = seeded(seed);
  const side = Math.floor((2 * BIN_HALF) / spacing);
  const x0 = -((side - 1) * spacing) / 2;
  const jitter = 0.1 * spacing;
  const positions = [];
  const quaternions = [];
  for (let i = 0; i < count; i += 1) {
    const layer = Math.floor(i / (side * side));
    const k = i % (side * side);
    const x = x0 + (k % side) * spacing + (rand() * 2 - 1) * jitter;
    const z = x0 + Math.floor(k / side) * spacing + (rand() * 2 - 1) * jitter;
    const y = bottom + layer * spacing + (rand() * 2 - 1) * jitter;
    positions.push([x, y, z]);
    quaternions.push(randomQuaternion(rand));
  }
  if (positions.some((p) => p[1] + spacing > BIN_HEIGHT)) throw new RangeError(`binLayout: ${name} starts above the walls`);
  return { name, kind, positions, quaternions };
}

/** 500 icosahedra (spacing 1.2 m: 6 × 6 a layer, 14 layers, centres from 1 m to 16.6 m). */
export const icosahedronPile = (count = 500, seed = 1800) => binLayout('icosahedra', count, 1.2, 1, seed);
/** 200 tori (spacing 1.45 m: 5 × 5 a layer, 8 layers, centres from 1 m to 11.2 m). */
export const torusPile = (count = 200, seed = 1801) => binLayout('tori', count, 1.45, 1, seed);

/** The static boxes of the bin: [half-extents, centre] each (floor, then the 4 walls). */
function binBoxes() {
  const h = BIN_HALF;
  const t = BIN_THICKNESS / 2;
  const outer = h + BIN_THICKNESS;
  return [
    [
      [outer, t, outer],
      [0, -t, 0],
    ],
    [
      [t, BIN_HEIGHT / 2, outer],
      [h + t, BIN_HEIGHT / 2, 0],
    ],
    [
      [t, BIN_HEIGHT / 2, outer],
      [-h - t, BIN_HEIGHT / 2, 0],
    ],
    [
      [h, BIN_HEIGHT / 2, t],
      [0, BIN_HEIGHT / 2, h + t],
    ],
    [
      [h, BIN_HEIGHT / 2, t],
      [0, BIN_HEIGHT / 2, -h - t],
    ],
  ];
}

// ---- PhysiN --------------------------------------------------------------------------------

/**
 * The layout in PhysiN: a World (3D, PHYSIN_PARAMS merged with `params`), the bin as 5 static
 * HyperBoxes, one body per layout entry.
 *
 * @returns {{ engine: 'PhysiN', layout, world, bodies: Body[], step(): void, poses(): { x, q }[],
 *   speeds(): number[], hull?, dispose(): void }} poses: centre and quaternion [x, y, z, w] of each
 *   body; speeds: |v| of each body (m/s)
 */
export function buildPhysinBin(layout, params = {}) {
  const D = dims(3);
  const world = new World({ dimensions: 3, gravity: [0, -GRAVITY, 0], params: { ...PHYSIN_PARAMS, ...params } });
  const material = { friction: FRICTION, restitution: RESTITUTION };
  for (const [half, position] of binBoxes()) {
    world.addBody(new Body(D, { shape: HyperBox(D, half), mass: 0, position, material, name: 'bin' }));
  }
  let shape;
  let hull;
  if (layout.kind === 'icosahedra') {
    const { vertices, faces } = icosahedron();
    shape = ConvexMesh(D, vertices, faces);
    const local = shape.vertices; // the principal frame: what the body's pose moves
    hull = hullData(local, shape.facets, shape.facetNormals);
  } else {
    shape = HyperTorus(D, TORUS_R, TORUS_TUBE, [0, 2]);
  }
  const rotor = new Float64Array(D.r);
  const bodies = layout.positions.map((position, i) => {
    quaternionToRotor(rotor, layout.quaternions[i]);
    return world.addBody(new Body(D, { shape, mass: MASS, position, rotor, material, name: `${layout.name}[${i}]` }));
  });
  const q = new Float64Array(4);
  return {
    engine: 'PhysiN',
    layout,
    world,
    bodies,
    hull,
    step: () => world.step(DT),
    poses: () =>
      bodies.map((b) => {
        rotorToQuaternion(q, b.R);
        return { x: Array.from(b.x), q: Array.from(q) };
      }),
    speeds: () => bodies.map((b) => Math.hypot(b.v[0], b.v[1], b.v[2])),
    dispose: () => {},
  };
}

// ---- Rapier --------------------------------------------------------------------------------

/** The corners (body frame, flat) of the polygon a Rapier torus's capsules follow. */
export function torusPolygon(m = TORUS_SEGMENTS, R = TORUS_R) {
  const corner = (2 * R) / (1 + Math.cos(Math.PI / m));
  const out = [];
  for (let i = 0; i < m; i += 1) {
    const a = (2 * Math.PI * i) / m;
    out.push(corner * Math.cos(a), 0, corner * Math.sin(a));
  }
  return out;
}

/**
 * The layout in Rapier (default integration parameters, timestep 1/60): the bin as 5 cuboids on
 * a fixed body; icosahedra as convex hulls, tori as compounds of capsules; setCanSleep(false).
 */
export function buildRapierBin(RAPIER, layout) {
  const world = new RAPIER.World({ x: 0, y: -GRAVITY, z: 0 });
  world.timestep = DT;
  const fixed = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  for (const [[hx, hy, hz], [x, y, z]] of binBoxes()) {
    world.createCollider(
      RAPIER.ColliderDesc.cuboid(hx, hy, hz).setTranslation(x, y, z).setFriction(FRICTION).setRestitution(RESTITUTION),
      fixed,
    );
  }
  let hull;
  let colliders;
  if (layout.kind === 'icosahedra') {
    // the same 12 points as PhysiN's mesh, in its principal frame (centred: the same body origin)
    const D = dims(3);
    const { vertices, faces } = icosahedron();
    const mesh = ConvexMesh(D, vertices, faces);
    hull = hullData(mesh.vertices, mesh.facets, mesh.facetNormals);
    const points = Float32Array.from(mesh.vertices);
    colliders = () => [RAPIER.ColliderDesc.convexHull(points)];
  } else {
    const m = TORUS_SEGMENTS;
    const corner = (2 * TORUS_R) / (1 + Math.cos(Math.PI / m));
    const half = corner * Math.sin(Math.PI / m);
    const mid = corner * Math.cos(Math.PI / m);
    colliders = () => {
      const out = [];
      for (let i = 0; i < m; i += 1) {
        const phi = (2 * Math.PI * (i + 0.5)) / m;
        // the capsule's axis (local y) turned onto the chord's direction (−sin φ, 0, cos φ)
        const s = Math.SQRT1_2;
        out.push(
          RAPIER.ColliderDesc.capsule(half, TORUS_TUBE)
            .setTranslation(mid * Math.cos(phi), 0, mid * Math.sin(phi))
            .setRotation({ x: s * Math.cos(phi), y: 0, z: s * Math.sin(phi), w: s }),
        );
      }
      return out;
    };
  }
  const bodies = layout.positions.map(([x, y, z], i) => {
    const [qx, qy, qz, qw] = layout.quaternions[i];
    const body = world.createRigidBody(
      RAPIER.RigidBodyDesc.dynamic().setTranslation(x, y, z).setRotation({ x: qx, y: qy, z: qz, w: qw }).setCanSleep(false),
    );
    const parts = colliders();
    for (const desc of parts) {
      world.createCollider(
        desc
          .setMass(MASS / parts.length)
          .setFriction(FRICTION)
          .setRestitution(RESTITUTION),
        body,
      );
    }
    return body;
  });
  return {
    engine: 'Rapier',
    layout,
    world,
    bodies,
    hull,
    step: () => world.step(),
    poses: () =>
      bodies.map((b) => {
        const t = b.translation();
        const r = b.rotation();
        return { x: [t.x, t.y, t.z], q: [r.x, r.y, r.z, r.w] };
      }),
    speeds: () =>
      bodies.map((b) => {
        const v = b.linvel();
        return Math.hypot(v.x, v.y, v.z);
      }),
    dispose: () => world.free(),
  };
}

// ---- penetration ---------------------------------------------------------------------------

/** out (flat) = the points `local` (flat, body frame) moved by the pose { x, q }. */
function transform(out, local, x, q, translate = true) {
  const [qx, qy, qz, qw] = q;
  for (let i = 0; i < local.length; i += 3) {
    const vx = local[i];
    const vy = local[i + 1];
    const vz = local[i + 2];
    // v' = v + 2w (u × v) + 2 u × (u × v), u = (qx, qy, qz)
    const tx = 2 * (qy * vz - qz * vy);
    const ty = 2 * (qz * vx - qx * vz);
    const tz = 2 * (qx * vy - qy * vx);
    out[i] = vx + qw * tx + (qy * tz - qz * ty) + (translate ? x[0] : 0);
    out[i + 1] = vy + qw * ty + (qz * tx - qx * tz) + (translate ? x[1] : 0);
    out[i + 2] = vz + qw * tz + (qx * ty - qy * tx) + (translate ? x[2] : 0);
  }
  return out;
}
export { transform as transformPoints };

/** The overlap of the projections of the two point sets on axis (ax, ay, az), divided by its length; +Infinity for a null axis. */
function overlapOn(a, b, ax, ay, az) {
  const len = Math.hypot(ax, ay, az);
  if (len < 1e-9) return Infinity;
  let minA = Infinity;
  let maxA = -Infinity;
  let minB = Infinity;
  let maxB = -Infinity;
  for (let i = 0; i < a.length; i += 3) {
    const d = a[i] * ax + a[i + 1] * ay + a[i + 2] * az;
    if (d < minA) minA = d;
    if (d > maxA) maxA = d;
  }
  for (let i = 0; i < b.length; i += 3) {
    const d = b[i] * ax + b[i + 1] * ay + b[i + 2] * az;
    if (d < minB) minB = d;
    if (d > maxB) maxB = d;
  }
  return Math.min(maxA - minB, maxB - minA) / len;
}

/** The penetration depth of two convex hulls (world vertices, normals, edges): 0 when apart. */
function hullDepth(A, B) {
  let depth = Infinity;
  for (const [normals] of [[A.normals], [B.normals]]) {
    for (let i = 0; i < normals.length; i += 3) {
      const o = overlapOn(A.vertices, B.vertices, normals[i], normals[i + 1], normals[i + 2]);
      if (o <= 0) return 0;
      if (o < depth) depth = o;
    }
  }
  const ea = A.edges;
  const eb = B.edges;
  for (let i = 0; i < ea.length; i += 3) {
    for (let j = 0; j < eb.length; j += 3) {
      const cx = ea[i + 1] * eb[j + 2] - ea[i + 2] * eb[j + 1];
      const cy = ea[i + 2] * eb[j] - ea[i] * eb[j + 2];
      const cz = ea[i] * eb[j + 1] - ea[i + 1] * eb[j];
      const o = overlapOn(A.vertices, B.vertices, cx, cy, cz);
      if (o <= 0) return 0;
      if (o < depth) depth = o;
    }
  }
  return depth;
}

/** Distance from point p to the circle of centre c, unit axis a, radius R. */
function pointCircleDistance(px, py, pz, c, a, R) {
  const dx = px - c[0];
  const dy = py - c[1];
  const dz = pz - c[2];
  const h = dx * a[0] + dy * a[1] + dz * a[2];
  const rx = dx - h * a[0];
  const ry = dy - h * a[1];
  const rz = dz - h * a[2];
  const rho = Math.hypot(rx, ry, rz);
  return Math.hypot(rho - R, h);
}

/** The distance between two circles (centre, unit axis, in-plane unit vectors u, v; radius R). */
function circleCircleDistance(A, B, R) {
  const at = (t) =>
    pointCircleDistance(
      A.c[0] + R * (Math.cos(t) * A.u[0] + Math.sin(t) * A.v[0]),
      A.c[1] + R * (Math.cos(t) * A.u[1] + Math.sin(t) * A.v[1]),
      A.c[2] + R * (Math.cos(t) * A.u[2] + Math.sin(t) * A.v[2]),
      B.c,
      B.a,
      R,
    );
  const M = 96;
  const h = (2 * Math.PI) / M;
  const f = new Float64Array(M);
  for (let i = 0; i < M; i += 1) f[i] = at(i * h);
  let best = Infinity;
  // refine every local minimum of the samples (linked rings have two) by golden section
  for (let i = 0; i < M; i += 1) {
    if (!(f[i] <= f[(i + M - 1) % M] && f[i] <= f[(i + 1) % M])) continue;
    let lo = (i - 1) * h;
    let hi = (i + 1) * h;
    const g = (Math.sqrt(5) - 1) / 2;
    let x1 = hi - g * (hi - lo);
    let x2 = lo + g * (hi - lo);
    let f1 = at(x1);
    let f2 = at(x2);
    for (let k = 0; k < 40; k += 1) {
      if (f1 < f2) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = at(x1);
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = at(x2);
      }
    }
    best = Math.min(best, f1, f2, f[i]);
  }
  return best;
}

/** The distance between segments [p0, p1] and [q0, q1] (flat arrays, offsets). */
function segmentDistance(P, i, j, Q, k, l) {
  const d1x = P[j] - P[i];
  const d1y = P[j + 1] - P[i + 1];
  const d1z = P[j + 2] - P[i + 2];
  const d2x = Q[l] - Q[k];
  const d2y = Q[l + 1] - Q[k + 1];
  const d2z = Q[l + 2] - Q[k + 2];
  const rx = P[i] - Q[k];
  const ry = P[i + 1] - Q[k + 1];
  const rz = P[i + 2] - Q[k + 2];
  const a = d1x * d1x + d1y * d1y + d1z * d1z;
  const e = d2x * d2x + d2y * d2y + d2z * d2z;
  const f = d2x * rx + d2y * ry + d2z * rz;
  const c = d1x * rx + d1y * ry + d1z * rz;
  const b = d1x * d2x + d1y * d2y + d1z * d2z;
  const den = a * e - b * b;
  let s = den > 1e-12 ? Math.min(1, Math.max(0, (b * f - c * e) / den)) : 0;
  let t = (b * s + f) / e;
  if (t < 0) {
    t = 0;
    s = Math.min(1, Math.max(0, -c / a));
  } else if (t > 1) {
    t = 1;
    s = Math.min(1, Math.max(0, (b - c) / a));
  }
  return Math.hypot(rx + d1x * s - d2x * t, ry + d1y * s - d2y * t, rz + d1z * s - d2z * t);
}

/** The distance between two closed polygons (flat world corners). */
function polygonDistance(P, Q) {
  const m = P.length;
  let best = Infinity;
  for (let i = 0; i < m; i += 3) {
    const j = (i + 3) % m;
    for (let k = 0; k < Q.length; k += 3) {
      const d = segmentDistance(P, i, j, Q, k, (k + 3) % Q.length);
      if (d < best) best = d;
    }
  }
  return best;
}

/** The inner faces of the bin as planes n·x >= d (solid where n·x < d). */
const BIN_PLANES = [
  [0, 1, 0, 0],
  [-1, 0, 0, -BIN_HALF],
  [1, 0, 0, -BIN_HALF],
  [0, 0, -1, -BIN_HALF],
  [0, 0, 1, -BIN_HALF],
];

/** Whether a body's centre has left the bin (below the floor or beyond a wall). */
const outside = (x) => x[1] < 0 || Math.abs(x[0]) > BIN_HALF || Math.abs(x[2]) > BIN_HALF;

/**
 * Penetration at the scene's current poses (see the top of the file).
 *
 * @returns {{ worst: number, mean: number, overlaps: number, lost: number }} depths in m
 */
export function penetration(scene) {
  const poses = scene.poses();
  const N = poses.length;
  const depths = [];
  let lost = 0;
  const tori = scene.layout.kind === 'tori';
  // per body: world geometry and a bounding radius
  let shapes;
  let reach;
  if (!tori) {
    const { hull } = scene;
    reach = Math.sqrt(
      Math.max(
        ...Array.from(
          { length: hull.vertices.length / 3 },
          (_, i) => hull.vertices[3 * i] ** 2 + hull.vertices[3 * i + 1] ** 2 + hull.vertices[3 * i + 2] ** 2,
        ),
      ),
    );
    shapes = poses.map(({ x, q }) => ({
      vertices: transform(new Float64Array(hull.vertices.length), hull.vertices, x, q),
      normals: transform(new Float64Array(hull.normals.length), hull.normals, x, q, false),
      edges: transform(new Float64Array(hull.edges.length), hull.edges, x, q, false),
    }));
  } else if (scene.engine === 'PhysiN') {
    reach = TORUS_R + TORUS_TUBE;
    shapes = poses.map(({ x, q }) => {
      const frame = transform(new Float64Array(9), [1, 0, 0, 0, 0, 1, 0, 1, 0], x, q, false); // u (x), v (z), axis (y)
      return { c: x, u: frame.subarray(0, 3), v: frame.subarray(3, 6), a: frame.subarray(6, 9) };
    });
  } else {
    const polygon = torusPolygon();
    reach = Math.max(...polygon.map(Math.abs)) + TORUS_TUBE;
    shapes = poses.map(({ x, q }) => ({ corners: transform(new Float64Array(polygon.length), polygon, x, q) }));
  }
  for (let i = 0; i < N; i += 1) {
    const { x } = poses[i];
    if (outside(x)) {
      lost += 1; // counted apart: its depth below the floor is not a penetration of a contact
      continue;
    }
    // against the bin's inner faces
    for (const [nx, ny, nz, d] of BIN_PLANES) {
      let low;
      if (!tori) {
        const v = shapes[i].vertices;
        low = Infinity;
        for (let k = 0; k < v.length; k += 3) low = Math.min(low, nx * v[k] + ny * v[k + 1] + nz * v[k + 2]);
      } else if (scene.engine === 'PhysiN') {
        const { c, a } = shapes[i];
        const dot = nx * a[0] + ny * a[1] + nz * a[2];
        low = nx * c[0] + ny * c[1] + nz * c[2] - TORUS_R * Math.sqrt(Math.max(0, 1 - dot * dot)) - TORUS_TUBE;
      } else {
        const v = shapes[i].corners;
        low = Infinity;
        for (let k = 0; k < v.length; k += 3) low = Math.min(low, nx * v[k] + ny * v[k + 1] + nz * v[k + 2] - TORUS_TUBE);
      }
      if (low < d) depths.push(d - low);
    }
    // against the other bodies
    for (let j = i + 1; j < N; j += 1) {
      const y = poses[j].x;
      if (outside(y)) continue;
      const dist = Math.hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
      if (dist >= 2 * reach) continue;
      let depth;
      if (!tori) depth = hullDepth(shapes[i], shapes[j]);
      else if (scene.engine === 'PhysiN') depth = 2 * TORUS_TUBE - circleCircleDistance(shapes[i], shapes[j], TORUS_R);
      else depth = 2 * TORUS_TUBE - polygonDistance(shapes[i].corners, shapes[j].corners);
      if (depth > 0) depths.push(depth);
    }
  }
  const worst = depths.length > 0 ? Math.max(...depths) : 0;
  const mean = depths.length > 0 ? depths.reduce((s, d) => s + d, 0) / depths.length : 0;
  return { worst, mean, overlaps: depths.length, lost };
}
