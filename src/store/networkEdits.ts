// Pure edits of one network's grid. The document store turns their results into diffs.
//
// Placing: an element goes on the cell it is dropped on; horizontal links under it are
// replaced. Insert in series (placing on a cell that holds a contact, coil, box...): the new
// element goes at that element's left edge `c`, and every element whose left edge is at or
// right of `c` (on every row) moves right by the new element's width; vertical links right of
// boundary `c` move with them (links *at* `c` stay on the left, so the new element sits after a
// branch join). On other rows, where a connection crossed boundary `c` (something ended at `c`
// — the left rail, an element or a vertical link — and something started at `c`), horizontal
// links fill the gap so every other path keeps its meaning. `cols` grows when needed.
//
// A box dropped on the first column does not sit on the left rail (that would feed the rail's
// power into every input): it goes one column right, and a link joins the rail to its power-flow
// input only (EN, else the first BOOL input). Its other inputs stay open for operands. Moving or
// pasting elements so that a box lands on the first column does the same: they all go one column
// further right, and the rail feeds each such box's power-flow input only.
import { boxLayout, type BoxLayout, type PlacedPin } from '../model/boxLayout';
import { STANDARD_LIBRARY, type BlockLibrary } from '../model/library';
import { withoutExecutionOrder, type LdElement, type VLink } from '../model/elements';
import { elementCells, elementSize } from '../model/factory';
import { cellKey, type Cell } from '../model/grid';
import { renamePastedConnectors, withDefaultName } from './connectors';
import { newId, type ElementId } from '../model/ids';
import type { Network } from '../model/project';

type DistributiveOmit<T, K extends PropertyKey> = T extends unknown ? Omit<T, K> : never;
/** An element before it has an id and a place: `{ kind: 'contact', contact: 'NO', variable: 'Start' }`. */
export type ElementTemplate = DistributiveOmit<LdElement, 'id' | 'row' | 'col'>;

export const placed = (t: ElementTemplate, id: ElementId, row: number, col: number): LdElement =>
  ({ ...t, id, row, col }) as LdElement;

export const templateSize = (t: ElementTemplate, lib: BlockLibrary = STANDARD_LIBRARY) =>
  elementSize(placed(t, '' as ElementId, 0, 0), lib);

/** Which element covers each cell, by cellKey. */
export function occupancy(
  n: Network,
  ignore?: ReadonlySet<ElementId>,
  lib: BlockLibrary = STANDARD_LIBRARY,
): Map<string, LdElement> {
  const map = new Map<string, LdElement>();
  for (const el of n.elements) {
    if (ignore?.has(el.id)) continue;
    for (const c of elementCells(el, lib)) map.set(cellKey(c.row, c.col), el);
  }
  return map;
}

export const elementAt = (
  n: Network,
  cell: Cell,
  lib: BlockLibrary = STANDARD_LIBRARY,
): LdElement | undefined => occupancy(n, undefined, lib).get(cellKey(cell.row, cell.col));

/** The network with these elements and vertical links, its grid grown to hold them all. */
export function grow(
  n: Network,
  elements: readonly LdElement[],
  vlinks: readonly VLink[],
  lib: BlockLibrary = STANDARD_LIBRARY,
): Network {
  let rows = n.rows;
  let cols = n.cols;
  for (const el of elements) {
    const s = elementSize(el, lib);
    rows = Math.max(rows, el.row + s.rows);
    cols = Math.max(cols, el.col + s.cols);
  }
  for (const v of vlinks) {
    rows = Math.max(rows, v.row + 2);
    cols = Math.max(cols, v.boundary);
  }
  return { ...n, elements, vlinks, rows, cols };
}

/** Cells an element would cover at (row, col). */
function cellsAt(t: ElementTemplate, row: number, col: number, lib: BlockLibrary): Cell[] {
  return elementCells(placed(t, '' as ElementId, row, col), lib);
}

/**
 * Places an element at `cell` when every cell it covers is free or a horizontal link (the links
 * go). Returns undefined when another element is in the way (the caller inserts in series).
 * An unnamed connector or continuation gets its default name (src/store/connectors.ts).
 */
