// A network's grid as SVG markup, drawn by the canvas's own drawing code (drawNetworkGrid) into an
// SvgContext: no selection, cursor or simulation marks, and always expanded.
import type { BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { drawNetworkGrid, type NetworkPaint } from '../canvas/drawNetwork';
import { CELL_H, GRID_PAD_BOTTOM, networkWidth, RAIL_X } from '../canvas/geometry';
import type { CanvasTheme } from '../theme/canvasTheme';
import { SvgContext, type MeasureText } from './svgContext';

const PAINT: NetworkPaint = { selected: new Set(), cursor: undefined, hover: undefined, markers: [] };

export interface NetworkDrawing {
  readonly svg: string;
  readonly width: number;
  readonly height: number;
}

export function networkSvg(
  network: Network,
  theme: CanvasTheme,
  measure: MeasureText,
  library?: BlockLibrary,
): NetworkDrawing {
  const ctx = new SvgContext(measure);
  const width = networkWidth(network);
  const height = network.rows * CELL_H + GRID_PAD_BOTTOM;
  ctx.translate(RAIL_X, 0);
  drawNetworkGrid(ctx as unknown as CanvasRenderingContext2D, theme, network, library ? { ...PAINT, library } : PAINT);
  return { svg: ctx.toSvg(width, height, 'class="rs-print-grid" role="img"'), width, height };
}
