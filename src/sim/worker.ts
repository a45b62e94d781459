// Web Worker entry: the engine runs here so the page never freezes, even on a runaway program.
// Created by host.ts with `new Worker(new URL('./worker.ts', import.meta.url), { type: 'module' })`.
// It also holds the gateway link's socket and drives the hardware (src/bridge/workerRelay.ts), so
// the controller's outputs and lease heartbeat come from where the program runs.
import { GatewayRelay } from '../bridge/workerRelay';
import type { SocketLike } from '../bridge/GatewayClient';
import { realEngine } from './engineAdapter';
import { SIM_PROTOCOL_VERSION, type HostMessage, type WorkerMessage } from './protocol';
import { createBrowserScheduler } from './scheduler';
import { SimSession } from './session';

const scope = self as unknown as DedicatedWorkerGlobalScope;
/** The page asked for output images (subscribeOutputs); the relay may want them too. */
let pageWantsOutputs = false;
const relay = new GatewayRelay(
  (message) => scope.postMessage(message),
  (url) => new WebSocket(url) as unknown as SocketLike,
  {
    setInputs: (values) => session.handle({ type: 'setInputs', values }),
    // Deferred: the relay may ask while the session is posting a frame.
    wantOutputs: (on) => queueMicrotask(() => session.handle({ type: 'subscribeOutputs', enabled: on || pageWantsOutputs })),
  },
);
const post = (message: WorkerMessage, transfer: Transferable[] = []) => {
  if (message.type === 'outputs') {
    relay.outputs(message.outputs, message.program);
    if (!pageWantsOutputs) return;
  } else if (message.type === 'frame') {
    relay.frame(message.frame);
  }
  scope.postMessage(message, transfer);
};
const session = new SimSession({ engine: realEngine, scheduler: createBrowserScheduler(), post });
scope.onmessage = (event: MessageEvent<HostMessage>) => {
  const m = event.data;
  switch (m.type) {
    case 'gwOpen':
    case 'gwSend':
    case 'gwClose':
    case 'gwDrive':
    case 'gwPrograms':
      relay.handle(m);
      return;
    case 'subscribeOutputs':
      pageWantsOutputs = m.enabled;
      session.handle({ type: 'subscribeOutputs', enabled: m.enabled || relay.driving });
      return;
    default:
      session.handle(m);
  }
};
post({ type: 'ready', version: SIM_PROTOCOL_VERSION });