export function placeElement(
  n: Network,
  cell: Cell,
  template: ElementTemplate,
  id: ElementId,
  lib: BlockLibrary = STANDARD_LIBRARY,
): Network | undefined {
  if (cell.row < 0 || cell.col < 0) return undefined;
  const t = withDefaultName(n, template);
  const occ = occupancy(n, undefined, lib);
  const replaced = new Set<ElementId>();
  for (const c of cellsAt(t, cell.row, cell.col, lib)) {
    const el = occ.get(cellKey(c.row, c.col));
    if (!el) continue;
    if (el.kind !== 'link') return undefined;
    replaced.add(el.id);
  }
  const kept = n.elements.filter((e) => !replaced.has(e.id));
  return grow(n, [...kept, placed(t, id, cell.row, cell.col)], n.vlinks, lib);
}

/** The input that takes the power flow: EN (functions, FBs with EN/ENO), else the first BOOL input. */
export const powerFlowInput = (layout: BoxLayout): PlacedPin | undefined =>
  layout.inputs.find((p) => p.name === 'EN') ?? layout.inputs.find((p) => p.type === 'BOOL');

/** The output that carries the power flow on: ENO (functions, FBs with EN/ENO), else the first BOOL output. */
export const powerFlowOutput = (layout: BoxLayout): PlacedPin | undefined =>
  layout.outputs.find((p) => p.name === 'ENO') ?? layout.outputs.find((p) => p.type === 'BOOL');

/**
 * A box put on the first column (see the file comment): placed (or inserted in series) at column
 * 1 with one link from the rail to its power-flow input; links from the rail to its other inputs
 * go. Undefined for anything else, or when there is no room (the caller places it as asked).
 */
export function placeBoxOffRail(
  n: Network,
  cell: Cell,
  t: ElementTemplate,
  id: ElementId,
  newId: () => ElementId,
  lib: BlockLibrary = STANDARD_LIBRARY,
): Network | undefined {
  if (t.kind !== 'box' || cell.col !== 0) return undefined;
  const layout = boxLayout(t, lib);
  if (!layout) return undefined;
  // An element on the first cell: make a column of room before it (the box goes in front of it).
  const occupant = elementAt(n, cell, lib);
  const room =
    occupant && occupant.kind !== 'link'
      ? insertInSeries(n, cell, { kind: 'link' }, newId(), lib)
      : n;
  if (!room) return undefined;
  const at = { row: cell.row, col: 1 };
  const out = placeElement(room, at, t, id, lib) ?? insertInSeries(room, at, t, id, lib);
  const box = out?.elements.find((e) => e.id === id);
  if (!out || !box || box.col !== 1) return undefined;
  return feedFromRail(out, [id], newId, lib);
}

/** Columns that moved or pasted elements go further right: 1 when one of them is a box on the first column. */
export const offRailShift = (els: readonly Pick<LdElement, 'kind' | 'col'>[]): number =>
  els.some((e) => e.kind === 'box' && e.col === 0) ? 1 : 0;

/** The extra columns elements `ids` of `n` go when moved `dCol` columns (offRailShift). */
export function moveShift(n: Network, ids: readonly ElementId[], dCol: number): number {
  const set = new Set(ids);
  return offRailShift(n.elements.filter((e) => set.has(e.id)).map((e) => ({ ...e, col: e.col + dCol })));
}

/**
 * The rail feeds only the power-flow input of each of these boxes at column 1: a link joins the
 * rail to that input where its cell in column 0 is free, links from the rail to its other inputs go.
 */
