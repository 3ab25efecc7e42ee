/**
 * @physin/worker — the PhysiN engine behind one interface, in the main thread or in a worker:
 * plain descriptions and commands in, one typed report per step out, the report buffers reused
 * (transferred, never copied), snapshots to move a world between threads or restart a worker.
 *
 * @module
 */
export { openWorld, createWorld } from './host.js';
export { COMMAND_NAMES } from './commands.js';
export type * from './types.js';
