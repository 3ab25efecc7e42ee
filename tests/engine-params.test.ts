/**
 * defaultParams: every name of the specification's tolerance table with its default, frozen, and
 * the validator (types, ranges, unknown names; all-or-nothing in World.setParams).
 */
import { describe, expect, it } from 'vitest';
import { defaultParams, mergeParams, validateParams, World } from '@physin/engine/internal';

// The specification's section 12 table, plus the two damping rates and the manifold reuse tolerance.
const table: Record<string, number | boolean> = {
  fixedTimeStep: 1 / 60,
  subSteps: 1,
  iterations: 10,
  shockIterations: 2,
  penetrationSlop: 0.005,
  biasFactor: 0.2,
  contactMargin: 0.02,
  restitutionThreshold: 0.5,
  maxContacts: 0,
  constraintBias: 0.2,
  constraintSlop: 0.001,
  constraintMaxBias: 10,
  constraintTolerance: 1e-6,
  constraintProjectionTolerance: 0,
  constraintHertz: 0,
  constraintDamping: 1,
  constraintHertzRatio: 0.25,
  rotorTolerance: 1e-9,
  gyroscopic: true,
  gyroscopicIterations: 1,
  allowSleep: true,
  sleepLinearVelocity: 0.03,
  sleepAngularVelocity: 0.03,
  sleepTime: 0.6,
  useShockPropagation: true,
  useWarmStart: true,
  linearDamping: 0,
  angularDamping: 0,
  manifoldReuseTolerance: 1e-4,
  solverTolerance: 1e-9,
  lengthUnit: 1,
};

describe('defaultParams', () => {
  it('has exactly the names of the table with the same defaults', () => {
    expect(Object.keys(defaultParams).sort()).toEqual(Object.keys(table).sort());
    for (const [name, value] of Object.entries(table)) expect(defaultParams[name as keyof typeof defaultParams]).toBe(value);
  });

  it('is frozen: a write throws in strict mode and changes nothing', () => {
    expect(Object.isFrozen(defaultParams)).toBe(true);
    expect(() => {
      (defaultParams as { iterations: number }).iterations = 3;
    }).toThrow(TypeError);
    expect(defaultParams.iterations).toBe(10);
  });

  it('passes its own validator', () => {
    expect(() => validateParams({ ...defaultParams })).not.toThrow();
  });
});

