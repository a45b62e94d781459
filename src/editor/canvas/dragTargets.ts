// Where a drag of selected elements would put them: within their own network (an offset in whole
// cells) or into another network's grid (the grabbed cell follows the pointer's cell there).
import type { LdElement } from '../../model/elements';
import { elementSize } from '../../model/factory';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import type { Cell } from '../../model/grid';
import type { ElementId, NetworkId } from '../../model/ids';
import type { Network } from '../../model/project';
import { boundsOf } from '../../store/networkEdits';
import { transferElements } from '../../store/networkTransfer';

export interface DragState {
  readonly network: NetworkId;
  readonly ids: ReadonlySet<ElementId>;
  readonly dRow: number;
  readonly dCol: number;
  readonly blocked: boolean;
  /** Over another network: the elements as they would land there (its cells). */
  readonly into?: {
    readonly network: NetworkId;
    readonly at: Cell;
    readonly ghost: readonly LdElement[];
    readonly blocked: boolean;
  };
}

/** Can `ids` move by (dRow, dCol) inside `n`? Horizontal links in the way are replaced. */
export function canMove(
  n: Network,
  ids: readonly ElementId[],
  dRow: number,
  dCol: number,
  lib: BlockLibrary = STANDARD_LIBRARY,
): boolean {
  const set = new Set(ids);
  const taken = new Map<string, boolean>();
  for (const e of n.elements) {
    if (set.has(e.id)) continue;
    const s = elementSize(e, lib);
    for (let r = 0; r < s.rows; r++)
      for (let c = 0; c < s.cols; c++) taken.set(`${e.row + r}:${e.col + c}`, e.kind === 'link');
  }
  for (const e of n.elements) {
    if (!set.has(e.id)) continue;
    if (e.row + dRow < 0 || e.col + dCol < 0) return false;
    const s = elementSize(e, lib);
    for (let r = 0; r < s.rows; r++)
      for (let c = 0; c < s.cols; c++)
        if (taken.get(`${e.row + dRow + r}:${e.col + dCol + c}`) === false) return false;
  }
  return true;
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
  const ghost = moving.map((e) => ({ ...e, row: e.row - b.top + at.row, col: e.col - b.left + at.col }));
  return { at, ghost, blocked: !transferElements(source, target, ids, at, lib) };
}