export function feedFromRail(
  n: Network,
  boxIds: readonly ElementId[],
  newId: () => ElementId,
  lib: BlockLibrary = STANDARD_LIBRARY,
): Network {
  let elements = [...n.elements];
  for (const id of boxIds) {
    const box = elements.find((e) => e.id === id);
    const layout = box?.kind === 'box' && box.col === 1 ? boxLayout(box, lib) : undefined;
    if (!box || !layout) continue;
    const power = powerFlowInput(layout);
    const powerRow = power ? box.row + power.rowOffset : -1;
    const inputRows = new Set(layout.inputs.map((p) => box.row + p.rowOffset));
    elements = elements.filter(
      (e) => !(e.kind === 'link' && e.col === 0 && inputRows.has(e.row) && e.row !== powerRow),
    );
    const occ = occupancy({ ...n, elements }, undefined, lib);
    if (power && !occ.has(cellKey(powerRow, 0))) elements.push({ kind: 'link', id: newId(), row: powerRow, col: 0 });
  }
  return grow(n, elements, n.vlinks, lib);
}

/** Boxes among `els` (moved or pasted `shift` columns further right) that went off the rail to column 1. */
export const shiftedBoxes = (els: readonly LdElement[], shift: number): ElementId[] =>
  shift ? els.filter((e) => e.kind === 'box' && e.col === 1).map((e) => e.id) : [];

/** Does element `el` connect to the point on row `row` at its left (side 'in') or right ('out') edge? */
function pinOnRow(el: LdElement, row: number, side: 'in' | 'out', lib: BlockLibrary): boolean {
  if (el.kind !== 'box') return el.row === row;
  const layout = boxLayout(el, lib);
  if (!layout) return el.row === row;
  const pins = side === 'in' ? layout.inputs : layout.outputs;
  return pins.some((p) => el.row + p.rowOffset === row);
}

/**
 * Insert in series at `cell` (see the file comment). Undefined when there is no room: a box
 * straddles the insertion column, or a path crosses it on a row a new multi-row box would cover.
 */
export function insertInSeries(
  n: Network,
  cell: Cell,
  template: ElementTemplate,
  id: ElementId,
  lib: BlockLibrary = STANDARD_LIBRARY,
): Network | undefined {
  const t = withDefaultName(n, template);
  const occupant = elementAt(n, cell, lib);
  if (!occupant || occupant.kind === 'link') {
    const direct = placeElement(n, cell, t, id, lib);
    if (direct) return direct;
  }
  const { rows: h, cols: w } = templateSize(t, lib);
  const c = occupant && occupant.kind !== 'link' ? occupant.col : cell.col;
  const row = cell.row;
  const lastRow = Math.max(n.rows, row + h);
  const bridgeRows: number[] = [];
  for (let r = 0; r < lastRow; r++) {
    if (r === row) continue;
    const endsHere =
      c === 0 ||
      n.elements.some((e) => e.col + elementSize(e, lib).cols === c && pinOnRow(e, r, 'out', lib)) ||
      n.vlinks.some((v) => v.boundary === c && (v.row === r || v.row + 1 === r));
    const startsHere = n.elements.some((e) => e.col === c && pinOnRow(e, r, 'in', lib));
    if (!endsHere || !startsHere) continue;
    // A path crossing where the new box's lower rows go would meet its pins: no room.
    if (r > row && r < row + h) return undefined;
    bridgeRows.push(r);
  }
  const shifted = n.elements.map((e) => (e.col >= c ? { ...e, col: e.col + w } : e));
  const vlinks = n.vlinks.map((v) => (v.boundary > c ? { ...v, boundary: v.boundary + w } : v));
  const after: Network = { ...n, elements: shifted, vlinks, cols: n.cols + w };
  const occ = occupancy(after, undefined, lib);
  if (cellsAt(t, row, c, lib).some((x) => occ.has(cellKey(x.row, x.col)))) return undefined;
  const bridges: LdElement[] = [];
  for (const r of bridgeRows) {
    for (let k = 0; k < w; k++) bridges.push({ kind: 'link', id: newBridgeId(id, r, k), row: r, col: c + k });
  }
  const result = grow(after, [...shifted, placed(t, id, row, c), ...bridges], vlinks, lib);
  return { ...result, cols: Math.max(n.cols, usedCols(result, lib)) };
}

const newBridgeId = (base: ElementId, row: number, k: number) => `${base}_b${row}_${k}` as ElementId;

