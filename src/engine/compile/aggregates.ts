// Variables of user data types (model/dataTypes.ts). An enum, subrange or alias variable is one
// VarSymbol of its elementary storage type (an enum holds its value's index in an INT) carrying
// DataTypeInfo. A struct or array variable is an AggSymbol: a tree (AggNode) whose leaves are
// VarSymbols named by their paths (`P.X`, `A[3]`, `G[1,2]`, `S.Pts[1].X`), allocated in order,
// so an array's elements are evenly spaced in each store (`per`: leaves of one element per store)
// and an element chosen by a variable index is `slot of the first element + (i - lower) * stride`.
import { checkDataTypes, enumIndexOf, leafPaths, type Dim, type Leaf, type TypeShape } from '../../model/dataTypes';
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { Variable } from '../../model/project';
import { parseLiteral } from '../values/literals';
import { defaultValue } from '../values/types';
import type { TExpr } from '../st/lowered';
import { Reporter } from './report';
import type { Diagnostic } from '../api';
import type { Project } from '../../model/project';
import type { Access, DataTypeInfo, SymbolTable, VarSymbol } from './symbols';

export type PerStore = { readonly b: number; readonly n: number; readonly g: number };

export type AggNode =
  | { readonly kind: 'leaf'; readonly v: VarSymbol }
  | {
      readonly kind: 'struct';
      readonly type: string;
      readonly members: readonly { readonly name: string; readonly node: AggNode }[];
    }
  | {
      readonly kind: 'array';
      readonly type: string;
      readonly dims: readonly Dim[];
      readonly elems: readonly AggNode[];
      /** Leaves of one element in each store. */
      readonly per: PerStore;
    };

/** A struct or array variable. */
export interface AggSymbol {
  readonly kind: 'agg';
  /** Path as declared (`Motor1.P` inside an instance). */
  readonly name: string;
  /** The declared type name. */
  readonly type: string;
  readonly node: AggNode;
  readonly retain: boolean;
  readonly global: boolean;
}

/** One variable index of an element access: its value minus `lower` times `mult` of the leaf's store. */
export interface IndexTerm {
  readonly index: TExpr;
  readonly lower: number;
  readonly upper: number;
  readonly mult: PerStore;
  /** What is indexed, for the bounds fault (`A`, `S.Pts`), and the ST line. */
  readonly what: string;
  readonly line: number;
}

const typeName = (n: AggNode): string => (n.kind === 'leaf' ? n.v.dataType?.name ?? n.v.type : n.type);

/** A type description for messages: `Point` (struct), `ARRAY[1..3] OF INT`. */
export const describeNode = (n: AggNode): string =>
  n.kind === 'leaf' ? typeName(n) : n.kind === 'struct' ? `the structure ${n.type}` : `the array ${n.type}`;

/** Every leaf under a node, in storage order. */
export function nodeLeaves(n: AggNode, out: VarSymbol[] = []): VarSymbol[] {
  if (n.kind === 'leaf') out.push(n.v);
  else if (n.kind === 'struct') for (const m of n.members) nodeLeaves(m.node, out);
  else for (const e of n.elems) nodeLeaves(e, out);
  return out;
}

/** True when values of the two nodes can be assigned as a whole (same type name and shape). */
export function sameShape(a: AggNode, b: AggNode): boolean {
  if (a.kind === 'leaf' || b.kind === 'leaf')
    return a.kind === 'leaf' && b.kind === 'leaf' && a.v.type === b.v.type && (a.v.dataType?.name ?? '').toUpperCase() === (b.v.dataType?.name ?? '').toUpperCase();
  if (a.kind === 'struct' && b.kind === 'struct') return a.type.toUpperCase() === b.type.toUpperCase();
  if (a.kind === 'array' && b.kind === 'array')
    return (
      a.dims.length === b.dims.length &&
      a.dims.every((d, i) => d.lower === b.dims[i]!.lower && d.upper === b.dims[i]!.upper) &&
      sameShape(a.elems[0]!, b.elems[0]!)
    );
  return false;
}

