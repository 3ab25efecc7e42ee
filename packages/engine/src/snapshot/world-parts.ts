/**
 * The private parts of a World that its snapshot reads and a restore rebuilds ({@link worldParts}:
 * a function, not a World method, so that the snapshot code lives here and a world without
 * snapshots does not carry it).
 *
 * @module
 */
import type { Body } from '../body.js';
import type { BroadphaseBase } from '../collision/broadphase-base.js';
import { createPose } from '../collision/manifold.js';
import type { Pose } from '../collision/manifold.js';
import type { ProxyTables } from '../contacts/contact-set.js';
import type { CompoundShape } from '../shapes/compound.js';
import type { AwakeSet } from '../solver/islands.js';
import type { WorldBase } from '../world.js';
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

/** What {@link worldParts} reads of a world (its private parts). */
interface WorldPrivate {
  readonly n: number;
  readonly clock: Float64Array;
  readonly reach: Float64Array;
  boundsStale: boolean;
  readonly broadphase: BroadphaseBase;
  readonly bodyOfProxy: (Body | null)[];
  readonly partProxies: (Int32Array | null)[];
  readonly proxyTables: ProxyTables;
  readonly contacts: ContactSet;
  readonly events: ContactEvents;
  readonly awake: AwakeSet;
  compact(): void;
  setBodyProxies(body: Body, ids: Int32Array | null, poses: Pose[] | null): void;
}

/** @internal The private parts of `world` that the snapshot code reads and restores. */
export function worldParts(world: WorldBase): WorldParts {
  const w = world as unknown as WorldPrivate;
  w.compact();
  // A restore sets the bodies' sleep flags and poses itself: the awake set is rebuilt after it.
  w.awake.stale = true;
  return {
    clock: w.clock,
    reach: w.reach,
    boundsStale: w.boundsStale,
    broadphase: w.broadphase,
    bodyOfProxy: w.bodyOfProxy,
    partProxies: w.partProxies,
    setBodyProxies: (body: Body, ids: Int32Array | null): void => {
      const compound = ids === null ? null : (body.shape as unknown as CompoundShape);
      const poses: Pose[] | null = compound === null ? null : [];
      if (compound !== null) {
        for (let i = 0; i < compound.partCount; i += 1) {
          const pose = createPose(w.n);
          compound.worldOps.partPose(w.n, body.pose!, compound, i, pose);
          poses!.push(pose);
        }
      }
      w.setBodyProxies(body, ids, poses);
    },
    clearProxyTables: (): void => {
      w.bodyOfProxy.length = 0;
      w.partProxies.length = 0;
      w.proxyTables.shape.length = 0;
      w.proxyTables.pose.length = 0;
      w.proxyTables.part.length = 0;
    },
    contacts: w.contacts,
    events: w.events,
    setBoundsStale: (stale: boolean): void => {
      w.boundsStale = stale;
    },
  };
}
