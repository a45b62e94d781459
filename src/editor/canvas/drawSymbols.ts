// IEC 61131-3 LD symbols drawn on a 2D canvas context, one element at a time, at the
// element's top-left cell corner, `width` wide (its columns are as wide as its names: columns.ts).
// Pure drawing: no state, no React. Names are never cut: when a font draws wider than its
// estimate the text is drawn narrower rather than shortened.
import { boxLayout } from '../../model/boxLayout';
import type { BoxElement, CoilElement, ContactElement, LdElement } from '../../model/elements';
import { powerFlowInput, powerFlowOutput } from '../../store/networkEdits';
import type { CanvasTheme } from '../theme/canvasTheme';
import {
  boolState,
  SYMBOL_TRUE_FILL_ALPHA,
  WIRE_EDIT,
  WIRE_FALSE,
  WIRE_FALSE_DASH,
  WIRE_TRUE,
} from '../theme/monitorStyle';
import { BOX_MARGIN, boxMetrics, CELL_W, JUMP_RAIL_GAP, JUMP_TEXT_X, jumpText } from './columns';
import { drawConnection } from './drawConnectors';
import { elide, wrapLines, type ElementPaint } from './elementPaint';
import { CELL_H, WIRE_Y } from './geometry';
import { FONT, FONT_BOLD, FONT_SMALL, FONT_SMALL_BOLD, MONO_SMALL_BOLD } from './textWidth';

export { FONT, FONT_BOLD, FONT_SMALL } from './textWidth';

type Ctx = CanvasRenderingContext2D;

/** Draws a name whole: narrower than its font when it would not fit `width` (never shortened). */
export function fillName(ctx: Ctx, text: string, x: number, y: number, width: number) {
  if (ctx.measureText(text).width <= width) ctx.fillText(text, x, y);
  else ctx.fillText(text, x, y, Math.max(1, width));
}

function line(ctx: Ctx, x1: number, y1: number, x2: number, y2: number) {
  ctx.beginPath();
  ctx.moveTo(x1, y1);
  ctx.lineTo(x2, y2);
  ctx.stroke();
}

/**
 * Sets the stroke for a wire: while simulating TRUE is thick and in the energised colour, FALSE
 * thin, dashed and blue-grey; when editing, the plain wire.
 */
export function wireStyle(ctx: Ctx, t: CanvasTheme, simulating: boolean, on: boolean) {
  ctx.setLineDash(simulating && !on ? WIRE_FALSE_DASH : []);
  ctx.strokeStyle = !simulating ? t.wire : on ? t.energised : t.falseState;
  ctx.lineWidth = !simulating ? WIRE_EDIT : on ? WIRE_TRUE : WIRE_FALSE;
}

/** A horizontal wire in the element's power state (bit `bit` of its power byte). */
export function wire(ctx: Ctx, t: CanvasTheme, x1: number, x2: number, y: number, power: number | undefined, bit: number) {
  wireStyle(ctx, t, power !== undefined, Boolean(power && power & bit));
  line(ctx, x1, y, x2, y);
  ctx.setLineDash([]);
}

/** Lead wires of a 1-cell symbol: left from 0 to a, right from b to the cell's end. */
function leads(ctx: Ctx, t: CanvasTheme, a: number, b: number, w: number, power: number | undefined) {
  wire(ctx, t, 0, a, WIRE_Y, power, 1);
  wire(ctx, t, b, w, WIRE_Y, power, 2);
  ctx.lineWidth = 1.5;
  ctx.strokeStyle = t.symbol;
}

/** Comments under operands: small italic text, two lines at most, each LINE_COMMENT high. */
export const FONT_COMMENT = 'italic 10px system-ui, -apple-system, "Segoe UI", Roboto, sans-serif';
const COMMENT_LINE = 11;
const COMMENT_LINES = 2;
/** Top of a contact's or coil's comment: the cell's own height (the comment band lies below it). */
const COMMENT_TOP = CELL_H - 1;

