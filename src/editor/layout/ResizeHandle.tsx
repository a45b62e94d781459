// The handle between a panel and the canvas (WAI-ARIA window splitter): drag it to resize the
// panel, drag it nearly shut to collapse the panel, double-click it for the default size. From the
// keyboard: arrows resize (Shift: in bigger steps), Home/End go to the smallest/largest size,
// Enter collapses or expands.
import { useRef, type KeyboardEvent, type PointerEvent } from 'react';
import { DEFAULT_PANELS } from '../../store/uiStore';
import { useUi, useUiStore } from '../../store/uiStore';
import { clampSize, collapsedKey, maxSize, PANEL_LIMITS, type PanelSide } from './panelSizes';

const NAMES: Record<PanelSide, string> = { left: 'left panel', right: 'side panel', bottom: 'bottom panel' };

const windowSize = () => ({ width: window.innerWidth, height: window.innerHeight });

export function ResizeHandle({ side, controls }: { readonly side: PanelSide; readonly controls: string }) {
  const ui = useUiStore();
  const size = useUi((s) => s.panels[side]);
  const collapsed = useUi((s) => s.panels[collapsedKey(side)]);
  const max = useUi((s) => maxSize(side, s.panels, windowSize()));
  const drag = useRef<{ start: number; size: number } | undefined>(undefined);
  const horizontal = side === 'bottom';

  /** Sets the size; dragged below half its smallest size, the panel collapses (keeping the size
   * it had when the drag started, for when it opens again). */
  const resize = (next: number, start: number) => {
    const panels = ui.getState().panels;
    if (next < PANEL_LIMITS[side].min / 2) {
      if (!panels[collapsedKey(side)])
        ui.getState().setPanels({ [collapsedKey(side)]: true, ...(start > 0 ? { [side]: start } : {}) });
      return;
    }
    ui.getState().setPanels({ [side]: clampSize(side, next, panels, windowSize()), [collapsedKey(side)]: false });
  };

  const onPointerDown = (e: PointerEvent<HTMLDivElement>) => {
    if (e.button !== 0) return;
    e.preventDefault();
    e.currentTarget.setPointerCapture(e.pointerId);
    e.currentTarget.focus();
    drag.current = { start: horizontal ? e.clientY : e.clientX, size: collapsed ? 0 : size };
  };
  const onPointerMove = (e: PointerEvent<HTMLDivElement>) => {
    const d = drag.current;
    if (!d) return;
    const delta = (horizontal ? e.clientY : e.clientX) - d.start;
    resize(d.size + (side === 'left' ? delta : -delta), d.size);
  };
  const onPointerUp = (e: PointerEvent<HTMLDivElement>) => {
    drag.current = undefined;
    if (e.currentTarget.hasPointerCapture(e.pointerId)) e.currentTarget.releasePointerCapture(e.pointerId);
  };

  const onKeyDown = (e: KeyboardEvent<HTMLDivElement>) => {
    const step = e.shiftKey ? 50 : 10;
    const grow = horizontal ? 'ArrowUp' : side === 'left' ? 'ArrowRight' : 'ArrowLeft';
    const shrink = horizontal ? 'ArrowDown' : side === 'left' ? 'ArrowLeft' : 'ArrowRight';
    const panels = ui.getState().panels;
    const set = (next: number) =>
      ui.getState().setPanels({ [side]: clampSize(side, next, panels, windowSize()), [collapsedKey(side)]: false });
    if (e.key === grow) set((collapsed ? PANEL_LIMITS[side].min : size) + (collapsed ? 0 : step));
    else if (e.key === shrink && !collapsed) {
      if (size <= PANEL_LIMITS[side].min) ui.getState().setPanels({ [collapsedKey(side)]: true });
      else set(size - step);
    } else if (e.key === 'Home') set(PANEL_LIMITS[side].min);
    else if (e.key === 'End') set(max);
    else if (e.key === 'Enter') ui.getState().setPanels({ [collapsedKey(side)]: !collapsed });
    else return;
    e.preventDefault();
    e.stopPropagation();
  };

  return (
    <div
      role="separator"
      tabIndex={0}
      aria-orientation={horizontal ? 'horizontal' : 'vertical'}
      aria-label={`Resize the ${NAMES[side]}`}
      aria-controls={controls}
      aria-valuenow={collapsed ? 0 : size}
      aria-valuemin={0}
      aria-valuemax={max}
      title={`Drag to resize the ${NAMES[side]}; double-click for the default size; Enter collapses or expands`}
      className={`rs-resize-handle rs-resize-${side}${collapsed ? ' rs-collapsed' : ''}`}
      data-testid={`resize-${side}`}
      onPointerDown={onPointerDown}
      onPointerMove={onPointerMove}
      onPointerUp={onPointerUp}
      onPointerCancel={onPointerUp}
      onDoubleClick={() => ui.getState().setPanels({ [side]: DEFAULT_PANELS[side], [collapsedKey(side)]: false })}
      onKeyDown={onKeyDown}
    />
  );
}
