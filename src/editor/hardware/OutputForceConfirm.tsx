// The confirmation before a write or force of a field output drives a real output (outputForce.ts).
// Mounted once, by HardwareSimLink. Cancel has the focus; Escape and a press outside also cancel.
import { useId } from 'react';
import { useStore } from 'zustand';
import type { SimState } from '../../store/simState';
import { useSim } from '../sim/simContext';
import { useModal } from '../layout/useModal';
import { answerOutputConfirm, outputConfirm, type OutputConfirmRequest } from './outputForce';
import { useGateway } from './useGateway';
import { useSteppingView } from './useHardwareStepping';
import './hardware.css';

export function OutputForceConfirm() {
  const first = useStore(outputConfirm, (s) => s.queue[0]);
  return first ? <OutputForceBox key={`${first.kind}:${first.name}:${first.value}`} request={first} /> : null;
}

const selectRunning = (s: SimState) => s.mode === 'running';

function OutputForceBox({ request }: { readonly request: OutputConfirmRequest }) {
  const titleId = useId();
  const textId = useId();
  const modal = useModal(() => answerOutputConfirm(false));
  const running = useSim(selectRunning);
  const armed = useGateway().status?.armed !== false;
  const stepping = useSteppingView().phase === 'stepping';
  const { kind, name, address, device, value } = request;
  const verb = kind === 'force' ? 'Force' : 'Write';
  return (
    <div
      className="rs-hw-backdrop"
      onMouseDown={(e) => e.target === e.currentTarget && answerOutputConfirm(false)}
    >
      <div
        {...modal}
        className="rs-hw-dialog"
        role="alertdialog"
        aria-modal="true"
        aria-labelledby={titleId}
        aria-describedby={textId}
        data-testid="hw-output-confirm"
      >
        <h2 id={titleId} data-testid="hw-output-confirm-title">
          {verb} real output {name} ({address}) to {value}?
        </h2>
        <div id={textId}>
          <p>
            {name} is output <strong>{address}</strong> of device <strong>{device}</strong>.{' '}
            {kind === 'force'
              ? `Forcing it holds it at ${value} whatever the program does, until you unforce it: what it drives (a motor, a valve, a heater) moves.`
              : `Writing it sets it to ${value} once; the program's next scan writes it again if it drives it.`}
          </p>
          <p className="rs-hw-error">
            Forcing or writing a real output can cause injury or damage. Make sure the machine is safe for it.
          </p>
          <p data-testid="hw-output-confirm-when">
            {stepping
              ? 'Stepping drives the outputs: the device gets it at the next step.'
              : running && armed
                ? 'The program drives the outputs: the device gets it at the next scan.'
                : 'The outputs are held in the safe state now: the device gets it as soon as the program drives them (Run, or Arm).'}
          </p>
        </div>
        <div className="rs-hw-dialog-buttons">
          {/* The safe answer has the focus. */}
          <button
            type="button"
            autoFocus
            onClick={() => answerOutputConfirm(false)}
            data-testid="hw-output-cancel"
          >
            Cancel
          </button>
          <button
            type="button"
            className="rs-hw-danger"
            onClick={() => answerOutputConfirm(true)}
            data-testid="hw-output-ok"
          >
            {verb} {address} to {value}
          </button>
        </div>
      </div>
    </div>
  );
}
