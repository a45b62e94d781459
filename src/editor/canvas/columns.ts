// A network's columns on screen: each column is as wide as the longest name drawn in it (names are
// never cut), and a coil that ends its rung is drawn at the right rail (CODESYS/TIA habit), its
// wire drawn on from its own cell. Model positions stay cells; this is only the view: everything
// that maps cells to pixels or back (drawing, hit tests, the inline editor, scrolling) goes
// through these functions, so the compiled meaning and the exported file never change.
import type { BoxLayout } from '../../model/boxLayout';
import { boxLayout } from '../../model/boxLayout';
import type { BoxElement, LdElement } from '../../model/elements';
import { elementSize } from '../../model/factory';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { openPins, type OpenPins } from './pinOperands';
import { SPEC_BOLD, SPEC_FONT, SPEC_MONO_SMALL, SPEC_SMALL, textWidth } from './textWidth';

/**
 * Narrowest column (content pixels): a contact or coil symbol with its leads. Ten of them (a new
 * network) fit the canvas beside the side panels at 1280×720; longer names widen their column.
 */
export const CELL_W = 60;
/** Room left and right of a name drawn over a contact or coil. */
export const LABEL_PAD = 10;
/** A box's margin between its cell edge and its body when no operand is written there. */
export const BOX_MARGIN = 18;

export interface NetworkColumns {
  readonly cols: number;
  /** x of each column boundary from the grid's left edge: xs[0] = 0, xs[cols] = the right rail. */
  readonly xs: Float64Array;
  /** Per row: the model column of a coil drawn at the right rail, or -1. */
  readonly alignedAt: Int32Array;
}

/** Where a box's body and labels go inside its cells. */
export interface BoxMetrics {
  /** From the box's left edge to its body: room for the input operands. */
  readonly left: number;
  /** From its body to the right edge: room for the output operands. */
  readonly rightMargin: number;
  /** The body's narrowest width: title, and input and output pin names side by side. */
  readonly body: number;
  /** Width of the instance name over the body (0 for a function). */
  readonly instance: number;
}

export const operandWidth = (text: string): number => textWidth(text, SPEC_SMALL);
export const nameWidth = (text: string): number => textWidth(text, SPEC_FONT);

/** `open`: pins drawn with a `???` operand (unwired, none given; pinOperands.ts), which need its room. */
export function boxMetrics(el: BoxElement, layout: BoxLayout, open?: OpenPins): BoxMetrics {
  let inOperand = 0;
  let outOperand = 0;
  let inPin = 0;
  let outPin = 0;
  for (const pin of layout.inputs) {
    inPin = Math.max(inPin, textWidth(pin.name, SPEC_SMALL));
    const operand = el.inputs[pin.name] || (open?.inputs.has(pin.name) ? '???' : '');
    if (operand) inOperand = Math.max(inOperand, operandWidth(operand));
  }
  for (const pin of layout.outputs) {
    outPin = Math.max(outPin, textWidth(pin.name, SPEC_SMALL));
    const operand = el.outputs[pin.name] || (open?.outputs.has(pin.name) ? '???' : '');
    if (operand) outOperand = Math.max(outOperand, operandWidth(operand));
  }
  return {
    left: Math.max(BOX_MARGIN, inOperand + 8),
    rightMargin: Math.max(BOX_MARGIN, outOperand + 8),
    body: Math.max(2 * CELL_W - 2 * BOX_MARGIN, textWidth(el.blockType, SPEC_BOLD) + 12, inPin + outPin + 20),
    instance: layout.signature.kind === 'fb' ? nameWidth(el.instance || '???') + 8 : 0,
  };
}

/** Where a jump's or return's label starts in its cell, and the room kept between it and the right rail. */
export const JUMP_TEXT_X = 10;
export const JUMP_RAIL_GAP = 14;

/** The label a jump or return shows, and the width it needs. */
export const jumpText = (el: LdElement): string =>
  el.kind === 'jump' ? `>>${el.target || '???'}` : el.kind === 'return' ? '<RETURN>' : '';

/** Widths the element needs, one per column it covers (before the network's minimum). */
function needs(el: LdElement, lib: BlockLibrary, n: Network): number[] {
  switch (el.kind) {
    case 'contact':
      return [el.contact === 'NOT' ? CELL_W : nameWidth(el.variable || '???') + LABEL_PAD];
    case 'coil':
      return [nameWidth(el.variable || '???') + LABEL_PAD];
    case 'jump':
    case 'return':
      return [JUMP_TEXT_X + textWidth(jumpText(el), SPEC_MONO_SMALL) + JUMP_RAIL_GAP];
    case 'connector':
    case 'continuation':
      return [textWidth(`>${el.name}>`, SPEC_BOLD) + 2 * LABEL_PAD];
    case 'link':
      return [0];
    case 'box': {
      const layout = boxLayout(el, lib);
      if (!layout) return [textWidth(el.blockType, SPEC_BOLD) + 2 * BOX_MARGIN + 8];
      const m = boxMetrics(el, layout, openPins(n, el, lib));
      const total = m.left + m.body + m.rightMargin;
      const extra = Math.max(0, m.instance - total) / 2;
      const first = m.left + m.body / 2 + extra;
      const last = m.body / 2 + m.rightMargin + extra;
      const out = new Array<number>(layout.cols).fill(0);
      out[0] = first;
      out[layout.cols - 1] = Math.max(out[layout.cols - 1]!, last);
      return out;
    }
  }
}

