/**
 * What the worker exposes through comlink: a {@link WorldCore} that takes a batch of operations
 * and a report buffer with each step and gives the buffer back (transferred, never copied).
 *
 * @module
 */
import { transfer } from 'comlink';
import type { WorldOptions } from '@physin/engine';
import { errorToData } from './errors.js';
import type { ErrorData } from './errors.js';
import { WorldCore } from './world-core.js';
import type { Operation } from './world-core.js';

/** The answer to a step: the report buffer, or an error (the buffer comes back either way). */
export interface StepAnswer {
  readonly buffer: ArrayBuffer | null;
  readonly error: ErrorData | null;
}

/** The worker's side of the protocol. */
export class WorkerApi {
  private core: WorldCore | null = null;

  /** Builds the world, new or from a host snapshot. */
  open(options: WorldOptions, snapshot: Uint8Array | null): ErrorData | null {
    try {
      this.core = snapshot === null ? WorldCore.create(options) : WorldCore.restore(snapshot);
      return null;
    } catch (error) {
      return errorToData(error);
    }
  }

  /** Applies `ops` in order, then steps for `elapsed` and writes the report into `buffer`. */
  step(ops: readonly Operation[], elapsed: number, maxSubSteps: number, buffer: ArrayBuffer | null): StepAnswer {
    const core = this.core!;
    try {
      for (const o of ops) core.apply(o);
      const steps = core.takeSteps(elapsed, maxSubSteps);
      const out = core.stepAndReport(steps, buffer);
      return transfer({ buffer: out, error: null }, [out]);
    } catch (error) {
      const answer: StepAnswer = { buffer, error: errorToData(error) };
      return buffer === null ? answer : transfer(answer, [buffer]);
    }
  }

  /** Applies `ops`, then returns the host snapshot. */
  snapshot(ops: readonly Operation[]): Uint8Array | ErrorData {
    const core = this.core!;
    try {
      for (const o of ops) core.apply(o);
      const bytes = core.snapshot();
      return transfer(bytes, [bytes.buffer]);
    } catch (error) {
      return errorToData(error);
    }
  }
}
