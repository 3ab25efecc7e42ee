/**
 * Collision events: a pair of bodies begins or ends touching.
 *
 * The step fills one typed list per world, cleared at the start of each `World.step`: read
 * `world.contactEvents` after the step without allocating anything. Listeners on bodies
 * (`body.addEventListener('collision', fn)`) are called after the step from the same list, with
 * one event object per world that is rewritten for every call: copy what you keep.
 *
 * @module
 */
import type { Body } from '../body.js';
import { growFloat64, growInt32 } from './contact-set.js';
import type { ContactSet } from './contact-set.js';

/** What a collision listener receives. The object is reused: copy the fields you keep. */
export interface CollisionEvent {
  /** 'begin' when the two bodies start touching, 'end' when they stop. */
  type: 'begin' | 'end';
  /** The body the listener is on. */
  body: Body;
  /** The other body. */
  other: Body;
  /**
   * Which part of `body` touched: the index into its compound's parts (`Compound(D, parts)`), 0
   * for a body of one shape. Two compounds make one event per pair of parts that touch.
   */
  part: number;
  /** Which part of `other` touched (0 for a body of one shape). */
  otherPart: number;
  /** Deepest contact point at the start of the touch (world, n numbers); zeros for 'end'. */
  readonly point: Float64Array;
  /** Contact normal pointing from `body` to `other` (n numbers); zeros for 'end'. */
  readonly normal: Float64Array;
  /** Total normal impulse of the first touching sub-step (N·s); 0 for 'end'. */
  impulse: number;
}

/** A listener of collision events on a body. */
export type CollisionListener = (event: CollisionEvent) => void;

/**
 * The begin and end events of one step, in flat arrays: begin event i is between
 * `beginA[i]` and `beginB[i]`, at `beginPoint[i*n ..]`, with normal `beginNormal[i*n ..]` (from A
 * to B) and normal impulse `beginImpulse[i]`.
 */
export class ContactEvents {
  /** Count of dimensions. */
  readonly n: number;
  /** Count of begin events of the last step. */
  beginCount = 0;
  /** First body of each begin event. */
  readonly beginA: Body[] = [];
  /** Second body of each begin event. */
  readonly beginB: Body[] = [];
  /** Deepest point of each begin event, n numbers each. */
  beginPoint: Float64Array;
  /** Normal (from A to B) of each begin event, n numbers each. */
  beginNormal: Float64Array;
  /** Total normal impulse of each begin event (N·s). */
  beginImpulse: Float64Array;
  /** The part of A of each begin event (its index in A's compound; 0 for a body of one shape). */
  beginPartA: Int32Array = new Int32Array(8);
  /** The part of B of each begin event. */
  beginPartB: Int32Array = new Int32Array(8);
  /** Count of end events of the last step. */
  endCount = 0;
  /** First body of each end event. */
  readonly endA: Body[] = [];
  /** Second body of each end event. */
  readonly endB: Body[] = [];
  /** The part of A of each end event (0 for a body of one shape). */
  endPartA: Int32Array = new Int32Array(8);
  /** The part of B of each end event. */
  endPartB: Int32Array = new Int32Array(8);
  /** End events of pairs whose body left the world between steps, for the next step's list. */
  private readonly laterA: Body[] = [];
  private readonly laterB: Body[] = [];
  private laterPartA: Int32Array = new Int32Array(8);
  private laterPartB: Int32Array = new Int32Array(8);
  private laterCount = 0;

  /** @internal */
  constructor(n: number) {
    this.n = n;
    this.beginPoint = new Float64Array(8 * n);
    this.beginNormal = new Float64Array(8 * n);
    this.beginImpulse = new Float64Array(8);
  }

