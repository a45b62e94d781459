// Program variables that are field I/O of the attached gateway: with hardware attached as controller
// a field input comes from the device (a click on the canvas must not write it; only an explicit,
// confirmed force overrides it), and a field output has a device value that may differ from the
// program's (paused: the device holds the safe state).
import type { GatewayView } from '../../bridge/GatewayClient';
import { gatewayLink } from '../../bridge/gatewayLink';
import { toWire } from '../../bridge/wireValues';
import type { Value } from '../../model/iecTypes';
import { canonicalAddress, type WireValue } from '../../protocol/points';
import type { SimVariable } from '../../sim/protocol';

/** This page drives the gateway's I/O (controller link open). */
export const hardwareAttached = (view: GatewayView = gatewayLink.snapshot()): boolean => view.link === 'open' && view.role === 'controller';

/** The gateway input point a program variable reads, when hardware is attached as controller. */
export function fieldInputAddress(variable: SimVariable | undefined, view: GatewayView = gatewayLink.snapshot()): string | undefined {
  if (!variable || variable.role !== 'input' || !variable.location || !hardwareAttached(view)) return undefined;
  const address = canonicalAddress(variable.location);
  return address && view.points.some((p) => p.address === address && p.dir === 'in') ? address : undefined;
}

/** "%IX0.0 Start comes from the device; force it to override." */
export const fieldInputWords = (address: string, name: string) => `${address} ${name} comes from the device; force it to override.`;

/**
 * The device's value of the output point a variable writes, as program text ("FALSE", "0"), when the
 * link is open and it differs from the program's value; undefined otherwise.
 */
export function deviceOutputDiff(variable: SimVariable | undefined, programValue: Value | undefined, view: GatewayView): WireValue | undefined {
  if (!variable?.location || programValue === undefined || view.link !== 'open') return undefined;
  const address = canonicalAddress(variable.location);
  const point = address ? view.points.find((p) => p.address === address && p.dir === 'out') : undefined;
  const device = point ? view.values[point.address] : undefined;
  if (!point || device === undefined) return undefined;
  return toWire(point.type, programValue) === device ? undefined : device;
}

/**
 * The device's value of the input point a variable reads, when the link is open and it differs from
 * the program's value; undefined otherwise. `fed`: the running program reads the device every scan
 * (they differ only until the next scan, so nothing is marked).
 */
export function deviceInputDiff(variable: SimVariable | undefined, programValue: Value | undefined, view: GatewayView, fed: boolean): WireValue | undefined {
  if (fed || !variable?.location || variable.role !== 'input' || programValue === undefined || view.link !== 'open') return undefined;
  const address = canonicalAddress(variable.location);
  const point = address ? view.points.find((p) => p.address === address && p.dir === 'in') : undefined;
  const device = point ? view.values[point.address] : undefined;
  if (!point || device === undefined) return undefined;
  return toWire(point.type, programValue) === device ? undefined : device;
}

export const deviceText = (v: WireValue): string => (typeof v === 'boolean' ? (v ? 'TRUE' : 'FALSE') : String(v));

/**
 * The gateway output point a program variable writes, when hardware is attached as controller: a
 * write or force of it drives a real output, so it asks to confirm first (outputForce.ts).
 */
export function fieldOutputAddress(variable: SimVariable | undefined, view: GatewayView = gatewayLink.snapshot()): string | undefined {
  if (!variable?.location || !hardwareAttached(view)) return undefined;
  const address = canonicalAddress(variable.location);
  return address && view.points.some((p) => p.address === address && p.dir === 'out') ? address : undefined;
}
