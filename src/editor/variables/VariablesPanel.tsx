// The variable table: the active POU's variables or the project's globals, edited in place and
// checked as you type (names, duplicates, addresses, initial values).
import { useMemo, useState } from 'react';
import type { VariableScope } from '../../store/changes';
import { selectActivePou, selectGlobals, selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { variable } from '../../model/factory';
import type { Variable } from '../../model/project';
import { VariableRow } from './VariableRow';
import { issuesByField, validateVariables } from './validation';
import './variables.css';

/** "Var1", "Var2", ... the first not taken (names compare case-insensitively). */
function freshName(vars: readonly Variable[]): string {
  const taken = new Set(vars.map((v) => v.name.toUpperCase()));
  for (let i = 1; ; i++) if (!taken.has(`VAR${i}`)) return `Var${i}`;
}

export function VariablesPanel() {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const pou = useDocument(selectActivePou);
  const globals = useDocument(selectGlobals);
  const [showGlobals, setShowGlobals] = useState(false);
  const [filter, setFilter] = useState('');
  const [focusName, setFocusName] = useState<string | undefined>(undefined);
  const [refusal, setRefusal] = useState('');

  const scope: VariableScope | undefined = showGlobals ? 'globals' : pou?.id;
  const vars = useMemo(() => (showGlobals ? globals : (pou?.variables ?? [])), [showGlobals, globals, pou]);
  const issues = useMemo(
    () => validateVariables(vars, { project, ...(showGlobals || !pou ? {} : { pou: pou.name }) }),
    [vars, project, showGlobals, pou],
  );
  const query = filter.trim().toUpperCase();
  const shown = vars.map((v, index) => ({ v, index })).filter(({ v }) => !query || `${v.name} ${v.type} ${v.location ?? ''} ${v.comment}`.toUpperCase().includes(query));
  const rowsWithIssues = new Set(issues.map((i) => i.index)).size;

  if (!scope) return <section className="rs-variables" aria-label="Variables" data-testid="variables-panel" />;

  const add = () => {
    const name = freshName(vars);
    if (store.getState().addVariable(variable(name, 'BOOL'), scope)) {
      setFocusName(name);
      setFilter('');
    }
  };
  const change = (v: Variable, patch: Partial<Variable>) => {
    setFocusName(undefined);
    if (store.getState().updateVariable(v.name, patch, scope)) setRefusal('');
    else if (patch.name !== undefined) setRefusal(`Cannot rename "${v.name}" to "${patch.name}": that name is already declared here.`);
  };

  return (
    <section className="rs-variables" aria-label="Variables" data-testid="variables-panel">
      <div className="rs-var-toolbar">
        <div role="radiogroup" aria-label="Which variables" className="rs-segmented">
          <label>
            <input type="radio" name="rs-var-scope" checked={!showGlobals} onChange={() => setShowGlobals(false)} />
            {pou ? `${pou.name} (${pou.kind.replace('_', ' ').toLowerCase()})` : 'POU'}
          </label>
          <label>
            <input type="radio" name="rs-var-scope" checked={showGlobals} onChange={() => setShowGlobals(true)} />
            Global
          </label>
        </div>
        <input type="search" aria-label="Filter variables" placeholder="Filter" className="rs-var-filter" value={filter} onChange={(e) => setFilter(e.target.value)} />
        <button type="button" className="rs-button" onClick={add} data-testid="add-variable">
          Add variable
        </button>
      </div>
      {refusal && (
        <p role="alert" className="rs-var-refusal">
          {refusal}
        </p>
      )}
      <div className="rs-var-scroll">
        <table className="rs-var-table" aria-label={showGlobals ? 'Global variables' : `Variables of ${pou?.name ?? ''}`}>
          <thead>
            <tr>
              <th>Name</th>
              <th>Type</th>
              <th>Address</th>
              <th>Initial</th>
              {!showGlobals && <th>Class</th>}
              <th title="Keeps its value over a warm restart">RETAIN</th>
              <th title="Read-only">CONST</th>
              <th>Comment</th>
              <th aria-label="Actions" />
            </tr>
          </thead>
          <tbody>
            {shown.map(({ v, index }) => (
              <VariableRow
                key={index}
                variable={v}
                issues={issuesByField(issues, index)}
                showClass={!showGlobals}
                focusName={focusName === v.name}
                onChange={(patch) => change(v, patch)}
                onDelete={() => store.getState().deleteVariable(v.name, scope)}
              />
            ))}
          </tbody>
        </table>
        {vars.length === 0 && <p className="rs-empty">No variables yet. Add one here, or type a new name on a contact or coil and declare it from there.</p>}
      </div>
      <p className="rs-var-summary" aria-live="polite">
        {vars.length} variable{vars.length === 1 ? '' : 's'}
        {rowsWithIssues > 0 ? ` · ${rowsWithIssues} with problems` : ''}
      </p>
    </section>
  );
}
