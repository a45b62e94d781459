// Stepping with hardware attached: the confirmation dialog (mounted once by HardwareSimLink) and
// the badge, in the notice band under the tool bar, that shows the lease and watchdog while
// stepping drives real outputs (and why a running program's outputs are not driven).
import { useId, type ReactNode } from 'react';
import type { StepRequest } from '../../bridge/steppingLease';
import type { GatewayView } from '../../bridge/GatewayClient';
import type { StatusMessage } from '../../protocol/messages';
import { gatewayLink } from '../../bridge/gatewayLink';
import type { SimState } from '../../store/simState';
import { useSim } from '../sim/simContext';
import { armBlocker, disarmWords } from './armState';
import { hardwareStepping, useSteppingView } from './useHardwareStepping';
import { useGateway } from './useGateway';
import { useModal } from '../layout/useModal';
import './hardware.css';

const WATCHDOG_STATE = { idle: 'idle', fed: 'fed', tripped: 'TRIPPED' } as const;

const stepWords = (r: StepRequest): string =>
  r.kind === 'network' ? 'one network' : r.scans === 1 ? 'one scan' : `${r.scans} scans`;

/** "Outputs armed; watchdog 1000 ms, fed" in the gateway's terms, with why when disarmed. */
function WatchdogLine({ status }: { status: StatusMessage | null }) {
  if (!status) return <span data-testid="hw-step-watchdog">Watchdog state not reported yet</span>;
  return (
    <span data-testid="hw-step-watchdog" className={status.armed ? undefined : 'rs-hw-error'}>
      Outputs <strong>{status.armed ? 'armed' : 'disarmed'}</strong>; watchdog {status.watchdog.ms} ms, {WATCHDOG_STATE[status.watchdog.state]}
    </span>
  );
}

/** The operator's Arm: disabled, with the reason, when a device is not online or this page is not the controller. */
function ArmButton({ view, testId }: { view: GatewayView; testId: string }) {
  if (view.status?.armed !== false) return null;
  const blocker = armBlocker(view);
  return (
    <button type="button" disabled={blocker !== null} onClick={() => gatewayLink.bridge?.arm()} data-testid={testId}
      title={blocker ?? 'Let the program drive the outputs again'}>
      Arm
    </button>
  );
}

export function SteppingConfirmDialog() {
  const view = useSteppingView();
  if (view.phase !== 'confirming' || !view.request) return null;
  return <SteppingConfirmBox request={view.request} />;
}

function SteppingConfirmBox({ request }: { readonly request: StepRequest }) {
  const gateway = useGateway();
  const { status } = gateway;
  const titleId = useId();
  const textId = useId();
  const modal = useModal(() => hardwareStepping.decline());

  return (
    <div className="rs-hw-backdrop" onMouseDown={(e) => e.target === e.currentTarget && hardwareStepping.decline()}>
      <div {...modal} className="rs-hw-dialog" role="alertdialog" aria-modal="true" aria-labelledby={titleId} aria-describedby={textId}
        data-testid="hw-step-confirm">
        <h2 id={titleId}>Step with real outputs?</h2>
        <div id={textId}>
          <p>
            This page is the gateway&apos;s controller. Stepping {stepWords(request)} now <strong>drives the real outputs</strong>: each
            step reads the gateway&apos;s current inputs, runs the scan and writes its outputs to the devices. The outputs of the last scan
            are written again at once.
          </p>
          <p>
            Between steps the lease is kept fed, so the outputs stay as the last scan left them until you Run, Reset, disconnect or end
            stepping (which writes the safe state).
          </p>
          <p>
            <WatchdogLine status={status} />
          </p>
          {status?.armed === false && (
            <p data-testid="hw-step-disarmed">
              The outputs are held in the safe state ({disarmWords(gateway)}). Confirming arms them.
              {armBlocker(gateway) !== null && <span className="rs-hw-error"> The gateway will refuse: {armBlocker(gateway)}.</span>}
            </p>
          )}
        </div>
        <div className="rs-hw-dialog-buttons">
          {/* The safe answer has the focus. */}
          <button type="button" autoFocus onClick={() => hardwareStepping.decline()} data-testid="hw-step-cancel">
            Cancel
          </button>
          <button type="button" className="rs-hw-danger" onClick={() => hardwareStepping.confirm()} data-testid="hw-step-ok">
            Step and drive outputs
          </button>
        </div>
      </div>
    </div>
  );
}

const selectRunning = (s: SimState) => s.mode === 'running';

/** "Outputs not driven — why", with what to do (Arm), in the notice band under the tool bar. */
function RunBadge({ testId, reason, children }: { testId: string; reason: string; children?: ReactNode }) {
  return (
    <span className="rs-hw-running-disarmed" role="status" data-testid={testId}>
      <strong>Outputs not driven</strong>{' '}
      <span className="rs-hw-reason">— {reason}</span>
      {children}
    </span>
  );
}

/**
 * In the notice band under the tool bar (the one-line tool bar has no room left for it: the reason
 * and Arm were past the window's edge): while stepping drives the hardware; and while the
 * simulation runs as controller with the outputs disarmed (Safe state, arm refused, a device
 * lost...): it keeps running in the browser, the outputs stay safe, and only the operator's Arm
 * drives them again.
 */
export function SteppingBadge() {
  const view = useSteppingView();
  const gateway = useGateway();
  const { status } = gateway;
  const running = useSim(selectRunning);
  if (view.phase !== 'stepping') {
    if (running && (gateway.link === 'retrying' || gateway.link === 'refused')) {
      // The simulation runs on, but never as if it still drove the hardware.
      return (
        <RunBadge testId="hw-run-link-lost" reason={`hardware link ${gateway.link === 'refused' ? 'refused' : 'lost'}: ${gateway.problem ?? 'no connection to the gateway'}`} />
      );
    }
    if (running && gateway.link === 'open' && gateway.role === 'observer') {
      // Asked as controller while another page held the lease, a page is an observer: what it runs is not what drives the hardware.
      return (
        <RunBadge
          testId="hw-run-observer"
          reason={`this page is connected as observer (read only)${status?.controller ? '; another page is the controller' : ''}. Disconnect and connect as controller to drive them.`}
        />
      );
    }
    if (!running || gateway.link !== 'open' || gateway.role !== 'controller' || status?.armed !== false) return null;
    return (
      <RunBadge testId="hw-run-disarmed" reason={disarmWords(gateway) ?? 'the gateway is disarmed'}>
        <ArmButton view={gateway} testId="hw-run-arm" />
      </RunBadge>
    );
  }
  return (
    <span className="rs-hw-stepping" role="status" data-testid="hw-stepping">
      <strong>Stepping on hardware</strong> <WatchdogLine status={status} />
      <ArmButton view={gateway} testId="hw-step-arm" />
      <button type="button" onClick={() => hardwareStepping.end('stop')} data-testid="hw-step-end"
        title="Leave hardware stepping: the gateway writes the safe state">
        End (safe state)
      </button>
    </span>
  );
}
