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
  /** The cell under the pointer, on a connector: its partners are outlined (the hover's fill is a page element). */
  readonly partners: Cell | undefined;
  readonly markers: readonly CellMarker[];
  readonly drag: NetworkPaint['drag'];
  /** Current zoom: the cached bitmap is drawn at this scale so it stays sharp. */
  readonly zoom: number;
  /** The project's blocks: user FB and function boxes are drawn with their own pins. */
  readonly library: BlockLibrary;
  /** Height of the network's rows (geometry.rowPitch). */
  readonly pitch?: number;
  /** Rows shown (geometry.shownRows: the used rows and any room to place into). */
  readonly rows?: number;
  /** Variables' comments drawn under operands (the view option on), else undefined. */
  readonly symbols?: SymbolComments | undefined;
}

/** Room around the grid inside the cached bitmap (drag ghosts, marks at the edges). */
const CACHE_MARGIN = 12;

export const NetworkShape = memo(function NetworkShape(props: NetworkShapeProps) {
  const { network, index, top, theme, selected, cursor, partners, markers, drag, zoom, library, symbols } = props;
  const pitch = props.pitch ?? CELL_H;
  const rows = props.rows ?? network.rows;
  const ref = useRef<Konva.Shape>(null);
  const overlay = useOverlayHook()(network, index);
  const paint = useMemo<NetworkPaint>(
    () => ({
      library,
      selected,
      cursor,
      hover: undefined,
      ...(partners ? { partners } : {}),
      markers,
      ...(pitch !== CELL_H ? { pitch } : {}),
      rows,
      ...(symbols ? { symbols } : {}),
      ...(drag ? { drag } : {}),
      ...(overlay.power ? { power: overlay.power } : {}),
      ...(overlay.liveValues ? { liveValues: overlay.liveValues } : {}),
      ...(overlay.pinValues ? { pinValues: overlay.pinValues } : {}),
      ...(overlay.forced ? { forced: overlay.forced } : {}),
      ...(overlay.device ? { device: overlay.device } : {}),
    }),
    [library, selected, cursor, partners, markers, pitch, rows, symbols, drag, overlay.power, overlay.liveValues, overlay.pinValues, overlay.forced, overlay.device],
  );
  const width = networkWidth(network, library);
  const height = rows * pitch + GRID_PAD_BOTTOM;
  // Each network is drawn once into its own bitmap; scrolling then only copies bitmaps, which keeps
  // frames short with many symbols and texts on screen. Redrawn when anything it shows changes,
  // into the same canvas (Konva's node.cache() made three new canvases on every redraw).
  const bitmap = useRef<HTMLCanvasElement | null>(null);
  useLayoutEffect(() => {
    const node = ref.current;
    if (!node) return;
    const canvas = (bitmap.current ??= document.createElement('canvas'));
    const ratio = zoom * (window.devicePixelRatio || 1);
    const w = Math.max(1, Math.ceil((width + 2 * CACHE_MARGIN) * ratio));
    const h = Math.max(1, Math.ceil((height + 2 * CACHE_MARGIN) * ratio));
    if (canvas.width !== w || canvas.height !== h) {
      canvas.width = w;
      canvas.height = h;
    }
    const ctx = canvas.getContext('2d');
    if (!ctx) return;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, w, h);
    ctx.setTransform(ratio, 0, 0, ratio, CACHE_MARGIN * ratio, CACHE_MARGIN * ratio);
    ctx.imageSmoothingEnabled = true;
    drawNetworkGrid(ctx, theme, network, paint);
    node.getLayer()?.batchDraw();
  }, [network, theme, paint, zoom, width, height]);
  // The bitmap's canvas goes with the shape (a scrolled-away network gives its memory back).
  useLayoutEffect(
    () => () => {
      if (bitmap.current) bitmap.current.width = bitmap.current.height = 0;
      bitmap.current = null;
    },
    [],
  );
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
      sceneFunc={(ctx) => {
        const b = bitmap.current;
        if (b && b.width > 1)
          ctx._context.drawImage(b, -CACHE_MARGIN, -CACHE_MARGIN, width + 2 * CACHE_MARGIN, height + 2 * CACHE_MARGIN);
      }}
    />
  );
});