/**
 * A comment under an operand, wrapped into at most two lines of `width` and cut with an ellipsis
 * after that (never into a neighbour's cell). `align` as canvas textAlign at `x`.
 */
function commentAt(ctx: Ctx, t: CanvasTheme, text: string, x: number, top: number, width: number, align: CanvasTextAlign) {
  if (width < 8) return;
  ctx.font = FONT_COMMENT;
  ctx.fillStyle = t.muted;
  ctx.textAlign = align;
  ctx.textBaseline = 'top';
  wrapLines(ctx, text, width, COMMENT_LINES).forEach((l, k) => ctx.fillText(l, x, top + k * COMMENT_LINE));
  ctx.textBaseline = 'alphabetic';
}

/** The element's comment under a contact or coil (drawn only when its rows have the comment band). */
function commentBelow(ctx: Ctx, t: CanvasTheme, paint: ElementPaint, w: number) {
  if (!paint.comment || (paint.pitch ?? CELL_H) <= CELL_H) return;
  commentAt(ctx, t, paint.comment, w / 2, COMMENT_TOP, w - 6, 'center');
}

function nameAbove(ctx: Ctx, t: CanvasTheme, text: string, missing: string, w: number) {
  ctx.font = FONT;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'alphabetic';
  ctx.fillStyle = text ? t.operand : t.muted;
  fillName(ctx, text || missing, w / 2, WIRE_Y - 18, w - 6);
}

/**
 * The value under an element while simulating: TRUE as a filled tag in the energised colour,
 * FALSE as an outlined blue-grey tag, anything else (numbers, times, FB outputs) in neutral text.
 */
function liveBelow(ctx: Ctx, t: CanvasTheme, text: string | undefined, cx: number, y: number, w: number) {
  if (!text) return;
  const state = boolState(text);
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  if (!state) {
    ctx.font = FONT_SMALL;
    ctx.fillStyle = t.text;
    ctx.fillText(elide(ctx, text, w - 6), cx, y);
    ctx.textBaseline = 'alphabetic';
    return;
  }
  ctx.font = state === 'TRUE' ? FONT_SMALL_BOLD : FONT_SMALL;
  // A forced value's "[F]" is the forced badge's job on the canvas (drawNetwork's drawForcedMark).
  const shown = elide(ctx, state, w - 12);
  const tw = ctx.measureText(shown).width + 8;
  const left = cx - tw / 2;
  if (state === 'TRUE') {
    ctx.fillStyle = t.energised;
    ctx.fillRect(left, y - 7, tw, 14);
    ctx.fillStyle = t.networkBg;
  } else {
    ctx.strokeStyle = t.falseState;
    ctx.lineWidth = 1;
    ctx.strokeRect(left + 0.5, y - 6.5, tw - 1, 13);
    ctx.fillStyle = t.falseState;
  }
  ctx.fillText(shown, cx, y + 0.5);
  ctx.textBaseline = 'alphabetic';
}

/** Fill inside a contact or coil whose variable is TRUE while simulating. */
function symbolFill(ctx: Ctx, t: CanvasTheme, paint: ElementPaint, draw: () => void) {
  if (boolState(paint.liveValue) !== 'TRUE') return;
  ctx.save();
  ctx.globalAlpha = SYMBOL_TRUE_FILL_ALPHA;
  ctx.fillStyle = t.energised;
  draw();
  ctx.restore();
}

/** The symbol's stroke: thick in the energised colour for TRUE while simulating, blue-grey for FALSE. */
function symbolStroke(ctx: Ctx, t: CanvasTheme, paint: ElementPaint) {
  const state = boolState(paint.liveValue);
  ctx.strokeStyle = state === 'TRUE' ? t.energised : state === 'FALSE' ? t.falseState : t.symbol;
  ctx.lineWidth = state === 'TRUE' ? 2.5 : 1.5;
}

