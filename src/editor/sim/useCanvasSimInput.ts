// Interacting with the canvas while simulating, without touching the canvas's own pointer tools:
// listeners in the capture phase see the event first and take it only when it is for the simulator.
// - click a contact bound to a BOOL input (%I): toggles it (a switch);
// - Alt + press on it: TRUE while held (a push-button);
// - with hardware attached (controller), an input the gateway has as a point comes from the device:
//   a click does not write it, it opens the menu that says so and offers a (confirmed) force;
// - right-click a contact or coil: the force/watch/trend menu.
// Shift/Ctrl-clicks and every other element go to the editor as usual.
import { useEffect } from 'react';
import type { LdElement } from '../../model/elements';
import { selectNetworks, useDocumentStore } from '../../store/documentStore';
import { elementAt } from '../../store/networkEdits';
import type { SimState } from '../../store/simStore';
import { useUiStore } from '../../store/uiStore';
import { hitTest, layoutNetworks } from '../canvas/geometry';
import { fieldInputAddress } from '../hardware/fieldIo';
import { useSimStore } from './simContext';

const simulating = (s: SimState) => s.mode === 'running' || s.mode === 'paused';

export function useCanvasSimInput(): void {
  const documents = useDocumentStore();
  const ui = useUiStore();
  const sim = useSimStore();
  useEffect(() => {
    let held: string | undefined;

    const elementUnder = (e: MouseEvent): LdElement | undefined => {
      const target = e.target;
      if (!(target instanceof HTMLCanvasElement)) return undefined;
      const scroller = target.closest<HTMLElement>('.rs-canvas');
      if (!scroller) return undefined;
      const networks = selectNetworks(documents.getState());
      const zoom = ui.getState().viewport.zoom;
      const rect = scroller.getBoundingClientRect();
      const point = { x: (e.clientX - rect.left + scroller.scrollLeft) / zoom, y: (e.clientY - rect.top + scroller.scrollTop) / zoom };
      const hit = hitTest(layoutNetworks(networks), networks, point);
      if (hit.area !== 'grid') return undefined;
      const network = networks[hit.index];
      return network ? elementAt(network, hit.cell) : undefined;
    };

    /** The BOOL input variable a contact reads, in the running program's own spelling. */
    const inputOf = (s: SimState, el: LdElement | undefined): string | undefined => {
      if (el?.kind !== 'contact' || !el.variable) return undefined;
      const v = s.layout?.variables[s.variableIndex.get(el.variable.toUpperCase()) ?? -1];
      return v?.role === 'input' && v.type === 'BOOL' ? v.name : undefined;
    };

    const onPointerDown = (e: PointerEvent) => {
      if (e.button !== 0 || e.shiftKey || e.ctrlKey || e.metaKey) return;
      const s = sim.getState();
      if (!simulating(s)) return;
      const name = inputOf(s, elementUnder(e));
      if (!name) return;
      e.stopPropagation();
      e.preventDefault();
      if (fieldInputAddress(s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1])) {
        // A field input: the device drives it; only an explicit force overrides it.
        s.openContextMenu({ x: e.clientX, y: e.clientY, variable: name });
        return;
      }
      if (e.altKey) {
        held = name;
        s.pressInput(name);
      } else {
        s.toggleInput(name);
      }
    };

    const release = () => {
      if (held === undefined) return;
      sim.getState().releaseInput(held);
      held = undefined;
    };

    const onContextMenu = (e: MouseEvent) => {
      const s = sim.getState();
      if (!s.layout || !s.live) return;
      const el = elementUnder(e);
      if ((el?.kind !== 'contact' && el?.kind !== 'coil') || !el.variable) return;
      const v = s.layout.variables[s.variableIndex.get(el.variable.toUpperCase()) ?? -1];
      if (!v) return;
      e.preventDefault();
      e.stopPropagation();
      s.openContextMenu({ x: e.clientX, y: e.clientY, variable: v.name });
    };

    document.addEventListener('pointerdown', onPointerDown, true);
    window.addEventListener('pointerup', release, true);
    window.addEventListener('pointercancel', release, true);
    window.addEventListener('blur', release);
    document.addEventListener('contextmenu', onContextMenu, true);
    return () => {
      release();
      document.removeEventListener('pointerdown', onPointerDown, true);
      window.removeEventListener('pointerup', release, true);
      window.removeEventListener('pointercancel', release, true);
      window.removeEventListener('blur', release);
      document.removeEventListener('contextmenu', onContextMenu, true);
    };
  }, [documents, ui, sim]);
}
