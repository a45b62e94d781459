// "Motor is used: delete it anyway?" with every place that uses it (POU, network, instance, task).
import type { Pou } from '../../model/project';
import { describeUse, type PouUse } from '../../store/pouEdits';
import { ModalDialog } from '../files/ModalDialog';
import { KIND_TITLES } from './pouWords';

export function DeletePouDialog({
  pou,
  uses,
  onCancel,
  onDelete,
}: {
  readonly pou: Pou;
  readonly uses: readonly PouUse[];
  readonly onCancel: () => void;
  readonly onDelete: () => void;
}) {
  return (
    <ModalDialog
      role="alertdialog"
      titleId="rs-delete-pou-title"
      title={`Delete ${KIND_TITLES[pou.kind].toLowerCase()} ${pou.name}?`}
      describedBy="rs-delete-pou-text"
      testId="delete-pou-dialog"
      onClose={onCancel}
      buttons={
        <>
          <button type="button" className="rs-button" autoFocus onClick={onCancel}>
            Cancel
          </button>
          <button
            type="button"
            className="rs-button rs-primary"
            data-testid="confirm-delete-pou"
            onClick={onDelete}
          >
            Delete {pou.name}
          </button>
        </>
      }
    >
      <p id="rs-delete-pou-text">
        {pou.name} is used in {uses.length} place{uses.length === 1 ? '' : 's'}. The calls and instances stay
        and the Problems list will report them; Undo brings {pou.name} back.
      </p>
      <ul className="rs-delete-uses" data-testid="pou-uses">
        {uses.map((u, i) => (
          <li key={i}>{describeUse(u)}</li>
        ))}
      </ul>
    </ModalDialog>
  );
}
