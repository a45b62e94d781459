// Extension point for the simulation: a hook that gives a network's power flow and live values.
// Provide it with <CanvasOverlayContext.Provider value={useMyOverlay}> (a stable, module-level
// hook: it is called once per visible network on every render). Without a provider the canvas
// shows no power flow.
import { createContext, useContext } from 'react';
import type { NetworkPower } from '../../engine/api';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import type { PinTexts } from './drawPinValues';

export interface NetworkOverlay {
  /** Power flow aligned with network.elements / network.vlinks (api.ts NetworkPower). */
  readonly power?: NetworkPower;
  /** Text shown under an element, e.g. a timer's ET. */
  readonly liveValues?: ReadonlyMap<ElementId, string>;
  /** Values beside box pins (operands, data lines between blocks), by box id. */
  readonly pinValues?: ReadonlyMap<ElementId, PinTexts>;
  /** Elements whose variable (or an output) is forced: drawn marked in the theme's forced colour. */
  readonly forced?: ReadonlySet<ElementId>;
  /** Elements whose I/O point holds another value on the device than in the program: the marker text ("device: FALSE"). */
  readonly device?: ReadonlyMap<ElementId, string>;
}

export type NetworkOverlayHook = (network: Network, index: number) => NetworkOverlay;

const NO_OVERLAY: NetworkOverlay = {};
const noOverlay: NetworkOverlayHook = () => NO_OVERLAY;

export const CanvasOverlayContext = createContext<NetworkOverlayHook>(noOverlay);

export const useOverlayHook = (): NetworkOverlayHook => useContext(CanvasOverlayContext);
