/**
 * The worker entry: exposes a {@link WorkerApi} through comlink, in a browser worker or on a Node
 * `worker_threads` port. Started by the host as
 * `new Worker(new URL('./worker.js', import.meta.url), { type: 'module' })`.
 *
 * @module
 */
import { expose } from 'comlink';
import { nodeEndpoint } from './node-endpoint.js';
import type { NodePort } from './node-endpoint.js';
import { WorkerApi } from './worker-api.js';

const api = new WorkerApi();
const scope = globalThis as { WorkerGlobalScope?: unknown };
if (scope.WorkerGlobalScope !== undefined) {
  expose(api);
} else {
  // Node: the module name is a variable so that bundlers leave it alone, and a promise rather
  // than a top-level await, which bundlers that build workers as classic scripts (Vite's default
  // format) refuse. Messages that arrive first wait on the port until `expose` listens.
  const name = 'node:worker_threads';
  void (import(/* @vite-ignore */ /* webpackIgnore: true */ name) as Promise<{ parentPort: NodePort | null }>).then((threads) => {
    if (threads.parentPort !== null) expose(api, nodeEndpoint(threads.parentPort));
  });
}
