// Glue between a running simulation and the gateway, for the simulation's Run/Pause/Stop:
//   const detach = attachSimulation(simStore.getState(), gatewayLink.bridge, report.bindings);  // on Run
//   detach(); bridge.stop();                                                                   // on Pause/Stop
// Inputs from the gateway go to the simulation's input image (converted to each bound variable's
// type); every output image the simulation reports goes to the gateway.
import type { Value } from '../model/iecTypes';
import type { GatewayBridge } from './GatewayBridge';
import type { Binding } from './mapping';

/** The two seams of the simulation store (src/store/simStore.ts) the link uses. */
export interface SimulationPorts {
  setInputs(values: Readonly<Record<string, Value>>): void;
  onOutputs(listener: (outputs: Readonly<Record<string, Value>>, scan: number) => void): () => void;
}

/** Starts exchanging images; returns the function that stops it (it does not send `stop`). */
export function attachSimulation(sim: SimulationPorts, bridge: GatewayBridge, bindings: readonly Binding[]): () => void {
  const bound = bindings.filter((b) => b.point.dir === 'in');
  const typed = (changed: Record<string, Value>) => {
    const image = bridge.inputImage(bound);
    const out: Record<string, Value> = {};
    for (const a of Object.keys(changed)) if (image[a] !== undefined) out[a] = image[a];
    return out;
  };
  sim.setInputs(bridge.inputImage(bound));
  const offInputs = bridge.onInputs((changed) => {
    const values = typed(changed);
    if (Object.keys(values).length) sim.setInputs(values);
  });
  const offOutputs = sim.onOutputs((outputs) => bridge.sendOutputs(outputs));
  return () => {
    offInputs();
    offOutputs();
  };
}
