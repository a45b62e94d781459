// Moving elements from one network to another (a drag that ends over another network's grid).
// The elements keep their ids and their relative positions; the selection's top-left cell goes to
// `at` in the target. Horizontal links in the way in the target go (like a move within a network);
// any other element in the way refuses the move. Vertical links inside the moved area (strictly
// between its left and right edges) move along; links on its edges stay in the source, where
// other paths may still use them. The target grows to fit. A box that would land on the first
// column goes one column right with the rest, its power-flow input fed from the rail (networkEdits.ts).
import type { LdElement, VLink } from '../model/elements';
import { elementCells } from '../model/factory';
import { STANDARD_LIBRARY, type BlockLibrary } from '../model/library';
import { cellKey, type Cell } from '../model/grid';
import { newId, type ElementId } from '../model/ids';
import type { Network } from '../model/project';
import { boundsOf, feedFromRail, grow, occupancy, offRailShift, shiftedBoxes } from './networkEdits';

export interface Transfer {
  readonly source: Network;
  readonly target: Network;
}

/** The source without the elements and the target with them, or undefined when blocked or off-grid. */
export function transferElements(
  source: Network,
  target: Network,
  ids: readonly ElementId[],
  at: Cell,
  lib: BlockLibrary = STANDARD_LIBRARY,
  makeId: () => ElementId = () => newId<'ElementId'>('e'),
): Transfer | undefined {
  if (source.id === target.id || at.row < 0 || at.col < 0) return undefined;
  const set = new Set(ids);
  const moving = source.elements.filter((e) => set.has(e.id));
  const b = boundsOf(moving, lib);
  if (!b) return undefined;
  const dRow = at.row - b.top;
  const shift = offRailShift(moving.map((e) => ({ ...e, col: e.col - b.left + at.col })));
  const dCol = at.col + shift - b.left;
  const moved: LdElement[] = moving.map((e) => ({ ...e, row: e.row + dRow, col: e.col + dCol }));
  const occ = occupancy(target, undefined, lib);
  const replaced = new Set<ElementId>();
  for (const el of moved)
    for (const c of elementCells(el, lib)) {
      const other = occ.get(cellKey(c.row, c.col));
      if (!other) continue;
      if (other.kind !== 'link') return undefined;
      replaced.add(other.id);
    }
  const inside = (v: VLink) =>
    v.row >= b.top && v.row < b.bottom && v.boundary > b.left && v.boundary < b.right;
  const carried = source.vlinks.filter(inside);
  const vlinks = [...target.vlinks];
  for (const v of carried) {
    const w = { row: v.row + dRow, boundary: v.boundary + dCol };
    if (!vlinks.some((x) => x.row === w.row && x.boundary === w.boundary)) vlinks.push(w);
  }
  const elements = [...target.elements.filter((e) => !replaced.has(e.id)), ...moved];
  return {
    source: {
      ...source,
      elements: source.elements.filter((e) => !set.has(e.id)),
      vlinks: source.vlinks.filter((v) => !inside(v)),
    },
    target: feedFromRail(grow(target, elements, vlinks, lib), shiftedBoxes(moved, shift), makeId, lib),
  };
}
