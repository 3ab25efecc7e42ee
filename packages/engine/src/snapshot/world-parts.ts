/**
 * The private parts of a World that its snapshot reads and a restore rebuilds (handed over by
 * the @internal `World.snapshotParts()`, so the snapshot code lives here and world.ts stays small).
 *
 * @module
 */
import type { Body } from '../body.js';
import type { BroadphaseBase } from '../collision/broadphase-base.js';
import type { ContactEvents } from '../contacts/contact-events.js';
import type { ContactSet } from '../contacts/contact-set.js';

/** @internal See the module. */
export interface WorldParts {
  /** [simulated time (s), completed steps]. */
  readonly clock: Float64Array;
  /** Per body (world index): the reach of the last sub-step (m). */
  readonly reach: Float64Array;
  /** Whether the broadphase boxes lag the poses (a query refreshes them first). */
  readonly boundsStale: boolean;
  readonly broadphase: BroadphaseBase;
  /** Body of each broadphase proxy id (null for a free id). */
  readonly bodyOfProxy: (Body | null)[];
  /** Per proxy id of a compound body (its proxyId): the proxy ids of its parts; null otherwise. */
  readonly partProxies: readonly (Int32Array | null)[];
  /** Fills the proxy tables of `body`: its proxyId alone (`ids` null), or one proxy per part. */
  setBodyProxies(body: Body, ids: Int32Array | null): void;
  /** Empties every proxy table (bodyOfProxy too), before a restore fills them. */
  clearProxyTables(): void;
  readonly contacts: ContactSet;
  readonly events: ContactEvents;
  setBoundsStale(stale: boolean): void;
}
