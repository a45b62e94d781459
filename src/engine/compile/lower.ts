// One network: graph, structural rules, evaluation order, then each element's operands and types
// (LD-R07, LD-R08, LD-R10, LD-R11, LD-R12, LD-R13) and the ordered operations for code generation.
import type { CoilElement, ContactElement, JumpElement } from '../../model/elements';
import type { Network } from '../../model/project';
import type { CoilFamily, PouContext } from './context';
import { buildGraph, upstream, type NetworkGraph } from './graph';
import type { NetworkIR, Op, Source } from './ir';
import { evaluationOrder } from './order';
import { describeElement, type Reporter } from './report';
import { checkStructure } from './structure';
import type { Access, Store } from './symbols';
import { lowerBox } from './box';
import { startGenerated } from './generated';

/** Maps graph nets to what the generated code reads for them. */
export class NetMap {
  private readonly power = new Map<number, number>();
  private count = 0;
  /** Graph net -> value source when the net carries a non-BOOL value from a box output. */
  readonly data = new Map<number, Source>();
  /** Nets driven by a block output that is not BOOL by signature, before that block is lowered. */
  readonly dataPending = new Set<number>();
  /**
   * openplc profile: data slots a block with an executionOrderId read before the function driving
   * the net ran (its stored output, generated.ts); that function writes its output there.
   */
  readonly heldData = new Map<number, { readonly store: Store; readonly slot: number }>();
  constructor(readonly g: NetworkGraph) {
    for (const node of g.nodes) {
      if (node.el.kind !== 'box') continue;
      for (const t of node.outputs)
        if (node.layout?.outputs.find((p) => p.name === t.pin)?.type !== 'BOOL') this.dataPending.add(t.net);
    }
  }

  /**
   * openplc profile (generated.ts): the locals of the reading being generated, which take
   * precedence; every reading of a contact gets locals of its own.
   */
  overlay: ReadonlyMap<number, number> | undefined;

  /** A new power-flow local, bound to no graph net (openplc readings). */
  fresh(): number {
    return this.count++;
  }

  /** The power-flow local for a graph net (allocated on first use). */
  powerNet(net: number): number {
    const over = this.overlay?.get(net);
    if (over !== undefined) return over;
    let id = this.power.get(net);
    if (id === undefined) {
      id = this.count++;
      this.power.set(net, id);
    }
    return id;
  }
  /** Makes a graph net share an existing power-flow local (a coil's right side with its left side). */
  alias(net: number, id: number): void {
    if (!this.power.has(net)) this.power.set(net, id);
  }
  hasPower(net: number): boolean {
    return this.power.has(net);
  }
  get powerCount(): number {
    return this.count;
  }
  railNets(): number[] {
    return [
      ...new Set(
        [...this.power].filter(([net]) => net >= 0 && this.g.nets[net]!.leftRail).map(([, id]) => id),
      ),
    ];
  }
  /** True when the net is driven: by the left rail or an element's output (LD-R03: a line that starts nowhere is not). */
  isFed(net: number): boolean {
    return upstream(this.g, net).fed;
  }
  /** True when something besides the terminal itself is attached to the net (a wire or another element). */
  isWired(net: number): boolean {
    const n = this.g.nets[net]!;
    return (
      n.leftRail ||
      n.links.length + n.vlinks.length + n.feeds.length + n.feedsOut.length > 0 ||
      n.sources.length + n.sinks.length > 1
    );
  }
}

const FAMILY: Record<CoilElement['coil'], CoilFamily> = {
  COIL: 'assign',
  M: 'assign',
  NEG: 'negated',
  P: 'pulse',
  N: 'pulse',
  SET: 'latch',
  RESET: 'latch',
  SM: 'latch',
  RM: 'latch',
};

/** A network being lowered: `finish` gives its IR once every network of the POU body is started. */
export interface PendingNetwork {
  finish(): NetworkIR | undefined;
}

