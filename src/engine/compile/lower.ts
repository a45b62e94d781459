// One network: graph, structural rules, evaluation order, then each element's operands and types
// (LD-R07, LD-R08, LD-R10, LD-R11, LD-R12, LD-R13) and the ordered operations for code generation.
// Contacts', coils' and jumps' operands: operands.ts; boxes: box.ts; the nets: netMap.ts; the
// openplc profile's order: generated.ts.
import type { Network } from '../../model/project';
import type { PouContext } from './context';
import { buildGraph, upstream, type NetworkGraph } from './graph';
import type { NetworkIR, Op } from './ir';
import { NetMap, networkIR, type PendingNetwork } from './netMap';
import { coilOperand, contactOp, contactOperand, edgeOf, jumpTarget } from './operands';
import { evaluationOrder, loopElement, planOrder, type Feedback } from './order';
import { hiddenVariable, instanceOutput, moveOp, outputType, rebindInputs, reportFeedback, storedDataLine } from './feedback';
import type { Access } from './symbols';
import { describeElement, type Reporter } from './report';
import { checkStructure } from './structure';
import { lowerBox } from './box';
import { startGenerated } from './generated';

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
export function startNetwork(ctx: PouContext, network: Network, index: number, r: Reporter, grouped = false): PendingNetwork {
  const g = buildGraph(network, ctx.symbols.library);
  const structureOk = checkStructure(network, g, r);
  const order = structureOk ? evaluationOrder(g) : undefined;
  if (structureOk && !order)
    r.error(
      'LD-R01',
      'an element feeds its own input through a wire going back to the left; power must flow left to right',
      loopElement(g),
    );
  if (order && ctx.profile === 'openplc') return startGenerated(ctx, network, index, r, g, grouped);
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
  // Explicit loops through blocks, cut where order.ts says (the same plan evaluationOrder gave).
  const stored = storedOutputs(ctx, g, structureOk ? (planOrder(g)?.feedback ?? []) : [], r);
  for (const ni of order) {
    const node = g.nodes[ni]!;
    const el = node.el;
    for (const t of node.inputs) bridgeInto(t.net);
    // Inputs on a loop's feedback wire read the stored outputs (feedback.ts), OR-ed with the line's other sources.
    const outerOverlay = nets.overlay;
    const fedBack = readStored(ctx, ni, nets, stored, ops, r);
    if (fedBack) nets.overlay = fedBack.overlay;
    const mark = ops.length;
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
    nets.overlay = outerOverlay;
    // A block reading its own output: its call reads the stored value and writes the line.
    if (fedBack?.self.size) for (let k = mark; k < ops.length; k++) if (ops[k]!.node === node.index) ops[k] = rebindInputs(ops[k]!, fedBack.self);
    // A block whose stored output a loop reads without the instance keeping it: its call writes it.
    for (const [pin, dst] of stored.held.get(ni) ?? []) {
      const t = node.outputs.find((o) => o.pin === pin);
      if (!t) continue;
      const own = el.kind === 'contact' ? (nets.hasPower(-1 - ni) ? nets.powerNet(-1 - ni) : undefined) : boxOwn.get(`${ni}:${pin}`);
      const write = moveOp(ctx, node.index, own ?? nets.powerNet(t.net), { pin: 'OUT', type: 'BOOL', dst });
      if (write) ops.push(write);
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

/** The stored outputs a network's loops read (order.ts's feedback wires). */
interface Stored {
  readonly feedback: readonly Feedback[];
  /** Producer node -> pin -> the variable its call writes (blocks that keep no outputs). */
  readonly held: Map<number, Map<string, Access>>;
  /** `producer:pin` -> what a BOOL reading reads. */
  readonly bool: Map<string, Access>;
}

/** Reports each feedback wire (LD-W30) and makes the variables the loops read. */
function storedOutputs(ctx: PouContext, g: NetworkGraph, feedback: readonly Feedback[], r: Reporter): Stored {
  const held = new Map<number, Map<string, Access>>();
  const bool = new Map<string, Access>();
  const reported = new Set<string>();
  for (const f of feedback) {
    const producer = g.nodes[f.producer]!;
    const key = `${f.producer}:${f.pin}`;
    if (!reported.has(`${key}:${f.reader}`)) {
      reported.add(`${key}:${f.reader}`);
      reportFeedback(r, ctx.profile, producer, f.pin, g.nodes[f.reader]!);
    }
    if (outputType(ctx, g, producer, f.pin) !== 'BOOL' || bool.has(key)) continue;
    let access = instanceOutput(ctx, producer, f.pin);
    if (!access) {
      access = hiddenVariable(ctx, `${describeElement(producer.el)}.${f.pin}`, 'BOOL');
      let pins = held.get(f.producer);
      if (!pins) held.set(f.producer, (pins = new Map()));
      pins.set(f.pin, access);
    }
    bool.set(key, access);
  }
  return { feedback, held, bool };
}

/**
 * Before element `ni` runs: the locals its fed-back BOOL inputs read (the stored outputs OR-ed with
 * the line's other sources, which have run), as an overlay; a fed-back data line reads the FB
 * instance's output or a slot the function writes. Undefined when no input of `ni` is fed back.
 */
function readStored(
  ctx: PouContext,
  ni: number,
  nets: NetMap,
  stored: Stored,
  ops: Op[],
  r: Reporter,
): { overlay: Map<number, number>; self: Map<number, number> } | undefined {
  const cuts = stored.feedback.filter((f) => f.reader === ni);
  if (!cuts.length) return undefined;
  const g = nets.g;
  const overlay = new Map(nets.overlay ?? []);
  const self = new Map<number, number>();
  const node = g.nodes[ni]!;
  for (const net of new Set(cuts.map((c) => c.net))) {
    const here = cuts.filter((c) => c.net === net);
    const first = here[0]!;
    const producer = g.nodes[first.producer]!;
    const type = outputType(ctx, g, producer, first.pin);
    if (type !== 'BOOL') {
      storedDataLine(ctx, nets, producer, first.pin, net, node, r);
      continue;
    }
    // A generic output (AND's OUT) driving power flow is BOOL: its line is read as power from here on.
    for (const c of here) {
      const t = g.nodes[c.producer]!.outputs.find((o) => o.pin === c.pin);
      if (t) nets.dataPending.delete(t.net);
    }
    const local = nets.fresh();
    const cutFrom = new Set(here.map((c) => c.producer));
    const up = upstream(g, net);
    if (up.leftRail || up.sources.some((s) => !cutFrom.has(s.node)))
      ops.push({ op: 'pass', node: node.index, inNet: nets.powerNet(net), outNet: local });
    for (const c of here) {
      const read = stored.bool.get(`${c.producer}:${c.pin}`);
      const op = read && moveOp(ctx, node.index, read, { pin: 'OUT', type: 'BOOL', net: local });
      if (op) ops.push(op);
    }
    // The element's own output on the line (a self-loop): it still writes the line itself.
    if (g.nets[net]!.sources.some((src) => src.node === ni)) self.set(nets.powerNet(net), local);
    else overlay.set(net, local);
  }
  return { overlay, self };
}
