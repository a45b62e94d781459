// The open POUs (then the open data types) as tabs above the canvas: click to show one, × (or middle click) to close it.
import type { PouId } from '../../model/ids';
import {
  selectActivePouId,
  selectOpenPouIds,
  selectProject,
  useDocument,
  useDocumentStore,
} from '../../store/documentStore';
import { DataTypeTabs } from '../dataTypes/TypeTabs';
import { dataTypeTabs, useDataTypeTabs } from '../dataTypes/dataTypeTabs';
import { InstancePicker } from '../sim/InstancePicker';
import { KIND_ICONS, KIND_TITLES } from './pouWords';

export function PouTabs() {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const open = useDocument(selectOpenPouIds);
  const active = useDocument(selectActivePouId);
  const typeShown = useDataTypeTabs((s) => s.shown) !== undefined;
  const close = (id: PouId) => store.getState().closePou(id);
  return (
    <>
      <div className="rs-pou-tabs" role="tablist" aria-label="Open POUs" data-testid="pou-tabs">
        {open.map((id) => {
          const pou = project.pous.find((p) => p.id === id);
          if (!pou) return null;
          const selected = id === active && !typeShown;
          return (
            <div key={id} className={selected ? 'rs-pou-tab rs-active' : 'rs-pou-tab'}>
              <button
                type="button"
                role="tab"
                aria-selected={selected}
                data-testid={`pou-tab-${pou.name}`}
                title={`${KIND_TITLES[pou.kind]} ${pou.name}${pou.language === 'LD' ? '' : ` (${pou.language}, read-only)`}`}
                onClick={() => {
                  store.getState().setActivePou(id);
                  dataTypeTabs(store).getState().showPou();
                }}
                onAuxClick={(e) => e.button === 1 && close(id)}
              >
                <span className={`rs-kind-icon rs-kind-${pou.kind}`} aria-hidden="true">
                  {KIND_ICONS[pou.kind]}
                </span>
                <span className="rs-mono">{pou.name}</span>
              </button>
              {open.length > 1 && (
                <button
                  type="button"
                  className="rs-pou-tab-close"
                  aria-label={`Close ${pou.name}`}
                  title={`Close ${pou.name}`}
                  onClick={() => close(id)}
                >
                  ×
                </button>
              )}
            </div>
          );
        })}
        <DataTypeTabs />
      </div>
      {/* While simulating: which instance of the shown FB the canvas monitors. */}
      <InstancePicker />
    </>
  );
}
