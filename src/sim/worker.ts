// Web Worker entry: the engine runs here so the page never freezes, even on a runaway program.
// Created by host.ts with `new Worker(new URL('./worker.ts', import.meta.url), { type: 'module' })`.
import { realEngine } from './engineAdapter';
import { SIM_PROTOCOL_VERSION, type HostMessage, type WorkerMessage } from './protocol';
import { createBrowserScheduler } from './scheduler';
import { SimSession } from './session';

const scope = self as unknown as DedicatedWorkerGlobalScope;
const post = (message: WorkerMessage, transfer: Transferable[] = []) => scope.postMessage(message, transfer);
const session = new SimSession({ engine: realEngine, scheduler: createBrowserScheduler(), post });
scope.onmessage = (event: MessageEvent<HostMessage>) => session.handle(event.data);
post({ type: 'ready', version: SIM_PROTOCOL_VERSION });
