/**
 * The awake set, islands and sleep.
 *
 * An island is a set of dynamic bodies linked by touching contacts and joints (static and kinematic bodies
 * do not link: a floor does not join every pile on it into one island). A body's sleep timer
 * counts the seconds it has moved slower than `sleepLinearVelocity` and `sleepAngularVelocity`;
 * an island whose slowest-to-settle body has waited `sleepTime` goes to sleep as a whole (its
 * velocities are zeroed), and an island with one awake, unsettled body wakes as a whole. So a box
 * that lands on a sleeping pile wakes the pile, and nothing else.
 *
 * The step pays for awake bodies alone: the world keeps them in an {@link AwakeSet} (changed on
 * every sleep and wake, O(1) each), and the island pass is a union–find over the awake bodies and
 * the active contacts (those with a moving body) only. A sleeping island is woken as a whole by
 * the world as soon as one of its bodies wakes, by a walk over its touching contacts (O(island)):
 * so an awake island never touches a sleeping body, except where the solver woke one in this
 * sub-step, and the pass below wakes the island of any such body before it builds the islands.
 *
 * Union–find with path halving; arrays grow with the awake set and the pass allocates nothing.
 *
 * @module
 */
import { Body, MOTION_DYNAMIC, MOTION_STATIC } from '../body.js';
import type { ContactSet } from '../contacts/contact-set.js';
import { STEP_H } from '../integrator/step-constants.js';
import type { Params } from '../params.js';
import { CONTACT_SENSOR, CONTACT_TOUCHING, growFloat64, growInt32, isMoving } from '../contacts/contact-set.js';

/**
 * The bodies a step visits: every body that is neither static nor asleep, in ascending world
 * index once {@link AwakeSet.sort} ran (the order the old full passes had, so a step gives the
 * same bits however the set was reached). Adding and removing are O(1); a removal leaves a stale
 * entry that `sort` drops. Also the step's bookkeeping that goes with it: the bodies moved by hand
 * since the last step, and the bodies whose state the step saved (to undo it).
 */
export class AwakeSet {
  /** The awake bodies: list[0 .. count), sorted by world index after `sort()` (stale entries before). */
  list: Body[] = [];
  /** Entries of `list` (stale ones included until `sort()`). */
  count = 0;
  /** Per world index: the body's position in `list` plus one (0: not in the set). */
  private pos = new Int32Array(16);
  /** Whether `list` changed since the last sort. */
  private unsorted = false;
  /** Bodies moved by hand (pose dirty) since the last step: moved[0 .. movedCount). */
  moved: Body[] = [];
  movedCount = 0;
  /** Per world index: 1 while the body is listed in `moved`. */
  private movedMark = new Uint8Array(16);
  /** Bodies whose state this step saved (World.step undoes them on a non-finite state). */
  saved: Body[] = [];
  savedCount = 0;
  /** Per world index: the step serial at which the body's state was saved. */
  private savedAt = new Int32Array(16);
  /** The serial of the current step (`beginStep`). */
  private serial = 0;
  /** True inside World.step: a body that wakes has its state saved first. */
  inStep = false;
  /** True when the set does not match the bodies (a restore set their flags): rebuilt before use. */
  stale = false;
  /** The island walk of a wake: bodies whose contacts are still to visit; `waking` while it runs. */
  pending: Body[] = [];
  waking = false;
  /** Bodies the last sub-step integrated (the awake set's size then). */
  visitedBodies = 0;
  /** Contact pairs the last sub-step's narrowphase visited (those with a moving body). */
  visitedPairs = 0;

  /** Makes room for world indices below `count`. */
  reserve(count: number): void {
    if (count > this.pos.length) {
      this.pos = growInt32(this.pos, count);
      this.savedAt = growInt32(this.savedAt, count);
      const mark = new Uint8Array(this.pos.length);
      mark.set(this.movedMark);
      this.movedMark = mark;
    }
  }

