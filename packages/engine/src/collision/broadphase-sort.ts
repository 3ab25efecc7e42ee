/**
 * In-place sorts for the broadphase: no allocation, no recursion, so the per-step update can
 * sort its pair keys and proxy lists without touching the heap. Unchecked hot-path kernels.
 */

/** Sorts keys[0 .. count) ascending in place (heapsort: O(count log count), not stable). */
export function sortKeys(keys: Float64Array, count: number): void {
  for (let start = (count >> 1) - 1; start >= 0; start -= 1) siftDown(keys, start, count);
  for (let end = count - 1; end > 0; end -= 1) {
    const top = keys[0]!;
    keys[0] = keys[end]!;
    keys[end] = top;
    siftDown(keys, 0, end);
  }
}

function siftDown(keys: Float64Array, start: number, end: number): void {
  let root = start;
  const value = keys[root]!;
  for (;;) {
    let child = 2 * root + 1;
    if (child >= end) break;
    if (child + 1 < end && keys[child + 1]! > keys[child]!) child += 1;
    if (keys[child]! <= value) break;
    keys[root] = keys[child]!;
    root = child;
  }
  keys[root] = value;
}

/**
 * Sorts ids[0 .. count) by `key(id) = values[id * stride + offset]` ascending, ties by id, so the
 * order is a pure function of the data. Insertion sort: O(count + inversions), the right cost
 * for a list that was sorted last step and moved a little.
 */
export function insertionSortIdsByKey(
  ids: Int32Array,
  count: number,
  values: Float64Array,
  stride: number,
  offset: number,
): void {
  for (let i = 1; i < count; i += 1) {
    const id = ids[i]!;
    const v = values[id * stride + offset]!;
    let j = i - 1;
    while (j >= 0) {
      const o = ids[j]!;
      const w = values[o * stride + offset]!;
      if (w < v || (w === v && o < id)) break;
      ids[j + 1] = o;
      j -= 1;
    }
    ids[j + 1] = id;
  }
}

/** As {@link insertionSortIdsByKey} but O(count log count) whatever the input order (heapsort). */
export function heapSortIdsByKey(ids: Int32Array, count: number, values: Float64Array, stride: number, offset: number): void {
  for (let start = (count >> 1) - 1; start >= 0; start -= 1) {
    siftDownIds(ids, start, count, values, stride, offset);
  }
  for (let end = count - 1; end > 0; end -= 1) {
    const top = ids[0]!;
    ids[0] = ids[end]!;
    ids[end] = top;
    siftDownIds(ids, 0, end, values, stride, offset);
  }
}

function siftDownIds(ids: Int32Array, start: number, end: number, values: Float64Array, stride: number, offset: number): void {
  let root = start;
  const id = ids[root]!;
  const v = values[id * stride + offset]!;
  for (;;) {
    let child = 2 * root + 1;
    if (child >= end) break;
    if (child + 1 < end) {
      const a = ids[child]!;
      const b = ids[child + 1]!;
      const va = values[a * stride + offset]!;
      const vb = values[b * stride + offset]!;
      if (vb > va || (vb === va && b > a)) child += 1;
    }
    const c = ids[child]!;
    const vc = values[c * stride + offset]!;
    if (vc < v || (vc === v && c < id)) break;
    ids[root] = c;
    root = child;
  }
  ids[root] = id;
}
