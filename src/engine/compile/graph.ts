// Grid -> element graph. Points (row, boundary) joined by horizontal links and vertical links
// form nets (union-find). Every other element sits between nets through its terminals:
// contacts, coils, jumps and returns have an input at (row, col) and (except jumps/returns) an
// output at (row, col + 1); boxes have their pins where boxLayout puts them.
// A connector `>NAME>` (its point at (row, col)) and every continuation `>NAME>` of the network
// (its point at (row, col + 1)) are one net, as if a wire joined them; they are not nodes.
import { boxLayout, type BoxLayout } from '../../model/boxLayout';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import type { BoxElement, LdElement } from '../../model/elements';
import type { Network } from '../../model/project';

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
  /** Elements that could not be placed (outside the grid or overlapping): element index and reason. */
  readonly misplaced: readonly { index: number; reason: string }[];
  /** Vertical links outside the grid (vlink index). */
  readonly badVlinks: readonly number[];
  /**
   * Connector/continuation pairs: the connector's point (left side) → the points of its
   * continuations (right side). Power and values go from the first to the others (LD-R14).
   */
  readonly connections: ReadonlyMap<number, readonly number[]>;
  /** Connectors and continuations that could not be paired (element index and reason), LD-R14. */
  readonly unpaired: readonly { index: number; reason: string; severity: 'error' | 'warning' }[];
}

/** Point of a connector (its left side) or a continuation (its right side). */
export const connectionPoint = (el: { kind: string; row: number; col: number }, cols: number): number =>
  el.row * (cols + 1) + (el.kind === 'continuation' ? el.col + 1 : el.col);

class UnionFind {
  private readonly parent: Int32Array;
  constructor(n: number) {
    this.parent = new Int32Array(n);
    for (let i = 0; i < n; i++) this.parent[i] = i;
  }
  find(a: number): number {
    let r = a;
    while (this.parent[r] !== r) r = this.parent[r]!;
    let x = a;
    while (this.parent[x] !== r) {
      const next = this.parent[x]!;
      this.parent[x] = r;
      x = next;
    }
    return r;
  }
  union(a: number, b: number): void {
    const ra = this.find(a);
    const rb = this.find(b);
    if (ra !== rb) this.parent[ra] = rb;
  }
}

const boxOf = (el: LdElement): BoxElement | undefined => (el.kind === 'box' ? el : undefined);

/** The graph of a network; boxes of user blocks need the project's `library` for their pins. */
export function buildGraph(network: Network, library: BlockLibrary = STANDARD_LIBRARY): NetworkGraph {
  const { rows, cols } = network;
  const width = cols + 1;
  const point = (row: number, boundary: number) => row * width + boundary;
  const uf = new UnionFind(rows * width);
  const misplaced: { index: number; reason: string }[] = [];
  const occupied = new Map<number, number>();
  const placed: boolean[] = [];

  network.elements.forEach((el, index) => {
    const box = boxOf(el);
    const layout = box ? boxLayout(box, library) : undefined;
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
    if (el.kind === 'link') uf.union(point(el.row, el.col), point(el.row, el.col + 1));
  });

  const badVlinks: number[] = [];
  network.vlinks.forEach((v, i) => {
    if (v.row < 0 || v.row + 1 >= rows || v.boundary < 0 || v.boundary > cols) badVlinks.push(i);
    else uf.union(point(v.row, v.boundary), point(v.row + 1, v.boundary));
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
    for (const i of conts) uf.union(from, connectionPoint(network.elements[i]!, cols));
  }
  for (const [key, list] of continuations)
    if (!connectors.has(key))
      for (const index of list)
        unpaired.push({
          index,
          reason: key === '' ? 'has no name' : 'has no connector of its name in this network: it carries nothing',
          severity: 'error',
        });

  // Dense net ids in point order (stable: the upper-left point names the net).
  const netOfPoint = new Int32Array(rows * width);
  const rootToNet = new Map<number, number>();
  const nets: Net[] = [];
  for (let p = 0; p < rows * width; p++) {
    const root = uf.find(p);
    let id = rootToNet.get(root);
    if (id === undefined) {
      id = nets.length;
      rootToNet.set(root, id);
      nets.push({
        id,
        points: [],
        leftRail: false,
        rightRail: false,
        sources: [],
        sinks: [],
        links: [],
        vlinks: [],
      });
    }
    netOfPoint[p] = id;
    const net = nets[id]!;
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
    if (el.kind === 'connector' || el.kind === 'continuation') {
      linkNet[index] = netOfPoint[connectionPoint(el, cols)]!;
      return;
    }
    let inputs: Terminal[];
    let outputs: Terminal[];
    let layout: BoxLayout | undefined;
    if (el.kind === 'box') {
      layout = boxLayout(el, library);
      if (!layout) {
        inputs = [];
        outputs = [];
      } else {
        const l = layout;
        inputs = l.inputs.map((pin) => terminal(pin.name, el.row + pin.rowOffset, el.col));
        outputs = l.outputs.map((pin) => terminal(pin.name, el.row + pin.rowOffset, el.col + l.cols));
      }
    } else {
      inputs = [terminal('IN', el.row, el.col)];
      outputs = el.kind === 'jump' || el.kind === 'return' ? [] : [terminal('OUT', el.row, el.col + 1)];
    }
    const node = nodes.length;
    nodes.push({ index, el, ...(layout ? { layout } : {}), inputs, outputs });
    for (const t of inputs) nets[t.net]!.sinks.push({ node, pin: t.pin, point: point(t.row, t.boundary) });
    for (const t of outputs) nets[t.net]!.sources.push({ node, pin: t.pin, point: point(t.row, t.boundary) });
  });

  return { rows, cols, nodes, nets, netOfPoint, linkNet, vlinkNet, misplaced, badVlinks, connections, unpaired };
}

/** True when the net holds wires or element terminals (not just an untouched grid point). */
export const netIsUsed = (net: Net): boolean =>
  net.links.length > 0 || net.vlinks.length > 0 || net.sources.length > 0 || net.sinks.length > 0;