function usedCols(n: Network, lib: BlockLibrary): number {
  let cols = 0;
  for (const e of n.elements) cols = Math.max(cols, e.col + elementSize(e, lib).cols);
  for (const v of n.vlinks) cols = Math.max(cols, v.boundary);
  return cols;
}

/** Bounding box of some elements: rows top..bottom (inclusive), boundaries left..right. */
export function boundsOf(
  elements: readonly LdElement[],
  lib: BlockLibrary = STANDARD_LIBRARY,
): { top: number; bottom: number; left: number; right: number } | undefined {
  if (elements.length === 0) return undefined;
  let top = Infinity;
  let bottom = -Infinity;
  let left = Infinity;
  let right = -Infinity;
  for (const e of elements) {
    const s = elementSize(e, lib);
    top = Math.min(top, e.row);
    bottom = Math.max(bottom, e.row + s.rows - 1);
    left = Math.min(left, e.col);
    right = Math.max(right, e.col + s.cols);
  }
  return { top, bottom, left, right };
}

/**
 * Wraps the selected elements in a parallel branch: a new row is inserted below them (rows
 * below move down; vertical links crossing into them are extended through the new row), holding
 * horizontal links from the selection's left edge to its right edge, joined by vertical links at
 * both ends (none at a power rail, which already joins every row).
 */
export function wrapInParallelBranch(
  n: Network,
  ids: readonly ElementId[],
  newId: () => ElementId,
  lib: BlockLibrary = STANDARD_LIBRARY,
): Network | undefined {
  const set = new Set(ids);
  const sel = n.elements.filter((e) => set.has(e.id));
  const b = boundsOf(sel, lib);
  if (!b) return undefined;
  let newRow = b.bottom + 1;
  // Never split a box that spans the row boundary.
  while (n.elements.some((e) => e.row < newRow && e.row + elementSize(e, lib).rows > newRow)) newRow++;
  const elements: LdElement[] = n.elements.map((e) => (e.row >= newRow ? { ...e, row: e.row + 1 } : e));
  const vlinks: VLink[] = [];
  for (const v of n.vlinks) {
    if (v.row >= newRow) vlinks.push({ ...v, row: v.row + 1 });
    else {
      vlinks.push(v);
      if (v.row === newRow - 1) vlinks.push({ row: newRow, boundary: v.boundary });
    }
  }
  for (let col = b.left; col < b.right; col++) elements.push({ kind: 'link', id: newId(), row: newRow, col });
  const cols = Math.max(n.cols, b.right);
  for (const boundary of [b.left, b.right]) {
    if (boundary === 0 || boundary === cols) continue;
    for (let r = b.top; r < newRow; r++) {
      if (!vlinks.some((v) => v.row === r && v.boundary === boundary)) vlinks.push({ row: r, boundary });
    }
  }
  return grow({ ...n, rows: n.rows + 1, cols }, elements, vlinks, lib);
}

/** Moves elements by whole cells; horizontal links in the way go. Undefined if off-grid or blocked. */
export function moveElements(
  n: Network,
  ids: readonly ElementId[],
  dRow: number,
  dCol: number,
  lib: BlockLibrary = STANDARD_LIBRARY,
  makeId: () => ElementId = () => newId<'ElementId'>('e'),
): Network | undefined {
  if (dRow === 0 && dCol === 0) return n;
  const set = new Set(ids);
  const shift = moveShift(n, ids, dCol);
  const out = moveBy(n, set, dRow, dCol + shift, lib);
  // A box moved left onto the first column from column 1 stays there and is fed like a placed one.
  if (!out || !shift) return out;
  return feedFromRail(out, shiftedBoxes(out.elements.filter((e) => set.has(e.id)), shift), makeId, lib);
}

