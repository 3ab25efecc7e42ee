/**
 * comlink's Endpoint over a Node `worker_threads` port or Worker: Node delivers the message data
 * itself and uses `on`/`off`, comlink expects `{ data }` events and `addEventListener`.
 *
 * @module
 */
import type { Endpoint } from 'comlink';

/** The part of a Node MessagePort / Worker that the adapter uses. */
export interface NodePort {
  postMessage(message: unknown, transfer?: readonly unknown[]): void;
  on(type: 'message', listener: (data: unknown) => void): unknown;
  off(type: 'message', listener: (data: unknown) => void): unknown;
}

type Listener = EventListenerOrEventListenerObject;

/** An Endpoint that comlink can `wrap` or `expose` on, over a Node port. */
export function nodeEndpoint(port: NodePort): Endpoint {
  const bound = new WeakMap<Listener, (data: unknown) => void>();
  return {
    postMessage: (message: unknown, transfer?: Transferable[]) => port.postMessage(message, transfer ?? []),
    addEventListener: (_type: string, listener: Listener) => {
      const fn = (data: unknown): void => {
        const event = { data } as MessageEvent;
        if (typeof listener === 'function') listener(event);
        else listener.handleEvent(event);
      };
      bound.set(listener, fn);
      port.on('message', fn);
    },
    removeEventListener: (_type: string, listener: Listener) => {
      const fn = bound.get(listener);
      if (fn === undefined) return;
      port.off('message', fn);
      bound.delete(listener);
    },
  };
}
