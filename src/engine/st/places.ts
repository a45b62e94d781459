// ST over variables of data types: struct members and array elements (constant indexes resolve
// like LD operands; variable indexes give an `elem` access whose slot is computed at run time,
// with a bounds check that faults, LD-E62), whole struct/array assignment and copies into struct
// inputs (leaf by leaf), enum values (`Color#RED`, bare `RED` of a named or an anonymous
// enumeration, stored as their index), and the
// compile-time check of literals assigned to a subrange variable (LD-E61; MATIEC checks nothing at
// run time, so neither does the engine).
import { resolveType } from '../../model/dataTypes';
import { IDENTIFIER_RE } from '../../model/iecTypes';
import { isIntegerType } from '../values/types';
import { describeNode, dimsText, elementAt, memberOf, nodeLeaves, outside, sameShape, type AggNode, type IndexTerm } from '../compile/aggregates';
import type { Access, AggSymbol, SymbolTable } from '../compile/symbols';
import { aggregateRef, nodeKey, shapeKey } from '../compile/aggregatePins';
import type { Expr, Pos } from './ast';
import { describe, Fail, type ExprChecker } from './checkScope';
import type { TExpr, TStmt } from './lowered';

type Place = { readonly access: Access } | { readonly node: AggNode; readonly terms: readonly IndexTerm[]; readonly text: string };

const ENUM_LITERAL = /^([A-Za-z_][A-Za-z0-9_]*)#([A-Za-z_][A-Za-z0-9_]*)$/;

export class Places {
  private enums: Map<string, number> | undefined;

  constructor(
    private readonly ck: ExprChecker,
    private readonly symbols: SymbolTable,
  ) {}

  /** A single value named by `e` (a variable, member, element, location). */
  leaf(e: Expr): Access {
    const p = this.place(e);
    if ('access' in p) return p.access;
    throw new Fail(e.pos, `"${p.text}" is ${describeNode(p.node)}, not a single value; name one of its ${p.node.kind === 'struct' ? 'members' : 'elements'} (or assign it whole from a variable of the same type)`);
  }

  private place(e: Expr): Place {
    if (e.k === 'name') {
      const r = this.symbols.resolve(e.text, { literals: false, implicitLocations: true });
      if (r.ok) return { access: r.access };
      if (r.aggregate) return { node: r.aggregate, terms: [], text: e.text };
      throw new Fail(e.pos, r.message, /^the index .* is outside/.test(r.message) ? 'LD-E62' : undefined);
    }
    if (e.k !== 'path') throw new Fail(e.pos, 'a variable is needed here');
    const r = this.symbols.resolve(e.head, { literals: false, implicitLocations: false });
    if (r.ok) throw new Fail(e.pos, `"${e.head}" is not an array; it has no elements`);
    if (!r.aggregate) throw new Fail(e.pos, r.message);
    let node: AggNode = r.aggregate;
    let text = e.head;
    const terms: IndexTerm[] = [];
    for (const step of e.steps) {
      if ('member' in step) {
        if (node.kind !== 'struct') throw new Fail(e.pos, `"${text}" is ${describeNode(node)}; it has no member ${step.member}`);
        const m = memberOf(node, step.member);
        if (!m) throw new Fail(e.pos, `${node.type} "${text}" has no member ${step.member} (it has: ${node.members.map((x) => x.name).join(', ')})`);
        node = m;
        text += `.${step.member}`;
        continue;
      }
      if (node.kind !== 'array') throw new Fail(e.pos, `"${text}" is ${describeNode(node)}, not an array`);
      const arr = node;
      if (step.index.length !== arr.dims.length)
        throw new Fail(e.pos, `"${text}" has ${arr.dims.length} dimension(s) (${dimsText(arr.dims)}); ${step.index.length} index(es) are given`);
      const values = step.index.map((x, d) => this.index(x, text, arr.dims[d]!));
      const constant = values.map((v) => (v.k === 'const' ? Number(v.value) : undefined));
      if (constant.every((v) => v !== undefined)) {
        const k = elementAt(arr, constant as number[], text);
        if (typeof k === 'string') throw new Fail(e.pos, k, 'LD-E62');
        node = arr.elems[k]!;
      } else {
        const sizes = arr.dims.map((d) => d.upper - d.lower + 1);
        values.forEach((index, d) => {
          const m = sizes.slice(d + 1).reduce((a, b) => a * b, 1);
          const { lower, upper } = arr.dims[d]!;
          terms.push({ index, lower, upper, mult: { b: arr.per.b * m, n: arr.per.n * m, g: arr.per.g * m }, what: text, line: e.pos.line });
        });
        node = arr.elems[0]!;
      }
      text += `[${step.index.map((x) => ('text' in x ? x.text : '…')).join(',')}]`;
    }
    if (node.kind !== 'leaf') return { node, terms, text };
    const v = node.v;
    return { access: terms.length ? { kind: 'elem', v, type: v.type, terms, text } : { kind: 'var', v, type: v.type } };
  }

