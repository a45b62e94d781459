// The selected connector or continuation `>NAME>`: its name (renaming a connector renames its
// continuations too unless unticked, one undo step), its partners with a way to go to each, and
// the problems the checks report on it (LD-R14: unpaired, duplicate or unnamed).
import { useState } from 'react';
import type { Network } from '../../model/project';
import { cellName, connectionNamesFor, partnersOf, renameConnection, type ConnectionElement } from '../../store/connectors';
import { useDocumentStore } from '../../store/documentStore';
import { useUiStore } from '../../store/uiStore';
import { goToElement } from '../outline/goTo';
import { useDiagnostics } from '../problems/useDiagnostics';
import { CommitInput } from '../variables/CommitInput';

interface Props {
  readonly element: ConnectionElement;
  readonly network: Network;
}

export function ConnectionInspector({ element: el, network }: Props) {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const [pair, setPair] = useState(true);
  const problems = useDiagnostics().filter((d) => d.elementId === el.id);
  const partners = partnersOf(network, el);
  const names = connectionNamesFor(network, el);
  const connector = el.kind === 'connector';
  return (
    <>
      <div className="rs-field">
        <label htmlFor={`connection-${el.id}`}>Name</label>
        <CommitInput
          id={`connection-${el.id}`}
          className="rs-cell-input rs-mono"
          data-testid="inspector-connection-name"
          placeholder={connector ? 'C1' : 'name of a connector'}
          list={names.length ? `connections-${el.id}` : undefined}
          value={el.name}
          onCommit={(name) => renameConnection(doc, el.id, name, pair)}
          {...(problems.some((d) => d.severity === 'error') ? { 'aria-invalid': true } : {})}
        />
        {names.length > 0 && (
          <datalist id={`connections-${el.id}`}>
            {names.map((n) => (
              <option key={n} value={n} />
            ))}
          </datalist>
        )}
      </div>
      {connector && partners.length > 0 && (
        <label className="rs-check">
          <input
            type="checkbox"
            data-testid="inspector-rename-pair"
            checked={pair}
            onChange={(e) => setPair(e.target.checked)}
          />{' '}
          Renaming renames its {partners.length === 1 ? 'continuation' : `${partners.length} continuations`} too
        </label>
      )}
      <h3>{connector ? 'Continuations' : 'Connector'}</h3>
      {partners.length === 0 ? (
        <p className="rs-binding-info" data-testid="inspector-partners">
          {connector
            ? 'None yet: place a continuation of this name where the line goes on.'
            : 'None: place a connector of this name where the line ends.'}
        </p>
      ) : (
        <ul className="rs-connection-partners" data-testid="inspector-partners">
          {partners.map((p) => (
            <li key={p.id}>
              <button
                type="button"
                className="rs-button"
                data-testid={`inspector-partner-${cellName(p)}`}
                title={`Select the ${p.kind} at ${cellName(p)} (G goes from one to its partner)`}
                onClick={() => goToElement({ doc, ui }, network.id, p)}
              >
                Go to {p.kind} at {cellName(p)}
              </button>
            </li>
          ))}
        </ul>
      )}
      {problems.length > 0 && (
        <ul className="rs-connection-problems" data-testid="inspector-problems">
          {problems.map((d, i) => (
            <li key={i} className={d.severity === 'error' ? 'rs-error' : 'rs-warning'}>
              {d.rule}: {d.message}
            </li>
          ))}
        </ul>
      )}
    </>
  );
}
