// Cells to pixels and back. Model positions are cells (src/model/grid.ts); pixels live only here,
// in unscaled content coordinates (zoom is applied by the stage and the header overlay).
import type { Cell } from '../../model/grid';
import type { BlockLibrary } from '../../model/library';
import type { LdElement } from '../../model/elements';
import type { NetworkId } from '../../model/ids';
import type { Network } from '../../model/project';
import { usedRows } from '../../store/networkEdits';
import {
  boundaryAtX,
  colAtX,
  colLeft,
  displayCol,
  modelBoundary,
  modelCol,
  networkColumns,
  spanWidth,
  type NetworkColumns,
} from './columns';

import { textWidth, wrappedLines, type FontSpec } from './textWidth';

export { CELL_W } from './columns';

/** A position in canvas content pixels (before zoom). Not a Cell. */
export interface PixelPoint {
  readonly x: number;
  readonly y: number;
}

export const CELL_H = 64;
/** Height of the wire inside a cell, leaving room for the variable name above it. */
export const WIRE_Y = 40;
/** The left power rail's x; the grid starts here. */
export const RAIL_X = 28;
export const HEADER_TITLE_H = 36;
export const COMMENT_LINE_H = 20;
export const GRID_PAD_BOTTOM = 14;
export const NETWORK_GAP = 10;

/** The header's text (13px; the title bold), as canvas.css sets it. */
const HEADER_FONT: FontSpec = { size: 13 };
const TITLE_FONT: FontSpec = { size: 13, bold: true };
/**
 * A comment is shown whole: its field spans the header (less COMMENT_INSET) up to COMMENT_W, and
 * its lines wrap at that width (the same for every network, so the layout never depends on the
 * view); the header is at least as wide as the comment's longest line needs (up to COMMENT_W).
 */
export const COMMENT_W = 640;
/** The header's width around its comment field: padding, the field's left margin and right gap. */
const COMMENT_INSET = 48;
/** The comment field's padding and border. */
const COMMENT_PAD = 10;
/** The title field's usual width; it shrinks to its text when the header is narrow, never below it. */
export const TITLE_W = 260;
const TITLE_MIN_W = 80;
/** The title bar without its title field: handle, marks, number, label, badge, buttons, gaps. */
export const TITLEBAR_REST_W = 520;

const commentMemo = new Map<string, { lines: number; widest: number }>();
function commentText(comment: string): { lines: number; widest: number } {
  let m = commentMemo.get(comment);
  if (!m) {
    if (commentMemo.size > 4096) commentMemo.clear();
    let widest = 0;
    for (const line of comment.split('\n')) widest = Math.max(widest, textWidth(line, HEADER_FONT));
    m = { lines: Math.max(1, wrappedLines(comment, COMMENT_W - COMMENT_PAD, HEADER_FONT)), widest };
    commentMemo.set(comment, m);
  }
  return m;
}

/** Lines the comment field shows: every line of the comment, long ones wrapped (at least one). */
export const commentLines = (n: Pick<Network, 'comment'>): number => (n.comment ? commentText(n.comment).lines : 1);

/** The title field's narrowest width: the whole title with the field's padding and border. */
export const titleFieldWidth = (n: Pick<Network, 'title'>): number =>
  Math.max(TITLE_MIN_W, Math.ceil(textWidth(n.title, TITLE_FONT)) + 14);

/** The width a network's header needs: the title bar with the whole title, the comment's longest line. */
export function headerNeed(n: Pick<Network, 'title' | 'comment'>): number {
  const comment = Math.min(COMMENT_W, Math.ceil(commentText(n.comment).widest) + COMMENT_PAD + 2);
  return Math.max(TITLEBAR_REST_W + titleFieldWidth(n), COMMENT_INSET + comment);
}

/** A collapsed network is its title bar alone: one header line, a small gap below. */
export const COLLAPSED_HEADER_H = HEADER_TITLE_H;
export const COLLAPSED_GAP = 4;

export const headerHeight = (n: Pick<Network, 'comment' | 'collapsed'>): number =>
  n.collapsed ? COLLAPSED_HEADER_H : HEADER_TITLE_H + commentLines(n) * COMMENT_LINE_H + 6;

/**
 * Comments under operands (CODESYS "Show symbol comment" and the per-element "operand comment"):
 * a row that shows them is taller by COMMENT_BAND, two lines of small text under the symbol.
 */
export const COMMENT_BAND = 26;
export const COMMENT_PITCH = CELL_H + COMMENT_BAND;

/** The symbol comment of a variable name (the view option on), or undefined (off / none). */
export type SymbolComments = (name: string) => string | undefined;

/** Names an element writes under itself: contact/coil variable, or a box's instance. */
function operandNames(el: LdElement): readonly string[] {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return el.variable ? [el.variable] : [];
    case 'box':
      return [...Object.values(el.inputs), ...Object.values(el.outputs)].filter(Boolean);
    default:
      return [];
  }
}

