// Where a drag of selected elements would put them: within their own network (an offset in whole
// cells) or into another network's grid (the grabbed cell follows the pointer's cell there).
import type { LdElement } from '../../model/elements';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import type { Cell } from '../../model/grid';
import type { ElementId, NetworkId } from '../../model/ids';
import type { Network } from '../../model/project';
import { boundsOf, moveElements, moveShift, offRailShift } from '../../store/networkEdits';
import { transferElements } from '../../store/networkTransfer';

export interface DragState {
  readonly network: NetworkId;
  readonly ids: ReadonlySet<ElementId>;
  readonly dRow: number;
  readonly dCol: number;
  readonly blocked: boolean;
  /** Where the elements land when that is not the offset (a box kept off the left rail). */
  readonly ghost?: readonly LdElement[];
  /** Over another network: the elements as they would land there (its cells). */
  readonly into?: {
    readonly network: NetworkId;
    readonly at: Cell;
    readonly ghost: readonly LdElement[];
    readonly blocked: boolean;
  };
}

/**
 * Moving `ids` by (dRow, dCol) inside `n`: blocked (another element in the way; horizontal links
 * are replaced) and, when a box would land on the first column and the move puts it one column
 * further right (networkEdits.ts), the ghost where they land.
 */
export function moveWithin(
  n: Network,
  ids: readonly ElementId[],
  dRow: number,
  dCol: number,
  lib: BlockLibrary = STANDARD_LIBRARY,
): { blocked: boolean; ghost?: LdElement[] } {
  const set = new Set(ids);
  const shift = moveShift(n, ids, dCol);
  const ghost = (): LdElement[] =>
    n.elements.filter((e) => set.has(e.id)).map((e) => ({ ...e, row: e.row + dRow, col: e.col + dCol + shift }));
  return { blocked: !moveElements(n, ids, dRow, dCol, lib), ...(shift ? { ghost: ghost() } : {}) };
}

/**
 * Dropping into `target` with the grabbed cell `grabbed` (of the source) over `cell` (of the
 * target): the top-left cell the selection lands on, its ghost, and whether something blocks it.
 */
export function dropInto(
  source: Network,
  target: Network,
  ids: readonly ElementId[],
  grabbed: Cell,
  cell: Cell,
  lib: BlockLibrary = STANDARD_LIBRARY,
): { at: Cell; ghost: LdElement[]; blocked: boolean } | undefined {
  const set = new Set(ids);
  const moving = source.elements.filter((e) => set.has(e.id));
  const b = boundsOf(moving, lib);
  if (!b) return undefined;
  const at = {
    row: Math.max(0, cell.row - (grabbed.row - b.top)),
    col: Math.max(0, cell.col - (grabbed.col - b.left)),
  };
  const placed = moving.map((e) => ({ ...e, row: e.row - b.top + at.row, col: e.col - b.left + at.col }));
  const shift = offRailShift(placed);
  const ghost = placed.map((e) => ({ ...e, col: e.col + shift }));
  return { at, ghost, blocked: !transferElements(source, target, ids, at, lib) };
}
