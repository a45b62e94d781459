// One network's grid as a single Konva shape: a projection of the network data, redrawn only
// when its props change (memo), so scrolling past 1,000 networks stays cheap.
import type Konva from 'konva';
import { memo, useLayoutEffect, useMemo, useRef } from 'react';
import { Shape } from 'react-konva';
import type { Cell } from '../../model/grid';
import type { ElementId } from '../../model/ids';
import type { BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import type { CanvasTheme } from '../theme/canvasTheme';
import { drawNetworkGrid, type CellMarker, type NetworkPaint } from './drawNetwork';
import { CELL_H, GRID_PAD_BOTTOM, headerHeight, networkWidth, RAIL_X, type SymbolComments } from './geometry';
import { useOverlayHook } from './overlay';

export interface NetworkShapeProps {
  readonly network: Network;
  readonly index: number;
  /** Top of the network in content pixels. */
  readonly top: number;
  readonly theme: CanvasTheme;
  readonly selected: ReadonlySet<ElementId>;
  readonly cursor: Cell | undefined;
  readonly hover: Cell | undefined;
  readonly markers: readonly CellMarker[];
  readonly drag: NetworkPaint['drag'];
  /** Current zoom: the cached bitmap is drawn at this scale so it stays sharp. */
  readonly zoom: number;
  /** The project's blocks: user FB and function boxes are drawn with their own pins. */
  readonly library: BlockLibrary;
  /** Height of the network's rows (geometry.rowPitch). */
  readonly pitch?: number;
  /** Variables' comments drawn under operands (the view option on), else undefined. */
  readonly symbols?: SymbolComments | undefined;
}

/** Room around the grid inside the cached bitmap (drag ghosts, marks at the edges). */
const CACHE_MARGIN = 12;

export const NetworkShape = memo(function NetworkShape(props: NetworkShapeProps) {
  const { network, index, top, theme, selected, cursor, hover, markers, drag, zoom, library, symbols } = props;
  const pitch = props.pitch ?? CELL_H;
  const ref = useRef<Konva.Shape>(null);
  const overlay = useOverlayHook()(network, index);
  const paint = useMemo<NetworkPaint>(
    () => ({
      library,
      selected,
      cursor,
      hover,
      markers,
      ...(pitch !== CELL_H ? { pitch } : {}),
      ...(symbols ? { symbols } : {}),
      ...(drag ? { drag } : {}),
      ...(overlay.power ? { power: overlay.power } : {}),
      ...(overlay.liveValues ? { liveValues: overlay.liveValues } : {}),
      ...(overlay.pinValues ? { pinValues: overlay.pinValues } : {}),
      ...(overlay.forced ? { forced: overlay.forced } : {}),
      ...(overlay.device ? { device: overlay.device } : {}),
    }),
    [library, selected, cursor, hover, markers, pitch, symbols, drag, overlay.power, overlay.liveValues, overlay.pinValues, overlay.forced, overlay.device],
  );
  const width = networkWidth(network, library);
  const height = network.rows * pitch + GRID_PAD_BOTTOM;
  // Each network is drawn once into a bitmap; scrolling then only copies bitmaps, which keeps
  // frames short with many symbols and texts on screen. Redrawn when anything it shows changes.
  useLayoutEffect(() => {
    const node = ref.current;
    if (!node) return;
    node.clearCache();
    node.cache({
      x: -CACHE_MARGIN,
      y: -CACHE_MARGIN,
      width: width + 2 * CACHE_MARGIN,
      height: height + 2 * CACHE_MARGIN,
      pixelRatio: zoom * (window.devicePixelRatio || 1),
      imageSmoothingEnabled: true,
    });
  }, [network, theme, paint, zoom, width, height]);
  if (network.collapsed) return null;
  return (
    <Shape
      ref={ref}
      x={RAIL_X}
      y={top + headerHeight(network)}
      width={width}
      height={height}
      listening={false}
      perfectDrawEnabled={false}
      sceneFunc={(ctx) => drawNetworkGrid(ctx._context, theme, network, paint)}
    />
  );
});
