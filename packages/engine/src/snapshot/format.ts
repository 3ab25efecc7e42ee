/**
 * The frame of a world snapshot: a fixed 16-byte header, then the payload.
 *
 * ```
 * offset  size  field
 * 0       4     magic, the ASCII bytes 'PNWS' (PhysiN World Snapshot)
 * 4       4     format version (u32, little-endian): SNAPSHOT_VERSION
 * 8       4     total length of the snapshot in bytes, header included (u32)
 * 12      4     checksum (u32) of the payload, bytes [16, length): see fnv1a
 * 16      ...   payload (see docs/engine.md, "Snapshots")
 * ```
 *
 * Why a checksum: a buffer cut short, padded, or damaged in transit must fail with a clear
 * message at `restoreWorld`, not rebuild a world that quietly differs from the one saved.
 *
 * @module
 */

/** The four magic bytes 'PNWS'. */
export const SNAPSHOT_MAGIC = Object.freeze([0x50, 0x4e, 0x57, 0x53]);
/**
 * The format version. Raise it whenever the payload changes meaning or layout; a reader accepts
 * only its own version (a snapshot is for moving a running world, not for archiving).
 */
export const SNAPSHOT_VERSION = 3;
/** Bytes of the header before the payload. */
export const SNAPSHOT_HEADER_BYTES = 16;

const LITTLE_ENDIAN = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;

/**
 * The checksum of bytes[from, to): FNV-1a (32 bits) over the little-endian 32-bit words of the
 * range (a last partial word padded with zeros). Words rather than bytes: a quarter of the steps,
 * so the checksum of a 2 MB snapshot costs well under a millisecond. `from` must be a multiple
 * of 4 from the start of the snapshot.
 */
export function fnv1a(bytes: Uint8Array, from: number, to: number): number {
  let h = 0x811c9dc5;
  const words = (to - from) >> 2;
  const start = bytes.byteOffset + from;
  if (LITTLE_ENDIAN && (start & 3) === 0) {
    const w = new Uint32Array(bytes.buffer, start, words);
    for (let i = 0; i < words; i += 1) h = Math.imul(h ^ w[i]!, 0x01000193);
  } else {
    const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
    for (let i = 0; i < words; i += 1) h = Math.imul(h ^ view.getUint32(from + 4 * i, true), 0x01000193);
  }
  let tail = 0;
  for (let i = from + 4 * words, shift = 0; i < to; i += 1, shift += 8) tail |= bytes[i]! << shift;
  if (to - from > 4 * words) h = Math.imul(h ^ tail, 0x01000193);
  return h >>> 0;
}
