// State of the variables panel's text view that outlives the component: which view the user
// chose (Table | Text, kept in localStorage like the panel layout), the text not applied yet per
// list (a POU's variables or the globals), so switching away never loses it, and its syntax
// problems, which the Problems list shows with rule LD-E18 until they are fixed or reverted.
import { createStore } from 'zustand/vanilla';
import type { DeclarationProblem } from '../../engine/st/declarations';
import type { VariableScope } from '../../store/changes';
import { variableFocus } from './variableFocus';

export const VARIABLES_VIEW_KEY = 'rungsmith.variablesView';
export type VariablesView = 'table' | 'text';

function readView(): VariablesView {
  try {
    return globalThis.localStorage?.getItem(VARIABLES_VIEW_KEY) === 'text' ? 'text' : 'table';
  } catch {
    return 'table';
  }
}

/** Syntax errors of text typed in the text view and not applied (it does not parse). */
export interface PendingText {
  /** The project it was typed in (DocumentState.opened): another project opened since shows none of it. */
  readonly opened: number;
  /** Who it declares, for the Problems list: the POU's name, or "Global variables". */
  readonly owner: string;
  readonly problems: readonly DeclarationProblem[];
}

export interface DeclarationViewState {
  readonly view: VariablesView;
  readonly pending: ReadonlyMap<VariableScope, PendingText>;
  /** "Show line 3 of this text": the Problems list asks, the variables panel answers. */
  readonly reveal:
    | { readonly scope: VariableScope; readonly line: number; readonly col: number; readonly seq: number }
    | undefined;
}

export const declarationView = createStore<DeclarationViewState>()(() => ({
  view: readView(),
  pending: new Map(),
  reveal: undefined,
}));

/**
 * The newest "show line" and "show variable" requests already answered, whichever text view
 * answered them (it remounts per list). Switching views by hand answers them all: a text view
 * opened later does not jump to an old request.
 */
export const handled = { reveal: 0, focus: 0 };

export function setVariablesView(view: VariablesView): void {
  handled.reveal = declarationView.getState().reveal?.seq ?? 0;
  handled.focus = variableFocus.getState().request?.seq ?? 0;
  declarationView.setState({ view });
  try {
    globalThis.localStorage?.setItem(VARIABLES_VIEW_KEY, view);
  } catch {
    // Private mode or storage full: the choice lasts for this page only.
  }
}

const pendingKey = (p: PendingText | undefined) =>
  p ? `${p.opened}\n${p.owner}\n${p.problems.map((e) => `${e.severity}:${e.line}:${e.col}:${e.message}`).join('\n')}` : '';

/** Records (or clears) the syntax errors of a list's unapplied text; no change, no notification. */
export function setPending(scope: VariableScope, pending: PendingText | undefined): void {
  const current = declarationView.getState().pending;
  if (pendingKey(current.get(scope)) === pendingKey(pending)) return;
  const next = new Map(current);
  if (pending) next.set(scope, pending);
  else next.delete(scope);
  declarationView.setState({ pending: next });
}

/** Unapplied text of a list: the text, the printed variables it was last in step with, and whether they changed since. */
export interface Draft {
  /** The project it was typed in (DocumentState.opened): another project opened since has no draft. */
  readonly opened: number;
  readonly text: string;
  /** The variables as printed when the text last followed them: printed differently now means they changed elsewhere. */
  readonly basis: string;
  /** The variables changed elsewhere while this text had changes (the text view says so until applied or reverted). */
  readonly stale: boolean;
}

/** Unapplied text per list, kept while the text view is closed (read when it opens again). */
const drafts = new Map<VariableScope, Draft>();
export const draftOf = (scope: VariableScope, opened: number): Draft | undefined => {
  const d = drafts.get(scope);
  return d?.opened === opened ? d : undefined;
};
export function keepDraft(scope: VariableScope, draft: Draft | undefined): void {
  if (draft === undefined) drafts.delete(scope);
  else drafts.set(scope, draft);
}

let seq = 0;
/** Opens the text view of `scope` with the caret at line/col (1-based). */
export function revealDeclarationText(scope: VariableScope, line: number, col: number): void {
  seq += 1;
  declarationView.setState({ view: 'text', reveal: { scope, line, col, seq } });
  document.getElementById('rs-tab-variables')?.click();
}
