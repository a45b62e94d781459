// Mounted once: while the simulation runs and this page is the gateway's controller, each scan's
// inputs come from the gateway and its outputs go there; pause, stop or a fault sends `stop`.
// Confirmed stepping on hardware (useHardwareStepping.ts) keeps the lease itself; a fault ends it.
import { useEffect, useRef } from 'react';
import { gatewayLink } from '../../bridge/gatewayLink';
import { checkBindings } from '../../bridge/mapping';
import { canonicalAddress } from '../../protocol/points';
import type { SimState } from '../../store/simState';
import { selectProject, useDocument } from '../../store/documentStore';
import { useSim, useSimStore } from '../sim/simContext';
import { SteppingConfirmDialog } from './HardwareStepping';
import { OutputForceConfirm } from './OutputForceConfirm';
import { guardFieldOutputs } from './outputForce';
import { hardwareStepping, useSteppingView } from './useHardwareStepping';
import { useGateway } from './useGateway';

const selectMode = (s: SimState) => s.mode;

export function HardwareSimLink() {
  const mode = useSim(selectMode);
  const sim = useSimStore();
  const project = useDocument(selectProject);
  const { link, role, points } = useGateway();
  const stepping = useSteppingView().phase === 'stepping';
  const wasRunning = useRef(false);
  const wasAttached = useRef(false);
  /** The controller link was lost (not disconnected by the user) and has not opened again yet. */
  const lostLink = useRef(false);

  // A write or force of a field output asks to confirm while this page drives the hardware.
  useEffect(() => guardFieldOutputs(sim), [sim]);

  useEffect(() => {
    // Forces made before this page drove the hardware (in simulation, as observer, or in an earlier
    // link) were never confirmed for it: carried onto the device, a forced input or output would
    // drive real outputs at the next Run or Arm without a word. They end as the hardware attaches,
    // and the notice says which; a force on the hardware is made again, with its confirmation.
    const attached = link === 'open' && role === 'controller';
    if (link === 'idle') lostLink.current = false; // disconnected on purpose
    else if (wasAttached.current && !attached) lostLink.current = true;
    if (!attached || wasAttached.current) {
      wasAttached.current = attached;
      return;
    }
    wasAttached.current = true;
    const afterLoss = lostLink.current;
    lostLink.current = false;
    const s = sim.getState();
    const ended: string[] = [];
    for (const name of s.forced.keys()) {
      const variable = s.layout?.variables[s.variableIndex.get(name) ?? -1];
      const address = variable?.location ? canonicalAddress(variable.location) : undefined;
      if (!variable || !address || !points.some((p) => p.address === address)) continue;
      s.unforce(variable.name);
      ended.push(`${variable.name} (${address})`);
    }
    if (ended.length > 0)
      sim.setState({
        notice: afterLoss
          ? `Unforced ${ended.join(', ')}: the link to the gateway was lost and is open again; a force on the hardware ends with its link (the gateway held the outputs in the safe state meanwhile). Force again on the hardware if you mean it (it asks to confirm).`
          : `Unforced ${ended.join(', ')}: forces made before the hardware was attached are not carried onto it. Force again on the hardware if you mean it (it asks to confirm).`,
      });
  }, [link, role, points, sim]);

  useEffect(() => {
    if (stepping) {
      // Step N shows 'running' while its scans execute: the stepping lease drives the I/O then.
      if (mode === 'faulted') hardwareStepping.end('stop');
      return undefined;
    }
    const bridge = gatewayLink.bridge;
    const controller = link === 'open' && role === 'controller' && bridge !== undefined;
    if (mode === 'running' && controller) {
      wasRunning.current = true;
      const { bindings } = checkBindings(project, points);
      const state = sim.getState();
      return bridge.attach({ setInputs: (v) => state.setInputs(v), onOutputs: (l) => state.onOutputs(l) }, bindings);
    }
    if (wasRunning.current) {
      wasRunning.current = false;
      bridge?.stop(); // paused, stopped or faulted: safe state first
      if (mode === 'running' && !controller) {
        // The link went while the program runs: the simulation goes on, but it does not drive the
        // outputs any more (the gateway holds them in the safe state). Never shown as if it did.
        const why = gatewayLink.snapshot().problem ?? 'the link to the gateway is closed';
        sim.setState({ notice: `Hardware link lost while running (${why}). The program no longer drives the outputs; the gateway holds them in the safe state. Reconnect in the Hardware panel, then press Run to drive them again.` });
      }
    }
    return undefined;
  }, [mode, link, role, points, project, sim, stepping]);

  return (
    <>
      <SteppingConfirmDialog />
      <OutputForceConfirm />
    </>
  );
}
