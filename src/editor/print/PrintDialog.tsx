// The Print dialog: the open POU or the whole project, with or without the variable lists and the
// cross-reference, A4 landscape or portrait; then the print view. A PDF is made from the browser's
// print dialog ("Save as PDF"), as the dialog says.
import { useState } from 'react';
import { useStore } from 'zustand';
import { selectActivePou, useDocument } from '../../store/documentStore';
import { ModalDialog } from '../files/ModalDialog';
import { printState, type PaperOrientation } from './printState';

export function PrintDialog() {
  const pou = useDocument(selectActivePou);
  const pouCount = useDocument((s) => s.project.pous.length);
  const last = useStore(printState, (s) => s.last);
  const [whole, setWhole] = useState(last.whole || !pou);
  const [variables, setVariables] = useState(last.variables);
  const [crossReference, setCrossReference] = useState(last.crossReference);
  const [orientation, setOrientation] = useState<PaperOrientation>(last.orientation);
  const close = () => printState.getState().closeDialog();
  const open = () =>
    printState.getState().openView({
      scope: whole || !pou ? { kind: 'project' } : { kind: 'pou', pou: pou.id },
      variables,
      crossReference,
      orientation,
    });
  return (
    <ModalDialog
      role="dialog"
      titleId="rs-print-title"
      title="Print / Export PDF"
      describedBy="rs-print-pdf-note"
      testId="print-dialog"
      onClose={close}
      buttons={
        <>
          <button type="button" className="rs-button" onClick={close}>
            Cancel
          </button>
          <button type="button" className="rs-button rs-primary" autoFocus onClick={open} data-testid="print-preview">
            Print preview
          </button>
        </>
      }
    >
      <fieldset className="rs-print-options">
        <legend>Print</legend>
        <label>
          <input type="radio" name="rs-print-scope" checked={!whole} disabled={!pou} onChange={() => setWhole(false)} />
          {pou ? `The open POU, ${pou.name}` : 'The open POU (none is open)'}
        </label>
        <label>
          <input type="radio" name="rs-print-scope" checked={whole} onChange={() => setWhole(true)} />
          The whole project ({pouCount} POU{pouCount === 1 ? '' : 's'} and the global variables)
        </label>
      </fieldset>
      <fieldset className="rs-print-options">
        <legend>Include</legend>
        <label>
          <input type="checkbox" checked={variables} onChange={(e) => setVariables(e.target.checked)} />
          Variable list of each POU
        </label>
        <label>
          <input type="checkbox" checked={crossReference} onChange={(e) => setCrossReference(e.target.checked)} />
          Cross-reference at the end
        </label>
      </fieldset>
      <label className="rs-print-paper">
        Paper{' '}
        <select value={orientation} onChange={(e) => setOrientation(e.target.value as PaperOrientation)}>
          <option value="landscape">A4 landscape</option>
          <option value="portrait">A4 portrait</option>
        </select>
      </label>
      <p id="rs-print-pdf-note" className="rs-print-pdf-note">
        Every page carries a title block: project, POU, date and page number. To export a PDF, open the
        print preview, press Print and choose “Save as PDF” as the printer.
      </p>
    </ModalDialog>
  );
}
