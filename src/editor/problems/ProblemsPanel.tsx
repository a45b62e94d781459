// The problems list: every diagnostic with severity, rule id, network, cell and message.
// Clicking one (or Enter on it) shows the place on the canvas and selects the element.
import { useMemo, useState } from 'react';
import type { Diagnostic } from '../../engine/api';
import type { Pou, Project } from '../../model/project';
import { elementCells } from '../../model/factory';
import { blockLibrary } from '../../model/library';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { countBySeverity, diagnosticCell, diagnosticNetwork, sortDiagnostics } from './describe';
import { useCheckedDiagnostics } from './useDiagnostics';
import { focusVariable } from '../variables/variableFocus';
import { declarationView, revealDeclarationText } from '../variables/declarationView';
import { DECLARATION_SYNTAX_RULE } from '../../engine/st/declarations';
import type { VariableScope } from '../../store/changes';
import { useStore } from 'zustand';
import { revealStLine } from '../st/services/reveal';
import './problems.css';

/** The network and cell a diagnostic points at, resolved against the document. */
function placeOf(project: Project, d: Diagnostic) {
  const pou = project.pous.find((p) => p.name === d.pou);
  const network = pou?.networks[d.network];
  if (!pou || !network) return { pou, network: undefined, cell: undefined, element: undefined };
  const element = d.elementId ? network.elements.find((e) => e.id === d.elementId) : undefined;
  const cell = d.cell ?? (element ? elementCells(element, blockLibrary(project))[0] : undefined);
  return { pou, network, cell, element };
}

/** A variable-table problem: show the variable it names ("the variable "Count" ...") in the table. */
function showVariable(project: Project, pou: Pou, message: string) {
  for (const [, name = ''] of message.matchAll(/"([^"]+)"/g)) {
    const key = name.toUpperCase();
    if (pou.variables.some((v) => v.name.toUpperCase() === key)) return focusVariable(name, false);
    if (project.globals.some((v) => v.name.toUpperCase() === key)) return focusVariable(name, true);
  }
  focusVariable('', false);
}

/** Rows rendered at most: a huge list helps nobody and would slow the page. */
const MAX_ROWS = 500;

export function ProblemsPanel() {
  const checkedList = useCheckedDiagnostics();
  const { checked } = checkedList;
  // Declaration text not applied because it does not parse (variables panel, Text view): LD-E18.
  const pending = useStore(declarationView, (s) => s.pending);
  const opened = useDocument((s) => s.opened);
  const textPlaces = useMemo(() => {
    const places = new Map<Diagnostic, { scope: VariableScope; line: number; col: number }>();
    for (const [scope, p] of pending)
      for (const e of p.opened === opened ? p.problems : [])
        if (e.severity === 'error')
          places.set(
            {
              severity: 'error',
              rule: DECLARATION_SYNTAX_RULE,
              pou: p.owner,
              network: -1,
              message: `declaration text, line ${e.line}, column ${e.col}: ${e.message} (not applied: the variables are unchanged)`,
            },
            { scope, line: e.line, col: e.col },
          );
    return places;
  }, [pending, opened]);
  const diagnostics = useMemo(
    () => (textPlaces.size ? [...textPlaces.keys(), ...checkedList.diagnostics] : checkedList.diagnostics),
    [textPlaces, checkedList.diagnostics],
  );
  const project = useDocument(selectProject);
  const pouCount = project.pous.length;
  const documentStore = useDocumentStore();
  const uiStore = useUiStore();
  const [showWarnings, setShowWarnings] = useState(true);
  const sorted = useMemo(() => sortDiagnostics(diagnostics), [diagnostics]);
  const { errors, warnings } = countBySeverity(diagnostics);
  const shown = showWarnings ? sorted : sorted.filter((d) => d.severity === 'error');
  // A row names its POU whenever the project has several (a problem in another POU than the one shown).
  const manyPous = pouCount > 1 || new Set(diagnostics.map((d) => d.pou)).size > 1;

  const jump = (d: Diagnostic) => {
    const text = textPlaces.get(d);
    if (text) return revealDeclarationText(text.scope, text.line, text.col);
    const doc = documentStore.getState();
    const { pou, network, cell, element } = placeOf(doc.project, d);
    if (pou && pou.id !== doc.activePouId) doc.setActivePou(pou.id);
    // A finding in an ST/IL body: its editor puts the cursor on the line.
    if (pou && d.line !== undefined) return revealStLine(pou.id, d.line, d.col);
    if (d.network < 0 && pou) return showVariable(doc.project, pou, d.message);
    if (!pou || !network) return;
    const ui = uiStore.getState();
    if (element) ui.select(network.id, [element.id]);
    else ui.select(network.id, []);
    ui.focusCell(network.id, cell ?? { row: 0, col: 0 });
  };

  return (
    <section className="rs-problems" aria-label="Problems" data-testid="problems-panel">
      <header className="rs-problems-head">
        <span data-testid="problems-summary" aria-live="polite">
          {!checked
            ? 'Checking…'
            : diagnostics.length === 0
            ? 'No problems'
            : `${errors} error${errors === 1 ? '' : 's'}, ${warnings} warning${warnings === 1 ? '' : 's'}`}
        </span>
        <label className="rs-problems-toggle">
          <input type="checkbox" checked={showWarnings} onChange={(e) => setShowWarnings(e.target.checked)} />
          Show warnings
        </label>
      </header>
      {shown.length > 0 && (
        <ul className="rs-problems-list" aria-label="Problem list">
          {shown.slice(0, MAX_ROWS).map((d, i) => (
            <li
              key={`${d.rule}:${d.pou}:${d.network}:${d.elementId ?? ''}:${d.cell?.row ?? ''}:${d.cell?.col ?? ''}:${i}`}
            >
              <button
                type="button"
                className={`rs-problem rs-${d.severity}`}
                data-testid="problem"
                data-rule={d.rule}
                title={d.line !== undefined ? 'Show this line in the editor' : 'Show this place on the canvas'}
                onClick={() => jump(d)}
              >
                <span className="rs-problem-severity" aria-label={d.severity}>
                  {d.severity === 'error' ? '⨯' : '!'}
                </span>
                <span className="rs-problem-rule">{d.rule}</span>
                <span className="rs-problem-where">
                  {manyPous ? `${d.pou} · ` : ''}
                  {diagnosticNetwork(d)}
                  {d.cell ? ` · ${diagnosticCell(d, placeOf(project, d).element)}` : ''}
                </span>
                <span className="rs-problem-message">{d.message}</span>
              </button>
            </li>
          ))}
          {shown.length > MAX_ROWS && (
            <li className="rs-problems-more">
              … and {shown.length - MAX_ROWS} more; fix the first ones
              {showWarnings ? ' or hide warnings' : ''} to see them.
            </li>
          )}
        </ul>
      )}
    </section>
  );
}
