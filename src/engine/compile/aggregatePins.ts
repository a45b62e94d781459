// Struct and array values on the pins of the project's own blocks (LD-SEMANTICS.md section 8): a
// pin declared with a structure or array type takes a whole variable of the same type (same type
// name; an array of the same dimensions and element type), written beside it or carried by a line
// from another block's output of that type. The value is copied leaf by leaf (inputs before the
// call, outputs after); a VAR_IN_OUT names the caller's variable itself (by reference).
//
// API
// - `aggregatePinShape(types, pin)`: the struct/array type of a pin, or undefined.
// - `shapeKey(shape)` / `nodeKey(node)`: equal keys = values that may be copied as a whole.
// - `aggregateOperand(symbols, operand)`: the whole variable an operand names.
// - `setAggregateLine(nets, net, value)` / `aggregateLine(nets, net)`: what a line between two
//   boxes carries (kept beside the network's NetMap, keyed by graph net).
// - `aggregateRef(node, name)`: a symbol binding an in-out name to the caller's variable.
// - `leafCopies(dst, src)`: the leaf assignments copying one value into another of the same shape.
import type { PinSignature } from '../../model/blocks';
import { elementaryOf, resolveType, type TypeShape } from '../../model/dataTypes';
import { declaredPinType } from '../../model/library';
import type { Project } from '../../model/project';
import { dimsText, nodeLeaves, type AggNode, type AggSymbol } from './aggregates';
import type { BoxElement } from '../../model/elements';
import type { PlacedPin } from '../../model/boxLayout';
import type { NetMap } from './netMap';
import { describeElement, type Reporter } from './report';
import type { Access, SymbolTable } from './symbols';

export type AggShape = Extract<TypeShape, { kind: 'struct' | 'array' }>;

/** A whole struct/array value given to a pin: a variable, or a line from another block's output. */
export interface AggValue {
  /** The variable holding the value (absent when only its type is known: a POU checked on its own). */
  readonly node?: AggNode;
  readonly key: string;
  /** Its type, for messages (`ScaleCfg`, `ARRAY[1..4] OF INT`). */
  readonly type: string;
  /** What gives it, for messages (`MyCfg`, `the line from output Out of ...`). */
  readonly what: string;
  /** A variable (may be passed by reference), not a function's result. */
  readonly variable: boolean;
  readonly constant: boolean;
}

/** The struct or array type a user block's pin is declared with; undefined for other pins. */
export function aggregatePinShape(types: Pick<Project, 'dataTypes' | 'pous'>, pin: PinSignature): AggShape | undefined {
  if (pin.type !== 'ANY') return undefined;
  const r = resolveType(types, declaredPinType(pin));
  return r.ok && (r.shape.kind === 'struct' || r.shape.kind === 'array') ? r.shape : undefined;
}

/** The name of a single value's type in a key: its elementary type, else its data type's name. */
const valueKey = (name: string, type: string): string => `E:${elementaryOf(name) ? type : name.toUpperCase()}`;

export function shapeKey(s: TypeShape): string {
  switch (s.kind) {
    case 'struct':
      return `S:${s.name.toUpperCase()}`;
    case 'array':
      return `A[${dimsText(s.dims)}]:${shapeKey(s.of)}`;
    case 'elementary':
      return valueKey(s.name, s.type);
    case 'subrange':
    case 'enum':
      return valueKey(s.name, '');
    case 'fb':
      return `F:${s.name}`;
  }
}

export function nodeKey(n: AggNode): string {
  if (n.kind === 'leaf') return valueKey(n.v.dataType?.name ?? n.v.type, n.v.type);
  if (n.kind === 'struct') return `S:${n.type.toUpperCase()}`;
  return `A[${dimsText(n.dims)}]:${nodeKey(n.elems[0]!)}`;
}

export const nodeType = (n: AggNode): string => (n.kind === 'leaf' ? n.v.dataType?.name ?? n.v.type : n.type);

/** The whole struct/array variable an operand names, a single value's type, or a message. */
export function aggregateOperand(
  symbols: SymbolTable,
  operand: string,
): { value: AggValue } | { single: string } | { message: string; unknown: boolean } {
  const res = symbols.resolve(operand, { literals: true, implicitLocations: false });
  if (res.ok) return { single: res.access.kind === 'const' ? `the literal ${operand}` : `${operand} is ${res.access.type}` };
  if (!res.aggregate) return { message: res.message, unknown: res.unknown === true };
  const node = res.aggregate;
  const leaves = nodeLeaves(node);
  return {
    value: { node, key: nodeKey(node), type: nodeType(node), what: operand, variable: true, constant: leaves.some((v) => v.constant) },
  };
}

const lines = new WeakMap<NetMap, Map<number, AggValue>>();

export function setAggregateLine(nets: NetMap, net: number, value: AggValue): void {
  let m = lines.get(nets);
  if (!m) lines.set(nets, (m = new Map()));
  m.set(net, value);
}

export const aggregateLine = (nets: NetMap, net: number): AggValue | undefined => lines.get(nets)?.get(net);

/** Binds an in-out name of a call to the caller's struct/array variable (by reference). */
export const aggregateRef = (node: AggNode, name: string): AggSymbol => ({
  kind: 'agg',
  name,
  type: nodeType(node),
  node,
  retain: false,
  global: false,
});

