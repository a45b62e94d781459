// Mounted once by the shell: the Print dialog, then the print view of what it chose. The view
// prints the project as it was when the view opened.
import { useMemo } from 'react';
import { useStore } from 'zustand';
import { useDocumentStore } from '../../store/documentStore';
import { useUi } from '../../store/uiStore';
import { PrintDialog } from './PrintDialog';
import { printState } from './printState';
import { PrintView } from './PrintView';

export function PrintHost() {
  const doc = useDocumentStore();
  const dialog = useStore(printState, (s) => s.dialog);
  const view = useStore(printState, (s) => s.view);
  const symbolComments = useUi((s) => s.symbolComments);
  // eslint-disable-next-line react-hooks/exhaustive-deps -- a snapshot per opened view
  const project = useMemo(() => doc.getState().project, [view, doc]);
  return (
    <>
      {dialog && <PrintDialog />}
      {view && <PrintView
          project={project}
          options={view}
          symbolComments={symbolComments}
          onClose={() => printState.getState().closeView()}
        />}
    </>
  );
}
