// The simulation's overlay for the ladder canvas (src/editor/canvas/overlay.ts): power flow and
// live values per network, and the elements whose variable is forced. Module-level and stable, as CanvasOverlayContext requires.
import { useMemo } from 'react';
import type { Network } from '../../model/project';
import type { NetworkOverlay } from '../canvas/overlay';
import { useNetworkForced, useNetworkLiveValues, useNetworkPower } from './useNetworkSim';

export function useSimNetworkOverlay(network: Network): NetworkOverlay {
  const power = useNetworkPower(network);
  const liveValues = useNetworkLiveValues(network);
  const forced = useNetworkForced(network);
  return useMemo(
    () => ({ ...(power ? { power } : {}), ...(liveValues ? { liveValues } : {}), ...(forced ? { forced } : {}) }),
    [power, liveValues, forced],
  );
}
