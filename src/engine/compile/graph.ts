// Grid -> element graph. Points (row, boundary) joined by horizontal links and vertical links
// form nets (wires.ts: vertical links are one-way, so a wire whose sources do not all reach all
// its inputs moving right is split into nets joined by bridges). Every other element sits between
// nets through its terminals:
// contacts, coils, jumps and returns have an input at (row, col) and (except jumps/returns) an
// output at (row, col + 1); boxes have their pins where boxLayout puts them.
// A connector `>NAME>` (its point at (row, col)) and every continuation `>NAME>` of the network
// (its point at (row, col + 1)) are joined as if a wire ran from the first to the others; they
// are not nodes.
import { boxLayout, type BoxLayout } from '../../model/boxLayout';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import type { BoxElement, LdElement } from '../../model/elements';
import type { Network } from '../../model/project';
import { feedingNets, wireNets, type Bridge, type WireEdge } from './wires';

export type { Bridge } from './wires';

export type NodeElement = Exclude<LdElement, { kind: 'link' }>;

export interface Terminal {
  readonly pin: string;
  readonly row: number;
  readonly boundary: number;
  readonly net: number;
}

/** A non-link element with its terminals. `index` is its position in network.elements. */
export interface GraphNode {
  readonly index: number;
  readonly el: NodeElement;
  readonly layout?: BoxLayout;
  readonly inputs: readonly Terminal[];
  readonly outputs: readonly Terminal[];
}

export interface Net {
  readonly id: number;
  readonly points: readonly number[];
  /** Holds a point of the left rail (boundary 0). */
  readonly leftRail: boolean;
  /** Holds a point of the right rail (boundary cols). */
  readonly rightRail: boolean;
  /** Outputs attached to the net (element right sides). */
  readonly sources: { node: number; pin: string; point: number }[];
  /** Inputs attached to the net (element left sides). */
  readonly sinks: { node: number; pin: string; point: number }[];
  /** Horizontal links (element indexes) and vertical links (vlink indexes) in the net. */
  readonly links: number[];
  readonly vlinks: number[];
  /** Bridges (indexes in NetworkGraph.bridges) whose state is OR-ed into this net, and out of it. */
  readonly feeds: number[];
  readonly feedsOut: number[];
}

export interface NetworkGraph {
  readonly rows: number;
  readonly cols: number;
  readonly nodes: readonly GraphNode[];
  readonly nets: readonly Net[];
  /** Net id of every point (row * (cols + 1) + boundary). */
  readonly netOfPoint: Int32Array;
  /** Net id of each horizontal link, connector and continuation (by element index); -1 for other elements. */
  readonly linkNet: Int32Array;
  /** Net id of each vertical link (by vlink index); -1 for one outside the grid. */
  readonly vlinkNet: Int32Array;
  /**
   * For the power display: the node whose output alone drives a horizontal link (through a line
   * with no vertical link on it), by element index; -1 for other links and elements. Such a line
   * shows that output's own state, not the OR its net forms further right (section 1).
   */
  readonly linkSource: Int32Array;
  /** The output pin of linkSource's node that drives the line (a block's Q, not its ENO); '' for other links. */
  readonly linkSourcePin: readonly string[];
  /** Elements that could not be placed (outside the grid or overlapping): element index and reason. */
  readonly misplaced: readonly { index: number; reason: string }[];
  /** Vertical links outside the grid (vlink index). */
  readonly badVlinks: readonly number[];
  /**
   * Connector/continuation pairs: the connector's point (left side) → the points of its
   * continuations (right side). Power and values go from the first to the others (LD-R14).
   */
  readonly connections: ReadonlyMap<number, readonly number[]>;
  /**
   * One-way joins between nets (wires.ts): the state of `to` is its own sources OR-ed with the
   * state of every net bridged into it. Empty unless a wire's sources do not all reach all its inputs.
   */
  readonly bridges: readonly Bridge[];
  /** Connectors and continuations that could not be paired (element index and reason), LD-R14. */
  readonly unpaired: readonly { index: number; reason: string; severity: 'error' | 'warning' }[];
}

/** Point of a connector (its left side) or a continuation (its right side). */
export const connectionPoint = (el: { kind: string; row: number; col: number }, cols: number): number =>
  el.row * (cols + 1) + (el.kind === 'continuation' ? el.col + 1 : el.col);

const boxOf = (el: LdElement): BoxElement | undefined => (el.kind === 'box' ? el : undefined);

/**
 * A network's graph as last built, with what it was built from: the network's grid, its element
 * and vertical-link lists, and each box's pin layout (a user block's layout is a new object when its
 * interface changes, boxLayout.ts).
 */
