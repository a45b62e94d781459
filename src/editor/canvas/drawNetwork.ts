// Draws one network's grid (rails, vertical links, elements and the overlays: selection,
// cursor, diagnostic markers, drag ghost) with the grid's top-left at the context origin.
import type { NetworkPower } from '../../engine/api';
import { elementSize } from '../../model/factory';
import type { BlockLibrary } from '../../model/library';
import type { Cell } from '../../model/grid';
import type { LdElement } from '../../model/elements';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import type { CanvasTheme } from '../theme/canvasTheme';
import { drawConnectionPartners } from './drawConnectors';
import { drawElement } from './drawSymbols';
import { CELL_H, CELL_W, GRID_PAD_BOTTOM, WIRE_Y } from './geometry';

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
  readonly markers: readonly CellMarker[];
  /** Simulation power flow, aligned with network.elements / network.vlinks. */
  readonly power?: NetworkPower;
  readonly liveValues?: ReadonlyMap<ElementId, string>;
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

/** The device holds another value than the program: a boxed "device: FALSE" tag over the element's top edge. */
function drawDeviceMark(ctx: Ctx, t: CanvasTheme, el: LdElement, text: string, lib?: BlockLibrary) {
  const s = elementSize(el, lib);
  const x = el.col * CELL_W;
  const y = el.row * CELL_H;
  ctx.font = 'bold 10px system-ui, sans-serif';
  const w = Math.min(ctx.measureText(text).width + 8, s.cols * CELL_W - 4);
  const left = x + s.cols * CELL_W - 2 - w;
  ctx.fillStyle = t.networkBg;
  ctx.fillRect(left, y + 1, w, 13);
  ctx.strokeStyle = t.warning;
  ctx.lineWidth = 1.5;
  ctx.strokeRect(left, y + 1, w, 13);
  ctx.fillStyle = t.text;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText(text, left + w / 2, y + 8, w - 4);
  ctx.textBaseline = 'alphabetic';
}

/** A forced element: an outline and an "F" tag at its top-left corner, in the theme's forced colour. */
function drawForcedMark(ctx: Ctx, t: CanvasTheme, el: LdElement, lib?: BlockLibrary) {
  const s = elementSize(el, lib);
  const x = el.col * CELL_W;
  const y = el.row * CELL_H;
  ctx.strokeStyle = t.forced;
  ctx.fillStyle = t.forced;
  ctx.lineWidth = 2;
  ctx.strokeRect(x + 2, y + 2, s.cols * CELL_W - 4, s.rows * CELL_H - 4);
  ctx.fillRect(x + 2, y + 2, 14, 14);
  ctx.fillStyle = t.networkBg;
  ctx.font = 'bold 11px system-ui, sans-serif';
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillText('F', x + 9, y + 9.5);
  ctx.textBaseline = 'alphabetic';
}

