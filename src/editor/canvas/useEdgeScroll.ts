// While dragging elements, holding the pointer near the canvas's top or bottom edge (or left and
// right) scrolls it, faster the closer to the edge, so a drag can reach a network that was off
// screen. Each scroll step calls back so the drag ghost follows the content under the pointer.
import { useCallback, useEffect, useRef, type RefObject } from 'react';

/** Distance from an edge (px) where scrolling starts. */
const EDGE = 36;
/** Fastest scroll, px per frame, with the pointer at (or past) the edge. */
const MAX_STEP = 18;

const speed = (pos: number, low: number, high: number) => {
  if (pos < low + EDGE) return -Math.ceil((MAX_STEP * Math.min(EDGE, low + EDGE - pos)) / EDGE);
  if (pos > high - EDGE) return Math.ceil((MAX_STEP * Math.min(EDGE, pos - (high - EDGE))) / EDGE);
  return 0;
};

export function useEdgeScroll(scrollRef: RefObject<HTMLDivElement | null>) {
  const frame = useRef(0);
  const step = useRef({ x: 0, y: 0, onStep: () => {} });

  const stop = useCallback(() => {
    if (frame.current) cancelAnimationFrame(frame.current);
    frame.current = 0;
  }, []);

  /** The pointer moved during a drag: scroll while it stays near an edge. */
  const follow = useCallback(
    (clientX: number, clientY: number, onStep: () => void) => {
      const el = scrollRef.current;
      if (!el) return;
      const r = el.getBoundingClientRect();
      step.current = { x: speed(clientX, r.left, r.right), y: speed(clientY, r.top, r.bottom), onStep };
      if (step.current.x === 0 && step.current.y === 0) return stop();
      if (frame.current) return;
      const tick = () => {
        const s = step.current;
        const beforeTop = el.scrollTop;
        const beforeLeft = el.scrollLeft;
        el.scrollTop += s.y;
        el.scrollLeft += s.x;
        if (el.scrollTop === beforeTop && el.scrollLeft === beforeLeft) {
          frame.current = 0;
          return;
        }
        s.onStep();
        frame.current = requestAnimationFrame(tick);
      };
      frame.current = requestAnimationFrame(tick);
    },
    [scrollRef, stop],
  );

  useEffect(() => stop, [stop]);
  return { follow, stop };
}
