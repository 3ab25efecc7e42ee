/**
 * The ruler of the 4D pages (sandbox, donuts): one band per 4D body over the interval of w it
 * covers, a marker at the flat's w; the flat cuts a body whose band the marker crosses. Dragging
 * it moves the flat.
 */
import { dims, rotorToMatrix } from '@physin/algebra';
import { HyperBoxMesh, HyperSphereMesh, HyperTorusMesh } from '@physin/three';
import type { Mesh, Scene } from '@physin/three';
import type * as THREE from 'three';

/** The w range the ruler shows. */
export const RULER_MIN = -2.5;
export const RULER_MAX = 2.5;

const D4 = dims(4);
const M = new Float64Array(16);

/** The interval of w that a 4D body covers (exact for boxes, balls and tori). */
export function wInterval(mesh: Mesh): [number, number] {
  const x = mesh.getPositionN();
  const w = x[3] ?? 0;
  let reach = 0;
  if (mesh instanceof HyperSphereMesh) reach = mesh.radius;
  else {
    rotorToMatrix(D4, M, mesh.getRotor());
    // row 3 of M: how much each body axis points along w
    if (mesh instanceof HyperBoxMesh) {
      for (let i = 0; i < 4; i += 1) reach += Math.abs(M[12 + i]!) * mesh.halfExtents[i]!;
    } else if (mesh instanceof HyperTorusMesh) {
      const [i, j] = mesh.plane;
      reach = mesh.majorRadius * Math.hypot(M[12 + i]!, M[12 + j]!) + mesh.minorRadius;
    }
  }
  return [w - reach, w + reach];
}

/** The w at a fraction `t` (0..1) of the ruler's width. */
export function rulerValueAt(t: number): number {
  const clamped = Math.min(1, Math.max(0, t));
  return RULER_MIN + clamped * (RULER_MAX - RULER_MIN);
}

/** One band of the ruler. */
export interface RulerRow {
  readonly lo: number;
  readonly hi: number;
  /** The flat cuts the body (its mesh is shown). */
  readonly cut: boolean;
  readonly colour: string;
}

/** Draws the ruler: ticks, one band per body (grey when the flat misses it), the flat's marker. */
export function drawRuler(canvas: HTMLCanvasElement, rows: readonly RulerRow[], sliceW: number): void {
  const ratio = window.devicePixelRatio || 1;
  const width = Math.max(1, Math.floor(canvas.clientWidth * ratio));
  const height = Math.max(1, Math.floor(canvas.clientHeight * ratio));
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  const ctx = canvas.getContext('2d')!;
  ctx.setTransform(ratio, 0, 0, ratio, 0, 0);
  const w = canvas.clientWidth;
  const h = canvas.clientHeight;
  ctx.clearRect(0, 0, w, h);
  const pad = 10;
  const xOf = (value: number): number => pad + ((value - RULER_MIN) / (RULER_MAX - RULER_MIN)) * (w - 2 * pad);
  // ticks every 0.5
  ctx.fillStyle = '#8d98ab';
  ctx.strokeStyle = '#3a4558';
  ctx.font = '10px ui-monospace, monospace';
  ctx.textAlign = 'center';
  for (let v = RULER_MIN; v <= RULER_MAX + 1e-9; v += 0.5) {
    const x = xOf(v);
    ctx.beginPath();
    ctx.moveTo(x, h - 16);
    ctx.lineTo(x, h - 10);
    ctx.stroke();
    if (Math.abs(v - Math.round(v)) < 1e-9) ctx.fillText(`w ${v.toFixed(0)}`, x, h - 1);
  }
  // bands
  const top = 6;
  const band = Math.max(2, Math.min(7, (h - 26 - top) / Math.max(1, rows.length)));
  rows.forEach((row, i) => {
    const y = top + i * band;
    ctx.fillStyle = row.cut ? row.colour : '#4a5264';
    ctx.globalAlpha = row.cut ? 1 : 0.7;
    ctx.fillRect(xOf(row.lo), y, Math.max(1, xOf(row.hi) - xOf(row.lo)), band - 1);
  });
  ctx.globalAlpha = 1;
  // the flat
  const x = xOf(sliceW);
  ctx.strokeStyle = '#ffa040';
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x, 0);
  ctx.lineTo(x, h - 12);
  ctx.stroke();
  ctx.lineWidth = 1;
  ctx.fillStyle = '#ffa040';
  ctx.textAlign = x > w - 70 ? 'right' : 'left';
  ctx.fillText(`sliceW ${sliceW.toFixed(2)}`, x + (x > w - 70 ? -4 : 4), 12);
}

/**
 * Shows the ruler on `canvas` for `bodies` (read at every frame, so bodies added later appear)
 * and lets the user drag the flat: `setW(w)` is called with the new w.
 */
export function mountRuler(canvas: HTMLCanvasElement, scene: Scene, bodies: readonly Mesh[], setW: (w: number) => void): void {
  canvas.hidden = false;
  let dragging = false;
  const move = (event: PointerEvent): void => {
    if (!dragging) return;
    const box = canvas.getBoundingClientRect();
    setW(rulerValueAt((event.clientX - box.left) / box.width));
  };
  canvas.addEventListener('pointerdown', (event) => {
    dragging = true;
    canvas.setPointerCapture(event.pointerId);
    move(event);
  });
  canvas.addEventListener('pointermove', move);
  canvas.addEventListener('pointerup', () => (dragging = false));
  const paint = (): void => {
    requestAnimationFrame(paint);
    const rows = bodies.map((mesh) => {
      const [lo, hi] = wInterval(mesh);
      const material = mesh.material as THREE.MeshStandardMaterial;
      return { lo, hi, cut: mesh.visible, colour: `#${material.color.getHexString()}` };
    });
    drawRuler(canvas, rows, scene.sliceW);
  };
  paint();
}
