// Cells to pixels and back. Model positions are cells (src/model/grid.ts); pixels live only here,
// in unscaled content coordinates (zoom is applied by the stage and the header overlay).
import type { Cell } from '../../model/grid';
import type { Network } from '../../model/project';

/** A position in canvas content pixels (before zoom). Not a Cell. */
export interface PixelPoint {
  readonly x: number;
  readonly y: number;
}

export const CELL_W = 72;
export const CELL_H = 64;
/** Height of the wire inside a cell, leaving room for the variable name above it. */
export const WIRE_Y = 40;
/** The left power rail's x; the grid starts here. */
export const RAIL_X = 28;
export const HEADER_TITLE_H = 36;
export const COMMENT_LINE_H = 20;
export const MAX_COMMENT_LINES = 4;
export const GRID_PAD_BOTTOM = 14;
export const NETWORK_GAP = 10;

export const commentLines = (n: Pick<Network, 'comment'>): number =>
  Math.min(MAX_COMMENT_LINES, Math.max(1, n.comment.split('\n').length));

export const headerHeight = (n: Pick<Network, 'comment'>): number =>
  HEADER_TITLE_H + commentLines(n) * COMMENT_LINE_H + 6;

export const gridHeight = (n: Pick<Network, 'rows' | 'collapsed'>): number =>
  n.collapsed ? 0 : n.rows * CELL_H + GRID_PAD_BOTTOM;

export const networkHeight = (n: Network): number => headerHeight(n) + gridHeight(n) + NETWORK_GAP;

export const networkWidth = (n: Pick<Network, 'cols'>): number => RAIL_X * 2 + n.cols * CELL_W;

export interface CanvasLayout {
  /** Top of each network (content pixels). */
  readonly tops: Float64Array;
  readonly heights: Float64Array;
  readonly totalHeight: number;
  readonly totalWidth: number;
}

export function layoutNetworks(networks: readonly Network[]): CanvasLayout {
  const tops = new Float64Array(networks.length);
  const heights = new Float64Array(networks.length);
  let y = 8;
  let width = 480;
  networks.forEach((n, i) => {
    tops[i] = y;
    heights[i] = networkHeight(n);
    y += heights[i]!;
    width = Math.max(width, networkWidth(n) + 40);
  });
  return { tops, heights, totalHeight: y + 40, totalWidth: width };
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

/** Top-left of a network's cell grid relative to the network's top. */
export const gridOrigin = (n: Pick<Network, 'comment'>): PixelPoint => ({ x: RAIL_X, y: headerHeight(n) });

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
  if (n.collapsed || local > origin.y + n.rows * CELL_H + GRID_PAD_BOTTOM) return { area: 'none' };
  const gx = p.x - origin.x;
  const gy = local - origin.y;
  const row = Math.min(n.rows - 1, Math.max(0, Math.floor(gy / CELL_H)));
  const col = Math.max(0, Math.floor(gx / CELL_W));
  const boundary = Math.max(0, Math.min(n.cols, Math.round(gx / CELL_W)));
  const wireRow = Math.max(0, Math.min(n.rows - 1, Math.floor((gy - WIRE_Y) / CELL_H)));
  return { area: 'grid', index, cell: { row, col }, boundary, wireRow };
}
