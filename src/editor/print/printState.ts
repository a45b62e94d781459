// What the Print command has open: the options dialog, then the print view built from its choices.
import { createStore } from 'zustand';
import type { PouId } from '../../model/ids';

export type PaperOrientation = 'landscape' | 'portrait';

export interface PrintOptions {
  /** One POU, or every POU of the project (and the global variables). */
  readonly scope: { readonly kind: 'pou'; readonly pou: PouId } | { readonly kind: 'project' };
  readonly variables: boolean;
  readonly crossReference: boolean;
  readonly orientation: PaperOrientation;
}

export interface PrintState {
  readonly dialog: boolean;
  /** The print view is open with these options. */
  readonly view: PrintOptions | undefined;
  /** The last choices, offered again next time. */
  readonly last: Omit<PrintOptions, 'scope'> & { readonly whole: boolean };
  openDialog(): void;
  closeDialog(): void;
  openView(options: PrintOptions): void;
  closeView(): void;
}

export const printState = createStore<PrintState>()((set) => ({
  dialog: false,
  view: undefined,
  last: { whole: false, variables: true, crossReference: true, orientation: 'landscape' },
  openDialog: () => set({ dialog: true }),
  closeDialog: () => set({ dialog: false }),
  openView: (options) =>
    set({
      dialog: false,
      view: options,
      last: {
        whole: options.scope.kind === 'project',
        variables: options.variables,
        crossReference: options.crossReference,
        orientation: options.orientation,
      },
    }),
  closeView: () => set({ view: undefined }),
}));
