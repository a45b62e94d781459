// Graph → grid: lays out one network from its wiring, not from coordinates (CODESYS files have none).
// Columns: longest path from the left rail (each net gets one vertical bar at the boundary where its
// last producer ends); coils, jumps and returns are pushed to the right rail. Rows: depth-first along
// the branches — a series element continues its source's row, parallel branches and fan-out go to the
// first row below where their cells, links and bars cross nothing of another net.
import type { BlockLibrary } from '../model/library';
import type { GNode } from './ldNodes';
import { placeRows } from './layoutRows';
import { shapeOf, type LaidOut, type Net, type PinSpec, type Shape } from './layoutShapes';

export interface Prepared {
  readonly nodes: readonly number[];
  readonly needCols: number;
  readonly run: (cols: number) => LaidOut;
}

/**
 * Layout strategies, tried in order until the grid draws the file exactly (see verifyLayout.ts):
 * 0 is the compact one; 1 staggers the vertical bars of a multi-row box's outputs right of the
 * box (an upper pin's bar right of those below it), so no bar runs down the box's edge past its
 * other output pins and no pin's wire crosses the bar of the pin above it.
 */
export const LAYOUT_STRATEGIES = 2;

/** Prepares the layout of the nodes of one network: columns now, rows when the width is known. */
export function prepareLayout(
  all: readonly GNode[],
  members: readonly number[],
  library: BlockLibrary,
  strategy = 0,
): Prepared {
  return new ColumnLayout(all, members, library, strategy);
}

function pinIndex(list: readonly PinSpec[], pin: string): number {
  for (let k = 0; k < list.length; k++) if (list[k]!.pin === pin) return k;
  return -1;
}

/**
 * The column pass of one network. A class, not closures: a file has thousands of networks, and
 * a few dozen closures per network were a large part of the import time.
 */
class ColumnLayout implements Prepared {
  readonly nodes: readonly number[];
  readonly needCols: number;
  private readonly shapes = new Map<number, Shape>();
  private readonly local = new Map<number, number>();
  private readonly inBase: number[];
  private readonly outBase: number[];
  private readonly parent: number[];
  private readonly touched: number[];
  private readonly netOfRoot = new Map<number, Net>();
  private readonly netOfPort: (Net | undefined)[];
  /** Nets by id (ids are given in order). */
  private readonly nets: Net[] = [];
  private readonly col = new Map<number, number>();
  private readonly gap = new Map<Net, number>();
  private readonly topo: number[] = [];
  private readonly tail = new Map<number, number>();
  readonly inNet: (node: number, pin: string) => Net | undefined;
  readonly outNet: (node: number, pin: string) => Net | undefined;

  constructor(
    private readonly all: readonly GNode[],
    members: readonly number[],
    library: BlockLibrary,
    private readonly strategy = 0,
  ) {
    this.nodes = members;
    const { shapes, local } = this;
    for (const i of members) shapes.set(i, shapeOf(all[i]!, library));
    // Nets: union of each wired input pin with its sources. Ports are numbered: 0 is the left rail,
    // then each member's input pins and output pins in shape order.
    for (let li = 0; li < members.length; li++) local.set(members[li]!, li);
    // Plain arrays: a network has a few dozen ports, and typed arrays cost far more to create.
    const inBase: number[] = new Array<number>(members.length).fill(0);
    const outBase: number[] = new Array<number>(members.length).fill(0);
    let ports = 1;
    for (let li = 0; li < members.length; li++) {
      const sh = shapes.get(members[li]!)!;
      inBase[li] = ports;
      ports += sh.inputs.length;
      outBase[li] = ports;
      ports += sh.outputs.length;
    }
    this.inBase = inBase;
    this.outBase = outBase;
    const parent: number[] = new Array<number>(ports).fill(0);
    for (let k = 0; k < ports; k++) parent[k] = k;
    this.parent = parent;
    this.touched = new Array<number>(ports).fill(0);
    this.netOfPort = new Array<Net | undefined>(ports);
    this.inNet = (node, pin) => {
      const k = this.inPort(node, pin);
      return k < 0 ? undefined : this.netOfPort[k];
    };
    this.outNet = (node, pin) => {
      const k = this.outPort(node, pin);
      return k < 0 ? undefined : this.netOfPort[k];
    };
    this.joinNets();
    this.needCols = this.columns();
  }

