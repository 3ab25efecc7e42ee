/**
 * The byte reader of world snapshots: checks the frame (magic, version, length, checksum) up
 * front, then reads little-endian fields with a bounds check on every read, so a bad buffer
 * fails with an error that names the argument `bytes` and says what is wrong.
 *
 * @module
 */
import { fnv1a, SNAPSHOT_HEADER_BYTES, SNAPSHOT_MAGIC, SNAPSHOT_VERSION } from './format.js';

const decoder = new TextDecoder('utf-8', { fatal: true });
const FN = 'restoreWorld';

/** Reads the fields of a snapshot written by SnapshotWriter, in the same order. */
export class SnapshotReader {
  private readonly bytes: Uint8Array;
  private readonly view: DataView;
  private at = SNAPSHOT_HEADER_BYTES;

  /**
   * @throws TypeError if `bytes` is not a Uint8Array; RangeError if it is shorter than its
   *   header or than the length the header gives, longer, foreign (no magic), of another format
   *   version, or damaged (checksum).
   */
  constructor(bytes: unknown) {
    if (!(bytes instanceof Uint8Array)) {
      const got =
        bytes === null ? 'null' : typeof bytes === 'object' ? ((bytes as object).constructor?.name ?? 'object') : typeof bytes;
      throw new TypeError(`${FN}: argument 'bytes' must be a Uint8Array (from snapshotWorld(world)), got ${got}`);
    }
    if (bytes.length < SNAPSHOT_HEADER_BYTES) {
      throw new RangeError(
        `${FN}: argument 'bytes' is truncated: ${bytes.length} bytes, shorter than the ${SNAPSHOT_HEADER_BYTES}-byte snapshot header`,
      );
    }
    for (let i = 0; i < 4; i += 1) {
      if (bytes[i] !== SNAPSHOT_MAGIC[i]) {
        throw new RangeError(`${FN}: argument 'bytes' is not a PhysiN world snapshot (its first bytes are not the magic 'PNWS')`);
      }
    }
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    const version = view.getUint32(4, true);
    if (version !== SNAPSHOT_VERSION) {
      throw new RangeError(
        `${FN}: argument 'bytes' is a snapshot of format version ${version}; this build reads version ${SNAPSHOT_VERSION} only`,
      );
    }
    const length = view.getUint32(8, true);
    if (bytes.length < length) {
      throw new RangeError(`${FN}: argument 'bytes' is truncated: ${bytes.length} bytes of a ${length}-byte snapshot`);
    }
    if (bytes.length > length) {
      throw new RangeError(
        `${FN}: argument 'bytes' has ${bytes.length - length} bytes past the end of its ${length}-byte snapshot`,
      );
    }
    const sum = view.getUint32(12, true);
    if (fnv1a(bytes, SNAPSHOT_HEADER_BYTES, length) !== sum) {
      throw new RangeError(`${FN}: argument 'bytes' is damaged: its checksum does not match its contents`);
    }
    this.bytes = bytes;
    this.view = view;
  }

  /** Throws the RangeError of a snapshot whose contents make no sense (`what` says why). */
  fail(what: string): never {
    throw new RangeError(`${FN}: argument 'bytes' is not a valid snapshot: ${what} (at byte ${this.at})`);
  }

  private need(size: number): void {
    if (this.at + size > this.bytes.length) {
      throw new RangeError(
        `${FN}: argument 'bytes' is truncated: a field at byte ${this.at} needs ${size} bytes, ${this.bytes.length - this.at} are left`,
      );
    }
  }

  /** Whether every byte was read (the reader checks this at the end). */
  get done(): boolean {
    return this.at === this.bytes.length;
  }

  u8(): number {
    this.need(1);
    return this.view.getUint8(this.at++);
  }

  bool(): boolean {
    const b = this.u8();
    if (b > 1) this.fail(`a flag byte holds ${b}`);
    return b === 1;
  }

  u32(): number {
    this.need(4);
    const v = this.view.getUint32(this.at, true);
    this.at += 4;
    return v;
  }

  /** Bytes not read yet. */
  get remaining(): number {
    return this.bytes.length - this.at;
  }

  /**
   * A count (u32) that must be <= max, and of items of at least `bytesEach` bytes that the rest
   * of the buffer can hold (so a bad count fails here rather than allocate gigabytes), else fail
   * naming `what`.
   */
  count(what: string, max: number, bytesEach = 0): number {
    const v = this.u32();
    if (v > max) this.fail(`${what} is ${v}, more than ${max}`);
    if (bytesEach > 0 && v * bytesEach > this.remaining) {
      throw new RangeError(
        `${FN}: argument 'bytes' is truncated: ${what} is ${v}, and ${this.remaining} bytes are left for them`,
      );
    }
    return v;
  }

  i32(): number {
    this.need(4);
    const v = this.view.getInt32(this.at, true);
    this.at += 4;
    return v;
  }

  f64(): number {
    this.need(8);
    const v = this.view.getFloat64(this.at, true);
    this.at += 8;
    return v;
  }

  /** Reads `count` doubles into out[from ..] (out defaults to a new array). */
  f64s(count: number, into?: Float64Array, from = 0): Float64Array {
    this.need(8 * count);
    const out = into ?? new Float64Array(count);
    const view = this.view;
    let at = this.at;
    for (let i = 0; i < count; i += 1, at += 8) out[from + i] = view.getFloat64(at, true);
    this.at = at;
    return out;
  }

  i32s(count: number, into?: Int32Array, from = 0): Int32Array {
    this.need(4 * count);
    const out = into ?? new Int32Array(count);
    for (let i = 0; i < count; i += 1) {
      out[from + i] = this.view.getInt32(this.at, true);
      this.at += 4;
    }
    return out;
  }

  u32s(count: number, into?: Uint32Array, from = 0): Uint32Array {
    this.need(4 * count);
    const out = into ?? new Uint32Array(count);
    for (let i = 0; i < count; i += 1) {
      out[from + i] = this.view.getUint32(this.at, true);
      this.at += 4;
    }
    return out;
  }

  u8s(count: number, into?: Uint8Array, from = 0): Uint8Array {
    this.need(count);
    const out = into ?? new Uint8Array(count);
    out.set(this.bytes.subarray(this.at, this.at + count), from);
    this.at += count;
    return out;
  }

  string(): string {
    const length = this.u32();
    this.need(length);
    // A copy: TextDecoder refuses views of a SharedArrayBuffer.
    const b = this.bytes.slice(this.at, this.at + length);
    this.at += length;
    try {
      return decoder.decode(b);
    } catch {
      return this.fail('a string is not valid UTF-8');
    }
  }
}