  /** An index expression: an integer; a constant one is checked against the bounds now. */
  private index(x: Expr, text: string, dim: { lower: number; upper: number }): TExpr {
    let v = this.ck.expr(x);
    if (v.k === 'const' && v.literal !== undefined) v = this.ck.to(v, 'DINT', x.pos, 'index');
    if (v.k === 'seq') throw new Fail(x.pos, `the index of "${text}" calls a user FUNCTION; assign its result to a variable first`);
    if (!isIntegerType(v.type)) throw new Fail(x.pos, `an array index must be an integer; the index of "${text}" is ${v.type}`);
    if (v.k === 'const' && (Number(v.value) < dim.lower || Number(v.value) > dim.upper))
      throw new Fail(x.pos, `the index ${String(v.value)} of ${text} is outside ${dim.lower}..${dim.upper}`, 'LD-E62');
    return v;
  }

  /** The index of an enum value written `Color#RED` or bare `RED` (when no variable has the name). */
  enumValue(e: Expr): number | undefined {
    // CODESYS qualifies an enum value with a dot: E_STATE.IDLE, when E_STATE is no variable.
    const dotted = e.k === 'name' ? /^([A-Za-z_]\w*)\.([A-Za-z_]\w*)$/.exec(e.text) : null;
    if (dotted && !this.symbols.lookup(dotted[1]!)) {
      const r = resolveType(this.symbols.storage.types, dotted[1]!);
      if (r.ok && r.shape.kind === 'enum') return this.enumValue({ k: 'lit', text: `${dotted[1]!}#${dotted[2]!}`, pos: e.pos });
    }
    if (e.k === 'lit') {
      const m = ENUM_LITERAL.exec(e.text);
      if (!m) return undefined;
      const r = resolveType(this.symbols.storage.types, m[1]!);
      if (!r.ok || r.shape.kind !== 'enum') return undefined;
      const i = r.shape.values.findIndex((v) => v.toUpperCase() === m[2]!.toUpperCase());
      if (i < 0) throw new Fail(e.pos, `${m[2]} is not a value of ${r.shape.name} (${r.shape.values.join(', ')})`);
      return i;
    }
    if (e.k !== 'name' || !IDENTIFIER_RE.test(e.text) || this.symbols.lookup(e.text)) return undefined;
    if (!this.enums) {
      this.enums = new Map();
      const add = (values: readonly string[]) => values.forEach((v, i) => this.enums!.has(v.toUpperCase()) || this.enums!.set(v.toUpperCase(), i));
      for (const dt of this.symbols.storage.types.dataTypes ?? []) if (dt.def.kind === 'enum') add(dt.def.values);
      // Anonymous enumerations of the declarations (`State : (Idle, Run, Fault)`).
      for (const v of this.symbols.storage.vars) if (v.dataType?.enumValues) add(v.dataType.enumValues);
    }
    return this.enums.get(e.text.toUpperCase());
  }

  /** `P1 := P2;` of two structs (or arrays) of the same type: one assignment per leaf; undefined when the target is a single value. */
  wholeAssignment(target: Expr, value: Expr): TStmt[] | undefined {
    if (target.k !== 'name' && target.k !== 'path') return undefined;
    const dst = this.place(target);
    if ('access' in dst) return undefined;
    return this.copyInto(dst, value, `"${dst.text}"`).map((a) => ({ k: 'assign', ...a }));
  }