export function lowerNetwork(
  ctx: PouContext,
  network: Network,
  index: number,
  r: Reporter,
): NetworkIR | undefined {
  return startNetwork(ctx, network, index, r).finish();
}

/**
 * Starts lowering a network. Profile `openplc`: in the order Beremiz's generator runs it
 * (generated.ts), whose blocks no coil needs are lowered by `finish`, after every network of the
 * body has lowered its coils; `iec`: completely, here.
 */
export function startNetwork(ctx: PouContext, network: Network, index: number, r: Reporter): PendingNetwork {
  const g = buildGraph(network, ctx.symbols.library);
  const structureOk = checkStructure(network, g, r);
  const order = structureOk ? evaluationOrder(g) : undefined;
  if (structureOk && !order)
    r.error(
      'LD-R01',
      'an element feeds its own input through a wire going back to the left; power must flow left to right',
    );
  if (order && ctx.profile === 'openplc') return startGenerated(ctx, network, index, r, g);
  const ir = lowerInOrder(ctx, network, index, r, g, structureOk, order);
  return { finish: () => ir };
}

function lowerInOrder(
  ctx: PouContext,
  network: Network,
  index: number,
  r: Reporter,
  g: NetworkGraph,
  structureOk: boolean,
  order: number[] | undefined,
): NetworkIR | undefined {
  if (!order) {
    order = g.nodes
      .map((_, i) => i)
      .sort((a, b) => g.nodes[a]!.el.row - g.nodes[b]!.el.row || g.nodes[a]!.el.col - g.nodes[b]!.el.col);
  }
  const nets = new NetMap(g);
  const ops: Op[] = [];
  const errorsBefore = r.errors;
  // One-way bridges (graph.ts): a net's bridged-in states are OR-ed into it before it is first read.
  const bridged = new Set<number>();
  const bridgeInto = (net: number): void => {
    for (const b of g.nets[net]!.feeds) {
      if (bridged.has(b)) continue;
      bridged.add(b);
      const { from, via } = g.bridges[b]!;
      bridgeInto(from);
      if (!nets.dataPending.has(from) && !nets.data.has(from))
        ops.push({ op: 'pass', node: via, inNet: nets.powerNet(from), outNet: nets.powerNet(net) });
    }
  };
  /** A block output's own local where its line is joined to others (`node:pin`), for the display. */
  const boxOwn = new Map<string, number>();
  for (const ni of order) {
    const node = g.nodes[ni]!;
    const el = node.el;
    for (const t of node.inputs) bridgeInto(t.net);
    const inNet = node.inputs[0] ? nets.powerNet(node.inputs[0].net) : -1;
    switch (el.kind) {
      case 'contact': {
        const src = el.contact === 'NOT' ? undefined : contactOperand(ctx, el, r);
        const edge = el.contact === 'P' || el.contact === 'N' ? edgeOf(ctx, el, index, r) : undefined;
        const outGraphNet = node.outputs[0]!.net;
        const outNet = nets.powerNet(outGraphNet);
        // Where other outputs join this contact's right side, keep its own result for the power display.
        const out = g.nets[outGraphNet]!;
        const joined = out.sources.length > 1 || out.leftRail || out.feeds.length > 0;
        const ownNet = joined ? nets.powerNet(-1 - ni) : undefined;
        ops.push(contactOp(node.index, el.contact, src, inNet, outNet, ownNet, edge));
        break;
      }
      case 'coil': {
        const dst = coilOperand(ctx, el, index, r);
        const edge = el.coil === 'P' || el.coil === 'N' ? edgeOf(ctx, el, index, r) : undefined;
        // A coil passes its left link on: when nothing else drives its right side, both sides are one net.
        const outGraph = g.nets[node.outputs[0]!.net]!;
        if (outGraph.sources.length === 1 && !outGraph.leftRail && !outGraph.feeds.length && inNet >= 0)
          nets.alias(outGraph.id, inNet);
        const outNet = nets.powerNet(outGraph.id);
        // LD-R03: a coil fed by nothing is not executed (Beremiz generates no assignment for a coil
        // whose input has no connection), so its variable keeps its value.
        const fed = node.inputs[0] !== undefined && nets.isFed(node.inputs[0].net);
        if (dst && fed)
          ops.push({
            op: 'coil',
            node: node.index,
            coil: el.coil,
            dst,
            inNet,
            outNet,
            ...(edge !== undefined ? { edge } : {}),
          });
        break;
      }
      case 'jump': {
        const target = jumpTarget(ctx, el, index, r);
        if (target !== undefined) ops.push({ op: 'jump', node: node.index, inNet, target });
        break;
      }
      case 'return':
        ops.push({ op: 'return', node: node.index, inNet });
        break;
      case 'box': {
        // Where other outputs join a BOOL output's line (an OR further right), the block writes the
        // output to a local of its own, OR-ed into the line after the call: the line from the
        // output shows the output, not the OR (a horizontal link copies its left side, section 1).
        const own: (readonly [net: number, id: number, pin: string])[] = [];
        for (const t of node.outputs) {
          const out = g.nets[t.net]!;
          const type = node.layout?.outputs.find((p) => p.name === t.pin)?.type;
          if (type !== 'BOOL' || nets.data.has(t.net) || nets.dataPending.has(t.net)) continue;
          if (out.sources.length > 1 || out.leftRail || out.feeds.length > 0) own.push([t.net, nets.fresh(), t.pin]);
        }
        const saved = nets.overlay;
        if (own.length) nets.overlay = new Map([...(saved ?? []), ...own.map(([net, id]) => [net, id] as const)]);
        const op = lowerBox(ctx, node, nets, index, r);
        nets.overlay = saved;
        if (op) ops.push(op);
        for (const [net, id, pin] of own) {
          ops.push({ op: 'pass', node: node.index, inNet: id, outNet: nets.powerNet(net) });
          boxOwn.set(`${ni}:${pin}`, id);
        }
        break;
      }
    }
  }
  // Nets read by no element (a line to the right rail) still show their state.
  for (const net of g.nets) bridgeInto(net.id);
  if (!structureOk || r.errors > errorsBefore) return undefined;

  const elementNets = network.elements.map((el, i): [number, number] => {
    if (el.kind === 'link' || el.kind === 'connector' || el.kind === 'continuation') {
      // A line from one contact to an OR shows the contact's own result (section 1).
      const own = g.linkSource[i]!;
      const boxed = own >= 0 ? boxOwn.get(`${own}:${g.linkSourcePin[i]}`) : undefined;
      if (boxed !== undefined) return [boxed, boxed];
      if (own >= 0 && nets.hasPower(-1 - own)) return [nets.powerNet(-1 - own), nets.powerNet(-1 - own)];
      const net = g.linkNet[i]!;
      return net >= 0 && nets.hasPower(net) ? [nets.powerNet(net), nets.powerNet(net)] : [-1, -1];
    }
    const node = g.nodes.find((n) => n.index === i);
    if (!node) return [-1, -1];
    const pin = (ts: typeof node.inputs, name: string | undefined) => {
      const t = name === undefined ? ts[0] : ts.find((x) => x.pin === name);
      return t && nets.hasPower(t.net) ? nets.powerNet(t.net) : -1;
    };
    if (el.kind === 'contact') {
      const ni = g.nodes.indexOf(node);
      return [
        pin(node.inputs, undefined),
        nets.hasPower(-1 - ni) ? nets.powerNet(-1 - ni) : pin(node.outputs, undefined),
      ];
    }
    if (el.kind === 'coil') return [pin(node.inputs, undefined), pin(node.inputs, undefined)]; // a coil passes its left link on
    if (el.kind !== 'box') return [pin(node.inputs, undefined), pin(node.outputs, undefined)];
    const pIn = node.layout?.inputs.find((p) => p.type === 'BOOL')?.name;
    const pOut = node.layout?.outputs.find((p) => p.type === 'BOOL')?.name;
    const outOwn = pOut ? boxOwn.get(`${g.nodes.indexOf(node)}:${pOut}`) : undefined;
    return [pIn ? pin(node.inputs, pIn) : -1, outOwn ?? (pOut ? pin(node.outputs, pOut) : -1)];
  });
  const vlinkNets = network.vlinks.map((_, i) => {
    const net = g.vlinkNet[i]!;
    return net >= 0 && nets.hasPower(net) ? nets.powerNet(net) : -1;
  });
  return networkIR(ctx, network, index, nets, { ops, elementNets, vlinkNets });
}

