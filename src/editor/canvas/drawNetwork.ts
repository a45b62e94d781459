// Draws one network's grid (rails, vertical links, elements and the overlays: selection,
// cursor, diagnostic markers, drag ghost) with the grid's top-left at the context origin.
import type { NetworkPower } from '../../engine/api';
import { elementSize } from '../../model/factory';
import type { BlockLibrary } from '../../model/library';
import type { Cell } from '../../model/grid';
import type { LdElement } from '../../model/elements';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import { elementAt } from '../../store/networkEdits';
import type { CanvasTheme } from '../theme/canvasTheme';
import { FORCED_BADGE } from '../theme/monitorStyle';
import { networkColumns, type NetworkColumns } from './columns';
import { drawConnectionPartners } from './drawConnectors';
import { openPins } from './pinOperands';
import { drawPinValues, type PinTexts } from './drawPinValues';
import { BOX_TOP, drawElement, wire, wireStyle } from './drawSymbols';
import { CELL_H, cellRect, elementCommentText, GRID_PAD_BOTTOM, WIRE_Y, type SymbolComments } from './geometry';

export interface CellMarker {
  readonly cell: Cell;
  readonly severity: 'error' | 'warning';
  /** "LD-R08: the contact ... is not declared", shown when the pointer rests on the cell. */
  readonly text: string;
}

export interface NetworkPaint {
  /** The project's blocks (user FBs and functions): box sizes and pins. */
  readonly library?: BlockLibrary;
  readonly selected: ReadonlySet<ElementId>;
  readonly cursor: Cell | undefined;
  readonly hover: Cell | undefined;
  /** The cell under the pointer when only its connection partners are drawn here (the canvas draws
   * the hover's fill with a page element, SelectionMarks.tsx); `hover` draws both. */
  readonly partners?: Cell | undefined;
  readonly markers: readonly CellMarker[];
  /** Height of the network's rows (CELL_H when absent; taller when comments are shown under operands). */
  readonly pitch?: number;
  /** Rows drawn (the used rows and any room to place into); the model's rows when absent. */
  readonly rows?: number;
  /** Variables' comments, shown under their operands (the "symbol comments" view option). */
  readonly symbols?: SymbolComments;
  /** Simulation power flow, aligned with network.elements / network.vlinks. */
  readonly power?: NetworkPower;
  readonly liveValues?: ReadonlyMap<ElementId, string>;
  /** Values beside box pins (simulation). */
  readonly pinValues?: ReadonlyMap<ElementId, PinTexts>;
  /** Elements with a forced variable (simulation). */
  readonly forced?: ReadonlySet<ElementId>;
  /** Elements whose device value differs from the program's, with the marker text (simulation with hardware). */
  readonly device?: ReadonlyMap<ElementId, string>;
  /** Elements being dragged (drawn faded) and the offset in cells of their ghost. */
  readonly drag?: {
    readonly ids: ReadonlySet<ElementId>;
    readonly dRow: number;
    readonly dCol: number;
    readonly blocked: boolean;
    /** Ghost drawn instead of the offset one: elements dragged in from another network, in this
     * network's cells (empty in the network they leave). */
    readonly ghost?: readonly LdElement[];
  };
}

type Ctx = CanvasRenderingContext2D;
type Rect = { x: number; y: number; width: number; height: number };

/** An element's drawn rectangle (grid coordinates). */
const elementRect = (nc: NetworkColumns, el: LdElement, lib?: BlockLibrary, pitch = CELL_H): Rect => {
  const s = elementSize(el, lib);
  return cellRect(nc, el, s.cols, s.rows, pitch);
};

/** Height of a device / "Why?" tag: it ends above the variable name drawn over the element. */
export const MARK_TAG_H = 10;

/**
 * The device holds another value than the program, or "Why?" names the element: a small boxed tag
 * ("device: FALSE", "why: blocks") in the element's top strip, right-aligned, clear of the
 * variable name below it (names are drawn from about 12 px down).
 */