/**
 * The comment shown under a contact or coil: its own (operand) comment first, else the symbol
 * comment of its variable (when the option gives `symbols`).
 */
export function elementCommentText(el: LdElement, symbols?: SymbolComments): string | undefined {
  if (el.comment) return el.comment;
  if (!symbols || (el.kind !== 'contact' && el.kind !== 'coil') || !el.variable) return undefined;
  return symbols(el.variable);
}

const pitchMemo = new WeakMap<Network, { symbols: SymbolComments | undefined; pitch: number }>();

/**
 * Height of a network's rows: CELL_H, or COMMENT_PITCH when one of its elements shows a comment
 * (its own, or its variables' with `symbols`). Memoised per network object and lookup.
 */
export function rowPitch(n: Network, symbols?: SymbolComments): number {
  const hit = pitchMemo.get(n);
  if (hit && hit.symbols === symbols) return hit.pitch;
  let pitch = CELL_H;
  for (const el of n.elements) {
    if (el.comment || (symbols && operandNames(el).some((name) => symbols(name)))) {
      pitch = COMMENT_PITCH;
      break;
    }
  }
  pitchMemo.set(n, { symbols, pitch });
  return pitch;
}

/** Height of a network's grid of `rows` shown rows (none when collapsed). */
export const gridHeight = (n: Pick<Network, 'collapsed'>, pitch = CELL_H, rows = 1): number =>
  n.collapsed ? 0 : rows * pitch + GRID_PAD_BOTTOM;

/**
 * Room to place into, beyond the rows a network uses (CODESYS/TIA: a network is as tall as its
 * rung; room appears while placing). `all`: every network shows one empty row under its last used
 * row (a palette tool is armed or elements are being dragged: a drop target). `network`/`rows`:
 * that network shows at least `rows` rows (the keyboard cursor went below its last used row).
 */
export interface Room {
  readonly all?: boolean;
  readonly network?: NetworkId;
  readonly rows?: number;
}

/** Rows network `n` shows: the rows its elements use (at least one), and the room asked for. */
export function shownRows(n: Network, library?: BlockLibrary, room?: Room): number {
  return withRoom(n, usedRows(n, library), room);
}

/** Rows a network that uses `used` rows shows with the room asked for. */
function withRoom(n: Network, used: number, room: Room | undefined): number {
  if (room?.all) return used + 1;
  return room?.network === n.id && room.rows ? Math.max(used, room.rows) : used;
}

export const networkHeight = (n: Network, symbols?: SymbolComments, rows = 1): number =>
  headerHeight(n) + gridHeight(n, rowPitch(n, symbols), rows) + (n.collapsed ? COLLAPSED_GAP : NETWORK_GAP);

/** Width of a network's drawing: the rails and its columns (each as wide as its longest name). */
export const networkWidth = (n: Network, library?: BlockLibrary): number =>
  RAIL_X * 2 + networkColumns(n, library).xs[n.cols]!;

export interface CanvasLayout {
  /** Top of each network (content pixels). */
  readonly tops: Float64Array;
  readonly heights: Float64Array;
  readonly totalHeight: number;
  readonly totalWidth: number;
  /** Height of each network's rows (CELL_H, or taller where comments are shown under operands). */
  readonly pitches: Float64Array;
  /** The symbol comments the layout was made with (undefined: the view option is off). */
  readonly symbols: SymbolComments | undefined;
  /** The project's blocks the columns were measured with (user FB boxes and their pins). */
  readonly library: BlockLibrary | undefined;
  /** Rows each network shows (shownRows: its used rows and the room asked for). */
  readonly rows: Int32Array;
  /** The room the layout was made with. */
  readonly room: Room | undefined;
}

export function layoutNetworks(
  networks: readonly Network[],
  library?: BlockLibrary,
  symbols?: SymbolComments,
  room?: Room,
): CanvasLayout {
  const tops = new Float64Array(networks.length);
  const heights = new Float64Array(networks.length);
  const pitches = new Float64Array(networks.length);
  const rows = new Int32Array(networks.length);
  let y = 8;
  let width = 480;
  networks.forEach((n, i) => {
    const m = networkMeasures(n, library, symbols);
    tops[i] = y;
    pitches[i] = m.pitch;
    const shown = withRoom(n, m.used, room);
    rows[i] = shown;
    const height = headerHeight(n) + gridHeight(n, m.pitch, shown) + (n.collapsed ? COLLAPSED_GAP : NETWORK_GAP);
    heights[i] = height;
    y += height;
    width = Math.max(width, m.width);
  });
  return { tops, heights, pitches, rows, room, symbols, totalHeight: y + 40, totalWidth: width, library };
}

interface NetworkMeasures {
  readonly library: BlockLibrary | undefined;
  readonly symbols: SymbolComments | undefined;
  readonly pitch: number;
  /** The rows its elements use (at least one): shownRows without room. */
  readonly used: number;
  /** The layout width the network needs: its grid or its header, whichever is wider. */
  readonly width: number;
}
const measuresMemo = new WeakMap<Network, NetworkMeasures>();

