// The variable table: the active POU's variables or the project's globals, edited in place and
// checked as you type (names, duplicates, addresses, initial values). A POU's variables are sorted
// by class, its interface first (VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT), with the class column first;
// in the narrow side panel each variable wraps onto three lines so no column is cut off
// (variables.css). Long tables render only the rows near the visible part (rowWindow.ts).
import { useDeferredValue, useEffect, useMemo, useRef, useState } from 'react';
import { useStore } from 'zustand';
import type { VariableScope } from '../../store/changes';
import { selectProject, useDocument, useDocumentStore, type DocumentState } from '../../store/documentStore';
import { useUi, useUiStore } from '../../store/uiStore';
import { toggleVariablesDock } from '../layout/shellCommands';
import { variable } from '../../model/factory';
import { blockLibrary } from '../../model/library';
import type { Variable } from '../../model/project';
import { useRowWindow } from './rowWindow';
import { SymbolPasteDialog } from './SymbolPasteDialog';
import { committedByEnter } from './CommitInput';
import { isTablePaste, isTextField, lastRowEnter } from './tableKeys';
import { scopeVariables } from '../../store/symbolPaste';
import { CLASS_ORDER, VariableRow } from './VariableRow';
import { variableFocus } from './variableFocus';
import { DeclarationText } from './DeclarationText';
import { declarationView, setVariablesView } from './declarationView';
import { undeclaredVariables } from './undeclared';
import { globalVariableUses, pouVariableUses, type VariableUse } from './usage';
import { issuesByField, validateVariables } from './validation';
import './variables.css';

/** "Var1", "Var2", ... the first not taken (names compare case-insensitively). */
function freshName(vars: readonly Variable[]): string {
  const taken = new Set(vars.map((v) => v.name.toUpperCase()));
  for (let i = 1; ; i++) if (!taken.has(`VAR${i}`)) return `Var${i}`;
}

const selectActivePouId = (s: DocumentState) => s.activePouId;

