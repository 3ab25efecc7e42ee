/**
 * A real ConvexMesh described off-centre and turned: the body places its principal frame so that
 * the mesh's vertices, carried by the body's pose, land exactly where the user described them,
 * and the body's centre of mass is the mesh's centroid.
 */
import { describe, expect, it } from 'vitest';
import { Body, ConvexMesh, dims, HyperBox } from '@physin/engine';
import { rotorApplyVector, rotorFromPlane } from '@physin/algebra';

const D = dims(3);

/** The 12 triangles (36 corners, repeated as three.js gives them) of a box turned and moved. */
function turnedBoxTriangles(half: number[], centre: number[], R: Float64Array): { positions: Float64Array; corners: number[][] } {
  const corners: number[][] = [];
  for (let m = 0; m < 8; m += 1) {
    const local = Float64Array.from([0, 1, 2].map((i) => ((m >> i) & 1 ? half[i]! : -half[i]!)));
    const w = rotorApplyVector(D, new Float64Array(3), R, local);
    corners.push([0, 1, 2].map((i) => w[i]! + centre[i]!));
  }
  // Each face: the 4 corners with bit `axis` equal to `side`, split into two triangles.
  const tris: number[] = [];
  for (let axis = 0; axis < 3; axis += 1) {
    for (const side of [0, 1]) {
      const face = [0, 1, 2, 3, 4, 5, 6, 7].filter((m) => ((m >> axis) & 1) === side);
      const [a, b, c, d] = face as [number, number, number, number];
      tris.push(a, b, d, a, d, c); // orientation does not matter: the mesh orients facets outward
    }
  }
  const positions = new Float64Array(tris.length * 3);
  tris.forEach((v, t) => positions.set(corners[v]!, t * 3));
  return { positions, corners };
}

describe('a body with a real ConvexMesh off the origin', () => {
  const half = [0.5, 0.3, 0.2];
  const centre = [1, 2, -0.5];
  const turn = rotorFromPlane(D, new Float64Array(4), 0, 1, 0.4);
  const { positions, corners } = turnedBoxTriangles(half, centre, turn);
  const mesh = ConvexMesh.fromTriangles(D, positions);

  it('has the mass properties of the same HyperBox (1e-12)', () => {
    const a = mesh.massProperties(D, 2);
    const b = HyperBox(D, half).massProperties(D, 2);
    expect(Math.abs(a.volume - b.volume)).toBeLessThan(1e-12);
    const sa = Array.from(a.inertia).sort();
    const sb = Array.from(b.inertia).sort();
    for (let i = 0; i < 3; i += 1) expect(Math.abs(sa[i]! - sb[i]!)).toBeLessThan(1e-12);
  });

  it('places its centre of mass at position + centroid, and carries every vertex to where it was described (1e-12)', () => {
    const p = [3, -1, 0.25];
    const body = new Body(D, { shape: mesh, mass: 2, position: p });
    for (let i = 0; i < 3; i += 1) expect(Math.abs(body.x[i]! - (p[i]! + centre[i]!))).toBeLessThan(1e-12);
    // Every stored (principal-frame) vertex, carried by the body's pose, is a described corner moved by p.
    const u = new Float64Array(3);
    for (let v = 0; v < mesh.vertices.length / 3; v += 1) {
      rotorApplyVector(D, u, body.R, mesh.vertices.subarray(v * 3, v * 3 + 3));
      const world = [0, 1, 2].map((i) => body.x[i]! + u[i]!);
      const nearest = Math.min(...corners.map((c) => Math.hypot(...c.map((ci, i) => ci + p[i]! - world[i]!))));
      expect(nearest).toBeLessThan(1e-12);
    }
  });
});
