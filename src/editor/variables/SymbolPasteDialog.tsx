// "Paste symbol table": rows copied from a spreadsheet (or a CSV file's text) shown before anything
// changes, each with what pasting does to it: added, renamed (its name is taken: a free name, or
// replace the existing variable, or skip it), or refused with the reason. Confirming writes the
// accepted rows as one undo step (src/store/symbolPaste.ts holds the logic).
import { useMemo, useState } from 'react';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import type { VariableScope } from '../../store/changes';
import {
  applySymbolPaste,
  parseSymbolTable,
  planCounts,
  planSymbolPaste,
  type ClashChoice,
  type PastePlanRow,
} from '../../store/symbolPaste';
import { useUiStore } from '../../store/uiStore';
import { ModalDialog } from '../files/ModalDialog';
import './symbolPaste.css';

interface Props {
  readonly text: string;
  readonly scope: VariableScope;
  /** "the global variables", "Main": where the rows go, for the title. */
  readonly target: string;
  readonly onClose: () => void;
  /** After a paste: the names written, to show them in the table. */
  readonly onPasted?: (names: readonly string[]) => void;
}

const VERDICT: Record<PastePlanRow['action'], string> = {
  add: 'added',
  rename: 'renamed',
  replace: 'replaces',
  refuse: 'refused',
  skip: 'skipped',
};

function Verdict({
  row,
  choice,
  onChoose,
}: {
  readonly row: PastePlanRow;
  readonly choice: ClashChoice;
  readonly onChoose: (c: ClashChoice) => void;
}) {
  if (row.action === 'refuse') return <span className="rs-paste-reason">{row.reasons.join('; ')}</span>;
  if (row.clash === undefined) return <span>{row.notes.length ? row.notes.join('; ') : ''}</span>;
  const renamed = row.action === 'rename' ? row.variable?.name : undefined;
  return (
    <select
      aria-label={`What to do with ${row.given}`}
      className="rs-cell-input"
      value={choice}
      onChange={(e) => onChoose(e.target.value as ClashChoice)}
    >
      <option value="rename">
        {renamed ? `Add as ${renamed} (${row.clash} exists)` : `Add under a free name (${row.clash} exists)`}
      </option>
      {row.canReplace && <option value="replace">Replace the existing {row.clash}</option>}
      <option value="skip">Skip this row</option>
    </select>
  );
}

export function SymbolPasteDialog({ text: initialText, scope, target, onClose, onPasted }: Props) {
  const store = useDocumentStore();
  const ui = useUiStore();
  const project = useDocument(selectProject);
  const [text, setText] = useState(initialText);
  const [choices, setChoices] = useState<ReadonlyMap<number, ClashChoice>>(new Map());
  const table = useMemo(() => parseSymbolTable(text), [text]);
  const plan = useMemo(
    () => planSymbolPaste(project, scope, table, choices),
    [project, scope, table, choices],
  );
  const counts = planCounts(plan);
  const writes = counts.add + counts.rename + counts.replace;
  const confirm = () => {
    const done = applySymbolPaste(store.getState(), scope, plan);
    const names = plan.flatMap((r) =>
      r.variable && ['add', 'rename', 'replace'].includes(r.action) ? [r.variable.name] : [],
    );
    ui.getState().setStatus(
      `Pasted ${done} variable${done === 1 ? '' : 's'} into ${target}` +
        (counts.refuse ? `; ${counts.refuse} refused row${counts.refuse === 1 ? '' : 's'} left out` : '') +
        ' (Ctrl+Z undoes the paste)',
    );
    onPasted?.(names);
    onClose();
  };
  const summary = [
    counts.add && `${counts.add} added`,
    counts.rename && `${counts.rename} renamed`,
    counts.replace && `${counts.replace} replaced`,
    counts.refuse && `${counts.refuse} refused`,
    counts.skip && `${counts.skip} skipped`,
  ]
    .filter(Boolean)
    .join(', ');

  return (
    <ModalDialog
      role="dialog"
      titleId="rs-symbol-paste-title"
      title={`Paste symbol table into ${target}`}
      describedBy="rs-symbol-paste-text"
      className="rs-symbol-paste"
      testId="symbol-paste-dialog"
      onClose={onClose}
      buttons={
        <>
          <button type="button" className="rs-button" onClick={onClose}>
            Cancel
          </button>
          <button
            type="button"
            className="rs-button rs-primary"
            data-testid="symbol-paste-confirm"
            disabled={writes === 0}
            autoFocus={writes > 0}
            onClick={confirm}
          >
            {writes === 0 ? 'Nothing to paste' : `Paste ${writes} variable${writes === 1 ? '' : 's'}`}
          </button>
        </>
      }
    >
      <p id="rs-symbol-paste-text" className="rs-paste-help">
        Rows from Excel, LibreOffice or Google Sheets (tab separated) or CSV (comma or semicolon): name, type,
        address, initial value, comment, or any order under a header row (Name, Data Type, Address, Initial,
        Comment, Class). TIA addresses such as %I0.0 and %IW64 are read as %IX0.0 and %IW64.
      </p>
      <textarea
        aria-label="Symbol table text"
        className="rs-paste-text rs-mono"
        spellCheck={false}
        value={text}
        autoFocus={writes === 0}
        onChange={(e) => {
          setText(e.target.value);
          setChoices(new Map());
        }}
      />
      {table.error && (
        <p role="alert" className="rs-var-refusal">
          The text is not a table: {table.error}
        </p>
      )}
      <p className="rs-paste-summary" data-testid="symbol-paste-summary" aria-live="polite">
        {plan.length === 0
          ? 'No rows yet: paste them in the field above.'
          : `${plan.length} row${plan.length === 1 ? '' : 's'}${table.header ? ' under a header' : ''}: ${summary}.`}
      </p>
      {plan.length > 0 && (
        <div className="rs-paste-scroll">
          <table className="rs-paste-table" aria-label="What the paste does">
            <thead>
              <tr>
                <th>Line</th>
                <th>Name</th>
                <th>Type</th>
                <th>Address</th>
                <th>Initial</th>
                <th>Comment</th>
                <th>Result</th>
                <th>Details</th>
              </tr>
            </thead>
            <tbody>
              {plan.map((row, i) => (
                <tr
                  key={i}
                  data-testid={`symbol-paste-row-${i}`}
                  data-action={row.action}
                  className={`rs-paste-${row.action}`}
                >
                  <td>{row.line}</td>
                  <td className="rs-mono">{row.variable?.name ?? row.given}</td>
                  <td className="rs-mono">{row.variable?.type ?? ''}</td>
                  <td className="rs-mono">{row.variable?.location ?? ''}</td>
                  <td className="rs-mono">{row.variable?.initial ?? ''}</td>
                  <td>{row.variable?.comment ?? ''}</td>
                  <td>{VERDICT[row.action]}</td>
                  <td>
                    <Verdict
                      row={row}
                      choice={
                        choices.get(i) ??
                        (row.action === 'skip' ? 'skip' : row.action === 'replace' ? 'replace' : 'rename')
                      }
                      onChoose={(c) => setChoices(new Map(choices).set(i, c))}
                    />
                  </td>
                </tr>
              ))}
            </tbody>
          </table>
        </div>
      )}
    </ModalDialog>
  );
}
