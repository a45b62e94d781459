// The ladder canvas: networks stacked vertically, only the visible ones rendered. A native
// scroll area (the browser's own scrollbars, wheel and touch scrolling) holds a sticky viewport;
// inside it a "world" layer follows the scroll position by a CSS transform. The Konva stage
// covers the viewport plus a band around it and is redrawn only when the scroll position leaves
// that band, so most scroll frames are pure compositing.
import { useEffect, useLayoutEffect, useMemo, useRef, useState } from 'react';
import { Layer, Stage } from 'react-konva';
import type { ElementId, NetworkId } from '../../model/ids';
import {
  selectActivePou,
  selectGlobals,
  selectLibrary,
  selectNetworks,
  useDocument,
  useDocumentStore,
} from '../../store/documentStore';
import { isConnection } from '../../store/connectors';
import { elementAt } from '../../store/networkEdits';
import {
  clampZoom,
  selectTheme,
  selectZoom,
  useUi,
  useUiStore,
} from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import { useDiagnosticsByNetwork } from '../problems/useDiagnostics';
import { readCanvasTheme, type CanvasTheme } from '../theme/canvasTheme';
import { BlockPicker } from './BlockPicker';
import { CanvasEmpty } from './CanvasEmpty';
import {
  cellRect,
  columnsOf,
  headerHeight,
  layoutNetworks,
  networkIndexAt,
  pitchOf,
  RAIL_X,
  rowsOf,
  visibleRange,
  type CanvasLayout,
  type Room,
} from './geometry';
import { roomFor } from './canvasLayout';
import { symbolCommentsFor } from './symbolComments';
import { hoverText } from './hoverText';
import { useSimStore } from '../sim/simContext';
import { simInputHint } from '../sim/useCanvasSimInput';
import { InlineEditor } from './InlineEditor';
import type { CellMarker, NetworkPaint } from './drawNetwork';
import type { DragState } from './dragTargets';
import { markersByNetwork } from './markers';
import { NetworkHeader } from './NetworkHeader';
import { NetworkShape } from './NetworkShape';
import { SelectionMarks } from './SelectionMarks';
import { useCanvasPointer, type PointerView } from './useCanvasPointer';
import { usePinchZoom, type ZoomAnchor } from './usePinchZoom';
import './canvas.css';

/** Where the focus is the user's own: a field being typed in, or a dialog. */
const FIELD_OR_DIALOG = 'input, textarea, select, [contenteditable="true"], [role="dialog"], [role="alertdialog"]';

const withSimHint = (text: string | undefined, hint: string | undefined) =>
  text && hint ? `${text}\n${hint}` : (text ?? hint);

const EMPTY_SET: ReadonlySet<ElementId> = new Set();
/** Screen pixels drawn beyond the viewport's edges; the stage moves in steps of these. The bands
 * keep redraws rare while scrolling through networks (sideways scrolling is rarer); every change
 * on the canvas (a click selecting an element) hands the whole stage canvas to the compositor, so
 * they are no taller than that needs: 320 px, not 640, cut that copy by ~40% a click (docs/benchmarks.md). */
const BAND_X = 160;
const BAND_Y = 320;

/** How far below the view's top edge (content pixels) the network "in view" is taken. */
const VIEW_PROBE = 24;

const windowFor = (left: number, top: number) => ({
  left: Math.max(0, Math.floor(left / BAND_X) * BAND_X - BAND_X),
  top: Math.max(0, Math.floor(top / BAND_Y) * BAND_Y - BAND_Y),
});

