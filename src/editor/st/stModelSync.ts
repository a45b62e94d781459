// The ST editor's link to the document: what is typed goes to the model as ONE named undo step per
// typing burst ("Edit ST body of Scale"), and the model's changes from elsewhere (undo, redo, a
// rename, an import) come into the editor as transactions, merged with a burst not yet committed.
//
// A burst ends (and is committed) after a pause in typing, when the cursor jumps to another line
// or is placed with the pointer, when the editor loses the focus, before the project's undo/redo,
// and when the editor closes. CodeMirror's own history is not used: Ctrl+Z / Ctrl+Y /
// Ctrl+Shift+Z in the editor are the project's undo and redo, so they behave as everywhere else.
import { Annotation, ChangeSet, EditorSelection, Facet, Prec, type EditorState, type Extension } from '@codemirror/state';
import { EditorView, keymap, ViewPlugin, type ViewUpdate } from '@codemirror/view';
import type { PouId } from '../../model/ids';
import type { DocumentStore } from '../../store/documentStore';

/** Marks the transactions that bring the model's text into the editor (not user edits). */
export const fromModel = Annotation.define<boolean>();

/** Typing pause after which a burst is committed (ms). */
export const ST_BURST_PAUSE_MS = 700;

/** The undo step name of a committed burst. */
export const stEditStepName = (pouName: string): string => `Edit ST body of ${pouName}`;

/** The change turning `a` into `b`: the part between their common start and common end. */
export function textDiff(a: string, b: string): ChangeSet {
  const max = Math.min(a.length, b.length);
  let start = 0;
  while (start < max && a.charCodeAt(start) === b.charCodeAt(start)) start++;
  let end = 0;
  while (end < max - start && a.charCodeAt(a.length - 1 - end) === b.charCodeAt(b.length - 1 - end)) end++;
  return ChangeSet.of(
    a === b ? [] : [{ from: start, to: a.length - end, insert: b.slice(start, b.length - end) }],
    a.length,
  );
}

class ModelSync {
  /** The model text the editor last agreed with. */
  private base: string;
  /** The edits typed since `base` (not committed yet): base -> editor text. */
  private local: ChangeSet;
  private timer: ReturnType<typeof setTimeout> | undefined;
  /** Line of the last edit of the burst (a cursor move off it ends the burst). */
  private editLine = 0;
  private readonly unsubscribe: () => void;
  /** The project the burst belongs to (DocumentState.opened): a burst never goes into another one. */
  private opened: number;

  constructor(
    private readonly view: EditorView,
    private readonly store: DocumentStore,
    private readonly pouId: PouId,
  ) {
    this.base = view.state.doc.toString();
    this.local = ChangeSet.empty(this.base.length);
    this.opened = store.getState().opened;
    this.unsubscribe = store.subscribe((s, prev) => {
      if (s.project === prev.project) return;
      const next = s.project.pous.find((p) => p.id === pouId)?.source;
      if (s.opened !== this.opened) return this.reopened(s.opened, next);
      if (next !== undefined && next !== this.base) this.fromModel(next);
    });
  }

  get pending(): boolean {
    return !this.local.empty;
  }

  update(u: ViewUpdate): void {
    let edited = false;
    for (const tr of u.transactions) {
      if (!tr.docChanged || tr.annotation(fromModel)) continue;
      this.local = this.local.compose(tr.changes);
      edited = true;
    }
    if (edited) {
      this.editLine = u.state.doc.lineAt(u.state.selection.main.head).number;
      this.schedule(ST_BURST_PAUSE_MS);
      return;
    }
    if (!this.pending) return;
    if (u.focusChanged && !u.view.hasFocus) return this.schedule(0);
    if (u.selectionSet) {
      const jumped = u.transactions.some((tr) => tr.isUserEvent('select.pointer'));
      const line = u.state.doc.lineAt(u.state.selection.main.head).number;
      if (jumped || line !== this.editLine) this.schedule(0);
    }
  }

  private schedule(ms: number): void {
    if (this.timer) clearTimeout(this.timer);
    // Never commit inside a view update (the store's listeners may dispatch to the view).
    this.timer = setTimeout(() => this.commit(), ms);
  }

