// State of the PLCopen import dialog (never part of the document or its history).
import { createStore } from 'zustand/vanilla';
import type { Project } from '../../model/project';
import type { ImportIssue, ImportReport } from '../../plcopen/types';

/** A file read successfully, waiting for the user to open it (report shown, POU chosen). */
export interface PendingImport {
  readonly fileName: string;
  readonly project: Project;
  readonly report: ImportReport;
}

export interface ImportFailure {
  readonly fileName: string;
  readonly errors: readonly ImportIssue[];
}

export interface PlcopenUiState {
  readonly pending: PendingImport | undefined;
  readonly failure: ImportFailure | undefined;
  /** The export review is open: what Beremiz/OpenPLC would run differently, before the download. */
  readonly reviewingExport: boolean;
  /** Opens the browser's file picker for .xml files; set by <PlcopenHost> while mounted. */
  readonly openPicker: (() => void) | undefined;
  setPending(p: PendingImport | undefined): void;
  setFailure(f: ImportFailure | undefined): void;
  setReviewingExport(open: boolean): void;
  setOpenPicker(fn: (() => void) | undefined): void;
}

export const plcopenUi = createStore<PlcopenUiState>()((set) => ({
  pending: undefined,
  failure: undefined,
  reviewingExport: false,
  openPicker: undefined,
  setPending: (pending) => set({ pending }),
  setFailure: (failure) => set({ failure }),
  setReviewingExport: (reviewingExport) => set({ reviewingExport }),
  setOpenPicker: (openPicker) => set({ openPicker }),
}));
