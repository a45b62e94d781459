// What the editor's commands do, over the document and UI stores. Shared by shortcuts, menus,
// the palette and the canvas's pointer tools, so every path behaves the same.
import { elementSize } from '../../model/factory';
import { blockLibrary, type BlockLibrary } from '../../model/library';
import type { BoxElement, LdElement } from '../../model/elements';
import type { Cell } from '../../model/grid';
import type { ElementId, NetworkId } from '../../model/ids';
import type { Network } from '../../model/project';
import { selectNetworks, type DocumentStore } from '../../store/documentStore';
import { elementAt, moveShift, usedRows, type ElementTemplate } from '../../store/networkEdits';
import type { CursorCell, UiStore } from '../../store/uiStore';
import { modelCol, networkColumns } from '../canvas/columns';
import { firstField, INSTANCE_FIELD, nextField } from '../canvas/pinOperands';

export interface EditorContext {
  readonly doc: DocumentStore;
  readonly ui: UiStore;
}

export const networksOf = (ctx: EditorContext): readonly Network[] => selectNetworks(ctx.doc.getState());
export const networkById = (ctx: EditorContext, id: NetworkId | undefined): Network | undefined =>
  id ? networksOf(ctx).find((n) => n.id === id) : undefined;

/** Elements that take a name typed right after placing them. */
export const needsName = (
  el: Pick<LdElement, 'kind'> & Partial<{ contact: string; instance: string }>,
): boolean =>
  el.kind === 'coil' ||
  el.kind === 'jump' ||
  el.kind === 'connector' ||
  el.kind === 'continuation' ||
  (el.kind === 'contact' && el.contact !== 'NOT') ||
  (el.kind === 'box' && el.instance !== undefined);

/** The cursor, placed on the first open network when there is none (a network is added if needed). */
export function ensureCursor(ctx: EditorContext): CursorCell {
  const ui = ctx.ui.getState();
  const nets = networksOf(ctx);
  const current = ui.cursor && nets.find((n) => n.id === ui.cursor!.network && !n.collapsed);
  if (ui.cursor && current) return ui.cursor;
  let target = nets.find((n) => !n.collapsed);
  if (!target) {
    const id = ctx.doc.getState().addNetwork();
    target = networksOf(ctx).find((n) => n.id === id)!;
  }
  const cursor = { network: target.id, row: 0, col: 0 };
  ctx.ui.getState().setCursor(cursor);
  return cursor;
}

/** Elements that end a rung's path: they go right of what they are placed on. */
const OUTPUT_KINDS: ReadonlySet<LdElement['kind']> = new Set(['coil', 'jump', 'return', 'connector']);

/**
 * Where template `t` goes when placed at `cell`: on an element of several cells, its own cell (the
 * cursor stands on a box, never on its half); a coil, jump, return or connector placed on anything
 * but another one of those goes in series right after it (a coil before a CTU would break LD-R04),
 * every other element in series before it.
 */
export function placementCell(n: Network, cell: Cell, t: ElementTemplate, lib: BlockLibrary): Cell {
  const at = cursorAnchor(n, cell, lib);
  const on = elementAt(n, at, lib);
  if (!on || on.kind === 'link' || !OUTPUT_KINDS.has(t.kind) || OUTPUT_KINDS.has(on.kind)) return at;
  return { row: on.row, col: on.col + elementSize(on, lib).cols };
}

/** Places a template at a cell (inserting in series on another element), selects it, and opens the name editor when it takes one. */
export function placeAt(
  ctx: EditorContext,
  network: NetworkId,
  cell: Cell,
  t: ElementTemplate,
): ElementId | undefined {
  const n = networkById(ctx, network);
  const id = ctx.doc.getState().placeElement(network, n ? placementCell(n, cell, t, libraryOf(ctx)) : cell, t);
  const ui = ctx.ui.getState();
  if (!id) {
    ui.setStatus(
      'No room to insert there: a box is in the way, or the box would touch a parallel path. Make room first.',
    );
    return undefined;
  }
  ui.select(network, [id]);
  const el = networkById(ctx, network)?.elements.find((e) => e.id === id);
  if (!el) return id;
  ui.setCursor({ network, row: el.row, col: el.col });
  // Naming it right away joins the placing's undo step.
  if (needsName(el)) ui.startEditing(id, { joinUndo: ctx.doc.getState().lastStep() });
  else advancePast(ctx, network, el);
  return id;
}

/** The project's blocks: standard blocks and its own FBs and functions. */
export const libraryOf = (ctx: EditorContext) => blockLibrary(ctx.doc.getState().project);

/**
 * The column the cursor lands on for model cell (row, col) of `n`: the cells right of a coil
 * drawn at the right rail are under its wire, so the cursor lands on the coil (columns.ts).
 */
const cursorCol = (ctx: EditorContext, n: Network, row: number, col: number): number =>
  modelCol(networkColumns(n, libraryOf(ctx)), row, col);