function moveBy(
  n: Network,
  set: ReadonlySet<ElementId>,
  dRow: number,
  dCol: number,
  lib: BlockLibrary,
): Network | undefined {
  if (dRow === 0 && dCol === 0) return n;
  const moved = n.elements
    .filter((e) => set.has(e.id))
    .map((e) => ({ ...e, row: e.row + dRow, col: e.col + dCol }));
  if (moved.length === 0 || moved.some((e) => e.row < 0 || e.col < 0)) return undefined;
  const occ = occupancy(n, set, lib);
  const replaced = new Set<ElementId>();
  for (const el of moved) {
    for (const c of elementCells(el, lib)) {
      const other = occ.get(cellKey(c.row, c.col));
      if (!other) continue;
      if (other.kind !== 'link') return undefined;
      replaced.add(other.id);
    }
  }
  const byId = new Map(moved.map((e) => [e.id, e]));
  const elements = n.elements.filter((e) => !replaced.has(e.id)).map((e) => byId.get(e.id) ?? e);
  return grow(n, elements, n.vlinks, lib);
}

export function deleteElements(n: Network, ids: readonly ElementId[]): Network {
  const set = new Set(ids);
  return { ...n, elements: n.elements.filter((e) => !set.has(e.id)) };
}

export function addVLink(n: Network, v: VLink, lib: BlockLibrary = STANDARD_LIBRARY): Network {
  if (v.row < 0 || v.boundary < 0 || n.vlinks.some((w) => w.row === v.row && w.boundary === v.boundary))
    return n;
  return grow(n, n.elements, [...n.vlinks, v], lib);
}

export function removeVLink(n: Network, v: VLink): Network {
  return { ...n, vlinks: n.vlinks.filter((w) => w.row !== v.row || w.boundary !== v.boundary) };
}

/** A copied piece of a network: positions relative to the copied area's top-left cell. */
export interface ClipContent {
  readonly elements: readonly LdElement[];
  readonly vlinks: readonly VLink[];
}

/** The selected elements and the vertical links inside their area, moved to (0, 0). */
export function copyElements(
  n: Network,
  ids: readonly ElementId[],
  lib: BlockLibrary = STANDARD_LIBRARY,
): ClipContent | undefined {
  const set = new Set(ids);
  const sel = n.elements.filter((e) => set.has(e.id));
  const b = boundsOf(sel, lib);
  if (!b) return undefined;
  return {
    elements: sel.map((e) => ({ ...e, row: e.row - b.top, col: e.col - b.left })),
    vlinks: n.vlinks
      .filter((v) => v.row >= b.top && v.row < b.bottom && v.boundary >= b.left && v.boundary <= b.right)
      .map((v) => ({ row: v.row - b.top, boundary: v.boundary - b.left })),
  };
}

/**
 * Pastes at `at` (new ids); horizontal links under the pasted cells go. When another element is
 * in the way, the paste goes below everything in the network instead, at the same column.
 * Returns the network and the pasted elements' ids.
 */
export function pasteElements(
  n: Network,
  clip: ClipContent,
  at: Cell,
  newId: () => ElementId,
  lib: BlockLibrary = STANDARD_LIBRARY,
): { network: Network; ids: ElementId[] } {
  const shift = offRailShift(clip.elements.map((e) => ({ ...e, col: e.col + at.col })));
  const col = at.col + shift;
  const fits = (row: number) => {
    const occ = occupancy(n, undefined, lib);
    return clip.elements.every((e) =>
      elementCells({ ...e, row: e.row + row, col: e.col + col }, lib).every((c) => {
        const o = occ.get(cellKey(c.row, c.col));
        return !o || o.kind === 'link';
      }),
    );
  };
  const below = Math.max(
    0,
    ...n.elements.map((e) => e.row + elementSize(e, lib).rows),
    ...n.vlinks.map((v) => v.row + 2),
  );
  const row = fits(at.row) ? at.row : below;
  const pasted = renamePastedConnectors(
    n,
    // A pasted copy keeps no PLCopen execution order: it must not jump the openplc queue.
    clip.elements.map((e) => ({ ...withoutExecutionOrder(e), id: newId(), row: e.row + row, col: e.col + col })),
  );
  const occ = occupancy(n, undefined, lib);
  const replaced = new Set<ElementId>();
  for (const el of pasted)
    for (const c of elementCells(el, lib)) {
      const o = occ.get(cellKey(c.row, c.col));
      if (o) replaced.add(o.id);
    }
  const vlinks = [...n.vlinks];
  for (const v of clip.vlinks) {
    const moved = { row: v.row + row, boundary: v.boundary + col };
    if (!vlinks.some((w) => w.row === moved.row && w.boundary === moved.boundary)) vlinks.push(moved);
  }
  const network = grow(n, [...n.elements.filter((e) => !replaced.has(e.id)), ...pasted], vlinks, lib);
  return { network: feedFromRail(network, shiftedBoxes(pasted, shift), newId, lib), ids: pasted.map((e) => e.id) };
}

