// The top bar's switch for the "Show symbol comments" view option (also View > Show symbol
// comments): variables' comments under contacts, coils and box operands, on the canvas and in print.
import { useUi, useUiStore } from '../../store/uiStore';

export function SymbolCommentsToggle() {
  const ui = useUiStore();
  const on = useUi((s) => s.symbolComments);
  return (
    <button
      type="button"
      className="rs-icon-button"
      aria-pressed={on}
      aria-label="Show symbol comments under operands"
      title={`${on ? 'Hide' : 'Show'} the variables' comments under contacts, coils and box operands`}
      data-testid="symbol-comments-toggle"
      onClick={() => ui.getState().setSymbolComments(!on)}
    >
      ❞
    </button>
  );
}
