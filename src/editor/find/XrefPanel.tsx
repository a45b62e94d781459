// The cross-reference list: every use of a variable or FB instance (POU, network, element kind,
// read/write), clickable; the variables no network uses; those written in several places.
// Logic in src/store/xref.ts.
import { useMemo, useState } from 'react';
import type { VariableScope } from '../../store/changes';
import { selectActivePouId, selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { crossReference, unusedVariables, writtenInSeveralPlaces, type VariableSummary } from '../../store/xref';
import type { Project } from '../../model/project';
import type { EditorContext } from '../commands/editorActions';
import { placeName, revealPlace } from './reveal';
import './find.css';

type View = 'uses' | 'unused' | 'multi';

/** The scope a name typed in the shown POU refers to: the POU's own variable, else a global. */
function scopeOf(project: Project, pouId: string, name: string): VariableScope | undefined {
  const key = name.trim().toUpperCase();
  const pou = project.pous.find((p) => p.id === pouId);
  if (pou?.variables.some((v) => v.name.toUpperCase() === key)) return pou.id;
  if (project.globals.some((v) => v.name.toUpperCase() === key)) return 'globals';
  return undefined;
}

function Summary({ list, project, pick }: { list: VariableSummary[]; project: Project; pick: (s: VariableSummary) => void }) {
  const pouName = (scope: VariableScope) =>
    scope === 'globals' ? 'Globals' : (project.pous.find((p) => p.id === scope)?.name ?? '?');
  if (!list.length) return <p>None.</p>;
  return (
    <table data-testid="xref-summary">
      <tbody>
        {list.map((s) => (
          <tr key={`${s.scope}:${s.variable.name}`}>
            <td>{pouName(s.scope)}</td>
            <td>
              <button type="button" className="rs-link-button rs-mono" onClick={() => pick(s)}>
                {s.variable.name}
              </button>
            </td>
            <td>{s.variable.type}</td>
            <td>{s.writers > 1 ? `${s.writers} writers` : `${s.uses} uses`}</td>
          </tr>
        ))}
      </tbody>
    </table>
  );
}

export function XrefPanel() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  const project = useDocument(selectProject);
  const pouId = useDocument(selectActivePouId);
  const [name, setName] = useState('');
  const [scope, setScope] = useState<VariableScope | undefined>(undefined);
  const [view, setView] = useState<View>('uses');
  // Another project opened (or a new one): the query was about the old one.
  const opened = useDocument((s) => s.opened);
  const [queryProject, setQueryProject] = useState(opened);
  if (queryProject !== opened) {
    setQueryProject(opened);
    setName('');
    setScope(undefined);
    setView('uses');
  }
  const resolved = scope ?? scopeOf(project, pouId, name);
  const uses = useMemo(
    () => (view === 'uses' && resolved && name.trim() ? crossReference(project, resolved, name.trim()) : []),
    [project, resolved, name, view],
  );
  const summary = useMemo(
    () => (view === 'unused' ? unusedVariables(project) : view === 'multi' ? writtenInSeveralPlaces(project) : []),
    [project, view],
  );
  const names = useMemo(() => {
    const pou = project.pous.find((p) => p.id === pouId);
    return [...(pou?.variables ?? []), ...project.globals].map((v) => v.name);
  }, [project, pouId]);

  return (
    <div className="rs-xref" data-testid="xref">
      <div className="rs-row">
        <input
          aria-label="Variable or instance"
          placeholder="Variable or instance"
          list="rs-xref-names"
          data-testid="xref-input"
          value={name}
          onChange={(e) => {
            setName(e.target.value);
            setScope(undefined);
            setView('uses');
          }}
        />
        <datalist id="rs-xref-names">
          {names.map((n) => (
            <option key={n} value={n} />
          ))}
        </datalist>
        <button type="button" aria-pressed={view === 'unused'} onClick={() => setView('unused')} data-testid="xref-unused">
          Unused variables
        </button>
        <button type="button" aria-pressed={view === 'multi'} onClick={() => setView('multi')} data-testid="xref-multi">
          Written in several places
        </button>
      </div>
      {view === 'uses' ? (
        name.trim() && !resolved ? (
          <p>{name.trim()} is not declared in this POU nor as a global.</p>
        ) : (
          uses.length > 0 && (
            <table data-testid="xref-uses">
              <thead>
                <tr>
                  <th>Where</th>
                  <th>Element</th>
                  <th>Operand</th>
                  <th>Access</th>
                </tr>
              </thead>
              <tbody>
                {uses.map((u, i) => (
                  <tr key={i}>
                    <td>
                      <button type="button" className="rs-link-button" onClick={() => revealPlace(ctx, u)}>
                        {placeName(u)}
                      </button>
                    </td>
                    <td>
                      {u.elementKind} {u.detail}
                      {u.pin && u.pin !== 'instance' ? `.${u.pin}` : ''}
                    </td>
                    <td className="rs-mono">{u.operand}</td>
                    <td>{u.access}</td>
                  </tr>
                ))}
              </tbody>
            </table>
          )
        )
      ) : (
        <Summary
          list={summary}
          project={project}
          pick={(s) => {
            setName(s.variable.name);
            setScope(s.scope);
            setView('uses');
          }}
        />
      )}
      {view === 'uses' && name.trim() && resolved && <p data-testid="xref-count">{uses.length} uses</p>}
    </div>
  );
}
