// Renders only the table rows near the visible part of a scroll area, so a table of thousands
// of variables opens and follows edits at once. Row heights are estimates measured from rendered
// rows (a plain row, and the message row under a row with problems); the rows outside the window
// are replaced by two spacer rows of their total height, so the scrollbar stays true.
import { useCallback, useLayoutEffect, useMemo, useState, type RefObject } from 'react';

/** Tables up to this many rows render every row (nothing to gain below it). */
export const WINDOW_THRESHOLD = 150;
/** Extra pixels rendered above and below the visible area. */
const OVERSCAN_PX = 600;

export interface RowHeights {
  readonly row: number;
  readonly issue: number;
}

export interface RowWindow {
  /** Rows first..last (inclusive) are rendered. */
  readonly first: number;
  readonly last: number;
  /** Heights of the spacers before and after them. */
  readonly before: number;
  readonly after: number;
  /** Content offset of row i (from the top of the first row). */
  offsetOf(i: number): number;
}

/** Offsets of each row from the rows' heights: offsets[i] is row i's top, offsets[n] the total. */
export function rowOffsets(hasIssue: readonly boolean[], h: RowHeights): Float64Array {
  const out = new Float64Array(hasIssue.length + 1);
  for (let i = 0; i < hasIssue.length; i++) out[i + 1] = out[i]! + h.row + (hasIssue[i] ? h.issue : 0);
  return out;
}

/** The rows overlapping [top - overscan, top + height + overscan]. */
export function windowFor(
  offsets: Float64Array,
  top: number,
  height: number,
): { first: number; last: number } {
  const n = offsets.length - 1;
  if (n <= WINDOW_THRESHOLD) return { first: 0, last: n - 1 };
  const lo = Math.max(0, top - OVERSCAN_PX);
  const hi = top + height + OVERSCAN_PX;
  // First row whose bottom is below lo.
  let a = 0;
  let b = n - 1;
  while (a < b) {
    const mid = (a + b) >> 1;
    if (offsets[mid + 1]! <= lo) a = mid + 1;
    else b = mid;
  }
  let last = a;
  while (last < n - 1 && offsets[last + 1]! < hi) last++;
  return { first: a, last };
}

/**
 * The window of rows to render in `scrollRef`. `hasIssue[i]`: row i has a message row under it.
 * `measure` reads the real heights from the rendered table (returns undefined when no row shows).
 */
export function useRowWindow(
  scrollRef: RefObject<HTMLElement | null>,
  hasIssue: readonly boolean[],
  measure: () => Partial<RowHeights> | undefined,
): RowWindow {
  const [view, setView] = useState({ top: 0, height: 800 });
  const [heights, setHeights] = useState<RowHeights>({ row: 28, issue: 24 });
  useLayoutEffect(() => {
    const el = scrollRef.current;
    if (!el) return undefined;
    let frame = 0;
    const update = () => {
      frame = 0;
      setView((v) =>
        v.top === el.scrollTop && v.height === el.clientHeight
          ? v
          : { top: el.scrollTop, height: el.clientHeight },
      );
    };
    const onScroll = () => {
      if (!frame) frame = requestAnimationFrame(update);
    };
    update();
    el.addEventListener('scroll', onScroll, { passive: true });
    const ro = new ResizeObserver(onScroll);
    ro.observe(el);
    return () => {
      el.removeEventListener('scroll', onScroll);
      ro.disconnect();
      if (frame) cancelAnimationFrame(frame);
    };
  }, [scrollRef]);
  const offsets = useMemo(() => rowOffsets(hasIssue, heights), [hasIssue, heights]);
  const { first, last } = windowFor(offsets, view.top, view.height);
  const total = offsets[offsets.length - 1]!;
  // Learn the real row heights from what is on screen (once they are known this changes nothing).
  useLayoutEffect(() => {
    const m = measure();
    if (!m) return;
    setHeights((h) => {
      const row = m.row && Math.abs(m.row - h.row) > 0.5 ? m.row : h.row;
      const issue = m.issue && Math.abs(m.issue - h.issue) > 0.5 ? m.issue : h.issue;
      return row === h.row && issue === h.issue ? h : { row, issue };
    });
  }, [measure]);
  const offsetOf = useCallback(
    (i: number) => offsets[Math.max(0, Math.min(i, offsets.length - 1))]!,
    [offsets],
  );
  return {
    first,
    last,
    before: offsets[first] ?? 0,
    after: last >= first ? total - offsets[last + 1]! : 0,
    offsetOf,
  };
}
