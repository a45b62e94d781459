// Pixel geometry of exported LD: the grid mapped to PLCopen coordinates so that Beremiz and
// OpenPLC draw the networks as Rungsmith shows them, and reconnect rail pins by wire endpoints.

export const CELL_W = 60;
export const ROW_H = 40;
export const LEFT_X = 40;
export const RAIL_W = 3;
export const ELEMENT_W = 21;
export const ELEMENT_H = 20;
export const BOX_MARGIN_X = 15;
export const BOX_MARGIN_Y = 8;
export const NETWORK_GAP = 20;
export const COMMENT_H = 40;
/** Coordinate snapping written to contentHeader. */
export const SCALING = 10;

export interface Point {
  readonly x: number;
  readonly y: number;
}

/** x of a column boundary. */
export const boundaryX = (b: number): number => LEFT_X + b * CELL_W;
/** y of the centre line of a row, relative to the network's top. */
export const rowY = (top: number, r: number): number => top + r * ROW_H + ROW_H / 2;