/** A lowered network's IR from its operations and its elements' nets. */
export function networkIR(
  ctx: PouContext,
  network: Network,
  index: number,
  nets: NetMap,
  parts: Pick<NetworkIR, 'ops' | 'elementNets' | 'vlinkNets' | 'late' | 'early' | 'earlyOrder'>,
): NetworkIR {
  return {
    index: ctx.first + index,
    ...(network.label ? { label: network.label } : {}),
    ops: parts.ops,
    netCount: nets.powerCount,
    railNets: nets.railNets(),
    elementNets: parts.elementNets,
    vlinkNets: parts.vlinkNets,
    constants: [],
    ...(parts.late?.length ? { late: parts.late } : {}),
    ...(parts.early?.length ? { early: parts.early, earlyOrder: parts.earlyOrder ?? [] } : {}),
  };
}

/** The network a jump goes to (LD-R07: its label exists); `back`: warn when it jumps back (LD-W03). */
export function jumpTarget(ctx: PouContext, el: JumpElement, index: number, r: Reporter, back = true): number | undefined {
  const target = ctx.labels.get(el.target.trim().toUpperCase());
  if (el.target.trim() === '')
    r.error(
      'LD-R07',
      `${describeElement(el)} names no label; write the label of the network to continue at`,
      el,
    );
  else if (target === undefined)
    r.error(
      'LD-R07',
      `${describeElement(el)} has no target: no network of ${ctx.pouName} is labelled "${el.target}"`,
      el,
    );
  // LD-W03: a jump back (to its own network or an earlier one) runs those networks again in
  // the same scan, looping until its condition goes FALSE (the watchdog stops an endless one).
  else if (back && target - ctx.first <= index)
    r.warning(
      'LD-W03',
      `${describeElement(el)} jumps back to network ${target - ctx.first + 1} ("${el.target.trim()}"): legal, but networks ${target - ctx.first + 1} to ${index + 1} run again in the same scan until the jump's condition goes FALSE; make sure it does, or the watchdog stops the PLC`,
      el,
    );
  return target;
}