describe('validateParams', () => {
  const bad: [string, unknown, 'TypeError' | 'RangeError'][] = [
    ['fixedTimeStep', 0, 'RangeError'],
    ['fixedTimeStep', -1 / 60, 'RangeError'],
    ['fixedTimeStep', Infinity, 'RangeError'],
    ['fixedTimeStep', '1/60', 'TypeError'],
    ['subSteps', 0, 'RangeError'],
    ['subSteps', 1.5, 'RangeError'],
    ['subSteps', 1e9, 'RangeError'],
    ['iterations', 0, 'RangeError'],
    ['shockIterations', -1, 'RangeError'],
    ['penetrationSlop', -0.001, 'RangeError'],
    ['penetrationSlop', NaN, 'RangeError'],
    ['biasFactor', 1.5, 'RangeError'],
    ['contactMargin', -1, 'RangeError'],
    ['restitutionThreshold', -0.5, 'RangeError'],
    ['maxContacts', -1, 'RangeError'],
    ['maxContacts', 2.5, 'RangeError'],
    ['constraintBias', -0.1, 'RangeError'],
    ['constraintSlop', -1, 'RangeError'],
    ['constraintMaxBias', -10, 'RangeError'],
    ['constraintTolerance', 0, 'RangeError'],
    ['constraintProjectionTolerance', -1e-9, 'RangeError'],
    ['constraintProjectionTolerance', '1e-3', 'TypeError'],
    ['constraintHertz', -5, 'RangeError'],
    ['constraintDamping', -1, 'RangeError'],
    ['constraintHertzRatio', 0, 'RangeError'],
    ['constraintHertzRatio', 1.1, 'RangeError'],
    ['rotorTolerance', -1e-9, 'RangeError'],
    ['gyroscopic', 1, 'TypeError'],
    ['gyroscopicIterations', -1, 'RangeError'],
    ['gyroscopicIterations', 0.5, 'RangeError'],
    ['allowSleep', 'yes', 'TypeError'],
    ['sleepLinearVelocity', -0.03, 'RangeError'],
    ['sleepAngularVelocity', null, 'TypeError'],
    ['sleepTime', -1, 'RangeError'],
    ['useShockPropagation', 0, 'TypeError'],
    ['useWarmStart', undefined, 'TypeError'],
    ['linearDamping', -0.1, 'RangeError'],
    ['angularDamping', Infinity, 'RangeError'],
    ['manifoldReuseTolerance', -1e-4, 'RangeError'],
    ['manifoldReuseTolerance', '1e-4', 'TypeError'],
    ['solverTolerance', -1e-9, 'RangeError'],
    ['solverTolerance', Number.NaN, 'RangeError'],
    ['lengthUnit', 0, 'RangeError'],
    ['lengthUnit', 1e7, 'RangeError'],
  ];
  for (const [name, value, kind] of bad) {
    it(`${name} = ${String(value)} throws a ${kind} naming '${name}'`, () => {
      const err = (() => {
        try {
          validateParams({ [name]: value });
        } catch (e) {
          return e as Error;
        }
        return null;
      })();
      expect(err).not.toBeNull();
      expect(err!.constructor.name).toBe(kind);
      expect(err!.message).toContain(`'${name}'`);
    });
  }

  it('every name of the table is covered above', () => {
    const covered = new Set(bad.map((b) => b[0]));
    for (const name of Object.keys(table)) expect(covered.has(name), name).toBe(true);
  });

  it('refuses an unknown name (RangeError naming it) and a non-object (TypeError)', () => {
    expect(() => validateParams({ iteration: 4 })).toThrow(RangeError);
    expect(() => validateParams({ iteration: 4 })).toThrow(/'iteration'/);
    expect(() => validateParams(null)).toThrow(TypeError);
    expect(() => validateParams([1, 2])).toThrow(TypeError);
  });

  it('accepts boundary values: 0 where allowed, biasFactor 1, constraintHertzRatio 1', () => {
    expect(() =>
      validateParams({
        shockIterations: 0,
        penetrationSlop: 0,
        biasFactor: 1,
        constraintHertzRatio: 1,
        constraintProjectionTolerance: 0,
        rotorTolerance: 0,
        gyroscopicIterations: 0,
      }),
    ).not.toThrow();
  });

  it('mergeParams returns a new frozen object and leaves its base alone', () => {
    const p = mergeParams(defaultParams, { subSteps: 4 });
    expect(p.subSteps).toBe(4);
    expect(defaultParams.subSteps).toBe(1);
    expect(Object.isFrozen(p)).toBe(true);
  });
});

describe('World params', () => {
  it('new World validates params and refuses unknown ones', () => {
    expect(() => new World({ dimensions: 3, params: { subSteps: 0 } })).toThrow(/'subSteps'/);
    expect(() => new World({ dimensions: 3, params: { foo: 1 } as never })).toThrow(/'foo'/);
  });

  it('setParams is all-or-nothing: one bad entry leaves every value unchanged', () => {
    const world = new World({ dimensions: 4, params: { iterations: 7 } });
    const before = world.params;
    expect(() => world.setParams({ subSteps: 2, biasFactor: 3 })).toThrow(RangeError);
    expect(world.params).toBe(before);
    expect(world.params.subSteps).toBe(1);
    world.setParams({ subSteps: 2 });
    expect(world.params.subSteps).toBe(2);
    expect(world.params.iterations).toBe(7);
    expect(Object.isFrozen(world.params)).toBe(true);
  });
});
