// The body of the data-type editor, one per kind: enumeration values, structure members, array
// dimensions and element type, subrange base and bounds, alias base. Every edit hands the whole new
// definition to `onChange` (one undo step); problems mark their field (see validation.ts).
import type { DataTypeDef } from '../../model/project';
import { CommitInput } from '../variables/CommitInput';
import { freshName, moveBy, removeAt, replaceAt, wholeNumber } from './listEdits';
import { TypeField } from './TypeField';
import { SUBRANGE_BASES } from './typeText';

type Def<K extends DataTypeDef['kind']> = Extract<DataTypeDef, { kind: K }>;

interface EditorProps<K extends DataTypeDef['kind']> {
  readonly def: Def<K>;
  readonly issue: (field: string) => string | undefined;
  readonly onChange: (def: Def<K>) => void;
}

const invalid = (message: string | undefined) => (message ? { 'aria-invalid': true, title: message } : {});

function RowActions(p: { what: string; index: number; count: number; onMove: (delta: number) => void; onRemove: () => void }) {
  return (
    <span className="rs-dt-row-actions">
      <button type="button" className="rs-icon-button" aria-label={`Move ${p.what} up`} title="Move up"
        disabled={p.index === 0} onClick={() => p.onMove(-1)}>↑</button>
      <button type="button" className="rs-icon-button" aria-label={`Move ${p.what} down`} title="Move down"
        disabled={p.index === p.count - 1} onClick={() => p.onMove(1)}>↓</button>
      <button type="button" className="rs-icon-button" aria-label={`Remove ${p.what}`} title={`Remove ${p.what}`}
        onClick={p.onRemove}>×</button>
    </span>
  );
}

export function EnumEditor({ def, issue, onChange }: EditorProps<'enum'>) {
  const set = (values: string[]) => onChange({ ...def, values });
  return (
    <div className="rs-dt-section" aria-label="Values">
      <h3>Values</h3>
      <ol className="rs-dt-list" data-testid="enum-values">
        {def.values.map((v, i) => (
          <li key={`${i}-${v}`}>
            <CommitInput aria-label={`Value ${i + 1}`} className="rs-cell-input rs-mono" spellCheck={false} value={v}
              onCommit={(t) => t.trim() && set(replaceAt(def.values, i, t.trim()))} {...invalid(issue(`value:${i}`))} />
            <RowActions what={`value ${v}`} index={i} count={def.values.length}
              onMove={(d) => set(moveBy(def.values, i, d))} onRemove={() => set(removeAt(def.values, i))} />
          </li>
        ))}
      </ol>
      <button type="button" className="rs-button" data-testid="add-enum-value"
        onClick={() => set([...def.values, freshName(def.values, 'VALUE')])}>+ Value</button>
    </div>
  );
}

type Member = Def<'struct'>['members'][number];

export function StructEditor({ def, issue, onChange }: EditorProps<'struct'>) {
  const set = (members: Member[]) => onChange({ ...def, members });
  const edit = (i: number, patch: Partial<Member>) => {
    const m: Record<string, unknown> = { ...def.members[i]!, ...patch };
    for (const k of ['initial', 'comment']) if (m[k] === undefined || m[k] === '') delete m[k];
    set(replaceAt(def.members, i, m as unknown as Member));
  };
  return (
    <div className="rs-dt-section">
      <h3>Members</h3>
      <table className="rs-dt-table" aria-label="Members" data-testid="struct-members">
        <thead>
          <tr><th>Name</th><th>Type</th><th>Initial value</th><th>Comment</th><th /></tr>
        </thead>
        <tbody>
          {def.members.map((m, i) => (
            <tr key={`${i}-${m.name}`} data-testid={`member-row-${m.name}`}>
              <td>
                <CommitInput aria-label="Member name" className="rs-cell-input rs-mono" spellCheck={false} value={m.name}
                  onCommit={(t) => t.trim() && edit(i, { name: t.trim() })} {...invalid(issue(`member:${i}:name`))} />
              </td>
              <td>
                <TypeField label="Member type" value={m.type} issue={issue(`member:${i}:type`)} onCommit={(type) => edit(i, { type })} />
              </td>
              <td>
                <CommitInput aria-label="Member initial value" className="rs-cell-input rs-mono" spellCheck={false}
                  value={m.initial ?? ''} onCommit={(t) => edit(i, { initial: t.trim() })} />
              </td>
              <td>
                <CommitInput aria-label="Member comment" className="rs-cell-input" value={m.comment ?? ''}
                  onCommit={(t) => edit(i, { comment: t.trim() })} />
              </td>
              <td>
                <RowActions what={`member ${m.name}`} index={i} count={def.members.length}
                  onMove={(d) => set(moveBy(def.members, i, d))} onRemove={() => set(removeAt(def.members, i))} />
              </td>
            </tr>
          ))}
        </tbody>
      </table>
      <button type="button" className="rs-button" data-testid="add-struct-member"
        onClick={() => set([...def.members, { name: freshName(def.members.map((m) => m.name), 'Member'), type: 'INT' }])}>
        + Member
      </button>
    </div>
  );
}

