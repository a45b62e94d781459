// Access to the simulation store from components. The app has one simulation (one worker), created
// on first use; a test or an embedding can provide its own store with <SimStoreProvider>.
import { createContext, createElement, useContext, type ReactNode } from 'react';
import { useStore } from 'zustand';
import { gatewayLink } from '../../bridge/gatewayLink';
import { createWorkerTransport } from '../../sim/host';
import type { SimState, SimStore } from '../../store/simState';
import { createSimStore } from '../../store/simStore';

let appStore: SimStore | undefined;

/** The app's simulation store (its worker starts with the first command). */
export function getAppSimStore(): SimStore {
  if (!appStore) {
    const transport = createWorkerTransport();
    appStore = createSimStore(transport);
    // The gateway link lives in the same worker as the scan: outputs and the lease heartbeat come
    // from where the program runs (src/bridge/workerRelay.ts).
    gatewayLink.useWorker(transport);
    // Leaving the page for another address in the same tab can keep it alive in the back/forward
    // cache, frozen, with the worker and its gateway socket open: the gateway would see neither a
    // stop nor a close, outputs would stay on until the watchdog tripped, and the frozen page would
    // hold the controller lease so that the page opened next is only an observer. With hardware
    // linked, the worker ends as the page is hidden: its socket closes, the gateway writes the safe
    // state at once and frees the lease. A page brought back shows Stopped and reconnects (never armed).
    window.addEventListener('pagehide', () => {
      if (gatewayLink.client) transport.terminate('the page was left while linked to the hardware (the gateway holds the outputs in the safe state); press Run to run again');
    });
    // Scripting aid and test handle, next to the document and UI stores (docs/editor.md "Scripting aid").
    const w = window as unknown as { rungsmith?: Record<string, unknown> };
    w.rungsmith = { ...(w.rungsmith ?? {}), simStore: appStore, terminateSimulation: () => transport.terminate() };
  }
  return appStore;
}

const SimStoreContext = createContext<SimStore | undefined>(undefined);

export function SimStoreProvider({ store, children }: { store: SimStore; children?: ReactNode }) {
  return createElement(SimStoreContext.Provider, { value: store }, children);
}

export function useSimStore(): SimStore {
  return useContext(SimStoreContext) ?? getAppSimStore();
}

/** Subscribes to one slice of the simulation state; pass a module-level selector. */
export function useSim<T>(selector: (s: SimState) => T): T {
  return useStore(useSimStore(), selector);
}
