// The simulation's overlay for the ladder canvas (src/editor/canvas/overlay.ts): power flow and
// live values per network, the elements whose variable is forced, and where the device's output
// differs from the program's, and the elements a "Why?" explanation names. Module-level and stable, as CanvasOverlayContext requires.
import { useMemo } from 'react';
import type { Network } from '../../model/project';
import type { NetworkOverlay } from '../canvas/overlay';
import { useNetworkDeviceMarks } from '../hardware/deviceMarks';
import { useNetworkWhyMarks } from '../history/whyMarks';
import { useNetworkForced, useNetworkLiveValues, useNetworkPower } from './useNetworkSim';
import { useNetworkPinValues } from './pinLiveValues';

export function useSimNetworkOverlay(network: Network): NetworkOverlay {
  const power = useNetworkPower(network);
  const liveValues = useNetworkLiveValues(network);
  const pinValues = useNetworkPinValues(network);
  const forced = useNetworkForced(network);
  const deviceMarks = useNetworkDeviceMarks(network);
  const why = useNetworkWhyMarks(network);
  // "Why?" tags share the marker channel with device values (a device mismatch wins on an element).
  const device = useMemo(() => (why ? new Map([...why, ...(deviceMarks ?? [])]) : deviceMarks), [why, deviceMarks]);
  return useMemo(
    () => ({
      ...(power ? { power } : {}),
      ...(liveValues ? { liveValues } : {}),
      ...(pinValues ? { pinValues } : {}),
      ...(forced ? { forced } : {}),
      ...(device ? { device } : {}),
    }),
    [power, liveValues, pinValues, forced, device],
  );
}
