// State of the file dialogs and notices (not part of the document, never in history).
// One per page: the File menu commands and <FilesHost> (which renders it) share it.
import { createStore } from 'zustand/vanilla';
import type { LoadError } from '../../model/load';

export interface Confirmation {
  readonly title: string;
  readonly message: string;
  readonly confirmLabel: string;
  readonly onConfirm: () => void;
}

export interface OpenFailure {
  readonly fileName: string;
  readonly errors: readonly LoadError[];
}

export interface FilesUiState {
  readonly confirmation: Confirmation | undefined;
  readonly openFailure: OpenFailure | undefined;
  /** A short message at the top ("Restored ... from autosave", "Saved Motor.json"). */
  readonly notice: string;
  /** How many notices were raised: the same words raised again count as a repeat (×2). */
  readonly noticeSerial: number;
  /** When the autosave last reached IndexedDB (ms since epoch), or an error text. */
  readonly autosavedAt: number | undefined;
  readonly autosaveError: string;
  /** A change is waiting to be written (or being written). */
  readonly autosavePending: boolean;
  /** Opens the browser's file picker; set by <FilesHost> while mounted. */
  readonly openPicker: (() => void) | undefined;

  confirm(c: Confirmation): void;
  closeConfirmation(): void;
  showOpenFailure(f: OpenFailure | undefined): void;
  setNotice(text: string): void;
  setAutosaved(at: number | undefined, error?: string): void;
  setAutosavePending(pending: boolean): void;
  setOpenPicker(fn: (() => void) | undefined): void;
}

export const filesUi = createStore<FilesUiState>()((set) => ({
  confirmation: undefined,
  openFailure: undefined,
  notice: '',
  noticeSerial: 0,
  autosavedAt: undefined,
  autosaveError: '',
  autosavePending: false,
  openPicker: undefined,
  confirm: (confirmation) => set({ confirmation }),
  closeConfirmation: () => set({ confirmation: undefined }),
  showOpenFailure: (openFailure) => set({ openFailure }),
  setNotice: (notice) => set((s) => ({ notice, noticeSerial: s.noticeSerial + 1 })),
  setAutosaved: (autosavedAt, autosaveError = '') => set({ autosavedAt, autosaveError }),
  setAutosavePending: (autosavePending) => set({ autosavePending }),
  setOpenPicker: (openPicker) => set({ openPicker }),
}));
