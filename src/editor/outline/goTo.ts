// Going to a network: by number (Ctrl+G), by label, or to a network of another POU (outline,
// find results, cross-reference). A collapsed network opens when the view goes into it. Also:
// from a connector or continuation to its partner, and to the network execution stands at.
import type { Cell } from '../../model/grid';
import type { ElementId, NetworkId, PouId } from '../../model/ids';
import type { LdElement } from '../../model/elements';
import type { Network } from '../../model/project';
import { isConnection, partnersOf } from '../../store/connectors';
import { elementAt } from '../../store/networkEdits';
import { canvasLayoutFor } from '../canvas/canvasLayout';
import { headerHeight, pitchOf } from '../canvas/geometry';
import type { EditorContext } from '../commands/editorActions';
import { libraryOf, networksOf } from '../commands/editorActions';

/** Shows the POU, scrolls to the cell of the network and puts the cursor there. */
export function revealNetwork(ctx: EditorContext, pou: PouId, network: NetworkId, cell: Cell = { row: 0, col: 0 }) {
  const doc = ctx.doc.getState();
  if (doc.activePouId !== pou) doc.setActivePou(pou);
  ctx.ui.getState().focusCell(network, cell);
}

/**
 * Goes to network `text` (1-based number or label) of the shown POU and selects it; returns a
 * problem to show, or ''. With `extend` (Ctrl+Shift+G) the selection runs from its anchor (the last
 * network selected, else the cursor's network) to the network entered, as a Shift+click does.
 */
export function goToNetwork(ctx: EditorContext, text: string, extend = false): string {
  const nets = networksOf(ctx);
  const t = text.trim();
  if (!t) return 'Type a network number or label.';
  const byLabel = nets.find((n) => n.label && n.label.toUpperCase() === t.toUpperCase());
  const no = /^\d+$/.test(t) ? Number(t) : NaN;
  const target = byLabel ?? (no >= 1 && no <= nets.length ? nets[no - 1] : undefined);
  if (!target) return `No network ${t}: this POU has networks 1 to ${nets.length}.`;
  const pou = ctx.doc.getState().activePouId;
  const ui = ctx.ui.getState();
  const ids = nets.map((n) => n.id);
  const selected = ui.networkSelection.filter((id) => ids.includes(id));
  const anchor = extend ? (selected[selected.length - 1] ?? ui.cursor?.network) : undefined;
  revealNetwork(ctx, pou, target.id);
  if (!anchor || !ids.includes(anchor)) {
    ctx.ui.getState().selectNetworks([target.id]);
    return '';
  }
  const a = ids.indexOf(anchor);
  const b = ids.indexOf(target.id);
  const range = ids.slice(Math.min(a, b), Math.max(a, b) + 1);
  // The anchor stays last: the next extension starts from it again.
  ctx.ui.getState().selectNetworks([...range.filter((id) => id !== anchor), anchor]);
  return '';
}

/** Element `id`, else the one selected alone, else the one at the cursor, with its network. */
function elementInFocus(ctx: EditorContext, id?: ElementId): { network: Network; el: LdElement } | undefined {
  const ui = ctx.ui.getState();
  const nets = networksOf(ctx);
  const wanted = id ?? (ui.selection.elements.length === 1 ? ui.selection.elements[0] : undefined);
  if (wanted) {
    for (const network of nets) {
      const el = network.elements.find((e) => e.id === wanted);
      if (el) return { network, el };
    }
    return undefined;
  }
  const network = ui.cursor && nets.find((n) => n.id === ui.cursor!.network);
  const el = network && elementAt(network, ui.cursor!, libraryOf(ctx));
  return network && el ? { network, el } : undefined;
}

/**
 * Goes from a connector to its first continuation, or from a continuation to its connector
 * (element `id`, else the selected one, else the one at the cursor), selecting it. Returns a
 * problem to show, or ''.
 */
export function goToPartner(ctx: EditorContext, id?: ElementId): string {
  const found = elementInFocus(ctx, id);
  if (!found || !isConnection(found.el)) return 'Select a connector or continuation to go to its partner.';
  const { network, el } = found;
  const target = partnersOf(network, el)[0];
  if (!target)
    return el.kind === 'connector'
      ? `The connector >${el.name}> has no continuation in this network (LD-R14).`
      : `The continuation >${el.name}> has no connector in this network (LD-R14).`;
  goToElement(ctx, network.id, target);
  return '';
}

/** Scrolls to an element of the shown POU and selects it (the cursor goes there). */
export function goToElement(ctx: EditorContext, network: NetworkId, el: Pick<LdElement, 'id' | 'row' | 'col'>) {
  revealNetwork(ctx, ctx.doc.getState().activePouId, network, { row: el.row, col: el.col });
  ctx.ui.getState().select(network, [el.id]);
}

/** The canvas's scroll area, when it is on the page. */
const canvasElement = (): HTMLElement | null =>
  typeof document === 'undefined' ? null : document.querySelector<HTMLElement>('[data-testid="ladder-canvas"]');

/** Room kept above a network scrolled into view, screen pixels. */
const REVEAL_MARGIN = 24;

/**
 * Scrolls the canvas so network `index` of the shown POU is on screen (its header and first row),
 * unless it already is: following execution while stepping must not make the view jump. Only the
 * view moves: cursor, selection and the document stay as they are (a collapsed network stays
 * collapsed). Returns whether it scrolled.
 */
export function scrollNetworkIntoView(ctx: EditorContext, index: number): boolean {
  const nets = networksOf(ctx);
  const network = nets[index];
  const el = canvasElement();
  if (!network || !el) return false;
  const zoom = ctx.ui.getState().viewport.zoom;
  const layout = canvasLayoutFor(ctx.doc.getState(), ctx.ui.getState());
  const top = layout.tops[index]!;
  const firstRow = headerHeight(network) + (network.collapsed ? 0 : pitchOf(layout, index));
  const from = top * zoom;
  const to = (top + firstRow) * zoom;
  if (from >= el.scrollTop && to <= el.scrollTop + el.clientHeight) return false;
  el.scrollTop = Math.max(0, from - REVEAL_MARGIN);
  return true;
}