type Dim = Def<'array'>['dims'][number];

export function ArrayEditor({ def, issue, onChange }: EditorProps<'array'>) {
  const setDims = (dims: Dim[]) => onChange({ ...def, dims });
  const bound = (i: number, key: keyof Dim, text: string) => {
    const n = wholeNumber(text);
    if (n !== undefined) setDims(replaceAt(def.dims, i, { ...def.dims[i]!, [key]: n }));
  };
  return (
    <div className="rs-dt-section">
      <h3>Dimensions</h3>
      <ol className="rs-dt-list" data-testid="array-dims">
        {def.dims.map((d, i) => (
          <li key={i}>
            <CommitInput aria-label={`Dimension ${i + 1} lower bound`} className="rs-cell-input rs-mono rs-dt-bound"
              value={String(d.lower)} onCommit={(t) => bound(i, 'lower', t)} {...invalid(issue(`dim:${i}`))} />
            <span className="rs-mono"> .. </span>
            <CommitInput aria-label={`Dimension ${i + 1} upper bound`} className="rs-cell-input rs-mono rs-dt-bound"
              value={String(d.upper)} onCommit={(t) => bound(i, 'upper', t)} {...invalid(issue(`dim:${i}`))} />
            <RowActions what={`dimension ${i + 1}`} index={i} count={def.dims.length}
              onMove={(delta) => setDims(moveBy(def.dims, i, delta))} onRemove={() => setDims(removeAt(def.dims, i))} />
          </li>
        ))}
      </ol>
      <button type="button" className="rs-button" data-testid="add-array-dim"
        onClick={() => setDims([...def.dims, { lower: 0, upper: 9 }])}>+ Dimension</button>
      <label className="rs-dt-field">
        <span>Element type</span>
        <TypeField label="Element type" value={def.of} issue={issue('of')} onCommit={(of) => onChange({ ...def, of })} />
      </label>
    </div>
  );
}

export function SubrangeEditor({ def, issue, onChange }: EditorProps<'subrange'>) {
  const bound = (key: 'lower' | 'upper', text: string) => {
    const n = wholeNumber(text);
    if (n !== undefined) onChange({ ...def, [key]: n });
  };
  const known = (SUBRANGE_BASES as readonly string[]).includes(def.base.toUpperCase());
  return (
    <div className="rs-dt-section">
      <label className="rs-dt-field">
        <span>Base type</span>
        <select aria-label="Base type" className="rs-cell-input" value={def.base.toUpperCase()}
          onChange={(e) => onChange({ ...def, base: e.target.value })} {...invalid(issue('base'))}>
          {!known && <option value={def.base.toUpperCase()}>{def.base}</option>}
          {SUBRANGE_BASES.map((b) => <option key={b} value={b}>{b}</option>)}
        </select>
      </label>
      <label className="rs-dt-field">
        <span>Range</span>
        <CommitInput aria-label="Lower bound" className="rs-cell-input rs-mono rs-dt-bound" value={String(def.lower)}
          onCommit={(t) => bound('lower', t)} {...invalid(issue('bounds'))} />
        <span className="rs-mono"> .. </span>
        <CommitInput aria-label="Upper bound" className="rs-cell-input rs-mono rs-dt-bound" value={String(def.upper)}
          onCommit={(t) => bound('upper', t)} {...invalid(issue('bounds'))} />
      </label>
    </div>
  );
}

export function AliasEditor({ def, issue, onChange }: EditorProps<'alias'>) {
  return (
    <div className="rs-dt-section">
      <label className="rs-dt-field">
        <span>Same as</span>
        <TypeField label="Base type" value={def.base} issue={issue('base')} onCommit={(base) => onChange({ ...def, base })} />
      </label>
    </div>
  );
}
