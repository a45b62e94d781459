// One registry of editor commands drives the menus, the palette tooltips and the keyboard
// shortcuts, so a shortcut shown anywhere is the one that works.
import { layoutNetworks } from '../canvas/geometry';
import { goToPartner } from '../outline/goTo';
import { PALETTE_ITEMS } from '../palette/paletteItems';
import { addToWatchAtCursor } from '../sim/watchFromCanvas';
import { copy, cut, pasteFromSystem } from './clipboardActions';
import {
  deleteCurrentNetwork,
  deleteTargets,
  duplicateTargets,
  editAtCursor,
  ensureCursor,
  escape,
  insertNetworkBelow,
  libraryOf,
  moveCursor,
  networksOf,
  nudgeTargets,
  placeAtCursor,
  selectAllInNetwork,
  toggleVLinkAtCursor,
  wrapTargetsInBranch,
  zoomToFit,
  type EditorContext,
} from './editorActions';
import {
  deleteSelectedNetworks,
  duplicateSelectedNetworks,
  extendNetworkSelection,
  hasNetworkSelection,
  moveSelectedNetworks,
  selectAllNetworks,
} from './networkActions';

export type CommandGroup = 'Edit' | 'Insert' | 'Network' | 'View' | 'Navigate';

export interface EditorCommand {
  readonly id: string;
  readonly label: string;
  readonly group: CommandGroup;
  /** Shortcuts (commands/keys.ts specs); the first is the one shown. */
  readonly keys?: readonly string[];
  /** Shown in menus; navigation-only commands stay out of them. */
  readonly inMenu?: boolean;
  run(ctx: EditorContext): void;
  enabled?(ctx: EditorContext): boolean;
  /** A view option the command switches: whether it is on (the menu shows a check mark). */
  checked?(ctx: EditorContext): boolean;
  /** Why the command cannot run now (the command palette shows it beside a disabled command). */
  disabledReason?(ctx: EditorContext): string | undefined;
}

/** Focuses a field of a network header once it is on screen (after focusCell scrolled there). */
function focusHeaderField(ctx: EditorContext, field: 'label' | 'title' | 'comment') {
  const c = ensureCursor(ctx);
  ctx.ui.getState().focusCell(c.network, { row: c.row, col: c.col });
  const tryFocus = (attempt: number) => {
    const el = document.querySelector<HTMLElement>(`[data-testid="network-${field}-${c.network}"]`);
    if (el) el.focus();
    else if (attempt < 10) requestAnimationFrame(() => tryFocus(attempt + 1));
  };
  requestAnimationFrame(() => tryFocus(0));
}

const hasDocSelectionOrCursor = (ctx: EditorContext) => {
  const ui = ctx.ui.getState();
  return ui.selection.elements.length > 0 || ui.cursor !== undefined || hasNetworkSelection(ctx);
};

/** Runs `onNetworks` when whole networks are selected (by their headers), else `onElements`. */
const unitOr =
  (onNetworks: (ctx: EditorContext) => void, onElements: (ctx: EditorContext) => void) =>
  (ctx: EditorContext) =>
    hasNetworkSelection(ctx) ? onNetworks(ctx) : onElements(ctx);

const placeCommands: EditorCommand[] = PALETTE_ITEMS.map((item) => ({
  id: `place.${item.id}`,
  label: item.label,
  group: 'Insert',
  ...(item.keys ? { keys: [item.keys] } : {}),
  inMenu: true,
  run: (ctx) => {
    placeAtCursor(ctx, item.template);
  },
}));

