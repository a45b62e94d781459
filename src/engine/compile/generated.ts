// Profile `openplc` (LD-SEMANTICS.md section 6): an LD network lowered in the order in which
// Beremiz and OpenPLC run it. Their generator (PLCGenerator.py, ComputeProgram) does not run the
// graph: it writes one ST statement per coil, in drawing order over the whole POU body, each
// re-tracing the coil's path from the left rail (ComputeExpression), so:
// - every coil and every variable written beside a block output (an outVariable) takes its turn by
//   position: network, then row, then column; the outVariable's statement `X := T1.Q` (or
//   `X := ADD3_OUT` for a function) is written at its own turn, not when the block runs. An
//   imported network may carry Beremiz's own order (Network.turns: SortInstances over the whole
//   body, where networks drawn side by side interleave): its statements take those turns, and
//   consecutive networks with turns run theirs together as early segments of the group's first
//   network (pou.ts);
// - a generic function's output that turns out BOOL (AND's ANY_BIT OUT) wired into another
//   block's input is power flow read from what the call wrote (`OR(_TMP_AND5_OUT, C)`);
// - a statement first calls what its path needs, in the generator's order (GeneratePaths: from the
//   coil back to the rail, a join's branches top first, an edge contact's R_TRIG/F_TRIG before its
//   own upstream part, a block's inputs in pin order), then evaluates its expression: the plain
//   contacts of the path are read after every call of the statement (a contact reading an output
//   of a block called in the same statement sees the new value); an edge contact's trigger reads
//   its variable at the trigger's place (a snapshot when a block called later in the statement
//   may change it);
// - at a coil's turn, every contact of its path is read again; a |P| |N| contact gets a new edge
//   memory per reading, and per branch when its upstream part splits and joins again (the
//   generator writes that part once per branch, each with an R_TRIG/F_TRIG of its own);
// - a coil in series passes its left side on (the generator traces through it);
// - a block (function, FB, user block; also the inverting contact, which the export writes as a
//   NOT block) runs once (ComputedBlocks), at the first statement that needs it, its inputs traced
//   at that moment; later readings read its stored outputs;
// - blocks no coil or output variable needs run after every coil of the POU body (`late`,
//   finished by pou.ts once all networks are started);
// - a function with no input connected is not called (LD-W22); jumps and RETURNs are never
//   generated: they do nothing (LD-W20, LD-W21).
// executionOrderId (ComputeProgram's orderedInstances; BoxElement.executionOrder/outputOrders):
// - only blocks, outVariables and inOutVariables with an id > 0 are ordered (coils, contacts and
//   connectors never are); they are generated before every other instance of the POU body (the
//   whole body, not network by network), sorted by id; then coils and outVariables by position,
//   then the blocks no one needed, as above;
// - an ordered block's turn is GenerateBlock(order=False): it runs unless a statement already
//   called it; an ordered outVariable's turn is its statement `X := <path>`, which calls the
//   block behind it first if it has not run (ComputeExpression with order=False);
// - a block with an id traces its inputs with `order` set (GenerateBlock passes executionOrderId >
//   0 to ComputeExpression; GeneratePaths passes it on through contacts and continuations): a
//   block upstream that has not run yet is not called, the statement reads its stored output
//   (`T1.Q`, a function's `_TMP_AND5_OUT`: the value of its last call, or the initial value), and
//   that block runs later at its own turn. The engine reads an FB instance's output, or a variable
//   the function's call writes (a slot for a data line; a function whose output type is generic
//   cannot reserve one before it runs: called first instead, LD-W23). The statements of ordered
//   instances are this network's `early` segments, run by the body's first network (pou.ts,
//   codegen.ts bodyUnits).
// What still differs (a join's branch order, connectors computed once) is listed in
// LD-SEMANTICS.md section 6.
import { executionOrderOf as orderOf, type BoxElement } from '../../model/elements';
import type { Network } from '../../model/project';
import { isElementaryType, type ElementaryType } from '../../model/iecTypes';
import { resolveFunction } from '../library/functions';
import { defaultValue } from '../values/types';
import { lowerBox } from './box';
import type { PouContext } from './context';
import { upstream, type GraphNode, type NetworkGraph } from './graph';
import type { NetworkIR, Op, OutIR, Source } from './ir';
import { coilOperand, contactOp, contactOperand, edgeOf, jumpTarget } from './operands';
import { NetMap, networkIR, type PendingNetwork } from './netMap';
import { describeElement, type Reporter } from './report';
import { holdData, outputType, rebindInputs, reportFeedback, storedDataLine } from './feedback';
import { storeOf, type Access } from './symbols';