/** The member of a struct node (case-insensitive). */
export const memberOf = (n: Extract<AggNode, { kind: 'struct' }>, name: string): AggNode | undefined =>
  n.members.find((m) => m.name.toUpperCase() === name.trim().toUpperCase())?.node;

/** Linear element number of constant indexes, or a message. */
export function elementAt(n: Extract<AggNode, { kind: 'array' }>, indexes: readonly number[], path: string): number | string {
  if (indexes.length !== n.dims.length)
    return `${path} has ${n.dims.length} dimension${n.dims.length > 1 ? 's' : ''} (${dimsText(n.dims)}); ${indexes.length} index${indexes.length > 1 ? 'es are' : ' is'} given`;
  let k = 0;
  for (let d = 0; d < n.dims.length; d++) {
    const { lower, upper } = n.dims[d]!;
    const i = indexes[d]!;
    if (i < lower || i > upper) return `the index ${i} of ${path} is outside ${lower}..${upper}`;
    k = k * (upper - lower + 1) + (i - lower);
  }
  return k;
}

export const dimsText = (dims: readonly Dim[]): string => dims.map((d) => `${d.lower}..${d.upper}`).join(', ');

/**
 * Declares a variable whose type is not elementary (and not a function block): an enum, subrange
 * or alias variable (returns its VarSymbol) or a struct/array variable (returns its AggSymbol).
 * Errors: LD-E15 unknown type, LD-E14 bad initial value, LD-E13 a location on a struct or array.
 * Warning LD-W61: initial values outside a subrange (IEC forbids them; MATIEC keeps them).
 */
export function declareDataTyped(
  table: SymbolTable,
  decl: Variable,
  global: boolean,
  r: Reporter,
  temp: boolean,
): VarSymbol | AggSymbol | undefined {
  const what = `the variable "${decl.name}"`;
  const res = leafPaths(table.storage.types, decl);
  if (!res.ok) {
    const unknown = /is not a type|contains itself|must be of an integer type|names the function block/.test(res.message);
    if (unknown)
      r.error('LD-E15', `${what} has the type "${decl.type}", which cannot be used: ${res.message}; use an elementary type, a standard block or a data type of the project`);
    else r.error('LD-E14', `${what} has a bad initial value: ${res.message}`);
    return undefined;
  }
  const shape = res.shape;
  const leaves = res.leaves;
  if (shape.kind === 'fb') {
    r.error('LD-E15', `${what} has the type "${decl.type}", a function block the simulator cannot instantiate here`);
    return undefined;
  }
  // An array of FB instances (ARRAY[1..8] OF TON, common in CODESYS projects): not instantiated.
  const fbArray = (s: TypeShape): boolean =>
    s.kind === 'array' ? s.of.kind === 'fb' || fbArray(s.of) : s.kind === 'struct' ? s.members.some((m) => m.type.kind !== 'fb' && fbArray(m.type)) : false;
  if (fbArray(shape)) {
    r.error('LD-E15', `${what} has the type "${decl.type}", an array of function block instances, which the simulator does not support`);
    return undefined;
  }
  const single = shape.kind === 'elementary' || shape.kind === 'enum' || shape.kind === 'subrange';
  const values: Value[] = [];
  let failed = false;
  const outOfRange: Leaf[] = [];
  for (const leaf of leaves) {
    const v = leafInitial(leaf);
    if (typeof v === 'object' && v !== null && 'error' in v) {
      r.error('LD-E14', `${what}: ${v.error}`);
      failed = true;
      continue;
    }
    if (leaf.range && outside(v as Value, leaf.range)) outOfRange.push(leaf);
    values.push(v as Value);
  }
  if (failed) return undefined;
  if (outOfRange.length) {
    const first = outOfRange[0]!;
    r.warning(
      'LD-W61',
      `${what}: ${outOfRange.length === 1 ? 'the initial value' : `${outOfRange.length} initial values`} ${outOfRange.length === 1 ? 'is' : 'are'} outside ${first.typeName} (${first.range!.lower}..${first.range!.upper}), first ${first.path} := ${first.initial}; IEC 61131-3 forbids it, MATIEC starts with the value as given and so does the simulator`,
    );
  }
  const retain = decl.retain;
  const constant = decl.constant === true;
  if (single) {
    const leaf = leaves[0]!;
    const location = table.declaredLocation(decl, leaf.type, r);
    if (location === false) return undefined;
    return table.addVar(table.prefix + decl.name, leaf.type, values[0]!, retain, constant, location, global, false, temp, infoOf(leaf));
  }
  if (decl.location !== undefined && decl.location.trim() !== '') {
    r.error('LD-E13', `${what} is ${shape.kind === 'struct' ? 'a structure' : 'an array'} (${decl.type}) and cannot have a location`);
    return undefined;
  }
  let k = 0;
  const build = (s: TypeShape): AggNode => {
    switch (s.kind) {
      case 'struct':
        return { kind: 'struct', type: s.name, members: s.members.filter((m) => m.type.kind !== 'fb').map((m) => ({ name: m.name, node: build(m.type) })) };
      case 'array': {
        const elems: AggNode[] = [];
        const count = s.dims.reduce((n, d) => n * (d.upper - d.lower + 1), 1);
        const start = { ...table.counts };
        elems.push(build(s.of));
        const per = { b: table.counts.b - start.b, n: table.counts.n - start.n, g: table.counts.g - start.g };
        for (let e = 1; e < count; e++) elems.push(build(s.of));
        return { kind: 'array', type: s.name, dims: s.dims, elems, per };
      }
      case 'fb':
        throw new Error('unreachable: FB members are filtered');
      default: {
        const leaf = leaves[k]!;
        const v = table.addVar(table.prefix + leaf.path, leaf.type, values[k]!, retain, constant, undefined, global, false, temp, infoOf(leaf));
        k++;
        return { kind: 'leaf', v };
      }
    }
  };
  const node = build(shape);
  const agg: AggSymbol = { kind: 'agg', name: table.prefix + decl.name, type: shape.name, node, retain, global };
  table.storage.aggs.push(agg);
  return agg;
}

