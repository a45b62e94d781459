// Whole networks as units in the editor: selecting them by their headers, copy/cut/paste through
// the system clipboard (the `rungsmith-networks` JSON text, src/store/networkUnits.ts), duplicate,
// delete and move. Pasting calls of FB instances the target already declares asks first: keep
// the instances or create new ones (the paste prompt, src/editor/outline/PastePrompt.tsx).
import type { NetworkId } from '../../model/ids';
import { selectActivePou } from '../../store/documentStore';
import {
  clipInstances,
  copyNetworks,
  networkClipText,
  parseNetworkClip,
  type InstanceMode,
} from '../../store/networkUnits';
import { findVariable } from '../../model/factory';
import { networksOf, type EditorContext } from './editorActions';

/** The selected networks, in the POU's order. */
export function selectedNetworks(ctx: EditorContext): NetworkId[] {
  const sel = new Set(ctx.ui.getState().networkSelection);
  return networksOf(ctx)
    .filter((n) => sel.has(n.id))
    .map((n) => n.id);
}

export const hasNetworkSelection = (ctx: EditorContext) => selectedNetworks(ctx).length > 0;

/** A click on a network's header: alone, Shift extends from the last selected, Ctrl toggles. */
export function clickNetwork(ctx: EditorContext, id: NetworkId, mods: { shift: boolean; toggle: boolean }) {
  const ui = ctx.ui.getState();
  const ids = networksOf(ctx).map((n) => n.id);
  const current = ui.networkSelection.filter((x) => ids.includes(x));
  if (mods.toggle)
    return ui.selectNetworks(current.includes(id) ? current.filter((x) => x !== id) : [...current, id]);
  const anchor = current[current.length - 1];
  if (mods.shift && anchor) {
    const a = ids.indexOf(anchor);
    const b = ids.indexOf(id);
    const range = ids.slice(Math.min(a, b), Math.max(a, b) + 1);
    // The anchor stays last so the next Shift-click extends from it.
    return ui.selectNetworks([...range.filter((x) => x !== anchor), anchor]);
  }
  ui.selectNetworks([id]);
}

/** Shift+Up/Down with networks selected: grows (or shrinks) the selection from its anchor. */
export function extendNetworkSelection(ctx: EditorContext, delta: number) {
  const ui = ctx.ui.getState();
  const ids = networksOf(ctx).map((n) => n.id);
  const sel = ui.networkSelection.filter((x) => ids.includes(x));
  if (sel.length === 0) return;
  const anchor = sel[sel.length - 1]!;
  const indices = sel.map((x) => ids.indexOf(x));
  const a = ids.indexOf(anchor);
  const lo = Math.min(...indices);
  const hi = Math.max(...indices);
  // The moving end is the one away from the anchor.
  const moving = hi === a ? lo : hi;
  const end = Math.max(0, Math.min(ids.length - 1, moving + delta));
  const range = ids.slice(Math.min(a, end), Math.max(a, end) + 1);
  ui.selectNetworks([...range.filter((x) => x !== anchor), anchor]);
  document.querySelector<HTMLElement>(`[data-testid="network-number-${ids[end]}"]`)?.focus();
}

/** Clip text of the selected networks, or undefined when none is selected. */
export function networkCopyText(ctx: EditorContext): string | undefined {
  const pou = selectActivePou(ctx.doc.getState());
  const clip = pou && copyNetworks(pou, selectedNetworks(ctx));
  return clip && networkClipText(clip);
}

/** Instances in the clip text that the shown POU already declares (a paste must ask about them). */
export function clashingInstances(ctx: EditorContext, text: string): string[] {
  const clip = parseNetworkClip(text);
  const doc = ctx.doc.getState();
  const pou = selectActivePou(doc);
  if (!clip || !pou) return [];
  return clipInstances(clip).filter((name) => findVariable(doc.project, pou, name));
}

/** Where pasted networks go: after the last selected network, else after the cursor's, else at the end. */
function pasteIndex(ctx: EditorContext): number {
  const nets = networksOf(ctx);
  const sel = selectedNetworks(ctx);
  const ui = ctx.ui.getState();
  const at = sel.length ? sel[sel.length - 1] : (ui.cursor?.network ?? ui.selection.network);
  const i = nets.findIndex((n) => n.id === at);
  return i >= 0 ? i + 1 : nets.length;
}

/** Pastes network clip text; when it calls instances this POU has, asks keep/new first. */
export function pasteNetworksText(ctx: EditorContext, text: string, mode?: InstanceMode): boolean {
  const clip = parseNetworkClip(text);
  const doc = ctx.doc.getState();
  const pou = selectActivePou(doc);
  if (!clip || !pou) return false;
  const ui = ctx.ui.getState();
  if (!mode) {
    const instances = clashingInstances(ctx, text);
    if (instances.length) {
      ui.setPastePrompt({ text, instances });
      return true;
    }
  }
  const ids = doc.pasteNetworks(pou.id, pasteIndex(ctx), clip, mode ?? 'new');
  ui.setPastePrompt(undefined);
  ui.selectNetworks(ids);
  ui.setStatus(`Pasted ${ids.length} network${ids.length === 1 ? '' : 's'}.`);
  if (ids[0]) ui.focusCell(ids[0], { row: 0, col: 0 });
  ui.selectNetworks(ids);
  return true;
}

export function deleteSelectedNetworks(ctx: EditorContext) {
  const ids = selectedNetworks(ctx);
  if (!ids.length) return;
  const nets = networksOf(ctx);
  const first = nets.findIndex((n) => n.id === ids[0]);
  ctx.doc.getState().deleteNetworks(ids);
  const rest = networksOf(ctx);
  const next = rest[Math.min(first, rest.length - 1)];
  const ui = ctx.ui.getState();
  ui.clearSelection();
  ui.setCursor(next ? { network: next.id, row: 0, col: 0 } : undefined);
  if (next) ui.selectNetworks([next.id]);
  ui.setStatus(`Deleted ${ids.length} network${ids.length === 1 ? '' : 's'} (undo brings them back).`);
}

/** Ctrl+D with networks selected: copies below them with new instances; the copies become the selection. */
export function duplicateSelectedNetworks(ctx: EditorContext) {
  const ids = ctx.doc.getState().duplicateNetworks(selectedNetworks(ctx), 'new');
  if (ids.length) ctx.ui.getState().selectNetworks(ids);
}

export function moveSelectedNetworks(ctx: EditorContext, delta: number) {
  if (!ctx.doc.getState().moveNetworks(selectedNetworks(ctx), delta))
    ctx.ui.getState().setStatus(delta < 0 ? 'Already at the top.' : 'Already at the bottom.');
}

/** Every network of the shown POU (Ctrl+A with networks selected). */
export function selectAllNetworks(ctx: EditorContext) {
  ctx.ui.getState().selectNetworks(networksOf(ctx).map((n) => n.id));
}