export function LadderCanvas() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  // Read when the pointer rests on a cell: an input contact's tooltip says how to switch it.
  const simStore = useSimStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const networks = useDocument(selectNetworks);
  const pou = useDocument(selectActivePou);
  const library = useDocument(selectLibrary);
  const zoom = useUi(selectZoom);
  // The selection and the cursor are drawn by SelectionMarks: a click does not render the canvas.
  const themeName = useUi(selectTheme);
  const tool = useUi((s) => s.tool);
  const focusRequest = useUi((s) => s.focusRequest);
  const showSymbolComments = useUi((s) => s.symbolComments);
  const globals = useDocument(selectGlobals);
  // Looked up per operand only when drawn or laid out (and memoised per network there).
  const symbols = symbolCommentsFor(showSymbolComments, pou?.variables, globals);
  // Networks are as tall as the rows they use; room to place into shows while placing (canvasLayout.ts).
  const dragging = useUi((s) => s.dragging);
  // The cursor matters to the layout only below a network's used rows (room to place into).
  const roomKey = useUi((s) => {
    const r = roomFor({ tool, cursor: s.cursor, dragging }, networks, library);
    return r ? (r.all ? 'all' : `${r.network}:${r.rows}`) : '';
  });
  const stableRoom = useMemo<Room | undefined>(
    () => roomFor({ tool, cursor: ui.getState().cursor, dragging }, networks, library),
    // eslint-disable-next-line react-hooks/exhaustive-deps
    [roomKey],
  );
  const layout = useMemo(
    () => layoutNetworks(networks, library, symbols, stableRoom),
    [networks, library, symbols, stableRoom],
  );
  const diagnostics = useDiagnosticsByNetwork(pou?.name);
  const markers = useMemo(() => markersByNetwork(networks, diagnostics), [networks, diagnostics]);

  const scrollRef = useRef<HTMLDivElement>(null);
  const worldRef = useRef<HTMLDivElement>(null);
  /** The drawn window's top-left, in screen pixels of the scrolled content. */
  const [win, setWin] = useState({ left: 0, top: 0 });
  const winRef = useRef(win);
  const [size, setSize] = useState({ width: 800, height: 600 });
  const [theme, setTheme] = useState<CanvasTheme | undefined>(undefined);
  const view = useRef<PointerView>({ layout, networks, zoom, library });
  view.current = { layout, networks, zoom, library };
  const spaceHeld = useRef(false);
  const zoomAnchor = useRef<ZoomAnchor | undefined>(undefined);
  const { drag, band, hover, cancel, handlers } = useCanvasPointer(ctx, scrollRef, view, spaceHeld);
  const dragPaints = useMemo(() => dragPaintsFor(drag), [drag]);
  usePinchZoom(scrollRef, ui, zoomAnchor, cancel);

  useLayoutEffect(() => {
    if (scrollRef.current) setTheme(readCanvasTheme(scrollRef.current));
  }, [themeName]);

  useLayoutEffect(() => {
    const el = scrollRef.current;
    if (!el) return undefined;
    const measure = () => {
      setSize({ width: el.clientWidth, height: el.clientHeight });
      ui.getState().setViewport({ width: el.clientWidth, height: el.clientHeight });
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(el);
    return () => ro.disconnect();
  }, [ui]);

  // Ctrl+wheel and trackpad pinch (which Chromium reports as Ctrl+wheel) zoom around the pointer;
  // touch pinch: usePinchZoom.
  useEffect(() => {
    const el = scrollRef.current;
    if (!el) return undefined;
    const onWheel = (e: WheelEvent) => {
      if (!e.ctrlKey && !e.metaKey) return;
      e.preventDefault();
      const rect = el.getBoundingClientRect();
      const z = ui.getState().viewport.zoom;
      const offsetX = e.clientX - rect.left;
      const offsetY = e.clientY - rect.top;
      zoomAnchor.current = {
        x: (offsetX + el.scrollLeft) / z,
        y: (offsetY + el.scrollTop) / z,
        offsetX,
        offsetY,
      };
      ui.getState().setZoom(clampZoom(z * Math.exp(-e.deltaY * 0.0015)));
    };
    el.addEventListener('wheel', onWheel, { passive: false });
    return () => el.removeEventListener('wheel', onWheel);
  }, [ui]);

  useLayoutEffect(() => {
    const el = scrollRef.current;
    const a = zoomAnchor.current;
    if (!el || !a) return;
    zoomAnchor.current = undefined;
    el.scrollLeft = a.x * zoom - a.offsetX;
    el.scrollTop = a.y * zoom - a.offsetY;
  }, [zoom]);

  // "Click to jump" from the problems list, and new networks: scroll the cell to the middle.
  useLayoutEffect(() => {
    const el = scrollRef.current;
    if (!el || !focusRequest) return;
    const i = networks.findIndex((n) => n.id === focusRequest.network);
    const n = networks[i];
    if (!n) return;
    if (n.collapsed) doc.getState().updateNetwork(n.id, { collapsed: false });
    const y = layout.tops[i]! + headerHeight(n) + focusRequest.cell.row * pitchOf(layout, i);
    const x = RAIL_X + cellRect(columnsOf(layout, n), focusRequest.cell).x;
    el.scrollTop = Math.max(0, (y - 80) * zoom - el.clientHeight / 3);
    el.scrollLeft = Math.max(0, x * zoom - el.clientWidth / 2);
    // A panel that shows places one after another (find: Enter for the next) keeps the keyboard.
    if (!document.activeElement?.closest('[data-keeps-focus]')) el.focus({ preventScroll: true });
    // Only a new request scrolls; later layout changes must not pull the view back.
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [focusRequest]);

  // When every network gains (or loses) its empty row to drop on, the network being worked on stays
  // where it is on screen (the cursor's, else the one at the view's top): no jump under the pointer.
  const prevLayout = useRef<CanvasLayout>(layout);
  useLayoutEffect(() => {
    const old = prevLayout.current;
    prevLayout.current = layout;
    const el = scrollRef.current;
    if (!el || old === layout || Boolean(old.room?.all) === Boolean(layout.room?.all)) return;
    if (old.tops.length !== layout.tops.length) return;
    const viewTop = el.scrollTop / zoom;
    const viewBottom = viewTop + el.clientHeight / zoom;
    const cursor = ui.getState().cursor;
    let a = cursor ? networks.findIndex((n) => n.id === cursor.network) : -1;
    if (a < 0 || old.tops[a]! + old.heights[a]! < viewTop || old.tops[a]! > viewBottom)
      a = networkIndexAt(old, viewTop + VIEW_PROBE);
    if (a < 0) return;
    const shift = (layout.tops[a]! - old.tops[a]!) * zoom;
    if (shift) el.scrollTop += shift;
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [layout]);

  // When the app opens and whenever another project is opened or created, the keyboard goes to the
  // canvas (arrows and letters work at once), unless a dialog is open or a field has the focus.
  const opened = useDocument((s) => s.opened);
  useEffect(() => {
    const frame = requestAnimationFrame(() => {
      const el = scrollRef.current;
      if (!el || document.querySelector('[aria-modal="true"]')) return;
      const active = document.activeElement;
      if (active && active !== document.body && active.closest(FIELD_OR_DIALOG)) return;
      el.focus({ preventScroll: true });
    });
    return () => cancelAnimationFrame(frame);
  }, [opened]);

  // Follow the scroll position: move the world layer every frame, re-render only per band.
  const followScroll = () => {
    const el = scrollRef.current;
    const world = worldRef.current;
    if (!el || !world) return;
    world.style.transform = `translate(${-el.scrollLeft}px, ${-el.scrollTop}px)`;
    // The network at the top of the view (a little below the edge: a header just scrolling in counts).
    const top = networks[networkIndexAt(layout, el.scrollTop / zoom + VIEW_PROBE)];
    ui.getState().setViewNetwork(top?.id ?? networks[0]?.id);
    const w = windowFor(el.scrollLeft, el.scrollTop);
    if (w.left !== winRef.current.left || w.top !== winRef.current.top) {
      winRef.current = w;
      setWin(w);
    }
  };
  useLayoutEffect(followScroll);

  const stageWidth = size.width + 2 * BAND_X;
  const stageHeight = size.height + 2 * BAND_Y;
  const { first, last } = visibleRange(layout, win.top / zoom, (win.top + stageHeight) / zoom);
  const refocus = () => scrollRef.current?.focus({ preventScroll: true });
  const hoverProblems = hover
    ? (markers.get(hover.index)?.markers ?? NO_MARKERS).filter(
        (m) => m.cell.row === hover.cell.row && m.cell.col === hover.cell.col,
      )
    : NO_MARKERS;
  const hoverNetwork = hover ? networks[hover.index] : undefined;
  const hoverElement = hoverNetwork && hover ? elementAt(hoverNetwork, hover.cell, library) : undefined;
  // Only a connector's partners are drawn into the network's picture when the pointer rests on it;
  // the cell's own fill is SelectionMarks' (moving the pointer redraws no network).
  const hoverOnConnection = hoverElement !== undefined && isConnection(hoverElement);
  const visible: number[] = [];
  for (let i = first; i <= last; i++) visible.push(i);

  return (
    <div
      ref={scrollRef}
      className={`rs-canvas rs-tool-${tool.kind}`}
      tabIndex={0}
      role="application"
      aria-label="Ladder diagram: arrows move the cursor, letters place elements (see the palette tooltips)"
      aria-roledescription="ladder editor"
      data-testid="ladder-canvas"
      onScroll={followScroll}
      onKeyDown={(e) => {
        if (e.key === ' ' && e.target === e.currentTarget) {
          spaceHeld.current = true;
          e.preventDefault();
        }
      }}
      onKeyUp={(e) => {
        if (e.key === ' ') spaceHeld.current = false;
      }}
    >
      <div
        className="rs-canvas-content"
        style={{
          width: Math.max(size.width, layout.totalWidth * zoom),
          height: Math.max(size.height, layout.totalHeight * zoom),
        }}
      >
        <div
          className="rs-canvas-sticky"
          style={{ width: size.width, height: size.height }}
          title={withSimHint(
            hoverText(hoverElement, hoverProblems, hoverNetwork),
            simInputHint(simStore.getState(), hoverElement),
          )}
          {...handlers}
        >
          <div className="rs-world" ref={worldRef}>
            {theme && (
              <div className="rs-stage-window" style={{ left: win.left, top: win.top }}>
                <Stage width={stageWidth} height={stageHeight} listening={false}>
                  <Layer x={-win.left} y={-win.top} scaleX={zoom} scaleY={zoom} listening={false}>
                    {visible.map((i) => {
                      const n = networks[i]!;
                      return (
                        <NetworkShape
                          key={n.id}
                          network={n}
                          index={i}
                          top={layout.tops[i]!}
                          theme={theme}
                          selected={EMPTY_SET}
                          cursor={undefined}
                          partners={hover?.index === i && hoverOnConnection ? hover.cell : undefined}
                          markers={markers.get(i)?.markers ?? NO_MARKERS}
                          drag={dragPaints.get(n.id)}
                          zoom={zoom}
                          library={library}
                          pitch={pitchOf(layout, i)}
                          rows={rowsOf(layout, i)}
                          symbols={symbols}
                        />
                      );
                    })}
                  </Layer>
                </Stage>
              </div>
            )}
            <div className="rs-headers" style={{ transform: `scale(${zoom})` }}>
              {visible.map((i) => {
                const n = networks[i]!;
                const m = markers.get(i);
                return (
                  <NetworkHeader
                    key={n.id}
                    network={n}
                    index={i}
                    count={networks.length}
                    top={layout.tops[i]!}
                    width={Math.max(layout.totalWidth, headerViewWidth(size.width, zoom))}
                    errors={m?.errors ?? 0}
                    warnings={m?.warnings ?? 0}
                    pitch={pitchOf(layout, i)}
                    rows={rowsOf(layout, i)}
                  />
                );
              })}
              {band && (
                <div
                  className="rs-band"
                  style={{
                    left: Math.min(band.from.x, band.to.x),
                    top: Math.min(band.from.y, band.to.y),
                    width: Math.abs(band.to.x - band.from.x),
                    height: Math.abs(band.to.y - band.from.y),
                  }}
                />
              )}
            </div>
            <SelectionMarks layout={layout} networks={networks} library={library} zoom={zoom} scrollRef={scrollRef} hover={hover} />
            <InlineEditor layout={layout} zoom={zoom} onDone={refocus} />
          </div>
          <BlockPicker onDone={refocus} />
          {networks.length === 0 && <CanvasEmpty />}
        </div>
      </div>
    </div>
  );
}

const NO_MARKERS: readonly CellMarker[] = [];

/** The `width` a network header takes to end 8 px short of the view's right edge (its left is RAIL_X - 20, it spans width - RAIL_X). */
const headerViewWidth = (viewWidth: number, zoom: number) => viewWidth / zoom + 12;

/** What each network shows of a drag: the faded originals and the ghost where they would land. */
function dragPaintsFor(drag: DragState | undefined): ReadonlyMap<NetworkId, NetworkPaint['drag']> {
  const out = new Map<NetworkId, NetworkPaint['drag']>();
  if (!drag) return out;
  if (!drag.into) return out.set(drag.network, drag);
  const { into } = drag;
  out.set(drag.network, { ids: drag.ids, dRow: 0, dCol: 0, blocked: into.blocked, ghost: [] });
  return out.set(into.network, {
    ids: EMPTY_SET,
    dRow: 0,
    dCol: 0,
    blocked: into.blocked,
    ghost: into.ghost,
  });
}
