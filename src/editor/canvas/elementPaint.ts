// What drawing one element takes (its power flow, live value, width, open pins) and how a text is
// shortened to fit the canvas; shared by drawSymbols.ts and drawConnectors.ts.
import type { BlockLibrary } from '../../model/library';
import type { OpenPins } from './pinOperands';

/** Power flow byte of an element (NetworkPower): bit 0 input side energised, bit 1 output side. */
export interface ElementPaint {
  /** The project's blocks (user FBs and functions); standard blocks only when absent. */
  readonly library?: BlockLibrary;
  /** Present while simulating (0 when nothing is energised). */
  readonly power?: number;
  /** Live value shown under the element during simulation (e.g. "ET=1.2s"). */
  readonly liveValue?: string;
  /** Drawn width of the element's columns (CELL_W per column when absent). */
  readonly width?: number;
  /** Box pins that are unwired and have no operand: drawn with a `???` operand (pinOperands.ts). */
  readonly openPins?: OpenPins;
  /** Height of the network's rows (CELL_H when absent): a box's pins are this far apart. */
  readonly pitch?: number;
  /** The comment drawn under the element (its own, else its variable's with the view option). */
  readonly comment?: string;
  /** Variables' comments for a box's operands (the symbol-comment view option). */
  readonly operandComments?: (name: string) => string | undefined;
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

/**
 * Splits `text` into at most `maxLines` lines of `width` (words wrapped; a word wider than a line
 * broken), the last line ended with an ellipsis when the text goes on: a comment stays in its cell.
 */
export function wrapLines(ctx: Ctx, text: string, width: number, maxLines: number): string[] {
  const words = text.replace(/\s+/g, ' ').trim().split(' ').filter(Boolean);
  const lines: string[] = [];
  let current = '';
  let i = 0;
  while (i < words.length) {
    const word = words[i]!;
    const next = current ? `${current} ${word}` : word;
    if (ctx.measureText(next).width <= width) {
      current = next;
      i++;
      continue;
    }
    let glue = ' ';
    if (!current) {
      // One word wider than the line: as much of it as fits here, the rest goes on.
      let cut = 1;
      while (cut < word.length && ctx.measureText(word.slice(0, cut + 1)).width <= width) cut++;
      current = word.slice(0, cut);
      words[i] = word.slice(cut);
      glue = '';
    }
    if (lines.length === maxLines - 1) {
      lines.push(elide(ctx, `${current}${glue}${words.slice(i).join(' ')}`, width));
      return lines;
    }
    lines.push(current);
    current = '';
  }
  if (current) lines.push(current);
  return lines;
}
