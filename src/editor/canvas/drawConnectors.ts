// Connectors and continuations `>NAME>` drawn as the IEC/CODESYS arrow-shaped tag with the name
// inside: a connector ends the line on its left (wire, then the tag), a continuation starts one on
// its right (the tag, then wire). While the pointer rests on one, it and its partners are outlined.
import type { LdElement } from '../../model/elements';
import type { Cell } from '../../model/grid';
import type { BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { isConnection, partnersOf, type ConnectionElement } from '../../store/connectors';
import { elementAt } from '../../store/networkEdits';
import type { CanvasTheme } from '../theme/canvasTheme';
import { elide, type ElementPaint } from './elementPaint';
import { networkColumns } from './columns';
import { CELL_H, CELL_W, cellRect, WIRE_Y } from './geometry';

type Ctx = CanvasRenderingContext2D;

const TAG_H = 22;
/** Depth of the notch on the tag's left and of its point on the right. */
const ARROW = 7;
/** Length of the wire between the cell edge and the tag. */
const LEAD = 10;
const TAG_FONT = 'bold 11px ui-monospace, "SF Mono", Menlo, Consolas, monospace';

/** The tag between x = a and x = b: a notch on its left, a point on its right (`>NAME>`). */
function tagPath(ctx: Ctx, a: number, b: number) {
  const top = WIRE_Y - TAG_H / 2;
  const bottom = WIRE_Y + TAG_H / 2;
  ctx.beginPath();
  ctx.moveTo(a, top);
  ctx.lineTo(b - ARROW, top);
  ctx.lineTo(b, WIRE_Y);
  ctx.lineTo(b - ARROW, bottom);
  ctx.lineTo(a, bottom);
  ctx.lineTo(a + ARROW, WIRE_Y);
  ctx.closePath();
}

/** Draws a connector or continuation with its top-left cell corner at the context's origin. */
export function drawConnection(ctx: Ctx, t: CanvasTheme, el: ConnectionElement, paint: ElementPaint) {
  const on = Boolean(paint.power && paint.power & 1);
  const connector = el.kind === 'connector';
  // The column may be wider than CELL_W (columns grow to their longest name: columns.ts).
  const w = paint.width ?? CELL_W;
  const a = connector ? LEAD : 2;
  const b = connector ? w - 2 : w - LEAD;
  ctx.lineCap = 'butt';
  ctx.strokeStyle = on ? t.energised : t.wire;
  ctx.lineWidth = on ? 3 : 1.5;
  ctx.beginPath();
  if (connector) {
    ctx.moveTo(0, WIRE_Y);
    ctx.lineTo(a + ARROW, WIRE_Y);
  } else {
    ctx.moveTo(b, WIRE_Y);
    ctx.lineTo(w, WIRE_Y);
  }
  ctx.stroke();
  tagPath(ctx, a, b);
  ctx.fillStyle = t.boxFill;
  ctx.fill();
  ctx.strokeStyle = on ? t.energised : t.symbol;
  ctx.lineWidth = on ? 2.5 : 1.5;
  ctx.stroke();
  const name = el.name.trim();
  ctx.font = TAG_FONT;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  ctx.fillStyle = name ? t.symbol : t.muted;
  const mid = (a + ARROW + b - ARROW) / 2;
  ctx.fillText(elide(ctx, name || '???', b - a - 2 * ARROW - 2), mid, WIRE_Y + 1);
  ctx.textBaseline = 'alphabetic';
  ctx.lineCap = 'round';
}

/** While the pointer rests on a connector or continuation: it and its partners outlined. */
export function drawConnectionPartners(ctx: Ctx, t: CanvasTheme, n: Network, hover: Cell, lib?: BlockLibrary, pitch = CELL_H) {
  const el: LdElement | undefined = elementAt(n, hover, lib);
  if (!el || !isConnection(el)) return;
  const partners = partnersOf(n, el);
  if (partners.length === 0) return;
  ctx.strokeStyle = t.selection;
  ctx.lineWidth = 2;
  ctx.setLineDash([3, 3]);
  const nc = networkColumns(n, lib);
  for (const p of [el, ...partners]) {
    const r = cellRect(nc, p, 1, 1, pitch);
    ctx.strokeRect(r.x + 4, r.y + 6, r.width - 8, CELL_H - 12);
  }
  ctx.setLineDash([]);
}
