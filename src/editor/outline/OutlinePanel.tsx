// The outline of the shown POU: one line per network (number, label, title), click to go there;
// collapse all / expand all.
import { useMemo } from 'react';
import { selectActivePouId, selectNetworks, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUi, useUiStore } from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import { revealNetwork } from './goTo';
import './outline.css';

export function OutlinePanel() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const networks = useDocument(selectNetworks);
  const pou = useDocument(selectActivePouId);
  const current = useUi((s) => s.cursor?.network);
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
          <li key={n.id}>
            <button
              type="button"
              data-testid={`outline-item-${i}`}
              aria-current={current === n.id}
              title={n.comment || undefined}
              onClick={() => {
                revealNetwork(ctx, pou, n.id);
                ui.getState().selectNetworks([n.id]);
              }}
            >
              {i + 1}.{n.label ? <span className="rs-outline-label"> {n.label}:</span> : null}{' '}
              {n.title || <em>untitled</em>}
              {n.collapsed ? ' ▸' : ''}
            </button>
          </li>
        ))}
      </ol>
    </nav>
  );
}
