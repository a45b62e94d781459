// Apply on request (issue 24): while the program running is not the one shown, a banner under the
// tool bar says so, with the number of edits, and offers Apply… (Alt+F8, CODESYS's key for login
// with online change), which lists the changes before anything is applied.
import { useEffect } from 'react';
import { useDocumentStore } from '../../store/documentStore';
import type { SimState } from '../../store/simState';
import { isModalOpen } from '../layout/useModal';
import { useSim, useSimStore } from './simContext';

const selectUnapplied = (s: SimState) => s.unapplied;
const selectConfirming = (s: SimState) => s.onlineChange?.kind === 'confirm';

/**
 * Apply on request: the running program is not the one shown. Says so as long as it is true, with
 * the number of edits, and offers Apply (Alt+F8, CODESYS's key for login with online change).
 */
export function UnappliedChanges() {
  const sim = useSimStore();
  const documents = useDocumentStore();
  const unapplied = useSim(selectUnapplied);
  const confirming = useSim(selectConfirming);
  const apply = () => sim.getState().applyChanges(documents.getState().project);
  useEffect(() => {
    if (!unapplied) return;
    const onKey = (e: KeyboardEvent) => {
      if (e.key !== 'F8' || !e.altKey || e.ctrlKey || e.metaKey || e.shiftKey || isModalOpen()) return;
      e.preventDefault();
      if (sim.getState().onlineChange?.kind !== 'confirm') sim.getState().applyChanges(documents.getState().project);
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [unapplied, sim, documents]);
  if (!unapplied) return null;
  const n = unapplied.count;
  return (
    <div className="rs-sim-unapplied" role="status" data-testid="sim-unapplied"
      title="The program running is not the one shown: the edits go in when you apply them">
      <span data-testid="sim-unapplied-text">Program changed — not applied ({n} edit{n === 1 ? '' : 's'})</span>
      <button type="button" className="rs-sim-btn rs-primary" aria-keyshortcuts="Alt+F8" disabled={confirming}
        title="Apply the changes to the running program (Alt+F8): lists them first" onClick={apply} data-testid="sim-apply">
        Apply…
      </button>
    </div>
  );
}

