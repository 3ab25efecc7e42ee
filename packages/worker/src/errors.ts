/**
 * Errors across the thread boundary: a worker's error travels as plain data and is rebuilt on the
 * caller's side with the same class, name and message (TypeError, RangeError, the engine's
 * NonFiniteStateError, else Error).
 *
 * @module
 */
import { NonFiniteStateError } from '@physin/engine';

/** An error as data. */
export interface ErrorData {
  readonly name: string;
  readonly message: string;
  readonly field?: string;
  readonly subStep?: number;
  readonly stack?: string;
}

/** Turns a thrown value into data that postMessage can carry. */
export function errorToData(error: unknown): ErrorData {
  if (error instanceof NonFiniteStateError) {
    return { name: error.name, message: error.message, field: error.field, subStep: error.subStep, stack: error.stack ?? '' };
  }
  if (error instanceof Error) return { name: error.name, message: error.message, stack: error.stack ?? '' };
  return { name: 'Error', message: String(error) };
}

/**
 * Rebuilds the error of `data` with its class. A NonFiniteStateError rebuilt here has `field` and
 * `subStep`; its `body` is null, because the body lives in the other thread (the message names it).
 */
export function errorFromData(data: ErrorData): Error {
  let error: Error;
  switch (data.name) {
    case 'TypeError':
      error = new TypeError(data.message);
      break;
    case 'RangeError':
      error = new RangeError(data.message);
      break;
    case 'NonFiniteStateError': {
      error = Object.create(NonFiniteStateError.prototype) as Error;
      Object.defineProperties(error, {
        message: { value: data.message, writable: true, configurable: true },
        name: { value: data.name, writable: true, configurable: true },
        field: { value: data.field, enumerable: true },
        subStep: { value: data.subStep, enumerable: true },
        body: { value: null, enumerable: true },
      });
      break;
    }
    default:
      error = new Error(data.message);
      error.name = data.name;
  }
  if (data.stack)
    error.stack = `${error.name}: ${error.message}\n    (in the world's thread)\n${data.stack.split('\n').slice(1).join('\n')}`;
  return error;
}
