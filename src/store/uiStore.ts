// UI state of one editor: selection, tool, cursor cell, viewport, theme, inline editing.
// None of it enters the undo history; changing it never clears the redo stack.
//
// State
//   selection    { network, elements: ElementId[] } — the selected elements (one network at a time)
//   cursor       { network, row, col } | undefined — the keyboard cursor cell (drawn on the canvas)
//   tool         'select' | 'vlink' | { place: template } (see src/editor/palette/tools.ts)
//   viewport     { zoom, scrollLeft, scrollTop, width, height } in CSS pixels of the canvas scroll area
//   theme        'light' | 'dark'
//   focusRequest { network, cell, seq } — set by focusCell(); the canvas scrolls there and moves the cursor
//   editing      { element, pin?, joinUndo? } | undefined — the element whose variable (or, with
//                `pin`, whose box pin operand) is being typed inline; `joinUndo`: the undo step
//                (placing it) the name joins, so placing and naming undo together
//   blockPicker  { network, cell } | undefined — the searchable block picker is open for that cell
//   networkSelection  whole networks selected by their headers (click, Shift/Ctrl-click,
//                Shift+arrows); selecting elements clears it and the reverse
//   pastePrompt  network clip text waiting for the choice keep / new FB instances
//   finder       'find' | 'goto' | 'gotoExtend' | undefined — the find/replace panel or the go-to box is open
//                (gotoExtend: Ctrl+Shift+G, the network entered extends the network selection)
//   panels       sizes (CSS px) and collapsed flags of the shell's left, right and bottom panels, and
//                where the variable table is docked; remembered by src/editor/layout/panelSizes.ts
import { createElement, createContext, useContext, type ReactNode } from 'react';
import { createStore, useStore, type StoreApi } from 'zustand';
import type { Cell } from '../model/grid';
import type { HistoryEntry } from './history';
import type { ElementId, NetworkId } from '../model/ids';
import type { ElementTemplate } from './networkEdits';

export type Tool =
  | { readonly kind: 'select' }
  | { readonly kind: 'vlink' }
  | { readonly kind: 'place'; readonly template: ElementTemplate; readonly name: string };
export type Theme = 'light' | 'dark';

export interface Selection {
  readonly network: NetworkId | undefined;
  readonly elements: readonly ElementId[];
}

export interface CursorCell extends Cell {
  readonly network: NetworkId;
}

export interface Viewport {
  readonly zoom: number;
  readonly scrollLeft: number;
  readonly scrollTop: number;
  /** Size of the visible canvas area in CSS pixels (written by the canvas). */
  readonly width: number;
  readonly height: number;
}

/** The shell's panels: sizes in CSS pixels, collapsed flags, where the variable table sits. */
export interface PanelLayout {
  readonly left: number;
  readonly right: number;
  readonly bottom: number;
  readonly leftCollapsed: boolean;
  readonly rightCollapsed: boolean;
  readonly bottomCollapsed: boolean;
  /** 'bottom': the variable table is a full-width tab of the bottom panel (every column visible). */
  readonly variablesDock: 'side' | 'bottom';
}

export const DEFAULT_PANELS: PanelLayout = {
  left: 230,
  right: 340,
  bottom: 160,
  leftCollapsed: false,
  rightCollapsed: false,
  bottomCollapsed: false,
  variablesDock: 'side',
};

export const MIN_ZOOM = 0.25;
export const MAX_ZOOM = 3;

/** What the inline editor edits (see the file comment). */
export interface EditingState {
  readonly element: ElementId;
  /** A box pin ('PT', 'Q'): its operand is edited instead of the element's name. */
  readonly pin?: string;
  readonly joinUndo?: HistoryEntry;
}

export interface UiState {
  readonly selection: Selection;
  readonly cursor: CursorCell | undefined;
  readonly tool: Tool;
  readonly viewport: Viewport;
  readonly theme: Theme;
  readonly focusRequest:
    { readonly network: NetworkId; readonly cell: Cell; readonly seq: number } | undefined;
  readonly editing: EditingState | undefined;
  readonly blockPicker: { readonly network: NetworkId; readonly cell: Cell } | undefined;
  readonly networkSelection: readonly NetworkId[];
  readonly pastePrompt: { readonly text: string; readonly instances: readonly string[] } | undefined;
  readonly finder: 'find' | 'goto' | 'gotoExtend' | undefined;
  /** A short message for the status bar ("Nothing to paste"), cleared by the next action. */
  readonly status: string;
  readonly panels: PanelLayout;
  /** The network at the top of the canvas's view (the outline highlights it and keeps it visible). */
  readonly viewNetwork: NetworkId | undefined;
  /** View option: variables' comments under contacts, coils and box operands (remembered; off by default as in CODESYS). */
  readonly symbolComments: boolean;
  /** Elements are being dragged on the canvas (every network shows an empty row to drop on). */
  readonly dragging: boolean;

