// The status bar: last message, where the simulation's execution stands, where the cursor is, what
// is wrong there, the zoom.
import { useMemo } from 'react';
import { selectActivePou, selectNetworks, useDocument } from '../../store/documentStore';
import { selectCursor, useUi, useUiStore } from '../../store/uiStore';
import { useDiagnosticsByNetwork } from '../problems/useDiagnostics';
import { SimInputHint } from '../sim/SimInputHint';
import { SimPosition } from '../sim/SimPosition';

export function StatusBar() {
  const ui = useUiStore();
  const status = useUi((s) => s.status);
  const cursor = useUi(selectCursor);
  const zoom = useUi((s) => s.viewport.zoom);
  const tool = useUi((s) => s.tool);
  const networks = useDocument(selectNetworks);
  const pou = useDocument(selectActivePou);
  // The active POU's diagnostics by network: a cursor move looks at its network's only.
  const byNetwork = useDiagnosticsByNetwork(pou?.name);
  const index = cursor ? networks.findIndex((n) => n.id === cursor.network) : -1;
  const here = useMemo(() => {
    if (!cursor || index < 0 || !pou) return undefined;
    const n = networks[index]!;
    return byNetwork.get(index)?.find((d) => {
      if (d.cell) return d.cell.row === cursor.row && d.cell.col === cursor.col;
      const el = d.elementId ? n.elements.find((e) => e.id === d.elementId) : undefined;
      return el ? el.row === cursor.row && el.col === cursor.col : false;
    });
  }, [cursor, index, pou, networks, byNetwork]);

  return (
    <footer className="rs-statusbar" data-testid="status-bar">
      <span role="status" aria-live="polite" className="rs-status-message">
        {status ||
          (tool.kind === 'place'
            ? 'Click a cell to place — Esc to stop'
            : tool.kind === 'vlink'
              ? 'Click a cell edge between two rows — Esc to stop'
              : '')}
      </span>
      {here && (
        <span className={`rs-status-problem rs-${here.severity}`}>
          {here.rule}: {here.message}
        </span>
      )}
      <SimPosition />
      <SimInputHint />
      <span className="rs-spacer" />
      {cursor && index >= 0 && (
        <span data-testid="cursor-position">
          Network {index + 1}, row {cursor.row + 1}, column {cursor.col + 1}
        </span>
      )}
      <button
        type="button"
        className="rs-zoom"
        title="Actual size (Ctrl+0)"
        onClick={() => ui.getState().setZoom(1)}
      >
        {Math.round(zoom * 100)}%
      </button>
    </footer>
  );
}
