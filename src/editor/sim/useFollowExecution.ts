// The canvas monitors the shown POU: the store learns which tab is shown (an FB's picked instance,
// a configuration's program instance), and after a step or at a breakpoint the editor shows the
// body where execution stands, with the caller's instance picked (stepping into a call opens the
// callee's tab; stepping out of a body returns to the caller's), scrolled so the network that runs
// next is on screen (the view stays put when it already is).
import { useEffect } from 'react';
import { selectActivePou, useDocumentStore } from '../../store/documentStore';
import type { SimStore } from '../../store/simState';
import type { DocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { scrollNetworkIntoView } from '../outline/goTo';

/** Shows the POU of `pou` (a tab, opened if needed) with `instance` picked. */
export function openBody(documents: DocumentStore, sim: SimStore, pou: string, instance: string | undefined): boolean {
  const target = documents.getState().project.pous.find((p) => p.name.toUpperCase() === pou.toUpperCase());
  if (!target) return false;
  if (instance !== undefined) sim.getState().pickInstance(target.name, instance);
  if (documents.getState().activePouId !== target.id) documents.getState().setActivePou(target.id);
  return true;
}

export function useFollowExecution(sim: SimStore): void {
  const documents = useDocumentStore();
  const ui = useUiStore();
  useEffect(() => {
    const tell = () => {
      const pou = selectActivePou(documents.getState());
      sim.getState().showPou(pou ? { name: pou.name, kind: pou.kind } : undefined);
    };
    tell();
    const offDocument = documents.subscribe((s, prev) => {
      if (s.activePouId !== prev.activePouId || s.project.pous !== prev.project.pous) tell();
    });
    let frame = 0;
    const offSim = sim.subscribe((s, prev) => {
      if (s.stopSeq === prev.stopSeq || !s.stop) return;
      const { network } = s.stop;
      if (!openBody(documents, sim, s.stop.pou, s.stop.instance)) return;
      // After the canvas has drawn the body (a step may have opened another tab).
      cancelAnimationFrame(frame);
      frame = requestAnimationFrame(() => scrollNetworkIntoView({ doc: documents, ui }, network));
    });
    return () => {
      cancelAnimationFrame(frame);
      offDocument();
      offSim();
    };
  }, [documents, sim, ui]);
}
