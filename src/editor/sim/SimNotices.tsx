// What went wrong, in the words of the rule ids and networks: a refused compile, a fault, a bad command.
import type { Diagnostic, Fault } from '../../engine/api';
import { describeOnlineChange, describeTransfer } from '../../sim/carryOver';
import type { SimState } from '../../store/simState';
import { Notice } from '../layout/Notice';
import { OnlineChangeDialog } from './OnlineChangeDialog';
import { UnappliedChanges } from './UnappliedChanges';
import { faultWords } from './position';
import { useSim, useSimStore } from './simContext';

const selectRefusal = (s: SimState) => s.refusal;
const selectFault = (s: SimState) => s.fault;
const selectNotice = (s: SimState) => s.notice;
const selectBreakpointAt = (s: SimState) => s.breakpointAt;
const selectMode = (s: SimState) => s.mode;
const selectOnlineChange = (s: SimState) => s.onlineChange;
const selectConfirmRequired = (s: SimState) => s.onlineConfirmRequired;

const where = (d: Pick<Diagnostic, 'network' | 'networkLabel' | 'line' | 'col'>) =>
  d.line !== undefined
    ? `line ${d.line}, column ${d.col ?? 1}`
    : d.network < 0
    ? 'variables'
    : `network ${d.network + 1}${d.networkLabel ? ` (${d.networkLabel})` : ''}`;

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
  const confirmRequired = useSim(selectConfirmRequired);
  const errors = refusal?.diagnostics.filter((d) => d.severity === 'error') ?? [];
  const dismissOnline = () => sim.getState().dismissOnlineChange();
  return (
    <>
      <UnappliedChanges />
      {refusal && (
        <Notice
          testId="sim-refusal"
          tone="error"
          token={refusal}
          onDismiss={() => sim.getState().dismissNotice()}
          text={
            refusal.online
              ? `Edit not applied: ${errors.length} error${errors.length === 1 ? '' : 's'}; the last good program keeps running.`
              : `Run refused: the program has ${errors.length} error${errors.length === 1 ? '' : 's'}.`
          }
        >
          <ul>
            {errors.slice(0, MAX_LISTED).map((d, i) => (
              <li key={i}>
                {d.rule} {d.pou} {where(d)}: {d.message}
              </li>
            ))}
            {errors.length > MAX_LISTED && <li>… and {errors.length - MAX_LISTED} more in the Problems list</li>}
          </ul>
        </Notice>
      )}
      {fault && mode === 'faulted' && (
        <Notice
          testId="sim-fault"
          tone="error"
          token={fault}
          text={`${describeFault(fault)} Press Reset or Warm restart to clear the fault.`}
        />
      )}
      {hit !== undefined && mode === 'paused' && (
        <Notice
          testId="sim-breakpoint-hit"
          tone="info"
          token={hit}
          text={`Paused at the breakpoint before network ${hit.network + 1} of ${hit.instance ? `${hit.instance} (${hit.pou})` : hit.pou}.`}
        />
      )}
      {online?.kind === 'confirm' && (
        <OnlineChangeDialog plan={online.plan} changes={online.changes} hardware={confirmRequired} onAnswer={(apply) => sim.getState().answerOnlineChange(apply)} />
      )}
      {online?.kind === 'pending' && (
        <Notice
          testId="sim-online-pending"
          tone="info"
          token={online}
          text={`Applying the edit online at the next scan boundary: ${describeTransfer(online.plan).replace(/^kept/, 'keeps')}.`}
        />
      )}
      {online?.kind === 'applied' && (
        <Notice
          testId="sim-online-applied"
          tone="info"
          token={online}
          onDismiss={dismissOnline}
          text={`${describeOnlineChange(online.scan, online.plan)}.`}
        />
      )}
      {online?.kind === 'cancelled' && (
        <Notice
          testId="sim-online-cancelled"
          tone="error"
          token={online}
          onDismiss={dismissOnline}
          text="Edit not applied online: the running program is unchanged (the edit stays in the document; Reset and Run load it)."
        />
      )}
      {notice && <Notice testId="sim-notice" tone="error" token={notice} onDismiss={() => sim.getState().dismissNotice()} text={notice} />}
    </>
  );
}
