// Grid geometry. Cells and pixels are different types: the editor converts, the model never sees pixels.
//
// A network is a grid of `rows` x `cols` cells. Column boundaries are numbered 0..cols:
// boundary 0 is the left power rail, boundary `cols` is the right power rail.
// A cell (row, col) has a left terminal at point (row, boundary col) and a right terminal at
// point (row, boundary col + 1). A vertical link joins point (row, b) to point (row + 1, b).

/** A cell position on a network grid (integers, 0-based). */
export interface Cell {
  readonly row: number;
  readonly col: number;
}

/** A connection point: a row and a column boundary (0 = left rail, cols = right rail). */
export interface GridPoint {
  readonly row: number;
  readonly boundary: number;
}

export const cellKey = (row: number, col: number): string => `${row}:${col}`;
export const pointKey = (row: number, boundary: number): string => `${row}|${boundary}`;
