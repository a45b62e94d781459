// The open data types as tabs after the POU tabs: click shows the data-type editor, × closes.
import { selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { dataTypeTabs, useDataTypeTabs } from './dataTypeTabs';

export function DataTypeTabs() {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const open = useDataTypeTabs((s) => s.open);
  const shown = useDataTypeTabs((s) => s.shown);
  const tabs = () => dataTypeTabs(store).getState();
  return (
    <>
      {open.map((name) => {
        const t = (project.dataTypes ?? []).find((x) => x.name.toUpperCase() === name.toUpperCase());
        if (!t) return null;
        const selected = shown !== undefined && shown.toUpperCase() === name.toUpperCase();
        return (
          <div key={name} className={selected ? 'rs-pou-tab rs-active' : 'rs-pou-tab'}>
            <button type="button" role="tab" aria-selected={selected} data-testid={`datatype-tab-${t.name}`}
              title={`Data type ${t.name}`} onClick={() => tabs().openType(t.name)}
              onAuxClick={(e) => e.button === 1 && tabs().closeType(t.name)}>
              <span className="rs-kind-icon rs-kind-TYPE" aria-hidden="true">T</span>
              <span className="rs-mono">{t.name}</span>
            </button>
            <button type="button" className="rs-pou-tab-close" aria-label={`Close ${t.name}`} title={`Close ${t.name}`}
              onClick={() => tabs().closeType(t.name)}>×</button>
          </div>
        );
      })}
    </>
  );
}
