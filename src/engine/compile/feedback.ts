// Explicit feedback loops through a block (order.ts): where the loop is cut, an element reads the
// block's stored output, its value from the block's previous call. An FB instance keeps its
// outputs (the wire reads `T1.Q`); a function, a user function or the inverting contact keeps
// nothing, so its call also writes the output to a variable of its own, which the reader reads
// (Beremiz's `_TMP_AND5_OUT`, declared in the program: FALSE/0 before the first call).
// The diagnostic (LD-W30) is shared by both profiles: profile `iec` cuts the loop where order.ts
// says, profile `openplc` where Beremiz's generator does (generated.ts).
import type { ElementaryType } from '../../model/iecTypes';
import { isElementaryType } from '../../model/iecTypes';
import type { Profile } from '../../model/project';
import { resolveFunction } from '../library/functions';
import { defaultValue } from '../values/types';
import type { PouContext } from './context';
import type { GraphNode, NetworkGraph } from './graph';
import type { Op, OutIR, Source } from './ir';
import type { NetMap } from './netMap';
import { describeElement, type Reporter } from './report';
import { storeOf, type Access } from './symbols';

/** The output of an FB instance (standard or user FB), read by its instance path; undefined for other blocks. */
export function instanceOutput(ctx: PouContext, node: GraphNode, pin: string): Access | undefined {
  const el = node.el;
  if (el.kind !== 'box' || node.layout?.signature.kind !== 'fb' || !el.instance?.trim() || pin.toUpperCase() === 'ENO') return undefined;
  const res = ctx.symbols.resolve(`${el.instance.trim()}.${pin}`, { literals: false, implicitLocations: false });
  return res.ok ? res.access : undefined;
}

/**
 * The type of a block's output pin before the block is lowered: its declared type, BOOL for the
 * inverting contact. For a generic output (AND's ANY_BIT OUT, ADD's ANY_NUM OUT), what the drawing
 * says, as Beremiz's generator types its `_TMP_ADD3_OUT`: BOOL when its line is power flow (it
 * reaches a contact, a coil, the rail, a BOOL input, or joins other outputs); else the type of the
 * variable written beside it, of a variable given to an input of the same generic type, or of the
 * first elementary input its line reaches. Undefined when nothing says.
 */
export function outputType(ctx: PouContext, g: NetworkGraph, producer: GraphNode, pin: string): ElementaryType | undefined {
  if (producer.el.kind === 'contact') return 'BOOL';
  const declared = producer.layout?.outputs.find((p) => p.name === pin)?.type;
  if (declared !== undefined && isElementaryType(declared)) return declared;
  const out = producer.outputs.find((t) => t.pin === pin);
  if (!out) return undefined;
  const line = g.nets[out.net]!;
  if (line.rightRail || line.leftRail || line.sources.length > 1 || line.feeds.length || line.feedsOut.length) return 'BOOL';
  const el = producer.el;
  const variableType = (operand: string | undefined): ElementaryType | undefined => {
    if (!operand?.trim()) return undefined;
    const res = ctx.symbols.resolve(operand.trim(), { literals: false, implicitLocations: true });
    return res.ok && isElementaryType(res.access.type) ? res.access.type : undefined;
  };
  const operandOf = (ops: Readonly<Record<string, string>>, name: string) =>
    Object.entries(ops).find(([k]) => k.toUpperCase() === name.toUpperCase())?.[1];
  let found: ElementaryType | undefined;
  for (const s of line.sinks) {
    const reader = g.nodes[s.node]!;
    if (reader.el.kind !== 'box') return 'BOOL';
    const t = reader.layout?.inputs.find((p) => p.name === s.pin)?.type;
    if (t === 'BOOL') return 'BOOL';
    if (!found && t !== undefined && isElementaryType(t)) found = t;
  }
  if (el.kind === 'box') {
    const beside = variableType(operandOf(el.outputs, pin));
    if (beside) return beside;
    for (const p of producer.layout?.inputs ?? []) {
      if (p.type !== declared) continue;
      const given = variableType(operandOf(el.inputs, p.name));
      if (given) return given;
    }
  }
  return found;
}

/** A variable of the generated code that the program does not declare. */
export function hiddenVariable(ctx: PouContext, name: string, type: ElementaryType): Access {
  const store = storeOf(type);
  const slot = ctx.symbols.counts[store]++;
  if (store !== 'b') ctx.dataSlots.push({ store, slot, type });
  const v = { kind: 'var', name, type, store, slot, initial: defaultValue(type), retain: false, constant: false, global: false, implicit: false, hidden: true } as const;
  return { kind: 'var', v, type };
}

