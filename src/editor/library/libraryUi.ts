// State of the library manager (never part of the document or its history): whether it is open,
// the file being read for an add or an update, and what the last refused action said.
import { createStore } from 'zustand/vanilla';
import type { LibraryUse } from '../../model/libraries';
import type { LibraryRead } from '../../plcopen/libraryFile';

/** A file read as a library, waiting for the user to confirm the add (or the update of `updating`). */
export interface PendingLibrary {
  readonly fileName: string;
  readonly read: LibraryRead;
  /** The library it would update; absent: a new library. */
  readonly updating?: string;
}

/** A removal the project refused: the library and where its blocks are used. */
export interface RefusedRemoval {
  readonly library: string;
  readonly uses: readonly LibraryUse[];
}

export interface LibraryUiState {
  readonly open: boolean;
  readonly pending: PendingLibrary | undefined;
  readonly refused: RefusedRemoval | undefined;
  /** The library whose update the next chosen file is for; undefined: the next file is added. */
  readonly updateTarget: string | undefined;
  /** The library block shown read-only (`library:<library>:<pou>` id). */
  readonly viewing: string | undefined;
  /** Opens the browser's file picker; set by <LibraryHost> while mounted. */
  readonly openPicker: (() => void) | undefined;
  setOpen(open: boolean): void;
  setPending(p: PendingLibrary | undefined): void;
  setRefused(r: RefusedRemoval | undefined): void;
  setUpdateTarget(name: string | undefined): void;
  setViewing(id: string | undefined): void;
  setOpenPicker(fn: (() => void) | undefined): void;
}

export const libraryUi = createStore<LibraryUiState>()((set) => ({
  open: false,
  pending: undefined,
  refused: undefined,
  updateTarget: undefined,
  viewing: undefined,
  openPicker: undefined,
  setOpen: (open) => set(open ? { open } : { open, pending: undefined, refused: undefined, viewing: undefined }),
  setPending: (pending) => set({ pending }),
  setRefused: (refused) => set({ refused }),
  setUpdateTarget: (updateTarget) => set({ updateTarget }),
  setViewing: (viewing) => set({ viewing }),
  setOpenPicker: (openPicker) => set({ openPicker }),
}));

/** Opens the library manager (File > Libraries…, the Project tree). */
export const openLibraryManager = (): void => libraryUi.getState().setOpen(true);
