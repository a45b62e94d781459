// Add to Watch from the canvas in one gesture (issue 24): `W` on the cursor's element (or the
// selected elements) while editing or simulating. A contact or coil adds its variable; a function
// block its instance (watched as a tree of its pins); a function the variables written beside its
// pins. Names are read in the monitored body (`Motor1.Run` inside the picked instance Motor1).
import type { LdElement } from '../../model/elements';
import type { BlockLibrary } from '../../model/library';
import { parseLiteral } from '../../engine/values/literals';
import { selectLibrary } from '../../store/documentStore';
import { elementAt } from '../../store/networkEdits';
import type { SimState } from '../../store/simState';
import type { EditorContext } from '../commands/editorActions';
import { networksOf } from '../commands/editorActions';
import { canvasName } from './liveValues';
import { getAppSimStore } from './simContext';

/** A variable name, not a literal (`T#5s`, `42`, `TRUE`). */
const isName = (text: string): boolean => /^[%A-Za-z_]/.test(text.trim()) && !parseLiteral(text).ok;

/** The names `el` puts on the watch list, in the monitored body's spelling. */
export function watchNamesOf(s: SimState, el: LdElement, library: BlockLibrary): string[] {
  const scoped = (operand: string) => canvasName(s, operand.trim()) ?? operand.trim();
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return el.variable.trim() ? [scoped(el.variable)] : [];
    case 'box': {
      if (library.signature(el.blockType)?.kind === 'fb' && el.instance?.trim()) return [scoped(el.instance)];
      const operands = [...Object.values(el.inputs), ...Object.values(el.outputs)].filter((o) => o.trim() && isName(o));
      return [...new Set(operands.map(scoped))];
    }
    default:
      return [];
  }
}

/** Shows the Watch tab of the bottom panels. */
export function showWatchTab(): void {
  document.getElementById('rs-tab-watch')?.click();
}

/** `W`: the selected elements' (else the cursor element's) names added to the watch list; says what it did. */
export function addToWatchAtCursor(ctx: EditorContext): void {
  const ui = ctx.ui.getState();
  const library = selectLibrary(ctx.doc.getState());
  const networks = networksOf(ctx);
  const selected = new Set<string>(ui.selection.elements);
  const elements: LdElement[] = [];
  if (selected.size > 0) for (const n of networks) for (const el of n.elements) if (selected.has(el.id)) elements.push(el);
  if (elements.length === 0 && ui.cursor) {
    const n = networks.find((x) => x.id === ui.cursor!.network);
    const el = n ? elementAt(n, { row: ui.cursor.row, col: ui.cursor.col }, library) : undefined;
    if (el) elements.push(el);
  }
  const sim = getAppSimStore();
  const names = [...new Set(elements.flatMap((el) => watchNamesOf(sim.getState(), el, library)))];
  if (names.length === 0) {
    ui.setStatus('Nothing to watch here: put the cursor on a contact, coil or block with a variable');
    return;
  }
  for (const name of names) sim.getState().addWatch(name);
  showWatchTab();
  ui.setStatus(`Watching ${names.join(', ')}`);
}
