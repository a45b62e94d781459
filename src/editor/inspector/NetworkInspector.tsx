// The selected network: label (jump target), title, comment, size, collapsed.
import { elementSize } from '../../model/factory';
import type { Network } from '../../model/project';
import { selectLibrary, useDocument, useDocumentStore } from '../../store/documentStore';
import { CommitInput, CommitTextArea } from '../variables/CommitInput';
import { labelProblem } from './networkLabel';

export function NetworkInspector({
  network,
  index,
  otherLabels,
}: {
  network: Network;
  index: number;
  otherLabels: readonly string[];
}) {
  const store = useDocumentStore();
  const library = useDocument(selectLibrary);
  const update = (patch: Parameters<ReturnType<typeof store.getState>['updateNetwork']>[1]) =>
    store.getState().updateNetwork(network.id, patch);
  const needRows = Math.max(
    1,
    ...network.elements.map((e) => e.row + elementSize(e, library).rows),
    ...network.vlinks.map((v) => v.row + 2),
  );
  const needCols = Math.max(
    1,
    ...network.elements.map((e) => e.col + elementSize(e, library).cols),
    ...network.vlinks.map((v) => v.boundary),
  );
  const problem = labelProblem(network.label ?? '', otherLabels);
  const size = (text: string, need: number, field: 'rows' | 'cols') => {
    const n = Math.round(Number(text));
    if (Number.isFinite(n))
      update({ [field]: Math.min(field === 'rows' ? 10_000 : 1_000, Math.max(need, n)) });
  };
  return (
    <div data-testid="network-inspector">
      <h2>Network {index + 1}</h2>
      <p className="rs-inspector-where">
        {network.elements.length} element{network.elements.length === 1 ? '' : 's'}
      </p>
      <div className="rs-field">
        <label htmlFor={`label-${network.id}`}>Label</label>
        <CommitInput
          id={`label-${network.id}`}
          className="rs-cell-input rs-mono"
          placeholder="jump target"
          value={network.label ?? ''}
          onCommit={(label) => update({ label: label.trim() })}
          {...(problem ? { 'aria-invalid': true, title: problem } : {})}
        />
        {problem && <p className="rs-binding-info rs-error-text">{problem}</p>}
      </div>
      <div className="rs-field">
        <label htmlFor={`title-${network.id}`}>Title</label>
        <CommitInput
          id={`title-${network.id}`}
          className="rs-cell-input"
          value={network.title}
          onCommit={(title) => update({ title })}
        />
      </div>
      <div className="rs-field">
        <label htmlFor={`comment-${network.id}`}>Comment</label>
        <CommitTextArea
          id={`comment-${network.id}`}
          value={network.comment}
          onCommit={(comment) => update({ comment })}
        />
      </div>
      <div className="rs-field">
        <label htmlFor={`rows-${network.id}`}>Rows</label>
        <CommitInput
          id={`rows-${network.id}`}
          type="number"
          min={needRows}
          className="rs-cell-input"
          value={String(network.rows)}
          onCommit={(t) => size(t, needRows, 'rows')}
        />
        <label htmlFor={`cols-${network.id}`}>Columns</label>
        <CommitInput
          id={`cols-${network.id}`}
          type="number"
          min={needCols}
          className="rs-cell-input"
          value={String(network.cols)}
          onCommit={(t) => size(t, needCols, 'cols')}
        />
        <label htmlFor={`collapsed-${network.id}`}>Collapsed</label>
        <input
          id={`collapsed-${network.id}`}
          type="checkbox"
          checked={network.collapsed === true}
          onChange={(e) => update({ collapsed: e.target.checked })}
        />
      </div>
    </div>
  );
}
