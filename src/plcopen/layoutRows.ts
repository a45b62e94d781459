// Second layout pass: rows. Depth-first along the branches — a series element continues its
// source's row; parallel branches and fan-out go to the first row below where their cells, links and
// vertical bars touch nothing of another net.
import type { LdElement, VLink } from '../model/elements';
import { newId, type ElementId } from '../model/ids';
import type { GNode } from './ldNodes';
import { KEY, type LaidOut, type Net, type Shape } from './layoutShapes';
import { sortInstances } from './generatorOrder';

type NetOf = (node: number, pin: string) => Net | undefined;
type ChainTarget = { box: number; off: number } | null;

export function placeRows(
  all: readonly GNode[],
  members: readonly number[],
  shapes: Map<number, Shape>,
  col: Map<number, number>,
  nets: readonly Net[],
  inNet: NetOf,
  outNet: NetOf,
  cols: number,
): LaidOut {
  return new RowPlacer(all, members, shapes, col, nets, inNet, outNet, cols).run();
}

/**
 * The state of placing one network's rows. A class, not closures: a file has thousands of
 * networks, and a few dozen closures per network were a large part of the import time.
 */
class RowPlacer {
  readonly cellOwner = new Map<number, number>(); // cell -> node index (>=0) or -(net id + 1) for links
  readonly pointNet = new Map<number, number>(); // point -> net id, or a unique negative id when blocked
  blockedId = -1;
  readonly row = new Map<number, number>();
  readonly elements: LdElement[] = [];
  readonly elementOf = new Map<number, ElementId>();
  readonly vlinks = new Map<number, VLink>();
  readonly forced: number[] = [];
  maxRow = -1;
  // Element ids: one fresh prefix per network and a counter (as unique as newId, far cheaper).
  readonly prefix = newId<'ElementId'>('e');
  counter = 0;
  readonly mine = new Map<number, number>();
  own = -1;
  readonly chainOf = new Map<number, ChainTarget>();
  readonly placing = new Set<number>();
  readonly byPosition: (a: number, b: number) => number;
  /** Beremiz's order of coils (SortInstances: by x when the tops are less than 10 apart, else by y), then file order. */
  readonly drawnOrder: (a: number, b: number) => number;
  /** Set once every other node is placed: continuations left over are placed on their own. */
  leftovers = false;

  constructor(
    readonly all: readonly GNode[],
    readonly members: readonly number[],
    readonly shapes: Map<number, Shape>,
    readonly col: Map<number, number>,
    readonly nets: readonly Net[],
    readonly inNet: NetOf,
    readonly outNet: NetOf,
    readonly cols: number,
  ) {
    this.byPosition = (a, b) =>
      all[a]!.y - all[b]!.y || all[a]!.x - all[b]!.x || all[a]!.order - all[b]!.order;
    this.drawnOrder = (a, b) => sortInstances(all[a]!, all[b]!) || all[a]!.order - all[b]!.order;
  }

  nextId(): ElementId {
    return `${this.prefix}_${(this.counter++).toString(36)}` as ElementId;
  }

