// "device: FALSE" next to a contact or coil whose output point holds another value on the device than
// the program's (paused on hardware: the program says TRUE, the device holds the safe state), so the
// canvas and the Watch panel never show only the program's side. Text, not only colour.
// Inputs likewise: paused (or not fed by this page), an input that changed on the device since the
// program last read it shows the device's value next to the program's stale one.
import { useMemo } from 'react';
import type { GatewayView } from '../../bridge/GatewayClient';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import type { SimState } from '../../store/simState';
import { useSim } from '../sim/simContext';
import { deviceInputDiff, deviceOutputDiff, deviceText } from './fieldIo';
import { useGateway } from './useGateway';

/** The marker for a variable, or undefined when the device agrees (or there is no device value). */
export function deviceMark(s: SimState, name: string, view: GatewayView): string | undefined {
  const i = s.variableIndex.get(name.toUpperCase());
  if (i === undefined || !s.live) return undefined;
  const variable = s.layout?.variables[i];
  // A running program that drives the hardware reads its inputs every scan: no stale input to mark.
  const fed = s.mode === 'running' && view.role === 'controller';
  const diff = deviceOutputDiff(variable, s.values[i], view) ?? deviceInputDiff(variable, s.values[i], view, fed);
  return diff === undefined ? undefined : `device: ${deviceText(diff)}`;
}

/** Marker text by element id for a network's contacts and coils. */
export function deviceMarks(s: SimState, network: Network, view: GatewayView): [ElementId, string][] {
  if (!s.live || view.link !== 'open') return [];
  const out: [ElementId, string][] = [];
  for (const el of network.elements) {
    if ((el.kind !== 'contact' && el.kind !== 'coil') || !el.variable) continue;
    const mark = deviceMark(s, el.variable, view);
    if (mark) out.push([el.id, mark]);
  }
  return out;
}

/** The network's device markers for the canvas overlay, or undefined when none. */
export function useNetworkDeviceMarks(network: Network): ReadonlyMap<ElementId, string> | undefined {
  const view = useGateway();
  const key = useSim((s) => {
    const marks = deviceMarks(s, network, view);
    return marks.length > 0 ? JSON.stringify(marks) : '';
  });
  return useMemo(() => (key ? new Map(JSON.parse(key) as [ElementId, string][]) : undefined), [key]);
}

/** The device marker of one variable (Watch panel). */
export function useDeviceMark(name: string): string | undefined {
  const view = useGateway();
  return useSim((s) => deviceMark(s, name, view));
}
