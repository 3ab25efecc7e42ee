/**
 * The three.js side of the rotors page: one canvas split into two viewports, the projected
 * tesseract on the left and the 3D cube on the right, each drawn as line segments plus small
 * spheres at the corners.
 *
 * Every buffer is made once in the constructor; the `set*` methods overwrite them in place and
 * flag them for upload, so a frame allocates nothing.
 */
import {
  AmbientLight,
  AxesHelper,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DynamicDrawUsage,
  InstancedMesh,
  LineBasicMaterial,
  LineSegments,
  Matrix4,
  MeshLambertMaterial,
  PerspectiveCamera,
  Scene,
  SphereGeometry,
  WebGLRenderer,
} from 'three';
import { writeSegments } from './geometry.js';

/** Colours of the w depth cue: corners at w = −wRange get COLD, at +wRange get WARM. */
const COLD = new Color(0x4aa8ff);
const WARM = new Color(0xffa040);
const NEUTRAL = new Color(0xd8dee9);
const GHOST = new Color(0x8090a0);

/** Line segments and corner spheres of one hypercube, with in-place updates. */
class Wireframe {
  readonly lines: LineSegments<BufferGeometry, LineBasicMaterial>;
  readonly corners: InstancedMesh<SphereGeometry, MeshLambertMaterial>;
  private readonly edges: Uint16Array;
  private readonly positions: Float32Array;
  private readonly colors: Float32Array;
  private readonly vertexColors: Float32Array;
  private readonly matrix = new Matrix4();
  private readonly color = new Color();

  constructor(vertexCount: number, edges: Uint16Array, radius: number, opacity = 1) {
    this.edges = edges;
    const m = edges.length >> 1;
    this.positions = new Float32Array(6 * m);
    this.colors = new Float32Array(6 * m);
    this.vertexColors = new Float32Array(3 * vertexCount);
    const geometry = new BufferGeometry();
    const pos = new BufferAttribute(this.positions, 3).setUsage(DynamicDrawUsage);
    const col = new BufferAttribute(this.colors, 3).setUsage(DynamicDrawUsage);
    geometry.setAttribute('position', pos);
    geometry.setAttribute('color', col);
    const material = new LineBasicMaterial({ vertexColors: true, transparent: opacity < 1, opacity });
    this.lines = new LineSegments(geometry, material);
    // The bounding sphere would go stale as the shape moves; these objects are always in view.
    this.lines.frustumCulled = false;
    this.corners = new InstancedMesh(new SphereGeometry(radius, 14, 10), new MeshLambertMaterial(), vertexCount);
    this.corners.instanceMatrix.setUsage(DynamicDrawUsage);
    this.corners.frustumCulled = false;
    for (let v = 0; v < vertexCount; v += 1) this.corners.setColorAt(v, NEUTRAL);
  }

  /**
   * New corner positions (`points3`, 3 per corner), an optional size factor per corner and an
   * optional colour coordinate per corner in [−1, 1] (null: one neutral colour).
   */
  update(points3: Float32Array, sizes: Float32Array | null, tint: Float32Array | null, base: Color = NEUTRAL): void {
    const count = this.corners.count;
    for (let v = 0; v < count; v += 1) {
      const c = this.color;
      if (tint) {
        const t = 0.5 + 0.5 * Math.max(-1, Math.min(1, tint[v]!));
        c.copy(COLD).lerp(WARM, t);
      } else {
        c.copy(base);
      }
      this.vertexColors[3 * v] = c.r;
      this.vertexColors[3 * v + 1] = c.g;
      this.vertexColors[3 * v + 2] = c.b;
      this.corners.setColorAt(v, c);
      const s = sizes ? sizes[v]! : 1;
      this.matrix.makeScale(s, s, s).setPosition(points3[3 * v]!, points3[3 * v + 1]!, points3[3 * v + 2]!);
      this.corners.setMatrixAt(v, this.matrix);
    }
    writeSegments(this.positions, points3, this.edges);
    writeSegments(this.colors, this.vertexColors, this.edges);
    this.lines.geometry.attributes['position']!.needsUpdate = true;
    this.lines.geometry.attributes['color']!.needsUpdate = true;
    this.corners.instanceMatrix.needsUpdate = true;
    if (this.corners.instanceColor) this.corners.instanceColor.needsUpdate = true;
  }