  /** Commits the burst typed so far as one undo step (nothing when there is none). */
  commit(): void {
    if (this.timer) clearTimeout(this.timer);
    this.timer = undefined;
    if (!this.pending) return;
    if (this.store.getState().opened !== this.opened) return this.reopened(this.store.getState().opened, undefined);
    const text = this.view.state.doc.toString();
    const pou = this.store.getState().project.pous.find((p) => p.id === this.pouId);
    this.base = text;
    this.local = ChangeSet.empty(text.length);
    if (pou && pou.source !== text)
      this.store.getState().setPouSource(this.pouId, text, stEditStepName(pou.name));
  }

  /**
   * Another project was opened (a file, an import, an example, New) while this editor was still
   * shown: a burst not committed yet belonged to the old project and is dropped, never carried into
   * the new one (which may have a POU with the same id). The editor shows the new project's text.
   */
  private reopened(opened: number, next: string | undefined): void {
    if (this.timer) clearTimeout(this.timer);
    this.timer = undefined;
    this.opened = opened;
    this.base = next ?? this.view.state.doc.toString();
    this.local = ChangeSet.empty(this.base.length);
    const shown = this.view.state.doc.toString();
    if (next === undefined || next === shown) return;
    this.view.dispatch({ changes: textDiff(shown, next), annotations: fromModel.of(true) });
  }

  /** The model's text changed elsewhere: merge that change with the burst not yet committed. */
  private fromModel(next: string): void {
    const outside = textDiff(this.base, next);
    const mapped = outside.map(this.local);
    this.local = this.local.map(outside, true);
    this.base = next;
    if (mapped.empty) return;
    // The cursor goes to the end of the change (where an undo or redo happened).
    let at = -1;
    mapped.iterChanges((_fa, _ta, _fb, toB) => (at = toB));
    this.view.dispatch({
      changes: mapped,
      selection: EditorSelection.cursor(at),
      annotations: fromModel.of(true),
      scrollIntoView: true,
    });
  }

  destroy(): void {
    this.commit();
    this.unsubscribe();
  }
}

/** The document and POU an editor is linked to. */
const modelLink = Facet.define<
  { store: DocumentStore; pouId: PouId },
  { store: DocumentStore; pouId: PouId } | undefined
>({
  combine: (v) => v[0],
});

const syncPlugin = ViewPlugin.define((view): ModelSync => {
  const link = view.state.facet(modelLink);
  if (!link) throw new Error('the ST editor needs modelSync(store, pouId)');
  return new ModelSync(view, link.store, link.pouId);
});

/** Commits the ST editor's typing burst now (before an action that reads the model, e.g. a rename). */
export function commitStEdit(view: EditorView): void {
  view.plugin(syncPlugin)?.commit();
}

const undoRedo = (which: 'undo' | 'redo') => (view: EditorView) => {
  const link = view.state.facet(modelLink);
  if (!link) return false;
  commitStEdit(view);
  const s = link.store.getState();
  if (which === 'undo' ? s.canUndo : s.canRedo) s[which]();
  return true;
};

/** Keeps the editor and the POU's `source` in the model in step, with the project's undo/redo. */
export function modelSync(store: DocumentStore, pouId: PouId): Extension {
  return [
    modelLink.of({ store, pouId }),
    syncPlugin,
    // A command key (Ctrl+S, F5...) may act on the model: the burst typed so far goes in first.
    EditorView.domEventHandlers({
      keydown: (e, view) => {
        if (e.ctrlKey || e.metaKey || /^F\d+$/.test(e.key)) commitStEdit(view);
        return false;
      },
    }),
    Prec.high(
      keymap.of([
        { key: 'Mod-z', run: undoRedo('undo'), preventDefault: true },
        { key: 'Mod-y', run: undoRedo('redo'), preventDefault: true },
        { key: 'Mod-Shift-z', run: undoRedo('redo'), preventDefault: true },
      ]),
    ),
  ];
}

/** The document and POU an editor shows (for extensions that read the project, e.g. language services). */
export const stModelLink = (state: EditorState): { store: DocumentStore; pouId: PouId } | undefined => state.facet(modelLink);