  /** Whether `body` is in the set. */
  has(body: Body): boolean {
    const i = body.worldIndex;
    return i >= 0 && i < this.pos.length && this.pos[i] !== 0;
  }

  /** The body's position in `list` (valid after `sort()`, for a body in the set). */
  positionOf(body: Body): number {
    return this.pos[body.worldIndex] - 1;
  }

  /** Puts `body` in the set if it belongs there (neither static nor asleep), else takes it out. */
  sync(body: Body): boolean {
    const awake = body.motion !== MOTION_STATIC && !body.sleeping;
    const was = this.has(body);
    if (awake === was) return false;
    const i = body.worldIndex;
    if (awake) {
      if (this.count === this.list.length) this.list.push(body);
      else this.list[this.count] = body;
      this.count += 1;
      this.pos[i] = this.count;
    } else this.pos[i] = 0;
    this.unsorted = true;
    return true;
  }

  /** Drops stale entries and sorts the list by world index (heap sort, no allocation). */
  sort(): void {
    if (!this.unsorted) return;
    this.unsorted = false;
    const list = this.list;
    const pos = this.pos;
    let o = 0;
    for (let i = 0; i < this.count; i += 1) {
      const body = list[i];
      const w = body.worldIndex;
      if (w >= 0 && w < pos.length && pos[w] === i + 1) list[o++] = body;
    }
    this.count = o;
    // Bodies join the set in world order as they are added (a world built by addBody appends in
    // order): when the list is already sorted, one pass says so, where the heap sort of 32,000
    // new bodies cost the first step more than everything else it did.
    let sorted = true;
    for (let i = 1; i < o && sorted; i += 1) if (list[i - 1].worldIndex > list[i].worldIndex) sorted = false;
    if (sorted) {
      for (let i = 0; i < o; i += 1) pos[list[i].worldIndex] = i + 1;
      return;
    }
    for (let start = (o >> 1) - 1; start >= 0; start -= 1) siftBody(list, start, o);
    for (let end = o - 1; end > 0; end -= 1) {
      const t = list[0];
      list[0] = list[end];
      list[end] = t;
      siftBody(list, 0, end);
    }
    for (let i = 0; i < o; i += 1) pos[list[i].worldIndex] = i + 1;
  }

  /** Builds the set again from every body of the world (after a renumbering or a restore). O(bodies). */
  rebuild(bodies: readonly Body[]): void {
    this.reserve(bodies.length);
    this.pos.fill(0);
    this.movedMark.fill(0);
    this.count = 0;
    this.movedCount = 0;
    this.unsorted = false;
    for (const body of bodies) {
      if (body.motion !== MOTION_STATIC && !body.sleeping) {
        if (this.count === this.list.length) this.list.push(body);
        else this.list[this.count] = body;
        this.count += 1;
        this.pos[body.worldIndex] = this.count;
      }
      if (body.poseDirty) this.queueMoved(body);
    }
  }

  /** Lists `body` among the bodies moved by hand (once). */
  queueMoved(body: Body): void {
    const i = body.worldIndex;
    if (i < 0 || this.movedMark[i] !== 0) return;
    this.movedMark[i] = 1;
    if (this.movedCount === this.moved.length) this.moved.push(body);
    else this.moved[this.movedCount] = body;
    this.movedCount += 1;
  }

  /** Empties the list of bodies moved by hand. */
  clearMoved(): void {
    for (let i = 0; i < this.movedCount; i += 1) {
      const w = this.moved[i].worldIndex;
      if (w >= 0) this.movedMark[w] = 0;
    }
    this.movedCount = 0;
  }

  /** Starts a step: no body is saved yet. */
  beginStep(): void {
    this.serial = (this.serial + 1) | 0;
    if (this.serial === 0) {
      this.savedAt.fill(0);
      this.serial = 1;
    }
    this.savedCount = 0;
  }

  /** Whether the body's state should be saved now (first time in this step); then it is listed. */
  markSaved(body: Body): boolean {
    const i = body.worldIndex;
    if (i < 0 || this.savedAt[i] === this.serial) return false;
    this.savedAt[i] = this.serial;
    if (this.savedCount === this.saved.length) this.saved.push(body);
    else this.saved[this.savedCount] = body;
    this.savedCount += 1;
    return true;
  }
}

