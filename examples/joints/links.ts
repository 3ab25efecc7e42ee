/**
 * Thin lines that show the joints of a 3D scene: one segment per joint from its anchor on `a` to
 * its anchor on `b` (or on the world), moved after each report, and a small dot at every anchor
 * on the world. A joint that broke loses its line.
 */
import * as THREE from 'three';
import type { Joint, Mesh } from '@physin/three';

interface Link {
  readonly joint: Joint;
  readonly a: Mesh;
  readonly localA: THREE.Vector3;
  readonly b: Mesh | null;
  /** In the frame of `b`, or in the world when `b` is null. */
  readonly localB: THREE.Vector3;
  gone: boolean;
}

const v = (p: readonly number[]): THREE.Vector3 => new THREE.Vector3(p[0] ?? 0, p[1] ?? 0, p[2] ?? 0);

/** The lines of one scene's joints (build a new one with each scene). */
export class JointLines {
  private readonly links: Link[] = [];
  private readonly geometry = new THREE.BufferGeometry();
  private positions = new Float32Array(0);
  private readonly dots: THREE.Vector3[] = [];
  private readonly p = new THREE.Vector3();

  constructor(private readonly scene: THREE.Scene) {}

  /** Shows `joint` (anchors as given to its constructor; null anchors are the bodies' centres). */
  add<J extends Joint>(joint: J, localA: readonly number[] | null, localB: readonly number[] | null): J {
    const link: Link = {
      joint,
      a: joint.a,
      localA: v(localA ?? [0, 0, 0]),
      b: joint.b,
      localB: v(localB ?? [0, 0, 0]),
      gone: false,
    };
    joint.addEventListener('broken', () => (link.gone = true));
    this.links.push(link);
    if (joint.b === null) this.dots.push(link.localB.clone());
    return joint;
  }

  /** Makes the line and dot objects; call once after the last `add`. */
  finish(): void {
    this.positions = new Float32Array(this.links.length * 6);
    this.geometry.setAttribute('position', new THREE.BufferAttribute(this.positions, 3));
    const lines = new THREE.LineSegments(this.geometry, new THREE.LineBasicMaterial({ color: 0x1d2630 }));
    lines.frustumCulled = false;
    this.scene.add(lines);
    const dot = new THREE.SphereGeometry(0.07, 12, 8);
    const ink = new THREE.MeshBasicMaterial({ color: 0x1d2630 });
    for (const at of this.dots) {
      const mark = new THREE.Mesh(dot, ink);
      mark.position.copy(at);
      this.scene.add(mark);
    }
    this.update();
  }

  /** Moves every segment to where its bodies are now. */
  update(): void {
    const out = this.positions;
    this.links.forEach((link, i) => {
      if (link.gone) {
        out.fill(0, 6 * i, 6 * i + 6);
        return;
      }
      link.a.updateMatrixWorld();
      link.a.localToWorld(this.p.copy(link.localA)).toArray(out, 6 * i);
      if (link.b === null) this.p.copy(link.localB);
      else {
        link.b.updateMatrixWorld();
        link.b.localToWorld(this.p.copy(link.localB));
      }
      this.p.toArray(out, 6 * i + 3);
    });
    const attribute = this.geometry.getAttribute('position') as THREE.BufferAttribute | undefined;
    if (attribute) attribute.needsUpdate = true;
  }
}
