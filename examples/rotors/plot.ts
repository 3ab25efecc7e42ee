/**
 * The rotors page's log plot: the last steps of the defect and orthonormality histories on a
 * 2D canvas, from 10^LOG_FLOOR (rounding level) up to 1, with the correction tolerance dashed.
 */
import { LOG_FLOOR, log10Floor } from './history.js';
import type { LogHistory } from './history.js';

/** Colour of each series of the history, in order (4D defect, 4D orthonormality error, 3D defect). */
export const SERIES_COLORS: readonly string[] = ['#ffa040', '#ff5c8a', '#4ad8c8'];

const TOP = 0;
const GRID = 'rgba(255,255,255,0.10)';
const LABEL = 'rgba(220,226,236,0.75)';
const MARGIN_LEFT = 44;
const MARGIN_RIGHT = 8;
const MARGIN_Y = 8;

/** Draws the log plot of a history onto a 2D canvas sized by CSS. */
export class LogPlot {
  private readonly canvas: HTMLCanvasElement;
  private readonly ctx: CanvasRenderingContext2D;
  private readonly dash: number[] = [5, 4];
  private readonly solid: number[] = [];
  // Grid lines every 4 decades, labels made once.
  private readonly gridExponents: readonly number[] = [0, -4, -8, -12, -16];
  private readonly gridLabels: readonly string[] = ['1', '1e-4', '1e-8', '1e-12', '1e-16'];

  constructor(canvas: HTMLCanvasElement) {
    const ctx = canvas.getContext('2d');
    if (!ctx) throw new Error('LogPlot: this browser gives no 2D canvas context');
    this.canvas = canvas;
    this.ctx = ctx;
    this.resize();
  }

  /** Matches the canvas's pixel size to its CSS size and the device pixel ratio. */
  resize(): void {
    const dpr = window.devicePixelRatio || 1;
    this.canvas.width = Math.max(1, Math.round(this.canvas.clientWidth * dpr));
    this.canvas.height = Math.max(1, Math.round(this.canvas.clientHeight * dpr));
    this.ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  }

  /**
   * Draws every series of `history` (log10 values, oldest on the left) over a fixed x range of
   * `history.capacity` steps, and the tolerance as a dashed line (null: none).
   */
  draw(history: LogHistory, tolerance: number | null): void {
    const { ctx } = this;
    const w = this.canvas.clientWidth;
    const h = this.canvas.clientHeight;
    ctx.clearRect(0, 0, w, h);
    const plotW = w - MARGIN_LEFT - MARGIN_RIGHT;
    const plotH = h - 2 * MARGIN_Y;
    const y = (log: number): number => MARGIN_Y + ((TOP - log) / (TOP - LOG_FLOOR)) * plotH;

    ctx.lineWidth = 1;
    ctx.font = '11px system-ui, sans-serif';
    ctx.textAlign = 'right';
    ctx.textBaseline = 'middle';
    for (let g = 0; g < this.gridExponents.length; g += 1) {
      const e = this.gridExponents[g]!;
      const yy = Math.round(y(e)) + 0.5;
      ctx.strokeStyle = GRID;
      ctx.beginPath();
      ctx.moveTo(MARGIN_LEFT, yy);
      ctx.lineTo(w - MARGIN_RIGHT, yy);
      ctx.stroke();
      ctx.fillStyle = LABEL;
      ctx.fillText(this.gridLabels[g]!, MARGIN_LEFT - 6, yy);
    }

    if (tolerance !== null) {
      const yy = y(log10Floor(tolerance));
      ctx.setLineDash(this.dash);
      ctx.strokeStyle = 'rgba(255,255,255,0.55)';
      ctx.beginPath();
      ctx.moveTo(MARGIN_LEFT, yy);
      ctx.lineTo(w - MARGIN_RIGHT, yy);
      ctx.stroke();
      ctx.setLineDash(this.solid);
    }

    const n = history.length;
    const dx = plotW / (history.capacity - 1);
    ctx.lineWidth = 1.5;
    for (let s = history.series - 1; s >= 0; s -= 1) {
      ctx.strokeStyle = SERIES_COLORS[s] ?? '#ffffff';
      ctx.beginPath();
      for (let i = 0; i < n; i += 1) {
        const xx = MARGIN_LEFT + i * dx;
        const yy = y(history.get(i, s));
        if (i === 0) ctx.moveTo(xx, yy);
        else ctx.lineTo(xx, yy);
      }
      ctx.stroke();
    }
  }
}
