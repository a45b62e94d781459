// Going to a network: by number (Ctrl+G), by label, or to a network of another POU (outline,
// find results, cross-reference). A collapsed network opens when the view goes into it.
import type { Cell } from '../../model/grid';
import type { NetworkId, PouId } from '../../model/ids';
import type { EditorContext } from '../commands/editorActions';
import { networksOf } from '../commands/editorActions';

/** Shows the POU, scrolls to the cell of the network and puts the cursor there. */
export function revealNetwork(ctx: EditorContext, pou: PouId, network: NetworkId, cell: Cell = { row: 0, col: 0 }) {
  const doc = ctx.doc.getState();
  if (doc.activePouId !== pou) doc.setActivePou(pou);
  ctx.ui.getState().focusCell(network, cell);
}

/** Goes to network `text` (1-based number or label) of the shown POU; returns a problem to show, or ''. */
export function goToNetwork(ctx: EditorContext, text: string): string {
  const nets = networksOf(ctx);
  const t = text.trim();
  if (!t) return 'Type a network number or label.';
  const byLabel = nets.find((n) => n.label && n.label.toUpperCase() === t.toUpperCase());
  const no = /^\d+$/.test(t) ? Number(t) : NaN;
  const target = byLabel ?? (no >= 1 && no <= nets.length ? nets[no - 1] : undefined);
  if (!target) return `No network ${t}: this POU has networks 1 to ${nets.length}.`;
  const pou = ctx.doc.getState().activePouId;
  revealNetwork(ctx, pou, target.id);
  ctx.ui.getState().selectNetworks([target.id]);
  return '';
}
