// A transport that hands commands straight to a SimSession in the same thread (no Worker), so the
// store, the protocol and the session are tested together in Node. Frames are structured-cloned
// like postMessage would.
import { realEngine } from '../../src/sim/engineAdapter';
import type { SimTransport } from '../../src/sim/host';
import type { WorkerMessage } from '../../src/sim/protocol';
import { SimSession } from '../../src/sim/session';
import type { SimEngine } from '../../src/sim/simEngine';
import { ManualScheduler } from './manualScheduler';

export function loopback(engine: SimEngine = realEngine): { transport: SimTransport; scheduler: ManualScheduler } {
  const scheduler = new ManualScheduler();
  const listeners = new Set<(m: WorkerMessage) => void>();
  const session = new SimSession({
    engine,
    scheduler,
    post: (m) => {
      const copy = structuredClone(m);
      for (const l of listeners) l(copy);
    },
  });
  const transport: SimTransport = {
    send: (m) => session.handle(structuredClone(m)),
    listen: (l) => {
      listeners.add(l);
      return () => listeners.delete(l);
    },
    terminate: () => listeners.clear(),
  };
  return { transport, scheduler };
}
