// Type checking and name resolution of ST statements (and IL translated to them) over a symbol
// table: the checked tree of lowered.ts. Types follow the LD side: operators are the standard
// functions (`a + b` is ADD, resolved like an ADD box: the common type of the operands by the IEC
// implicit widenings, untyped literals take it), assignments accept a value that widens to the
// variable's type, anything else needs an explicit conversion (INT_TO_REAL), as MATIEC requires.
// Struct members, array elements and enum values: places.ts; the scope, errors and describe:
// checkScope.ts.
import { iecInputName } from '../../model/vendorPins';
import { blockSignature } from '../../model/blocks';
import { isElementaryType, type ElementaryType, type Value } from '../../model/iecTypes';
import type { Pou } from '../../model/project';
import { resolveFunction, type ResolvedFunction } from '../library/functions';
import { parseLiteral } from '../values/literals';
import { canWiden, commonType, isIntegerType, isBitStringType, isRealType, defaultValue } from '../values/types';
import { storeOf, type Access, type AggSymbol, type Sym, type SymbolTable } from '../compile/symbols';
import { initialLeaves, type AggNode } from '../compile/aggregates';
import { shapeKey } from '../compile/aggregatePins';
import type { Arg, BinaryOp, Expr, Pos, Stmt } from './ast';
import { ENUM_STORAGE, resolveType } from '../../model/dataTypes';
import { Places } from './places';
import { describe, Fail, type StError, type StScope } from './checkScope';
import type { CompareOp, TExpr, TStmt } from './lowered';

const CMP: Record<string, { fn: string; js: CompareOp }> = {
  '<': { fn: 'LT', js: '<' },
  '>': { fn: 'GT', js: '>' },
  '<=': { fn: 'LE', js: '<=' },
  '>=': { fn: 'GE', js: '>=' },
  '=': { fn: 'EQ', js: '===' },
  '<>': { fn: 'NE', js: '!==' },
};
const ARITH: Record<string, string> = { '+': 'ADD', '-': 'SUB', '*': 'MUL', '/': 'DIV', MOD: 'MOD' };

export class StChecker {
  readonly errors: StError[] = [];
  /** Types of IL's current-result slots, as the statements in order leave them. */
  private crTypes = new Map<number, ElementaryType>();
  /** Slots holding an untyped literal (LD 0): it takes the type of where it is used. */
  private crLiterals = new Map<number, TExpr>();
  /** Where jumps brought another type of current result than the code falling through. */
  private crConflict: { pos: Pos; message: string } | undefined;
  private labelIds = new Map<string, number>();
  private labelTypes = new Map<number, ElementaryType | undefined>();
  private seenLabels = new Set<string>();
  private loops = 0;
  /** Depth of nested statement lists (IL's jumps and RETURN at depth 0 end the reachable code). */
  private nest = 0;
  private reachable = true;

  /** Struct members, array elements, enum values, subrange checks (places.ts). */
  private readonly places: Places;

  constructor(readonly scope: StScope) {
    this.places = new Places(this, scope.symbols);
  }

  // ---- statements ----

  /** Checks a statement list; errors are collected (a statement in error is left out). */
  statements(list: readonly Stmt[]): TStmt[] {
    const out: TStmt[] = [];
    for (const s of list) {
      try {
        const t = this.statement(s);
        if (t && s.k !== 'label') out.push({ k: 'line', line: s.pos.line });
        if (t) out.push(...t);
      } catch (e) {
        if (!(e instanceof Fail)) throw e;
        this.errors.push({ pos: e.pos, message: e.message, ...(e.rule ? { rule: e.rule } : {}) });
      }
    }
    return out;
  }

  /** Declares IL labels before the statements that jump to them. */
  declareLabels(list: readonly Stmt[]): void {
    for (const s of list)
      if (s.k === 'label') {
        const key = s.name.toUpperCase();
        if (this.labelIds.has(key)) this.errors.push({ pos: s.pos, message: `the label ${s.name} is used twice` });
        else this.labelIds.set(key, this.labelIds.size);
      }
  }