  pointOk(r: number, b: number, net: Net): boolean {
    if (b === this.cols) return true;
    if (b === 0) return net.rail;
    const v = this.pointNet.get(r * KEY + b);
    return v === undefined || v === net.id;
  }
  cellOk(r: number, c: number, net: Net | undefined): boolean {
    const v = this.cellOwner.get(r * KEY + c);
    return v === undefined || (net !== undefined && v === -(net.id + 1));
  }
  /** Takes point (row, b) for net in `mine` unless another net holds it. */
  take(row: number, b: number, net: Net, mine: Map<number, number>): boolean {
    if (!this.pointOk(row, b, net)) return false;
    if (b === 0 || b === this.cols) return true;
    const k = row * KEY + b;
    const m = mine.get(k);
    if (m !== undefined && m !== net.id) return false;
    mine.set(k, net.id);
    return true;
  }
  /** Whether net may run on row r from boundary a to z (and its bar reach r); `mine` holds the
   * points the same placement already uses, so two pins of one box cannot cross each other. */
  runOk(r: number, a: number, z: number, net: Net, mine: Map<number, number>): boolean {
    for (let c = a; c < z; c++) if (!this.cellOk(r, c, net)) return false;
    for (let b = a; b <= z; b++) if (!this.take(r, b, net, mine)) return false;
    if (net.b > 0) {
      const lo = net.min === Infinity ? r : Math.min(r, net.min);
      const hi = net.max === -Infinity ? r : Math.max(r, net.max);
      for (let rr = lo; rr <= hi; rr++) if (!this.take(rr, net.b, net, mine)) return false;
    }
    return true;
  }
  /** Horizontal run of net on row r from boundary a to boundary z (a <= z), plus the bar reaching r. */
  claimRun(r: number, a: number, z: number, net: Net): void {
    const cols = this.cols;
    for (let c = a; c < z; c++) {
      const k = r * KEY + c;
      if (this.cellOwner.get(k) === undefined) {
        this.cellOwner.set(k, -(net.id + 1));
        this.elements.push({ id: this.nextId(), kind: 'link', row: r, col: c });
      }
    }
    for (let b = a; b <= z; b++) if (b !== 0 && b !== cols) this.pointNet.set(r * KEY + b, net.id);
    if (net.b > 0) {
      const lo = Math.min(r, net.min === Infinity ? r : net.min);
      const hi = Math.max(r, net.max === -Infinity ? r : net.max);
      for (let rr = lo; rr < hi; rr++) this.vlinks.set(rr * KEY + net.b, { row: rr, boundary: net.b });
      for (let rr = lo; rr <= hi; rr++) this.pointNet.set(rr * KEY + net.b, net.id);
    }
    net.min = Math.min(net.min, r);
    net.max = Math.max(net.max, r);
  }

  block(row: number, b: number): boolean {
    const k = row * KEY + b;
    if (this.pointNet.has(k) || this.mine.has(k)) return false;
    this.mine.set(k, this.own--);
    return true;
  }
  /**
   * The continuations that alone feed this input pin, not yet placed: drawn with the pin, the first
   * on its row and the others below it in the same column, OR-ed by the pin's bar (layoutCut.ts
   * gives a pin one continuation per source where a source also feeds other ORs).
   */
  pendingContinuations(net: Net | undefined): number[] | undefined {
    if (!net || !net.producers.length || net.rail) return undefined;
    const list: number[] = [];
    for (const p of net.producers) {
      if (this.all[p.node]!.kind !== 'continuation' || this.row.has(p.node)) return undefined;
      list.push(p.node);
    }
    return list.length > 1 ? sortSmall(list, this.byPosition) : list;
  }
  fits(i: number, r: number): boolean {
    const sh = this.shapes.get(i)!;
    const c = this.col.get(i)!;
    const mine = this.mine;
    mine.clear();
    this.own = -1;
    for (let y = 0; y < sh.h; y++)
      for (let x = 0; x < sh.w; x++) if (this.cellOwner.has((r + y) * KEY + c + x)) return false;
    for (const p of sh.inputs) {
      const net = this.inNet(i, p.pin);
      const ks = this.pendingContinuations(net);
      if (!ks) continue;
      for (let j = 0; j < ks.length; j++) {
        const kc = this.col.get(ks[j]!)!;
        const rr = r + p.off + j;
        if (this.cellOwner.has(rr * KEY + kc)) return false;
        if (kc !== 0 && !this.block(rr, kc)) return false;
        // Below the pin's row: the continuation's output and the bar up to the pin.
        if (j > 0 && !this.runOk(rr, kc + 1, kc + 1, net!, mine)) return false;
      }
    }
    for (let y = 0; y < sh.h; y++) for (let x = 1; x < sh.w; x++) if (!this.block(r + y, c + x)) return false;
    for (const p of sh.inputs) {
      const net = this.inNet(i, p.pin);
      if (net) {
        if (!this.runOk(r + p.off, Math.min(net.b, c), c, net, mine)) return false;
      } else if (c !== 0 && !this.block(r + p.off, c)) return false;
    }
    for (const p of sh.outputs) {
      const net = this.outNet(i, p.pin);
      const end = c + sh.w;
      if (net && (net.consumers.length || net.producers.length > 1)) {
        if (!this.runOk(r + p.off, end, Math.max(net.b, end), net, mine)) return false;
      } else if (end !== this.cols && !this.block(r + p.off, end)) return false;
    }
    return true;
  }

