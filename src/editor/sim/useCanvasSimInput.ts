// Interacting with the canvas while simulating, without touching the canvas's own pointer tools:
// listeners in the capture phase see the event first and take it only when it is for the simulator.
// - a click only ever selects, as when editing: it never changes the process (running, paused, after
//   a step or at a breakpoint alike);
// - double-click a contact bound to a BOOL input (%I): switches it (as CODESYS's double-click on a
//   BOOL in online mode); Alt + press on it: TRUE while held (a push-button). The tooltip and the
//   status line (SimInputHint) say so;
// - with hardware attached (controller), an input the gateway has as a point comes from the device:
//   a double-click does not write it, it opens the menu that says so and offers a (confirmed) force;
// - with a machine attached (Plant panel), an input it writes every scan (a sensor, an operator
//   control) comes from the machine: a double-click does not write it (the next scan would undo it),
//   it opens the force menu and the status line says so;
// - right-click a contact or coil: the force/watch/trend menu;
// - right-click or double-click a call of a user FB: "Open instance", the FB's tab with that instance picked.
// Inside an FB's body the operands are the monitored instance's (`Motor1.Start`), globals as they are.
// Shift/Ctrl-clicks and every other element go to the editor as usual.
import { useEffect } from 'react';
import type { LdElement } from '../../model/elements';
import { selectLibrary, selectNetworks, useDocumentStore } from '../../store/documentStore';
import { canvasLayoutFor } from '../canvas/canvasLayout';
import { elementAt } from '../../store/networkEdits';
import type { SimState } from '../../store/simState';
import { useUiStore } from '../../store/uiStore';
import { hitTest } from '../canvas/geometry';
import { fieldInputAddress } from '../hardware/fieldIo';
import { addressKey } from '../../plant/loop';
import { canvasName } from './liveValues';
import { useSimStore } from './simContext';
import { openBody } from './useFollowExecution';

const simulating = (s: SimState) => s.mode === 'running' || s.mode === 'paused';

/** The readable variable an operand stands for in the monitored body (`Motor1.Start` inside Motor1). */
function variableOf(s: SimState, operand: string) {
  const name = canvasName(s, operand);
  return name === undefined ? undefined : s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1];
}

/** While simulating, the BOOL input variable a contact reads, in the running program's own spelling. */
export function simInputOf(s: SimState, el: LdElement | undefined): string | undefined {
  if (!simulating(s) || el?.kind !== 'contact' || !el.variable) return undefined;
  const v = variableOf(s, el.variable);
  return v?.role === 'input' && v.type === 'BOOL' ? v.name : undefined;
}

/** "the machine tank (its sensor LowLevel)" when the attached machine writes input `name` every scan. */
export function machineInputOf(s: SimState, name: string): string | undefined {
  const plant = s.plant;
  const location = s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1]?.location;
  if (!plant || !location) return undefined;
  const key = addressKey(location);
  const point = plant.points.find((p) => p.kind !== 'actuator' && addressKey(p.address) === key);
  if (!point) return undefined;
  return `the machine ${plant.id} (its ${point.kind === 'operator' ? 'operator control' : 'sensor'} ${point.name})`;
}

/** How to change the input a contact reads, for its tooltip and the status line. */
export function simInputHint(s: SimState, el: LdElement | undefined): string | undefined {
  const name = simInputOf(s, el);
  if (!name) return undefined;
  if (fieldInputAddress(s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1]))
    return `${name} comes from the device: double-click to force it`;
  const machine = machineInputOf(s, name);
  if (machine) return `${name} comes from ${machine}: double-click to force it`;
  return `Input ${name}: double-click to switch it, Alt+press to hold it on (a click only selects)`;
}

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
      const hit = hitTest(canvasLayoutFor(documents.getState(), ui.getState()), networks, point);
      if (hit.area !== 'grid') return undefined;
      const network = networks[hit.index];
      // With the project's blocks: a user FB's box covers all its cells.
      return network ? elementAt(network, hit.cell, selectLibrary(documents.getState())) : undefined;
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
      if (e.shiftKey || e.ctrlKey || e.metaKey || e.altKey) return;
      const el = elementUnder(e);
      const name = simInputOf(s, el);
      if (name) {
        e.stopPropagation();
        e.preventDefault();
        if (fieldInputAddress(s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1])) {
          // A field input: the device drives it; only an explicit force overrides it.
          s.openContextMenu({ x: e.clientX, y: e.clientY, variable: name });
          return;
        }
        const machine = machineInputOf(s, name);
        if (machine) {
          // The machine writes it every scan: a switch here would be undone; a force overrides it.
          s.openContextMenu({ x: e.clientX, y: e.clientY, variable: name });
          ui.getState().setStatus(`${name} comes from ${machine}: it writes it every scan; force it to override`);
          return;
        }
        s.toggleInput(name);
        ui.getState().setStatus(`${name} switched ${s.values[s.variableIndex.get(name.toUpperCase()) ?? -1] === true ? 'OFF' : 'ON'} (double-click)`);
        return;
      }
      if (!s.live) return;
      const call = callOf(s, el);
      if (!call) return;
      e.stopPropagation();
      e.preventDefault();
      openBody(documents, sim, call.pou, call.instance);
    };

    // Alt + press: a push-button, TRUE while held. A plain press goes to the editor (selection).
    const onPointerDown = (e: PointerEvent) => {
      if (e.button !== 0 || !e.altKey || e.shiftKey || e.ctrlKey || e.metaKey) return;
      const s = sim.getState();
      const name = simInputOf(s, elementUnder(e));
      if (!name || fieldInputAddress(s.layout?.variables[s.variableIndex.get(name.toUpperCase()) ?? -1]) || machineInputOf(s, name)) return;
      e.stopPropagation();
      e.preventDefault();
      held = name;
      s.pressInput(name);
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