function drawContact(ctx: Ctx, t: CanvasTheme, el: ContactElement, paint: ElementPaint, w: number) {
  const cx = w / 2;
  const a = cx - 12;
  const b = cx + 12;
  leads(ctx, t, a, b, w, paint.power);
  const h = 12;
  symbolFill(ctx, t, paint, () => ctx.fillRect(a, WIRE_Y - h, b - a, 2 * h));
  symbolStroke(ctx, t, paint);
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
      ctx.fillText(el.contact, cx, WIRE_Y + 1);
      break;
    case 'NOT':
      ctx.font = '10px system-ui, sans-serif';
      ctx.fillText('NOT', cx, WIRE_Y + 1);
      break;
  }
  ctx.textBaseline = 'alphabetic';
  if (el.contact !== 'NOT') nameAbove(ctx, t, el.variable, '???', w);
  liveBelow(ctx, t, paint.liveValue, cx, WIRE_Y + 16, w);
  commentBelow(ctx, t, paint, w);
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

function drawCoil(ctx: Ctx, t: CanvasTheme, el: CoilElement, paint: ElementPaint, w: number) {
  const r = 13;
  const cx = w / 2;
  leads(ctx, t, cx - r, cx + r, w, paint.power);
  symbolFill(ctx, t, paint, () => {
    ctx.beginPath();
    ctx.arc(cx, WIRE_Y, r - 1, 0, Math.PI * 2);
    ctx.fill();
  });
  symbolStroke(ctx, t, paint);
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
  nameAbove(ctx, t, el.variable, '???', w);
  liveBelow(ctx, t, paint.liveValue, cx, WIRE_Y + 16, w);
  commentBelow(ctx, t, paint, w);
}

/** Where the instance name of a box is drawn (relative to the box's top-left cell corner). */
export const INSTANCE_BASELINE = WIRE_Y - 31;
/** Top of a box's body; the instance name ends above it, a diagnostic outline runs between. */
export const BOX_TOP = WIRE_Y - 24;

function drawBox(ctx: Ctx, t: CanvasTheme, el: BoxElement, paint: ElementPaint, w: number) {
  const layout = boxLayout(el, paint.library);
  const rows = layout?.rows ?? 1;
  const pitch = paint.pitch ?? CELL_H;
  const banded = pitch > CELL_H;
  const m = layout ? boxMetrics(el, layout, paint.openPins) : undefined;
  const left = m?.left ?? BOX_MARGIN;
  const right = w - (m?.rightMargin ?? BOX_MARGIN);
  const top = BOX_TOP;
  const bottom = (rows - 1) * pitch + WIRE_Y + 14;
  ctx.fillStyle = t.boxFill;
  ctx.strokeStyle = layout ? t.symbol : t.error;
  ctx.lineWidth = 1.5;
  ctx.fillRect(left, top, right - left, bottom - top);
  ctx.strokeRect(left, top, right - left, bottom - top);
  ctx.textBaseline = 'alphabetic';
  ctx.textAlign = 'center';
  ctx.fillStyle = t.symbol;
  ctx.font = FONT_BOLD;
  const mid = (left + right) / 2;
  fillName(ctx, el.blockType, mid, top + 13, right - left - 8);
  if (layout?.signature.kind === 'fb') {
    ctx.font = FONT;
    ctx.fillStyle = el.instance ? t.operand : t.muted;
    const name = el.instance || '???';
    const half = Math.min(w, ctx.measureText(name).width + 8) / 2;
    fillName(ctx, name, Math.max(half, Math.min(w - half, mid)), INSTANCE_BASELINE, w - 4);
  }
  if (!layout) return;
  const flowIn = powerFlowInput(layout)?.name;
  const flowOut = powerFlowOutput(layout)?.name;
  for (const pin of layout.inputs) {
    const y = pin.rowOffset * pitch + WIRE_Y;
    wire(ctx, t, 0, left, y, pin.name === flowIn ? paint.power : undefined, 1);
    ctx.font = FONT_SMALL;
    ctx.fillStyle = t.symbol;
    ctx.textAlign = 'left';
    ctx.fillText(pin.name, left + 4, y + 4);
    const operand = el.inputs[pin.name] || (paint.openPins?.inputs.has(pin.name) ? '???' : '');
    if (operand) {
      ctx.fillStyle = el.inputs[pin.name] ? t.operand : t.muted;
      ctx.textAlign = 'right';
      fillName(ctx, operand, left - 3, y - 4, left - 6);
      const note = banded && el.inputs[pin.name] ? paint.operandComments?.(el.inputs[pin.name]!) : undefined;
      if (note) commentAt(ctx, t, note, left - 3, y + 4, left - 6, 'right');
    }
  }
  for (const pin of layout.outputs) {
    const y = pin.rowOffset * pitch + WIRE_Y;
    wire(ctx, t, right, w, y, pin.name === flowOut ? paint.power : undefined, 2);
    ctx.font = FONT_SMALL;
    ctx.fillStyle = t.symbol;
    ctx.textAlign = 'right';
    ctx.fillText(pin.name, right - 4, y + 4);
    // While simulating, an output nothing reads is not a missing operand: no `???` beside it (TON's ET).
    const operand = el.outputs[pin.name] || (paint.power === undefined && paint.openPins?.outputs.has(pin.name) ? '???' : '');
    if (operand) {
      ctx.fillStyle = el.outputs[pin.name] ? t.operand : t.muted;
      ctx.textAlign = 'left';
      fillName(ctx, operand, right + 3, y - 4, w - right - 6);
      const note = banded && el.outputs[pin.name] ? paint.operandComments?.(el.outputs[pin.name]!) : undefined;
      if (note) commentAt(ctx, t, note, right + 3, y + 4, w - right - 6, 'left');
    }
  }
  liveBelow(ctx, t, paint.liveValue, mid, bottom + 9, Math.max(right - left, w - 8));
  if (banded && paint.comment) commentAt(ctx, t, paint.comment, mid, (rows - 1) * pitch + COMMENT_TOP, right - left - 4, 'center');
}

