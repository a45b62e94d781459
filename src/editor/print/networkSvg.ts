// A network's grid as SVG markup, drawn by the canvas's own drawing code (drawNetworkGrid) into an
// SvgContext: no selection, cursor or simulation marks, and always expanded.
import type { BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { drawNetworkGrid, type NetworkPaint } from '../canvas/drawNetwork';
import { GRID_PAD_BOTTOM, networkWidth, RAIL_X, rowPitch, type SymbolComments } from '../canvas/geometry';
import type { CanvasTheme } from '../theme/canvasTheme';
import { usedRows } from '../../store/networkEdits';
import { SvgContext, svgFrame, type MeasureText } from './svgContext';

const PAINT: NetworkPaint = { selected: new Set(), cursor: undefined, hover: undefined, markers: [] };

export interface NetworkDrawing {
  readonly svg: string;
  /** An empty <svg> of the same size: what measuring the block needs, at a fraction of the cost. */
  readonly frame: string;
  readonly width: number;
  readonly height: number;
  /** Height of its rows (taller where comments are shown under operands). */
  readonly pitch: number;
  /** Rows drawn: those the rung uses (store/networkEdits.usedRows). */
  readonly rows: number;
}

const ATTRS = 'class="rs-print-grid"';

export function networkSvg(
  network: Network,
  theme: CanvasTheme,
  measure: MeasureText,
  library?: BlockLibrary,
  symbols?: SymbolComments,
): NetworkDrawing {
  const ctx = new SvgContext(measure);
  const width = networkWidth(network, library);
  const pitch = rowPitch(network, symbols);
  // Printed as the canvas shows it: as tall as the rows the rung uses.
  const rows = usedRows(network, library);
  const height = rows * pitch + GRID_PAD_BOTTOM;
  ctx.translate(RAIL_X, 0);
  const paint: NetworkPaint = { ...PAINT, pitch, rows, ...(library ? { library } : {}), ...(symbols ? { symbols } : {}) };
  drawNetworkGrid(ctx as unknown as CanvasRenderingContext2D, theme, network, paint);
  return { svg: ctx.toSvg(width, height, ATTRS), frame: svgFrame(width, height, ATTRS), width, height, pitch, rows };
}