interface BuiltGraph {
  readonly rows: number;
  readonly cols: number;
  readonly elements: Network['elements'];
  /** The elements and vertical links it held (a list changed in place is seen). */
  readonly held: readonly LdElement[];
  readonly vlinks: Network['vlinks'];
  readonly heldVlinks: Network['vlinks'];
  readonly layouts: readonly (BoxLayout | undefined)[];
  readonly graph: NetworkGraph;
}

/**
 * Graphs by network object. The model is immutable (an edit makes new element, list and network
 * objects), and a graph depends only on the network and its boxes' layouts: a compile of an edited
 * project rebuilds only the graphs of the networks the edit touched, and a body lowered once per
 * instance of its FB builds its graphs once (the online change at 650 networks, docs/benchmarks.md).
 * Nothing changes a graph after it is built; the lists are compared item by item, so a list changed
 * in place after a compile is never taken for the one compiled.
 */
const built = new WeakMap<Network, BuiltGraph>();

function sameItems<T>(a: readonly T[], b: readonly T[]): boolean {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}

/** The graph of a network; boxes of user blocks need the project's `library` for their pins. */
export function buildGraph(network: Network, library: BlockLibrary = STANDARD_LIBRARY): NetworkGraph {
  const layouts = network.elements.map((el) => {
    const box = boxOf(el);
    return box ? boxLayout(box, library) : undefined;
  });
  const hit = built.get(network);
  if (
    hit &&
    hit.rows === network.rows &&
    hit.cols === network.cols &&
    hit.elements === network.elements &&
    sameItems(hit.held, network.elements) &&
    hit.vlinks === network.vlinks &&
    sameItems(hit.heldVlinks, network.vlinks) &&
    sameItems(hit.layouts, layouts)
  )
    return hit.graph;
  const graph = graphOf(network, layouts);
  built.set(network, {
    rows: network.rows,
    cols: network.cols,
    elements: network.elements,
    held: network.elements.slice(),
    vlinks: network.vlinks,
    heldVlinks: network.vlinks.slice(),
    layouts,
    graph,
  });
  return graph;
}