type Pair = readonly [number, number];

const at = (g: NetworkGraph, ni: number) => g.nodes[ni]!.el;
const byPosition = (a: { row: number; col: number }, b: { row: number; col: number }) => a.row - b.row || a.col - b.col;

/** Blocks for the generator: boxes and inverting contacts (exported as NOT blocks). */
const isBlock = (node: GraphNode): boolean =>
  node.el.kind === 'box' || (node.el.kind === 'contact' && node.el.contact === 'NOT');

/** Operations that call a block (and may write variables a contact reads). */
const isCall = (op: Op): boolean => op.op === 'fb' || op.op === 'function' || op.op === 'call';

/**
 * One generated statement (a coil's, an output variable's, a block call's): what it calls first,
 * in the generator's order, then its expression, evaluated after every call.
 */
interface Statement {
  readonly calls: Op[];
  readonly expr: Op[];
  /** Edge contacts: where their R_TRIG/F_TRIG stands among the calls, and their operation in `expr`. */
  readonly triggers: { readonly at: number; readonly expr: number }[];
}

const statement = (): Statement => ({ calls: [], expr: [], triggers: [] });

export function startGenerated(
  ctx: PouContext,
  network: Network,
  index: number,
  r: Reporter,
  g: NetworkGraph,
  /** The network's statements interleave with those of neighbouring networks (Network.turns, pou.ts). */
  grouped = false,
): PendingNetwork {
  const nets = new NetMap(g);
  const errorsBefore = r.errors;
  const ops: Op[] = [];
  const late: Op[] = [];
  let sink = ops;
  let stmt = statement();
  /** The locals of the reading being generated: graph net -> local. */
  let trace = new Map<number, number>();
  const readings = new Map<number, number>();
  const computed = new Set<number>();
  const blockOut = new Map<number, Map<string, number>>();
  /** Per block: the statements writing the variables beside its outputs (by upper-case pin), run at their turns. */
  const blockWrites = new Map<number, Map<string, Op>>();
  /** Element (node) -> [left, right] locals of its latest evaluation; graph net -> latest local. */
  const latest = new Map<number, Pair>();
  const latestNet = new Map<number, number>();
  const wiredIn = (net: number) => nets.isWired(net) && nets.isFed(net);
  /**
   * Tracing the inputs of a block with an executionOrderId (GenerateBlock's `order`): the blocks
   * upstream not called yet are not called, their stored outputs are read.
   */
  let ordered = false;
  /** Blocks whose BOOL outputs were read stored before their call: pin -> the variable their call writes. */
  const heldOut = new Map<number, Map<string, Access>>();

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

  /** A variable of the generated code the program does not declare (the generator's `ADD3_OUT`). */
  const hiddenVar = (name: string, type: ElementaryType): Access => {
    const store = storeOf(type);
    const slot = ctx.symbols.counts[store]++;
    if (store !== 'b') ctx.dataSlots.push({ store, slot, type });
    const v = { kind: 'var', name, type, store, slot, initial: defaultValue(type), retain: false, constant: false, global: false, implicit: false, hidden: true } as const;
    return { kind: 'var', v, type };
  };
  /** `dst := src` as a MOVE (node -1 when it belongs to no element: an edge contact's snapshot); `src` a variable or a power-flow local. */
  const moveFns = new Map<ElementaryType, number>();
  const move = (node: number, src: Access | number, out: OutIR, en?: Access): Op | undefined => {
    const type = typeof src === 'number' ? 'BOOL' : src.type;
    let fn = moveFns.get(type);
    if (fn === undefined) {
      const res = resolveFunction('MOVE', [type], ctx.profile);
      if (!res.ok) return undefined;
      fn = ctx.functions.length;
      ctx.functions.push(res.fn);
      moveFns.set(type, fn);
    }
    const from: Source = typeof src === 'number' ? { from: 'power', net: src } : { from: 'access', access: src };
    const args = [{ pin: 'IN', type, src: from }];
    return { op: 'function', node, name: 'MOVE', fn, ...(en ? { en: { from: 'access', access: en } } : {}), args, out, eno: { pin: 'ENO', type: 'BOOL' } };
  };

  /** A statement's operations: its calls, then its expression (snapshots added where the calls move a trigger's variable). */
  const close = (s: Statement): Op[] => {
    const moved = s.triggers.filter((t) => s.calls.slice(t.at).some(isCall));
    for (const t of moved.sort((a, b) => b.at - a.at)) {
      const op = s.expr[t.expr]!;
      if (op.op !== 'contact' || !op.src) continue;
      // R_TRIGn(CLK := V) stands before calls that may write V: V is read there (and shown by its name).
      const contact = network.elements[op.node];
      const held = hiddenVar(contact?.kind === 'contact' ? contact.variable.trim() : 'CLK', 'BOOL');
      const snap = move(-1, op.src, { pin: 'OUT', type: 'BOOL', dst: held });
      if (!snap) continue;
      s.calls.splice(t.at, 0, snap);
      s.expr[t.expr] = { ...op, src: held };
    }
    return [...s.calls, ...s.expr];
  };
  /** Runs `f` as a statement of its own and writes its operations to the sink. */
  const asStatement = (f: () => void): void => {
    stmt = statement();
    f();
    sink.push(...close(stmt));
  };

  /** A |P| |N| contact drives the net through contacts and coils (not through a block): traced once per branch. */
  const edgeMemo = new Map<number, boolean>();
  const edgeUpstream = (net: number): boolean => {
    const known = edgeMemo.get(net);
    if (known !== undefined) return known;
    edgeMemo.set(net, false);
    const n = g.nets[net]!;
    let found = false;
    for (const s of n.sources) {
      const node = g.nodes[s.node]!;
      const el = node.el;
      if (isBlock(node) || (el.kind !== 'contact' && el.kind !== 'coil')) continue;
      if (el.kind === 'contact' && (el.contact === 'P' || el.contact === 'N')) found = true;
      else if (node.inputs[0] && edgeUpstream(node.inputs[0].net)) found = true;
    }
    for (const b of n.feeds) if (edgeUpstream(g.bridges[b]!.from)) found = true;
    edgeMemo.set(net, found);
    return found;
  };

  const bind = (net: number, id: number): number => {
    trace.set(net, id);
    latestNet.set(net, id);
    return id;
  };

  /** The local holding a net's value in the current reading, generating what it needs. */
  const value = (net: number): number => {
    const hit = trace.get(net);
    // Plain contacts read twice in one statement read the same value: traced once. An edge
    // contact's part is traced again on every branch (an R_TRIG/F_TRIG per branch).
    if (hit !== undefined && !edgeUpstream(net)) return hit;
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
      const inNet = value(from);
      stmt.expr.push({ op: 'pass', node: via, inNet, outNet: join });
    }
    return join;
  };

  /** One source of a net, OR-ed into `join` when the net has several. */
  const source = (s: { node: number; pin: string }, join: number | undefined): number => {
    const node = g.nodes[s.node]!;
    const el = node.el;
    const pass = (inNet: number) => {
      if (join !== undefined) stmt.expr.push({ op: 'pass', node: node.index, inNet, outNet: join });
      return inNet;
    };
    if (isBlock(node)) {
      if (running.has(s.node)) return pass(loopBool(s));
      if (ordered && !computed.has(s.node)) return pass(storedBool(s.node, s.pin));
      generateBlock(s.node);
      return pass(blockOut.get(s.node)?.get(s.pin) ?? nets.fresh());
    }
    if (el.kind === 'coil') return pass(node.inputs[0] ? value(node.inputs[0].net) : nets.fresh());
    if (el.kind !== 'contact') return nets.fresh();
    // ExtractModifier before GeneratePaths: an edge contact's trigger is written before its upstream part.
    const trigger = stmt.calls.length;
    const inNet = value(node.inputs[0]!.net);
    const outNet = join ?? nets.fresh();
    const ownNet = join !== undefined ? nets.fresh() : undefined;
    const k = readings.get(s.node) ?? 0;
    readings.set(s.node, k + 1);
    const edge = el.contact === 'P' || el.contact === 'N' ? edgeOf(ctx, el, index, r, k) : undefined;
    stmt.expr.push(contactOp(node.index, el.contact, operands.get(s.node), inNet, outNet, ownNet, edge));
    if (edge !== undefined) stmt.triggers.push({ at: trigger, expr: stmt.expr.length - 1 });
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

  /**
   * The variables written beside a block's outputs leave its operation: each is a statement of its
   * own at its turn, reading the FB instance's output there (`X := T1.Q`) or, for a function's
   * results and ENO, a variable the call writes (`X := _TMP_ADD3_OUT`). When the block's EN is
   * wired, the generator guards it (GetUsedEno): `IF _TMP_ADD3_ENO THEN X := _TMP_ADD3_OUT; END_IF;`.
   */
  const detachWrites = (ni: number, op: Op): Op => {
    const node = g.nodes[ni]!;
    const el = node.el;
    const writes = new Map<string, Op>();
    blockWrites.set(ni, writes);
    // EN connected: by a wire or by a variable beside it (an inVariable in PLCopen).
    const enOperand = el.kind === 'box' && Object.entries(el.inputs).some(([k, v]) => k.toUpperCase() === 'EN' && v.trim() !== '');
    // An EN the file left open and Rungsmith draws from the rail (BoxElement.enOpen) is not connected.
    const railEn = el.kind === 'box' && el.enOpen === true && (op.op === 'function' || op.op === 'fb' || op.op === 'call') && op.en === undefined;
    const guarded = !railEn && (enOperand || node.inputs.some((t) => t.pin === 'EN' && wiredIn(t.net)));
    const held = (o: OutIR) => hiddenVar(`${describeElement(el)}.${o.pin}`, o.type);
    // ENO first: the variable holding it guards the other writes.
    const eno0 = 'eno' in op ? op.eno : undefined;
    const enoHeld = eno0 && (eno0.dst || guarded) ? held(eno0) : undefined;
    const later = (o: OutIR, instanceOut: Access | undefined): OutIR => {
      const from = o.pin === 'ENO' ? enoHeld : instanceOut;
      if (!o.dst) return o.pin === 'ENO' && from ? { ...o, dst: from } : o;
      const { dst, ...kept } = o;
      const src = from ?? held(o);
      const write = move(node.index, src, { pin: o.pin, type: o.type, dst }, guarded ? enoHeld : undefined);
      if (!write) return o;
      writes.set(o.pin.toUpperCase(), write);
      return from === instanceOut && instanceOut ? kept : { ...kept, dst: src };
    };
    switch (op.op) {
      case 'fb': {
        const fb = ctx.symbols.fbs[op.fb]!;
        const outs = op.outs.map((o) => later(o, { kind: 'pin', fb, pin: o.pin, type: o.type, dir: 'out' }));
        return { ...op, outs, ...(op.eno ? { eno: later(op.eno, undefined) } : {}) };
      }
      case 'function':
        return { ...op, out: later(op.out, undefined), eno: later(op.eno, undefined) };
      case 'call': {
        const outs = op.outs.map((o) => ({ ...o, out: later(o.out, op.kind === 'fb' ? o.src : undefined) }));
        return { ...op, outs, ...(op.eno ? { eno: later(op.eno, undefined) } : {}) };
      }
      default:
        return op;
    }
  };

  /** A block, once: its inputs traced now, each in pin order (its calls, then its expression), then the call. */
  const generateBlock = (ni: number): void => {
    if (computed.has(ni)) return;
    computed.add(ni);
    running.add(ni);
    const node = g.nodes[ni]!;
    const outer = stmt;
    const savedTrace = trace;
    const savedOverlay = nets.overlay;
    const savedOrdered = ordered;
    stmt = statement();
    trace = new Map();
    ordered = orderOf(node.el) > 0;
    let call: Op | undefined;
    try {
      if (node.el.kind === 'contact') {
        // The inverting contact: a NOT block. Unconnected, the generator cancels it (its output stays FALSE).
        const t = node.inputs[0]!;
        const out = outLocal(ni, node.outputs[0]!);
        if (!wiredIn(t.net)) return void cancelled(node.el, 'NOT');
        const inNet = value(t.net);
        call = { op: 'contact', node: node.index, contact: 'NOT', inNet, outNet: out };
        latest.set(ni, [inNet, out]);
        return;
      }
      const el = node.el as BoxElement;
      const layout = node.layout;
      for (const t of node.inputs) {
        if (!wiredIn(t.net)) continue;
        if (loopLine(t.net)) continue;
        // A value line: the block feeding it runs first. A power line: traced now.
        if (nets.data.has(t.net) || nets.dataPending.has(t.net)) {
          for (const s of upstream(g, t.net).sources)
            if (isBlock(g.nodes[s.node]!) && !(ordered && !computed.has(s.node) && storedData(s, t.net, node.el))) generateBlock(s.node);
          // A generic output (AND's ANY_BIT OUT) that turned out BOOL once its block ran is power
          // flow: this block reads the variable that call wrote (`OR(_TMP_AND5_OUT, C)`), traced
          // like any other BOOL line (the block already ran: its stored result, not a new call).
          if (!nets.data.has(t.net) && !nets.dataPending.has(t.net)) value(t.net);
        } else value(t.net);
      }
      const selfRead = storedSelf(node);
      for (const t of node.outputs) {
        const type = layout?.outputs.find((p) => p.name === t.pin)?.type;
        if (type === undefined || type === 'BOOL' || !isElementaryType(type)) trace.set(t.net, outLocal(ni, t));
      }
      nets.overlay = trace;
      const op = selfRead(lowerBox(ctx, node, nets, index, r));
      // LD-W22: a function none of whose inputs is connected (wire or variable) is not called.
      const fn = layout?.signature.kind === 'function';
      const connected = node.inputs.some(
        (t) => t.pin !== 'EN' && (wiredIn(t.net) || Object.entries(el.inputs).some(([k, v]) => k.toUpperCase() === t.pin.toUpperCase() && v.trim() !== '')),
      );
      if (fn && !connected && node.inputs.some((t) => t.pin !== 'EN')) cancelled(el, el.blockType.trim());
      else if (op) call = detachWrites(ni, op);
      const pIn = layout?.inputs.find((p) => p.type === 'BOOL')?.name;
      const pOut = layout?.outputs.find((p) => p.type === 'BOOL')?.name;
      const tIn = node.inputs.find((t) => t.pin === pIn);
      latest.set(ni, [
        tIn ? (trace.get(tIn.net) ?? -1) : -1,
        pOut !== undefined ? (blockOut.get(ni)?.get(pOut) ?? -1) : -1,
      ]);
    } finally {
      running.delete(ni);
      const own = stmt;
      trace = savedTrace;
      nets.overlay = savedOverlay;
      ordered = savedOrdered;
      stmt = outer;
      // The whole call (what its inputs call, their expressions, the call) is one call of the outer statement.
      outer.calls.push(...close(own), ...(call ? [call, ...holdWrites(ni)] : []));
    }
  };

  /**
   * A block output read before the block ran this scan, by a block with an executionOrderId: the
   * value its last call left (`T1.Q` of an FB instance; a function's `_TMP_AND5_OUT`, here a
   * variable its call writes). Returns the local holding it.
   */
  const storedBool = (ni: number, pin: string): number => {
    const node = g.nodes[ni]!;
    const el = node.el;
    let src: Access | undefined;
    if (el.kind === 'box' && node.layout?.signature.kind === 'fb' && el.instance?.trim() && pin.toUpperCase() !== 'ENO') {
      const res = ctx.symbols.resolve(`${el.instance.trim()}.${pin}`, { literals: false, implicitLocations: false });
      if (res.ok && res.access.type === 'BOOL') src = res.access;
    }
    if (!src) {
      let pins = heldOut.get(ni);
      if (!pins) heldOut.set(ni, (pins = new Map()));
      src = pins.get(pin);
      if (!src) pins.set(pin, (src = hiddenVar(`${describeElement(el)}.${pin}`, 'BOOL')));
    }
    const local = nets.fresh();
    const read = move(node.index, src, { pin: 'OUT', type: 'BOOL', net: local });
    if (read) stmt.expr.push(read);
    return local;
  };

  /** The writes of the stored outputs read before this block's call (storedBool), after it. */
  const holdWrites = (ni: number): Op[] => {
    const out: Op[] = [];
    for (const [pin, dst] of heldOut.get(ni) ?? []) {
      const local = blockOut.get(ni)?.get(pin);
      const write = local === undefined ? undefined : move(g.nodes[ni]!.index, local, { pin: 'OUT', type: 'BOOL', dst });
      if (write) out.push(write);
    }
    return out;
  };

  /**
   * A data line into a block with an executionOrderId from a block not called yet: the line reads
   * the block's stored output (an FB instance's output; a slot the function writes when it runs).
   * False when that cannot be known before the function runs (an output of a generic type): the
   * function is then called first (LD-W23).
   */
  const storedData = (s: { node: number; pin: string }, net: number, reader: GraphNode['el']): boolean => {
    if (nets.data.has(net)) return true;
    const node = g.nodes[s.node]!;
    const el = node.el;
    if (el.kind !== 'box') return false;
    if (node.layout?.signature.kind === 'fb' && el.instance?.trim()) {
      const res = ctx.symbols.resolve(`${el.instance.trim()}.${s.pin}`, { literals: false, implicitLocations: false });
      if (res.ok) {
        nets.data.set(net, { from: 'access', access: res.access });
        return true;
      }
      return false;
    }
    const type = node.layout?.outputs.find((p) => p.name === s.pin)?.type;
    if (type !== undefined && isElementaryType(type) && type !== 'BOOL') {
      holdData(ctx, nets, net, type);
      return true;
    }
    r.warning(
      'LD-W23',
      `${describeElement(reader)} has an execution order and reads output ${s.pin} of ${describeElement(el)}, which has not run yet in this scan; Beremiz and OpenPLC read the value its last call left, but the type of that output is only known once it runs, so the simulator calls ${describeElement(el)} first here`,
      reader,
    );
    return false;
  };

  // Explicit feedback loops (order.ts, feedback.ts): a block whose inputs are being traced
  // (`running`) is reached again through its own output. Beremiz marks a block computed before it
  // traces its inputs (GenerateBlock), so that reading is the block's stored output, `T1.Q` or
  // `_TMP_AND5_OUT` (its last call's value), and the call is written after the reading.
  const running = new Set<number>();
  /** The element whose inputs are being traced when a loop closes: the innermost running block. */
  const reader = (): GraphNode => g.nodes[[...running].pop()!]!;
  const loopsReported = new Set<string>();
  const reportLoop = (s: { node: number; pin: string }) => {
    const key = `${s.node}:${s.pin}`;
    if (loopsReported.has(key)) return;
    loopsReported.add(key);
    reportFeedback(r, ctx.profile, g.nodes[s.node]!, s.pin, reader());
  };
  const loopBool = (s: { node: number; pin: string }): number => {
    reportLoop(s);
    // A generic output (AND's OUT) on a power line is BOOL: its line is read as power.
    const t = g.nodes[s.node]!.outputs.find((o) => o.pin === s.pin);
    if (t) nets.dataPending.delete(t.net);
    return storedBool(s.node, s.pin);
  };
  /** An input line fed back from a running block: its stored output read (power: traced; data: the stored value). */
  const loopLine = (net: number): boolean => {
    const loop = upstream(g, net).sources.filter((s) => running.has(s.node));
    if (!loop.length) return false;
    const s = loop[0]!;
    if (outputType(ctx, g, g.nodes[s.node]!, s.pin) === 'BOOL') value(net);
    else {
      reportLoop(s);
      storedDataLine(ctx, nets, g.nodes[s.node]!, s.pin, net, reader(), r);
    }
    return true;
  };

  /** A block reading its own output (a self-loop): its call reads the stored value traced for that line, not its new output. */
  const storedSelf = (node: GraphNode) => {
    const stored = new Map<number, number>();
    for (const t of node.inputs) {
      const local = trace.get(t.net);
      if (local !== undefined && node.outputs.some((o) => o.net === t.net)) stored.set(t.net, local);
    }
    return (op: Op | undefined): Op | undefined => {
      const map = new Map<number, number>();
      for (const [net, local] of stored) {
        const now = trace.get(net);
        if (now !== undefined && now !== local) map.set(now, local);
      }
      return op && rebindInputs(op, map);
    };
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
    let inNet = -1;
    asStatement(() => (inNet = value(node.inputs[0]!.net)));
    latest.set(ni, [inNet, inNet]);
    if (dst) sink.push({ op: 'coil', node: node.index, coil: el.coil, dst, inNet, outNet: inNet, ...(edge !== undefined ? { edge } : {}) });
  };

  /** An output variable's turn: `X := <the block's output>`, the block called first if no statement needed it yet. */
  const generateOutVariable = (ni: number, pin: string): void => {
    asStatement(() => generateBlock(ni));
    const write = blockWrites.get(ni)?.get(pin.toUpperCase());
    if (write) sink.push(write);
  };

  // Coils and block outputs written to variables (outVariables), by position; before them, the
  // blocks and outVariables with an executionOrderId, in id order (ComputeProgram's orderedInstances).
  // A network imported with turns (Network.turns) takes its statements in that order instead.
  type Turn = { row: number; col: number; key?: number; run: () => void };
  const turns: Turn[] = [];
  const first: (Turn & { id: number })[] = [];
  const fileTurns = network.turns;
  g.nodes.forEach((node, ni) => {
    const el = node.el;
    if (el.kind === 'coil') turns.push({ row: el.row, col: el.col, key: fileTurns?.[el.id], run: () => generateCoil(ni) });
    if (el.kind !== 'box') return;
    const id = orderOf(el);
    if (id > 0 && node.layout) first.push({ id, row: el.row, col: el.col, run: () => asStatement(() => generateBlock(ni)) });
    if (node.layout)
      for (const pin of node.layout.outputs) {
        const operand = Object.entries(el.outputs).find(([k]) => k.toUpperCase() === pin.name.toUpperCase())?.[1];
        if (!operand?.trim()) continue;
        const key = fileTurns?.[`${el.id}.${pin.name.toUpperCase()}`];
        const turn = { row: el.row + pin.rowOffset, col: el.col + node.layout.cols, key, run: () => generateOutVariable(ni, pin.name) };
        const order = orderOf(el, pin.name);
        if (order > 0) first.push({ ...turn, id: order });
        else turns.push(turn);
      }
  });
  const early: Op[][] = [];
  const earlyOrder: number[] = [];
  for (const t of first.sort((a, b) => a.id - b.id || byPosition(a, b))) {
    sink = [];
    t.run();
    if (!sink.length) continue;
    early.push(sink);
    earlyOrder.push(t.id);
  }
  turns.sort(byPosition);
  // Imported turns: an element without one keeps its place after the one before it (row, column).
  const keys: number[] = [];
  if (fileTurns) {
    let prev = -1;
    for (const t of turns) keys.push(t.key !== undefined ? (prev = t.key) : prev + 0.5);
    const at = new Map(turns.map((t, k) => [t, keys[k]!] as const));
    turns.sort((a, b) => at.get(a)! - at.get(b)!);
    keys.sort((a, b) => a - b);
  }
  // A network whose statements interleave with its neighbours' (`grouped`): each statement is a
  // segment of its own, run in turn order by the group's first network (pou.ts).
  const turnSegments: Op[][] = [];
  const turnKeys: number[] = [];
  turns.forEach((t, k) => {
    sink = grouped ? [] : ops;
    t.run();
    if (!grouped || !sink.length) return;
    turnSegments.push(sink);
    turnKeys.push(keys[k]!);
  });
  sink = ops;

  return {
    finish(): NetworkIR | undefined {
      // The blocks no coil needed, after every coil of the POU body.
      sink = late;
      g.nodes
        .map((_, ni) => ni)
        .filter((ni) => isBlock(g.nodes[ni]!) && !computed.has(ni))
        .sort((a, b) => byPosition(at(g, a), at(g, b)))
        .forEach((ni) => asStatement(() => generateBlock(ni)));
      if (r.errors > errorsBefore) return undefined;
      const netOf = (net: number) => (net >= 0 ? (latestNet.get(net) ?? -1) : -1);
      const elementNets = network.elements.map((el, i): Pair => {
        if (el.kind === 'link' || el.kind === 'connector' || el.kind === 'continuation') {
          // A line from one contact to an OR shows that contact's own (latest) result; a line from a
          // block output shows that output (not the block's first BOOL output, its ENO).
          const own = g.linkSource[i]!;
          const mine = own < 0 ? -1 : isBlock(g.nodes[own]!) ? (blockOut.get(own)?.get(g.linkSourcePin[i]!) ?? -1) : (latest.get(own)?.[1] ?? -1);
          const net = mine >= 0 ? mine : netOf(g.linkNet[i]!);
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
        early: [...early, ...turnSegments],
        earlyOrder,
        ...(grouped ? { earlyTurns: turnKeys } : {}),
      });
    },
  };
}
