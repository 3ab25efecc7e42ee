/**
 * Islands and sleep.
 *
 * An island is a set of dynamic bodies linked by touching contacts and joints (static and kinematic bodies
 * do not link: a floor does not join every pile on it into one island). A body's sleep timer
 * counts the seconds it has moved slower than `sleepLinearVelocity` and `sleepAngularVelocity`;
 * an island whose slowest-to-settle body has waited `sleepTime` goes to sleep as a whole (its
 * velocities are zeroed), and an island with one awake, unsettled body wakes as a whole. So a box
 * that lands on a sleeping pile wakes the pile, and nothing else.
 *
 * Union–find over the world's body list with path halving; arrays grow with the world and the
 * pass allocates nothing.
 *
 * @module
 */
import type { Body } from '../body.js';
import { MOTION_DYNAMIC } from '../body.js';
import type { ContactSet } from '../contacts/contact-set.js';
import { STEP_H } from '../integrator/step-constants.js';
import type { Params } from '../params.js';
import { CONTACT_SENSOR, CONTACT_TOUCHING, growFloat64, growInt32, isMoving } from '../contacts/contact-set.js';

/** Scratch of the island pass. */
export class Islands {
  private parent = new Int32Array(16);
  private minTimer = new Float64Array(16);

  private find(i: number): number {
    const parent = this.parent;
    while (parent[i] !== i) {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  }

  /**
   * Advances the sleep timers by the sub-step h (`constants[STEP_H]`), builds the islands and puts to sleep or wakes each as a whole.
   * `setSleeping(body, asleep)` is called for every change (the world updates its broadphase).
   */
  update(
    bodies: readonly Body[],
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
    const count = bodies.length;
    this.parent = growInt32(this.parent, count);
    this.minTimer = growFloat64(this.minTimer, count);
    const parent = this.parent;
    const lin2 = linear * linear;
    const ang2 = angular * angular;
    for (let i = 0; i < count; i += 1) {
      parent[i] = i;
      const body = bodies[i];
      if (body.motion !== MOTION_DYNAMIC || body.sleeping) continue;
      let v2 = 0;
      for (let d = 0; d < body.v.length; d += 1) v2 += body.v[d] * body.v[d];
      let w2 = 0;
      for (let p = 0; p < body.w.length; p += 1) w2 += body.w[p] * body.w[p];
      body.sleepTimer = v2 > lin2 || w2 > ang2 ? 0 : body.sleepTimer + h;
    }
    for (let c = 0; c < contacts.count; c += 1) {
      const slot = contacts.order[c];
      // (a sensor's overlap links no island: it holds nothing up and wakes nothing)
      if ((contacts.flags[slot] & (CONTACT_TOUCHING | CONTACT_SENSOR)) !== CONTACT_TOUCHING) continue;
      const A = contacts.bodyA[slot] as Body;
      const B = contacts.bodyB[slot] as Body;
      const dynA = A.motion === MOTION_DYNAMIC;
      const dynB = B.motion === MOTION_DYNAMIC;
      if (dynA && dynB) {
        const ra = this.find(A.worldIndex);
        const rb = this.find(B.worldIndex);
        if (ra !== rb) parent[ra < rb ? rb : ra] = ra < rb ? ra : rb;
      } else if (dynA && isMoving(B)) {
        A.sleepTimer = 0; // carried by a moving kinematic body
      } else if (dynB && isMoving(A)) {
        B.sleepTimer = 0;
      }
    }
    // A joint links its two bodies as a touching contact does.
    for (let j = 0; j < joints.length; j += 1) {
      const A = joints[j].a;
      const B = joints[j].b;
      if (B === null) continue;
      const dynA = A.motion === MOTION_DYNAMIC;
      const dynB = B.motion === MOTION_DYNAMIC;
      if (dynA && dynB) {
        const ra = this.find(A.worldIndex);
        const rb = this.find(B.worldIndex);
        if (ra !== rb) parent[ra < rb ? rb : ra] = ra < rb ? ra : rb;
      } else if (dynA && isMoving(B)) {
        A.sleepTimer = 0;
      } else if (dynB && isMoving(A)) {
        B.sleepTimer = 0;
      }
    }
    const minTimer = this.minTimer;
    minTimer.fill(Infinity, 0, count);
    for (let i = 0; i < count; i += 1) {
      const body = bodies[i];
      if (body.motion !== MOTION_DYNAMIC) continue;
      const r = this.find(i);
      if (body.sleepTimer < minTimer[r]) minTimer[r] = body.sleepTimer;
    }
    for (let i = 0; i < count; i += 1) {
      const body = bodies[i];
      if (body.motion !== MOTION_DYNAMIC) continue;
      const asleep = minTimer[this.find(i)] >= sleepTime;
      if (asleep !== body.sleeping) setSleeping(body, asleep);
    }
  }
}
