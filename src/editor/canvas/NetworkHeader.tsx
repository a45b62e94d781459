// The header above a network: number, label, title, comment, collapse toggle, reorder handle and
// buttons. Plain DOM over the canvas so every control is a real, accessible form element.
import { memo, useState, type DragEvent, type KeyboardEvent } from 'react';
import type { Network } from '../../model/project';
import { useDocumentStore } from '../../store/documentStore';
import { useUi, useUiStore } from '../../store/uiStore';
import { clickNetwork } from '../commands/networkActions';
import { useCommitField } from '../variables/CommitInput';
import {
  COMMENT_LINE_H,
  COMMENT_W,
  commentLines,
  HEADER_LEFT,
  headerHeight,
  headerNeed,
  RAIL_X,
  TITLE_W,
  titleFieldWidth,
} from './geometry';
import { NetworkSimMarker } from '../sim/NetworkSimMarker';
import '../outline/outline.css';

const DRAG_TYPE = 'application/x-rungsmith-network';
const LABEL_W = 100;

interface FieldProps {
  readonly value: string;
  readonly onCommit: (v: string) => void;
  readonly label: string;
  readonly testId: string;
  readonly placeholder: string;
  readonly className: string;
  readonly multiline?: number;
  /** The field's width and narrowest width (content pixels): a title is shown whole. */
  readonly width?: number;
  readonly minWidth?: number;
}

/**
 * A field that edits locally and commits once, on Enter or leaving it (a comment takes a new line
 * with Shift+Enter); Escape reverts. Enter and Escape give the keyboard back to the canvas.
 */
function CommitField({ value, onCommit, label, testId, placeholder, className, multiline, width, minWidth }: FieldProps) {
  const field = useCommitField<HTMLInputElement | HTMLTextAreaElement>(value, onCommit, {
    multiline: Boolean(multiline),
    leaveOnEnter: true,
  });
  const common = {
    ...field,
    'aria-label': label,
    'data-testid': testId,
    placeholder,
    className,
    spellCheck: false,
    onKeyDown: (e: KeyboardEvent<HTMLInputElement | HTMLTextAreaElement>) => {
      e.stopPropagation();
      field.onKeyDown(e);
    },
  };
  return multiline ? (
    <textarea {...common} rows={multiline} style={{ maxWidth: COMMENT_W, height: multiline * COMMENT_LINE_H + 4 }} />
  ) : (
    <input {...common} style={{ width, minWidth }} />
  );
}

export interface NetworkHeaderProps {
  readonly network: Network;
  readonly index: number;
  readonly count: number;
  readonly top: number;
  readonly width: number;
  readonly errors: number;
  readonly warnings: number;
  /** Height of the network's rows (geometry.rowPitch). */
  readonly pitch?: number;
  /** Rows the network shows (geometry.shownRows). */
  readonly rows?: number;
}