  private statement(s: Stmt): TStmt[] | undefined {
    switch (s.k) {
      case 'assign': {
        const whole = this.places.wholeAssignment(s.target, s.value);
        if (whole) return whole;
        const dst = this.target(s.target);
        const value = this.expr(s.value, dst.type);
        return [this.places.assign(dst, this.to(value, dst.type, s.value.pos, `assign to ${s.target.k === 'name' || s.target.k === 'path' ? s.target.text : 'it'}`), s.value.pos)];
      }
      case 'call':
        return [this.callStatement(s.name, s.args, s.pos)];
      case 'if': {
        const branches = s.branches.map((b) => ({ cond: this.condition(b.cond, 'IF'), body: this.nested(b.body), line: b.cond.pos.line }));
        return [{ k: 'if', branches, ...(s.otherwise ? { otherwise: this.nested(s.otherwise) } : {}) }];
      }
      case 'case':
        return [this.caseStatement(s)];
      case 'for':
        return [this.forStatement(s)];
      case 'while': {
        const cond = this.condition(s.cond, 'WHILE');
        return [{ k: 'while', cond, body: this.loopBody(s.body), line: s.pos.line }];
      }
      case 'repeat': {
        const body = this.loopBody(s.body);
        return [{ k: 'repeat', body, until: this.condition(s.until, 'UNTIL'), line: s.pos.line }];
      }
      case 'exit':
      case 'continue':
        if (this.loops === 0) throw new Fail(s.pos, `${s.k.toUpperCase()} is only allowed inside FOR, WHILE or REPEAT`);
        return [{ k: s.k }];
      case 'return':
        if (this.nest === 0) this.reachable = false;
        return [{ k: 'return' }];
      case 'now': {
        const dst = this.target(s.target);
        if (dst.type !== 'TIME') throw new Fail(s.pos, `__CURRENT_TIME is a TIME; ${s.target.k === 'name' ? s.target.text : 'the variable'} is ${dst.type}`);
        return [{ k: 'now', dst }];
      }
      case 'setcr': {
        const value = this.expr(s.value);
        this.crTypes.set(s.slot, value.type);
        if (s.slot === 0) this.crConflict = undefined;
        if (value.k === 'const' && value.literal !== undefined) this.crLiterals.set(s.slot, value);
        else this.crLiterals.delete(s.slot);
        this.reachable = true;
        return [{ k: 'setcr', slot: s.slot, value }];
      }
      case 'label': {
        const id = this.labelIds.get(s.name.toUpperCase())!;
        this.seenLabels.add(s.name.toUpperCase());
        // The current result's type at a label: the one falling through, else the one jumps bring.
        const jumped = this.labelTypes.get(id);
        const here = this.reachable ? this.crTypes.get(0) : jumped;
        // Two types meet here: an error only if the current result is used before it is loaded again.
        if (this.reachable && jumped && here && jumped !== here) {
          this.crTypes.delete(0);
          this.crConflict = { pos: s.pos, message: `the current result is ${here} here but ${jumped} where jumps to ${s.name} come from` };
        } else if (here) this.crTypes.set(0, here);
        this.crLiterals.clear();
        this.reachable = true;
        return [{ k: 'label', id }];
      }
      case 'goto': {
        const id = this.labelIds.get(s.label.toUpperCase());
        if (id === undefined) throw new Fail(s.pos, `there is no label ${s.label} in this body`);
        const t = this.crTypes.get(0);
        const had = this.labelTypes.get(id);
        if (!this.labelTypes.has(id) || had === undefined) this.labelTypes.set(id, t);
        if (this.nest === 0) this.reachable = false;
        return [{ k: 'goto', id, back: this.seenLabels.has(s.label.toUpperCase()), line: s.pos.line }];
      }
    }
  }

  private nested(list: readonly Stmt[]): TStmt[] {
    this.nest++;
    try {
      return this.statements(list);
    } finally {
      this.nest--;
    }
  }

  private loopBody(list: readonly Stmt[]): TStmt[] {
    this.loops++;
    try {
      return this.nested(list);
    } finally {
      this.loops--;
    }
  }

  private condition(e: Expr, what: string): TExpr {
    const c = this.expr(e, 'BOOL');
    if (c.type !== 'BOOL') throw new Fail(e.pos, `the ${what} condition must be BOOL; ${describe(e)} is ${c.type}`);
    return c;
  }