function drawDeviceMark(ctx: Ctx, t: CanvasTheme, r: Rect, text: string) {
  ctx.font = 'bold 8.5px system-ui, sans-serif';
  const w = Math.min(ctx.measureText(text).width + 6, r.width - 4);
  const left = r.x + r.width - 2 - w;
  const top = r.y + 0.5;
  ctx.fillStyle = t.networkBg;
  ctx.fillRect(left, top, w, MARK_TAG_H);
  ctx.strokeStyle = t.warning;
  ctx.lineWidth = 1;
  ctx.strokeRect(left, top, w, MARK_TAG_H);
  ctx.fillStyle = t.text;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText(text, left + w / 2, top + MARK_TAG_H / 2 + 0.5, w - 4);
  ctx.textBaseline = 'alphabetic';
}

/** A forced element: an outline and the forced badge (FORCED_BADGE, as in the watch table) at its top-left corner. */
export function drawForcedMark(ctx: Ctx, t: CanvasTheme, r: Rect) {
  const size = FORCED_BADGE.size;
  ctx.strokeStyle = t.forced;
  ctx.lineWidth = 2;
  ctx.strokeRect(r.x + 2, r.y + 2, r.width - 4, r.height - 4);
  ctx.fillStyle = t.forced;
  ctx.fillRect(r.x + 2, r.y + 2, size, size);
  ctx.fillStyle = FORCED_BADGE.letterColour;
  ctx.font = FORCED_BADGE.font;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText(FORCED_BADGE.letter, r.x + 2 + size / 2, r.y + 2.5 + size / 2);
  ctx.textBaseline = 'alphabetic';
}

/** Top of a diagnostic marker's outline inside an element's first row: below the names drawn over it. */
export const MARKER_TOP = WIRE_Y - 14;
/** On a box: just above its body, below its instance name (so the title stays clear too). */
const BOX_MARKER_TOP = BOX_TOP - 2;
/** Side of the marker's corner triangle (bottom-left of the cell, away from every name). */
export const MARKER_CORNER = 13;

/**
 * A diagnostic marker: a dashed outline around the element's symbol (below its name or
 * instance name, so it never hides them) and a filled triangle in the cell's bottom-left corner.
 */
function drawMarker(ctx: Ctx, t: CanvasTheme, m: CellMarker, r: Rect, box: boolean, pitch: number) {
  const top = box ? BOX_MARKER_TOP : MARKER_TOP;
  ctx.strokeStyle = m.severity === 'error' ? t.error : t.warning;
  ctx.fillStyle = ctx.strokeStyle;
  ctx.lineWidth = 2;
  ctx.setLineDash([5, 3]);
  ctx.strokeRect(r.x + 3, r.y + top, r.width - 6, r.height - top - 3);
  ctx.setLineDash([]);
  const bottom = m.cell.row * pitch + CELL_H - 3;
  ctx.beginPath();
  ctx.moveTo(r.x + 3, bottom - MARKER_CORNER);
  ctx.lineTo(r.x + 3, bottom);
  ctx.lineTo(r.x + 3 + MARKER_CORNER, bottom);
  ctx.closePath();
  ctx.fill();
}

/** The wire drawn on from a coil's own cell to the coil at the right rail. */
function drawCoilRuns(ctx: Ctx, t: CanvasTheme, n: Network, nc: NetworkColumns, paint: NetworkPaint, pitch: number) {
  n.elements.forEach((el, i) => {
    if (el.kind !== 'coil' || nc.alignedAt[el.row] !== el.col) return;
    const power = paint.power ? (paint.power.elements[i] ?? 0) : undefined;
    ctx.save();
    if (paint.drag?.ids.has(el.id)) ctx.globalAlpha = 0.35;
    ctx.lineCap = 'round';
    wire(ctx, t, nc.xs[el.col]!, nc.xs[n.cols - 1]!, el.row * pitch + WIRE_Y, power, 1);
    ctx.restore();
  });
}

