// Applying an edited declaration text (the variables panel's text view) to the document as ONE
// undo step named 'editDeclarations': the variables the text declares replace the list, through the
// same commands as the table (so calls of an FB follow its interface, a rename renames the uses).
import { planDeclarationEdit } from '../engine/st/declarations';
import type { Variable } from '../model/project';
import type { VariableScope } from './changes';
import type { DocumentStore } from './documentStore';
import { renameVariable } from './renameVariable';

/** The history step's name (DocumentState.undoName). */
export const EDIT_DECLARATIONS = 'editDeclarations';

/** The declared variables of a scope now. */
export function scopeVariables(doc: DocumentStore, scope: VariableScope): readonly Variable[] {
  const project = doc.getState().project;
  return scope === 'globals' ? project.globals : (project.pous.find((p) => p.id === scope)?.variables ?? []);
}

/**
 * Makes the scope declare exactly `variables` (parsed from the text, in its order). Names changed
 * at the same position are renames (uses and test scenarios follow); other names gone are
 * deleted, new ones added, changed ones updated. Returns whether anything changed, or why not.
 */
export function applyDeclarationText(
  doc: DocumentStore,
  scope: VariableScope,
  variables: readonly Variable[],
): { ok: true; changed: boolean } | { ok: false; reason: string } {
  const plan = planDeclarationEdit(scopeVariables(doc, scope), variables);
  const revision = doc.getState().revision;
  let failure: string | undefined;
  doc.getState().batch(EDIT_DECLARATIONS, () => {
    const s = () => doc.getState();
    for (const rename of plan.renames ?? []) {
      const r = renameVariable(doc, rename.from, rename.to, [scope], EDIT_DECLARATIONS);
      if (!r.ok) failure ??= r.reason;
    }
    for (const name of plan.removed) s().deleteVariable(name, scope);
    for (const { name, after } of plan.updated) {
      // Every field given, so one the text no longer has (an address, an initial value) goes.
      const patch: Partial<Variable> = { location: undefined, initial: undefined, constant: undefined, ...after };
      if (!s().updateVariable(name, patch, scope)) failure ??= `"${after.name}" could not be updated`;
    }
    for (const v of plan.added)
      if (!s().addVariable(v, scope)) failure ??= `"${v.name}" is already declared`;
    s().reorderVariables(plan.order, scope);
  });
  if (failure) {
    // Never half an edit: what did apply is taken back (the step is the newest one).
    if (doc.getState().revision !== revision) doc.getState().undo();
    return { ok: false, reason: failure };
  }
  return { ok: true, changed: doc.getState().revision !== revision };
}
