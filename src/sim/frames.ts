// Builds the frames the worker posts to the UI: packed power bytes (transferable) and values.
import type { NetworkPower, Plc } from '../engine/api';
import type { Value } from '../model/iecTypes';
import type { SimLayout } from './protocol';

export interface PackedPower {
  readonly elements: Uint8Array;
  readonly vlinks: Uint8Array;
  readonly executed: Uint8Array;
}

/** Copies the PLC's power snapshot into three fresh arrays laid out by `layout` (fresh so they can be transferred). */
export function packPower(plc: Plc, layout: SimLayout): PackedPower {
  return packNetworks(plc.snapshot().networks, layout);
}

/** Packs per-network power (a snapshot's, or a recorded scan's decoded) by `layout`. */
export function packNetworks(networks: readonly NetworkPower[], layout: SimLayout): PackedPower {
  const networkCount = layout.networkIds.length;
  const elements = new Uint8Array(layout.elementOffsets[networkCount] ?? 0);
  const vlinks = new Uint8Array(layout.vlinkOffsets[networkCount] ?? 0);
  const executed = new Uint8Array(networkCount);
  const count = Math.min(networkCount, networks.length);
  for (let n = 0; n < count; n++) {
    const power = networks[n]!;
    const eStart = layout.elementOffsets[n]!;
    const eEnd = layout.elementOffsets[n + 1]!;
    elements.set(power.elements.length > eEnd - eStart ? power.elements.subarray(0, eEnd - eStart) : power.elements, eStart);
    const vStart = layout.vlinkOffsets[n]!;
    const vEnd = layout.vlinkOffsets[n + 1]!;
    vlinks.set(power.vlinks.length > vEnd - vStart ? power.vlinks.subarray(0, vEnd - vStart) : power.vlinks, vStart);
    executed[n] = power.executed ? 1 : 0;
  }
  return { elements, vlinks, executed };
}

/** Current values of every name in the layout, in layout order. */
export function readValues(plc: Plc, layout: SimLayout): Value[] {
  const out: Value[] = new Array<Value>(layout.variables.length);
  for (let i = 0; i < layout.variables.length; i++) out[i] = plc.read(layout.variables[i]!.name);
  return out;
}

/** True when two output images differ (same keys are expected; a new key counts as a change). */
export function outputsChanged(a: Readonly<Record<string, Value>> | undefined, b: Readonly<Record<string, Value>>): boolean {
  if (!a) return true;
  const keys = Object.keys(b);
  if (keys.length !== Object.keys(a).length) return true;
  for (const k of keys) if (a[k] !== b[k]) return true;
  return false;
}
