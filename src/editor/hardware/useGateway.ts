// React view of the page's gateway link.
import { useSyncExternalStore } from 'react';
import type { GatewayView } from '../../bridge/GatewayClient';
import { gatewayLink } from '../../bridge/gatewayLink';

export function useGateway(): GatewayView {
  return useSyncExternalStore(gatewayLink.subscribe, gatewayLink.snapshot, gatewayLink.snapshot);
}