/** Leaf-by-leaf assignments copying `src` into `dst` (same shape: equal keys). */
export function leafCopies(dst: AggNode, src: AggNode): { dst: Access; src: Access }[] {
  const from = nodeLeaves(src);
  return nodeLeaves(dst).map((v, i) => ({
    dst: { kind: 'var', v, type: v.type },
    src: { kind: 'var', v: from[i]!, type: from[i]!.type },
  }));
}

/** Where a box is lowered: for messages (`name` is `the Scale block "S1"`). */
export interface BoxSite {
  readonly symbols: SymbolTable;
  readonly nets: NetMap;
  readonly el: BoxElement;
  readonly name: string;
  readonly r: Reporter;
}

/**
 * The value a struct/array input pin is given (a variable beside it, or a line from another
 * block's output of that type), after the type checks: LD-R11 when it has another type or is a
 * single value, LD-E02/E03 when the operand does not resolve. Undefined: not given, or in error.
 */
export function lowerAggregateInput(
  site: BoxSite,
  pin: PlacedPin,
  shape: AggShape,
  given: { readonly net: number; readonly wired: boolean; readonly operand: string },
): AggValue | undefined {
  const { nets, el, name, r } = site;
  const expects = `input ${pin.name} of ${name} expects ${shape.name}`;
  let value: AggValue | undefined;
  if (given.wired) {
    value = aggregateLine(nets, given.net);
    if (!value) {
      const data = nets.data.get(given.net);
      if (data) r.error('LD-R11', `${expects}; its line carries ${data.from === 'data' ? data.type : data.from === 'access' ? data.access.type : 'BOOL'}`, el);
      else if (!nets.dataPending.has(given.net)) r.error('LD-R11', `${expects}; its line carries power flow (BOOL)`, el);
      return undefined; // (a source block in error reported itself)
    }
  } else if (given.operand) {
    const res = aggregateOperand(site.symbols, given.operand);
    if ('message' in res) {
      r.error(res.unknown ? 'LD-E02' : 'LD-E03', `input ${pin.name} of ${name}: ${res.message}`, el);
      return undefined;
    }
    if ('single' in res) {
      r.error('LD-R11', `${expects}, a whole ${shape.kind === 'struct' ? 'structure' : 'array'}; ${res.single}`, el);
      return undefined;
    }
    value = res.value;
  } else return undefined;
  if (value.key !== shapeKey(shape)) {
    r.error('LD-R11', `${expects}; ${value.what} is ${value.type}`, el);
    return undefined;
  }
  return value;
}

/**
 * A struct/array output pin: the leaf copies into the variable beside it (LD-R11 when it has
 * another type), and the value its line carries to other blocks' inputs of that type (LD-R11 when
 * the line reaches a contact, a coil, the rail or an input of another type). `src`: the callee's
 * variable (absent when the POU is only checked).
 */
export function lowerAggregateOutput(
  site: BoxSite,
  out: { readonly pin: PlacedPin; readonly net: number; readonly wired: boolean; readonly operand: string },
  shape: AggShape,
  src: AggNode | undefined,
  variable: boolean,
): { dst: Access; src: Access }[] {
  const { nets, el, name, r } = site;
  const gives = `output ${out.pin.name} of ${name} gives ${shape.name}`;
  const copies: { dst: Access; src: Access }[] = [];
  if (out.operand) {
    const res = aggregateOperand(site.symbols, out.operand);
    if ('message' in res) r.error(res.unknown ? 'LD-E02' : 'LD-R11', `output ${out.pin.name} of ${name}: ${res.message}`, el);
    else if ('single' in res) r.error('LD-R11', `${gives}, a whole ${shape.kind === 'struct' ? 'structure' : 'array'}; ${res.single}`, el);
    else if (res.value.key !== shapeKey(shape)) r.error('LD-R11', `${gives}; ${out.operand} is ${res.value.type}`, el);
    else if (res.value.constant) r.error('LD-R11', `output ${out.pin.name} of ${name} cannot write "${out.operand}", which is CONSTANT`, el);
    else if (src) copies.push(...leafCopies(res.value.node!, src));
  }
  if (!out.wired) return copies;
  const g = nets.g.nets[out.net]!;
  if (g.sources.length > 1 || g.leftRail || g.feeds.length || g.feedsOut.length) {
    r.error('LD-R11', `${gives}; its line is joined to other outputs or to the rail`, el);
    return copies;
  }
  if (g.rightRail) r.error('LD-R11', `${gives} to the right rail; only power flow may reach the rail`, el);
  for (const s of g.sinks) {
    const node = nets.g.nodes[s.node]!;
    const pin = node.layout?.inputs.find((p) => p.name === s.pin);
    if (node.el.kind !== 'box')
      r.error('LD-R11', `${describeElement(node.el)} is on the ${shape.name} line from output ${out.pin.name} of ${name}; contacts and coils need BOOL power flow`, node.el);
    else if (pin && !aggregatePinShape(site.symbols.storage.types, pin))
      r.error('LD-R11', `input ${pin.name} of ${describeElement(node.el)} needs ${pin.type} but its line carries ${shape.name} (output ${out.pin.name} of ${name})`, node.el);
  }
  setAggregateLine(nets, out.net, {
    ...(src ? { node: src } : {}),
    key: shapeKey(shape),
    type: shape.name,
    what: `the line from output ${out.pin.name} of ${name}`,
    variable,
    constant: false,
  });
  return copies;
}