export function drawNetworkGrid(ctx: Ctx, t: CanvasTheme, n: Network, paint: NetworkPaint) {
  const w = n.cols * CELL_W;
  const h = n.rows * CELL_H;
  ctx.fillStyle = t.networkBg;
  ctx.fillRect(0, 0, w, h + GRID_PAD_BOTTOM);
  // Cell corners as small dots: enough to read the grid without clutter.
  ctx.fillStyle = t.grid;
  for (let r = 0; r <= n.rows; r++)
    for (let c = 1; c < n.cols; c++) ctx.fillRect(c * CELL_W - 1, r * CELL_H - 1, 2, 2);
  if (paint.hover) {
    ctx.fillStyle = t.hover;
    ctx.fillRect(paint.hover.col * CELL_W, paint.hover.row * CELL_H, CELL_W, CELL_H);
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
    const on = Boolean(paint.power?.vlinks[j]);
    ctx.strokeStyle = on ? t.energised : t.wire;
    ctx.lineWidth = on ? 3 : 1.5;
    ctx.beginPath();
    ctx.moveTo(v.boundary * CELL_W, v.row * CELL_H + WIRE_Y);
    ctx.lineTo(v.boundary * CELL_W, (v.row + 1) * CELL_H + WIRE_Y);
    ctx.stroke();
    ctx.fillStyle = on ? t.energised : t.wire;
    ctx.fillRect(v.boundary * CELL_W - 2, v.row * CELL_H + WIRE_Y - 2, 4, 4);
    ctx.fillRect(v.boundary * CELL_W - 2, (v.row + 1) * CELL_H + WIRE_Y - 2, 4, 4);
  });
  n.elements.forEach((el, i) => {
    const dragged = paint.drag?.ids.has(el.id);
    ctx.save();
    if (dragged) ctx.globalAlpha = 0.35;
    ctx.translate(el.col * CELL_W, el.row * CELL_H);
    const live = paint.liveValues?.get(el.id);
    drawElement(ctx, t, el, {
      ...(paint.library ? { library: paint.library } : {}),
      ...(paint.power ? { power: paint.power.elements[i] ?? 0 } : {}),
      ...(live ? { liveValue: live } : {}),
    });
    ctx.restore();
  });
  if (paint.forced) for (const el of n.elements) if (paint.forced.has(el.id)) drawForcedMark(ctx, t, el, paint.library);
  if (paint.device) for (const el of n.elements) {
    const text = paint.device.get(el.id);
    if (text) drawDeviceMark(ctx, t, el, text, paint.library);
  }
  for (const el of n.elements) {
    if (!paint.selected.has(el.id)) continue;
    const s = elementSize(el, paint.library);
    ctx.fillStyle = t.selectionFill;
    ctx.strokeStyle = t.selection;
    ctx.lineWidth = 2;
    ctx.fillRect(el.col * CELL_W + 2, el.row * CELL_H + 2, s.cols * CELL_W - 4, s.rows * CELL_H - 4);
    ctx.strokeRect(el.col * CELL_W + 2, el.row * CELL_H + 2, s.cols * CELL_W - 4, s.rows * CELL_H - 4);
  }
  if (paint.hover) drawConnectionPartners(ctx, t, n, paint.hover, paint.library);
  for (const m of paint.markers) {
    const x = m.cell.col * CELL_W;
    const y = m.cell.row * CELL_H;
    ctx.strokeStyle = m.severity === 'error' ? t.error : t.warning;
    ctx.fillStyle = ctx.strokeStyle;
    ctx.lineWidth = 2;
    ctx.setLineDash([5, 3]);
    ctx.strokeRect(x + 3, y + 3, CELL_W - 6, CELL_H - 6);
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(x + CELL_W - 16, y + 3);
    ctx.lineTo(x + CELL_W - 3, y + 3);
    ctx.lineTo(x + CELL_W - 3, y + 16);
    ctx.closePath();
    ctx.fill();
  }
  if (paint.drag) {
    const { dRow, dCol, blocked, ids, ghost } = paint.drag;
    const shown = ghost ?? n.elements.filter((el) => ids.has(el.id));
    const offset = ghost ? { dRow: 0, dCol: 0 } : { dRow, dCol };
    for (const el of shown) {
      ctx.save();
      ctx.translate((el.col + offset.dCol) * CELL_W, (el.row + offset.dRow) * CELL_H);
      ctx.globalAlpha = 0.85;
      drawElement(ctx, t, el, paint.library ? { library: paint.library } : {});
      const s = elementSize(el, paint.library);
      ctx.strokeStyle = blocked ? t.error : t.selection;
      ctx.setLineDash([4, 3]);
      ctx.lineWidth = 1.5;
      ctx.strokeRect(1, 1, s.cols * CELL_W - 2, s.rows * CELL_H - 2);
      ctx.setLineDash([]);
      ctx.restore();
    }
  }
  if (paint.cursor) {
    ctx.strokeStyle = t.cursor;
    ctx.lineWidth = 2.5;
    ctx.strokeRect(paint.cursor.col * CELL_W + 1, paint.cursor.row * CELL_H + 1, CELL_W - 2, CELL_H - 2);
  }
}
