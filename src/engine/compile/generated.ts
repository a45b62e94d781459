// Profile `openplc` (LD-SEMANTICS.md section 6): an LD network lowered in the order in which
// Beremiz and OpenPLC run it. Their generator (PLCGenerator.py, ComputeProgram) does not run the
// graph: it writes one ST statement per coil, in drawing order over the whole POU body, each
// re-tracing the coil's path from the left rail (ComputeExpression), so:
// - every coil (and every block output written to a variable: an outVariable) takes its turn by
//   position: network, then row, then column;
// - at a coil's turn, every contact of its path is read again, with locals of its own (a contact
//   on the paths of two coils is read twice; a |P| |N| contact gets a new edge memory per
//   reading: a new R_TRIG/F_TRIG each time the generator traces it);
// - a coil in series passes its left side on (the generator traces through it);
// - a block (function, FB, user block; also the inverting contact, which the export writes as a
//   NOT block) runs once (ComputedBlocks), at the first coil or output variable that needs it, its
//   inputs traced at that moment; later readings read its stored outputs;
// - blocks no coil or output variable needs run after every coil of the POU body (`late`,
//   finished by pou.ts once all networks are started);
// - a function with no input connected is not called (LD-W22); jumps and RETURNs are never
//   generated: they do nothing (LD-W20, LD-W21).
// Inside one coil's reading the elements run in the graph's order (inputs first). The generator
// instead calls the blocks and R_TRIGs of the path first and reads the plain contacts in the
// coil's statement; the two differ only when a contact of the path reads an output of a block
// called in the same reading. A branch that splits and joins again is read once per coil here;
// the generator writes its upstream part twice (the same values, except an edge contact there,
// which gets two memories).
import type { BoxElement } from '../../model/elements';
import type { Network } from '../../model/project';
import { isElementaryType } from '../../model/iecTypes';
import { lowerBox } from './box';
import type { PouContext } from './context';
import { upstream, type GraphNode, type NetworkGraph } from './graph';
import type { NetworkIR, Op } from './ir';
import { coilOperand, contactOp, contactOperand, edgeOf, jumpTarget, NetMap, networkIR, type PendingNetwork } from './lower';
import { describeElement, type Reporter } from './report';
import type { Access } from './symbols';

type Pair = readonly [number, number];

const at = (g: NetworkGraph, ni: number) => g.nodes[ni]!.el;
const byPosition = (a: { row: number; col: number }, b: { row: number; col: number }) => a.row - b.row || a.col - b.col;

/** Blocks for the generator: boxes and inverting contacts (exported as NOT blocks). */
const isBlock = (node: GraphNode): boolean =>
  node.el.kind === 'box' || (node.el.kind === 'contact' && node.el.contact === 'NOT');