/** The sift-down of AwakeSet.sort's heap over list[0 .. end), by world index. */
function siftBody(list: Body[], root: number, end: number): void {
  for (;;) {
    let child = 2 * root + 1;
    if (child >= end) return;
    if (child + 1 < end && list[child + 1].worldIndex > list[child].worldIndex) child += 1;
    if (list[root].worldIndex >= list[child].worldIndex) return;
    const t = list[root];
    list[root] = list[child];
    list[child] = t;
    root = child;
  }
}

/** Scratch of the island pass. */
export class Islands {
  private parent = new Int32Array(16);
  private minTimer = new Float64Array(16);
  /** Per awake position: 1 when the body changes state (asleep ↔ awake) at the end of the pass. */
  private change = new Uint8Array(16);

  private find(i: number): number {
    const parent = this.parent;
    while (parent[i] !== i) {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  }

  /** Links the awake positions of A and B. */
  private union(a: number, b: number): void {
    const ra = this.find(a);
    const rb = this.find(b);
    if (ra !== rb) this.parent[ra < rb ? rb : ra] = ra < rb ? ra : rb;
  }

  /**
   * Advances the sleep timers of the awake bodies by the sub-step h (`constants[STEP_H]`), builds
   * their islands from the active contacts (`contacts.active`) and the joints, and puts to sleep
   * each island whose bodies all rested `sleepTime`. A sleeping dynamic body that touches a moving
   * one, or is held by a joint to an awake one, is woken first (`body.wake()`: the world wakes its
   * island and puts it in `awake`). `setSleeping(body, true)` is called for every body put to sleep.
   */
  update(
    awake: AwakeSet,
    contacts: ContactSet,
    constants: Float64Array,
    params: Readonly<Params>,
    setSleeping: (body: Body, asleep: boolean) => void,
    joints: readonly { readonly a: Body; readonly b: Body | null }[] = [],
  ): void {
    const h = constants[STEP_H];
    const linear = params.sleepLinearVelocity;
    const angular = params.sleepAngularVelocity;
    const sleepTime = params.sleepTime;
    const active = contacts.active;
    const activeCount = contacts.activeCount;
    // Wake what an awake island touches (a body the solver did not reach, e.g. past maxContacts).
    for (let c = 0; c < activeCount; c += 1) {
      const slot = active[c];
      // (a sensor's overlap links no island: it holds nothing up and wakes nothing)
      if ((contacts.flags[slot] & (CONTACT_TOUCHING | CONTACT_SENSOR)) !== CONTACT_TOUCHING) continue;
      const A = contacts.bodyA[slot] as Body;
      const B = contacts.bodyB[slot] as Body;
      if (A.sleeping && A.motion === MOTION_DYNAMIC && isMoving(B)) A.wake();
      else if (B.sleeping && B.motion === MOTION_DYNAMIC && isMoving(A)) B.wake();
    }
    // (the world's wake walks joints too; this catches a joint to a moving kinematic body)
    for (let j = 0; j < joints.length; j += 1) {
      const A = joints[j].a;
      const B = joints[j].b;
      if (B === null) continue;
      if (A.sleeping && A.motion === MOTION_DYNAMIC && isMoving(B)) A.wake();
      else if (B.sleeping && B.motion === MOTION_DYNAMIC && isMoving(A)) B.wake();
    }
    awake.sort();
    const bodies = awake.list;
    const count = awake.count;
    this.reserve(count);
    const lin2 = linear * linear;
    const ang2 = angular * angular;
    for (let i = 0; i < count; i += 1) {
      const body = bodies[i];
      if (body.motion !== MOTION_DYNAMIC) continue;
      // v and ω through the record (a body makes its views only when asked for them)
      const { n, k } = body.D;
      const s = body.storage;
      const v = body.storageOffset + Body.velocityOffset(body.D); // then L, then w
      let v2 = 0;
      for (let i = v; i < v + n; i += 1) v2 += s[i] * s[i];
      let w2 = 0;
      for (let i = v + n + k; i < v + n + 2 * k; i += 1) w2 += s[i] * s[i];
      body.sleepTimer = v2 > lin2 || w2 > ang2 ? 0 : body.sleepTimer + h;
    }
    this.build(awake, contacts, joints, true);
    const minTimer = this.minTimer;
    minTimer.fill(Infinity, 0, count);
    for (let i = 0; i < count; i += 1) {
      const body = bodies[i];
      if (body.motion !== MOTION_DYNAMIC) continue;
      const r = this.find(i);
      if (body.sleepTimer < minTimer[r]) minTimer[r] = body.sleepTimer;
    }
    const change = this.change;
    for (let i = 0; i < count; i += 1) {
      const body = bodies[i];
      change[i] = body.motion === MOTION_DYNAMIC && minTimer[this.find(i)] >= sleepTime ? 1 : 0;
    }
    // (after the decisions: putting a body to sleep takes it out of the awake set)
    for (let i = 0; i < count; i += 1) if (change[i] !== 0) setSleeping(bodies[i], true);
  }

  /**
   * Counts the islands of the awake dynamic bodies, as the island pass would build them now
   * (`world.stats.islands`). Changes no body: only this scratch. `awake` must be sorted.
   */
  count(awake: AwakeSet, contacts: ContactSet, joints: readonly { readonly a: Body; readonly b: Body | null }[]): number {
    this.reserve(awake.count);
    this.build(awake, contacts, joints, false);
    let islands = 0;
    for (let i = 0; i < awake.count; i += 1) if (awake.list[i].motion === MOTION_DYNAMIC && this.find(i) === i) islands += 1;
    return islands;
  }

  private reserve(count: number): void {
    this.parent = growInt32(this.parent, count);
    this.minTimer = growFloat64(this.minTimer, count);
    if (this.change.length < count) this.change = new Uint8Array(this.parent.length);
  }

  /**
   * The union–find of the awake positions over the active touching contacts and the joints. With
   * `carry`, a dynamic body on a moving kinematic one has its sleep timer reset (the island pass).
   */
  private build(
    awake: AwakeSet,
    contacts: ContactSet,
    joints: readonly { readonly a: Body; readonly b: Body | null }[],
    carry: boolean,
  ): void {
    const parent = this.parent;
    for (let i = 0; i < awake.count; i += 1) parent[i] = i;
    // Positions in the awake list: every dynamic body of an active touching contact is awake now.
    const active = contacts.active;
    for (let c = 0; c < contacts.activeCount; c += 1) {
      const slot = active[c];
      if ((contacts.flags[slot] & (CONTACT_TOUCHING | CONTACT_SENSOR)) !== CONTACT_TOUCHING) continue;
      this.link(awake, contacts.bodyA[slot] as Body, contacts.bodyB[slot] as Body, carry);
    }
    // A joint links its two bodies as a touching contact does.
    for (let j = 0; j < joints.length; j += 1) {
      const B = joints[j].b;
      if (B !== null) this.link(awake, joints[j].a, B, carry);
    }
  }

  /** Links A and B (a touching contact or a joint) in the union–find of the awake bodies. */
  private link(awake: AwakeSet, A: Body, B: Body, carry: boolean): void {
    const dynA = A.motion === MOTION_DYNAMIC;
    const dynB = B.motion === MOTION_DYNAMIC;
    if (dynA && dynB) {
      if (!awake.has(A) || !awake.has(B)) return; // both asleep: not this pass's island
      this.union(awake.positionOf(A), awake.positionOf(B));
    } else if (!carry) {
      return;
    } else if (dynA && isMoving(B)) {
      A.sleepTimer = 0; // carried by a moving kinematic body
    } else if (dynB && isMoving(A)) {
      B.sleepTimer = 0;
    }
  }
}
