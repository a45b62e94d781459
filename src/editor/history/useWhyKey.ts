// The "Why?" key: `?` (outside text fields) explains the selected element at the viewed scan, or
// at the last recorded one, and shows the Why? tab.
import { useEffect } from 'react';
import { useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import type { SimStore } from '../../store/simState';
import { isModalOpen } from '../layout/useModal';

export function showWhyTab(): void {
  document.getElementById('rs-tab-why')?.click();
}

export function useWhyKey(sim: SimStore): void {
  const ui = useUiStore();
  const doc = useDocumentStore();
  useEffect(() => {
    const onKey = (e: KeyboardEvent) => {
      if (e.key !== '?' || e.ctrlKey || e.metaKey || e.altKey || isModalOpen()) return;
      const t = e.target as HTMLElement | null;
      if (t && (t.tagName === 'INPUT' || t.tagName === 'TEXTAREA' || t.isContentEditable)) return;
      const sel = ui.getState().selection;
      const layout = sim.getState().layout;
      const id = sel.elements[0];
      // Nothing recorded (never run, or Reset): no Why? to give, so `?` lists the shortcuts (CommandHost).
      if (!layout || !id || sel.network === undefined || sim.getState().history?.last === undefined) return;
      const network = layout.networkIds.indexOf(sel.network);
      const pou = doc.getState().project.pous.find((p) => p.name === layout.pou);
      const element = pou?.networks[network]?.elements.findIndex((el) => el.id === id) ?? -1;
      if (network < 0 || element < 0) return;
      e.preventDefault();
      sim.getState().explain({ kind: 'element', network, element });
      showWhyTab();
    };
    window.addEventListener('keydown', onKey);
    return () => window.removeEventListener('keydown', onKey);
  }, [ui, doc, sim]);
}