export function startGenerated(
  ctx: PouContext,
  network: Network,
  index: number,
  r: Reporter,
  g: NetworkGraph,
): PendingNetwork {
  const nets = new NetMap(g);
  const errorsBefore = r.errors;
  const ops: Op[] = [];
  const late: Op[] = [];
  let sink = ops;
  /** The locals of the reading being generated: graph net -> local. */
  let trace = new Map<number, number>();
  const readings = new Map<number, number>();
  const computed = new Set<number>();
  const blockOut = new Map<number, Map<string, number>>();
  /** Element (node) -> [left, right] locals of its latest evaluation; graph net -> latest local. */
  const latest = new Map<number, Pair>();
  const latestNet = new Map<number, number>();
  const wiredIn = (net: number) => nets.isWired(net) && nets.isFed(net);

  // Operands are checked once per element, whether or not a coil reads it.
  const operands = new Map<number, Access | undefined>();
  g.nodes.forEach((node, ni) => {
    const el = node.el;
    if (el.kind === 'contact' && el.contact !== 'NOT') operands.set(ni, contactOperand(ctx, el, r));
    if (el.kind === 'jump' || el.kind === 'return') {
      if (el.kind === 'jump') jumpTarget(ctx, el, index, r, false);
      const what = el.kind === 'jump' ? 'jump' : 'RETURN';
      r.warning(
        el.kind === 'jump' ? 'LD-W20' : 'LD-W21',
        `${describeElement(el)}: Beremiz and OpenPLC drop this ${what} (their generator never writes it): under the openplc profile it does nothing${el.kind === 'jump' ? ' and the networks after it run' : ''}`,
        el,
      );
    }
  });

  const bind = (net: number, id: number): number => {
    trace.set(net, id);
    latestNet.set(net, id);
    return id;
  };

  /** The local holding a net's value in the current reading, generating what it needs. */
  const value = (net: number): number => {
    const hit = trace.get(net);
    if (hit !== undefined) return hit;
    const n = g.nets[net]!;
    if (n.leftRail) {
      const saved = nets.overlay;
      nets.overlay = undefined;
      const id = nets.powerNet(net);
      nets.overlay = saved;
      return bind(net, id);
    }
    const sources = [...n.sources].sort((a, b) => byPosition(at(g, a.node), at(g, b.node)));
    if (sources.length + n.feeds.length === 0) return bind(net, nets.fresh()); // fed by nothing: OFF
    if (sources.length === 1 && !n.feeds.length) return bind(net, source(sources[0]!, undefined));
    const join = bind(net, nets.fresh());
    for (const s of sources) source(s, join);
    // One-way bridges (graph.ts): the nets bridged in are more terms of the OR.
    for (const b of n.feeds) {
      const { from, via } = g.bridges[b]!;
      sink.push({ op: 'pass', node: via, inNet: value(from), outNet: join });
    }
    return join;
  };

  /** One source of a net, OR-ed into `join` when the net has several. */
  const source = (s: { node: number; pin: string }, join: number | undefined): number => {
    const node = g.nodes[s.node]!;
    const el = node.el;
    const pass = (inNet: number) => {
      if (join !== undefined) sink.push({ op: 'pass', node: node.index, inNet, outNet: join });
      return inNet;
    };
    if (isBlock(node)) {
      generateBlock(s.node);
      return pass(blockOut.get(s.node)?.get(s.pin) ?? nets.fresh());
    }
    if (el.kind === 'coil') return pass(node.inputs[0] ? value(node.inputs[0].net) : nets.fresh());
    if (el.kind !== 'contact') return nets.fresh();
    const inNet = value(node.inputs[0]!.net);
    const outNet = join ?? nets.fresh();
    const ownNet = join !== undefined ? nets.fresh() : undefined;
    const k = readings.get(s.node) ?? 0;
    readings.set(s.node, k + 1);
    const edge = el.contact === 'P' || el.contact === 'N' ? edgeOf(ctx, el, index, r, k) : undefined;
    sink.push(contactOp(node.index, el.contact, operands.get(s.node), inNet, outNet, ownNet, edge));
    latest.set(s.node, [inNet, ownNet ?? outNet]);
    return ownNet ?? outNet;
  };

  /** The local a block output pin writes: the net itself when the block is its only source. */
  const outLocal = (ni: number, t: { pin: string; net: number }): number => {
    const id = nets.fresh();
    let pins = blockOut.get(ni);
    if (!pins) blockOut.set(ni, (pins = new Map()));
    pins.set(t.pin, id);
    const n = g.nets[t.net]!;
    if (n.sources.length === 1 && !n.leftRail && !n.feeds.length) latestNet.set(t.net, id);
    return id;
  };

  /** A block, once: its inputs traced now (each input a reading of its own), then the call. */
  const generateBlock = (ni: number): void => {
    if (computed.has(ni)) return;
    computed.add(ni);
    const node = g.nodes[ni]!;
    const savedTrace = trace;
    const savedOverlay = nets.overlay;
    trace = new Map();
    try {
      // Blocks feeding its inputs (value lines too) run first.
      for (const t of node.inputs)
        if (wiredIn(t.net))
          for (const s of upstream(g, t.net).sources) if (isBlock(g.nodes[s.node]!)) generateBlock(s.node);
      if (node.el.kind === 'contact') {
        // The inverting contact: a NOT block. Unconnected, the generator cancels it (its output stays FALSE).
        const t = node.inputs[0]!;
        const out = outLocal(ni, node.outputs[0]!);
        if (!wiredIn(t.net)) return void cancelled(node.el, 'NOT');
        const inNet = value(t.net);
        sink.push({ op: 'contact', node: node.index, contact: 'NOT', inNet, outNet: out });
        latest.set(ni, [inNet, out]);
        return;
      }
      const el = node.el as BoxElement;
      const layout = node.layout;
      for (const t of node.inputs)
        if (wiredIn(t.net) && !nets.data.has(t.net) && !nets.dataPending.has(t.net)) value(t.net);
      for (const t of node.outputs) {
        const type = layout?.outputs.find((p) => p.name === t.pin)?.type;
        if (type === undefined || type === 'BOOL' || !isElementaryType(type)) trace.set(t.net, outLocal(ni, t));
      }
      nets.overlay = trace;
      const op = lowerBox(ctx, node, nets, index, r);
      // LD-W22: a function none of whose inputs is connected (wire or variable) is not called.
      const fn = layout?.signature.kind === 'function';
      const connected = node.inputs.some(
        (t) => t.pin !== 'EN' && (wiredIn(t.net) || Object.entries(el.inputs).some(([k, v]) => k.toUpperCase() === t.pin.toUpperCase() && v.trim() !== '')),
      );
      if (fn && !connected && node.inputs.some((t) => t.pin !== 'EN')) cancelled(el, el.blockType.trim());
      else if (op) sink.push(op);
      const pIn = layout?.inputs.find((p) => p.type === 'BOOL')?.name;
      const pOut = layout?.outputs.find((p) => p.type === 'BOOL')?.name;
      const tIn = node.inputs.find((t) => t.pin === pIn);
      latest.set(ni, [
        tIn ? (trace.get(tIn.net) ?? -1) : -1,
        pOut !== undefined ? (blockOut.get(ni)?.get(pOut) ?? -1) : -1,
      ]);
    } finally {
      trace = savedTrace;
      nets.overlay = savedOverlay;
    }
  };

  const cancelled = (el: GraphNode['el'], type: string) =>
    r.warning(
      'LD-W22',
      `${describeElement(el)}: no input of this ${type} function is connected; Beremiz and OpenPLC cancel such a function ("function cancelled ... No input connected"), so under the openplc profile it is not called: variables written beside its outputs keep their values and its wired outputs carry FALSE/0`,
      el,
    );

  const generateCoil = (ni: number): void => {
    const node = g.nodes[ni]!;
    const el = node.el;
    if (el.kind !== 'coil') return;
    const dst = coilOperand(ctx, el, index, r);
    const edge = el.coil === 'P' || el.coil === 'N' ? edgeOf(ctx, el, index, r) : undefined;
    // LD-R03: a coil fed by nothing is not executed (no assignment is generated).
    if (!node.inputs[0] || !nets.isFed(node.inputs[0].net)) return;
    trace = new Map();
    const inNet = value(node.inputs[0].net);
    latest.set(ni, [inNet, inNet]);
    if (dst) sink.push({ op: 'coil', node: node.index, coil: el.coil, dst, inNet, outNet: inNet, ...(edge !== undefined ? { edge } : {}) });
  };

  // Coils and block outputs written to variables (outVariables), by position.
  const turns: { row: number; col: number; run: () => void }[] = [];
  g.nodes.forEach((node, ni) => {
    const el = node.el;
    if (el.kind === 'coil') turns.push({ row: el.row, col: el.col, run: () => generateCoil(ni) });
    if (el.kind === 'box' && node.layout)
      for (const pin of node.layout.outputs) {
        const operand = Object.entries(el.outputs).find(([k]) => k.toUpperCase() === pin.name.toUpperCase())?.[1];
        if (operand?.trim())
          turns.push({ row: el.row + pin.rowOffset, col: el.col + node.layout.cols, run: () => generateBlock(ni) });
      }
  });
  turns.sort(byPosition);
  for (const t of turns) t.run();

  return {
    finish(): NetworkIR | undefined {
      // The blocks no coil needed, after every coil of the POU body.
      sink = late;
      g.nodes
        .map((_, ni) => ni)
        .filter((ni) => isBlock(g.nodes[ni]!) && !computed.has(ni))
        .sort((a, b) => byPosition(at(g, a), at(g, b)))
        .forEach(generateBlock);
      if (r.errors > errorsBefore) return undefined;
      const netOf = (net: number) => (net >= 0 ? (latestNet.get(net) ?? -1) : -1);
      const elementNets = network.elements.map((el, i): Pair => {
        if (el.kind === 'link' || el.kind === 'connector' || el.kind === 'continuation') {
          const net = netOf(g.linkNet[i]!);
          return [net, net];
        }
        const ni = g.nodes.findIndex((n) => n.index === i);
        return ni >= 0 ? (latest.get(ni) ?? [-1, -1]) : [-1, -1];
      });
      return networkIR(ctx, network, index, nets, {
        ops,
        elementNets,
        vlinkNets: network.vlinks.map((_, i) => netOf(g.vlinkNet[i]!)),
        late,
      });
    },
  };
}
