// The selection, the keyboard cursor and the cell under the pointer, drawn by page elements over the canvas instead of into the
// networks' pictures: a click or an arrow key then changes two small elements (each on its own
// compositor layer, moved by a transform) and redraws no network, does not render the canvas and
// hands no new stage bitmap to the compositor (docs/benchmarks.md, select-ms). The rectangles are
// the ones drawNetworkGrid draws for print (selectionRects, cursorRect).
import { memo, useLayoutEffect, type RefObject } from 'react';
import type { Cell } from '../../model/grid';
import type { BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { selectCursor, selectSelection, useUi, useUiStore } from '../../store/uiStore';
import { cursorAnchor } from '../commands/editorActions';
import { CURSOR_LINE, cursorRect, SELECTION_LINE, selectionRects } from './drawNetwork';
import { cellRect, columnsOf, headerHeight, pitchOf, RAIL_X, type CanvasLayout } from './geometry';

interface Props {
  readonly layout: CanvasLayout;
  readonly networks: readonly Network[];
  readonly library: BlockLibrary;
  readonly zoom: number;
  readonly scrollRef: RefObject<HTMLDivElement | null>;
  /** The grid cell under the pointer (network index and cell). */
  readonly hover: { readonly index: number; readonly cell: Cell } | undefined;
}

type Rect = { x: number; y: number; width: number; height: number };

/** A box whose border is centred on `r` (content pixels) like a canvas stroke of width `line`. */
const boxStyle = (r: Rect, line: number) => ({
  transform: `translate(${r.x - line / 2}px, ${r.y - line / 2}px)`,
  width: r.width + line,
  height: r.height + line,
  borderWidth: line,
});

export const SelectionMarks = memo(function SelectionMarks({ layout, networks, library, zoom, scrollRef, hover }: Props) {
  const ui = useUiStore();
  const selection = useUi(selectSelection);
  const cursor = useUi(selectCursor);

  // The cursor never stays inside an element of several cells (a click on a box's right half, an undo
  // that leaves it where a box now is): it stands on the element's own cell.
  useLayoutEffect(() => {
    const n = cursor && networks.find((m) => m.id === cursor.network);
    if (!cursor || !n) return;
    const at = cursorAnchor(n, cursor, library);
    if (at.row !== cursor.row || at.col !== cursor.col) ui.getState().setCursor({ network: n.id, ...at });
  }, [cursor, networks, library, ui]);

  // Keep the keyboard cursor on screen.
  useLayoutEffect(() => {
    const el = scrollRef.current;
    if (!el || !cursor) return;
    const i = networks.findIndex((n) => n.id === cursor.network);
    const n = networks[i];
    if (!n) return;
    const pitch = pitchOf(layout, i);
    const top = (layout.tops[i]! + headerHeight(n) + cursor.row * pitch) * zoom;
    const cell = cellRect(columnsOf(layout, n), cursor, 1, 1, pitch);
    const left = (RAIL_X + cell.x) * zoom;
    const margin = 24;
    if (top < el.scrollTop + margin)
      el.scrollTop = top - (i > 0 && cursor.row === 0 ? headerHeight(n) * zoom : 0) - margin;
    else if (top + pitch * zoom > el.scrollTop + el.clientHeight - margin)
      el.scrollTop = top + pitch * zoom - el.clientHeight + margin;
    if (left < el.scrollLeft) el.scrollLeft = left - margin;
    else if (left + cell.width * zoom > el.scrollLeft + el.clientWidth)
      el.scrollLeft = left + cell.width * zoom - el.clientWidth + margin;
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [cursor]);

  const at = (id: string | undefined) => {
    const i = id === undefined ? -1 : networks.findIndex((n) => n.id === id);
    const n = networks[i];
    return n && !n.collapsed ? { i, n, x: RAIL_X, y: layout.tops[i]! + headerHeight(n) } : undefined;
  };
  const sel = selection.elements.length > 0 ? at(selection.network) : undefined;
  const selected = sel
    ? selectionRects(sel.n, columnsOf(layout, sel.n), new Set(selection.elements), library, pitchOf(layout, sel.i)).map((r) => ({
        ...r,
        x: r.x + sel.x,
        y: r.y + sel.y,
      }))
    : [];
  const cur = cursor ? at(cursor.network) : undefined;
  const cursorBox =
    cur && cursor ? cursorRect(cur.n, columnsOf(layout, cur.n), cursor, library, pitchOf(layout, cur.i)) : undefined;

  const hovered = hover ? networks[hover.index] : undefined;
  const hoverBox =
    hover && hovered && !hovered.collapsed
      ? cellRect(columnsOf(layout, hovered), hover.cell, 1, 1, pitchOf(layout, hover.index))
      : undefined;

  return (
    <div className="rs-marks" style={{ transform: `scale(${zoom})` }}>
      {hover && hovered && hoverBox && (
        <div
          className="rs-mark rs-hover-mark"
          data-testid="canvas-hover-mark"
          style={{
            transform: `translate(${RAIL_X + hoverBox.x}px, ${layout.tops[hover.index]! + headerHeight(hovered) + hoverBox.y}px)`,
            width: hoverBox.width,
            height: hoverBox.height,
          }}
        />
      )}
      {selected.map((r, k) => (
        <div key={k} className="rs-mark rs-selection-mark" data-testid="canvas-selection-mark" style={boxStyle(r, SELECTION_LINE)} />
      ))}
      {cur && cursorBox && (
        <div
          className="rs-mark rs-cursor-mark"
          data-testid="canvas-cursor-mark"
          style={boxStyle({ ...cursorBox, x: cursorBox.x + cur.x, y: cursorBox.y + cur.y }, CURSOR_LINE)}
        />
      )}
    </div>
  );
});