  select(network: NetworkId | undefined, elements: readonly ElementId[]): void;
  toggleSelected(network: NetworkId, element: ElementId): void;
  clearSelection(): void;
  setCursor(cursor: CursorCell | undefined): void;
  setTool(tool: Tool): void;
  setViewport(patch: Partial<Viewport>): void;
  setZoom(zoom: number): void;
  setTheme(theme: Theme): void;
  focusCell(network: NetworkId, cell: Cell): void;
  startEditing(element: ElementId, opts?: Omit<EditingState, 'element'>): void;
  stopEditing(): void;
  openBlockPicker(network: NetworkId, cell: Cell): void;
  closeBlockPicker(): void;
  setStatus(text: string): void;
  selectNetworks(ids: readonly NetworkId[]): void;
  setPastePrompt(p: UiState['pastePrompt']): void;
  setFinder(f: UiState['finder']): void;
  setPanels(patch: Partial<PanelLayout>): void;
  setSymbolComments(on: boolean): void;
  setViewNetwork(id: NetworkId | undefined): void;
  setDragging(on: boolean): void;
}

/** localStorage key of the "Show symbol comments" view option. */
export const SYMBOL_COMMENTS_KEY = 'rungsmith.symbolComments';

function savedSymbolComments(): boolean {
  try {
    return typeof localStorage !== 'undefined' && localStorage.getItem(SYMBOL_COMMENTS_KEY) === 'on';
  } catch {
    return false;
  }
}

export type UiStore = StoreApi<UiState>;

export const clampZoom = (z: number) => Math.min(MAX_ZOOM, Math.max(MIN_ZOOM, Math.round(z * 100) / 100));

export function createUiStore(initial: Partial<Pick<UiState, 'theme' | 'panels'>> = {}): UiStore {
  let seq = 0;
  return createStore<UiState>()((set, get) => ({
    selection: { network: undefined, elements: [] },
    cursor: undefined,
    tool: { kind: 'select' },
    viewport: { zoom: 1, scrollLeft: 0, scrollTop: 0, width: 800, height: 600 },
    theme: initial.theme ?? 'light',
    focusRequest: undefined,
    editing: undefined,
    blockPicker: undefined,
    status: '',
    networkSelection: [],
    pastePrompt: undefined,
    finder: undefined,
    panels: initial.panels ?? DEFAULT_PANELS,
    symbolComments: savedSymbolComments(),
    viewNetwork: undefined,
    dragging: false,

    select: (network, elements) =>
      set({
        selection: { network, elements: [...elements] },
        ...(get().networkSelection.length && (network || elements.length) ? { networkSelection: [] } : {}),
      }),
    toggleSelected: (network, element) => {
      if (get().networkSelection.length) set({ networkSelection: [] });
      const sel = get().selection;
      if (sel.network !== network) return set({ selection: { network, elements: [element] } });
      const has = sel.elements.includes(element);
      set({
        selection: {
          network,
          elements: has ? sel.elements.filter((e) => e !== element) : [...sel.elements, element],
        },
      });
    },
    clearSelection: () => set({ selection: { network: undefined, elements: [] }, networkSelection: [] }),
    setCursor: (cursor) => set({ cursor }),
    setTool: (tool) => set({ tool }),
    setDragging: (dragging) => {
      if (get().dragging !== dragging) set({ dragging });
    },
    setViewport: (patch) => set({ viewport: { ...get().viewport, ...patch } }),
    setZoom: (zoom) => set({ viewport: { ...get().viewport, zoom: clampZoom(zoom) } }),
    setTheme: (theme) => set({ theme }),
    focusCell: (network, cell) => {
      seq += 1;
      set({ focusRequest: { network, cell, seq }, cursor: { network, ...cell } });
    },
    startEditing: (element, opts) => set({ editing: { element, ...opts } }),
    stopEditing: () => set({ editing: undefined }),
    openBlockPicker: (network, cell) => set({ blockPicker: { network, cell } }),
    closeBlockPicker: () => set({ blockPicker: undefined }),
    setStatus: (status) => set({ status }),
    selectNetworks: (ids) =>
      set({ networkSelection: [...new Set(ids)], selection: { network: undefined, elements: [] } }),
    setPastePrompt: (pastePrompt) => set({ pastePrompt }),
    setFinder: (finder) => set({ finder }),
    setPanels: (patch) => set({ panels: { ...get().panels, ...patch } }),
    setViewNetwork: (viewNetwork) => {
      if (get().viewNetwork !== viewNetwork) set({ viewNetwork });
    },
    setSymbolComments: (symbolComments) => {
      set({ symbolComments });
      try {
        if (typeof localStorage !== 'undefined') localStorage.setItem(SYMBOL_COMMENTS_KEY, symbolComments ? 'on' : 'off');
      } catch {
        // Private mode: the option is just not remembered.
      }
    },
  }));
}

export const selectSelection = (s: UiState) => s.selection;
export const selectCursor = (s: UiState) => s.cursor;
export const selectTool = (s: UiState) => s.tool;
export const selectZoom = (s: UiState) => s.viewport.zoom;
export const selectTheme = (s: UiState) => s.theme;
export const selectNetworkSelection = (s: UiState) => s.networkSelection;
export const selectPanels = (s: UiState) => s.panels;

const UiStoreContext = createContext<UiStore | null>(null);

export function UiStoreProvider({ store, children }: { store: UiStore; children?: ReactNode }) {
  return createElement(UiStoreContext.Provider, { value: store }, children);
}

export function useUiStore(): UiStore {
  const store = useContext(UiStoreContext);
  if (!store) throw new Error('useUiStore needs a <UiStoreProvider> above it');
  return store;
}

/** Subscribes to one slice of the UI state: `useUi(selectSelection)`. */
export function useUi<T>(selector: (s: UiState) => T): T {
  return useStore(useUiStore(), selector);
}
