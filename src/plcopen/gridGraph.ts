// The connections a network grid draws, as a graph: for every element input pin wired on the
// grid, the element output pins (or the left rail) feeding it. Points joined by horizontal links,
// vertical links and the left rail form one net (the same rule as the engine's compiler).
import { boxLayout } from '../model/boxLayout';
import type { BlockLibrary } from '../model/library';
import type { LdElement } from '../model/elements';
import type { Network } from '../model/project';

export type Source =
  { readonly kind: 'rail' } | { readonly kind: 'pin'; readonly el: number; readonly pin: string };

export interface PinPoint {
  readonly pin: string;
  readonly row: number;
  readonly boundary: number;
}

/** Input and output pins of an element with their grid points. 1-cell elements use pins "in"/"out". */
/** Shared by links and unknown boxes (most elements of a big network): never written. */
const NO_PINS: { readonly inputs: readonly PinPoint[]; readonly outputs: readonly PinPoint[] } =
  Object.freeze({
    inputs: Object.freeze([]),
    outputs: Object.freeze([]),
  });

export function elementPins(
  el: LdElement,
  library?: BlockLibrary,
): {
  readonly inputs: readonly PinPoint[];
  readonly outputs: readonly PinPoint[];
} {
  switch (el.kind) {
    case 'contact':
    case 'coil':
      return {
        inputs: [{ pin: 'in', row: el.row, boundary: el.col }],
        outputs: [{ pin: 'out', row: el.row, boundary: el.col + 1 }],
      };
    case 'jump':
    case 'return':
      return { inputs: [{ pin: 'in', row: el.row, boundary: el.col }], outputs: [] };
    case 'link':
      return NO_PINS;
    case 'connector':
      return { inputs: [{ pin: 'in', row: el.row, boundary: el.col }], outputs: [] };
    case 'continuation':
      return { inputs: [], outputs: [{ pin: 'out', row: el.row, boundary: el.col + 1 }] };
    case 'box': {
      const layout = boxLayout(el, library);
      if (!layout) return NO_PINS;
      return {
        inputs: layout.inputs.map((p) => ({ pin: p.name, row: el.row + p.rowOffset, boundary: el.col })),
        outputs: layout.outputs.map((p) => ({
          pin: p.name,
          row: el.row + p.rowOffset,
          boundary: el.col + layout.cols,
        })),
      };
    }
  }
}

export interface GridGraph {
  /** sources.get(elementIndex).get(pin): what feeds that input pin; only pins whose net has a source. */
  readonly sources: Map<number, Map<string, Source[]>>;
  /** Rows at which a net with a source reaches the right rail, with that net's sources. */
  readonly rightRail: Map<number, Source[]>;
  /** Every net id by point key row*(cols+1)+boundary, for diagnostics and routing. */
  readonly netOf: (row: number, boundary: number) => number;
  /** Boundaries of vertical links per net (to route wires through the drawn bar). */
  readonly barBoundary: Map<number, number>;
}

/** Union-find root of a point (with path halving). */
function findRoot(parent: number[], a: number): number {
  while (parent[a]! !== a) {
    parent[a] = parent[parent[a]!]!;
    a = parent[a]!;
  }
  return a;
}
/** Joins two points; the smaller index becomes the root. */
function unite(parent: number[], a: number, b: number): void {
  const ra = findRoot(parent, a);
  const rb = findRoot(parent, b);
  if (ra !== rb) parent[Math.max(ra, rb)] = Math.min(ra, rb);
}

/** The grid's wiring; `library` knows the project's own blocks (standard blocks only without it). */
export function gridGraph(
  net: Pick<Network, 'rows' | 'cols' | 'elements' | 'vlinks'>,
  library?: BlockLibrary,
): GridGraph {
  const W = net.cols + 1;
  const rows = net.rows;
  const cols = net.cols;
  const n = rows * W;
  const parent: number[] = new Array<number>(n).fill(0); // small: cheaper than a typed array
  for (let i = 0; i < n; i++) parent[i] = i;
  const inGrid = (r: number, b: number) => r >= 0 && r < rows && b >= 0 && b <= cols;
  for (let r = 1; r < rows; r++) unite(parent, 0, r * W); // the left rail joins every row at boundary 0
  for (const el of net.elements)
    if (el.kind === 'link' && inGrid(el.row, el.col + 1))
      unite(parent, el.row * W + el.col, el.row * W + el.col + 1);
  for (const v of net.vlinks)
    if (inGrid(v.row + 1, v.boundary)) unite(parent, v.row * W + v.boundary, (v.row + 1) * W + v.boundary);

  const producers = new Map<number, Source[]>();
  const railNet = rows > 0 ? findRoot(parent, 0) : -1;
  if (railNet >= 0) producers.set(railNet, [{ kind: 'rail' }]);
  const elements = net.elements;
  const pins: ReturnType<typeof elementPins>[] = new Array<ReturnType<typeof elementPins>>(elements.length);
  for (let ei = 0; ei < elements.length; ei++) {
    const p = (pins[ei] = elementPins(elements[ei]!, library));
    for (const o of p.outputs) {
      if (!inGrid(o.row, o.boundary)) continue;
      const id = findRoot(parent, o.row * W + o.boundary);
      let list = producers.get(id);
      if (!list) producers.set(id, (list = []));
      list.push({ kind: 'pin', el: ei, pin: o.pin });
    }
  }
  const sources = new Map<number, Map<string, Source[]>>();
  for (let ei = 0; ei < elements.length; ei++) {
    for (const i of pins[ei]!.inputs) {
      if (!inGrid(i.row, i.boundary)) continue;
      const list = producers.get(findRoot(parent, i.row * W + i.boundary));
      if (!list) continue;
      let own: Source[] = list;
      for (let k = 0; k < list.length; k++) {
        const s = list[k]!;
        if (s.kind === 'pin' && s.el === ei) {
          own = list.filter((x) => x.kind === 'rail' || x.el !== ei);
          break;
        }
      }
      if (!own.length) continue;
      let m = sources.get(ei);
      if (!m) sources.set(ei, (m = new Map()));
      m.set(i.pin, own === list ? list.slice() : own);
    }
  }
  const rightRail = new Map<number, Source[]>();
  for (let r = 0; r < rows; r++) {
    const id = findRoot(parent, r * W + cols);
    const list = producers.get(id);
    if (list && id !== railNet) rightRail.set(r, list);
  }
  const barBoundary = new Map<number, number>();
  for (const v of net.vlinks)
    if (inGrid(v.row + 1, v.boundary)) barBoundary.set(findRoot(parent, v.row * W + v.boundary), v.boundary);
  return { sources, rightRail, netOf: (r, b) => findRoot(parent, r * W + b), barBoundary };
}
