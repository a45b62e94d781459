// Per-network simulation overlay for the canvas: the network's power bytes (NetworkPower, aligned
// with the document's elements and vlinks, matched by id so an edited network never shows the
// wrong bytes) and the live value text of each element. Each hook's selector returns a string, so
// a network re-renders only when its own state changed.
import { useMemo } from 'react';
import type { NetworkPower } from '../../engine/api';
import type { LdElement } from '../../model/elements';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import { selectLibrary, useDocument } from '../../store/documentStore';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import type { SimState } from '../../store/simState';
import { canvasName, isForced, liveText } from './liveValues';
import { useSim } from './simContext';

function powerKey(s: SimState, network: Network): string {
  if (!s.live || !s.layout) return '';
  // Power of another body than the layout's (a view change in flight) is never drawn.
  if (s.elements.length !== s.layout.elementOffsets[s.layout.networkIds.length]) return '';
  const n = s.layout.networkIds.indexOf(network.id);
  if (n < 0) return '';
  let key = s.executed[n] ? '1' : '0';
  for (const el of network.elements) {
    const i = s.elementIndex.get(el.id);
    key += String.fromCharCode(i === undefined ? 0 : (s.elements[i] ?? 0));
  }
  key += ':';
  for (const v of network.vlinks) {
    const i = s.vlinkIndex.get(`${network.id}/${v.row}|${v.boundary}`);
    key += String.fromCharCode(i === undefined ? 0 : (s.vlinks[i] ?? 0));
  }
  return key;
}

/** The network's power flow, or undefined when not simulating (or the network is not in the running program). */
export function useNetworkPower(network: Network): NetworkPower | undefined {
  const key = useSim((s) => powerKey(s, network));
  return useMemo(() => {
    if (!key) return undefined;
    const colon = key.indexOf(':', 1 + network.elements.length);
    const elements = Uint8Array.from(key.slice(1, colon), (c) => c.charCodeAt(0));
    const vlinks = Uint8Array.from(key.slice(colon + 1), (c) => c.charCodeAt(0));
    return { elements, vlinks, executed: key[0] === '1' };
  }, [key, network.elements.length]);
}

const FORCED_MARK = ' [F]';

/** The live text of an operand of the shown body (read in the monitored instance), marked when forced. */
const operandText = (s: SimState, operand: string): string | undefined => {
  const name = canvasName(s, operand);
  const text = name === undefined ? undefined : liveText(s, name);
  return text === undefined ? undefined : isForced(s, name!) ? `${text}${FORCED_MARK}` : text;
};

/**
 * Text shown under a contact or coil while simulating: its variable's state, read in the monitored
 * body. A box shows its values beside its pins instead (pinLiveValues.ts).
 */
export function elementLiveText(s: SimState, el: LdElement, _library?: BlockLibrary): string | undefined {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return el.variable ? operandText(s, el.variable) : undefined;
    case 'box':
      // A box's values stand beside its pins (pinLiveValues.ts), not under it.
      return undefined;
    case 'link':
    case 'jump':
    case 'return':
    case 'connector':
    case 'continuation':
      return undefined;
  }
}

function liveKey(s: SimState, network: Network, library: BlockLibrary): string {
  if (!s.live) return '';
  const entries: [string, string][] = [];
  for (const el of network.elements) {
    const text = elementLiveText(s, el, library);
    if (text !== undefined) entries.push([el.id, text]);
  }
  return entries.length > 0 ? JSON.stringify(entries) : '';
}

/** True when the element's variable, or one of the outputs it shows, is forced. */
export function elementForced(s: SimState, el: LdElement, library: BlockLibrary = STANDARD_LIBRARY): boolean {
  const forced = (operand: string) => {
    const name = operand ? canvasName(s, operand) : undefined;
    return name !== undefined && isForced(s, name);
  };
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return forced(el.variable);
    case 'box': {
      const signature = library.signature(el.blockType);
      if (signature?.kind === 'fb' && el.instance) {
        const instance = el.instance;
        return signature.outputs.some((pin) => forced(`${instance}.${pin.name}`));
      }
      return Object.values(el.outputs).some((target) => Boolean(target) && forced(target));
    }
    case 'link':
    case 'jump':
    case 'return':
    case 'connector':
    case 'continuation':
      return false;
  }
}

function forcedKey(s: SimState, network: Network, library: BlockLibrary): string {
  if (s.forced.size === 0) return '';
  return network.elements
    .filter((el) => elementForced(s, el, library))
    .map((el) => el.id)
    .join('\n');
}

/** Ids of the network's elements with a forced variable, or undefined when none is forced. */
export function useNetworkForced(network: Network): ReadonlySet<ElementId> | undefined {
  const library = useDocument(selectLibrary);
  const key = useSim((s) => forcedKey(s, network, library));
  return useMemo(() => (key ? new Set(key.split('\n') as ElementId[]) : undefined), [key]);
}

/** Live value text by element id, or undefined when not simulating. */
export function useNetworkLiveValues(network: Network): ReadonlyMap<ElementId, string> | undefined {
  const library = useDocument(selectLibrary);
  const key = useSim((s) => liveKey(s, network, library));
  return useMemo(() => (key ? new Map(JSON.parse(key) as [ElementId, string][]) : undefined), [key]);
}
