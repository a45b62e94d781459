// Two-finger pinch on a touch screen zooms the canvas around the fingers' midpoint, and moving
// both fingers pans. (Trackpad pinch arrives as Ctrl+wheel and is handled with the wheel.) The
// page itself never zooms: the canvas allows only panning to the browser (touch-action in
// canvas.css) and takes two-finger moves for itself.
import { useEffect, type RefObject } from 'react';
import { clampZoom, type UiStore } from '../../store/uiStore';

/** Where the zoom should keep a content point: under this offset of the viewport, after the zoom applies. */
export interface ZoomAnchor {
  readonly x: number;
  readonly y: number;
  readonly offsetX: number;
  readonly offsetY: number;
}

interface Pinch {
  readonly distance: number;
  readonly zoom: number;
  /** The content point (unscaled) under the fingers' midpoint when the pinch began. */
  readonly x: number;
  readonly y: number;
}

const midpoint = (a: Touch, b: Touch) => ({ x: (a.clientX + b.clientX) / 2, y: (a.clientY + b.clientY) / 2 });
const distance = (a: Touch, b: Touch) => Math.hypot(a.clientX - b.clientX, a.clientY - b.clientY);

/**
 * Pinch zoom on `scrollRef`'s element. `onStart` runs when a second finger lands (stop any drag
 * the first finger began); `zoomAnchor` is filled before each zoom change so the canvas can keep
 * the pinched point under the fingers (it applies the anchor once the new zoom has rendered).
 */
export function usePinchZoom(
  scrollRef: RefObject<HTMLDivElement | null>,
  ui: UiStore,
  zoomAnchor: { current: ZoomAnchor | undefined },
  onStart: () => void,
): void {
  useEffect(() => {
    const el = scrollRef.current;
    if (!el) return undefined;
    let pinch: Pinch | undefined;
    const begin = (e: TouchEvent) => {
      const [a, b] = [e.touches[0], e.touches[1]];
      if (e.touches.length !== 2 || !a || !b) {
        pinch = undefined;
        return;
      }
      const rect = el.getBoundingClientRect();
      const m = midpoint(a, b);
      const zoom = ui.getState().viewport.zoom;
      pinch = {
        distance: Math.max(1, distance(a, b)),
        zoom,
        x: (m.x - rect.left + el.scrollLeft) / zoom,
        y: (m.y - rect.top + el.scrollTop) / zoom,
      };
      onStart();
    };
    const move = (e: TouchEvent) => {
      const [a, b] = [e.touches[0], e.touches[1]];
      if (!pinch || e.touches.length !== 2 || !a || !b) return;
      if (e.cancelable) e.preventDefault();
      const rect = el.getBoundingClientRect();
      const m = midpoint(a, b);
      const zoom = clampZoom(pinch.zoom * (distance(a, b) / pinch.distance));
      const anchor = { x: pinch.x, y: pinch.y, offsetX: m.x - rect.left, offsetY: m.y - rect.top };
      if (zoom === ui.getState().viewport.zoom) {
        // Same zoom: only pan, so the pinched point follows the fingers.
        el.scrollLeft = anchor.x * zoom - anchor.offsetX;
        el.scrollTop = anchor.y * zoom - anchor.offsetY;
        return;
      }
      zoomAnchor.current = anchor;
      ui.getState().setZoom(zoom);
    };
    const end = (e: TouchEvent) => {
      if (e.touches.length === 2) begin(e);
      else pinch = undefined;
    };
    el.addEventListener('touchstart', begin, { passive: true });
    el.addEventListener('touchmove', move, { passive: false });
    el.addEventListener('touchend', end, { passive: true });
    el.addEventListener('touchcancel', end, { passive: true });
    return () => {
      el.removeEventListener('touchstart', begin);
      el.removeEventListener('touchmove', move);
      el.removeEventListener('touchend', end);
      el.removeEventListener('touchcancel', end);
    };
  }, [scrollRef, ui, zoomAnchor, onStart]);
}
