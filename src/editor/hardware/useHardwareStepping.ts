// The page's stepping lease (src/bridge/steppingLease.ts) wired to the gateway link, and the
// toolbar's step/run/restart commands routed through it.
import { useMemo, useSyncExternalStore } from 'react';
import { gatewayLink } from '../../bridge/gatewayLink';
import { checkBindings } from '../../bridge/mapping';
import { SteppingLease, type StepRequest, type SteppingView } from '../../bridge/steppingLease';
import { useDocumentStore } from '../../store/documentStore';
import { useSimStore } from '../sim/simContext';

/** The page's lease: hardware counts as attached while this page is the gateway's controller. */
export const hardwareStepping = new SteppingLease(() => {
  const v = gatewayLink.snapshot();
  return v.link === 'open' && v.role === 'controller' ? gatewayLink.bridge : undefined;
});
gatewayLink.subscribe(() => hardwareStepping.hardwareChanged());

export function useSteppingView(): SteppingView {
  return useSyncExternalStore(hardwareStepping.subscribe, hardwareStepping.snapshot, hardwareStepping.snapshot);
}

export interface SimCommands {
  run(): void;
  step(request: StepRequest): void;
  reset(): void;
  warmRestart(): void;
}

/** The simulation commands of the toolbar, aware of attached hardware. */
export function useSimCommands(): SimCommands {
  const sim = useSimStore();
  const documents = useDocumentStore();
  return useMemo(() => {
    const project = () => documents.getState().project;
    return {
      run: () => {
        hardwareStepping.end('run');
        // Run as controller is the operator's deliberate act: the gateway is armed before the run's
        // first outputs (and by nothing else: not a reconnect, not an online change).
        const v = gatewayLink.snapshot();
        if (v.link === 'open' && v.role === 'controller') gatewayLink.bridge?.requestArm();
        sim.getState().run(project());
      },
      step: (request) => {
        hardwareStepping.step(request, {
          sim: { setInputs: (v) => sim.getState().setInputs(v), onOutputs: (l) => sim.getState().onOutputs(l) },
          bindings: () => checkBindings(project(), gatewayLink.snapshot().points).bindings,
          perform: (r) => (r.kind === 'network' ? sim.getState().stepNetwork(project(), r.into, r.out) : sim.getState().step(project(), r.scans)),
        });
      },
      reset: () => {
        hardwareStepping.end('stop');
        sim.getState().reset();
      },
      warmRestart: () => {
        hardwareStepping.end('stop');
        sim.getState().warmRestart();
      },
    };
  }, [sim, documents]);
}
