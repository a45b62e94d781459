// IEC 61131-3 LD symbols drawn on a 2D canvas context, one element at a time, at the
// element's top-left cell corner. Pure drawing: no state, no React.
import { boxLayout } from '../../model/boxLayout';
import type { BlockLibrary } from '../../model/library';
import type { BoxElement, CoilElement, ContactElement, LdElement } from '../../model/elements';
import type { CanvasTheme } from '../theme/canvasTheme';
import { drawConnection } from './drawConnectors';
import { CELL_H, CELL_W, WIRE_Y } from './geometry';

export const FONT = '12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
export const FONT_BOLD = 'bold 12px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
export const FONT_SMALL = '11px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
const MONO_SMALL = '11px ui-monospace, "SF Mono", Menlo, Consolas, monospace';

/** Power flow byte of an element (NetworkPower): bit 0 input side energised, bit 1 output side. */
export interface ElementPaint {
  /** The project's blocks (user FBs and functions); standard blocks only when absent. */
  readonly library?: BlockLibrary;
  readonly power?: number;
  /** Live value shown under the element during simulation (e.g. "ET=1.2s"). */
  readonly liveValue?: string;
}

type Ctx = CanvasRenderingContext2D;

export function elide(ctx: Ctx, text: string, width: number): string {
  if (ctx.measureText(text).width <= width) return text;
  let lo = 0;
  let hi = text.length;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (ctx.measureText(`${text.slice(0, mid)}…`).width <= width) lo = mid;
    else hi = mid - 1;
  }
  return `${text.slice(0, lo)}…`;
}

function line(ctx: Ctx, x1: number, y1: number, x2: number, y2: number) {
  ctx.beginPath();
  ctx.moveTo(x1, y1);
  ctx.lineTo(x2, y2);
  ctx.stroke();
}

const wireColour = (t: CanvasTheme, on: boolean) => (on ? t.energised : t.wire);

/** Lead wires of a 1-cell symbol: left from 0 to a, right from b to the cell's end. */
function leads(ctx: Ctx, t: CanvasTheme, a: number, b: number, power: number | undefined) {
  ctx.lineWidth = power && power & 1 ? 3 : 1.5;
  ctx.strokeStyle = wireColour(t, Boolean(power && power & 1));
  line(ctx, 0, WIRE_Y, a, WIRE_Y);
  ctx.lineWidth = power && power & 2 ? 3 : 1.5;
  ctx.strokeStyle = wireColour(t, Boolean(power && power & 2));
  line(ctx, b, WIRE_Y, CELL_W, WIRE_Y);
  ctx.lineWidth = 1.5;
  ctx.strokeStyle = t.symbol;
}

function nameAbove(ctx: Ctx, t: CanvasTheme, text: string, missing: string) {
  ctx.font = FONT;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'alphabetic';
  ctx.fillStyle = text ? t.operand : t.muted;
  ctx.fillText(elide(ctx, text || missing, CELL_W - 6), CELL_W / 2, WIRE_Y - 18);
}

function liveBelow(ctx: Ctx, t: CanvasTheme, paint: ElementPaint) {
  if (!paint.liveValue) return;
  ctx.font = FONT_SMALL;
  ctx.textAlign = 'center';
  ctx.fillStyle = t.energised;
  ctx.fillText(elide(ctx, paint.liveValue, CELL_W - 6), CELL_W / 2, WIRE_Y + 20);
}