/** A contact's operation (`ownNet`: its own result where other outputs join its right side). */
export function contactOp(
  node: number,
  contact: ContactElement['contact'],
  src: Access | undefined,
  inNet: number,
  outNet: number,
  ownNet: number | undefined,
  edge: number | undefined,
): Op {
  return {
    op: 'contact',
    node,
    contact,
    ...(src ? { src } : {}),
    inNet,
    outNet,
    ...(ownNet !== undefined ? { ownNet } : {}),
    ...(edge !== undefined ? { edge } : {}),
  };
}

/** The edge memory of a |P| |N| contact or (P) (N) coil; a FUNCTION has none to keep (LD-E22). */
export function edgeOf(ctx: PouContext, el: ContactElement | CoilElement, network: number, r: Reporter, trace = 0): number {
  if (ctx.pouKind === 'FUNCTION' && trace === 0)
    r.error(
      'LD-E22',
      `${describeElement(el)} detects an edge, which a FUNCTION cannot: a function keeps nothing between calls, so the memory of the previous value would be lost; use a FUNCTION_BLOCK`,
      el,
    );
  return ctx.edges.allocate(el, ctx.pouName, network, ctx.instance, trace);
}

export function contactOperand(ctx: PouContext, el: ContactElement, r: Reporter): Access | undefined {
  const edge = el.contact === 'P' || el.contact === 'N';
  if (el.variable.trim() === '') {
    r.error('LD-R08', `${describeElement(el)} names no variable; write a BOOL variable on it`, el);
    return undefined;
  }
  const res = ctx.symbols.resolve(el.variable, {
    expected: 'BOOL',
    literals: !edge,
    implicitLocations: true,
  });
  if (!res.ok) {
    const constant = /constant/.test(res.message) || /^(TRUE|FALSE)$/i.test(el.variable.trim());
    r.error(
      'LD-R08',
      edge && constant
        ? `${describeElement(el)} names a constant; a transition contact needs a BOOL variable`
        : `${describeElement(el)}: ${res.message}`,
      el,
    );
    return undefined;
  }
  if (res.access.type !== 'BOOL') {
    r.error(
      'LD-R08',
      `${describeElement(el)} names ${res.access.type} ${accessWords(res.access)}; a contact needs a BOOL variable, an FB's BOOL pin or a bit like Word.3`,
      el,
    );
    return undefined;
  }
  return res.access;
}

