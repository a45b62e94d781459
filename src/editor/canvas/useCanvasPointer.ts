// Pointer tools on the canvas as a small state machine:
//   idle --down on element--> pressing --moved 4px--> dragging --up--> moveElements (one undo step),
//     or moveElementsToNetwork when released over another network's grid (also one undo step)
//   idle --down on empty cell--> banding (rubber band) --up--> select elements inside
//   idle --middle button or Space held--> panning --up--> idle
// With a placing tool, a click places the element; with the vertical link tool, a click toggles
// the vertical link nearest to the pointer.
import {
  useCallback,
  useRef,
  useState,
  type MouseEvent,
  type PointerEvent as ReactPointerEvent,
  type RefObject,
} from 'react';
import { elementSize } from '../../model/factory';
import type { BlockLibrary } from '../../model/library';
import type { Cell } from '../../model/grid';
import type { ElementId } from '../../model/ids';
import type { Network } from '../../model/project';
import { elementAt, moveShift } from '../../store/networkEdits';
import { needsName, placeAt, type EditorContext } from '../commands/editorActions';
import { dropInto, moveWithin, type DragState } from './dragTargets';
import { useEdgeScroll } from './useEdgeScroll';
import { colAtX, modelCol } from './columns';
import {
  cellRect,
  columnsOf,
  gridOrigin,
  hitTest,
  networkIndexAt,
  pitchOf,
  rowsOf,
  type CanvasLayout,
  type PixelPoint,
} from './geometry';

export type { DragState } from './dragTargets';

export interface BandState {
  readonly index: number;
  readonly from: PixelPoint;
  readonly to: PixelPoint;
}

type Machine =
  | { readonly kind: 'idle' }
  | {
      readonly kind: 'pressing';
      readonly index: number;
      /** Where the press began; its y counts from the top of network `index` (rows shown above may change). */
      readonly start: PixelPoint;
      readonly startCell: Cell;
      readonly ids: ElementId[];
    }
  | {
      readonly kind: 'dragging';
      readonly index: number;
      readonly start: PixelPoint;
      readonly startCell: Cell;
      readonly ids: ElementId[];
    }
  | { readonly kind: 'banding'; readonly index: number; readonly start: PixelPoint }
  | {
      readonly kind: 'panning';
      readonly clientX: number;
      readonly clientY: number;
      readonly left: number;
      readonly top: number;
    };

export interface PointerView {
  readonly layout: CanvasLayout;
  readonly networks: readonly Network[];
  readonly zoom: number;
  /** The project's blocks: box sizes for hit tests and drags. */
  readonly library: BlockLibrary;
}

/**
 * Cell offset of a drag in network `n` from the grabbed cell: whole rows by the pointer's travel,
 * and the model column under the pointer in the target row (columns differ in width; the wire
 * drawn on to a rail-aligned coil counts as the coil's cell).
 */
function cellDelta(layout: CanvasLayout, n: Network, startCell: Cell, a: PixelPoint, b: PixelPoint) {
  const index = networkIndexAt(layout, a.y);
  const dRow = Math.round((b.y - a.y) / pitchOf(layout, index));
  const nc = columnsOf(layout, n);
  const row = Math.max(0, Math.min(rowsOf(layout, index) - 1, startCell.row + dRow));
  const col = modelCol(nc, row, colAtX(nc, b.x - gridOrigin(n).x));
  return { dRow, dCol: col - startCell.col };
}

const sameDrag = (a: DragState | undefined, b: DragState | undefined) =>
  a === b ||
  (a !== undefined &&
    b !== undefined &&
    a.network === b.network &&
    a.dRow === b.dRow &&
    a.dCol === b.dCol &&
    a.blocked === b.blocked &&
    a.into?.network === b.into?.network &&
    a.into?.at.row === b.into?.at.row &&
    a.into?.at.col === b.into?.at.col);

