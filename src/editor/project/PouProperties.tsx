// The open POU's properties: kind, a FUNCTION's return type, comment and language.
import { bodyLanguage } from '../../model/codesysUtil';
import { ELEMENTARY_TYPES } from '../../model/iecTypes';
import type { Pou, PouKind } from '../../model/project';
import { useDocumentStore } from '../../store/documentStore';
import { CommitInput } from '../variables/CommitInput';
import { KIND_TITLES } from './pouWords';

export function PouProperties({ pou }: { readonly pou: Pou }) {
  const store = useDocumentStore();
  const update = store.getState().updatePou;
  return (
    <div className="rs-pou-properties" data-testid="pou-properties">
      <h2>
        {KIND_TITLES[pou.kind]} <span className="rs-mono">{pou.name}</span>
      </h2>
      <div className="rs-field">
        <label htmlFor={`pou-kind-${pou.id}`}>Kind</label>
        <select
          id={`pou-kind-${pou.id}`}
          className="rs-cell-input"
          value={pou.kind}
          onChange={(e) => update(pou.id, { kind: e.target.value as PouKind })}
        >
          {(Object.keys(KIND_TITLES) as PouKind[]).map((k) => (
            <option key={k} value={k}>
              {KIND_TITLES[k]}
            </option>
          ))}
        </select>
        {pou.kind === 'FUNCTION' && (
          <>
            <label htmlFor={`pou-return-${pou.id}`}>Return type</label>
            <select
              id={`pou-return-${pou.id}`}
              className="rs-cell-input"
              data-testid="pou-return-type"
              title="The type of the function's result, its output pin OUT"
              value={pou.returnType ?? 'BOOL'}
              onChange={(e) => update(pou.id, { returnType: e.target.value })}
            >
              {!(ELEMENTARY_TYPES as readonly string[]).includes(pou.returnType ?? 'BOOL') && (
                <option value={pou.returnType}>{pou.returnType}</option>
              )}
              {ELEMENTARY_TYPES.map((t) => (
                <option key={t} value={t}>
                  {t}
                </option>
              ))}
            </select>
          </>
        )}
        <label htmlFor={`pou-comment-${pou.id}`}>Comment</label>
        <CommitInput
          id={`pou-comment-${pou.id}`}
          className="rs-cell-input"
          value={pou.comment}
          onCommit={(comment) => update(pou.id, { comment })}
        />
      </div>
      <p className="rs-tree-detail">
        Language {bodyLanguage(pou)}
        {pou.language === 'LD' ? '' : pou.language === 'FBD' ? ` (read-only; ${bodyLanguage(pou)} bodies are not run: LD-E51)` : ' (runs; read-only: the editor edits LD only)'}
      </p>
    </div>
  );
}