export function drawNetworkGrid(ctx: Ctx, t: CanvasTheme, n: Network, paint: NetworkPaint) {
  const nc = networkColumns(n, paint.library);
  const pitch = paint.pitch ?? CELL_H;
  const w = nc.xs[n.cols]!;
  const rows = paint.rows ?? n.rows;
  const h = rows * pitch;
  ctx.fillStyle = t.networkBg;
  ctx.fillRect(0, 0, w, h + GRID_PAD_BOTTOM);
  // Cell corners as small dots: enough to read the grid without clutter.
  ctx.fillStyle = t.grid;
  for (let r = 0; r <= rows; r++)
    for (let c = 1; c < n.cols; c++) ctx.fillRect(nc.xs[c]! - 1, r * pitch - 1, 2, 2);
  if (paint.hover) {
    const r = cellRect(nc, paint.hover, 1, 1, pitch);
    ctx.fillStyle = t.hover;
    ctx.fillRect(r.x, r.y, r.width, r.height);
  }
  // Power rails: the left one is always ON.
  ctx.lineCap = 'butt';
  ctx.strokeStyle = paint.power ? t.energised : t.rail;
  ctx.lineWidth = 4;
  ctx.beginPath();
  ctx.moveTo(0, 4);
  ctx.lineTo(0, h - 4);
  ctx.stroke();
  ctx.strokeStyle = t.rail;
  ctx.beginPath();
  ctx.moveTo(w, 4);
  ctx.lineTo(w, h - 4);
  ctx.stroke();
  n.vlinks.forEach((v, j) => {
    const simulating = paint.power !== undefined;
    const on = Boolean(paint.power?.vlinks[j]);
    const x = nc.xs[v.boundary] ?? w;
    wireStyle(ctx, t, simulating, on);
    ctx.beginPath();
    ctx.moveTo(x, v.row * pitch + WIRE_Y);
    ctx.lineTo(x, (v.row + 1) * pitch + WIRE_Y);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.fillStyle = ctx.strokeStyle;
    ctx.fillRect(x - 2, v.row * pitch + WIRE_Y - 2, 4, 4);
    ctx.fillRect(x - 2, (v.row + 1) * pitch + WIRE_Y - 2, 4, 4);
  });
  drawCoilRuns(ctx, t, n, nc, paint, pitch);
  n.elements.forEach((el, i) => {
    const dragged = paint.drag?.ids.has(el.id);
    const r = elementRect(nc, el, paint.library, pitch);
    ctx.save();
    if (dragged) ctx.globalAlpha = 0.35;
    ctx.translate(r.x, r.y);
    const live = paint.liveValues?.get(el.id);
    const comment = elementCommentText(el, paint.symbols);
    const open = el.kind === 'box' ? openPins(n, el, paint.library) : undefined;
    drawElement(ctx, t, el, {
      width: r.width,
      ...(pitch !== CELL_H ? { pitch } : {}),
      ...(comment ? { comment } : {}),
      ...(paint.symbols && el.kind === 'box' ? { operandComments: paint.symbols } : {}),
      ...(open ? { openPins: open } : {}),
      ...(paint.library ? { library: paint.library } : {}),
      ...(paint.power ? { power: paint.power.elements[i] ?? 0 } : {}),
      ...(live ? { liveValue: live } : {}),
    });
    const pins = el.kind === 'box' ? paint.pinValues?.get(el.id) : undefined;
    if (pins && el.kind === 'box') drawPinValues(ctx, t, el, pins, r.width, paint.library, open, pitch);
    ctx.restore();
  });
  if (paint.forced)
    for (const el of n.elements) if (paint.forced.has(el.id)) drawForcedMark(ctx, t, elementRect(nc, el, paint.library, pitch));
  if (paint.device)
    for (const el of n.elements) {
      const text = paint.device.get(el.id);
      if (text) drawDeviceMark(ctx, t, elementRect(nc, el, paint.library, pitch), text);
    }
  for (const r of selectionRects(n, nc, paint.selected, paint.library, pitch)) {
    ctx.fillStyle = t.selectionFill;
    ctx.strokeStyle = t.selection;
    ctx.lineWidth = SELECTION_LINE;
    ctx.fillRect(r.x, r.y, r.width, r.height);
    ctx.strokeRect(r.x, r.y, r.width, r.height);
  }
  const partners = paint.partners ?? paint.hover;
  if (partners) drawConnectionPartners(ctx, t, n, partners, paint.library, pitch);
  for (const m of paint.markers) {
    const el = elementAt(n, m.cell, paint.library);
    const r = el ? { ...elementRect(nc, el, paint.library, pitch), height: CELL_H, y: m.cell.row * pitch } : { ...cellRect(nc, m.cell, 1, 1, pitch), height: CELL_H };
    drawMarker(ctx, t, m, r, el?.kind === 'box' && el.row === m.cell.row, pitch);
  }
  if (paint.drag) {
    const { dRow, dCol, blocked, ids, ghost } = paint.drag;
    const shown = ghost ?? n.elements.filter((el) => ids.has(el.id));
    const offset = ghost ? { dRow: 0, dCol: 0 } : { dRow, dCol };
    for (const el of shown) {
      const moved = { ...el, row: el.row + offset.dRow, col: el.col + offset.dCol };
      const r = elementRect(nc, moved, paint.library, pitch);
      ctx.save();
      ctx.translate(r.x, r.y);
      ctx.globalAlpha = 0.85;
      drawElement(ctx, t, moved, {
        width: r.width,
        ...(pitch !== CELL_H ? { pitch } : {}),
        ...(paint.library ? { library: paint.library } : {}),
      });
      ctx.strokeStyle = blocked ? t.error : t.selection;
      ctx.setLineDash([4, 3]);
      ctx.lineWidth = 1.5;
      ctx.strokeRect(1, 1, r.width - 2, r.height - 2);
      ctx.setLineDash([]);
      ctx.restore();
    }
  }
  if (paint.cursor) {
    const r = cursorRect(n, nc, paint.cursor, paint.library, pitch);
    ctx.strokeStyle = t.cursor;
    ctx.lineWidth = CURSOR_LINE;
    ctx.strokeRect(r.x, r.y, r.width, r.height);
  }
}

