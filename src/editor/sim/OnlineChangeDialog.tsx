// Online change with hardware attached as controller: before the edit goes into the running
// program, say what it resets (instances and edge elements that start fresh) and ask.
import { ModalDialog } from '../files/ModalDialog';
import type { OnlineChangePlan } from '../../sim/protocol';

const MAX_LISTED = 12;

export function OnlineChangeDialog({ plan, onAnswer }: { readonly plan: OnlineChangePlan; readonly onAnswer: (apply: boolean) => void }) {
  const cancel = () => onAnswer(false);
  return (
    <ModalDialog
      role="alertdialog"
      titleId="rs-online-change-title"
      title="Apply the edit to the running program?"
      describedBy="rs-online-change-summary"
      testId="online-change-dialog"
      onClose={cancel}
      buttons={
        <>
          <button type="button" className="rs-button" autoFocus onClick={cancel} data-testid="online-change-cancel">
            Cancel
          </button>
          <button type="button" className="rs-button rs-primary" onClick={() => onAnswer(true)} data-testid="online-change-apply">
            Apply
          </button>
        </>
      }
    >
      <p id="rs-online-change-summary">
        Hardware is attached: the edit goes in at the next scan boundary and drives real outputs. It keeps the state
        of {plan.kept} instance{plan.kept === 1 ? '' : 's'} (function blocks and edge contacts and coils)
        {plan.reset.length === 0 ? ' and resets none' : ''}.
      </p>
      {plan.reset.length > 0 && (
        <>
          <p>
            {plan.reset.length === 1 ? 'This one starts' : `These ${plan.reset.length} start`} from the initial state (timers stopped,
            counters at 0, edge memories cleared):
          </p>
          <ul className="rs-load-errors" data-testid="online-change-resets">
            {plan.reset.slice(0, MAX_LISTED).map((r, i) => (
              <li key={i}>
                <code>{r.name}</code>: {r.reason}
              </li>
            ))}
            {plan.reset.length > MAX_LISTED && <li>… and {plan.reset.length - MAX_LISTED} more</li>}
          </ul>
        </>
      )}
      {plan.removed.length > 0 && <p>Deleted by the edit: {plan.removed.join(', ')}.</p>}
      <p>Cancel leaves the running program unchanged; the edit stays in the document.</p>
    </ModalDialog>
  );
}