export const NetworkHeader = memo(function NetworkHeader({
  network: n,
  index,
  count,
  top,
  width,
  errors,
  warnings,
  pitch,
  rows,
}: NetworkHeaderProps) {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const [dropTarget, setDropTarget] = useState(false);
  const selected = useUi((s) => s.networkSelection.includes(n.id));
  const no = index + 1;
  const update = (patch: Parameters<ReturnType<typeof doc.getState>['updateNetwork']>[1]) =>
    doc.getState().updateNetwork(n.id, patch);

  // A drag carries the dragged network's index; when that network is selected, the whole
  // selection moves (before this network when coming from below, after it from above).
  const onDrop = (e: DragEvent) => {
    const from = Number(e.dataTransfer.getData(DRAG_TYPE));
    setDropTarget(false);
    if (!Number.isInteger(from) || from === index) return;
    e.preventDefault();
    const nets = doc.getState().project.pous.find((p) => p.networks.some((x) => x.id === n.id))?.networks;
    const dragged = nets?.[from];
    const sel = ui.getState().networkSelection;
    if (!nets || !dragged || !sel.includes(dragged.id)) return doc.getState().moveNetwork(from, index);
    const ids = nets.filter((x) => sel.includes(x.id)).map((x) => x.id);
    doc.getState().moveNetworksTo(ids, from < index ? index + 1 : index);
  };

  return (
    <div
      className={`rs-network-header${dropTarget ? ' rs-drop-target' : ''}${selected ? ' rs-network-selected' : ''}`}
      data-selected={selected || undefined}
      style={{
        top,
        left: HEADER_LEFT,
        width: Math.max(headerNeed(n), width - RAIL_X),
        height: headerHeight(n) - (n.collapsed ? 1 : 4),
      }}
      title={n.collapsed && n.comment ? n.comment : undefined}
      data-collapsed={n.collapsed || undefined}
      role="group"
      aria-label={`Network ${no}${n.label ? ` (${n.label})` : ''}`}
      data-testid={`network-header-${index}`}
      onDragOver={(e) => {
        if (!e.dataTransfer.types.includes(DRAG_TYPE)) return;
        e.preventDefault();
        setDropTarget(true);
      }}
      onDragLeave={() => setDropTarget(false)}
      onDrop={onDrop}
    >
      <div className="rs-network-titlebar">
        <span
          className="rs-drag-handle"
          draggable
          role="button"
          tabIndex={-1}
          aria-label={`Drag to reorder network ${no}`}
          title="Drag to reorder"
          onDragStart={(e) => {
            e.dataTransfer.setData(DRAG_TYPE, String(index));
            e.dataTransfer.effectAllowed = 'move';
          }}
        >
          ⠿
        </span>
        <NetworkSimMarker network={n} index={index} {...(pitch ? { pitch } : {})} {...(rows ? { rows } : {})} />
        <button
          type="button"
          className="rs-icon-button"
          aria-expanded={!n.collapsed}
          aria-label={`${n.collapsed ? 'Expand' : 'Collapse'} network ${no}`}
          title={n.collapsed ? 'Expand' : 'Collapse'}
          onClick={() => update({ collapsed: !n.collapsed })}
        >
          {n.collapsed ? '▸' : '▾'}
        </button>
        <button
          type="button"
          className="rs-network-number"
          data-testid={`network-number-${n.id}`}
          aria-pressed={selected}
          title="Select this network (Shift: a range, Ctrl: add or remove); copy, cut, paste, duplicate, delete and Alt+↑/↓ then act on whole networks"
          onClick={(e) => {
            const toggle = e.ctrlKey || e.metaKey;
            if (!e.shiftKey && !toggle && !n.collapsed) ui.getState().setCursor({ network: n.id, row: 0, col: 0 });
            clickNetwork({ doc, ui }, n.id, { shift: e.shiftKey, toggle });
          }}
        >
          Network {no}
        </button>
        <CommitField
          value={n.label ?? ''}
          onCommit={(label) => update({ label: label.trim() })}
          label={`Label of network ${no}`}
          testId={`network-label-${n.id}`}
          placeholder="label"
          className="rs-network-label rs-mono"
          width={LABEL_W}
        />
        <CommitField
          value={n.title}
          onCommit={(title) => update({ title })}
          label={`Title of network ${no}`}
          testId={`network-title-${n.id}`}
          placeholder="Title"
          className="rs-network-title"
          width={Math.max(TITLE_W, titleFieldWidth(n))}
          minWidth={titleFieldWidth(n)}
        />
        {errors + warnings > 0 && (
          <span
            className={errors ? 'rs-badge rs-badge-error' : 'rs-badge rs-badge-warning'}
            title="Problems in this network"
          >
            {errors > 0
              ? `${errors} error${errors > 1 ? 's' : ''}`
              : `${warnings} warning${warnings > 1 ? 's' : ''}`}
          </span>
        )}
        <span className="rs-spacer" />
        <button
          type="button"
          className="rs-icon-button"
          aria-label={`Move network ${no} up`}
          title="Move up"
          disabled={index === 0}
          onClick={() => doc.getState().moveNetwork(index, index - 1)}
        >
          ↑
        </button>
        <button
          type="button"
          className="rs-icon-button"
          aria-label={`Move network ${no} down`}
          title="Move down"
          disabled={index === count - 1}
          onClick={() => doc.getState().moveNetwork(index, index + 1)}
        >
          ↓
        </button>
        <button
          type="button"
          className="rs-icon-button"
          aria-label={`Insert network after network ${no}`}
          title="Insert a network below"
          onClick={() => {
            const id = doc.getState().insertNetwork(index + 1);
            ui.getState().focusCell(id, { row: 0, col: 0 });
          }}
        >
          +
        </button>
        <button
          type="button"
          className="rs-icon-button rs-danger"
          aria-label={`Delete network ${no}`}
          title="Delete network (undo brings it back)"
          onClick={() => doc.getState().deleteNetwork(n.id)}
        >
          ✕
        </button>
      </div>
      {/* A collapsed network is its title bar alone (its comment shows as the header's tooltip). */}
      {!n.collapsed && (
        <CommitField
          value={n.comment}
          onCommit={(comment) => update({ comment })}
          label={`Comment of network ${no}`}
          testId={`network-comment-${n.id}`}
          placeholder="Comment"
          className="rs-network-comment"
          multiline={commentLines(n)}
        />
      )}
    </div>
  );
});
