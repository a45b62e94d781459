// What went wrong, in the words of the rule ids and networks: a refused compile, a fault, a bad command.
import type { Diagnostic, Fault } from '../../engine/api';
import { describeOnlineChange, describeTransfer } from '../../sim/carryOver';
import type { SimState } from '../../store/simStore';
import { OnlineChangeDialog } from './OnlineChangeDialog';
import { faultWords } from './position';
import { useSim, useSimStore } from './simContext';

const selectRefusal = (s: SimState) => s.refusal;
const selectFault = (s: SimState) => s.fault;
const selectNotice = (s: SimState) => s.notice;
const selectBreakpointAt = (s: SimState) => s.breakpointAt;
const selectMode = (s: SimState) => s.mode;
const selectOnlineChange = (s: SimState) => s.onlineChange;

const where = (d: Pick<Diagnostic, 'network' | 'networkLabel'>) =>
  d.network < 0 ? 'variables' : `network ${d.network + 1}${d.networkLabel ? ` (${d.networkLabel})` : ''}`;

/** A fault in words, naming the instance and POU inside a body (position.ts). */
export const describeFault = (f: Fault) => faultWords(f);

const MAX_LISTED = 5;

export function SimNotices() {
  const sim = useSimStore();
  const refusal = useSim(selectRefusal);
  const fault = useSim(selectFault);
  const notice = useSim(selectNotice);
  const hit = useSim(selectBreakpointAt);
  const mode = useSim(selectMode);
  const online = useSim(selectOnlineChange);
  const errors = refusal?.diagnostics.filter((d) => d.severity === 'error') ?? [];
  return (
    <>
      {refusal && (
        <div className="rs-sim-notice rs-sim-error" role="alert" data-testid="sim-refusal">
          <b>
            {refusal.online
              ? `Edit not applied: ${errors.length} error${errors.length === 1 ? '' : 's'}; the last good program keeps running.`
              : `Run refused: the program has ${errors.length} error${errors.length === 1 ? '' : 's'}.`}
          </b>
          <ul>
            {errors.slice(0, MAX_LISTED).map((d, i) => (
              <li key={i}>
                {d.rule} {d.pou} {where(d)}: {d.message}
              </li>
            ))}
            {errors.length > MAX_LISTED && <li>… and {errors.length - MAX_LISTED} more in the Problems list</li>}
          </ul>
          <button type="button" className="rs-sim-btn" onClick={() => sim.getState().dismissNotice()}>
            Dismiss
          </button>
        </div>
      )}
      {fault && mode === 'faulted' && (
        <div className="rs-sim-notice rs-sim-error" role="alert" data-testid="sim-fault">
          <b>{describeFault(fault)}</b> Press Reset or Warm restart to clear the fault.
        </div>
      )}
      {hit !== undefined && mode === 'paused' && (
        <div className="rs-sim-notice" role="status" data-testid="sim-breakpoint-hit">
          Paused at the breakpoint before network {hit.network + 1} of {hit.instance ? `${hit.instance} (${hit.pou})` : hit.pou}.
        </div>
      )}
      {online?.kind === 'confirm' && <OnlineChangeDialog plan={online.plan} onAnswer={(apply) => sim.getState().answerOnlineChange(apply)} />}
      {online?.kind === 'pending' && (
        <div className="rs-sim-notice" role="status" data-testid="sim-online-pending">
          Applying the edit online at the next scan boundary: {describeTransfer(online.plan).replace(/^kept/, 'keeps')}.
        </div>
      )}
      {online?.kind === 'applied' && (
        <div className="rs-sim-notice" role="status" data-testid="sim-online-applied">
          {describeOnlineChange(online.scan, online.plan)}.{' '}
          <button type="button" className="rs-sim-btn" onClick={() => sim.getState().dismissOnlineChange()}>
            Dismiss
          </button>
        </div>
      )}
      {online?.kind === 'cancelled' && (
        <div className="rs-sim-notice rs-sim-error" role="status" data-testid="sim-online-cancelled">
          Edit not applied online: the running program is unchanged (the edit stays in the document; Reset and Run load it).{' '}
          <button type="button" className="rs-sim-btn" onClick={() => sim.getState().dismissOnlineChange()}>
            Dismiss
          </button>
        </div>
      )}
      {notice && (
        <div className="rs-sim-notice rs-sim-error" role="alert" data-testid="sim-notice">
          {notice}{' '}
          <button type="button" className="rs-sim-btn" onClick={() => sim.getState().dismissNotice()}>
            Dismiss
          </button>
        </div>
      )}
    </>
  );
}
