// Apply on request (issue 24): while the program running is not the one shown, a banner under the
// tool bar says so, with the number of edits, and offers Apply… (Alt+F8, CODESYS's key for login
// with online change; the key is the command sim.applyChanges in commands/simCommands.ts), which
// lists the changes before anything is applied.
import { useDocumentStore } from '../../store/documentStore';
import type { SimState } from '../../store/simState';
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