function drawContact(ctx: Ctx, t: CanvasTheme, el: ContactElement, paint: ElementPaint) {
  const a = CELL_W / 2 - 12;
  const b = CELL_W / 2 + 12;
  leads(ctx, t, a, b, paint.power);
  const h = 12;
  line(ctx, a, WIRE_Y - h, a, WIRE_Y + h);
  line(ctx, b, WIRE_Y - h, b, WIRE_Y + h);
  ctx.fillStyle = t.symbol;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  switch (el.contact) {
    case 'NO':
      break;
    case 'NC':
      line(ctx, a + 4, WIRE_Y + h - 2, b - 4, WIRE_Y - h + 2);
      break;
    case 'P':
    case 'N':
      ctx.font = FONT_BOLD;
      ctx.fillText(el.contact, CELL_W / 2, WIRE_Y + 1);
      break;
    case 'NOT':
      ctx.font = '10px system-ui, sans-serif';
      ctx.fillText('NOT', CELL_W / 2, WIRE_Y + 1);
      break;
  }
  ctx.textBaseline = 'alphabetic';
  if (el.contact !== 'NOT') nameAbove(ctx, t, el.variable, '???');
  liveBelow(ctx, t, paint);
}

const COIL_LETTER: Record<CoilElement['coil'], string> = {
  COIL: '',
  NEG: '/',
  SET: 'S',
  RESET: 'R',
  M: 'M',
  SM: 'SM',
  RM: 'RM',
  P: 'P',
  N: 'N',
};

function drawCoil(ctx: Ctx, t: CanvasTheme, el: CoilElement, paint: ElementPaint) {
  const r = 13;
  const cx = CELL_W / 2;
  leads(ctx, t, cx - r, cx + r, paint.power);
  ctx.beginPath();
  ctx.arc(cx + 4, WIRE_Y, r + 1, Math.PI * 0.72, Math.PI * 1.28);
  ctx.stroke();
  ctx.beginPath();
  ctx.arc(cx - 4, WIRE_Y, r + 1, -Math.PI * 0.28, Math.PI * 0.28);
  ctx.stroke();
  const letter = COIL_LETTER[el.coil];
  if (letter === '/') line(ctx, cx - 5, WIRE_Y + 8, cx + 5, WIRE_Y - 8);
  else if (letter) {
    ctx.fillStyle = t.symbol;
    ctx.font = letter.length > 1 ? '10px system-ui, sans-serif' : FONT_BOLD;
    ctx.textAlign = 'center';
    ctx.textBaseline = 'middle';
    ctx.fillText(letter, cx, WIRE_Y + 1);
    ctx.textBaseline = 'alphabetic';
  }
  nameAbove(ctx, t, el.variable, '???');
  liveBelow(ctx, t, paint);
}

