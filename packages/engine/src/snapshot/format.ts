/**
 * The frame of a world snapshot: a fixed 16-byte header, then the payload.
 *
 * ```
 * offset  size  field
 * 0       4     magic, the ASCII bytes 'PNWS' (PhysiN World Snapshot)
 * 4       4     format version (u32, little-endian): SNAPSHOT_VERSION
 * 8       4     total length of the snapshot in bytes, header included (u32)
 * 12      4     FNV-1a checksum (u32) of the payload, bytes [16, length)
 * 16      ...   payload (see docs/engine.md, "Snapshots")
 * ```
 *
 * Why a checksum: a buffer cut short, padded, or damaged in transit must fail with a clear
 * message at `World.restore`, not rebuild a world that quietly differs from the one saved.
 *
 * @module
 */

/** The four magic bytes 'PNWS'. */
export const SNAPSHOT_MAGIC = Object.freeze([0x50, 0x4e, 0x57, 0x53]);
/**
 * The format version. Raise it whenever the payload changes meaning or layout; a reader accepts
 * only its own version (a snapshot is for moving a running world, not for archiving).
 */
export const SNAPSHOT_VERSION = 1;
/** Bytes of the header before the payload. */
export const SNAPSHOT_HEADER_BYTES = 16;

/** FNV-1a (32 bits) of bytes[from, to): cheap, and any single changed byte changes it. */
export function fnv1a(bytes: Uint8Array, from: number, to: number): number {
  let h = 0x811c9dc5;
  for (let i = from; i < to; i += 1) {
    h ^= bytes[i]!;
    h = Math.imul(h, 0x01000193);
  }
  return h >>> 0;
}
