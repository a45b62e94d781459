// The inspector: the selected element, else the selected network, else the project.
import { useMemo } from 'react';
import { selectActivePou, useDocument } from '../../store/documentStore';
import { selectSelection, useUi } from '../../store/uiStore';
import { ElementInspector } from './ElementInspector';
import { NetworkInspector } from './NetworkInspector';
import { ProjectInspector } from './ProjectInspector';
import { elementTitle } from './elementWords';
import './inspector.css';

export function InspectorPanel() {
  const pou = useDocument(selectActivePou);
  const selection = useUi(selectSelection);
  const index = pou && selection.network ? pou.networks.findIndex((n) => n.id === selection.network) : -1;
  const network = pou?.networks[index];
  // The POU's labels, gathered again only when its networks change (not on every selection).
  const networks = pou?.networks;
  const labels = useMemo(() => (networks ?? []).flatMap((n) => (n.label ? [n.label] : [])), [networks]);
  const elements = network ? network.elements.filter((e) => selection.elements.includes(e.id)) : [];

  let body;
  if (!network) body = <ProjectInspector />;
  else if (elements.length === 1 && elements[0]) {
    body = (
      <ElementInspector
        // A contact or coil selected after another one keeps the inspector's fields (they drop what
        // was typed for the other by its id): a click builds no new form (docs/benchmarks.md).
        key={elements[0].kind === 'contact' || elements[0].kind === 'coil' ? elements[0].kind : elements[0].id}
        element={elements[0]}
        network={network}
        networkIndex={index}
        labels={labels}
      />
    );
  } else if (elements.length > 1) {
    body = (
      <div data-testid="multi-inspector">
        <h2>{elements.length} elements selected</h2>
        <ul>
          {elements.map((e) => (
            <li key={e.id}>
              {elementTitle(e)}
              {(e.kind === 'contact' || e.kind === 'coil') && e.variable ? ` ${e.variable}` : ''}
            </li>
          ))}
        </ul>
      </div>
    );
  } else {
    const others = (pou?.networks ?? [])
      .filter((n) => n.id !== network.id)
      .flatMap((n) => (n.label ? [n.label] : []));
    body = <NetworkInspector key={network.id} network={network} index={index} otherLabels={others} />;
  }
  return (
    <section className="rs-inspector" aria-label="Inspector" data-testid="inspector-panel">
      {body}
    </section>
  );
}
