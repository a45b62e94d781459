// Commands of the shell itself: show or hide each panel, dock the variable table, print. Shaped
// like the command registry's (src/editor/commands/registry.ts) so the menus show them with their
// keys; useShellKeys binds the keys.
import type { UiStore } from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import { printState } from '../print/printState';
import { collapsedKey, type PanelSide } from './panelSizes';

export interface ShellCommand {
  readonly id: string;
  readonly label: string;
  readonly menu: 'File' | 'View';
  readonly description: string;
  /** Shortcut specs as in commands/keys.ts; the first is the one shown. */
  readonly keys?: readonly string[];
  run(ctx: EditorContext): void;
}

const toggle = (side: PanelSide) => (ctx: EditorContext) => {
  const ui = ctx.ui.getState();
  ui.setPanels({ [collapsedKey(side)]: !ui.panels[collapsedKey(side)] });
};

/** Moves the variable table between the side panel and the full-width bottom panel, and shows it. */
export function toggleVariablesDock(store: UiStore) {
  const ui = store.getState();
  const dock = ui.panels.variablesDock === 'bottom' ? 'side' : 'bottom';
  ui.setPanels({ variablesDock: dock, ...(dock === 'bottom' ? { bottomCollapsed: false } : { rightCollapsed: false }) });
  requestAnimationFrame(() => document.getElementById('rs-tab-variables')?.click());
}

export const SHELL_COMMANDS: readonly ShellCommand[] = [
  {
    id: 'file.print',
    label: 'Print / Export PDF…',
    menu: 'File',
    description: 'Print a POU or the whole project, or save it as a PDF from the browser’s print dialog',
    keys: ['mod+p'],
    run: () => printState.getState().openDialog(),
  },
  {
    id: 'view.toggleLeft',
    label: 'Show / hide the palette and project tree',
    menu: 'View',
    description: 'Collapse or expand the left panel',
    keys: ['mod+b'],
    run: toggle('left'),
  },
  {
    id: 'view.toggleRight',
    label: 'Show / hide the side panel',
    menu: 'View',
    description: 'Collapse or expand the inspector / variables panel',
    keys: ['mod+alt+b'],
    run: toggle('right'),
  },
  {
    id: 'view.toggleBottom',
    label: 'Show / hide the bottom panel',
    menu: 'View',
    description: 'Collapse or expand the problems / watch / trend panel',
    keys: ['mod+j'],
    run: toggle('bottom'),
  },
  {
    id: 'view.variablesWide',
    label: 'Variable table: wide view in the bottom panel',
    menu: 'View',
    description: 'Dock the variable table in the full-width bottom panel (every column on one line), or back in the side panel',
    run: (ctx) => toggleVariablesDock(ctx.ui),
  },
];