  private inPort(node: number, pin: string): number {
    const li = this.local.get(node);
    if (li === undefined) return -1;
    const k = pinIndex(this.shapes.get(node)!.inputs, pin);
    return k < 0 ? -1 : this.inBase[li]! + k;
  }
  private outPort(node: number, pin: string): number {
    const li = this.local.get(node);
    if (li === undefined) return -1;
    const k = pinIndex(this.shapes.get(node)!.outputs, pin);
    return k < 0 ? -1 : this.outBase[li]! + k;
  }
  private find(a: number): number {
    const parent = this.parent;
    while (parent[a]! !== a) {
      parent[a] = parent[parent[a]!]!;
      a = parent[a]!;
    }
    return a;
  }
  private union(a: number, b: number): void {
    this.touched[a] = 1;
    this.touched[b] = 1;
    const ra = this.find(a);
    const rb = this.find(b);
    if (ra !== rb) this.parent[ra] = rb;
  }
  private netFor(k: number): Net | undefined {
    if (k < 0 || !this.touched[k]) return undefined;
    const root = this.find(k);
    let net = this.netOfRoot.get(root);
    if (!net) {
      net = {
        id: this.netOfRoot.size,
        producers: [],
        consumers: [],
        rail: false,
        rightRail: false,
        b: 0,
        min: Infinity,
        max: -Infinity,
      };
      this.netOfRoot.set(root, net);
      this.nets.push(net);
    }
    this.netOfPort[k] = net;
    return net;
  }

  private joinNets(): void {
    const { all, nodes: members, shapes, touched } = this;
    for (const i of members) {
      // Keys, not entries: no [pin, sources] pair (nor a callback) for every pin of the file.
      const inputs = all[i]!.inputs;
      for (const pin of inputs.keys()) {
        const k = this.inPort(i, pin);
        if (k < 0) continue;
        touched[k] = 1;
        for (const s of inputs.get(pin)!) {
          const o = s.kind === 'rail' ? 0 : this.outPort(s.node, s.pin);
          if (o >= 0) this.union(k, o);
        }
      }
    }
    if (touched[0]) this.netFor(0)!.rail = true;
    for (const i of members) {
      const sh = shapes.get(i)!;
      for (const p of sh.inputs) this.netFor(this.inPort(i, p.pin))?.consumers.push({ node: i, pin: p.pin });
      for (const p of sh.outputs)
        this.netFor(this.outPort(i, p.pin))?.producers.push({ node: i, pin: p.pin });
      if (all[i]!.feedsRightRail) {
        const o = sh.outputs[0];
        if (o) {
          const k = this.outPort(i, o.pin);
          touched[k] = 1;
          this.netFor(k)!.rightRail = true;
        }
      }
    }
  }

  /** Bars of a box's outputs, staggered: an upper pin's bar lies right of those of the pins below it. */
  private stagger(p: { node: number; pin: string }): number {
    const outs = this.shapes.get(p.node)!.outputs;
    let k = 1;
    let below = false;
    for (const o of outs) {
      if (o.pin === p.pin) below = true;
      else if (below && this.outNet(p.node, o.pin)?.consumers.length) k++;
    }
    return k;
  }
  private tall(node: number): boolean {
    return this.shapes.get(node)!.h > 1;
  }
  private barOf(net: Net): number {
    let b = 0;
    for (const p of net.producers) {
      const c = this.col.get(p.node);
      if (c !== undefined) b = Math.max(b, c + this.shapes.get(p.node)!.w);
    }
    return net.producers.length ? b + this.gap.get(net)! : 0;
  }
  private settle(i: number): void {
    let c = 0;
    if (this.all[i]!.kind === 'continuation') {
      // Drawn right before the pin it feeds (run() moves it there once the columns are known).
      this.col.set(i, 0);
      this.topo.push(i);
      return;
    }
    for (const p of this.shapes.get(i)!.inputs) {
      const net = this.inNet(i, p.pin);
      // Boundary 0 is the left rail on every row: an input that is not wired stays off it. A box
      // keeps one link between its pins and the bar feeding them, so the bar never runs down its edge.
      c = Math.max(c, net ? this.barOf(net) + (this.tall(i) && net.producers.length ? 1 : 0) : 1);
    }
    this.col.set(i, c);
    this.topo.push(i);
  }