/** Width of the selection's outline; the rectangles below are the outlines' centre lines. */
export const SELECTION_LINE = 2;
/** Width of the keyboard cursor's outline. */
export const CURSOR_LINE = 2.5;

/** The selection marks of a network's selected elements (grid coordinates: outline's centre line, filled inside). */
export function selectionRects(
  n: Network,
  nc: NetworkColumns,
  selected: ReadonlySet<ElementId>,
  library: BlockLibrary | undefined,
  pitch = CELL_H,
): Rect[] {
  const out: Rect[] = [];
  if (selected.size === 0) return out;
  for (const el of n.elements) {
    if (!selected.has(el.id)) continue;
    const r = elementRect(nc, el, library, pitch);
    out.push({ x: r.x + 2, y: r.y + 2, width: r.width - 4, height: r.height - 4 });
  }
  return out;
}

/** The keyboard cursor's outline in a network (grid coordinates, the outline's centre line). */
export function cursorRect(n: Network, nc: NetworkColumns, cursor: Cell, library: BlockLibrary | undefined, pitch = CELL_H): Rect {
  const { row, col } = cursor;
  const k = nc.alignedAt[row] ?? -1;
  // An empty cell past a rail-aligned coil: after the end of the rung, a bar right of the rail.
  if (k >= 0 && col > k && col < n.cols) return { x: nc.xs[n.cols]! + 4, y: row * pitch + 6, width: 5, height: pitch - 12 };
  // On a box (or any element of several cells) the cursor frames the whole element: it stands
  // on the element, never on one of its halves.
  const el = elementAt(n, cursor, library);
  const r = el && el.kind !== 'link' ? elementRect(nc, el, library, pitch) : cellRect(nc, cursor, 1, 1, pitch);
  return { x: r.x + 1, y: r.y + 1, width: r.width - 2, height: r.height - 2 };
}