export function VariablesPanel() {
  const store = useDocumentStore();
  // Deferred: while drawing, the canvas repaints first and the table follows a moment later.
  const project = useDeferredValue(useDocument(selectProject));
  const activePouId = useDocument(selectActivePouId);
  const pou = project.pous.find((p) => p.id === activePouId);
  const globals = project.globals;
  const [showGlobals, setShowGlobals] = useState(false);
  const [filter, setFilter] = useState('');
  const [focusName, setFocusName] = useState<string | undefined>(undefined);
  const [refusal, setRefusal] = useState('');
  /** The symbol table paste preview is open with this text. */
  const [pasting, setPasting] = useState<string | undefined>(undefined);

  const scope: VariableScope | undefined = showGlobals ? 'globals' : pou?.id;
  const vars = useMemo(() => (showGlobals ? globals : (pou?.variables ?? [])), [showGlobals, globals, pou]);
  const issues = useMemo(
    () => validateVariables(vars, { project, ...(showGlobals || !pou ? {} : { pou: pou.name }) }),
    [vars, project, showGlobals, pou],
  );
  const uses = useMemo(
    () =>
      showGlobals
        ? globalVariableUses(project)
        : pou
          ? pouVariableUses(pou)
          : new Map<string, VariableUse[]>(),
    [showGlobals, project, pou],
  );
  const uiStore = useUiStore();
  const wide = useUi((s) => s.panels.variablesDock === 'bottom');
  const nextUse = useRef(new Map<string, number>());
  const focusRequest = useStore(variableFocus, (s) => s.request);
  const panel = useRef<HTMLElement>(null);
  const scroller = useRef<HTMLDivElement>(null);
  /** A row to bring into view (and focus its name field), once it is in the list. */
  const [reveal, setReveal] = useState<{ name: string; focus: boolean; seq: number } | undefined>(undefined);
  const revealSeq = useRef(0);
  useEffect(() => {
    if (!focusRequest) return;
    setShowGlobals(focusRequest.globals);
    setFilter('');
    revealSeq.current += 1;
    setReveal({ name: focusRequest.name, focus: true, seq: revealSeq.current });
  }, [focusRequest]);
  // Table | Text (DeclarationText.tsx): the text view of the same list, the choice remembered.
  const view = useStore(declarationView, (s) => s.view);
  const textReveal = useStore(declarationView, (s) => s.reveal);
  useEffect(() => {
    if (!textReveal) return;
    setShowGlobals(textReveal.scope === 'globals');
    if (textReveal.scope !== 'globals' && textReveal.scope !== store.getState().activePouId)
      store.getState().setActivePou(textReveal.scope);
  }, [textReveal, store]);
  const query = filter.trim().toUpperCase();
  const shown = useMemo(() => {
    const rows = vars
      .map((v, index) => ({ v, index }))
      .filter(
        ({ v }) =>
          !query || `${v.name} ${v.type} ${v.location ?? ''} ${v.comment}`.toUpperCase().includes(query),
      );
    // The interface first: a stable sort by class keeps the declaration order within a class.
    if (!showGlobals)
      rows.sort((a, b) => CLASS_ORDER.indexOf(a.v.varClass) - CLASS_ORDER.indexOf(b.v.varClass));
    return rows;
  }, [vars, query, showGlobals]);
  const library = blockLibrary(project);
  const issueRows = useMemo(() => new Set(issues.map((i) => i.index)), [issues]);
  const hasIssue = useMemo(() => shown.map(({ index }) => issueRows.has(index)), [shown, issueRows]);
  const rows = useRowWindow(scroller, hasIssue, () => {
    const row = scroller.current?.querySelector('.rs-var-row');
    const issue = scroller.current?.querySelector('.rs-var-issues');
    if (!row) return undefined;
    return {
      row: row.getBoundingClientRect().height,
      ...(issue ? { issue: issue.getBoundingClientRect().height } : {}),
    };
  });
  const offsetOf = rows.offsetOf;
  const revealed = useRef(0);
  useEffect(() => {
    const el = scroller.current;
    if (!reveal || revealed.current === reveal.seq || !el) return undefined;
    const i = shown.findIndex(({ v }) => v.name.toUpperCase() === reveal.name.toUpperCase());
    if (i < 0) return undefined;
    revealed.current = reveal.seq;
    const head = el.querySelector('thead')?.getBoundingClientRect().height ?? 0;
    const top = offsetOf(i);
    if (top < el.scrollTop || top + head + 40 > el.scrollTop + el.clientHeight)
      el.scrollTop = Math.max(0, top - el.clientHeight / 3);
    // The row renders once the window has followed the scroll: look for it over a few frames.
    let frame = 0;
    let tries = 0;
    const find = () => {
      const row = panel.current?.querySelector(`[data-testid="variable-row-${CSS.escape(reveal.name)}"]`);
      if (!row) {
        if (++tries < 10) frame = requestAnimationFrame(find);
        return;
      }
      if (reveal.focus) row.querySelector<HTMLInputElement>('input[aria-label="Name"]')?.focus();
      row.scrollIntoView({ block: 'nearest' });
    };
    frame = requestAnimationFrame(find);
    return () => cancelAnimationFrame(frame);
  }, [reveal, shown, offsetOf]);
  const rowsWithIssues = issueRows.size;
  const undeclared = useMemo(
    () => (!showGlobals && pou ? undeclaredVariables(project, pou) : []),
    [showGlobals, project, pou],
  );

  if (!scope)
    return <section className="rs-variables" aria-label="Variables" data-testid="variables-panel" />;

  const add = () => {
    // The list as it is now: Enter on the last row commits its field first, then adds.
    const name = freshName(scopeVariables(store.getState().project, scope));
    if (store.getState().addVariable(variable(name, 'BOOL'), scope)) {
      setFocusName(name);
      setFilter('');
      revealSeq.current += 1;
      setReveal({ name, focus: false, seq: revealSeq.current });
    }
  };
  /** Selects the next element using the variable and scrolls the canvas there. */
  const showUse = (name: string) => {
    const list = uses.get(name.toUpperCase()) ?? [];
    const i = (nextUse.current.get(name.toUpperCase()) ?? 0) % Math.max(1, list.length);
    const use = list[i];
    if (!use) return;
    nextUse.current.set(name.toUpperCase(), i + 1);
    if (use.pou !== store.getState().activePouId) store.getState().setActivePou(use.pou);
    uiStore.getState().select(use.network, [use.element]);
    uiStore.getState().focusCell(use.network, { row: use.row, col: use.col });
  };
  const change = (v: Variable, patch: Partial<Variable>) => {
    setFocusName(undefined);
    if (store.getState().updateVariable(v.name, patch, scope)) setRefusal('');
    else if (patch.name !== undefined) {
      const to = patch.name.toUpperCase();
      // A global is renamed in the POUs declaring it VAR_EXTERNAL too: the name may be taken there.
      const inPou =
        scope === 'globals'
          ? store.getState().project.pous.find((p) => p.variables.some((w) => w.varClass === 'external' && w.name.toUpperCase() === v.name.toUpperCase()) && p.variables.some((w) => w.name.toUpperCase() === to))
          : undefined;
      setRefusal(
        inPou
          ? `Cannot rename "${v.name}" to "${patch.name}": ${inPou.name} declares ${v.name} VAR_EXTERNAL and already has a variable "${patch.name}".`
          : `Cannot rename "${v.name}" to "${patch.name}": that name is already declared here.`,
      );
    }
  };

  return (
    <section
      ref={panel}
      className="rs-variables"
      aria-label="Variables"
      data-testid="variables-panel"
      onKeyDown={(e) => {
        // Ctrl+V outside a text field is a table paste here, not a network paste on the canvas.
        if (pasting !== undefined) return;
        if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === 'v' && !isTextField(e.target)) e.stopPropagation();
        // Enter that confirmed an edit stays on the row; Enter again (nothing to commit) adds one.
        if (lastRowEnter(e, shown[shown.length - 1]?.v.name) && !committedByEnter.has(e.nativeEvent)) add();
      }}
      onPaste={(e) => {
        const text = e.clipboardData.getData('text/plain');
        if (pasting !== undefined || !isTablePaste(e.target, text)) return;
        e.preventDefault();
        e.stopPropagation();
        setPasting(text);
      }}
    >
      <div className="rs-var-toolbar">
        <div role="radiogroup" aria-label="Which variables" className="rs-segmented">
          <label>
            <input
              type="radio"
              name="rs-var-scope"
              checked={!showGlobals}
              onChange={() => setShowGlobals(false)}
            />
            {pou ? `${pou.name} (${pou.kind.replace('_', ' ').toLowerCase()})` : 'POU'}
          </label>
          <label>
            <input
              type="radio"
              name="rs-var-scope"
              checked={showGlobals}
              onChange={() => setShowGlobals(true)}
            />
            Global
          </label>
        </div>
        <div role="radiogroup" aria-label="Variables view" className="rs-segmented rs-var-view">
          <label title="The variables as a table">
            <input
              type="radio"
              name="rs-var-view"
              checked={view === 'table'}
              onChange={() => setVariablesView('table')}
              data-testid="variables-view-table"
            />
            Table
          </label>
          <label title="The declarations as IEC 61131-3 text (VAR_INPUT … END_VAR), edited like code">
            <input
              type="radio"
              name="rs-var-view"
              checked={view === 'text'}
              onChange={() => setVariablesView('text')}
              data-testid="variables-view-text"
            />
            Text
          </label>
        </div>
        <input
          hidden={view === 'text'}
          type="search"
          aria-label="Filter variables"
          placeholder="Filter"
          className="rs-var-filter"
          value={filter}
          onChange={(e) => setFilter(e.target.value)}
        />
        <button type="button" className="rs-button" onClick={add} data-testid="add-variable">
          Add variable
        </button>
        <button
          type="button"
          className="rs-button"
          title="Paste rows copied from a spreadsheet or CSV (name, type, address, initial value, comment), with a preview first; Ctrl+V in the table does the same"
          onClick={() => setPasting('')}
          data-testid="paste-symbols"
        >
          Paste table…
        </button>
        <button
          type="button"
          className="rs-button"
          aria-pressed={wide}
          title={
            wide
              ? 'Back to the side panel'
              : 'Wide view: the table in the full-width bottom panel, every column on one line'
          }
          onClick={() => toggleVariablesDock(uiStore)}
          data-testid="variables-wide"
        >
          Wide view
        </button>
        {undeclared.length > 0 && (
          <button
            type="button"
            className="rs-button"
            title={`Declares ${undeclared.map((v) => `${v.name} : ${v.type}`).join(', ')} (one undo step)`}
            onClick={() =>
              store.getState().batch('declareUsedNames', () => {
                for (const v of undeclared) store.getState().addVariable(v, scope);
              })
            }
          >
            Declare {undeclared.length} used name{undeclared.length === 1 ? '' : 's'}
          </button>
        )}
      </div>
      {refusal && (
        <p role="alert" className="rs-var-refusal">
          {refusal}
        </p>
      )}
      {view === 'text' && (
        <DeclarationText key={scope} scope={scope} pouName={showGlobals ? undefined : pou?.name} />
      )}
      <div className="rs-var-scroll" ref={scroller} hidden={view === 'text'}>
        <table
          className="rs-var-table"
          aria-label={showGlobals ? 'Global variables' : `Variables of ${pou?.name ?? ''}`}
        >
          <thead>
            <tr>
              <th
                data-col="class"
                title={showGlobals ? 'Declared in the configuration or the resource' : 'Variable class'}
              >
                {showGlobals ? 'Declared in' : 'Class'}
              </th>
              <th data-col="name">Name</th>
              <th data-col="type">Type</th>
              <th data-col="address">Address</th>
              <th data-col="initial">Initial</th>
              <th data-col="retain" title="Keeps its value over a warm restart">
                RETAIN
              </th>
              <th data-col="constant" title="Read-only">
                CONST
              </th>
              <th data-col="comment">Comment</th>
              <th data-col="uses" title="Elements using the variable">
                Uses
              </th>
              <th data-col="actions" aria-label="Actions" />
            </tr>
          </thead>
          <tbody>
            {rows.before > 0 && (
              <tr aria-hidden="true" className="rs-var-spacer" style={{ height: rows.before }} />
            )}
            {shown.slice(rows.first, rows.last + 1).map(({ v, index }, i) => (
              <VariableRow
                key={index}
                variable={v}
                issues={issuesByField(issues, index)}
                showClass={!showGlobals}
                showScope={showGlobals}
                library={library}
                dataTypes={project.dataTypes}
                firstOfClass={
                  !showGlobals && rows.first + i > 0 && shown[rows.first + i - 1]?.v.varClass !== v.varClass
                }
                focusName={focusName === v.name}
                useCount={uses.get(v.name.toUpperCase())?.length ?? 0}
                onShowUse={() => showUse(v.name)}
                onChange={(patch) => change(v, patch)}
                onDelete={() => store.getState().deleteVariable(v.name, scope)}
              />
            ))}
            {rows.after > 0 && (
              <tr aria-hidden="true" className="rs-var-spacer" style={{ height: rows.after }} />
            )}
          </tbody>
        </table>
        {vars.length === 0 && (
          <p className="rs-empty">
            No variables yet. Add one here, or type a new name on a contact or coil and declare it from there.
          </p>
        )}
      </div>
      {pasting !== undefined && (
        <SymbolPasteDialog
          text={pasting}
          scope={scope}
          target={showGlobals ? 'the global variables' : (pou?.name ?? 'the POU')}
          onClose={() => setPasting(undefined)}
          onPasted={(names) => {
            // Show the first pasted row.
            if (!names[0]) return;
            setFilter('');
            revealSeq.current += 1;
            setReveal({ name: names[0], focus: false, seq: revealSeq.current });
          }}
        />
      )}
      <p className="rs-var-summary" aria-live="polite">
        {vars.length} variable{vars.length === 1 ? '' : 's'}
        {rowsWithIssues > 0 ? ` · ${rowsWithIssues} with problems` : ''}
      </p>
    </section>
  );
}
