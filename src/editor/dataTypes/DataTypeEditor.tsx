// The data-type editor shown in the main area when a data type's tab is open: its kind-specific
// body, the initial value and comment, the problems found (each also marks its field), and the
// declaration as IEC text.
import type { DataTypeDef } from '../../model/project';
import { DATA_TYPE_KIND_WORDS } from '../../store/dataTypeCommands';
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { CommitInput } from '../variables/CommitInput';
import { AliasEditor, ArrayEditor, EnumEditor, StructEditor, SubrangeEditor } from './DefEditors';
import { TypeChoices } from './TypeField';
import { declarationText } from './typeText';
import { dataTypeProblems } from './validation';
import './dataTypes.css';

const INITIAL_HINTS: Record<DataTypeDef['kind'], string> = {
  enum: 'a value, e.g. GREEN',
  struct: '(X := 1, Y := 2)',
  array: '[1, 2, 3] or [10(0)]',
  subrange: 'a number in the range',
  alias: 'a value of the base type',
};

export function DataTypeEditor({ name }: { readonly name: string }) {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const t = (project.dataTypes ?? []).find((x) => x.name.toUpperCase() === name.toUpperCase());
  if (!t) return <p className="rs-dt-missing">The data type {name} is no longer in the project.</p>;
  const problems = dataTypeProblems(project, t);
  const issue = (field: string) => problems.find((p) => p.field === field)?.message;
  const update = store.getState().updateDataType;
  const setDef = (def: DataTypeDef) => update(t.name, { def });
  const def = t.def;
  return (
    <section className="rs-dt-editor" aria-label={`Data type ${t.name}`} data-testid={`datatype-editor-${t.name}`}>
      <TypeChoices />
      <header className="rs-dt-header">
        <h2>
          <span className="rs-kind-icon" aria-hidden="true">T</span> <span className="rs-mono">{t.name}</span>{' '}
          <span className="rs-dt-kind">{DATA_TYPE_KIND_WORDS[def.kind]}</span>
        </h2>
        <CommitInput aria-label="Data type comment" placeholder="Comment" className="rs-cell-input rs-dt-comment"
          value={t.comment ?? ''} onCommit={(comment) => update(t.name, { comment })} />
      </header>
      {def.kind === 'enum' && <EnumEditor def={def} issue={issue} onChange={setDef} />}
      {def.kind === 'struct' && <StructEditor def={def} issue={issue} onChange={setDef} />}
      {def.kind === 'array' && <ArrayEditor def={def} issue={issue} onChange={setDef} />}
      {def.kind === 'subrange' && <SubrangeEditor def={def} issue={issue} onChange={setDef} />}
      {def.kind === 'alias' && <AliasEditor def={def} issue={issue} onChange={setDef} />}
      <label className="rs-dt-field">
        <span>Initial value</span>
        {def.kind === 'enum' ? (
          <select aria-label="Initial value" className="rs-cell-input rs-mono" value={t.initial ?? ''}
            onChange={(e) => update(t.name, { initial: e.target.value })}>
            <option value="">(first value)</option>
            {def.values.map((v) => <option key={v} value={v}>{v}</option>)}
          </select>
        ) : (
          <CommitInput aria-label="Initial value" className="rs-cell-input rs-mono" spellCheck={false}
            placeholder={INITIAL_HINTS[def.kind]} value={t.initial ?? ''} onCommit={(initial) => update(t.name, { initial })} />
        )}
      </label>
      {problems.length > 0 && (
        <ul className="rs-dt-problems" role="alert" data-testid="datatype-problems">
          {problems.map((p, i) => <li key={i} className="rs-error-text">{t.name}: {p.message}</li>)}
        </ul>
      )}
      <h3>Declaration</h3>
      <pre className="rs-dt-text rs-mono" data-testid="datatype-text">{declarationText(t)}</pre>
    </section>
  );
}
