// The connections a network grid draws, as a graph: for every element input pin wired on the
// grid, the element output pins (or the left rail) feeding it. Points joined by horizontal links,
// vertical links and the left rail form nets by the engine's rule (src/engine/compile/wires.ts:
// vertical links are one-way, so a fan-out into two different ORs feeds each input only what
// reaches it from its left).
import { boxLayout } from '../model/boxLayout';
import type { BlockLibrary } from '../model/library';
import type { LdElement } from '../model/elements';
import type { Network } from '../model/project';
import { feedingNets, wireNets, type WireEdge } from '../engine/compile/wires';

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

/** The grid's wiring; `library` knows the project's own blocks (standard blocks only without it). */
export function gridGraph(
  net: Pick<Network, 'rows' | 'cols' | 'elements' | 'vlinks'>,
  library?: BlockLibrary,
): GridGraph {
  const W = net.cols + 1;
  const rows = net.rows;
  const cols = net.cols;
  const n = rows * W;
  const inGrid = (r: number, b: number) => r >= 0 && r < rows && b >= 0 && b <= cols;
  const bars: [number, number][] = [];
  for (let r = 1; r < rows; r++) bars.push([(r - 1) * W, r * W]); // the left rail joins every row at boundary 0
  const edges: WireEdge[] = [];
  const elements = net.elements;
  for (let ei = 0; ei < elements.length; ei++) {
    const el = elements[ei]!;
    if (el.kind === 'link' && inGrid(el.row, el.col) && inGrid(el.row, el.col + 1))
      edges.push({ from: el.row * W + el.col, to: el.row * W + el.col + 1, via: ei });
  }
  for (const v of net.vlinks)
    if (inGrid(v.row, v.boundary) && inGrid(v.row + 1, v.boundary))
      bars.push([v.row * W + v.boundary, (v.row + 1) * W + v.boundary]);
  const sourceAt = new Uint8Array(n);
  const sinkAt = new Uint8Array(n);
  for (let r = 0; r < rows; r++) {
    sourceAt[r * W] = 1;
    sinkAt[r * W + cols] = 1;
  }
  const pins: ReturnType<typeof elementPins>[] = new Array<ReturnType<typeof elementPins>>(elements.length);
  for (let ei = 0; ei < elements.length; ei++) {
    const p = (pins[ei] = elementPins(elements[ei]!, library));
    for (const o of p.outputs) if (inGrid(o.row, o.boundary)) sourceAt[o.row * W + o.boundary] = 1;
    for (const i of p.inputs) if (inGrid(i.row, i.boundary)) sinkAt[i.row * W + i.boundary] = 1;
  }
  // One-way vertical links, as the engine reads the grid (src/engine/compile/wires.ts).
  const wired = wireNets({ points: n, bars, edges, sourceAt, sinkAt });
  const netOfPoint = wired.netOfPoint;

  const own: Source[][] = Array.from({ length: wired.count }, () => []);
  const railNet = rows > 0 ? netOfPoint[0]! : -1;
  if (railNet >= 0) own[railNet]!.push({ kind: 'rail' });
  for (let ei = 0; ei < elements.length; ei++)
    for (const o of pins[ei]!.outputs)
      if (inGrid(o.row, o.boundary)) own[netOfPoint[o.row * W + o.boundary]!]!.push({ kind: 'pin', el: ei, pin: o.pin });
  // What drives each net: its own sources, then those of the nets bridged into it.
  const feeds = new Map<number, number[]>();
  for (const b of wired.bridges) feeds.set(b.to, [...(feeds.get(b.to) ?? []), b.from]);
  const producersMemo = new Map<number, Source[]>();
  const producers = (id: number): Source[] => {
    if (!feeds.has(id)) return own[id]!;
    const hit = producersMemo.get(id);
    if (hit) return hit;
    const list = feedingNets(id, (m) => feeds.get(m) ?? []).flatMap((m) => own[m]!);
    producersMemo.set(id, list);
    return list;
  };

  const sources = new Map<number, Map<string, Source[]>>();
  for (let ei = 0; ei < elements.length; ei++) {
    for (const i of pins[ei]!.inputs) {
      if (!inGrid(i.row, i.boundary)) continue;
      const list = producers(netOfPoint[i.row * W + i.boundary]!);
      if (!list.length) continue;
      let mine: Source[] = list;
      for (let k = 0; k < list.length; k++) {
        const s = list[k]!;
        if (s.kind === 'pin' && s.el === ei) {
          mine = list.filter((x) => x.kind === 'rail' || x.el !== ei);
          break;
        }
      }
      if (!mine.length) continue;
      let m = sources.get(ei);
      if (!m) sources.set(ei, (m = new Map()));
      m.set(i.pin, mine === list ? list.slice() : mine);
    }
  }
  const rightRail = new Map<number, Source[]>();
  for (let r = 0; r < rows; r++) {
    const id = netOfPoint[r * W + cols]!;
    const list = producers(id);
    if (list.length && id !== railNet) rightRail.set(r, list);
  }
  const barBoundary = new Map<number, number>();
  for (const v of net.vlinks)
    if (inGrid(v.row, v.boundary) && inGrid(v.row + 1, v.boundary)) barBoundary.set(netOfPoint[v.row * W + v.boundary]!, v.boundary);
  return { sources, rightRail, netOf: (r, b) => netOfPoint[r * W + b]!, barBoundary };
}