  commit(i: number, r: number): void {
    const n = this.all[i]!;
    const sh = this.shapes.get(i)!;
    const c = this.col.get(i)!;
    const { cellOwner, pointNet, cols } = this;
    this.row.set(i, r);
    this.maxRow = Math.max(this.maxRow, r + sh.h - 1);
    for (let y = 0; y < sh.h; y++) for (let x = 0; x < sh.w; x++) cellOwner.set((r + y) * KEY + c + x, i);
    for (let y = 0; y < sh.h; y++)
      for (let x = 1; x < sh.w; x++) pointNet.set((r + y) * KEY + c + x, this.blockedId--);
    for (const p of sh.inputs) {
      const net = this.inNet(i, p.pin);
      if (net) this.claimRun(r + p.off, Math.min(net.b, c), c, net);
      else if (c !== 0) pointNet.set((r + p.off) * KEY + c, this.blockedId--);
    }
    for (const p of sh.outputs) {
      const net = this.outNet(i, p.pin);
      const end = c + sh.w;
      if (net && (net.consumers.length || net.producers.length > 1))
        this.claimRun(r + p.off, end, Math.max(net.b, end), net);
      else if (end !== cols) pointNet.set((r + p.off) * KEY + end, this.blockedId--);
    }
    const id = this.nextId();
    this.elementOf.set(i, id);
    this.elements.push(elementFor(n, id, r, c));
  }

  preferredRow(i: number): number {
    const sh = this.shapes.get(i)!;
    let best = Infinity;
    for (const p of sh.inputs) {
      const net = this.inNet(i, p.pin);
      if (!net) continue;
      for (const pr of net.producers) {
        const pr_r = this.row.get(pr.node);
        if (pr_r === undefined) continue;
        const off = pinOffset(this.shapes.get(pr.node)!.outputs, pr.pin);
        best = Math.min(best, pr_r + off - p.off);
      }
    }
    return best === Infinity ? 0 : Math.max(0, best);
  }

  // A chain of contacts from the rail that only feeds a lower pin of a box (R of a counter, G of a
  // SEL) is drawn on that pin's row, after the box: placed first, at the top, its wire would have to
  // cross the pins of the boxes between.
  chainTarget(n: number, depth = 0): ChainTarget {
    const known = this.chainOf.get(n);
    if (known !== undefined) return known;
    let result: ChainTarget = null;
    const out = this.all[n]!.kind === 'contact' && depth < 64 ? this.outNet(n, 'out') : undefined;
    const inn = out ? this.inNet(n, 'in') : undefined;
    const fromRail = inn ? inn.rail && inn.producers.length === 0 : false;
    const fromChain = inn ? !inn.rail && inn.producers.length === 1 && inn.consumers.length === 1 : false;
    if (
      out &&
      inn &&
      (fromRail || fromChain) &&
      out.producers.length === 1 &&
      out.consumers.length === 1 &&
      !out.rail
    ) {
      const c = out.consumers[0]!;
      const sh = this.shapes.get(c.node)!;
      if (sh.h > 1) {
        const off = pinOffset(sh.inputs, c.pin);
        result = off > 0 ? { box: c.node, off } : null;
      } else result = this.chainTarget(c.node, depth + 1);
    }
    this.chainOf.set(n, result);
    return result;
  }

