// Online change that asks first (hardware attached as controller, or applied on request): what
// changes (networks changed, added, removed per POU, new variables), what it keeps and what starts
// from its initial state (with the reason), then Apply or Cancel.
import { ModalDialog } from '../files/ModalDialog';
import type { OnlineChangePlan } from '../../sim/protocol';
import { describeChanges, type ChangeList } from '../../sim/changeList';

const MAX_LISTED = 12;

export function OnlineChangeDialog({
  plan,
  changes,
  hardware,
  onAnswer,
}: {
  readonly plan: OnlineChangePlan;
  readonly changes?: ChangeList | undefined;
  readonly hardware: boolean;
  readonly onAnswer: (apply: boolean) => void;
}) {
  const cancel = () => onAnswer(false);
  const lines = changes ? describeChanges(changes) : [];
  return (
    <ModalDialog
      role="alertdialog"
      titleId="rs-online-change-title"
      title={changes ? 'Apply the changes to the running program?' : 'Apply the edit to the running program?'}
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
        {hardware
          ? 'Hardware is attached: the edit goes in at the next scan boundary and drives real outputs.'
          : 'The changes go in at the next scan boundary; the program runs on meanwhile.'}{' '}
        It keeps the state
        of {plan.kept} instance{plan.kept === 1 ? '' : 's'} (function blocks and edge contacts and coils)
        {plan.reset.length === 0 ? ' and resets none' : ''}.
      </p>
      {lines.length > 0 && (
        <>
          <p>Changes:</p>
          <ul className="rs-load-errors" data-testid="online-change-list">
            {lines.slice(0, MAX_LISTED).map((line, i) => (
              <li key={i}>{line}</li>
            ))}
            {lines.length > MAX_LISTED && <li>… and {lines.length - MAX_LISTED} more</li>}
          </ul>
        </>
      )}
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