function graphOf(network: Network, layouts: readonly (BoxLayout | undefined)[]): NetworkGraph {
  const { rows, cols } = network;
  const width = cols + 1;
  const point = (row: number, boundary: number) => row * width + boundary;
  const edges: WireEdge[] = [];
  const bars: [number, number][] = [];
  const misplaced: { index: number; reason: string }[] = [];
  const occupied = new Map<number, number>();
  const placed: boolean[] = [];

  network.elements.forEach((el, index) => {
    const layout = layouts[index];
    const h = layout ? layout.rows : 1;
    const w = layout ? layout.cols : 1;
    if (el.row < 0 || el.col < 0 || el.row + h > rows || el.col + w > cols) {
      misplaced.push({ index, reason: `lies outside the ${rows}x${cols} grid` });
      placed.push(false);
      return;
    }
    for (let r = 0; r < h; r++) {
      for (let c = 0; c < w; c++) {
        const other = occupied.get((el.row + r) * cols + el.col + c);
        if (other !== undefined) {
          misplaced.push({
            index,
            reason: `overlaps another element at R${el.row + r + 1}C${el.col + c + 1}`,
          });
          placed.push(false);
          return;
        }
      }
    }
    for (let r = 0; r < h; r++)
      for (let c = 0; c < w; c++) occupied.set((el.row + r) * cols + el.col + c, index);
    placed.push(true);
    if (el.kind === 'link') edges.push({ from: point(el.row, el.col), to: point(el.row, el.col + 1), via: index });
  });

  const badVlinks: number[] = [];
  network.vlinks.forEach((v, i) => {
    if (v.row < 0 || v.row + 1 >= rows || v.boundary < 0 || v.boundary > cols) badVlinks.push(i);
    else bars.push([point(v.row, v.boundary), point(v.row + 1, v.boundary)]);
  });

  // Connectors and continuations by name (names compare as IEC identifiers: case-insensitive).
  const connectors = new Map<string, number[]>();
  const continuations = new Map<string, number[]>();
  network.elements.forEach((el, index) => {
    if (!placed[index] || (el.kind !== 'connector' && el.kind !== 'continuation')) return;
    const key = el.name.trim().toUpperCase();
    const into = el.kind === 'connector' ? connectors : continuations;
    into.set(key, [...(into.get(key) ?? []), index]);
  });
  const connections = new Map<number, number[]>();
  const unpaired: { index: number; reason: string; severity: 'error' | 'warning' }[] = [];
  for (const [key, list] of connectors) {
    const at = network.elements[list[0]!]!;
    for (const extra of list.slice(1))
      unpaired.push({
        index: extra,
        reason: `has the same name as the connector at R${at.row + 1}C${at.col + 1}; a connector name is used once per network`,
        severity: 'error',
      });
    const conts = continuations.get(key) ?? [];
    if (key === '') unpaired.push({ index: list[0]!, reason: 'has no name', severity: 'error' });
    else if (!conts.length)
      unpaired.push({ index: list[0]!, reason: 'has no continuation of its name in this network: its value goes nowhere', severity: 'warning' });
    const from = connectionPoint(at, cols);
    connections.set(
      from,
      conts.map((i) => connectionPoint(network.elements[i]!, cols)),
    );
    for (const i of conts) edges.push({ from, to: connectionPoint(network.elements[i]!, cols), via: i });
  }
  for (const [key, list] of continuations)
    if (!connectors.has(key))
      for (const index of list)
        unpaired.push({
          index,
          reason: key === '' ? 'has no name' : 'has no connector of its name in this network: it carries nothing',
          severity: 'error',
        });

  // Element terminals (boxes where boxLayout puts their pins), then the nets of the wiring.
  const terminals: { inputs: [string, number, number][]; outputs: [string, number, number][] }[] = [];
  const sourceAt = new Uint8Array(rows * width);
  const sinkAt = new Uint8Array(rows * width);
  for (let p = 0; p < rows * width; p++) {
    if (p % width === 0) sourceAt[p] = 1;
    if (p % width === cols) sinkAt[p] = 1;
  }
  network.elements.forEach((el, index) => {
    const t: (typeof terminals)[number] = { inputs: [], outputs: [] };
    terminals.push(t);
    if (!placed[index] || el.kind === 'link' || el.kind === 'connector' || el.kind === 'continuation') return;
    if (el.kind === 'box') {
      const l = layouts[index];
      if (l) {
        for (const pin of l.inputs) t.inputs.push([pin.name, el.row + pin.rowOffset, el.col]);
        for (const pin of l.outputs) t.outputs.push([pin.name, el.row + pin.rowOffset, el.col + l.cols]);
      }
    } else {
      t.inputs.push(['IN', el.row, el.col]);
      if (el.kind !== 'jump' && el.kind !== 'return') t.outputs.push(['OUT', el.row, el.col + 1]);
    }
    for (const [, r, b] of t.inputs) sinkAt[point(r, b)] = 1;
    for (const [, r, b] of t.outputs) sourceAt[point(r, b)] = 1;
  });
  const wired = wireNets({ points: rows * width, bars, edges, sourceAt, sinkAt });
  const netOfPoint = wired.netOfPoint;
  const nets: Net[] = [];
  for (let id = 0; id < wired.count; id++)
    nets.push({
      id,
      points: [],
      leftRail: false,
      rightRail: false,
      sources: [],
      sinks: [],
      links: [],
      vlinks: [],
      feeds: [],
      feedsOut: [],
    });
  for (let p = 0; p < rows * width; p++) {
    const net = nets[netOfPoint[p]!]!;
    (net.points as number[]).push(p);
    const b = p % width;
    if (b === 0) (net as { leftRail: boolean }).leftRail = true;
    if (b === cols) (net as { rightRail: boolean }).rightRail = true;
  }

  const linkNet = new Int32Array(network.elements.length).fill(-1);
  const vlinkNet = new Int32Array(network.vlinks.length).fill(-1);
  network.vlinks.forEach((v, i) => {
    if (badVlinks.includes(i)) return;
    const id = netOfPoint[point(v.row, v.boundary)]!;
    vlinkNet[i] = id;
    nets[id]!.vlinks.push(i);
  });

  const nodes: GraphNode[] = [];
  const terminal = (pin: string, row: number, boundary: number): Terminal => ({
    pin,
    row,
    boundary,
    net: netOfPoint[point(row, boundary)]!,
  });
  network.elements.forEach((el, index) => {
    if (!placed[index]) return;
    if (el.kind === 'link') {
      const id = netOfPoint[point(el.row, el.col)]!;
      linkNet[index] = id;
      nets[id]!.links.push(index);
      return;
    }
    if (el.kind === 'connector') {
      linkNet[index] = netOfPoint[connectionPoint(el, cols)]!;
      return;
    }
    if (el.kind === 'continuation') {
      // A continuation shows what its connector carries.
      const key = el.name.trim().toUpperCase();
      const from = connectors.get(key)?.[0];
      linkNet[index] = netOfPoint[from !== undefined ? connectionPoint(network.elements[from]!, cols) : connectionPoint(el, cols)]!;
      return;
    }
    const layout = layouts[index];
    const inputs = terminals[index]!.inputs.map(([pin, r, b]) => terminal(pin, r, b));
    const outputs = terminals[index]!.outputs.map(([pin, r, b]) => terminal(pin, r, b));
    const node = nodes.length;
    nodes.push({ index, el, ...(layout ? { layout } : {}), inputs, outputs });
    for (const t of inputs) nets[t.net]!.sinks.push({ node, pin: t.pin, point: point(t.row, t.boundary) });
    for (const t of outputs) nets[t.net]!.sources.push({ node, pin: t.pin, point: point(t.row, t.boundary) });
  });

  // Lines driven by one element output alone (no vertical link on them), for the power display.
  const linkSource = new Int32Array(network.elements.length).fill(-1);
  const linkSourcePin: string[] = network.elements.map(() => '');
  const onBar = new Uint8Array(rows * width);
  network.vlinks.forEach((v, i) => {
    if (badVlinks.includes(i)) return;
    onBar[point(v.row, v.boundary)] = 1;
    onBar[point(v.row + 1, v.boundary)] = 1;
  });
  const outAt = new Int32Array(rows * width).fill(-1);
  const pinAt = new Map<number, string>();
  nodes.forEach((n, ni) => {
    for (const t of n.outputs) {
      const p = point(t.row, t.boundary);
      outAt[p] = outAt[p] === -1 ? ni : -2;
      pinAt.set(p, t.pin);
    }
  });
  const linkEndingAt = new Int32Array(rows * width).fill(-1);
  const links: number[] = [];
  network.elements.forEach((el, i) => {
    if (el.kind !== 'link' || !placed[i]) return;
    links.push(i);
    linkEndingAt[point(el.row, el.col + 1)] = i;
  });
  links.sort((a, b) => network.elements[a]!.row - network.elements[b]!.row || network.elements[a]!.col - network.elements[b]!.col);
  for (const i of links) {
    const el = network.elements[i]!;
    const p = point(el.row, el.col);
    if (onBar[p] || el.col === 0) continue;
    const before = linkEndingAt[p]!;
    if (outAt[p]! >= 0 && before < 0) {
      linkSource[i] = outAt[p]!;
      linkSourcePin[i] = pinAt.get(p) ?? '';
    } else if (outAt[p] === -1 && before >= 0) {
      linkSource[i] = linkSource[before]!;
      linkSourcePin[i] = linkSourcePin[before]!;
    }
  }

  wired.bridges.forEach((b, i) => {
    nets[b.from]!.feedsOut.push(i);
    nets[b.to]!.feeds.push(i);
  });
  return {
    rows,
    cols,
    nodes,
    nets,
    netOfPoint,
    linkNet,
    vlinkNet,
    linkSource,
    linkSourcePin,
    misplaced,
    badVlinks,
    bridges: wired.bridges,
    connections,
    unpaired,
  };
}

