// The watch list is kept per project (issue 24): it is saved with the project (Project.watch, so in
// the file and in the autosave) and comes back when the project is opened again or the page is
// reloaded. Opening another project shows that project's list. Both stores stay in step: the
// simulation store's list is what the Watch panel edits; the document keeps a copy.
import { useEffect } from 'react';
import type { DocumentStore } from '../../store/documentStore';
import type { SimStore } from '../../store/simState';

const sameList = (a: readonly string[] | undefined, b: readonly string[] | undefined): boolean => {
  const x = a ?? [];
  const y = b ?? [];
  return x.length === y.length && x.every((n, i) => n === y[i]);
};

/** Keeps the simulation's watch list and the project's in step (mounted once, SimHostMount). */
export function useWatchList(documents: DocumentStore, sim: SimStore): void {
  useEffect(() => {
    const fromProject = () => {
      const list = documents.getState().project.watch ?? [];
      if (!sameList(sim.getState().watch, list)) sim.setState({ watch: [...list] });
    };
    fromProject();
    const offDocument = documents.subscribe((s, prev) => {
      if (s.opened !== prev.opened || s.project.watch !== prev.project.watch) fromProject();
    });
    const offSim = sim.subscribe((s, prev) => {
      if (s.watch === prev.watch || sameList(s.watch, documents.getState().project.watch)) return;
      documents.getState().setWatchList(s.watch);
    });
    return () => {
      offDocument();
      offSim();
    };
  }, [documents, sim]);
}