  /** Columns: longest path (Kahn over "producers of my input nets"); returns the width needed. */
  private columns(): number {
    const { nodes: members, shapes, nets, col, gap } = this;
    // Dependencies as short arrays (a node has a handful): a Set per node costs far more.
    const deps = new Map<number, number[]>();
    const users = new Map<number, number[]>();
    for (const i of members) {
      const d: number[] = [];
      for (const p of shapes.get(i)!.inputs) {
        const net = this.inNet(i, p.pin);
        if (net) for (const pr of net.producers) if (pr.node !== i && !d.includes(pr.node)) d.push(pr.node);
      }
      deps.set(i, d);
      for (const x of d) {
        let u = users.get(x);
        if (!u) users.set(x, (u = []));
        u.push(i);
      }
    }
    const indeg = new Map<number, number>();
    for (const i of members) indeg.set(i, deps.get(i)!.length);
    const queue: number[] = [];
    for (const i of members) if (indeg.get(i) === 0) queue.push(i);
    // A bar (or a direct join) right at the edge of a multi-row box would touch its other pins:
    // such nets get their bar one boundary further right, with a link from the box.
    for (const net of nets) {
      let tallProducer = false;
      for (const p of net.producers) if (this.tall(p.node)) tallProducer = true;
      let tallConsumer = false;
      for (const c of net.consumers) if (this.tall(c.node)) tallConsumer = true;
      const many = net.producers.length + (net.rail ? 1 : 0) > 1;
      gap.set(net, tallProducer && (net.consumers.length > 1 || many || tallConsumer) ? 1 : 0);
      if (this.strategy >= 1 && tallProducer && (net.consumers.length || many))
        for (const p of net.producers)
          if (this.tall(p.node)) gap.set(net, Math.max(gap.get(net)!, this.stagger(p)));
    }
    for (let qi = 0; qi < queue.length; qi++) {
      const i = queue[qi]!;
      this.settle(i);
      const us = users.get(i);
      if (us)
        for (const u of us) {
          const left = indeg.get(u)! - 1;
          indeg.set(u, left);
          if (left === 0) queue.push(u);
        }
    }
    for (const i of members) if (!col.has(i)) this.settle(i); // feedback loops: best effort
    let needCols = 1;
    for (const i of members) needCols = Math.max(needCols, col.get(i)! + shapes.get(i)!.w);
    for (const net of nets) if (net.consumers.length) needCols = Math.max(needCols, this.barOf(net) + 1);
    return needCols;
  }

  /** Right-aligned tails: coils (and chains of coils), jumps, returns with nothing after them (only the row pass needs them). */
  private tails(): void {
    const { all, topo, tail } = this;
    for (let k = topo.length - 1; k >= 0; k--) {
      const i = topo[k]!;
      const n = all[i]!;
      if (n.kind === 'jump' || n.kind === 'return') tail.set(i, 1);
      else if (n.kind === 'coil') {
        const net = this.outNet(i, 'out');
        const cons = net?.consumers ?? [];
        let allTails = true;
        let longest = 0;
        for (const c of cons) {
          const t = tail.get(c.node);
          if (t === undefined || all[c.node]!.kind !== 'coil') {
            allTails = false;
            break;
          }
          longest = Math.max(longest, t);
        }
        if (allTails && (net?.producers.length ?? 1) <= 1) tail.set(i, 1 + longest);
      }
    }
  }

  run(cols: number): LaidOut {
    const { col, nets } = this;
    this.tails();
    for (const [i, t] of this.tail) col.set(i, Math.max(col.get(i)!, cols - t));
    // A continuation sits in the cell left of the pin it feeds (it feeds one pin, see layoutCut.ts).
    for (const i of this.nodes) {
      if (this.all[i]!.kind !== 'continuation') continue;
      let at = Infinity;
      for (const c of this.outNet(i, 'out')?.consumers ?? []) at = Math.min(at, col.get(c.node)!);
      if (at !== Infinity) col.set(i, Math.max(0, at - 1));
    }
    for (const net of nets) net.b = this.barOf(net);
    return placeRows(this.all, this.nodes, this.shapes, col, nets, this.inNet, this.outNet, cols);
  }
}