/** True when the net holds wires or element terminals (not just an untouched grid point). */
export const netIsUsed = (net: Net): boolean =>
  net.links.length > 0 ||
  net.vlinks.length > 0 ||
  net.sources.length > 0 ||
  net.sinks.length > 0 ||
  net.feeds.length > 0 ||
  net.feedsOut.length > 0;

/** What drives a net: its own sources and the left rail, and those of every net bridged into it. */
export interface Upstream {
  readonly sources: readonly Net['sources'][number][];
  readonly leftRail: boolean;
  /** The rail or some element output drives the net (directly or through bridges). */
  readonly fed: boolean;
}

const upstreamMemo = new WeakMap<NetworkGraph, Map<number, Upstream>>();

/** The sources driving a net, following bridges upstream (the net's own when it has none). */
export function upstream(g: NetworkGraph, net: number): Upstream {
  const n = g.nets[net]!;
  if (!n.feeds.length) return { sources: n.sources, leftRail: n.leftRail, fed: n.leftRail || n.sources.length > 0 };
  let memo = upstreamMemo.get(g);
  if (!memo) upstreamMemo.set(g, (memo = new Map()));
  const hit = memo.get(net);
  if (hit) return hit;
  const sources: Net['sources'][number][] = [];
  let leftRail = false;
  for (const id of feedingNets(net, (m) => g.nets[m]!.feeds.map((b) => g.bridges[b]!.from))) {
    const m = g.nets[id]!;
    sources.push(...m.sources);
    leftRail ||= m.leftRail;
  }
  const up = { sources, leftRail, fed: leftRail || sources.length > 0 };
  memo.set(net, up);
  return up;
}