  /** Places the nodes of these pins top to bottom, then left to right (as drawn in the file). */
  inOrder(pins: readonly { node: number }[]): void {
    if (pins.length === 1) return this.place(pins[0]!.node);
    const nodes: number[] = new Array<number>(pins.length);
    for (let k = 0; k < pins.length; k++) nodes[k] = pins[k]!.node;
    for (const n of sortSmall(nodes, this.byPosition)) this.place(n);
  }
  /**
   * Consumers of a net, top to bottom as drawn (parallel coils in the order Beremiz runs them),
   * except those waiting for a source still being placed (that source places them). While another
   * consumer of the net is being placed (this net is one of its sources), none is placed: that
   * consumer's rows come first (a TON drawn below a counter whose reset it feeds, also driving a
   * coil: the coil placed first would take the counter's rows).
   */
  consumersOf(net: Net): void {
    if (this.placing.size)
      for (const c of net.consumers) if (this.placing.has(c.node)) return;
    const nodes: number[] = new Array<number>(net.consumers.length);
    for (let k = 0; k < nodes.length; k++) nodes[k] = net.consumers[k]!.node;
    if (nodes.length > 1) sortSmall(nodes, this.drawnOrder);
    for (const c of nodes) if (this.placing.size === 0 || !this.waiting(c)) this.place(c);
  }
  /** Whether a producer of one of the node's input nets is being placed. */
  waiting(i: number): boolean {
    for (const p of this.shapes.get(i)!.inputs) {
      const net = this.inNet(i, p.pin);
      if (net) for (const pr of net.producers) if (pr.node !== i && this.placing.has(pr.node)) return true;
    }
    return false;
  }
  /** Whether a producer of this net other than `i` is being placed (its sources first). */
  siblingPlacing(net: Net, i: number): boolean {
    for (const pr of net.producers) if (pr.node !== i && this.placing.has(pr.node)) return true;
    return false;
  }
  place(i: number, prefer?: number): void {
    if (this.row.has(i) || this.placing.has(i)) return;
    // A continuation is drawn with the pin it feeds (unless that failed: then where it fits).
    if (this.all[i]!.kind === 'continuation' && !this.leftovers) return;
    this.placing.add(i);
    const sh = this.shapes.get(i)!;
    let later: { node: number; row: number }[] | undefined;
    let conts: { node: number; row: number }[] | undefined;
    // Everything feeding my input bars first, top to bottom (chains drawn on a lower pin: after me).
    for (const p of sh.inputs) {
      const net = this.inNet(i, p.pin);
      if (!net) continue;
      const ks = this.pendingContinuations(net);
      if (ks) {
        ks.forEach((k, j) => (conts ??= []).push({ node: k, row: p.off + j }));
        continue;
      }
      const only = net.producers.length === 1 ? net.producers[0]!.node : undefined;
      if (only !== undefined && !this.row.has(only) && this.chainTarget(only)?.box === i) {
        (later ??= []).push({ node: only, row: p.off });
        continue;
      }
      const chained = prefer !== undefined && only !== undefined && this.chainTarget(only) !== null;
      if (chained) this.place(only, prefer);
      else this.inOrder(net.producers);
    }
    let r = prefer ?? this.preferredRow(i);
    while (r <= this.maxRow + 1 && !this.fits(i, r)) r++;
    if (r > this.maxRow + 1) {
      r = this.maxRow + 1;
      this.forced.push(i);
    }
    this.commit(i, r);
    if (conts) for (const k of conts) if (!this.row.has(k.node)) this.commit(k.node, r + k.row);
    this.placing.delete(i);
    if (later) for (const l of later) this.place(l.node, r + l.row);
    // Then what I feed: siblings in the same bars, then consumers, depth-first. Siblings wait while
    // one of them is still being placed (its own sources come first): placed now, they would take
    // the rows between that sibling's branches, and its wires would cross theirs.
    for (const p of sh.outputs) {
      const net = this.outNet(i, p.pin);
      if (!net) continue;
      if (!this.siblingPlacing(net, i)) this.inOrder(net.producers);
      if (net.consumers.length === 1 && this.placing.size === 0) this.place(net.consumers[0]!.node);
      else this.consumersOf(net);
    }
  }