function drawBox(ctx: Ctx, t: CanvasTheme, el: BoxElement, paint: ElementPaint) {
  const layout = boxLayout(el, paint.library);
  const rows = layout?.rows ?? 1;
  const w = CELL_W * 2;
  const left = 18;
  const right = w - 18;
  const top = WIRE_Y - 24;
  const bottom = (rows - 1) * CELL_H + WIRE_Y + 14;
  ctx.fillStyle = t.boxFill;
  ctx.strokeStyle = layout ? t.symbol : t.error;
  ctx.lineWidth = 1.5;
  ctx.fillRect(left, top, right - left, bottom - top);
  ctx.strokeRect(left, top, right - left, bottom - top);
  ctx.textBaseline = 'alphabetic';
  ctx.textAlign = 'center';
  ctx.fillStyle = t.symbol;
  ctx.font = FONT_BOLD;
  ctx.fillText(elide(ctx, el.blockType, right - left - 8), w / 2, top + 13);
  if (layout?.signature.kind === 'fb') {
    ctx.font = FONT;
    ctx.fillStyle = el.instance ? t.operand : t.muted;
    ctx.fillText(elide(ctx, el.instance || '???', w - 8), w / 2, top - 6);
  }
  if (!layout) return;
  const enEno = layout.signature.kind === 'function' || el.executionControl === true;
  const flowIn = enEno ? 'EN' : layout.inputs.find((p) => p.type === 'BOOL')?.name;
  const flowOut = enEno ? 'ENO' : layout.outputs.find((p) => p.type === 'BOOL')?.name;
  ctx.font = FONT_SMALL;
  for (const pin of layout.inputs) {
    const y = pin.rowOffset * CELL_H + WIRE_Y;
    const on = pin.name === flowIn && Boolean(paint.power && paint.power & 1);
    ctx.strokeStyle = wireColour(t, on);
    ctx.lineWidth = on ? 3 : 1.5;
    line(ctx, 0, y, left, y);
    ctx.fillStyle = t.symbol;
    ctx.textAlign = 'left';
    ctx.fillText(pin.name, left + 4, y + 4);
    const operand = el.inputs[pin.name];
    if (operand) {
      ctx.fillStyle = t.operand;
      ctx.textAlign = 'right';
      ctx.fillText(elide(ctx, operand, CELL_W - 8), left - 2, y - 4);
    }
  }
  for (const pin of layout.outputs) {
    const y = pin.rowOffset * CELL_H + WIRE_Y;
    const on = pin.name === flowOut && Boolean(paint.power && paint.power & 2);
    ctx.strokeStyle = wireColour(t, on);
    ctx.lineWidth = on ? 3 : 1.5;
    line(ctx, right, y, w, y);
    ctx.fillStyle = t.symbol;
    ctx.textAlign = 'right';
    ctx.fillText(pin.name, right - 4, y + 4);
    const operand = el.outputs[pin.name];
    if (operand) {
      ctx.fillStyle = t.operand;
      ctx.textAlign = 'left';
      ctx.fillText(elide(ctx, operand, CELL_W - 8), right + 2, y - 4);
    }
  }
  if (paint.liveValue) {
    ctx.font = FONT_SMALL;
    ctx.textAlign = 'center';
    ctx.fillStyle = t.energised;
    ctx.fillText(elide(ctx, paint.liveValue, w - 8), w / 2, bottom + 12);
  }
}

function drawLink(ctx: Ctx, t: CanvasTheme, paint: ElementPaint) {
  const on = Boolean(paint.power && paint.power & 1);
  ctx.strokeStyle = wireColour(t, on);
  ctx.lineWidth = on ? 3 : 1.5;
  line(ctx, 0, WIRE_Y, CELL_W, WIRE_Y);
}

/** Jump and return labels may run into the next cell: they end a rung, nothing sits right of them. */
function drawJumpOrReturn(ctx: Ctx, t: CanvasTheme, text: string, paint: ElementPaint, missing: boolean) {
  const on = Boolean(paint.power && paint.power & 1);
  ctx.strokeStyle = wireColour(t, on);
  ctx.lineWidth = on ? 3 : 1.5;
  line(ctx, 0, WIRE_Y, 8, WIRE_Y);
  ctx.font = `bold ${MONO_SMALL}`;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  ctx.fillStyle = missing ? t.muted : t.symbol;
  ctx.fillText(elide(ctx, text, CELL_W * 2 - 14), 10, WIRE_Y + 1);
  ctx.textBaseline = 'alphabetic';
}

/** Draws `el` with its top-left cell corner at the context's origin. */
export function drawElement(ctx: Ctx, t: CanvasTheme, el: LdElement, paint: ElementPaint = {}) {
  ctx.lineCap = 'round';
  ctx.strokeStyle = t.symbol;
  ctx.lineWidth = 1.5;
  switch (el.kind) {
    case 'link':
      return drawLink(ctx, t, paint);
    case 'contact':
      return drawContact(ctx, t, el, paint);
    case 'coil':
      return drawCoil(ctx, t, el, paint);
    case 'box':
      return drawBox(ctx, t, el, paint);
    case 'jump':
      return drawJumpOrReturn(ctx, t, `>>${el.target || '???'}`, paint, !el.target);
    case 'return':
      return drawJumpOrReturn(ctx, t, '<RETURN>', paint, false);
    case 'connector':
    case 'continuation':
      return drawConnection(ctx, t, el, paint);
  }
}