/**
 * Inserts an empty row at `at` (below a box that spans it): rows from there move one row down; a
 * vertical link that crossed into that row is extended through the new row so no connection breaks.
 */
export function insertRow(n: Network, at: number, lib: BlockLibrary = STANDARD_LIBRARY): Network {
  let row = Math.max(0, Math.min(at, n.rows));
  // Never split a box: a row asked for inside one goes below it.
  while (n.elements.some((e) => e.row < row && e.row + elementSize(e, lib).rows > row)) row++;
  const elements = n.elements.map((e) => (e.row >= row ? { ...e, row: e.row + 1 } : e));
  const vlinks: VLink[] = [];
  for (const v of n.vlinks) {
    if (v.row >= row) vlinks.push({ ...v, row: v.row + 1 });
    else {
      vlinks.push(v);
      if (v.row === row - 1) vlinks.push({ row, boundary: v.boundary });
    }
  }
  return grow({ ...n, rows: n.rows + 1 }, elements, vlinks, lib);
}

/**
 * Deletes row `at` when no element covers it; rows below move up. A vertical link through the
 * row (above and below it at the same edge) stays one link; links that only touched it go.
 * Undefined when an element is on the row or it is the only row.
 */
export function deleteRow(n: Network, at: number, lib: BlockLibrary = STANDARD_LIBRARY): Network | undefined {
  if (n.rows <= 1 || at < 0 || at >= n.rows) return undefined;
  if (n.elements.some((e) => e.row <= at && e.row + elementSize(e, lib).rows > at)) return undefined;
  const elements = n.elements.map((e) => (e.row > at ? { ...e, row: e.row - 1 } : e));
  const vlinks: VLink[] = [];
  for (const v of n.vlinks) {
    if (v.row < at - 1 || v.row > at) vlinks.push(v.row > at ? { ...v, row: v.row - 1 } : v);
    else if (v.row === at - 1 && n.vlinks.some((w) => w.row === at && w.boundary === v.boundary))
      vlinks.push(v);
  }
  return { ...n, rows: n.rows - 1, elements, vlinks };
}

/**
 * The network without the empty rows below its rung (CODESYS/FPWIN "optimize network height"): as
 * many rows as its elements and vertical links reach, so a one-row rung takes one row. An empty
 * network is left as it is (its rows are where a rung gets drawn). The same object when nothing goes.
 */
export function fitRows(n: Network, lib: BlockLibrary = STANDARD_LIBRARY): Network {
  if (n.elements.length === 0 && n.vlinks.length === 0) return n;
  const rows = usedRows(n, lib);
  return rows < n.rows ? { ...n, rows } : n;
}

const usedMemo = new WeakMap<Network, { lib: BlockLibrary; rows: number }>();

/**
 * The rows a network's elements and vertical links reach (at least one): how tall the editor and
 * print draw it. Rows of the model below these are empty and not shown (they stay in the model,
 * so positions and the export do not change). Memoised per network object and library.
 */
export function usedRows(n: Network, lib: BlockLibrary = STANDARD_LIBRARY): number {
  const hit = usedMemo.get(n);
  if (hit && hit.lib === lib) return hit.rows;
  let rows = 1;
  for (const el of n.elements) rows = Math.max(rows, el.row + elementSize(el, lib).rows);
  for (const v of n.vlinks) rows = Math.max(rows, v.row + 2);
  usedMemo.set(n, { lib, rows });
  return rows;
}