export function coilOperand(ctx: PouContext, el: CoilElement, network: number, r: Reporter): Access | undefined {
  if (el.variable.trim() === '') {
    r.error('LD-R08', `${describeElement(el)} names no variable; write a BOOL variable on it`, el);
    return undefined;
  }
  const res = ctx.symbols.resolve(el.variable, {
    expected: 'BOOL',
    literals: false,
    implicitLocations: true,
  });
  if (!res.ok) {
    r.error(
      'LD-R08',
      `${describeElement(el)}: ${res.message}${/constant/.test(res.message) ? '; a coil must write a BOOL variable' : ''}`,
      el,
    );
    return undefined;
  }
  const a = res.access;
  if (a.type !== 'BOOL') {
    r.error(
      'LD-R08',
      `${describeElement(el)} names ${a.type} ${accessWords(a)}; a coil needs a BOOL variable, an FB's BOOL input or a bit like Word.3`,
      el,
    );
    return undefined;
  }
  if (a.kind === 'pin' && a.dir === 'out') {
    r.error(
      'LD-R08',
      `${describeElement(el)} writes the output ${a.fb.name}.${a.pin}, which only the block itself sets`,
      el,
    );
    return undefined;
  }
  if ((a.kind === 'var' || a.kind === 'bit') && a.v.constant) {
    r.error('LD-R08', `${describeElement(el)} writes "${a.v.name}", which is declared CONSTANT`, el);
    return undefined;
  }
  if (a.kind === 'var' || a.kind === 'bit') {
    const v = a.v;
    if (v.location?.area === 'I')
      r.warning(
        'LD-R13',
        `${describeElement(el)} writes the input ${v.locationText}; the next input read overwrites it`,
        el,
      );
    if (el.coil === 'M' || el.coil === 'SM' || el.coil === 'RM') ctx.retentiveCoilVars.add(v);
    if (a.kind === 'var') {
      let families = ctx.coilWrites.get(v);
      if (!families) ctx.coilWrites.set(v, (families = new Map()));
      if (!families.has(FAMILY[el.coil]))
        families.set(FAMILY[el.coil], { network, row: el.row, col: el.col });
    }
  }
  return a;
}

export function accessWords(a: Access): string {
  switch (a.kind) {
    case 'var':
      return `"${a.v.name}"`;
    case 'bit':
      return `bit ${a.bit} of "${a.v.name}"`;
    case 'pin':
      return `"${a.fb.name}.${a.pin}"`;
    case 'const':
      return `constant ${a.text}`;
    case 'elem':
      return `"${a.text}"`;
  }
}
