// The canvas's layout as the canvas draws it (the project's blocks, comments under operands with
// the view option), for code outside the canvas component that maps networks to pixels.
import { selectActivePou, selectLibrary, selectNetworks, type DocumentState } from '../../store/documentStore';
import type { UiState } from '../../store/uiStore';
import { layoutNetworks, type CanvasLayout, type SymbolComments } from './geometry';
import { symbolCommentsFor } from './symbolComments';

/** The symbol-comment lookup of the shown POU (undefined: the view option is off). */
export const viewSymbols = (doc: DocumentState, ui: Pick<UiState, 'symbolComments'>): SymbolComments | undefined =>
  symbolCommentsFor(ui.symbolComments, selectActivePou(doc)?.variables, doc.project.globals);

export const canvasLayoutFor = (doc: DocumentState, ui: Pick<UiState, 'symbolComments'>): CanvasLayout =>
  layoutNetworks(selectNetworks(doc), selectLibrary(doc), viewSymbols(doc, ui));
