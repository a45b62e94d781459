// Devices (state and what their outputs hold), armed/disarmed with why, watchdog, Arm and Safe state.
// Safe state latches like STOP: the gateway refuses outputs until Arm, and a running simulation keeps
// running without re-arming by itself (only Arm, or a new Run / confirmed step, arms).
import { gatewayLink } from '../../bridge/gatewayLink';
import { armBlocker, disarmWords, outputsWords } from './armState';
import { hardwareStepping } from './useHardwareStepping';
import { useGateway } from './useGateway';

/** Safe state now; while stepping on hardware that also ends stepping, or its heartbeat would write the outputs again. */
function safeState(): void {
  if (hardwareStepping.snapshot().phase === 'stepping') hardwareStepping.end('stop');
  else gatewayLink.client?.stop();
}

const refusalWords = (code: string, ref: string | number | null) =>
  code === 'arm-refused' ? 'Arm refused' : code === 'disarmed' ? 'Outputs refused' : `Gateway refused ${String(ref ?? 'a message')}`;

const WATCHDOG_WORDS = { idle: 'idle (no outputs running)', fed: 'fed by the program (running, or stepping on hardware)', tripped: 'TRIPPED: outputs in safe state' } as const;

export function GatewayStatus() {
  const view = useGateway();
  if (view.link !== 'open') return null;
  const status = view.status;
  const controller = view.role === 'controller';
  const kinds = new Map(view.devices.map((d) => [d.id, d]));
  const blocker = armBlocker(view);
  const disarmed = disarmWords(view);
  return (
    <section className="rs-hw-section" aria-label="Gateway status">
      <table className="rs-hw-table" data-testid="hw-devices">
        <thead>
          <tr>
            <th>Device</th>
            <th>Where</th>
            <th>State</th>
            <th>Outputs</th>
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
              <td className={`rs-hw-outputs rs-hw-outputs-${d.outputs}`} data-testid="hw-device-outputs">
                {outputsWords(d)}
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
      {disarmed && (
        <p className="rs-hw-disarm" role="status" data-testid="hw-disarm">
          <strong>Outputs held in the safe state</strong>: {disarmed}
        </p>
      )}
      <div className="rs-hw-row">
        <button type="button" disabled={blocker !== null || status?.armed !== false} onClick={() => gatewayLink.bridge?.arm()} data-testid="hw-arm"
          title={blocker ?? (status?.armed ? 'Outputs are armed' : 'Let the program drive the outputs again')}>
          Arm
        </button>
        {blocker !== null && status?.armed === false && (
          <span className="rs-hw-warning" data-testid="hw-arm-blocked">
            Arm unavailable: {blocker}
          </span>
        )}
        <button type="button" disabled={!controller} onClick={safeState} data-testid="hw-safe"
          title="Write the safe state now (every output OFF unless configured hold)">
          Safe state
        </button>
        <button type="button" onClick={() => gatewayLink.client?.resync()} title="Ask the gateway for a full image">
          Resync
        </button>
      </div>
      {view.lastError && (
        <p className="rs-hw-problem" role="alert" data-testid="hw-last-error">
          {refusalWords(view.lastError.code, view.lastError.ref)}: {view.lastError.message.replace(/^outputs refused: /, '')}
        </p>
      )}
    </section>
  );
}
