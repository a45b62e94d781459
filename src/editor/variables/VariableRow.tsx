// One row of the variable table: every field edits the document as one undoable step on commit.
import { useRef, useState, type KeyboardEvent } from 'react';
import { FB_SIGNATURES } from '../../model/blocks';
import { ELEMENTARY_TYPES, parseLocation } from '../../model/iecTypes';
import type { BlockLibrary } from '../../model/library';
import type { DataType, GlobalScope, Variable, VarClass } from '../../model/project';
import { TypeChoices } from '../dataTypes/TypeField';
import { CommitInput } from './CommitInput';
import { canonicalLocation, type VariableField } from './validation';
import { classForTyped } from './tableKeys';

export const CLASS_LABELS: Record<VarClass, string> = {
  input: 'VAR_INPUT',
  output: 'VAR_OUTPUT',
  inOut: 'VAR_IN_OUT',
  external: 'VAR_EXTERNAL',
  local: 'VAR',
  temp: 'VAR_TEMP',
};

/** The order of classes in the table: the POU's interface (inputs, outputs, in-outs) first. */
export const CLASS_ORDER: readonly VarClass[] = ['input', 'output', 'inOut', 'external', 'local', 'temp'];

const FIELD_WORDS: Record<VariableField, string> = {
  name: 'Name',
  type: 'Type',
  varClass: 'Class',
  location: 'Address',
  initial: 'Initial value',
  retain: 'RETAIN',
  constant: 'CONSTANT',
};

interface Props {
  readonly variable: Variable;
  readonly issues: Partial<Record<VariableField, string>>;
  readonly showClass: boolean;
  /** Globals: where the global is declared (configuration or resource) instead of a class. */
  readonly showScope?: boolean;
  /** The project's blocks: FB instance types offered, standard and the project's own. */
  readonly library: BlockLibrary;
  /** The project's data types, offered as types. */
  readonly dataTypes?: readonly DataType[] | undefined;
  /** First row of its class: drawn with a separator above it. */
  readonly firstOfClass?: boolean;
  readonly focusName: boolean;
  /** How many elements use the variable; showing them cycles through the uses. */
  readonly useCount: number;
  readonly onShowUse: () => void;
  readonly onChange: (patch: Partial<Variable>) => void;
  readonly onDelete: () => void;
}

const OTHER_TYPE = '\u0000other';

/** One group of the type picker (left out when empty). */
function TypeGroup({ label, names }: { readonly label: string; readonly names: readonly string[] }) {
  if (names.length === 0) return null;
  return (
    <optgroup label={label}>
      {names.map((t) => (
        <option key={t} value={t}>
          {t}
        </option>
      ))}
    </optgroup>
  );
}
const TYPED_TYPE_LIST = 'rs-variable-type-choices';

/** Empty text clears an optional field; an address is written in its canonical spelling. */
const optional = (text: string): string | undefined => (text.trim() === '' ? undefined : text.trim());
const normaliseLocation = (text: string): string | undefined => {
  const t = optional(text);
  const loc = t ? parseLocation(t) : undefined;
  return loc ? canonicalLocation(loc) : t;
};

