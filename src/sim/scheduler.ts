// Timers for the simulation loop, injected so the loop runs on a fake clock in tests.

export interface Scheduler {
  /** Wall-clock milliseconds (monotonic). */
  now(): number;
  /** Calls fn after ms (0: as soon as pending messages are handled). Returns a cancel function. */
  schedule(fn: () => void, ms: number): () => void;
}

/**
 * setTimeout for waits; a MessageChannel for "as soon as possible", because nested setTimeout(0)
 * is clamped to 4 ms, which would waste most of a 0 ms cycle run.
 */
export function createBrowserScheduler(): Scheduler {
  const channel = new MessageChannel();
  const queue = new Map<number, () => void>();
  let nextId = 0;
  channel.port1.onmessage = (event: MessageEvent<number>) => {
    const fn = queue.get(event.data);
    queue.delete(event.data);
    fn?.();
  };
  return {
    now: () => performance.now(),
    schedule(fn, ms) {
      if (ms > 0) {
        const handle = setTimeout(fn, ms);
        return () => clearTimeout(handle);
      }
      const id = nextId++;
      queue.set(id, fn);
      channel.port2.postMessage(id);
      return () => queue.delete(id);
    },
  };
}