/** `out := src` as a MOVE call of the element `node` (a variable or a power-flow local into a local or a variable). */
export function moveOp(ctx: PouContext, node: number, src: Access | number, out: OutIR): Op | undefined {
  const type = typeof src === 'number' ? 'BOOL' : src.type;
  const res = resolveFunction('MOVE', [type], ctx.profile);
  if (!res.ok) return undefined;
  let fn = ctx.functions.indexOf(res.fn);
  if (fn < 0) {
    fn = ctx.functions.length;
    ctx.functions.push(res.fn);
  }
  const from: Source = typeof src === 'number' ? { from: 'power', net: src } : { from: 'access', access: src };
  return { op: 'function', node, name: 'MOVE', fn, args: [{ pin: 'IN', type, src: from }], out, eno: { pin: 'ENO', type: 'BOOL' } };
}

/** LD-W30 on the block whose output is fed back: which element reads its stored value, and why. */
export function reportFeedback(r: Reporter, profile: Profile, producer: GraphNode, pin: string, reader: GraphNode): void {
  const block = describeElement(producer.el);
  const instance = producer.el.kind === 'box' ? producer.el.instance?.trim() : undefined;
  const output = instance ? `${instance}.${pin}` : `its output ${pin}`;
  const self = reader === producer;
  const who = self ? 'the block' : describeElement(reader.el);
  const how = profile === 'openplc' ? ', as Beremiz and OpenPLC run it' : '';
  r.warning(
    'LD-W30',
    `${block} feeds back into ${self ? 'its own input' : describeElement(reader.el)} (an explicit loop, which IEC 61131-3 allows in FBD only): ${who} reads ${output} as the block's previous call left it (its initial value at the first scan), then the block runs${how}; to choose where the loop is cut, write ${instance ? output : pin} to a variable and read that variable instead`,
    producer.el,
  );
}

/**
 * A data line read before the function feeding it runs: a slot the function's call writes when it
 * runs (boxPins.ts writes a held slot), which the readers read first.
 */
export function holdData(ctx: PouContext, nets: NetMap, net: number, type: ElementaryType): void {
  const store = storeOf(type);
  const data = { store, slot: ctx.symbols.counts[store]++ };
  ctx.dataSlots.push({ ...data, type });
  nets.heldData.set(net, data);
  nets.data.set(net, { from: 'data', ...data, type });
}

/**
 * A data line (INT, TIME, ...) read back through a loop before its block ran: the FB instance's
 * output, or a slot the function's call writes (boxPins.ts writes a held slot). False, with an
 * error, when the type of a generic output cannot be known before the function runs.
 */
export function storedDataLine(ctx: PouContext, nets: NetMap, producer: GraphNode, pin: string, net: number, reader: GraphNode, r: Reporter): boolean {
  if (nets.data.has(net)) return true;
  const access = instanceOutput(ctx, producer, pin);
  if (access) {
    nets.data.set(net, { from: 'access', access });
    return true;
  }
  const type = outputType(ctx, nets.g, producer, pin);
  if (type && type !== 'BOOL') {
    holdData(ctx, nets, net, type);
    return true;
  }
  r.error(
    'LD-R01',
    `${describeElement(reader.el)} reads output ${pin} of ${describeElement(producer.el)} back through a loop, before that block has run, and the type of that output is only known once it runs: write ${pin} to a variable and read the variable`,
    reader.el,
  );
  return false;
}

/**
 * A block reading its own output (a self-loop: its input and output on one line): the call reads
 * its inputs on that line from `map` (line local -> the local holding the stored value), and still
 * writes its output to the line.
 */
export function rebindInputs(op: Op, map: ReadonlyMap<number, number>): Op {
  if (!map.size) return op;
  const src = (s: Source): Source => (s.from === 'power' && map.has(s.net) ? { from: 'power', net: map.get(s.net)! } : s);
  switch (op.op) {
    case 'contact':
      return map.has(op.inNet) ? { ...op, inNet: map.get(op.inNet)! } : op;
    case 'function':
    case 'fb':
      return { ...op, args: op.args.map((a) => ({ ...a, src: src(a.src) })), ...(op.en ? { en: src(op.en) } : {}) };
    case 'call':
      return { ...op, assigns: op.assigns.map((a) => ({ ...a, src: src(a.src) })), ...(op.en ? { en: src(op.en) } : {}) };
    default:
      return op;
  }
}