function drawLink(ctx: Ctx, t: CanvasTheme, paint: ElementPaint, w: number) {
  wire(ctx, t, 0, w, WIRE_Y, paint.power, 1);
}

/**
 * Jump and return labels end a rung; their column is as wide as the label, and the label keeps
 * clear of the right rail (a jump is not connected to it).
 */
function drawJumpOrReturn(ctx: Ctx, t: CanvasTheme, text: string, paint: ElementPaint, missing: boolean, w: number) {
  wire(ctx, t, 0, JUMP_TEXT_X - 2, WIRE_Y, paint.power, 1);
  ctx.font = MONO_SMALL_BOLD;
  ctx.textAlign = 'left';
  ctx.textBaseline = 'middle';
  ctx.fillStyle = missing ? t.muted : t.symbol;
  fillName(ctx, text, JUMP_TEXT_X, WIRE_Y + 1, w - JUMP_TEXT_X - JUMP_RAIL_GAP);
  ctx.textBaseline = 'alphabetic';
}

/** Draws `el` with its top-left cell corner at the context's origin. */
export function drawElement(ctx: Ctx, t: CanvasTheme, el: LdElement, paint: ElementPaint = {}) {
  ctx.lineCap = 'round';
  ctx.strokeStyle = t.symbol;
  ctx.lineWidth = 1.5;
  const w = paint.width ?? CELL_W * (el.kind === 'box' ? 2 : 1);
  switch (el.kind) {
    case 'link':
      return drawLink(ctx, t, paint, w);
    case 'contact':
      return drawContact(ctx, t, el, paint, w);
    case 'coil':
      return drawCoil(ctx, t, el, paint, w);
    case 'box':
      return drawBox(ctx, t, el, paint, w);
    case 'jump':
    case 'return':
      return drawJumpOrReturn(ctx, t, jumpText(el), paint, el.kind === 'jump' && !el.target, w);
    case 'connector':
    case 'continuation':
      return drawConnection(ctx, t, el, { ...paint, width: w });
  }
}
