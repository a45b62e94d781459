// One network's grid as a single Konva shape: a projection of the network data, redrawn only
// when its props change (memo), so scrolling past 1,000 networks stays cheap.
import { memo, useMemo } from 'react';
import { Shape } from 'react-konva';
import type { Cell } from '../../model/grid';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import type { CanvasTheme } from '../theme/canvasTheme';
import { drawNetworkGrid, type CellMarker, type NetworkPaint } from './drawNetwork';
import { CELL_H, GRID_PAD_BOTTOM, headerHeight, networkWidth, RAIL_X } from './geometry';
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
}

export const NetworkShape = memo(function NetworkShape(props: NetworkShapeProps) {
  const { network, index, top, theme, selected, cursor, hover, markers, drag } = props;
  const overlay = useOverlayHook()(network, index);
  const paint = useMemo<NetworkPaint>(
    () => ({
      selected,
      cursor,
      hover,
      markers,
      ...(drag ? { drag } : {}),
      ...(overlay.power ? { power: overlay.power } : {}),
      ...(overlay.liveValues ? { liveValues: overlay.liveValues } : {}),
    }),
    [selected, cursor, hover, markers, drag, overlay.power, overlay.liveValues],
  );
  if (network.collapsed) return null;
  return (
    <Shape
      x={RAIL_X}
      y={top + headerHeight(network)}
      width={networkWidth(network)}
      height={network.rows * CELL_H + GRID_PAD_BOTTOM}
      listening={false}
      perfectDrawEnabled={false}
      sceneFunc={(ctx) => drawNetworkGrid(ctx._context, theme, network, paint)}
    />
  );
});
