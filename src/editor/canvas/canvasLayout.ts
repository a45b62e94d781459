// The canvas's layout as the canvas draws it (the project's blocks, comments under operands with
// the view option), for code outside the canvas component that maps networks to pixels.
import { selectActivePou, selectLibrary, selectNetworks, type DocumentState } from '../../store/documentStore';
import type { UiState } from '../../store/uiStore';
import type { BlockLibrary } from '../../model/library';
import type { Network } from '../../model/project';
import { usedRows } from '../../store/networkEdits';
import { layoutNetworks, type CanvasLayout, type Room, type SymbolComments } from './geometry';
import { symbolCommentsFor } from './symbolComments';

/** The symbol-comment lookup of the shown POU (undefined: the view option is off). */
export const viewSymbols = (doc: DocumentState, ui: Pick<UiState, 'symbolComments'>): SymbolComments | undefined =>
  symbolCommentsFor(ui.symbolComments, selectActivePou(doc)?.variables, doc.project.globals);

/**
 * The room the canvas shows beyond the used rows: an empty row under every network while a palette
 * tool is armed or elements are dragged (drop targets), else the rows down to the keyboard cursor
 * when it went below its network's last used row. Undefined: networks show their used rows only.
 */
export function roomFor(
  ui: Pick<UiState, 'tool' | 'cursor' | 'dragging'>,
  networks: readonly Network[],
  library?: BlockLibrary,
): Room | undefined {
  if (ui.dragging || ui.tool.kind !== 'select') return ALL;
  const c = ui.cursor;
  const n = c && networks.find((m) => m.id === c.network);
  return c && n && c.row + 1 > usedRows(n, library) ? { network: c.network, rows: c.row + 1 } : undefined;
}
const ALL: Room = { all: true };

export const canvasLayoutFor = (
  doc: DocumentState,
  ui: Pick<UiState, 'symbolComments' | 'tool' | 'cursor' | 'dragging'>,
): CanvasLayout => {
  const networks = selectNetworks(doc);
  const library = selectLibrary(doc);
  return layoutNetworks(networks, library, viewSymbols(doc, ui), roomFor(ui, networks, library));
};