  private caseStatement(s: Extract<Stmt, { k: 'case' }>): TStmt {
    const selector = this.expr(s.selector);
    const type = selector.type;
    if (!isIntegerType(type) && !isBitStringType(type) || type === 'BOOL')
      throw new Fail(s.selector.pos, `the CASE selector must be an integer; ${describe(s.selector)} is ${type}`);
    const label = (e: Expr): Value => {
      const en = this.places.enumValue(e);
      if (en !== undefined) return en;
      if (e.k !== 'lit') throw new Fail(e.pos, 'a CASE label must be an integer literal (like 3 or 16#0F) or an enum value');
      const lit = parseLiteral(e.text, type);
      if (!lit.ok) throw new Fail(e.pos, lit.message);
      return lit.value;
    };
    const arms = s.arms.map((a) => ({
      labels: a.labels.map((l) => ({ lo: label(l.lo), ...(l.hi ? { hi: label(l.hi) } : {}) })),
      body: this.nested(a.body),
    }));
    return { k: 'case', selector, arms, ...(s.otherwise ? { otherwise: this.nested(s.otherwise) } : {}) };
  }

  private forStatement(s: Extract<Stmt, { k: 'for' }>): TStmt {
    const control = this.target(s.control);
    if (control.kind !== 'var' || !isIntegerType(control.type))
      throw new Fail(s.control.pos, `the FOR control variable must be an integer variable; ${describe(s.control)} is ${control.type}`);
    const t = control.type;
    const from = this.to(this.expr(s.from, t), t, s.from.pos, 'start the FOR at');
    const to = this.to(this.expr(s.to, t), t, s.to.pos, 'end the FOR at');
    const by = s.by ? this.to(this.expr(s.by, t), t, s.by.pos, 'step the FOR by') : this.literal('1', t, s.pos);
    const add = this.fnIndex('ADD', [t, t], s.pos);
    return { k: 'for', control, from, to, by, add, body: this.loopBody(s.body), line: s.pos.line };
  }

  // ---- calls ----

  private callStatement(name: string, args: readonly Arg[], pos: Pos): TStmt {
    const sym = this.scope.symbols.lookup(name);
    if (sym?.kind === 'fb') return this.standardFbCall(sym, args);
    if (sym?.kind === 'ufb') return this.userFbCall(sym, args, pos);
    if (sym) throw new Fail(pos, `"${name}" is a variable, not a function block instance; only instances and functions can be called`);
    const value = this.functionCall(name, args, pos, undefined);
    return { k: 'eval', value };
  }

  private standardFbCall(fb: Extract<ReturnType<SymbolTable["lookup"]>, { kind: "fb" }>, args: readonly Arg[]): TStmt {
    const sig = blockSignature(fb.type)!;
    const ins: { pin: string; value: TExpr }[] = [];
    const outs: { pin: string; type: ElementaryType; dst: Access; negated?: boolean }[] = [];
    for (const a of args) {
      if (!a.name) throw new Fail(a.pos, `the inputs of ${fb.type} "${fb.name}" are given by name, like ${sig.inputs[0]?.name ?? 'IN'} := value`);
      // CODESYS's names of the IEC inputs (SR.SET1 is S1, CTU.RESET is R: model/vendorPins.ts).
      const pinName = (a.out ? undefined : iecInputName(fb.type, a.name)) ?? a.name.toUpperCase();
      if (a.out) {
        const pin = sig.outputs.find((p) => p.name === pinName);
        if (!pin) throw new Fail(a.pos, `${fb.type} has no output ${a.name} (outputs: ${sig.outputs.map((p) => p.name).join(', ')})`);
        const dst = this.target(a.value);
        const type = pin.type as ElementaryType;
        if (a.negated && type !== 'BOOL') throw new Fail(a.pos, `NOT applies to BOOL outputs; ${pin.name} is ${type}`);
        if (!canWiden(type, dst.type)) throw new Fail(a.pos, `the output ${pin.name} is ${type}; ${describe(a.value)} is ${dst.type}`);
        outs.push({ pin: pin.name, type, dst, ...(a.negated ? { negated: true } : {}) });
        continue;
      }
      const pin = sig.inputs.find((p) => p.name === pinName);
      if (!pin) throw new Fail(a.pos, `${fb.type} has no input ${a.name} (inputs: ${sig.inputs.map((p) => p.name).join(', ')})`);
      const type = pin.type as ElementaryType;
      ins.push({ pin: pin.name, value: this.to(this.expr(a.value, type), type, a.value.pos, `give the input ${pin.name}`) });
    }
    return { k: 'fb', fb: fb.index, ins, outs };
  }

