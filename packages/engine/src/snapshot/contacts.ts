/**
 * The contacts in a snapshot: the warm-start state of every pair the broadphase holds, and the
 * end events recorded for the next step.
 *
 * Per pair, in the set's order (ascending pair key, the order the narrowphase, the solver, the
 * events and the islands visit them): the key, the two bodies, the touching flags, the mixed
 * friction and restitution, the manifold (normal, points, separations, feature ids — the next
 * narrowphase matches its new points against these), the accumulated normal impulse and the
 * approach speed of each point, the friction patch's impulses (a world vector and a world
 * bivector), and the box–box manifold cache (the relative pose it was computed at, the normal and
 * the surface points in the bodies' frames) that decides whether the next sub-step reuses it.
 *
 * Slot numbers are not saved: nothing computed depends on them (every pass walks `order`), and a
 * restored set hands out slots 0, 1, 2, … in order. The values past a manifold's point count are
 * not saved either, nor, for a pair whose manifold is empty (most broadphase pairs: fattened boxes
 * that overlap while the bodies do not touch), its normal, friction patch and cache: nothing
 * reads them before they are written (a manifold that gains points with none carried over clears
 * its patch; an empty manifold is never cached). A restored set holds zeros there.
 *
 * @module
 */
import type { Dims } from '@physin/algebra';
import type { Body } from '../body.js';
import type { ContactEvents } from '../contacts/contact-events.js';
import { PAIR_KEY_SCALE } from '../contacts/contact-set.js';
import type { ContactSet } from '../contacts/contact-set.js';
import type { SnapshotReader } from './reader.js';
import type { SnapshotWriter } from './writer.js';

/** Writes every contact of the set (see the module); `indexOf` gives a body's world index. */
export function writeContacts(w: SnapshotWriter, D: Dims, set: ContactSet, indexOf: (body: Body) => number): void {
  const { n, k } = D;
  const P = set.pointCapacity;
  const cache = set.manifoldCache;
  w.u32(set.count);
  for (let i = 0; i < set.count; i += 1) {
    const slot = set.order[i]!;
    const m = set.manifolds[slot]!;
    const c = m.count;
    w.f64(set.keys[slot]!);
    w.u32(indexOf(set.bodyA[slot]!));
    w.u32(indexOf(set.bodyB[slot]!));
    w.u8(set.flags[slot]!);
    w.f64(set.friction[slot]!);
    w.f64(set.restitution[slot]!);
    w.u32(c);
    if (c === 0) continue; // an empty manifold: nothing else of the pair is read before it is written
    w.f64s(m.normal, 0, n);
    w.f64s(m.points, 0, c * n);
    w.f64s(m.separations, 0, c);
    w.u32s(m.ids, 0, c);
    w.f64s(set.normalImpulse, slot * P, c);
    w.f64s(set.approachSpeed, slot * P, c);
    w.f64s(set.patchTangent, slot * n, n);
    w.f64s(set.patchTwist, slot * k, k);
    const valid = cache.isValid(slot);
    w.bool(valid);
    if (valid) {
      const v = cache.slotViews(slot);
      w.f64s(v.pose);
      w.f64s(v.normal);
      w.f64s(v.local, 0, c * 2 * n);
    }
  }
}

/** Reads the contacts written by {@link writeContacts} into `set` (an empty set). */
export function readContacts(r: SnapshotReader, D: Dims, set: ContactSet, bodies: readonly Body[]): void {
  const { n, k } = D;
  const P = set.pointCapacity;
  const count = r.count('the contact count', 1 << 26, 37);
  set.takeSlots(count);
  const cache = set.manifoldCache;
  let lastKey = -1;
  for (let i = 0; i < count; i += 1) {
    const slot = set.order[i]!;
    const key = r.f64();
    const ai = r.u32();
    const bi = r.u32();
    if (ai >= bodies.length || bi >= bodies.length) r.fail(`a contact names body ${ai} or ${bi} of ${bodies.length}`);
    const A = bodies[ai]!;
    const B = bodies[bi]!;
    // The key names the two proxies (a compound body has one per part): they must be A's and B's.
    const pa = Math.floor(key / PAIR_KEY_SCALE);
    const pb = key - pa * PAIR_KEY_SCALE;
    const owners = set.proxies.body;
    if (!(key > lastKey) || !(pa < pb) || owners[pa] !== A || owners[pb] !== B || A === B) {
      r.fail(`a contact's pair key ${key} does not match its bodies' proxies`);
    }
    lastKey = key;
    set.keys[slot] = key;
    set.bodyA[slot] = A;
    set.bodyB[slot] = B;
    set.setSlotProxies(slot, pa, pb);
    set.flags[slot] = r.u8();
    set.friction[slot] = r.f64();
    set.restitution[slot] = r.f64();
    const m = set.manifolds[slot]!;
    const c = r.count('a manifold point count', P);
    m.count = c;
    if (c === 0) continue;
    r.f64s(n, m.normal);
    r.f64s(c * n, m.points);
    r.f64s(c, m.separations);
    r.u32s(c, m.ids);
    r.f64s(c, set.normalImpulse, slot * P);
    r.f64s(c, set.approachSpeed, slot * P);
    r.f64s(n, set.patchTangent, slot * n);
    r.f64s(k, set.patchTwist, slot * k);
    if (r.bool()) {
      const v = cache.slotViews(slot);
      r.f64s(v.pose.length, v.pose);
      r.f64s(n, v.normal);
      r.f64s(c * 2 * n, v.local);
      cache.markValid(slot);
    }
  }
}

/**
 * Writes the end events pending for the next step. A side is a world index (>= 0) or, for a body
 * that has left the world, −1 − its index in the snapshot's list of departed bodies.
 */
export function writePendingEnds(w: SnapshotWriter, events: ContactEvents, refOf: (body: Body) => number): void {
  const p = events.pendingEnds();
  w.u32(p.count);
  for (let i = 0; i < p.count; i += 1) {
    w.i32(refOf(p.a[i]!));
    w.i32(refOf(p.b[i]!));
    w.i32(p.partA[i]!);
    w.i32(p.partB[i]!);
  }
}

/** Reads the pending end events written by {@link writePendingEnds} into `events`. */
export function readPendingEnds(
  r: SnapshotReader,
  events: ContactEvents,
  bodies: readonly Body[],
  departed: readonly Body[],
): void {
  const count = r.count('the pending end event count', 1 << 26, 16);
  const pick = (ref: number): Body => {
    const body = ref >= 0 ? bodies[ref] : departed[-1 - ref];
    if (body === undefined) return r.fail(`a pending end event names the unknown body reference ${ref}`);
    return body;
  };
  for (let i = 0; i < count; i += 1) {
    const A = pick(r.i32());
    const B = pick(r.i32());
    const partA = r.i32();
    const partB = r.i32();
    if (partA < 0 || partB < 0) r.fail(`a pending end event names the part ${Math.min(partA, partB)}`);
    events.pushEndLater(A, B, partA, partB);
  }
}
