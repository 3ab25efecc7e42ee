import { checkFinite, checkPoints, checkTuples, isNumberList } from './checks.js';

/** Options of the vertex merge of a triangle list. */
export interface TriangleMergeOptions {
  /**
   * Positions closer than this (m, >= 0) become one vertex. 0 (the default) merges only
   * positions that are exactly equal.
   */
  readonly mergeTolerance?: number;
}

/** A triangle list after merging repeated positions. */
export interface MergedTriangles {
  /** Distinct positions, flat (x, y, z). */
  readonly vertices: Float64Array;
  readonly vertexCount: number;
  /** Three merged-vertex indices per triangle; collapsed triangles are left out. */
  readonly triangles: Int32Array;
  /** For each merged vertex, the first input position it came from (for messages). */
  readonly firstSource: Int32Array;
  /** For each kept triangle, its index in the input (for messages). */
  readonly triangleSource: Int32Array;
}

/**
 * Merges the repeated vertices of a 3D triangle list (three.js repeats a corner once per
 * normal or uv), drops the triangles that collapse (two corners merged into one) and the
 * positions no remaining triangle uses.
 *
 * With `mergeTolerance` > 0, a position joins the first earlier vertex within that distance
 * (found through a grid of cells of that size, so the cost stays linear).
 *
 * @param where - the public function, for messages.
 * @param positions - flat (x, y, z per vertex) or number[][].
 * @param indices - three indices per triangle (flat or nested), or undefined/null for
 *   consecutive triples of positions.
 */
export function mergeTriangles(
  where: string,
  positions: unknown,
  indices: unknown,
  options: TriangleMergeOptions,
): MergedTriangles {
  const p = checkPoints(where, positions, 'positions', 3);
  const count = p.length / 3;
  let corners: Int32Array;
  if (indices === undefined || indices === null) {
    if (count % 3 !== 0) {
      throw new TypeError(
        `${where}: without 'indices', 'positions' must hold a multiple of 3 points (whole triangles), got ${count}`,
      );
    }
    corners = new Int32Array(count);
    for (let i = 0; i < count; i += 1) corners[i] = i;
  } else {
    if (!Array.isArray(indices) && !isNumberList(indices)) {
      throw new TypeError(`${where}: argument 'indices' must be an array of indices, null or undefined`);
    }
    corners = checkTuples(where, indices, 'indices', 3, count, true);
  }
  const tol = options.mergeTolerance === undefined ? 0 : checkFinite(where, options.mergeTolerance, 'options.mergeTolerance');
  if (tol < 0) throw new RangeError(`${where}: argument 'options.mergeTolerance' must be >= 0, got ${tol}`);

  const remap = new Int32Array(count);
  const kept: number[] = [];
  const firstSource: number[] = [];
  const cells = new Map<string, number[]>();
  const cellOf = (x: number): number => Math.floor(x / tol);
  for (let i = 0; i < count; i += 1) {
    const x = p[3 * i];
    const y = p[3 * i + 1];
    const z = p[3 * i + 2];
    let found = -1;
    if (tol === 0) {
      const key = `${x},${y},${z}`; // String(-0) is "0": ±0 merge
      const list = cells.get(key);
      if (list) found = list[0];
      else cells.set(key, [firstSource.length]);
    } else {
      const cx = cellOf(x);
      const cy = cellOf(y);
      const cz = cellOf(z);
      search: for (let dx = -1; dx <= 1; dx += 1) {
        for (let dy = -1; dy <= 1; dy += 1) {
          for (let dz = -1; dz <= 1; dz += 1) {
            const list = cells.get(`${cx + dx},${cy + dy},${cz + dz}`);
            if (!list) continue;
            for (const v of list) {
              if (Math.hypot(kept[3 * v] - x, kept[3 * v + 1] - y, kept[3 * v + 2] - z) <= tol) {
                found = v;
                break search;
              }
            }
          }
        }
      }
      if (found < 0) {
        const key = `${cx},${cy},${cz}`;
        const list = cells.get(key);
        if (list) list.push(firstSource.length);
        else cells.set(key, [firstSource.length]);
      }
    }
    if (found < 0) {
      found = firstSource.length;
      firstSource.push(i);
      kept.push(x, y, z);
    }
    remap[i] = found;
  }

  const triangles: number[] = [];
  const triangleSource: number[] = [];
  for (let t = 0; t < corners.length / 3; t += 1) {
    const a = remap[corners[3 * t]];
    const b = remap[corners[3 * t + 1]];
    const c = remap[corners[3 * t + 2]];
    if (a === b || b === c || a === c) continue;
    triangles.push(a, b, c);
    triangleSource.push(t);
  }
  // positions used only by collapsed triangles (or by none) are not part of the surface
  const renumber = new Int32Array(firstSource.length).fill(-1);
  const vertices: number[] = [];
  const source: number[] = [];
  for (let i = 0; i < triangles.length; i += 1) {
    const v = triangles[i];
    if (renumber[v] < 0) {
      renumber[v] = source.length;
      source.push(firstSource[v]);
      vertices.push(kept[3 * v], kept[3 * v + 1], kept[3 * v + 2]);
    }
    triangles[i] = renumber[v];
  }
  return {
    vertices: Float64Array.from(vertices),
    vertexCount: source.length,
    triangles: Int32Array.from(triangles),
    firstSource: Int32Array.from(source),
    triangleSource: Int32Array.from(triangleSource),
  };
}
