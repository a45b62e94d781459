// Narrow hooks for the canvas: each element reads only its own power byte and live value, so a
// frame re-renders only the elements whose state changed. All return undefined when not simulating.
import type { StepFrame } from '../../engine/api';
import type { SimState } from '../../store/simState';
import { isForced, liveText } from './liveValues';
import { useSim } from './simContext';

/** Power-flow bits (api.ts NetworkPower): 1 = left side energised, 2 = right side energised, 4 = executed. */
export const POWER_IN = 1;
export const POWER_OUT = 2;
export const POWER_EXECUTED = 4;

export function useElementPower(elementId: string): number | undefined {
  return useSim((s) => {
    if (!s.live) return undefined;
    const i = s.elementIndex.get(elementId);
    return i === undefined ? undefined : s.elements[i];
  });
}

export function useVLinkPower(networkId: string, row: number, boundary: number): number | undefined {
  return useSim((s) => {
    if (!s.live) return undefined;
    const i = s.vlinkIndex.get(`${networkId}/${row}|${boundary}`);
    return i === undefined ? undefined : s.vlinks[i];
  });
}

/** Live value text of a variable or `Instance.PIN` (TRUE, T#1s200ms, 42), undefined when not simulating. */
export function useLiveText(name: string | undefined): string | undefined {
  return useSim((s) => (s.live && name ? liveText(s, name) : undefined));
}

export function useIsForced(name: string | undefined): boolean {
  return useSim((s) => (name ? isForced(s, name) : false));
}

const networkIndex = (s: SimState, networkId: string) => s.layout?.networkIds.indexOf(networkId) ?? -1;

/** Where execution stands for the debugger: the breakpoint it stopped at, or the next network of the innermost frame. */
export const stopOf = (s: SimState): StepFrame | undefined => s.breakpointAt ?? s.position.at(-1);

const same = (a: string | undefined, b: string | undefined) => (a ?? '').toUpperCase() === (b ?? '').toUpperCase();

/**
 * The network the debugger will execute next (stepping or stopped at a breakpoint), in the body the
 * canvas shows: the same POU and instance (inside an FB, the picked instance's call).
 */
export function useIsCurrentNetwork(networkId: string): boolean {
  return useSim((s) => {
    if (s.mode === 'running' || s.mode === 'stopped' || !s.live) return false;
    const stop = stopOf(s);
    const view = s.layout?.view;
    if (stop && view) return same(stop.pou, view.pou) && same(stop.instance, view.instance) && networkIndex(s, networkId) === stop.network;
    const current = s.breakpointHit ?? s.nextNetwork;
    return current >= 0 && networkIndex(s, networkId) === current;
  });
}

export function useHasBreakpoint(networkId: string): boolean {
  return useSim((s) => s.breakpoints.includes(networkId));
}

/** False when a jump or return skipped the network in the last scan (undefined in the middle of a scan). */
export function useNetworkExecuted(networkId: string): boolean | undefined {
  return useSim((s) => {
    if (!s.live || s.nextNetwork !== -1) return undefined;
    const n = networkIndex(s, networkId);
    return n < 0 ? undefined : s.executed[n] === 1;
  });
}

/**
 * Whether any network of the shown body ran in the last scan (undefined when not known): a body none
 * of whose networks ran was not executed at all (its task was not due in this tick, or nothing called it).
 */
export function useBodyRan(): boolean | undefined {
  return useSim((s) => {
    if (!s.live || s.nextNetwork !== -1 || !s.layout) return undefined;
    return s.layout.networkIds.some((_, i) => s.executed[i] === 1);
  });
}

/** True while the simulation has a program that is running or paused (editing applies as an online change). */
export const useSimActive = (): boolean => useSim((s) => s.mode !== 'stopped' || s.scan > 0);
