// Devices, armed/watchdog state, re-arm and safe-state buttons.
import { gatewayLink } from '../../bridge/gatewayLink';
import { hardwareStepping } from './useHardwareStepping';
import { useGateway } from './useGateway';

/** Safe state now; while stepping on hardware that also ends stepping, or its heartbeat would write the outputs again. */
function safeState(): void {
  if (hardwareStepping.snapshot().phase === 'stepping') hardwareStepping.end('stop');
  else gatewayLink.client?.stop();
}

const WATCHDOG_WORDS = { idle: 'idle (no outputs running)', fed: 'fed by the program (running, or stepping on hardware)', tripped: 'TRIPPED: outputs in safe state' } as const;

export function GatewayStatus() {
  const view = useGateway();
  if (view.link !== 'open') return null;
  const status = view.status;
  const controller = view.role === 'controller';
  const kinds = new Map(view.devices.map((d) => [d.id, d]));
  return (
    <section className="rs-hw-section" aria-label="Gateway status">
      <table className="rs-hw-table" data-testid="hw-devices">
        <thead>
          <tr>
            <th>Device</th>
            <th>Where</th>
            <th>State</th>
          </tr>
        </thead>
        <tbody>
          {(status?.devices ?? []).map((d) => (
            <tr key={d.id} data-testid={`hw-device-${d.id}`}>
              <td>{d.id}</td>
              <td>{kinds.get(d.id)?.target ?? ''}</td>
              <td className={`rs-hw-state rs-hw-state-${d.state}`} title={d.error ?? undefined}>
                {d.state}
                {d.error ? `: ${d.error}` : ''}
              </td>
            </tr>
          ))}
        </tbody>
      </table>
      {status && (
        <p className="rs-hw-watchdog" data-testid="hw-watchdog">
          Outputs <strong>{status.armed ? 'armed' : 'disarmed'}</strong>; watchdog {status.watchdog.ms} ms, {WATCHDOG_WORDS[status.watchdog.state]}
          {status.watchdog.autoRearm ? ' (auto re-arm)' : ''}
        </p>
      )}
      <div className="rs-hw-row">
        <button type="button" disabled={!controller || status?.armed !== false} onClick={() => gatewayLink.client?.arm()} data-testid="hw-arm"
          title={controller ? 'Resume writing outputs after a watchdog trip' : 'Only the controller can re-arm'}>
          Re-arm
        </button>
        <button type="button" disabled={!controller} onClick={safeState} data-testid="hw-safe"
          title="Write the safe state now (every output OFF unless configured hold)">
          Safe state
        </button>
        <button type="button" onClick={() => gatewayLink.client?.resync()} title="Ask the gateway for a full image">
          Resync
        </button>
      </div>
      {view.lastError && (
        <p className="rs-hw-problem" data-testid="hw-last-error">
          Gateway refused {String(view.lastError.ref ?? 'a message')}: {view.lastError.message}
        </p>
      )}
    </section>
  );
}
