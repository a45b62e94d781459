// Shown when the POU has no network yet.
import { useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';

export function CanvasEmpty() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  return (
    <div className="rs-canvas-empty">
      <p>This program has no network yet.</p>
      <button
        type="button"
        className="rs-button rs-primary"
        onClick={() => {
          const id = doc.getState().addNetwork();
          ui.getState().focusCell(id, { row: 0, col: 0 });
        }}
      >
        Add a network
      </button>
    </div>
  );
}