  private userFbCall(inst: Extract<ReturnType<SymbolTable['lookup']>, { kind: 'ufb' }>, args: readonly Arg[], pos: Pos): TStmt {
    const pou = inst.pou;
    const refs = new Map<string, Access | AggSymbol>();
    const assigns: { dst: Access; value: TExpr }[] = [];
    const outArgs: Arg[] = [];
    const inputs = pou.variables.filter((v) => v.varClass === 'input' || v.varClass === 'inOut');
    args.forEach((a, i) => {
      if (a.out) {
        outArgs.push(a);
        return;
      }
      const decl = a.name ? pou.variables.find((v) => v.name.toUpperCase() === a.name!.toUpperCase()) : inputs[i];
      if (!decl || (decl.varClass !== 'input' && decl.varClass !== 'inOut'))
        throw new Fail(a.pos, a.name ? `${pou.name} has no input ${a.name} (inputs: ${inputs.map((v) => v.name).join(', ')})` : `${pou.name} takes ${inputs.length} inputs`);
      if (decl.varClass === 'inOut') {
        refs.set(decl.name, this.inOutArgument(a, decl.name, decl.type, pou.name));
        return;
      }
      const member = inst.scope.own(decl.name);
      if (member?.kind === 'agg') {
        assigns.push(...this.places.copyInto(member.node, a.value, `the input ${decl.name} of ${pou.name}`));
        return;
      }
      if (member?.kind !== 'var') throw new Fail(a.pos, `the input ${decl.name} of ${pou.name} has a type the simulator does not run (${decl.type})`);
      const dst: Access = { kind: 'var', v: member, type: member.type };
      assigns.push({ dst, value: this.to(this.expr(a.value, dst.type), dst.type, a.value.pos, `give the input ${decl.name}`) });
    });
    const outs = outArgs.flatMap((a) => this.outputArgument(a, pou, refs, (name) => inst.scope.own(name)));
    const body = this.scope.calls ? this.scope.calls.fbBody(inst, refs) : { first: -1, end: -1 };
    if (!body) throw new Fail(pos, `the call of ${inst.name} cannot be built`);
    const inits = initialLeaves(inst.scope, (v) => v.temp === true);
    return { k: 'call', inits, assigns, first: body.first, end: body.end, outs };
  }

  private inOutArgument(a: Arg, pin: string, declared: string, callee: string): Access | AggSymbol {
    if (a.value.k !== 'name' && a.value.k !== 'path') throw new Fail(a.pos, `the in-out ${pin} of ${callee} must name a variable: it is passed by reference`);
    const whole = this.places.byReference(a.value, declared, `the in-out ${pin} of ${callee}`);
    if (whole) return whole;
    if (a.value.k !== 'name') throw new Fail(a.pos, `the in-out ${pin} of ${callee} must name a variable: it is passed by reference`);
    const acc = this.target(a.value);
    const type = declared.trim().toUpperCase();
    if (isElementaryType(type) && acc.type !== type) throw new Fail(a.pos, `the in-out ${pin} of ${callee} is ${type}; ${describe(a.value)} is ${acc.type}`);
    return acc;
  }

