// Editing while the simulation runs is an online change: the edited document is compiled and, if it
// has no errors, swapped in at the next scan boundary. Variables keep their values by name, FB
// instances by name and type, edge memories by element id; what is new starts fresh, and the
// notice lists it. With the gateway attached as controller the worker first asks (Apply / Cancel).
// If it has errors, the last good program keeps running and the errors are shown. Opening another
// project (new POU ids) is not an edit: the simulation stops and forgets the old program.
import { useEffect } from 'react';
import { gatewayLink } from '../../bridge/gatewayLink';
import { useDocumentStore } from '../../store/documentStore';
import { useSimStore } from './simContext';

const DEBOUNCE_MS = 300;

export function useOnlineChange(): void {
  const documents = useDocumentStore();
  const sim = useSimStore();
  useEffect(() => {
    let timer: ReturnType<typeof setTimeout> | undefined;
    const unsubscribe = documents.subscribe((state, previous) => {
      if (state.project === previous.project) return;
      const s = sim.getState();
      if (!s.layout) return;
      const samePous = state.project.pous.some((p) => previous.project.pous.some((q) => q.id === p.id));
      if (!samePous) {
        clearTimeout(timer);
        s.unload();
        return;
      }
      if (s.mode === 'stopped' && s.scan === 0) return;
      clearTimeout(timer);
      timer = setTimeout(() => sim.getState().documentChanged(documents.getState().project), DEBOUNCE_MS);
    });
    return () => {
      clearTimeout(timer);
      unsubscribe();
    };
  }, [documents, sim]);
  useEffect(() => {
    // Real outputs are driven only while the link is open as controller: then online changes ask.
    const update = () => {
      const view = gatewayLink.snapshot();
      sim.getState().setOnlineConfirmRequired(view.link === 'open' && view.role === 'controller');
    };
    update();
    return gatewayLink.subscribe(update);
  }, [sim]);
}
