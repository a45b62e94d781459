// The selected element: what it is, where it is, and its variable / type / target.
import {
  COIL_TYPES,
  CONTACT_TYPES,
  type CoilType,
  type ContactType,
  type LdElement,
} from '../../model/elements';
import type { Network } from '../../model/project';
import { useDocumentStore } from '../../store/documentStore';
import { CommitInput, CommitTextArea } from '../variables/CommitInput';
import { BindingField } from './BindingField';
import { BoxInspector } from './BoxInspector';
import { ConnectionInspector } from './ConnectionInspector';
import { COIL_WORDS, CONTACT_WORDS, elementTitle } from './elementWords';

interface Props {
  readonly element: LdElement;
  readonly network: Network;
  readonly networkIndex: number;
  readonly labels: readonly string[];
}

export function ElementInspector({ element: el, network, networkIndex, labels }: Props) {
  const store = useDocumentStore();
  const update = store.getState().updateElement;
  return (
    <div data-testid="element-inspector">
      <h2>{elementTitle(el)}</h2>
      <p className="rs-inspector-where">
        Network {networkIndex + 1}
        {network.label ? ` (${network.label})` : ''} · row {el.row + 1}, column {el.col + 1}
      </p>
      {el.kind === 'contact' && (
        <>
          <div className="rs-field">
            <label htmlFor={`kind-${el.id}`}>Contact</label>
            <select
              id={`kind-${el.id}`}
              className="rs-cell-input"
              value={el.contact}
              onChange={(e) => update(el.id, { contact: e.target.value as ContactType })}
            >
              {CONTACT_TYPES.map((t) => (
                <option key={t} value={t}>
                  {CONTACT_WORDS[t]}
                </option>
              ))}
            </select>
          </div>
          {el.contact !== 'NOT' && (
            <BindingField
              label="Variable"
              value={el.variable}
              role={{ kind: 'contact' }}
              placeholder="BOOL variable, T1.Q or Word.3"
              testId="inspector-variable"
              resetKey={el.id}
              onCommit={(variable) => update(el.id, { variable })}
            />
          )}
        </>
      )}
      {el.kind === 'coil' && (
        <>
          <div className="rs-field">
            <label htmlFor={`kind-${el.id}`}>Coil</label>
            <select
              id={`kind-${el.id}`}
              className="rs-cell-input"
              value={el.coil}
              onChange={(e) => update(el.id, { coil: e.target.value as CoilType })}
            >
              {COIL_TYPES.map((t) => (
                <option key={t} value={t}>
                  {COIL_WORDS[t]}
                </option>
              ))}
            </select>
          </div>
          <BindingField
            label="Variable"
            value={el.variable}
            role={{ kind: 'coil' }}
            placeholder="BOOL variable"
            testId="inspector-variable"
            resetKey={el.id}
            onCommit={(variable) => update(el.id, { variable })}
          />
        </>
      )}
      {el.kind === 'jump' && (
        <div className="rs-field">
          <label htmlFor={`target-${el.id}`}>Jump to</label>
          <CommitInput
            id={`target-${el.id}`}
            className="rs-cell-input rs-mono"
            list={`labels-${el.id}`}
            placeholder="network label"
            value={el.target}
            onCommit={(target) => update(el.id, { target: target.trim() })}
            {...(el.target && !labels.some((l) => l.toUpperCase() === el.target.toUpperCase())
              ? { 'aria-invalid': true, title: `No network is labelled ${el.target}` }
              : {})}
          />
          <datalist id={`labels-${el.id}`}>
            {labels.map((l) => (
              <option key={l} value={l} />
            ))}
          </datalist>
          {labels.length === 0 && (
            <p className="rs-binding-info">No network has a label yet: select a network and give it one.</p>
          )}
        </div>
      )}
      {el.kind === 'return' && <p>When powered, the POU ends for this scan.</p>}
      {el.kind === 'link' && <p>Copies the state on its left to its right.</p>}
      {el.kind === 'box' && <BoxInspector box={el} />}
      {(el.kind === 'connector' || el.kind === 'continuation') && (
        <ConnectionInspector element={el} network={network} />
      )}
      {(el.kind === 'contact' || el.kind === 'coil' || el.kind === 'box') && (
        <div className="rs-field">
          <label htmlFor={`comment-${el.id}`}>Comment</label>
          <CommitTextArea
            id={`comment-${el.id}`}
            className="rs-cell-input"
            rows={2}
            data-testid="inspector-element-comment"
            resetKey={el.id}
            placeholder={
              el.kind === 'box' ? 'shown under the box' : "shown under the symbol, instead of the variable's comment"
            }
            title="This element's own comment (CODESYS operand comment): shown under it on the canvas and in print, kept in PLCopen exports"
            value={el.comment ?? ''}
            onCommit={(text) => update(el.id, { comment: text.trim() || undefined })}
          />
        </div>
      )}
    </div>
  );
}