  private outputArgument(
    a: Arg,
    pou: Pou,
    refs: Map<string, Access | AggSymbol>,
    member: (name: string) => ReturnType<SymbolTable['own']>,
  ): { dst: Access; src: Access; negated?: boolean }[] {
    const decl = pou.variables.find((v) => v.name.toUpperCase() === a.name!.toUpperCase() && (v.varClass === 'output' || v.varClass === 'inOut'));
    if (!decl) throw new Fail(a.pos, `${pou.name} has no output ${a.name} (outputs: ${pou.variables.filter((v) => v.varClass === 'output').map((v) => v.name).join(', ')})`);
    const from = decl.varClass === 'inOut' ? refs.get(decl.name) : member(decl.name);
    if (from?.kind === 'agg') {
      // A struct/array output: copied leaf by leaf into a variable of the same type.
      if (a.negated) throw new Fail(a.pos, `NOT applies to BOOL outputs; ${decl.name} is ${decl.type}`);
      return this.places.copyFrom(from.node, a.value, `the output ${decl.name} of ${pou.name}`);
    }
    const dst = this.target(a.value);
    let src: Access | undefined;
    if (decl.varClass === 'inOut') src = refs.get(decl.name) as Access | undefined;
    else {
      const m = member(decl.name);
      if (m?.kind === 'var') src = { kind: 'var', v: m, type: m.type };
    }
    if (!src) throw new Fail(a.pos, `the output ${decl.name} of ${pou.name} cannot be read here`);
    if (a.negated && src.type !== 'BOOL') throw new Fail(a.pos, `NOT applies to BOOL outputs; ${decl.name} is ${src.type}`);
    if (!canWiden(src.type, dst.type)) throw new Fail(a.pos, `the output ${decl.name} is ${src.type}; ${describe(a.value)} is ${dst.type}`);
    return [{ dst, src, ...(a.negated ? { negated: true } : {}) }];
  }

  /** A function call in an expression (or as a statement): standard or the project's own. */
  private functionCall(name: string, args: readonly Arg[], pos: Pos, hint: ElementaryType | undefined): TExpr {
    const user = this.scope.symbols.library.userPou(name);
    if (user && user.kind === 'FUNCTION' && !blockSignature(name)) return this.userFunctionCall(user, args, pos);
    if (user && user.kind === 'FUNCTION_BLOCK') throw new Fail(pos, `${user.name} is a function block: declare an instance (Inst : ${user.name}) and call the instance`);
    const sig = blockSignature(name);
    if (!sig) throw new Fail(pos, `"${name}" is not a function the simulator knows (standard functions, the project's FUNCTIONs)`);
    if (sig.kind === 'fb') throw new Fail(pos, `${sig.name} is a function block: declare an instance (T1 : ${sig.name}) and call it like T1(IN := x)`);
    // Arguments in input order: positional, or by name (extensible series by their number).
    let ordered: Arg[];
    if (args.every((a) => !a.name)) ordered = [...args];
    else if (args.every((a) => a.name && !a.out)) {
      const rank = (n: string): number => {
        const upper = n.toUpperCase();
        const fixed = sig.inputs.findIndex((p) => p.name === upper);
        if (fixed >= 0 && !(sig.extensible && new RegExp(`^${sig.extensible.prefix}\\d+$`).test(upper))) return fixed * 1000;
        const m = sig.extensible ? new RegExp(`^${sig.extensible.prefix}(\\d+)$`).exec(upper) : null;
        if (m) return (sig.inputs.length - 1) * 1000 + Number(m[1]);
        throw new Fail(pos, `${sig.name} has no input ${n} (inputs: ${sig.inputs.map((p) => p.name).join(', ')})`);
      };
      ordered = [...args].sort((a, b) => rank(a.name!) - rank(b.name!));
    } else throw new Fail(pos, `give the inputs of ${sig.name} either all by position or all by name (EN/ENO are not used in ST)`);
    const values = ordered.map((a) => this.expr(a.value));
    return this.applyFunction(sig.name, values, ordered.map((a) => a.value.pos), pos, hint);
  }

  private userFunctionCall(pou: Pou, args: readonly Arg[], pos: Pos): TExpr {
    const type = (pou.returnType ?? 'BOOL').toUpperCase();
    if (!isElementaryType(type)) {
      const shape = resolveType(this.scope.symbols.storage.types, pou.returnType ?? 'BOOL');
      if (shape.ok && (shape.shape.kind === 'struct' || shape.shape.kind === 'array'))
        throw new Fail(pos, `${pou.name} returns ${pou.returnType}, a whole ${shape.shape.kind === 'struct' ? 'structure' : 'array'}: assign it to a variable of that type (V := ${pou.name}(...);) and use its ${shape.shape.kind === 'struct' ? 'members' : 'elements'}`);
      throw new Fail(pos, `${pou.name} returns ${pou.returnType}, a type the simulator does not run`);
    }
    const { call, result } = this.userFunctionCallStmt(pou, args, pos);
    if (!call) return { k: 'const', type, value: defaultValue(type) };
    if (result?.kind !== 'var') throw new Fail(pos, `${pou.name} has no result variable`);
    return { k: 'seq', type, pre: [call], value: { k: 'read', type: result.type, access: { kind: 'var', v: result, type: result.type } } };
  }

