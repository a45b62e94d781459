// Interacting with the canvas while simulating, without touching the canvas's own pointer tools:
// listeners in the capture phase see the event first and take it only when it is for the simulator.
// - click a contact bound to a BOOL input (%I): toggles it (a switch);
// - Alt + press on it: TRUE while held (a push-button);
// - with hardware attached (controller), an input the gateway has as a point comes from the device:
//   a click does not write it, it opens the menu that says so and offers a (confirmed) force;
// - right-click a contact or coil: the force/watch/trend menu;
// - right-click or double-click a call of a user FB: "Open instance", the FB's tab with that instance picked.
// Inside an FB's body the operands are the monitored instance's (`Motor1.Start`), globals as they are.
// Shift/Ctrl-clicks and every other element go to the editor as usual.
import { useEffect } from 'react';
import type { LdElement } from '../../model/elements';
import { selectLibrary, selectNetworks, useDocumentStore } from '../../store/documentStore';
import { elementAt } from '../../store/networkEdits';
import type { SimState } from '../../store/simStore';
import { useUiStore } from '../../store/uiStore';
import { hitTest, layoutNetworks } from '../canvas/geometry';
import { fieldInputAddress } from '../hardware/fieldIo';
import { canvasName } from './liveValues';
import { useSimStore } from './simContext';
import { openBody } from './useFollowExecution';

const simulating = (s: SimState) => s.mode === 'running' || s.mode === 'paused';

export function useCanvasSimInput(): void {
  const documents = useDocumentStore();
  const ui = useUiStore();
  const sim = useSimStore();
  useEffect(() => {
    let held: string | undefined;

    const elementUnder = (e: MouseEvent): LdElement | undefined => {
      const target = e.target;
      // The stage's canvas, or the sticky layer over it (a double-click's second press can land there);
      // never a field or a button of a network header.
      if (!(target instanceof HTMLCanvasElement) && !(target instanceof HTMLDivElement)) return undefined;
      const scroller = target.closest<HTMLElement>('.rs-canvas');
      if (!scroller) return undefined;
      const networks = selectNetworks(documents.getState());
      const zoom = ui.getState().viewport.zoom;
      const rect = scroller.getBoundingClientRect();
      const point = { x: (e.clientX - rect.left + scroller.scrollLeft) / zoom, y: (e.clientY - rect.top + scroller.scrollTop) / zoom };
      const hit = hitTest(layoutNetworks(networks, selectLibrary(documents.getState())), networks, point);
      if (hit.area !== 'grid') return undefined;
      const network = networks[hit.index];
      // With the project's blocks: a user FB's box covers all its cells.
      return network ? elementAt(network, hit.cell, selectLibrary(documents.getState())) : undefined;
    };

    /** The readable variable an operand stands for in the monitored body (`Motor1.Start` inside Motor1). */
    const variableOf = (s: SimState, operand: string) => {
      const name = canvasName(s, operand);
      return name === undefined ? undefined : s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1];
    };

    /** The BOOL input variable a contact reads, in the running program's own spelling. */
    const inputOf = (s: SimState, el: LdElement | undefined): string | undefined => {
      if (el?.kind !== 'contact' || !el.variable) return undefined;
      const v = variableOf(s, el.variable);
      return v?.role === 'input' && v.type === 'BOOL' ? v.name : undefined;
    };

    /** A call of a user FB under the pointer: its POU and the instance's path in the running program. */
    const callOf = (s: SimState, el: LdElement | undefined): { pou: string; instance: string } | undefined => {
      if (el?.kind !== 'box' || !el.instance || !s.layout) return undefined;
      const pou = selectLibrary(documents.getState()).userPou(el.blockType);
      if (pou?.kind !== 'FUNCTION_BLOCK') return undefined;
      const prefix = s.canvasScope?.prefix;
      const path = prefix ? `${prefix}.${el.instance}` : el.instance;
      const known = s.layout.instances?.find((i) => i.path.toUpperCase() === path.toUpperCase());
      return known ? { pou: pou.name, instance: known.path } : undefined;
    };

    const onDoubleClick = (e: MouseEvent) => {
      const s = sim.getState();
      if (!s.live || e.shiftKey || e.ctrlKey || e.metaKey) return;
      const call = callOf(s, elementUnder(e));
      if (!call) return;
      e.stopPropagation();
      e.preventDefault();
      openBody(documents, sim, call.pou, call.instance);
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
      const call = callOf(s, el);
      if (call) {
        e.preventDefault();
        e.stopPropagation();
        s.openContextMenu({ x: e.clientX, y: e.clientY, variable: '', call });
        return;
      }
      if ((el?.kind !== 'contact' && el?.kind !== 'coil') || !el.variable) return;
      const v = variableOf(s, el.variable);
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
    document.addEventListener('dblclick', onDoubleClick, true);
    return () => {
      release();
      document.removeEventListener('pointerdown', onPointerDown, true);
      window.removeEventListener('pointerup', release, true);
      window.removeEventListener('pointercancel', release, true);
      window.removeEventListener('blur', release);
      document.removeEventListener('contextmenu', onContextMenu, true);
      document.removeEventListener('dblclick', onDoubleClick, true);
    };
  }, [documents, ui, sim]);
}
