// Forcing (or writing) a field output while this page drives real hardware asks to confirm first, as
// TIA Portal warns before any force on a real output: the dialog (OutputForceConfirm.tsx) names the
// output, its address, the device and the value, Cancel has the focus, and nothing is sent on Cancel.
// The guard sits on the simulator store's write/force (simStore.setValueGuard), the one path every
// force takes (Watch row, canvas menu, F7/Ctrl+F7 prepared values), so none of them bypasses it. In
// pure simulation, or for a variable that is no field output, it holds nothing: one click as before.
import { createStore } from 'zustand/vanilla';
import type { GatewayView } from '../../bridge/GatewayClient';
import { gatewayLink } from '../../bridge/gatewayLink';
import type { SimValueAction, SimStore } from '../../store/simState';
import type { SimValueInput } from '../../sim/protocol';
import { fieldOutputAddress, hardwareAttached } from './fieldIo';

export interface OutputConfirmRequest {
  readonly kind: SimValueAction['kind'];
  /** The program's spelling of the variable. */
  readonly name: string;
  /** `%QX0.0`. */
  readonly address: string;
  /** `"plant" (127.0.0.1:502 unit 1)`. */
  readonly device: string;
  /** As the dialog says it: `TRUE`, `1200`. */
  readonly value: string;
  readonly send: () => void;
}

interface OutputConfirmState {
  /** The first waits for the answer; the others (F7 forcing several prepared outputs) follow it. */
  readonly queue: readonly OutputConfirmRequest[];
}

export const outputConfirm = createStore<OutputConfirmState>()(() => ({ queue: [] }));

/** The operator's answer to the shown request: Confirm sends it, Cancel drops it (nothing reaches the device). */
export function answerOutputConfirm(go: boolean): void {
  const [first, ...rest] = outputConfirm.getState().queue;
  if (!first) return;
  outputConfirm.setState({ queue: rest });
  // Confirmed on a link that has gone meanwhile: the request was dropped with the link (see below).
  if (go) first.send();
}

const valueWords = (input: SimValueInput): string =>
  'text' in input
    ? input.text.trim().toUpperCase()
    : typeof input.value === 'boolean'
      ? input.value
        ? 'TRUE'
        : 'FALSE'
      : String(input.value);

/** `"plant" (127.0.0.1:502 unit 1)` for the point's device. */
export function deviceWords(view: GatewayView, address: string): string {
  const id = view.points.find((p) => p.address === address && p.dir === 'out')?.device ?? '?';
  const info = view.devices.find((d) => d.id === id);
  return info
    ? `"${id}" (${info.kind === 'simulated' ? "the gateway's simulated device" : info.target})`
    : `"${id}"`;
}

/** Installs the guard on a page's simulator store; returns its removal. */
export function guardFieldOutputs(sim: SimStore): () => void {
  sim.getState().setValueGuard((action, send) => {
    const s = sim.getState();
    const variable = s.layout?.variables[s.variableIndex.get(action.name.toUpperCase()) ?? -1];
    const view = gatewayLink.snapshot();
    const address = fieldOutputAddress(variable, view);
    if (!address || !variable) return false;
    const request: OutputConfirmRequest = {
      kind: action.kind,
      name: variable.name,
      address,
      device: deviceWords(view, address),
      value: valueWords(action.input),
      send,
    };
    outputConfirm.setState({ queue: [...outputConfirm.getState().queue, request] });
    return true;
  });
  // A request asked for one link: when the page stops driving the hardware it is dropped unanswered
  // (a Confirm later must not force on a link, or a device, the operator did not see).
  const unsubscribe = gatewayLink.subscribe(() => {
    if (!hardwareAttached() && outputConfirm.getState().queue.length > 0)
      outputConfirm.setState({ queue: [] });
  });
  return () => {
    sim.getState().setValueGuard(undefined);
    unsubscribe();
    outputConfirm.setState({ queue: [] });
  };
}