export function VariableRow({
  variable: v,
  issues,
  showClass,
  showScope = false,
  library,
  dataTypes = [],
  firstOfClass = false,
  focusName,
  useCount,
  onShowUse,
  onChange,
  onDelete,
}: Props) {
  const userFbs = library.userBlocks.filter((s) => s.kind === 'fb');
  const typeKnown =
    (ELEMENTARY_TYPES as readonly string[]).includes(v.type) ||
    FB_SIGNATURES.some((s) => s.name === v.type) ||
    userFbs.some((s) => s.name === v.type) ||
    dataTypes.some((t) => t.name === v.type);
  // "Other type...": the type is typed instead of picked: ARRAY[1..10] OF INT, STRING[20], or an
  // anonymous STRUCT X : INT; END_STRUCT, enumeration (Idle, Run) or subrange INT (0..100).
  const [typing, setTyping] = useState(false);
  // The class is typed: letters pick the class they begin (`in` VAR_INPUT, `o` VAR_OUTPUT, `in_`
  // VAR_IN_OUT, `t` VAR_TEMP), arrows step through the classes; a pause of a second starts anew.
  const typed = useRef({ text: '', at: 0 });
  const classKeys = (e: KeyboardEvent<HTMLSelectElement>) => {
    if (e.ctrlKey || e.altKey || e.metaKey) return;
    if (e.key === 'ArrowDown' || e.key === 'ArrowUp') {
      e.preventDefault();
      typed.current = { text: '', at: 0 };
      const i = CLASS_ORDER.indexOf(v.varClass) + (e.key === 'ArrowDown' ? 1 : -1);
      const next = CLASS_ORDER[Math.max(0, Math.min(CLASS_ORDER.length - 1, i))];
      if (next && next !== v.varClass) onChange({ varClass: next });
      return;
    }
    if (e.key.length !== 1 || !/[A-Za-z_]/.test(e.key)) return;
    e.preventDefault();
    const now = e.timeStamp;
    const text = (now - typed.current.at < 1000 ? typed.current.text : '') + e.key;
    typed.current = { text, at: now };
    const c = classForTyped(text);
    if (c && c !== v.varClass) onChange({ varClass: c });
    // `c` and `r` (no class begins so) switch CONSTANT and RETAIN, as VAR CONSTANT / VAR RETAIN.
    else if (!c && text.length === 1 && /c/i.test(text)) onChange({ constant: !v.constant || undefined });
    else if (!c && text.length === 1 && /r/i.test(text)) onChange({ retain: !v.retain });
  };
  const invalid = (field: VariableField) =>
    issues[field] ? { 'aria-invalid': true, title: issues[field] } : {};
  const messages = (Object.keys(issues) as VariableField[]).map((f) => `${FIELD_WORDS[f]}: ${issues[f]}`);
  return (
    <>
      <tr
        data-testid={`variable-row-${v.name}`}
        className={`rs-var-row${messages.length ? ' rs-has-issue' : ''}${firstOfClass ? ' rs-class-first' : ''}`}
      >
        {showClass && (
          <td data-col="class">
            <select
              aria-label="Class"
              className="rs-cell-input"
              value={v.varClass}
              title="Type the class: in (VAR_INPUT), o (VAR_OUTPUT), in_ (VAR_IN_OUT), v (VAR), e (VAR_EXTERNAL), t (VAR_TEMP), or use the arrows; c switches CONSTANT, r RETAIN"
              onKeyDown={classKeys}
              onChange={(e) => onChange({ varClass: e.target.value as VarClass })}
            >
              {CLASS_ORDER.map((c) => (
                <option key={c} value={c}>
                  {CLASS_LABELS[c]}
                </option>
              ))}
            </select>
          </td>
        )}
        {showScope && (
          <td data-col="class">
            <select
              aria-label="Declared in"
              title="Where the global is declared: the configuration or the resource (both are visible to every POU)"
              className="rs-cell-input"
              value={v.scope ?? 'configuration'}
              onChange={(e) => onChange({ scope: e.target.value as GlobalScope })}
            >
              <option value="configuration">configuration</option>
              <option value="resource">resource</option>
            </select>
          </td>
        )}
        <td data-col="name">
          <CommitInput
            aria-label="Name"
            className="rs-cell-input rs-var-name"
            value={v.name}
            autoFocus={focusName}
            onFocus={(e) => focusName && e.currentTarget.select()}
            spellCheck={false}
            onCommit={(name) => onChange({ name: name.trim() })}
            {...invalid('name')}
          />
        </td>
        <td data-col="type">
          {typing ? (
            <>
              <TypeChoices id={TYPED_TYPE_LIST} />
              <CommitInput
                aria-label="Type"
                className="rs-cell-input rs-mono"
                autoFocus
                list={TYPED_TYPE_LIST}
                spellCheck={false}
                placeholder="ARRAY[1..10] OF INT"
                value={v.type}
                onCommit={(type) => type.trim() && onChange({ type: type.trim() })}
                onBlur={() => setTyping(false)}
                {...invalid('type')}
              />
            </>
          ) : (
            <select
              aria-label="Type"
              className="rs-cell-input"
              value={v.type}
              onChange={(e) =>
                e.target.value === OTHER_TYPE ? setTyping(true) : onChange({ type: e.target.value })
              }
              {...invalid('type')}
            >
              {!typeKnown && <option value={v.type}>{v.type || '(choose)'}</option>}
              <TypeGroup label="Elementary types" names={ELEMENTARY_TYPES} />
              <TypeGroup label="This project's data types" names={dataTypes.map((t) => t.name)} />
              <TypeGroup label="This project's function blocks" names={userFbs.map((s) => s.name)} />
              <TypeGroup label="Function block instances" names={FB_SIGNATURES.map((s) => s.name)} />
              <option value={OTHER_TYPE}>Other type (ARRAY[..] OF, STRUCT, (A, B), STRING[n])…</option>
            </select>
          )}
        </td>
        <td data-col="address">
          <CommitInput
            aria-label="Address"
            className="rs-cell-input rs-mono"
            // No address: an explicit hint, never a grey "%QX0.0" that looks like one every variable shares.
            placeholder={library.isFbType(v.type) ? '' : 'no address'}
            title={v.location ? undefined : 'No address: type one (%IX0.0 input, %QX0.0 output, %MW0 memory) to map it to I/O or memory'}
            spellCheck={false}
            value={v.location ?? ''}
            onCommit={(text) => onChange({ location: normaliseLocation(text) })}
            {...invalid('location')}
          />
        </td>
        <td data-col="initial">
          <CommitInput
            aria-label="Initial value"
            className="rs-cell-input rs-mono"
            spellCheck={false}
            value={v.initial ?? ''}
            onCommit={(text) => onChange({ initial: optional(text) })}
            {...invalid('initial')}
          />
        </td>
        <td className="rs-center" data-col="retain">
          <input
            type="checkbox"
            aria-label="RETAIN"
            checked={v.retain}
            onChange={(e) => onChange({ retain: e.target.checked })}
            {...invalid('retain')}
          />
        </td>
        <td className="rs-center" data-col="constant">
          <input
            type="checkbox"
            aria-label="CONSTANT"
            checked={v.constant === true}
            onChange={(e) => onChange({ constant: e.target.checked || undefined })}
          />
        </td>
        <td data-col="comment">
          <CommitInput
            aria-label="Comment"
            placeholder="Comment"
            className="rs-cell-input"
            value={v.comment}
            onCommit={(comment) => onChange({ comment })}
          />
        </td>
        <td className="rs-center" data-col="uses">
          {useCount > 0 ? (
            <button
              type="button"
              className="rs-uses"
              aria-label={`Show uses of ${v.name}`}
              title={`Used by ${useCount} element${useCount === 1 ? '' : 's'}; click to show ${useCount === 1 ? 'it' : 'the next'} on the canvas`}
              onClick={onShowUse}
            >
              {useCount}
            </button>
          ) : (
            <span className="rs-unused" title="Not used in the program">
              –
            </span>
          )}
        </td>
        <td data-col="actions">
          <button
            type="button"
            className="rs-icon-button"
            aria-label={`Delete variable ${v.name}`}
            title={`Delete variable ${v.name}`}
            onClick={onDelete}
          >
            ×
          </button>
        </td>
      </tr>
      {messages.length > 0 && (
        <tr className="rs-var-issues">
          <td colSpan={showClass || showScope ? 10 : 9} role="alert" data-testid="variable-issue">
            <div className="rs-var-issue-text">{messages.join(' · ')}</div>
          </td>
        </tr>
      )}
    </>
  );
}
