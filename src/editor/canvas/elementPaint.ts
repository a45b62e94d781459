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
