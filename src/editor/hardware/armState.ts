// Why the gateway's outputs are disarmed, and whether this page may arm them, in plain words for the
// Hardware panel, the stepping dialog and the toolbar badge.
import type { GatewayView } from '../../bridge/GatewayClient';
import type { DeviceOutputs, DeviceStatus, DisarmCause } from '../../protocol/messages';

export const CAUSE_WORDS: Record<DisarmCause, string> = {
  start: 'not armed since the gateway started',
  stop: 'STOP or Safe state',
  watchdog: 'watchdog trip',
  'controller-lost': 'the controller disconnected',
  'device-lost': 'a device was lost',
  shutdown: 'the gateway is shutting down',
  'other-master': 'another Modbus master is writing the outputs',
};

export const OUTPUTS_WORDS: Record<DeviceOutputs, string> = {
  driven: 'driven by the program',
  safe: 'safe state',
  'safe-pending': 'safe state pending (not acknowledged yet)',
};

/** What a device's outputs hold, with how long a safe state has been pending and another master seen. */
export function outputsWords(d: DeviceStatus): string {
  if (d.conflict) return `not written by this gateway: ${d.conflict}`;
  if (d.outputs === 'safe-pending' && typeof d.safePendingMs === 'number' && d.safePendingMs >= 1000) {
    return `safe state pending for ${Math.floor(d.safePendingMs / 1000)} s (not acknowledged yet)`;
  }
  return OUTPUTS_WORDS[d.outputs];
}

/** Null when this page can arm the gateway now; else why not. */
export function armBlocker(view: GatewayView): string | null {
  if (view.link !== 'open') return 'not connected';
  if (view.role !== 'controller') return 'only the controller can arm';
  const down = (view.status?.devices ?? []).filter((d) => d.state !== 'online');
  if (down.length > 0) return `device ${down.map((d) => `"${d.id}" is ${d.state}`).join(', ')}: arm when it is online`;
  return null;
}

/** "stop at 12:03:04: STOP (…): outputs are held in the safe state until …" */
export function disarmWords(view: GatewayView): string | null {
  const d = view.status?.disarm;
  if (!d || view.status?.armed) return null;
  return `${CAUSE_WORDS[d.cause]} (${new Date(d.at).toLocaleTimeString()}): ${d.message}`;
}
