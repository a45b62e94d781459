// Editing while the simulation runs is an online change, in one of two modes chosen in the project
// (Project.onlineChange, docs/simulation.md "Editing while running"):
// - apply as you edit (default): the edited document is compiled after a pause in typing and, if it
//   has no errors, swapped in at the next scan boundary;
// - apply on request: edits accumulate while the program runs; the toolbar says the running program
//   is not the one shown (and how many edits), changed networks are marked, and Apply (Alt+F8)
//   lists the changes and applies them on confirmation.
// Variables keep their values by name, FB instances by name and type, edge memories by element id;
// what is new starts fresh, and the notice lists it. With the gateway attached as controller the
// worker first asks (Apply / Cancel). If the edit has errors, the last good program keeps running
// and the errors are shown. Opening another project (new POU ids) is not an edit: the simulation
// stops and forgets the old program.
import { useEffect } from 'react';
import { gatewayLink } from '../../bridge/gatewayLink';
import { changedNetworkIds, changeList } from '../../sim/changeList';
import { programId } from '../../sim/programId';
import { useDocumentStore } from '../../store/documentStore';
import type { SimState } from '../../store/simState';
import { useSimStore } from './simContext';

const DEBOUNCE_MS = 300;

export function useOnlineChange(): void {
  const documents = useDocumentStore();
  const sim = useSimStore();
  useEffect(() => {
    let timer: ReturnType<typeof setTimeout> | undefined;
    /** Apply on request: what differs between the running program and the shown document. */
    const updateUnapplied = () => {
      const s = sim.getState();
      const project = documents.getState().project;
      if (s.onlineMode !== 'request' || !s.live || s.runningProgram === null || programId(project) === s.runningProgram) {
        if (s.unapplied) s.setUnapplied(undefined);
        return;
      }
      const changes = s.runningProject ? changeList(s.runningProject, project) : undefined;
      const networks = s.runningProject ? changedNetworkIds(s.runningProject, project) : new Set<string>();
      s.setUnapplied({ changes, count: Math.max(1, changes?.count ?? 1), networks });
    };
    sim.getState().setOnlineMode(documents.getState().project.onlineChange ?? 'edit');
    const unsubscribe = documents.subscribe((state, previous) => {
      if (state.project === previous.project) return;
      const mode = state.project.onlineChange ?? 'edit';
      sim.getState().setOnlineMode(mode);
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
      if (mode === 'request') {
        updateUnapplied();
        return;
      }
      if (s.unapplied) s.setUnapplied(undefined);
      timer = setTimeout(() => sim.getState().documentChanged(documents.getState().project), DEBOUNCE_MS);
    });
    // The running program changed (applied, Run, Reset, stopped): the difference is worked out again.
    const watched = (s: SimState) => [s.onlineMode, s.live, s.runningProgram, s.runningProject] as const;
    let last = watched(sim.getState());
    const unsubscribeSim = sim.subscribe((state) => {
      const now = watched(state);
      if (now.every((v, i) => v === last[i])) return;
      last = now;
      updateUnapplied();
    });
    return () => {
      clearTimeout(timer);
      unsubscribe();
      unsubscribeSim();
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