/**
 * A network's row pitch, used rows and needed width, memoised per network object, library and symbol
 * lookup: an edit lays out again only the networks it replaced (the others keep their objects).
 */
export function networkMeasures(n: Network, library?: BlockLibrary, symbols?: SymbolComments): NetworkMeasures {
  const hit = measuresMemo.get(n);
  if (hit && hit.library === library && hit.symbols === symbols) return hit;
  const m: NetworkMeasures = {
    library,
    symbols,
    pitch: rowPitch(n, symbols),
    used: usedRows(n, library),
    width: Math.max(networkWidth(n, library) + 16, HEADER_LEFT + headerNeed(n) + 8),
  };
  measuresMemo.set(n, m);
  return m;
}

/** Rows network `index` shows in a layout. */
export const rowsOf = (layout: CanvasLayout, index: number): number => layout.rows[index] ?? 1;

/** Row height of network `index` in a layout. */
export const pitchOf = (layout: CanvasLayout, index: number): number => layout.pitches[index] ?? CELL_H;

/** The columns of network `n` as laid out (the layout's library). */
export const columnsOf = (layout: CanvasLayout, n: Network): NetworkColumns => networkColumns(n, layout.library);

/**
 * A model cell's rectangle relative to the grid's top-left (a rail-aligned coil's cell is drawn in
 * the last column); `cols` columns wide.
 */
export function cellRect(
  nc: NetworkColumns,
  cell: Cell,
  cols = 1,
  rows = 1,
  pitch = CELL_H,
): { x: number; y: number; width: number; height: number } {
  const d = displayCol(nc, cell.row, cell.col);
  return { x: colLeft(nc, d), y: cell.row * pitch, width: spanWidth(nc, d, cols), height: rows * pitch };
}

/** Index of the network containing content y (the last one starting at or above y), -1 before the first. */
export function networkIndexAt(layout: CanvasLayout, y: number): number {
  let lo = 0;
  let hi = layout.tops.length - 1;
  let found = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (layout.tops[mid]! <= y) {
      found = mid;
      lo = mid + 1;
    } else hi = mid - 1;
  }
  return found;
}

/** Networks overlapping content rows [top, bottom]: first and last index (inclusive); empty when last < first. */
export function visibleRange(
  layout: CanvasLayout,
  top: number,
  bottom: number,
): { first: number; last: number } {
  const first = Math.max(0, networkIndexAt(layout, top));
  const last = networkIndexAt(layout, bottom);
  return { first, last };
}

/** The left edge of a network's header (content pixels). */
export const HEADER_LEFT = RAIL_X - 20;

/** Top-left of a network's cell grid relative to the network's top. */
export const gridOrigin = (n: Pick<Network, 'comment' | 'collapsed'>): PixelPoint => ({ x: RAIL_X, y: headerHeight(n) });

export type Hit =
  | { readonly area: 'none' }
  | { readonly area: 'header'; readonly index: number }
  | {
      readonly area: 'grid';
      readonly index: number;
      /** The cell under the pointer (may lie outside the grid to the right/bottom: placing there grows it). */
      readonly cell: Cell;
      /** The nearest column boundary, and the row whose wire is just above the pointer (a vertical link goes down from it). */
      readonly boundary: number;
      readonly wireRow: number;
    };

/** What lies under content point p. */
export function hitTest(layout: CanvasLayout, networks: readonly Network[], p: PixelPoint): Hit {
  const index = networkIndexAt(layout, p.y);
  const n = networks[index];
  if (!n) return { area: 'none' };
  const local = p.y - layout.tops[index]!;
  const origin = gridOrigin(n);
  if (local < origin.y) return { area: 'header', index };
  const pitch = pitchOf(layout, index);
  const rows = rowsOf(layout, index);
  if (n.collapsed || local > origin.y + rows * pitch + GRID_PAD_BOTTOM) return { area: 'none' };
  const nc = columnsOf(layout, n);
  const gx = p.x - origin.x;
  const gy = local - origin.y;
  const row = Math.min(rows - 1, Math.max(0, Math.floor(gy / pitch)));
  const col = modelCol(nc, row, colAtX(nc, gx));
  const wireRow = Math.max(0, Math.min(rows - 1, Math.floor((gy - WIRE_Y) / pitch)));
  const boundary = modelBoundary(nc, wireRow, boundaryAtX(nc, gx));
  return { area: 'grid', index, cell: { row, col }, boundary, wireRow };
}

/** Content point of the middle of a model cell of network `index` (where a user clicks it). */
export function cellCentre(layout: CanvasLayout, networks: readonly Network[], index: number, cell: Cell): PixelPoint {
  const n = networks[index]!;
  const pitch = pitchOf(layout, index);
  const r = cellRect(columnsOf(layout, n), cell, 1, 1, pitch);
  return { x: RAIL_X + r.x + r.width / 2, y: layout.tops[index]! + headerHeight(n) + r.y + CELL_H / 2 };
}