/** Moves the cursor to the cell right of an element (after placing or naming it). */
export function advancePast(ctx: EditorContext, network: NetworkId, el: LdElement) {
  const n = networkById(ctx, network);
  if (!n) return;
  const col = Math.min(n.cols - 1, el.col + elementSize(el, libraryOf(ctx)).cols);
  ctx.ui.getState().setCursor({ network, row: el.row, col: cursorCol(ctx, n, el.row, col) });
}

export function placeAtCursor(ctx: EditorContext, t: ElementTemplate): ElementId | undefined {
  const c = ensureCursor(ctx);
  return placeAt(ctx, c.network, c, t);
}

/**
 * The cell the cursor stands on for `cell`: a cell covered by an element of several cells (a box's
 * other columns and rows) is the element's own cell, so the cursor is never inside a box.
 */
export function cursorAnchor(n: Network, cell: Cell, lib: BlockLibrary): Cell {
  const el = elementAt(n, cell, lib);
  return el && el.kind !== 'link' && (el.row !== cell.row || el.col !== cell.col) ? { row: el.row, col: el.col } : cell;
}

/**
 * Moves the cursor by cells; past the top/bottom row it continues in the previous/next open
 * network. A box is one stop: moving right or down from it goes past its last column or row, moving
 * onto any of its cells lands on the box. The element under the cursor becomes the selection, or
 * joins it with `extend` (Shift).
 */
export function moveCursor(ctx: EditorContext, dRow: number, dCol: number, extend = false) {
  const lib = libraryOf(ctx);
  const c = ensureCursor(ctx);
  const nets = networksOf(ctx);
  let index = nets.findIndex((n) => n.id === c.network);
  let n = nets[index]!;
  const from = cursorAnchor(n, c, lib);
  const on = elementAt(n, from, lib);
  const size = on && on.kind !== 'link' ? elementSize(on, lib) : { rows: 1, cols: 1 };
  let row = from.row + (dRow > 0 ? dRow + size.rows - 1 : dRow);
  let col = from.col + (dCol > 0 ? dCol + size.cols - 1 : dCol);
  // A network shows the rows its rung uses; the cursor may go one row below them (the canvas shows
  // that empty row: room for a branch), and from there on to the next network.
  const roomRows = (m: Network) => usedRows(m, lib) + 1;
  while (row < 0 || row >= roomRows(n)) {
    const step = row < 0 ? -1 : 1;
    let next = index + step;
    while (nets[next]?.collapsed) next += step;
    const target = nets[next];
    if (!target) {
      row = Math.max(0, Math.min(roomRows(n) - 1, row));
      break;
    }
    index = next;
    n = target;
    row = step < 0 ? usedRows(n, lib) - 1 : 0;
  }
  col = cursorCol(ctx, n, row, Math.max(0, Math.min(n.cols - 1, col)));
  const at = cursorAnchor(n, { row, col }, lib);
  const ui = ctx.ui.getState();
  ui.setCursor({ network: n.id, row: at.row, col: at.col });
  const el = elementAt(n, at, lib);
  const kept = extend && ui.selection.network === n.id ? ui.selection.elements : [];
  ui.select(n.id, [...new Set([...kept, ...(el ? [el.id] : [])])]);
}

/** Alt+arrows: moves the selected elements (or the one under the cursor) by one cell, cursor along. */
export function nudgeTargets(ctx: EditorContext, dRow: number, dCol: number) {
  const t = targets(ctx);
  if (!t) return;
  const n = networkById(ctx, t.network);
  // A box nudged onto the first column stays right of the rail (networkEdits.ts): the cursor follows it.
  const shift = n ? moveShift(n, t.ids, dCol) : 0;
  if (!ctx.doc.getState().moveElements(t.network, t.ids, dRow, dCol)) {
    ctx.ui.getState().setStatus('Cannot move there: another element is in the way, or the edge of the grid.');
    return;
  }
  const ui = ctx.ui.getState();
  ui.select(t.network, t.ids);
  if (ui.cursor?.network === t.network)
    ui.setCursor({ ...ui.cursor, row: ui.cursor.row + dRow, col: ui.cursor.col + dCol + shift });
}

/** The elements a command acts on: the selection, else the element under the cursor. */
export function targets(ctx: EditorContext): { network: NetworkId; ids: ElementId[] } | undefined {
  const ui = ctx.ui.getState();
  const sel = ui.selection;
  if (sel.network && sel.elements.length > 0 && networkById(ctx, sel.network))
    return { network: sel.network, ids: [...sel.elements] };
  if (!ui.cursor) return undefined;
  const n = networkById(ctx, ui.cursor.network);
  const el = n && elementAt(n, ui.cursor, libraryOf(ctx));
  return n && el ? { network: n.id, ids: [el.id] } : undefined;
}

