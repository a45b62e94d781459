// Live values beside a box's pins (issue 24, monitoring): under the pin's wire, in the margin where
// its operand name stands above the wire (so a value never covers a name), right-aligned against
// the box for an input, left-aligned for an output. TRUE and FALSE as the tags contacts and coils
// show under them; any other value in a small framed tag. Drawn at the box's top-left corner.
import { boxLayout } from '../../model/boxLayout';
import type { BoxElement } from '../../model/elements';
import type { BlockLibrary } from '../../model/library';
import type { CanvasTheme } from '../theme/canvasTheme';
import { boolState } from '../theme/monitorStyle';
import { BOX_MARGIN, boxMetrics } from './columns';
import { elide } from './elementPaint';
import { CELL_H, COMMENT_BAND, WIRE_Y } from './geometry';
import type { OpenPins } from './pinOperands';
import { FONT_SMALL, FONT_SMALL_BOLD } from './textWidth';

type Ctx = CanvasRenderingContext2D;

/** Text beside each pin of one box, by pin name (pinLiveValues.ts BoxPinTexts). */
export interface PinTexts {
  readonly inputs: Readonly<Record<string, string>>;
  readonly outputs: Readonly<Record<string, string>>;
}

/** Widest a pin value is drawn (longer ones end in …; the watch list shows them whole). */
export const PIN_VALUE_MAX_W = 120;
/** Centre of a value's tag below its pin's wire. */
export const PIN_VALUE_DY = 12;
const TAG_H = 13;

/** One value tag: its right edge at `x` (`align` right) or its left edge (`align` left). */
function tag(ctx: Ctx, t: CanvasTheme, text: string, x: number, y: number, align: 'left' | 'right') {
  const state = boolState(text);
  ctx.font = state === 'TRUE' ? FONT_SMALL_BOLD : FONT_SMALL;
  const shown = elide(ctx, state ?? text, PIN_VALUE_MAX_W - 8);
  const w = ctx.measureText(shown).width + 8;
  const left = align === 'right' ? x - w : x;
  ctx.textAlign = 'center';
  ctx.textBaseline = 'middle';
  if (state === 'TRUE') {
    ctx.fillStyle = t.energised;
    ctx.fillRect(left, y - TAG_H / 2, w, TAG_H);
    ctx.fillStyle = t.networkBg;
  } else {
    ctx.fillStyle = t.networkBg;
    ctx.fillRect(left, y - TAG_H / 2, w, TAG_H);
    ctx.strokeStyle = state === 'FALSE' ? t.falseState : t.muted;
    ctx.lineWidth = 1;
    ctx.strokeRect(left + 0.5, y - TAG_H / 2 + 0.5, w - 1, TAG_H - 1);
    ctx.fillStyle = state === 'FALSE' ? t.falseState : t.text;
  }
  ctx.fillText(shown, left + w / 2, y + 0.5);
  ctx.textBaseline = 'alphabetic';
}

/** Draws `texts` beside the pins of `el` (`width`: the box's drawn width). */
export function drawPinValues(
  ctx: Ctx,
  t: CanvasTheme,
  el: BoxElement,
  texts: PinTexts,
  width: number,
  library?: BlockLibrary,
  openPins?: OpenPins,
  pitch: number = CELL_H,
) {
  const layout = boxLayout(el, library);
  if (!layout) return;
  const m = boxMetrics(el, layout, openPins);
  const left = m.left ?? BOX_MARGIN;
  const right = width - (m.rightMargin ?? BOX_MARGIN);
  // With symbol comments shown (taller rows), the operand's comment stands under the wire: the value goes below it.
  const dy = pitch > CELL_H ? PIN_VALUE_DY + COMMENT_BAND : PIN_VALUE_DY;
  for (const pin of layout.inputs) {
    const text = texts.inputs[pin.name];
    if (text !== undefined) tag(ctx, t, text, left - 3, pin.rowOffset * pitch + WIRE_Y + dy, 'right');
  }
  for (const pin of layout.outputs) {
    const text = texts.outputs[pin.name];
    if (text !== undefined) tag(ctx, t, text, right + 3, pin.rowOffset * pitch + WIRE_Y + dy, 'left');
  }
}