/**
 * Coils drawn at the right rail: a coil is the last thing on its row (no element right of it, no
 * vertical link right of its left side touching the row) and not already in the last column.
 * A coil in series before another element (LD-R04) stays where it is.
 */
function alignedCoils(n: Network, lib: BlockLibrary): Int32Array {
  const aligned = new Int32Array(n.rows).fill(-1);
  const rightmost = new Int32Array(n.rows).fill(-1);
  for (const el of n.elements) {
    const s = elementSize(el, lib);
    for (let r = el.row; r < el.row + s.rows && r < n.rows; r++)
      rightmost[r] = Math.max(rightmost[r]!, el.col + s.cols - 1);
  }
  for (const el of n.elements) {
    if (el.kind !== 'coil' || el.row >= n.rows || el.col >= n.cols - 1) continue;
    if (rightmost[el.row] !== el.col) continue;
    const blocked = n.vlinks.some(
      (v) => (v.row === el.row || v.row + 1 === el.row) && v.boundary > el.col,
    );
    if (!blocked) aligned[el.row] = el.col;
  }
  return aligned;
}

const cache = new WeakMap<Network, { lib: BlockLibrary; value: NetworkColumns }>();

/** The network's column geometry (memoised per network object and library). */
export function networkColumns(n: Network, lib: BlockLibrary = STANDARD_LIBRARY): NetworkColumns {
  const hit = cache.get(n);
  if (hit && hit.lib === lib) return hit.value;
  const alignedAt = alignedCoils(n, lib);
  const widths = new Float64Array(Math.max(0, n.cols)).fill(CELL_W);
  for (const el of n.elements) {
    const d = el.row < n.rows && alignedAt[el.row] === el.col && el.kind === 'coil' ? n.cols - 1 : el.col;
    needs(el, lib, n).forEach((w, i) => {
      const c = d + i;
      if (c < widths.length) widths[c] = Math.max(widths[c]!, Math.ceil(w));
    });
  }
  const xs = new Float64Array(n.cols + 1);
  for (let c = 0; c < n.cols; c++) xs[c + 1] = xs[c]! + widths[c]!;
  const value: NetworkColumns = { cols: n.cols, xs, alignedAt };
  cache.set(n, { lib, value });
  return value;
}

/** The column a model cell is drawn in (a rail-aligned coil's cell moves to the last column). */
export function displayCol(nc: NetworkColumns, row: number, col: number): number {
  const k = nc.alignedAt[row] ?? -1;
  if (k < 0 || col < k || col > nc.cols - 1) return col;
  return col === k ? nc.cols - 1 : col - 1;
}

/** The model column under a drawn column: the wire drawn on to a rail-aligned coil belongs to the coil. */
export function modelCol(nc: NetworkColumns, row: number, col: number): number {
  const k = nc.alignedAt[row] ?? -1;
  return k >= 0 && col >= k && col <= nc.cols - 1 ? k : col;
}

/** Left x of a drawn column (columns right of the grid are CELL_W wide). */
export function colLeft(nc: NetworkColumns, col: number): number {
  if (col <= nc.cols) return nc.xs[Math.max(0, col)]!;
  return nc.xs[nc.cols]! + (col - nc.cols) * CELL_W;
}

/** Width of `count` drawn columns from `col`. */
export const spanWidth = (nc: NetworkColumns, col: number, count = 1): number =>
  colLeft(nc, col + count) - colLeft(nc, col);

/** The drawn column at x (0 left of the grid; past the right rail it keeps counting in CELL_W steps). */
export function colAtX(nc: NetworkColumns, x: number): number {
  if (x < 0) return 0;
  const right = nc.xs[nc.cols]!;
  if (x >= right) return nc.cols + Math.floor((x - right) / CELL_W);
  let lo = 0;
  let hi = nc.cols - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (nc.xs[mid]! <= x) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

/** The column boundary nearest to x, 0..cols. */
export function boundaryAtX(nc: NetworkColumns, x: number): number {
  const c = Math.min(nc.cols, colAtX(nc, x));
  if (c >= nc.cols) return nc.cols;
  return x - nc.xs[c]! < nc.xs[c + 1]! - x ? c : c + 1;
}

/**
 * The model boundary for a drawn boundary between rows `row` and `row + 1`: inside the wire drawn
 * on to a rail-aligned coil it is the coil's left side (the same node).
 */
export function modelBoundary(nc: NetworkColumns, row: number, boundary: number): number {
  let out = boundary;
  for (const r of [row, row + 1]) {
    const k = nc.alignedAt[r] ?? -1;
    if (k >= 0 && boundary > k && boundary < nc.cols) out = Math.min(out, k);
  }
  return out;
}

/** An element's drawn rectangle's left and width (x from the grid's left edge). */
export function elementSpan(
  nc: NetworkColumns,
  el: Pick<LdElement, 'row' | 'col'>,
  cols: number,
): { x: number; width: number } {
  const d = displayCol(nc, el.row, el.col);
  return { x: colLeft(nc, d), width: spanWidth(nc, d, cols) };
}
