// A type name typed or picked from the project's types (elementary, data types, FBs); inline
// `ARRAY[1..10] OF INT` and `STRING[20]` may be typed too. Commits on Enter or when leaving.
import { selectProject, useDocument } from '../../store/documentStore';
import { CommitInput } from '../variables/CommitInput';
import { typeChoices } from './typeText';

export const TYPE_LIST_ID = 'rs-datatype-type-choices';

/** The datalist a TypeField completes from (id TYPE_LIST_ID unless given); render once per view. */
export function TypeChoices({ id = TYPE_LIST_ID }: { readonly id?: string }) {
  const project = useDocument(selectProject);
  const { elementary, dataTypes, fbs } = typeChoices(project);
  return (
    <datalist id={id}>
      {dataTypes.map((t) => (
        <option key={`d-${t}`} value={t}>
          data type
        </option>
      ))}
      {elementary.map((t) => (
        <option key={`e-${t}`} value={t} />
      ))}
      {fbs.map((t) => (
        <option key={`f-${t}`} value={t}>
          function block
        </option>
      ))}
    </datalist>
  );
}

export function TypeField(p: {
  readonly value: string;
  readonly label: string;
  readonly issue?: string | undefined;
  readonly onCommit: (type: string) => void;
}) {
  return (
    <CommitInput
      aria-label={p.label}
      className="rs-cell-input rs-mono"
      list={TYPE_LIST_ID}
      spellCheck={false}
      value={p.value}
      onCommit={(t) => t.trim() !== '' && p.onCommit(t.trim())}
      {...(p.issue ? { 'aria-invalid': true, title: p.issue } : {})}
    />
  );
}