export function deleteTargets(ctx: EditorContext) {
  const t = targets(ctx);
  if (!t) return;
  ctx.doc.getState().deleteElements(t.network, t.ids);
  ctx.ui.getState().select(t.network, []);
}

export function wrapTargetsInBranch(ctx: EditorContext) {
  const t = targets(ctx);
  if (!t) return ctx.ui.getState().setStatus('Select the elements to put a parallel branch around.');
  ctx.doc.getState().wrapInParallelBranch(t.network, t.ids);
}

export function duplicateTargets(ctx: EditorContext) {
  const t = targets(ctx);
  if (!t) return;
  const ids = ctx.doc.getState().duplicateElements(t.network, t.ids);
  ctx.ui.getState().select(t.network, ids);
}

/** Enter: edit the name of the element under the cursor (or the single selected element); on a box, its first open pin operand. */
export function editAtCursor(ctx: EditorContext) {
  const t = targets(ctx);
  const n = t && networkById(ctx, t.network);
  const el = n?.elements.find((e) => e.id === t?.ids[0]);
  if (!n || !el) return;
  if (el.kind === 'box') return editBox(ctx, n, el);
  if (!needsName(el)) return ctx.ui.getState().setStatus('This element has no name to edit.');
  ctx.ui.getState().startEditing(el.id);
}

/** Vertical link down from the cursor cell's left edge (or right edge). */
export function toggleVLinkAtCursor(ctx: EditorContext, side: 'left' | 'right') {
  const c = ensureCursor(ctx);
  const boundary = side === 'left' ? c.col : c.col + 1;
  ctx.doc.getState().toggleVLink(c.network, { row: c.row, boundary });
}

export function selectAllInNetwork(ctx: EditorContext) {
  const c = ctx.ui.getState().cursor ?? ensureCursor(ctx);
  const n = networkById(ctx, c.network);
  if (n)
    ctx.ui.getState().select(
      n.id,
      n.elements.map((e) => e.id),
    );
}

/** Network the cursor or selection is in (else the last one). */
export function currentNetworkIndex(ctx: EditorContext): number {
  const nets = networksOf(ctx);
  const ui = ctx.ui.getState();
  const id = ui.cursor?.network ?? ui.selection.network;
  const i = nets.findIndex((n) => n.id === id);
  return i >= 0 ? i : nets.length - 1;
}

export function insertNetworkBelow(ctx: EditorContext) {
  const id = ctx.doc.getState().insertNetwork(currentNetworkIndex(ctx) + 1);
  ctx.ui.getState().focusCell(id, { row: 0, col: 0 });
}

export function deleteCurrentNetwork(ctx: EditorContext) {
  const nets = networksOf(ctx);
  const i = currentNetworkIndex(ctx);
  const n = nets[i];
  if (!n) return;
  ctx.doc.getState().deleteNetwork(n.id);
  const next = networksOf(ctx)[Math.min(i, nets.length - 2)];
  ctx.ui.getState().clearSelection();
  ctx.ui.getState().setCursor(next ? { network: next.id, row: 0, col: 0 } : undefined);
}

export function escape(ctx: EditorContext) {
  const ui = ctx.ui.getState();
  if (ui.blockPicker) return ui.closeBlockPicker();
  if (ui.tool.kind !== 'select') return ui.setTool({ kind: 'select' });
  ui.clearSelection();
}

/** Zoom so the widest network fits the visible width. */
export function zoomToFit(ctx: EditorContext, contentWidth: number) {
  const ui = ctx.ui.getState();
  ui.setZoom(Math.min(1.5, (ui.viewport.width - 24) / Math.max(1, contentWidth)));
}

// ---- Typing a box's pin operands from the keyboard: Enter on a box opens the field of its first open
// pin (or its unnamed instance), Tab / Shift+Tab go to the next / previous field (see
// src/editor/canvas/pinOperands.ts for the order).

function editField(ctx: EditorContext, box: BoxElement, field: string | undefined) {
  const ui = ctx.ui.getState();
  if (field === undefined) {
    ui.stopEditing();
    return ui.setStatus(`Every pin of this ${box.blockType} is wired: nothing to type.`);
  }
  ui.startEditing(box.id, field === INSTANCE_FIELD ? {} : { pin: field });
}

/** Enter on a box. */
export function editBox(ctx: EditorContext, n: Network, box: BoxElement) {
  editField(ctx, box, firstField(n, box, libraryOf(ctx)));
}

/** Tab (or Shift+Tab, `back`) from `field` of the box: the next field, as the document is now. */
export function tabToField(ctx: EditorContext, network: NetworkId, boxId: ElementId, field: string, back: boolean) {
  const n = networkById(ctx, network);
  const box = n?.elements.find((e): e is BoxElement => e.id === boxId && e.kind === 'box');
  if (!n || !box) return ctx.ui.getState().stopEditing();
  editField(ctx, box, nextField(n, box, field, back, libraryOf(ctx)));
}
