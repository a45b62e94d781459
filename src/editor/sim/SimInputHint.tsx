// The status line's word on the selected input contact while simulating: a click only selected it;
// double-click switches the input, Alt+press holds it (useCanvasSimInput).
import { useCallback } from 'react';
import type { SimState } from '../../store/simState';
import { selectNetworks, useDocument } from '../../store/documentStore';
import { selectSelection, useUi } from '../../store/uiStore';
import { useSim } from './simContext';
import { simInputHint } from './useCanvasSimInput';

export function SimInputHint() {
  const selection = useUi(selectSelection);
  const networks = useDocument(selectNetworks);
  const el =
    selection.elements.length === 1
      ? networks.find((n) => n.id === selection.network)?.elements.find((e) => e.id === selection.elements[0])
      : undefined;
  // A string: the status line re-renders when the hint changes, not every scan.
  const hint = useSim(useCallback((s: SimState) => simInputHint(s, el), [el]));
  return hint ? (
    <span className="rs-sim-input-hint" data-testid="sim-input-hint">
      {hint}
    </span>
  ) : null;
}
