// The UI side of the simulation worker: sends commands, delivers the worker's messages to listeners.
// The worker is created lazily, on the first command, so merely opening the editor costs nothing.
import type { HostMessage, WorkerMessage } from './protocol';

export interface SimTransport {
  send(message: HostMessage): void;
  /** Returns an unsubscribe function. */
  listen(listener: (message: WorkerMessage) => void): () => void;
  /** Ends the worker and whatever it held (the gateway link's socket); `reason` says why, in plain words. */
  terminate(reason?: string): void;
}

/** A transport over the real Web Worker (browser only). */
export function createWorkerTransport(): SimTransport {
  let worker: Worker | undefined;
  const listeners = new Set<(message: WorkerMessage) => void>();
  const ensure = (): Worker => {
    if (worker) return worker;
    const created = new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: 'rungsmith-sim' });
    created.onmessage = (event: MessageEvent<WorkerMessage>) => {
      for (const listener of listeners) listener(event.data);
    };
    created.onerror = (event: ErrorEvent) => {
      const message: WorkerMessage = { type: 'error', message: `the simulator stopped: ${event.message || 'worker error'}` };
      for (const listener of listeners) listener(message);
    };
    worker = created;
    return created;
  };
  return {
    send(message) {
      ensure().postMessage(message);
    },
    listen(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    terminate(reason = 'the worker was terminated') {
      if (!worker) return;
      worker.terminate();
      worker = undefined;
      // Whatever the worker held (the gateway link's socket) is gone with it.
      const message: WorkerMessage = { type: 'error', message: `the simulator stopped: ${reason}` };
      for (const listener of listeners) listener(message);
    },
  };
}