  /**
   * @internal
   * Forgets the events of the last step; the end events recorded since by
   * {@link ContactEvents.pushEndLater} become the first of the new step's list.
   */
  clear(): void {
    this.beginCount = 0;
    for (let i = 0; i < this.laterCount; i += 1) {
      this.endA[i] = this.laterA[i]!;
      this.endB[i] = this.laterB[i]!;
    }
    if (this.laterCount > this.endPartA.length) {
      this.endPartA = growInt32(this.endPartA, this.laterCount);
      this.endPartB = growInt32(this.endPartB, this.laterCount);
    }
    for (let i = 0; i < this.laterCount; i += 1) {
      this.endPartA[i] = this.laterPartA[i]!;
      this.endPartB[i] = this.laterPartB[i]!;
    }
    this.endCount = this.laterCount;
    this.laterCount = 0;
  }

  /**
   * @internal
   * Records that A and B stopped touching between steps (one of them left the world). Reported
   * with the events of the next step, as Box2D does, so that a reader of the last step's list is
   * not surprised by an event appended after the step, and no end goes unreported.
   */
  pushEndLater(A: Body, B: Body, partA = 0, partB = 0): void {
    const i = this.laterCount++;
    this.laterA[i] = A;
    this.laterB[i] = B;
    if (i >= this.laterPartA.length) {
      this.laterPartA = growInt32(this.laterPartA, i + 1);
      this.laterPartB = growInt32(this.laterPartB, i + 1);
    }
    this.laterPartA[i] = partA;
    this.laterPartB[i] = partB;
  }

  /**
   * @internal The end events recorded for the next step (pushEndLater), for world snapshots:
   * `count` pairs (a[i], b[i]).
   */
  pendingEnds(): {
    readonly count: number;
    readonly a: readonly Body[];
    readonly b: readonly Body[];
    readonly partA: Int32Array;
    readonly partB: Int32Array;
  } {
    return { count: this.laterCount, a: this.laterA, b: this.laterB, partA: this.laterPartA, partB: this.laterPartB };
  }

  /**
   * @internal
   * Records that the bodies of contact `slot` began touching, with the deepest point of their
   * manifold and its total normal impulse.
   */
  pushBegin(contacts: ContactSet, slot: number): void {
    const n = this.n;
    const A = contacts.bodyA[slot]!;
    const B = contacts.bodyB[slot]!;
    const man = contacts.manifolds[slot]!;
    const P = contacts.pointCapacity;
    let impulse = 0;
    for (let q = 0; q < man.count; q += 1) impulse += contacts.normalImpulse[slot * P + q]!;
    const i = this.beginCount++;
    if ((i + 1) * n > this.beginPoint.length) {
      this.beginPoint = growFloat64(this.beginPoint, (i + 1) * n);
      this.beginNormal = growFloat64(this.beginNormal, (i + 1) * n);
      this.beginImpulse = growFloat64(this.beginImpulse, i + 1);
    }
    if (i >= this.beginPartA.length) {
      this.beginPartA = growInt32(this.beginPartA, i + 1);
      this.beginPartB = growInt32(this.beginPartB, i + 1);
    }
    this.beginPartA[i] = contacts.partA[slot]!;
    this.beginPartB[i] = contacts.partB[slot]!;
    this.beginA[i] = A;
    this.beginB[i] = B;
    let deepest = 0;
    for (let q = 1; q < man.count; q += 1) if (man.separations[q] < man.separations[deepest]) deepest = q;
    for (let d = 0; d < n; d += 1) {
      this.beginPoint[i * n + d] = man.points[deepest * n + d];
      this.beginNormal[i * n + d] = man.normal[d];
    }
    this.beginImpulse[i] = impulse;
  }

  /** @internal Records that A and B stopped touching. */
  pushEnd(A: Body, B: Body, partA = 0, partB = 0): void {
    const i = this.endCount++;
    this.endA[i] = A;
    this.endB[i] = B;
    if (i >= this.endPartA.length) {
      this.endPartA = growInt32(this.endPartA, i + 1);
      this.endPartB = growInt32(this.endPartB, i + 1);
    }
    this.endPartA[i] = partA;
    this.endPartB[i] = partB;
  }
}