export const COMMANDS: readonly EditorCommand[] = [
  {
    id: 'edit.undo',
    label: 'Undo',
    group: 'Edit',
    keys: ['mod+z'],
    inMenu: true,
    run: (ctx) => ctx.doc.getState().undo(),
    enabled: (ctx) => ctx.doc.getState().canUndo,
  },
  {
    id: 'edit.redo',
    label: 'Redo',
    group: 'Edit',
    keys: ['mod+y', 'mod+shift+z'],
    inMenu: true,
    run: (ctx) => ctx.doc.getState().redo(),
    enabled: (ctx) => ctx.doc.getState().canRedo,
  },
  {
    id: 'edit.cut',
    label: 'Cut',
    group: 'Edit',
    keys: ['mod+x'],
    inMenu: true,
    run: (ctx) => void cut(ctx),
    enabled: hasDocSelectionOrCursor,
  },
  {
    id: 'edit.copy',
    label: 'Copy',
    group: 'Edit',
    keys: ['mod+c'],
    inMenu: true,
    run: (ctx) => void copy(ctx),
    enabled: hasDocSelectionOrCursor,
  },
  {
    id: 'edit.paste',
    label: 'Paste',
    group: 'Edit',
    keys: ['mod+v'],
    inMenu: true,
    run: (ctx) => void pasteFromSystem(ctx),
  },
  {
    id: 'edit.duplicate',
    label: 'Duplicate',
    group: 'Edit',
    keys: ['mod+d'],
    inMenu: true,
    run: unitOr(duplicateSelectedNetworks, duplicateTargets),
    enabled: hasDocSelectionOrCursor,
  },
  {
    id: 'edit.delete',
    label: 'Delete',
    group: 'Edit',
    keys: ['delete', 'backspace'],
    inMenu: true,
    run: unitOr(deleteSelectedNetworks, deleteTargets),
    enabled: hasDocSelectionOrCursor,
  },
  {
    id: 'edit.selectAll',
    label: 'Select all in network',
    group: 'Edit',
    keys: ['mod+a'],
    inMenu: true,
    run: unitOr(selectAllNetworks, selectAllInNetwork),
  },
  {
    id: 'edit.branch',
    label: 'Parallel branch around selection',
    group: 'Edit',
    keys: ['mod+shift+b'],
    inMenu: true,
    run: wrapTargetsInBranch,
    enabled: hasDocSelectionOrCursor,
  },
  {
    id: 'edit.name',
    label: 'Edit name or pin operand',
    group: 'Edit',
    keys: ['enter', 'f2'],
    inMenu: true,
    run: editAtCursor,
  },
  { id: 'edit.escape', label: 'Cancel tool / clear selection', group: 'Edit', keys: ['escape'], run: escape },
  ...placeCommands,
  {
    id: 'place.box',
    label: 'Function or function block…',
    group: 'Insert',
    keys: ['b'],
    inMenu: true,
    run: (ctx) => {
      const c = ensureCursor(ctx);
      ctx.ui.getState().openBlockPicker(c.network, { row: c.row, col: c.col });
    },
  },
  {
    id: 'place.vlink',
    label: 'Vertical link down (left edge)',
    group: 'Insert',
    keys: ['v'],
    inMenu: true,
    run: (ctx) => toggleVLinkAtCursor(ctx, 'left'),
  },
  {
    id: 'place.vlinkRight',
    label: 'Vertical link down (right edge)',
    group: 'Insert',
    keys: ['shift+v'],
    inMenu: true,
    run: (ctx) => toggleVLinkAtCursor(ctx, 'right'),
  },
  {
    id: 'network.insert',
    label: 'Insert network below',
    group: 'Network',
    keys: ['n'],
    inMenu: true,
    run: insertNetworkBelow,
  },
  {
    id: 'network.add',
    label: 'Add network at the end',
    group: 'Network',
    inMenu: true,
    run: (ctx) => {
      const id = ctx.doc.getState().addNetwork();
      ctx.ui.getState().focusCell(id, { row: 0, col: 0 });
    },
  },
  {
    id: 'network.insertRow',
    label: 'Insert row below the cursor',
    group: 'Network',
    keys: ['mod+enter'],
    inMenu: true,
    run: (ctx) => {
      const c = ensureCursor(ctx);
      ctx.doc.getState().insertRow(c.network, c.row + 1);
      moveCursor(ctx, 1, 0);
    },
  },
  {
    id: 'network.deleteRow',
    label: 'Delete empty row at the cursor',
    group: 'Network',
    keys: ['mod+shift+backspace'],
    inMenu: true,
    run: (ctx) => {
      const c = ensureCursor(ctx);
      if (!ctx.doc.getState().deleteRow(c.network, c.row))
        ctx.ui.getState().setStatus('Only an empty row can be deleted (and not the last one).');
      else moveCursor(ctx, c.row > 0 ? -1 : 0, 0);
    },
  },
  {
    id: 'network.delete',
    label: 'Delete network',
    group: 'Network',
    keys: ['alt+shift+delete'],
    inMenu: true,
    run: deleteCurrentNetwork,
  },
  {
    id: 'network.moveUp',
    label: 'Move selected networks up',
    group: 'Network',
    inMenu: true,
    run: (ctx) => moveSelectedNetworks(ctx, -1),
    enabled: hasNetworkSelection,
  },
  {
    id: 'network.moveDown',
    label: 'Move selected networks down',
    group: 'Network',
    inMenu: true,
    run: (ctx) => moveSelectedNetworks(ctx, 1),
    enabled: hasNetworkSelection,
  },
  {
    id: 'network.collapseAll',
    label: 'Collapse all networks',
    group: 'Network',
    keys: ['mod+shift+arrowup'],
    inMenu: true,
    run: (ctx) => ctx.doc.getState().setCollapsed('all', true),
  },
  {
    id: 'network.expandAll',
    label: 'Expand all networks',
    group: 'Network',
    keys: ['mod+shift+arrowdown'],
    inMenu: true,
    run: (ctx) => ctx.doc.getState().setCollapsed('all', false),
  },
  {
    id: 'nav.goto',
    label: 'Go to network…',
    group: 'Network',
    keys: ['mod+g'],
    inMenu: true,
    run: (ctx) => ctx.ui.getState().setFinder('goto'),
  },
  {
    id: 'nav.gotoExtend',
    label: 'Extend selection to network…',
    group: 'Network',
    keys: ['mod+shift+g'],
    inMenu: true,
    run: (ctx) => ctx.ui.getState().setFinder('gotoExtend'),
  },
  {
    id: 'edit.find',
    label: 'Find / replace…',
    group: 'Edit',
    keys: ['mod+f', 'mod+h'],
    inMenu: true,
    run: (ctx) => ctx.ui.getState().setFinder('find'),
  },
  {
    id: 'network.label',
    label: 'Network label',
    group: 'Network',
    keys: ['l'],
    inMenu: true,
    run: (ctx) => focusHeaderField(ctx, 'label'),
  },
  {
    id: 'network.title',
    label: 'Network title',
    group: 'Network',
    keys: ['t'],
    inMenu: true,
    run: (ctx) => focusHeaderField(ctx, 'title'),
  },
  {
    id: 'network.comment',
    label: 'Network comment',
    group: 'Network',
    keys: ['k'],
    inMenu: true,
    run: (ctx) => focusHeaderField(ctx, 'comment'),
  },
  {
    id: 'view.watch',
    label: 'Add to watch',
    group: 'View',
    keys: ['w'],
    inMenu: true,
    run: addToWatchAtCursor,
  },
  {
    id: 'nav.partner',
    label: 'Go to connector / continuation',
    group: 'Edit',
    keys: ['g'],
    inMenu: true,
    run: (ctx) => {
      const problem = goToPartner(ctx);
      if (problem) ctx.ui.getState().setStatus(problem);
    },
  },
  {
    id: 'nav.left',
    label: 'Cursor left',
    group: 'Navigate',
    keys: ['arrowleft'],
    run: (ctx) => moveCursor(ctx, 0, -1),
  },
  {
    id: 'nav.right',
    label: 'Cursor right',
    group: 'Navigate',
    keys: ['arrowright'],
    run: (ctx) => moveCursor(ctx, 0, 1),
  },
  {
    id: 'nav.up',
    label: 'Cursor up',
    group: 'Navigate',
    keys: ['arrowup'],
    run: (ctx) => moveCursor(ctx, -1, 0),
  },
  {
    id: 'nav.down',
    label: 'Cursor down',
    group: 'Navigate',
    keys: ['arrowdown'],
    run: (ctx) => moveCursor(ctx, 1, 0),
  },
  ...(
    [
      ['Left', 0, -1],
      ['Right', 0, 1],
      ['Up', -1, 0],
      ['Down', 1, 0],
    ] as const
  ).flatMap(([dir, dRow, dCol]): EditorCommand[] => [
    {
      id: `nav.extend${dir}`,
      label: `Extend selection ${dir.toLowerCase()}`,
      group: 'Navigate',
      keys: [`shift+arrow${dir.toLowerCase()}`],
      run: (ctx) =>
        hasNetworkSelection(ctx) && dRow !== 0
          ? extendNetworkSelection(ctx, dRow)
          : moveCursor(ctx, dRow, dCol, true),
    },
    {
      id: `edit.move${dir}`,
      label: `Move selection ${dir.toLowerCase()}`,
      group: 'Edit',
      keys: [`alt+arrow${dir.toLowerCase()}`],
      run: (ctx) =>
        hasNetworkSelection(ctx) ? dRow !== 0 && moveSelectedNetworks(ctx, dRow) : nudgeTargets(ctx, dRow, dCol),
    },
  ]),
  {
    id: 'view.zoomIn',
    label: 'Zoom in',
    group: 'View',
    keys: ['mod+='],
    inMenu: true,
    run: (ctx) => ctx.ui.getState().setZoom(ctx.ui.getState().viewport.zoom * 1.2),
  },
  {
    id: 'view.zoomOut',
    label: 'Zoom out',
    group: 'View',
    keys: ['mod+-'],
    inMenu: true,
    run: (ctx) => ctx.ui.getState().setZoom(ctx.ui.getState().viewport.zoom / 1.2),
  },
  {
    id: 'view.zoomReset',
    label: 'Actual size',
    group: 'View',
    keys: ['mod+0'],
    inMenu: true,
    run: (ctx) => ctx.ui.getState().setZoom(1),
  },
  {
    id: 'view.fit',
    label: 'Fit width',
    group: 'View',
    keys: ['mod+9'],
    inMenu: true,
    run: (ctx) => zoomToFit(ctx, layoutNetworks(networksOf(ctx), libraryOf(ctx)).totalWidth),
  },
  {
    id: 'view.theme',
    label: 'Toggle dark theme',
    group: 'View',
    inMenu: true,
    run: (ctx) => ctx.ui.getState().setTheme(ctx.ui.getState().theme === 'dark' ? 'light' : 'dark'),
  },
  {
    id: 'view.symbolComments',
    label: 'Show symbol comments',
    group: 'View',
    inMenu: true,
    checked: (ctx) => ctx.ui.getState().symbolComments,
    run: (ctx) => ctx.ui.getState().setSymbolComments(!ctx.ui.getState().symbolComments),
  },
];

export const commandById = (id: string): EditorCommand | undefined => COMMANDS.find((c) => c.id === id);