  /**
   * `V := F(...)` where the project's FUNCTION F returns a structure or an array: the call, and
   * the call site's result variable to copy from (both absent when the POU is only checked).
   * Undefined when `e` is not such a call.
   */
  aggregateCall(e: Expr): { call?: TStmt; node?: AggNode; type: string; key: string } | undefined {
    if (e.k !== 'call') return undefined;
    const pou = this.scope.symbols.library.userPou(e.name);
    if (!pou || pou.kind !== 'FUNCTION' || blockSignature(e.name)) return undefined;
    const shape = resolveType(this.scope.symbols.storage.types, pou.returnType ?? 'BOOL');
    if (!shape.ok || (shape.shape.kind !== 'struct' && shape.shape.kind !== 'array')) return undefined;
    const { call, result } = this.userFunctionCallStmt(pou, e.args, e.pos);
    return { ...(call ? { call } : {}), ...(result?.kind === 'agg' ? { node: result.node } : {}), type: shape.shape.name, key: shapeKey(shape.shape) };
  }

  /** The call of a user FUNCTION (its inputs, body and outputs) and its result variable; no call when the POU is only checked. */
  private userFunctionCallStmt(pou: Pou, args: readonly Arg[], pos: Pos): { call?: TStmt; result?: Sym } {
    const inputs = pou.variables.filter((v) => v.varClass === 'input' || v.varClass === 'inOut');
    const site = this.scope.calls?.functionCall(pou, `${this.scope.symbols.prefix}${this.scope.pouName}@L${pos.line}C${pos.col}`);
    const refs = new Map<string, Access | AggSymbol>();
    const assigns: { dst: Access; value: TExpr }[] = [];
    const given = new Set<string>();
    const outArgs: Arg[] = [];
    args.forEach((a, i) => {
      if (a.out) {
        outArgs.push(a);
        return;
      }
      const decl = a.name ? inputs.find((v) => v.name.toUpperCase() === a.name!.toUpperCase()) : inputs[i];
      if (!decl) throw new Fail(a.pos, a.name ? `${pou.name} has no input ${a.name} (inputs: ${inputs.map((v) => v.name).join(', ')})` : `${pou.name} takes ${inputs.length} inputs, not ${args.length}`);
      given.add(decl.name.toUpperCase());
      if (decl.varClass === 'inOut') {
        refs.set(decl.name, this.inOutArgument(a, decl.name, decl.type, pou.name));
        return;
      }
      const m = site?.scope.own(decl.name);
      if (m?.kind === 'agg') {
        assigns.push(...this.places.copyInto(m.node, a.value, `the input ${decl.name} of ${pou.name}`));
        return;
      }
      const declared = m?.kind === 'var' ? m.type : decl.type.trim().toUpperCase();
      if (!isElementaryType(declared)) throw new Fail(a.pos, `the input ${decl.name} of ${pou.name} is ${decl.type}, a type the simulator does not run`);
      const value = this.to(this.expr(a.value, declared), declared, a.value.pos, `give the input ${decl.name}`);
      if (m?.kind === 'var') assigns.push({ dst: { kind: 'var', v: m, type: m.type }, value });
    });
    for (const v of inputs)
      if (v.varClass === 'inOut' && !given.has(v.name.toUpperCase())) throw new Fail(pos, `the in-out ${v.name} of ${pou.name} must be given (it is passed by reference)`);
    if (!site) {
      for (const a of outArgs) this.target(a.value);
      return {};
    }
    const outs = outArgs.flatMap((a) => this.outputArgument(a, pou, refs, (name) => site.scope.own(name)));
    const body = site.body(refs);
    if (!body) throw new Fail(pos, `the call of ${pou.name} cannot be built`);
    const inits = initialLeaves(site.scope, (_, key) => !given.has(key));
    const result = site.scope.own(pou.name);
    return { call: { k: 'call', inits, assigns, first: body.first, end: body.end, outs }, ...(result ? { result } : {}) };
  }