  run(): LaidOut {
    const { nets, shapes, col, cellOwner, pointNet, cols, row } = this;
    let railNet: Net | undefined;
    for (const n of nets)
      if (n.rail) {
        railNet = n;
        break;
      }
    const starts: number[] = [];
    if (railNet) for (const c of railNet.consumers) starts.push(c.node);
    sortSmall(starts, this.byPosition);
    for (const i of starts) if (!this.chainTarget(i)) this.place(i);
    const rest = sortSmall([...this.members], this.byPosition);
    for (const i of rest) if (!this.chainTarget(i)) this.place(i);
    for (const i of rest) this.place(i);
    this.leftovers = true;
    for (const i of rest) this.place(i);

    // Cosmetic: wires to the right rail where the row is free.
    for (const net of nets) {
      if (!net.rightRail || net.consumers.length) continue;
      for (const pr of net.producers) {
        const r = row.get(pr.node)! + pinOffset(shapes.get(pr.node)!.outputs, pr.pin);
        const end = col.get(pr.node)! + shapes.get(pr.node)!.w;
        if (end >= cols) continue;
        let ok = true;
        for (let c = end; c < cols && ok; c++) ok = !cellOwner.has(r * KEY + c);
        for (let b = end + 1; b < cols && ok; b++)
          ok = !pointNet.has(r * KEY + b) || pointNet.get(r * KEY + b) === net.id;
        if (ok) {
          const save = net.b;
          net.b = 0;
          this.claimRun(r, end, cols, net);
          net.b = save;
        }
      }
    }
    return {
      rows: Math.max(1, this.maxRow + 1),
      cols,
      elements: this.elements,
      vlinks: [...this.vlinks.values()],
      elementOf: this.elementOf,
      forced: this.forced,
    };
  }
}

/** Offset of a pin in a list of pins (0 when absent). */
function pinOffset(list: readonly { pin: string; off: number }[], pin: string): number {
  for (let k = 0; k < list.length; k++) if (list[k]!.pin === pin) return list[k]!.off;
  return 0;
}

/**
 * The model element of a placed node, with the file's `<documentation>` of a contact, coil or block
 * as the element's own comment.
 */
export function elementFor(n: GNode, id: ElementId, r: number, c: number): LdElement {
  const el = bareElementFor(n, id, r, c);
  if (el.kind !== 'contact' && el.kind !== 'coil' && el.kind !== 'box') return el;
  const comment = n.obj.documentation();
  return comment ? { ...el, comment } : el;
}

/** Literal objects, not spreads of a shared base: this runs for every element of the file. */
function bareElementFor(n: GNode, id: ElementId, r: number, c: number): LdElement {
  switch (n.kind) {
    case 'contact':
      return { id, row: r, col: c, kind: 'contact', contact: n.contact ?? 'NO', variable: n.variable ?? '' };
    case 'coil':
      return { id, row: r, col: c, kind: 'coil', coil: n.coil ?? 'COIL', variable: n.variable ?? '' };
    case 'jump':
      return { id, row: r, col: c, kind: 'jump', target: n.target ?? '' };
    case 'return':
      return { id, row: r, col: c, kind: 'return' };
    case 'connector':
    case 'continuation':
      return { id, row: r, col: c, kind: n.kind, name: n.name ?? '' };
    case 'box':
      return {
        id,
        row: r,
        col: c,
        kind: 'box',
        blockType: n.blockType ?? '',
        ...(n.instance ? { instance: n.instance } : {}),
        ...(n.inputCount !== undefined ? { inputCount: n.inputCount } : {}),
        ...(n.executionControl ? { executionControl: true } : {}),
        ...(n.implicitEn && n.inputs.has('EN') ? { enOpen: true } : {}),
        inputs: { ...n.operandsIn },
        outputs: { ...n.operandsOut },
        ...(n.executionOrder ? { executionOrder: n.executionOrder } : {}),
        ...(n.outputOrders ? { outputOrders: { ...n.outputOrders } } : {}),
      };
  }
}
/** Stable in-place sort; insertion sort for the short lists of one network (no work array). */
function sortSmall(a: number[], cmp: (x: number, y: number) => number): number[] {
  if (a.length > 24) return a.sort(cmp);
  for (let i = 1; i < a.length; i++) {
    const v = a[i]!;
    let j = i - 1;
    while (j >= 0 && cmp(a[j]!, v) > 0) {
      a[j + 1] = a[j]!;
      j--;
    }
    a[j + 1] = v;
  }
  return a;
}
