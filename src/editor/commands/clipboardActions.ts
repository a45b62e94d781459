// Copy, cut and paste of elements, through the system clipboard as JSON text with the
// `rungsmith-clip` marker (src/store/clipboard.ts) and an in-page copy when the browser denies
// clipboard access.
import { findVariable } from '../../model/factory';
import type { Variable } from '../../model/project';
import { clipText, parseClip, type Clip } from '../../store/clipboard';
import { selectActivePou } from '../../store/documentStore';
import { copyElements } from '../../store/networkEdits';
import { ensureCursor, libraryOf, networkById, targets, type EditorContext } from './editorActions';
import { deleteSelectedNetworks, hasNetworkSelection, networkCopyText, pasteNetworksText } from './networkActions';
import { parseNetworkClip } from '../../store/networkUnits';

let inPage: string | undefined;
/**
 * Whether the system clipboard is known to hold the in-page copy. Until its asynchronous write
 * lands (or when the browser refuses it) the system clipboard still holds what was there before,
 * and a paste must take the user's latest copy, the in-page one.
 */
let inPageOnSystem = true;

/** True while the latest copy has not reached the system clipboard: paste takes the in-page copy. */
export const latestCopyInPageOnly = (): boolean => inPage !== undefined && !inPageOnSystem;

/** The clip text of the selected networks, else of the current targets; undefined when nothing is selected. */
export function copyText(ctx: EditorContext): string | undefined {
  if (hasNetworkSelection(ctx)) return networkCopyText(ctx);
  const t = targets(ctx);
  const n = t && networkById(ctx, t.network);
  const content = n && copyElements(n, t.ids, libraryOf(ctx));
  if (!content) return undefined;
  const doc = ctx.doc.getState();
  const pou = selectActivePou(doc);
  const names = new Set<string>();
  for (const el of content.elements) {
    if (el.kind === 'contact' || el.kind === 'coil') names.add(el.variable.split('.')[0]!);
    if (el.kind === 'box') {
      if (el.instance) names.add(el.instance);
      for (const v of [...Object.values(el.inputs), ...Object.values(el.outputs)])
        names.add(v.split('.')[0]!);
    }
  }
  const variables: Variable[] = [];
  for (const name of names) {
    const v = pou && name && findVariable(doc.project, pou, name);
    if (v && pou?.variables.includes(v)) variables.push(v);
  }
  return clipText(content, variables);
}

/** Copies the targets; `systemClipboard` writes the text there too when the browser allows. */
export function copy(ctx: EditorContext, systemClipboard = true): string | undefined {
  const text = copyText(ctx);
  if (!text) {
    ctx.ui.getState().setStatus('Select elements to copy.');
    return undefined;
  }
  inPage = text;
  inPageOnSystem = false;
  if (systemClipboard)
    navigator.clipboard
      ?.writeText(text)
      .then(() => {
        if (inPage === text) inPageOnSystem = true;
      })
      .catch(() => undefined);
  ctx.ui.getState().setStatus('Copied.');
  return text;
}

export function cut(ctx: EditorContext, systemClipboard = true): string | undefined {
  if (hasNetworkSelection(ctx)) {
    const text = copy(ctx, systemClipboard);
    if (text) deleteSelectedNetworks(ctx);
    return text;
  }
  const t = targets(ctx);
  const text = copy(ctx, systemClipboard);
  if (!text || !t) return undefined;
  ctx.doc.getState().deleteElements(t.network, t.ids);
  ctx.ui.getState().select(t.network, []);
  return text;
}

/** Pastes clip text: whole networks (networkActions.ts), or elements at the cursor (declaring the copied variables that this POU lacks) as one undo step. */
export function pasteText(ctx: EditorContext, text: string | undefined): boolean {
  if (text && pasteNetworksText(ctx, text)) return true;
  const clip: Clip | undefined = text ? parseClip(text) : undefined;
  if (!clip) {
    ctx.ui.getState().setStatus('The clipboard holds no ladder elements.');
    return false;
  }
  const c = ensureCursor(ctx);
  const doc = ctx.doc.getState();
  const ids = doc.batch('paste', () => {
    const pou = selectActivePou(ctx.doc.getState());
    for (const v of clip.variables)
      if (pou && !findVariable(ctx.doc.getState().project, pou, v.name)) doc.addVariable(v);
    return doc.pasteElements(c.network, clip, { row: c.row, col: c.col });
  });
  ctx.ui.getState().select(c.network, ids);
  ctx.ui.getState().setStatus(`Pasted ${ids.length} element${ids.length === 1 ? '' : 's'}.`);
  return true;
}

/** Paste from the in-page copy (the keyboard path when no paste event brought text). */
export const pasteInPage = (ctx: EditorContext) => pasteText(ctx, inPage);

/** Paste for menus: the system clipboard when readable, else the in-page copy. */
export async function pasteFromSystem(ctx: EditorContext): Promise<void> {
  let text: string | undefined;
  try {
    text = await navigator.clipboard.readText();
  } catch {
    text = undefined;
  }
  pasteText(ctx, !latestCopyInPageOnly() && text && (parseClip(text) || parseNetworkClip(text)) ? text : inPage);
}