  /**
   * Leaf-by-leaf copies of `value` into a struct/array place (a whole assignment, a struct input):
   * `value` names a variable of the same type, or calls a FUNCTION returning that type.
   */
  copyInto(dst: AggNode | Place, value: Expr, what: string): { dst: Access; value: TExpr }[] {
    const to: Place = 'kind' in dst ? { node: dst, terms: [], text: what } : dst;
    if ('access' in to) throw new Fail(value.pos, `${what} is a single value`);
    const call = this.ck.aggregateCall(value);
    if (call) {
      if (call.key !== nodeKey(to.node)) throw new Fail(value.pos, `${what} is ${describeNode(to.node)}; ${describe(value)} returns ${call.type}`);
      if (!call.call || !call.node) return [];
      const srcs = nodeLeaves(call.node);
      return this.leaves(to).map((d, i) => {
        const read: TExpr = { k: 'read', type: srcs[i]!.type, access: { kind: 'var', v: srcs[i]!, type: srcs[i]!.type } };
        return { dst: d, value: i === 0 ? { k: 'seq', type: read.type, pre: [call.call!], value: read } : read };
      });
    }
    const from = value.k === 'name' || value.k === 'path' ? this.place(value) : undefined;
    if (!from || 'access' in from)
      throw new Fail(value.pos, `${what} is ${describeNode(to.node)}; give it a variable of the same type (member by member otherwise)`);
    if (!sameShape(to.node, from.node))
      throw new Fail(value.pos, `${what} is ${describeNode(to.node)}; "${from.text}" is ${describeNode(from.node)}`);
    const dsts = this.leaves(to);
    const srcs = this.leaves(from);
    if (dsts.some((a) => a.kind !== 'const' && 'v' in a && a.v.constant)) throw new Fail(value.pos, `${what} is CONSTANT and cannot be written`);
    return dsts.map((d, i) => ({ dst: d, value: { k: 'read', type: srcs[i]!.type, access: srcs[i]! } }));
  }

  /** Leaf-by-leaf copies of a callee's struct/array output into the variable `target` names (`S1(Last => Got)`). */
  copyFrom(src: AggNode, target: Expr, what: string): { dst: Access; src: Access }[] {
    const to = target.k === 'name' || target.k === 'path' ? this.place(target) : undefined;
    if (!to || 'access' in to) throw new Fail(target.pos, `${what} is ${describeNode(src)}; give it a variable of the same type`);
    if (!sameShape(to.node, src)) throw new Fail(target.pos, `${what} is ${describeNode(src)}; "${to.text}" is ${describeNode(to.node)}`);
    const dsts = this.leaves(to);
    if (dsts.some((a) => 'v' in a && a.v.constant)) throw new Fail(target.pos, `"${to.text}" is CONSTANT and cannot be written`);
    const from = nodeLeaves(src);
    return dsts.map((d, i) => ({ dst: d, src: { kind: 'var', v: from[i]!, type: from[i]!.type } }));
  }

  /**
   * A whole struct/array variable passed to an in-out of type `declared` (by reference: the
   * callee's name is bound to it); undefined when `e` names a single value.
   */
  byReference(e: Expr, declared: string, what: string): AggSymbol | undefined {
    const p = this.place(e);
    if ('access' in p) return undefined;
    const shape = resolveType(this.symbols.storage.types, declared);
    if (!shape.ok || nodeKey(p.node) !== shapeKey(shape.shape)) throw new Fail(e.pos, `${what} is ${declared}; "${p.text}" is ${describeNode(p.node)}`);
    if (p.terms.length) throw new Fail(e.pos, `${what} is passed by reference; "${p.text}" picks its element with a variable index: pass a constant index or a whole variable`);
    if (nodeLeaves(p.node).some((v) => v.constant)) throw new Fail(e.pos, `${what} cannot be "${p.text}", which is CONSTANT`);
    return aggregateRef(p.node, p.text);
  }

  private leaves(p: Extract<Place, { node: AggNode }>): Access[] {
    return nodeLeaves(p.node).map((v) =>
      p.terms.length ? { kind: 'elem', v, type: v.type, terms: p.terms, text: p.text } : { kind: 'var', v, type: v.type },
    );
  }

  /** An assignment; a constant outside a subrange variable's range is an error (LD-E61). */
  assign(dst: Access, value: TExpr, pos: Pos): TStmt {
    const range = (dst.kind === 'var' || dst.kind === 'elem') && dst.v.dataType?.range;
    if (range && value.k === 'const' && outside(value.value, range))
      throw new Fail(pos, `${String(value.value)} is outside the subrange ${dst.v.dataType!.name} (${range.lower}..${range.upper}) of "${dst.kind === 'elem' ? dst.text : dst.v.name}"`, 'LD-E61');
    return { k: 'assign', dst, value };
  }
}