  /** A standard function applied to checked arguments; untyped literals take the resolved types. */
  applyFunction(name: string, args: readonly TExpr[], positions: readonly Pos[], pos: Pos, hint?: ElementaryType): TExpr {
    const types = args.map((a) => (a.k === 'const' && a.literal !== undefined ? undefined : a.type));
    const r = resolveFunction(name, types, this.scope.profile, hint);
    if (!r.ok) throw new Fail(pos, r.message);
    const fn = this.addFunction(r.fn);
    const typed = args.map((a, i) => this.to(a, r.fn.argTypes[i]!, positions[i] ?? pos, `give ${r.fn.inputNames[i]} of ${name}`));
    return { k: 'fn', type: r.fn.outType, fn, args: typed };
  }

  private addFunction(fn: ResolvedFunction): number {
    this.scope.functions.push(fn);
    return this.scope.functions.length - 1;
  }

  private fnIndex(name: string, types: ElementaryType[], pos: Pos): number {
    const r = resolveFunction(name, types, this.scope.profile);
    if (!r.ok) throw new Fail(pos, r.message);
    return this.addFunction(r.fn);
  }

  // ---- expressions ----

  /** A writable variable. */
  target(e: Expr): Access {
    if (e.k !== 'name' && e.k !== 'path') throw new Fail(e.pos, `${describe(e)} is not a variable and cannot be assigned`);
    const a = this.places.leaf(e);
    if (a.kind === 'const') throw new Fail(e.pos, `"${e.text}" is a constant`);
    if ((a.kind === 'var' || a.kind === 'bit' || a.kind === 'elem') && a.v.constant) throw new Fail(e.pos, `"${e.text}" is CONSTANT and cannot be written`);
    if (a.kind === 'pin' && a.dir === 'out') throw new Fail(e.pos, `"${e.text}" is an output of ${a.fb.type} "${a.fb.name}"; only the block writes it`);
    return a;
  }

  /** The value of `e` as type `t`: untyped literals take it, others must widen to it. */
  to(e: TExpr, t: ElementaryType, pos: Pos, what: string): TExpr {
    if (e.k === 'const' && e.literal !== undefined) return this.literal(e.literal, t, pos);
    if (e.type === t) return e;
    if (!canWiden(e.type, t))
      throw new Fail(pos, `cannot ${what}: ${t} is needed and the value is ${e.type}${conversionHint(e.type, t)}`);
    return storeOf(e.type) === 'n' && storeOf(t) === 'g' ? { k: 'big', type: t, a: e } : { ...e, type: t } as TExpr;
  }

  private literal(text: string, t: ElementaryType, pos: Pos): TExpr {
    const lit = parseLiteral(text, t);
    if (!lit.ok) throw new Fail(pos, lit.message);
    return { k: 'const', type: lit.type, value: lit.value };
  }

