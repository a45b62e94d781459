// Which data types are open as tabs beside the POU tabs, and whether one of them is shown in the
// main area instead of the canvas. Not part of the document's history: one small store per
// document store (so two editors never share tabs). Names that no longer exist (after an undo or
// a delete) are simply not shown.
import { createStore, useStore, type StoreApi } from 'zustand';
import { useDocument, useDocumentStore, type DocumentStore } from '../../store/documentStore';

export interface DataTypeTabsState {
  readonly open: readonly string[];
  /** The data type shown in the main area; undefined: the active POU is shown. */
  readonly shown: string | undefined;
  openType(name: string): void;
  closeType(name: string): void;
  /** Back to the active POU (its tab was clicked, or another POU was opened). */
  showPou(): void;
  /** A rename: the tab follows. */
  renamed(from: string, to: string): void;
}

const same = (a: string, b: string) => a.toUpperCase() === b.toUpperCase();

function createTabs(doc: DocumentStore): StoreApi<DataTypeTabsState> {
  const tabs = createStore<DataTypeTabsState>()((set, get) => ({
    open: [],
    shown: undefined,
    openType: (name) =>
      set({ open: get().open.some((n) => same(n, name)) ? get().open : [...get().open, name], shown: name }),
    closeType: (name) => {
      const open = get().open.filter((n) => !same(n, name));
      set({ open, shown: get().shown !== undefined && same(get().shown!, name) ? undefined : get().shown });
    },
    showPou: () => get().shown !== undefined && set({ shown: undefined }),
    renamed: (from, to) =>
      set({
        open: get().open.map((n) => (same(n, from) ? to : n)),
        shown: get().shown !== undefined && same(get().shown!, from) ? to : get().shown,
      }),
  }));
  // Opening another POU (tree, problems, find, go to) shows it; a new project closes the tabs.
  doc.subscribe((s, prev) => {
    if (s.activePouId !== prev.activePouId) tabs.getState().showPou();
    if (s.project !== prev.project && s.history.undo.length === 0 && s.revision !== prev.revision && !s.dirty)
      tabs.setState({ open: [], shown: undefined });
  });
  return tabs;
}

const stores = new WeakMap<DocumentStore, StoreApi<DataTypeTabsState>>();

export function dataTypeTabs(doc: DocumentStore): StoreApi<DataTypeTabsState> {
  let tabs = stores.get(doc);
  if (!tabs) stores.set(doc, (tabs = createTabs(doc)));
  return tabs;
}

export function useDataTypeTabs<T>(selector: (s: DataTypeTabsState) => T): T {
  return useStore(dataTypeTabs(useDocumentStore()), selector);
}

/** The data type shown in the main area, when it still exists in the project. */
export function useShownDataType(): string | undefined {
  const shown = useDataTypeTabs((s) => s.shown);
  const exists = useDocument((s) => shown !== undefined && (s.project.dataTypes ?? []).some((t) => same(t.name, shown)));
  return exists ? shown : undefined;
}