function infoOf(leaf: Leaf): DataTypeInfo {
  return {
    name: leaf.typeName,
    ...(leaf.enumValues ? { enumValues: leaf.enumValues } : {}),
    ...(leaf.range ? { range: leaf.range } : {}),
  };
}

/** The initial value of a leaf: its literal, an enum value's index, a subrange's lower bound by default. */
function leafInitial(leaf: Leaf): Value | { error: string } {
  if (leaf.initial === undefined) {
    if (leaf.range) return literalOf(String(leaf.range.lower), leaf.type);
    return defaultValue(leaf.type);
  }
  if (leaf.enumValues) {
    const i = enumIndexOf(leaf, leaf.initial);
    if (!i) return { error: `${leaf.path}: ${leaf.initial} is not a value of ${leaf.typeName} (${leaf.enumValues.join(', ')})` };
    return i - 1;
  }
  const lit = parseLiteral(leaf.initial, leaf.type);
  if (!lit.ok) return { error: `${leaf.path}: ${lit.message}` };
  return lit.value;
}

/** LD-E60: the problems of the project's data type declarations (unknown names, cycles, empty ranges...), under "types". */
export function reportDataTypes(project: Project, out: Diagnostic[]): void {
  const r = new Reporter(out, 'types', -1);
  for (const e of checkDataTypes(project)) r.error('LD-E60', `${e.name}: ${e.message}`);
}

export const outside = (v: Value, range: Dim): boolean => Number(v) < range.lower || Number(v) > range.upper;

function literalOf(text: string, type: ElementaryType): Value {
  const lit = parseLiteral(text, type);
  return lit.ok ? lit.value : defaultValue(type);
}

/** Initial values of a callee's variables (`which` leaves; a struct/array variable's every leaf). */
export function initialLeaves(scope: SymbolTable, which: (v: VarSymbol, key: string) => boolean): { dst: Access; value: Value }[] {
  const out: { dst: Access; value: Value }[] = [];
  for (const [key, m] of scope.ownNames()) {
    const vars = m.kind === 'var' ? [m] : m.kind === 'agg' ? nodeLeaves(m.node) : [];
    for (const v of vars) if (which(v, key)) out.push({ dst: { kind: 'var', v, type: v.type }, value: v.initial });
  }
  return out;
}