  expr(e: Expr, hint?: ElementaryType): TExpr {
    switch (e.k) {
      case 'lit': {
        const en = this.places.enumValue(e);
        if (en !== undefined) return { k: 'const', type: ENUM_STORAGE, value: en };
        const lit = parseLiteral(e.text);
        if (!lit.ok) throw new Fail(e.pos, lit.message);
        const untyped = /^[+-]?(\d|\d[\d_]*#)/.test(e.text) && !/^[+-]?\d[\d_]*#.*#/.test(e.text);
        if (untyped && hint) {
          const typed = parseLiteral(e.text, hint);
          if (typed.ok) return { k: 'const', type: typed.type, value: typed.value, literal: e.text };
        }
        return { k: 'const', type: lit.type, value: lit.value, ...(untyped ? { literal: e.text } : {}) };
      }
      case 'name':
      case 'path': {
        const en = this.places.enumValue(e);
        if (en !== undefined) return { k: 'const', type: ENUM_STORAGE, value: en };
        const a = this.places.leaf(e);
        if (a.kind === 'const') return { k: 'const', type: a.type, value: a.value };
        return { k: 'read', type: a.type, access: a };
      }
      case 'cr': {
        const lit = this.crLiterals.get(e.slot);
        if (lit) return lit;
        const type = this.crTypes.get(e.slot);
        if (!type && e.slot === 0 && this.crConflict) throw new Fail(this.crConflict.pos, this.crConflict.message);
        if (!type) throw new Fail(e.pos, 'there is no current result here: load a value first (LD)');
        return { k: 'cr', type, slot: e.slot };
      }
      case 'call':
        return this.functionCall(e.name, e.args, e.pos, hint);
      case 'unary': {
        const a = this.expr(e.a, hint);
        if (e.op === 'NOT') {
          if (a.type === 'BOOL') return { k: 'not', type: 'BOOL', a };
          return this.applyFunction('NOT', [a], [e.a.pos], e.pos, hint);
        }
        if (a.k === 'const' && a.literal !== undefined) return this.expr({ k: 'lit', text: `-${a.literal}`, pos: e.pos }, hint);
        return this.applyFunction('NEG', [a], [e.a.pos], e.pos, hint);
      }
      case 'binary':
        return this.binary(e, hint);
    }
  }

  private binary(e: Extract<Expr, { k: 'binary' }>, hint: ElementaryType | undefined): TExpr {
    const op: BinaryOp = e.op;
    const arith = ARITH[op];
    if (arith) {
      const a = this.expr(e.a, hint);
      const b = this.expr(e.b, hint);
      const r = this.applyFunction(arith, [a, b], [e.a.pos, e.b.pos], e.pos, hint);
      if (op === '/' && r.k === 'fn' && isRealType(r.type)) return { k: 'rdiv', type: r.type, a: r.args[0]!, b: r.args[1]! };
      return r;
    }
    const cmp = CMP[op];
    if (cmp) {
      const a = this.expr(e.a);
      const b = this.expr(e.b, a.k === 'const' && a.literal !== undefined ? undefined : a.type);
      const a2 = a.k === 'const' && a.literal !== undefined && !(b.k === 'const' && b.literal !== undefined) ? this.to(a, b.type, e.a.pos, 'compare') : a;
      const types = [a2, b].map((x) => (x.k === 'const' && x.literal !== undefined ? undefined : x.type));
      const r = resolveFunction(cmp.fn, types, this.scope.profile);
      if (!r.ok) throw new Fail(e.pos, `cannot compare ${a2.type} with ${b.type}${types[0] && types[1] ? conversionHint(types[1]!, types[0]!) : ''}`);
      const t = r.fn.argTypes[0]!;
      return { k: 'cmp', type: 'BOOL', op: cmp.js, a: this.to(a2, t, e.a.pos, 'compare'), b: this.to(b, t, e.b.pos, 'compare') };
    }
    if (op === '**') {
      let a = this.expr(e.a, hint && isRealType(hint) ? hint : 'REAL');
      const b = this.expr(e.b);
      if (a.k === 'const' && a.literal !== undefined) a = this.to(a, hint && isRealType(hint) ? hint : 'REAL', e.a.pos, 'raise');
      if (!isRealType(a.type)) throw new Fail(e.a.pos, `** (EXPT) raises a REAL or LREAL; ${describe(e.a)} is ${a.type}: convert it (${a.type}_TO_REAL)`);
      if (!isRealType(b.type) && !isIntegerType(b.type)) throw new Fail(e.b.pos, `the exponent must be a number; ${describe(e.b)} is ${b.type}`);
      return { k: 'pow', type: a.type, a, b };
    }
    // AND, XOR, OR
    const a = this.expr(e.a, hint);
    const b = this.expr(e.b, hint);
    if (a.type === 'BOOL' && b.type === 'BOOL') return { k: 'logic', type: 'BOOL', op: op as 'AND' | 'OR' | 'XOR', a, b };
    return this.applyFunction(op, [a, b], [e.a.pos, e.b.pos], e.pos, hint);
  }
}

/** ", convert it with INT_TO_REAL" when such a conversion exists. */
function conversionHint(from: ElementaryType, to: ElementaryType): string {
  const name = `${from}_TO_${to}`;
  return blockSignature(name) ? `; convert it with ${name}` : '';
}

/** The common type of several typed values (for tests and tools). */
export const common = commonType;