export function useCanvasPointer(
  ctx: EditorContext,
  scrollRef: RefObject<HTMLDivElement | null>,
  view: RefObject<PointerView>,
  spaceHeld: RefObject<boolean>,
) {
  const machine = useRef<Machine>({ kind: 'idle' });
  const { follow: edgeFollow, stop: edgeStop } = useEdgeScroll(scrollRef);
  const [drag, setDrag] = useState<DragState | undefined>(undefined);
  const [band, setBand] = useState<BandState | undefined>(undefined);
  const [hover, setHover] = useState<{ index: number; cell: Cell } | undefined>(undefined);

  const contentPoint = (e: { clientX: number; clientY: number }): PixelPoint => {
    const el = scrollRef.current!;
    const rect = el.getBoundingClientRect();
    const z = view.current.zoom;
    return { x: (e.clientX - rect.left + el.scrollLeft) / z, y: (e.clientY - rect.top + el.scrollTop) / z };
  };

  /** The drag shown for pointer point p: within the network, into another one, or undefined off any grid. */
  const dragAt = (
    n: Network,
    index: number,
    ids: readonly ElementId[],
    local: PixelPoint,
    startCell: Cell,
    p: PixelPoint,
  ): DragState | undefined => {
    const { layout, networks } = view.current;
    const start = { x: local.x, y: local.y + (layout.tops[index] ?? 0) };
    const hit = hitTest(layout, networks, p);
    if (hit.area !== 'grid') return undefined;
    const target = networks[hit.index]!;
    const base = { network: n.id, ids: new Set(ids), dRow: 0, dCol: 0 };
    if (target.id !== n.id) {
      const d = dropInto(n, target, ids, startCell, hit.cell, view.current.library);
      if (!d) return undefined;
      return { ...base, blocked: d.blocked, into: { network: target.id, ...d } };
    }
    const { dRow, dCol } = cellDelta(layout, n, startCell, start, p);
    return { ...base, dRow, dCol, ...moveWithin(n, ids, dRow, dCol, view.current.library) };
  };

  /** Stops a press, drag or rubber band without applying it (a second finger started a pinch). */
  const cancel = useCallback(() => {
    edgeStop();
    machine.current = { kind: 'idle' };
    ctx.ui.getState().setDragging(false);
    setDrag(undefined);
    setBand(undefined);
  }, [edgeStop, ctx.ui]);

  /** On the canvas itself (the layer the stage is drawn on), not on a header's field or button over it. */
  const onCanvas = (e: { target: EventTarget; currentTarget: EventTarget }) =>
    e.target === e.currentTarget || e.target instanceof HTMLCanvasElement;

  const onPointerDown = (e: ReactPointerEvent<HTMLDivElement>) => {
    if (!onCanvas(e)) return;
    const el = scrollRef.current!;
    el.focus({ preventScroll: true });
    if (e.button === 1 || (e.button === 0 && spaceHeld.current)) {
      e.preventDefault();
      e.currentTarget.setPointerCapture(e.pointerId);
      machine.current = {
        kind: 'panning',
        clientX: e.clientX,
        clientY: e.clientY,
        left: el.scrollLeft,
        top: el.scrollTop,
      };
      return;
    }
    if (e.button !== 0) return;
    const { layout, networks } = view.current;
    const p = contentPoint(e);
    const hit = hitTest(layout, networks, p);
    if (hit.area !== 'grid') return;
    const n = networks[hit.index]!;
    // A click just right of the grid may grow it by one column, not more.
    if (hit.cell.col > n.cols) return;
    const ui = ctx.ui.getState();
    ui.setStatus('');
    const tool = ui.tool;
    if (tool.kind === 'place') {
      placeAt(ctx, n.id, hit.cell, tool.template);
      return;
    }
    if (tool.kind === 'vlink') {
      if (hit.boundary > 0 && hit.boundary < n.cols)
        ctx.doc.getState().toggleVLink(n.id, { row: hit.wireRow, boundary: hit.boundary });
      else ui.setStatus('The power rails already join every row; put vertical links between cells.');
      return;
    }
    e.currentTarget.setPointerCapture(e.pointerId);
    ui.setCursor({ network: n.id, row: hit.cell.row, col: hit.cell.col });
    const target = elementAt(n, hit.cell, view.current.library);
    if (target) {
      let ids: ElementId[];
      if (e.shiftKey || e.ctrlKey || e.metaKey) {
        ui.toggleSelected(n.id, target.id);
        ids = [...ctx.ui.getState().selection.elements];
      } else {
        const sel = ui.selection;
        ids = sel.network === n.id && sel.elements.includes(target.id) ? [...sel.elements] : [target.id];
        ui.select(n.id, ids);
      }
      const local = { x: p.x, y: p.y - layout.tops[hit.index]! };
      machine.current = { kind: 'pressing', index: hit.index, start: local, startCell: hit.cell, ids };
    } else {
      if (!e.shiftKey) ui.select(n.id, []);
      machine.current = { kind: 'banding', index: hit.index, start: p };
    }
  };

  const onPointerMove = (e: ReactPointerEvent<HTMLDivElement>) => {
    const m = machine.current;
    const el = scrollRef.current;
    if (!el) return;
    if (m.kind === 'panning') {
      el.scrollLeft = m.left - (e.clientX - m.clientX);
      el.scrollTop = m.top - (e.clientY - m.clientY);
      return;
    }
    const p = contentPoint(e);
    const { layout, networks } = view.current;
    if (m.kind === 'pressing' || m.kind === 'dragging') {
      const startY = m.start.y + (layout.tops[m.index] ?? 0);
      if (m.kind === 'pressing' && Math.hypot(p.x - m.start.x, p.y - startY) < 4) return;
      const n = networks[m.index];
      if (!n) return;
      const dragging = { ...m, kind: 'dragging' as const };
      machine.current = dragging;
      // Every network shows an empty row under its rung to drop on while the drag lasts.
      ctx.ui.getState().setDragging(true);
      const show = (at: PixelPoint) => {
        const next = dragAt(n, dragging.index, dragging.ids, dragging.start, dragging.startCell, at);
        setDrag((prev) => (sameDrag(prev, next) ? prev : next));
      };
      show(p);
      // Near an edge the canvas scrolls; the ghost follows what is under the pointer.
      const client = { clientX: e.clientX, clientY: e.clientY };
      edgeFollow(client.clientX, client.clientY, () => {
        if (machine.current === dragging) show(contentPoint(client));
      });
      return;
    }
    if (m.kind === 'banding') {
      setBand({ index: m.index, from: m.start, to: p });
      return;
    }
    const hit = hitTest(layout, networks, p);
    const next =
      hit.area === 'grid' && hit.cell.col < (networks[hit.index]?.cols ?? 0)
        ? { index: hit.index, cell: hit.cell }
        : undefined;
    if (
      next?.index !== hover?.index ||
      next?.cell.row !== hover?.cell.row ||
      next?.cell.col !== hover?.cell.col
    )
      setHover(next);
  };

  const finish = (e: ReactPointerEvent<HTMLDivElement>) => {
    edgeStop();
    const m = machine.current;
    machine.current = { kind: 'idle' };
    if (e.currentTarget.hasPointerCapture(e.pointerId)) e.currentTarget.releasePointerCapture(e.pointerId);
    const { layout, networks } = view.current;
    if (m.kind === 'dragging') {
      const n = networks[m.index];
      setDrag(undefined);
      const d = n && dragAt(n, m.index, m.ids, m.start, m.startCell, contentPoint(e));
      const ui = ctx.ui.getState();
      ui.setDragging(false);
      if (!n || !d) {
        ui.setStatus('Drop elements on a network grid.');
      } else if (d.into) {
        const into = d.into;
        if (ctx.doc.getState().moveElementsToNetwork(n.id, m.ids, into.network, into.at)) {
          ui.select(into.network, m.ids);
          ui.setCursor({ network: into.network, row: into.at.row, col: into.at.col });
        } else ui.setStatus('Cannot move there: another element is in the way.');
      } else if (d.dRow !== 0 || d.dCol !== 0) {
        const shift = moveShift(n, m.ids, d.dCol);
        const moved = ctx.doc.getState().moveElements(n.id, m.ids, d.dRow, d.dCol);
        if (moved)
          ui.setCursor({ network: n.id, row: m.startCell.row + d.dRow, col: m.startCell.col + d.dCol + shift });
        else ui.setStatus('Cannot move there: another element is in the way.');
      }
    } else if (m.kind === 'banding') {
      setBand(undefined);
      const n = networks[m.index];
      const p = contentPoint(e);
      if (!n || Math.hypot(p.x - m.start.x, p.y - m.start.y) < 4) return;
      const o = gridOrigin(n);
      const top = layout.tops[m.index]! + o.y;
      const x1 = Math.min(m.start.x, p.x) - o.x;
      const x2 = Math.max(m.start.x, p.x) - o.x;
      const y1 = Math.min(m.start.y, p.y) - top;
      const y2 = Math.max(m.start.y, p.y) - top;
      const nc = columnsOf(layout, n);
      const inside = n.elements.filter((el) => {
        const s = elementSize(el, view.current.library);
        const r = cellRect(nc, el, s.cols, s.rows, pitchOf(layout, m.index));
        const cx = r.x + r.width / 2;
        const cy = r.y + r.height / 2;
        return cx >= x1 && cx <= x2 && cy >= y1 && cy <= y2;
      });
      const ui = ctx.ui.getState();
      const keep = e.shiftKey && ui.selection.network === n.id ? ui.selection.elements : [];
      ui.select(n.id, [...new Set([...keep, ...inside.map((el) => el.id)])]);
    }
  };

  const onDoubleClick = (e: MouseEvent<HTMLDivElement>) => {
    // The press captured the pointer on this layer, so Chromium sends the click and the
    // double-click to the layer itself, not to the canvas under it; a header field never counts.
    if (!onCanvas(e)) return;
    const { layout, networks } = view.current;
    const hit = hitTest(layout, networks, contentPoint(e));
    if (hit.area !== 'grid') return;
    const el = elementAt(networks[hit.index]!, hit.cell, view.current.library);
    if (el && needsName(el)) ctx.ui.getState().startEditing(el.id);
  };

  return {
    drag,
    band,
    hover,
    cancel,
    handlers: {
      onPointerDown,
      onPointerMove,
      onPointerUp: finish,
      onPointerCancel: finish,
      onDoubleClick,
      onPointerLeave: () => setHover(undefined),
      // Focus is managed in onPointerDown; the browser's own focus-on-mousedown would take it away
      // from a name editor that just opened.
      onMouseDown: (e: MouseEvent<HTMLDivElement>) => {
        if (onCanvas(e)) e.preventDefault();
      },
    },
  };
}
