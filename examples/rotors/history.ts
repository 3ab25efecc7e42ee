/**
 * A fixed-size ring buffer of log10 samples for the page's plot: one row per simulation step,
 * one column per series (the 4D defect, the 4D orthonormality error, the 3D defect).
 *
 * Pure (no DOM). `push` allocates nothing.
 */

/** Exact zeros (a defect can be exactly 0) are plotted at this floor instead of −∞. */
export const LOG_FLOOR = -17;

/** log10 of x, with 0 (and anything below 10^LOG_FLOOR) sent to LOG_FLOOR. */
export function log10Floor(x: number): number {
  return x > 0 ? Math.max(LOG_FLOOR, Math.log10(x)) : LOG_FLOOR;
}

/** The last `capacity` rows of `series` (1 to 3) numbers each, stored as log10 values. */
export class LogHistory {
  /** Numbers per row. */
  readonly series: number;
  /** Rows kept; older ones are overwritten. */
  readonly capacity: number;
  private readonly data: Float64Array;
  private head = 0;
  private filled = 0;

  constructor(series: number, capacity: number) {
    if (!Number.isInteger(series) || series < 1 || series > 3)
      throw new RangeError(`LogHistory: argument 'series' must be 1, 2 or 3, got ${series}`);
    if (!Number.isInteger(capacity) || capacity < 2)
      throw new RangeError(`LogHistory: argument 'capacity' must be an integer >= 2, got ${capacity}`);
    this.series = series;
    this.capacity = capacity;
    this.data = new Float64Array(series * capacity);
  }

  /** Rows currently held (at most `capacity`). */
  get length(): number {
    return this.filled;
  }

  /** Appends a row: log10 of each value (`log10Floor`). Missing trailing values count as 0. */
  push(a: number, b = 0, c = 0): void {
    const o = this.head * this.series;
    this.data[o] = log10Floor(a);
    if (this.series > 1) this.data[o + 1] = log10Floor(b);
    if (this.series > 2) this.data[o + 2] = log10Floor(c);
    this.head = (this.head + 1) % this.capacity;
    if (this.filled < this.capacity) this.filled += 1;
  }

  /** The log10 value of series `s` in row `i`, counting from the oldest row held (i = 0). */
  get(i: number, s: number): number {
    const row = (this.head - this.filled + i + this.capacity) % this.capacity;
    return this.data[row * this.series + s]!;
  }

  /** Forgets every row. */
  clear(): void {
    this.head = 0;
    this.filled = 0;
  }
}