  set visible(on: boolean) {
    this.lines.visible = on;
    this.corners.visible = on;
  }
}

/** A scene, its camera and the rectangle of the canvas it is drawn in (fractions of the width). */
interface Panel {
  scene: Scene;
  camera: PerspectiveCamera;
  left: number;
  width: number;
}

function makePanel(left: number, width: number, eye: readonly [number, number, number]): Panel {
  const scene = new Scene();
  scene.add(new AmbientLight(0xffffff, 1.2));
  const sun = new DirectionalLight(0xffffff, 2);
  sun.position.set(3, 5, 4);
  scene.add(sun);
  // Short x (red), y (green), z (blue) axes for orientation.
  scene.add(new AxesHelper(0.6));
  const camera = new PerspectiveCamera(38, 1, 0.1, 100);
  camera.position.set(eye[0], eye[1], eye[2]);
  camera.lookAt(0, 0, 0);
  return { scene, camera, left, width };
}

/** The page's renderer: the tesseract panel (left half) and the cube panel (right half). */
export class RotorsView {
  readonly renderer: WebGLRenderer;
  private readonly canvas: HTMLCanvasElement;
  private readonly tesseractPanel: Panel;
  private readonly cubePanel: Panel;
  private readonly panels: readonly Panel[];
  private readonly tesseract: Wireframe;
  private readonly ghost: Wireframe;
  private readonly cube: Wireframe;

  /**
   * @param canvas the canvas to draw in (sized by CSS; call `resize` when it changes).
   * @param tesseractEdges edges of the tesseract (16 corners), from `hypercubeEdges(4)`.
   * @param cubeEdges edges of the cube (8 corners), from `hypercubeEdges(3)`.
   */
  constructor(canvas: HTMLCanvasElement, tesseractEdges: Uint16Array, cubeEdges: Uint16Array) {
    this.canvas = canvas;
    this.renderer = new WebGLRenderer({ canvas, antialias: true });
    this.renderer.setClearColor(0x10141c);
    this.renderer.setScissorTest(true);
    this.tesseractPanel = makePanel(0, 0.5, [4.9, 3.5, 7.5]);
    this.cubePanel = makePanel(0.5, 0.5, [3.9, 2.8, 6.0]);
    this.panels = [this.tesseractPanel, this.cubePanel];
    this.ghost = new Wireframe(16, tesseractEdges, 0.001, 0.35);
    this.ghost.corners.visible = false;
    this.tesseract = new Wireframe(16, tesseractEdges, 0.06);
    this.cube = new Wireframe(8, cubeEdges, 0.05);
    this.tesseractPanel.scene.add(this.ghost.lines, this.tesseract.lines, this.tesseract.corners);
    this.cubePanel.scene.add(this.cube.lines, this.cube.corners);
    this.resize();
  }

  /**
   * The projected tesseract: corner positions (3 per corner), the perspective factor of each
   * corner (sizes its sphere) and each corner's w divided by the largest |w| expected (colour).
   */
  setTesseract(points3: Float32Array, scales: Float32Array, wTint: Float32Array): void {
    this.tesseract.update(points3, scales, wTint);
  }

  /** The faint outline of the nearest true rotation, or null to hide it. */
  setGhost(points3: Float32Array | null): void {
    this.ghost.visible = points3 !== null;
    if (points3) {
      this.ghost.update(points3, null, null, GHOST);
      this.ghost.corners.visible = false;
    }
  }

  /** The cube's corners (3 per corner). */
  setCube(points3: Float32Array): void {
    this.cube.update(points3, null, null);
  }

  /** Matches the drawing buffer to the canvas's CSS size and the device pixel ratio. */
  resize(): void {
    const w = Math.max(1, this.canvas.clientWidth);
    const h = Math.max(1, this.canvas.clientHeight);
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(w, h, false);
  }

  /** Draws both panels. */
  render(): void {
    const w = this.canvas.clientWidth;
    const h = this.canvas.clientHeight;
    for (const p of this.panels) {
      const x = Math.round(p.left * w);
      const pw = Math.round(p.width * w);
      this.renderer.setViewport(x, 0, pw, h);
      this.renderer.setScissor(x, 0, pw, h);
      p.camera.aspect = pw / Math.max(1, h);
      p.camera.updateProjectionMatrix();
      this.renderer.render(p.scene, p.camera);
    }
  }
}
