/**
 * The byte writer of world snapshots: little-endian numbers appended to a buffer that grows by
 * doubling. Doubles are written as their exact 8 bytes, so every Float64 of the world (NaN
 * payloads and signed zeros included) comes back bit for bit.
 *
 * @module
 */
import { fnv1a, SNAPSHOT_HEADER_BYTES, SNAPSHOT_MAGIC, SNAPSHOT_VERSION } from './format.js';

const encoder = new TextEncoder();

/** Appends the fields of a snapshot; {@link SnapshotWriter.finish} frames them (see format.ts). */
export class SnapshotWriter {
  private bytes: Uint8Array;
  private view: DataView;
  private at = SNAPSHOT_HEADER_BYTES;

  constructor(initialCapacity = 4096) {
    this.bytes = new Uint8Array(Math.max(64, initialCapacity));
    this.view = new DataView(this.bytes.buffer);
  }

  private room(size: number): void {
    if (this.at + size <= this.bytes.length) return;
    let cap = this.bytes.length * 2;
    while (cap < this.at + size) cap *= 2;
    const next = new Uint8Array(cap);
    next.set(this.bytes.subarray(0, this.at));
    this.bytes = next;
    this.view = new DataView(next.buffer);
  }

  /** An unsigned byte (0..255). */
  u8(value: number): void {
    this.room(1);
    this.view.setUint8(this.at, value);
    this.at += 1;
  }

  /** A boolean as one byte (0 or 1). */
  bool(value: boolean): void {
    this.u8(value ? 1 : 0);
  }

  /** An unsigned 32-bit integer. */
  u32(value: number): void {
    this.room(4);
    this.view.setUint32(this.at, value, true);
    this.at += 4;
  }

  /** A signed 32-bit integer. */
  i32(value: number): void {
    this.room(4);
    this.view.setInt32(this.at, value, true);
    this.at += 4;
  }

  /** A double, bit for bit. */
  f64(value: number): void {
    this.room(8);
    this.view.setFloat64(this.at, value, true);
    this.at += 8;
  }

  /** `count` doubles of `a` from `from` (no length prefix: the reader knows the count). */
  f64s(a: ArrayLike<number>, from = 0, count = a.length - from): void {
    this.room(8 * count);
    const view = this.view;
    let at = this.at;
    for (let i = 0; i < count; i += 1, at += 8) view.setFloat64(at, a[from + i]!, true);
    this.at = at;
  }

  /** `count` signed 32-bit integers of `a` from `from`. */
  i32s(a: ArrayLike<number>, from = 0, count = a.length - from): void {
    this.room(4 * count);
    for (let i = 0; i < count; i += 1) {
      this.view.setInt32(this.at, a[from + i]!, true);
      this.at += 4;
    }
  }

  /** `count` unsigned 32-bit integers of `a` from `from`. */
  u32s(a: ArrayLike<number>, from = 0, count = a.length - from): void {
    this.room(4 * count);
    for (let i = 0; i < count; i += 1) {
      this.view.setUint32(this.at, a[from + i]!, true);
      this.at += 4;
    }
  }

  /** `count` bytes of `a` from `from`. */
  u8s(a: ArrayLike<number>, from = 0, count = a.length - from): void {
    this.room(count);
    for (let i = 0; i < count; i += 1) this.bytes[this.at + i] = a[from + i]!;
    this.at += count;
  }

  /** A string: its UTF-8 byte length (u32), then the bytes. */
  string(value: string): void {
    const b = encoder.encode(value);
    this.u32(b.length);
    this.u8s(b);
  }

  /** The snapshot: header (magic, version, length, checksum) and payload, in a buffer of its own size. */
  finish(): Uint8Array {
    const out = this.bytes.slice(0, this.at);
    const view = new DataView(out.buffer);
    for (let i = 0; i < 4; i += 1) out[i] = SNAPSHOT_MAGIC[i]!;
    view.setUint32(4, SNAPSHOT_VERSION, true);
    view.setUint32(8, out.length, true);
    view.setUint32(12, fnv1a(out, SNAPSHOT_HEADER_BYTES, out.length), true);
    return out;
  }
}
