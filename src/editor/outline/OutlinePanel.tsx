// The outline of the shown POU: one line per network (number, label, title); collapse all /
// expand all. A click goes to the network; Shift+click selects a range of networks, Ctrl+click
// adds or removes one (the same selection as the network headers'). Dragging a line moves its
// network, or all selected networks when it is one of them, in one undo step. The line of the
// network at the top of the canvas's view is marked and kept visible while the canvas scrolls.
import { memo, useEffect, useMemo, useRef, useState, type DragEvent } from 'react';
import type { NetworkId, PouId } from '../../model/ids';
import type { Network } from '../../model/project';
import { selectActivePouId, selectNetworks, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUi, useUiStore } from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import { clickNetwork } from '../commands/networkActions';
import { revealNetwork } from './goTo';
import './outline.css';

const DRAG_TYPE = 'application/x-rungsmith-outline';

interface ItemProps {
  readonly network: Network;
  readonly index: number;
  readonly pou: PouId;
  readonly ctx: EditorContext;
  readonly onDropAt: (from: number, to: number) => void;
}

const OutlineItem = memo(function OutlineItem({ network: n, index: i, pou, ctx, onDropAt }: ItemProps) {
  const current = useUi((s) => s.cursor?.network === n.id);
  const selected = useUi((s) => s.networkSelection.includes(n.id));
  const inView = useUi((s) => s.viewNetwork === n.id);
  const [drop, setDrop] = useState<'before' | 'after' | undefined>(undefined);
  const ref = useRef<HTMLButtonElement>(null);

  // Follow the canvas: the line of the network in view stays visible in the outline.
  useEffect(() => {
    if (inView) ref.current?.scrollIntoView({ block: 'nearest' });
  }, [inView]);

  const onDragOver = (e: DragEvent) => {
    if (!e.dataTransfer.types.includes(DRAG_TYPE)) return;
    e.preventDefault();
    e.dataTransfer.dropEffect = 'move';
    const r = e.currentTarget.getBoundingClientRect();
    setDrop(e.clientY < r.top + r.height / 2 ? 'before' : 'after');
  };
  const onDrop = (e: DragEvent) => {
    const from = Number(e.dataTransfer.getData(DRAG_TYPE));
    const where = drop;
    setDrop(undefined);
    if (!Number.isInteger(from) || !e.dataTransfer.types.includes(DRAG_TYPE)) return;
    e.preventDefault();
    onDropAt(from, where === 'after' ? i + 1 : i);
  };

  return (
    <li
      className={drop ? `rs-outline-drop-${drop}` : undefined}
      onDragOver={onDragOver}
      onDragLeave={() => setDrop(undefined)}
      onDrop={onDrop}
    >
      <button
        ref={ref}
        type="button"
        draggable
        data-testid={`outline-item-${i}`}
        aria-current={current}
        aria-pressed={selected}
        data-inview={inView || undefined}
        className={`${selected ? 'rs-outline-selected' : ''}${inView ? ' rs-outline-inview' : ''}`}
        title={`${n.comment ? `${n.comment}\n` : ''}Click: go to it · Shift+click: select a range · Ctrl+click: add or remove · drag: move`}
        onDragStart={(e) => {
          e.dataTransfer.setData(DRAG_TYPE, String(i));
          e.dataTransfer.effectAllowed = 'move';
        }}
        onClick={(e) => {
          const toggle = e.ctrlKey || e.metaKey;
          if (e.shiftKey || toggle) return clickNetwork(ctx, n.id, { shift: e.shiftKey, toggle });
          revealNetwork(ctx, pou, n.id);
          ctx.ui.getState().selectNetworks([n.id]);
        }}
      >
        {i + 1}.{n.label ? <span className="rs-outline-label"> {n.label}:</span> : null}{' '}
        {n.title || <em>untitled</em>}
        {n.collapsed ? ' ▸' : ''}
      </button>
    </li>
  );
});

export function OutlinePanel() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const networks = useDocument(selectNetworks);
  const pou = useDocument(selectActivePouId);

  // A line dropped at `to` (an index between lines): the dragged network moves there, or the whole
  // selection when the dragged one is selected (networkUnits' move: one undo step).
  const onDropAt = useMemo(
    () => (from: number, to: number) => {
      const nets = selectNetworks(doc.getState());
      const dragged = nets[from];
      if (!dragged) return;
      const sel = new Set(ui.getState().networkSelection);
      const ids: NetworkId[] = sel.has(dragged.id) ? nets.filter((x) => sel.has(x.id)).map((x) => x.id) : [dragged.id];
      doc.getState().moveNetworksTo(ids, to);
    },
    [doc, ui],
  );

  return (
    <nav className="rs-outline" aria-label="Outline of networks" data-testid="outline">
      <div className="rs-outline-tools">
        <button type="button" onClick={() => doc.getState().setCollapsed('all', true)}>
          Collapse all
        </button>
        <button type="button" onClick={() => doc.getState().setCollapsed('all', false)}>
          Expand all
        </button>
      </div>
      <ol>
        {networks.map((n, i) => (
          <OutlineItem key={n.id} network={n} index={i} pou={pou} ctx={ctx} onDropAt={onDropAt} />
        ))}
      </ol>
    </nav>
  );
}
