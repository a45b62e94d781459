// Go to definition (F12, Ctrl/Cmd+click) and rename (F2) in the ST editor. Rename opens a small
// prompt at the name; Enter renames the variable everywhere as one undo step (its declaration, this
// body and other ST bodies, LD operands and box pins: documentStore updateVariable), or says in the
// prompt why it cannot (the name taken, hiding a global, a keyword). Escape closes it.
import { StateEffect, StateField, type Extension } from '@codemirror/state';
import { EditorView, keymap, showTooltip, type Tooltip } from '@codemirror/view';
import { planStRename, stDefinition } from '../../../engine/st/services';
import { renameVariable } from '../../../store/renameVariable';
import { dataTypeTabs } from '../../dataTypes/dataTypeTabs';
import { focusVariable } from '../../variables/variableFocus';
import { commitStEdit, stModelLink } from '../stModelSync';

type Prompt =
  | { readonly kind: 'rename'; readonly pos: number; readonly name: string; readonly error?: string }
  | { readonly kind: 'note'; readonly pos: number; readonly text: string };

const setPrompt = StateEffect.define<Prompt | undefined>();

const promptField = StateField.define<Prompt | undefined>({
  create: () => undefined,
  update(value, tr) {
    for (const e of tr.effects) if (e.is(setPrompt)) return e.value;
    // A note goes with the next edit or cursor move; the rename prompt stays until answered.
    if (value?.kind === 'note' && (tr.docChanged || tr.selection)) return undefined;
    if (value && tr.docChanged) return { ...value, pos: tr.changes.mapPos(value.pos) };
    return value;
  },
  provide: (f) =>
    showTooltip.from(f, (p): Tooltip | null =>
      p ? { pos: p.pos, above: false, create: (view) => promptDom(view, p) } : null,
    ),
});

function promptDom(view: EditorView, p: Prompt): { dom: HTMLElement; mount?: () => void } {
  const dom = document.createElement('div');
  if (p.kind === 'note') {
    dom.className = 'rs-st-note-tip';
    dom.setAttribute('role', 'status');
    dom.setAttribute('data-testid', 'st-note');
    dom.textContent = p.text;
    return { dom };
  }
  dom.className = 'rs-st-rename';
  dom.setAttribute('data-testid', 'st-rename');
  const label = dom.appendChild(document.createElement('label'));
  label.textContent = `Rename ${p.name} to `;
  const input = label.appendChild(document.createElement('input'));
  input.value = p.name;
  input.spellcheck = false;
  input.setAttribute('aria-label', `New name for ${p.name}`);
  input.setAttribute('data-testid', 'st-rename-input');
  if (p.error) {
    const err = dom.appendChild(document.createElement('div'));
    err.className = 'rs-st-rename-error';
    err.setAttribute('role', 'alert');
    err.setAttribute('data-testid', 'st-rename-error');
    err.textContent = p.error;
  }
  const hint = dom.appendChild(document.createElement('div'));
  hint.className = 'rs-st-rename-hint';
  hint.textContent = 'Enter renames it everywhere (one undo step); Esc cancels.';
  input.addEventListener('keydown', (e) => {
    if (e.key === 'Escape') {
      e.preventDefault();
      view.dispatch({ effects: setPrompt.of(undefined) });
      view.focus();
    } else if (e.key === 'Enter') {
      e.preventDefault();
      applyRename(view, p.pos, input.value.trim(), p.name);
    }
    e.stopPropagation();
  });
  return {
    dom,
    mount: () => {
      input.focus();
      input.select();
    },
  };
}

function applyRename(view: EditorView, pos: number, to: string, from: string): void {
  const link = stModelLink(view.state);
  if (!link) return;
  // The model must hold the text as typed before the rename rewrites it.
  commitStEdit(view);
  const plan = planStRename(link.store.getState().project, link.pouId, view.state.doc.toString(), pos, to);
  if (!plan.ok) {
    view.dispatch({ effects: setPrompt.of({ kind: 'rename', pos, name: from, error: plan.reason }) });
    return;
  }
  const done = renameVariable(link.store, plan.from, plan.to, [plan.scope]);
  if (!done.ok) {
    view.dispatch({ effects: setPrompt.of({ kind: 'rename', pos, name: from, error: done.reason }) });
    return;
  }
  view.dispatch({ effects: setPrompt.of(undefined) });
  view.focus();
}

/** F2: the rename prompt for the name at the cursor. */
export function startRename(view: EditorView): boolean {
  const pos = view.state.selection.main.head;
  const word = view.state.wordAt(pos);
  if (!word) {
    view.dispatch({
      effects: setPrompt.of({ kind: 'note', pos, text: 'Put the cursor on a variable to rename it.' }),
    });
    return true;
  }
  view.dispatch({
    effects: setPrompt.of({ kind: 'rename', pos: word.from, name: view.state.sliceDoc(word.from, word.to) }),
  });
  return true;
}

/** F12 / Ctrl+click: shows where the name at the cursor is declared. */
export function goToDefinition(view: EditorView): boolean {
  const link = stModelLink(view.state);
  if (!link) return false;
  const pos = view.state.selection.main.head;
  const doc = link.store.getState();
  const def = stDefinition(doc.project, link.pouId, view.state.doc.toString(), pos);
  if (!def) {
    const word = view.state.wordAt(pos);
    const name = word ? view.state.sliceDoc(word.from, word.to) : '';
    view.dispatch({
      effects: setPrompt.of({
        kind: 'note',
        pos,
        text: name
          ? `${name}: no declaration in this project to go to (a standard block, or not declared).`
          : 'Put the cursor on a name to go to its declaration.',
      }),
    });
    return true;
  }
  switch (def.kind) {
    case 'variable':
      if (def.scope === 'globals') focusVariable(def.name, true);
      else {
        if (def.scope !== link.pouId) doc.setActivePou(def.scope);
        focusVariable(def.name, false);
      }
      return true;
    case 'pou':
      doc.setActivePou(def.pouId);
      return true;
    case 'dataType':
      dataTypeTabs(link.store).getState().openType(def.name);
      return true;
  }
}

export function stRename(): Extension {
  return [promptField, keymap.of([{ key: 'F2', run: startRename, preventDefault: true }])];
}
