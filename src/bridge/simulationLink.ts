// The simulation as the gateway link sees it: the two seams of the simulation store a bridge
// (src/bridge/GatewayBridge.ts, attachSimulation) or a stepping lease exchanges images through.
import type { Value } from '../model/iecTypes';

/** The two seams of the simulation store (src/store/simStore.ts) the link uses. */
export interface SimulationPorts {
  setInputs(values: Readonly<Record<string, Value>>): void;
  onOutputs(listener: (outputs: Readonly<Record<string, Value>>, scan: number) => void): () => void;
}
