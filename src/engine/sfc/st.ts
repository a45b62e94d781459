// The ST written inside a chart (transition conditions, action bodies, as Beremiz writes them
// inline): expressions over the POU's variables (`NOT Reset`, `Cnt + 1`, `Step1.X`, `TON1.Q`),
// assignments and IF. Checked against the instance's symbols, then written as JavaScript by the
// chart's code (codegen.ts). Calls of functions or blocks from ST are not part of this subset.
import { isElementaryType, type ElementaryType, type Value } from '../../model/iecTypes';
import { parseLiteral } from '../values/literals';
import { isBigIntType, isIntegerType, isRealType } from '../values/types';
import type { Access, SymbolTable } from '../compile/symbols';

export type StExpr =
  | { readonly k: 'lit'; readonly type: ElementaryType; readonly value: Value; readonly untyped?: boolean; readonly text: string }
  | { readonly k: 'acc'; readonly type: ElementaryType; readonly access: Access }
  | { readonly k: 'not'; readonly type: 'BOOL'; readonly e: StExpr }
  | { readonly k: 'neg'; readonly type: ElementaryType; readonly e: StExpr }
  | { readonly k: 'bin'; readonly type: ElementaryType; readonly op: string; readonly a: StExpr; readonly b: StExpr };

export type StStmt =
  | { readonly k: 'assign'; readonly dst: Access; readonly e: StExpr }
  | { readonly k: 'if'; readonly arms: readonly { readonly cond: StExpr; readonly body: readonly StStmt[] }[]; readonly other: readonly StStmt[] };

export class StError extends Error {}

const KEYWORDS = new Set(['NOT', 'AND', 'OR', 'XOR', 'MOD', 'IF', 'THEN', 'ELSIF', 'ELSE', 'END_IF', 'TRUE', 'FALSE']);
const TOKEN =
  /\s+|\(\*[\s\S]*?\*\)|\/\/[^\n]*|([A-Za-z_][A-Za-z0-9_]*#[-+]?[A-Za-z0-9_.:#]+|\d[\d_]*(?:\.\d[\d_]*)?(?:[eE][-+]?\d+)?(?:#[0-9A-Fa-f_]+)?)|([A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_0-9]+)*)|(:=|<>|<=|>=|[-+*/=<>();&])/y;

interface Tok {
  readonly kind: 'num' | 'id' | 'op';
  readonly text: string;
}

function lex(src: string): Tok[] {
  const out: Tok[] = [];
  TOKEN.lastIndex = 0;
  let at = 0;
  while (at < src.length) {
    TOKEN.lastIndex = at;
    const m = TOKEN.exec(src);
    if (!m) throw new StError(`cannot read "${src.slice(at, at + 12)}"`);
    at = TOKEN.lastIndex;
    if (m[1]) out.push({ kind: 'num', text: m[1] });
    else if (m[2]) out.push({ kind: 'id', text: m[2] });
    else if (m[3]) out.push({ kind: 'op', text: m[3] === '&' ? 'AND' : m[3] });
  }
  return out;
}

const isNumeric = (t: ElementaryType): boolean => t !== 'BOOL' && !isBigIntType(t);
const RANK: Partial<Record<ElementaryType, number>> = {
  SINT: 1, USINT: 1, BYTE: 1, INT: 2, UINT: 2, WORD: 2, DINT: 3, UDINT: 3, DWORD: 3, REAL: 4, LREAL: 5, TIME: 3,
};

/** Parses and checks ST over a scope. */
class Parser {
  private i = 0;
  constructor(
    private readonly toks: Tok[],
    private readonly scope: SymbolTable,
  ) {}

  private peek(): Tok | undefined {
    return this.toks[this.i];
  }
  private isWord(w: string): boolean {
    const t = this.peek();
    return !!t && (t.kind === 'id' || t.kind === 'op') && t.text.toUpperCase() === w;
  }
  private expect(w: string): void {
    if (!this.isWord(w)) throw new StError(`expected ${w}${this.peek() ? ` before "${this.peek()!.text}"` : ' at the end'}`);
    this.i++;
  }
  get done(): boolean {
    return this.i >= this.toks.length;
  }

  statements(until: readonly string[] = []): StStmt[] {
    const out: StStmt[] = [];
    while (!this.done && !until.some((w) => this.isWord(w))) {
      if (this.isWord(';')) {
        this.i++;
        continue;
      }
      if (this.isWord('IF')) {
        this.i++;
        const arms: { cond: StExpr; body: StStmt[] }[] = [];
        let cond = this.bool(this.expr());
        this.expect('THEN');
        arms.push({ cond, body: this.statements(['ELSIF', 'ELSE', 'END_IF']) });
        let other: StStmt[] = [];
        while (this.isWord('ELSIF')) {
          this.i++;
          cond = this.bool(this.expr());
          this.expect('THEN');
          arms.push({ cond, body: this.statements(['ELSIF', 'ELSE', 'END_IF']) });
        }
        if (this.isWord('ELSE')) {
          this.i++;
          other = this.statements(['END_IF']);
        }
        this.expect('END_IF');
        out.push({ k: 'if', arms, other });
        continue;
      }
      const t = this.peek()!;
      if (t.kind !== 'id' || KEYWORDS.has(t.text.toUpperCase()))
        throw new StError(`a statement cannot start with "${t.text}" (this chart runs assignments and IF)`);
      this.i++;
      if (this.isWord('(')) throw new StError(`"${t.text}(...)": calls are not supported in chart ST yet`);
      const dst = this.access(t.text);
      if (dst.kind === 'const') throw new StError(`"${t.text}" is a constant`);
      if ((dst.kind === 'var' || dst.kind === 'bit') && dst.v.constant) throw new StError(`"${t.text}" is CONSTANT`);
      this.expect(':=');
      const e = this.fit(this.expr(), dst.type, t.text);
      out.push({ k: 'assign', dst, e });
      if (!this.done) this.expect(';');
    }
    return out;
  }

  private access(text: string): Access {
    const r = this.scope.resolve(text, { literals: false, implicitLocations: false });
    if (!r.ok) throw new StError(r.message);
    if (isBigIntType(r.access.type)) throw new StError(`"${text}" is ${r.access.type}: 64-bit values are not supported in chart ST yet`);
    return r.access;
  }

  /** An expression given to a place of type `to` (an untyped literal takes that type). */
  fit(e: StExpr, to: ElementaryType, what: string): StExpr {
    if (e.type === to) return e;
    if (e.k === 'lit' && e.untyped) return this.literal(e.text, to);
    if (to === 'BOOL' || e.type === 'BOOL' || (e.type === 'TIME') !== (to === 'TIME'))
      throw new StError(`${what} is ${to}; the expression is ${e.type}`);
    return e; // numeric widening (and narrowing, wrapped on store as MATIEC's C does)
  }
  private bool(e: StExpr): StExpr {
    return this.fit(e, 'BOOL', 'a condition');
  }
  private literal(text: string, type?: ElementaryType): StExpr {
    if (type === 'BOOL' && (text === '0' || text === '1')) return { k: 'lit', type, value: text === '1', text };
    const lit = parseLiteral(text, type);
    if (!lit.ok) throw new StError(lit.message);
    if (isBigIntType(lit.type)) throw new StError(`"${text}": 64-bit values are not supported in chart ST yet`);
    const untyped = type === undefined && /^[\d.]/.test(text);
    return { k: 'lit', type: lit.type, value: lit.value, text, ...(untyped ? { untyped } : {}) };
  }

  expr(): StExpr {
    return this.binary(0);
  }
  private static readonly LEVELS: readonly (readonly string[])[] = [
    ['OR'],
    ['XOR'],
    ['AND'],
    ['=', '<>'],
    ['<', '>', '<=', '>='],
    ['+', '-'],
    ['*', '/', 'MOD'],
  ];
  private binary(level: number): StExpr {
    if (level >= Parser.LEVELS.length) return this.unary();
    let a = this.binary(level + 1);
    for (;;) {
      const t = this.peek();
      const op = t && Parser.LEVELS[level]!.find((o) => o === t.text.toUpperCase());
      if (!op) return a;
      this.i++;
      const b = this.binary(level + 1);
      a = this.combine(op, a, b);
    }
  }
  private combine(op: string, a: StExpr, b: StExpr): StExpr {
    if (a.k === 'lit' && a.untyped && !(b.k === 'lit' && b.untyped)) a = this.fit(a, b.type, 'the left side');
    if (b.k === 'lit' && b.untyped && !(a.k === 'lit' && a.untyped)) b = this.fit(b, a.type, 'the right side');
    if (op === 'OR' || op === 'XOR' || op === 'AND') {
      if (a.type !== 'BOOL' || b.type !== 'BOOL') throw new StError(`${op} needs BOOL operands here (${a.type}, ${b.type})`);
      return { k: 'bin', type: 'BOOL', op, a, b };
    }
    if (a.type === 'BOOL' || b.type === 'BOOL') {
      if ((op === '=' || op === '<>') && a.type === b.type) return { k: 'bin', type: 'BOOL', op, a, b };
      throw new StError(`${op} cannot take BOOL operands`);
    }
    if (!isNumeric(a.type) || !isNumeric(b.type)) throw new StError(`${op} needs numbers`);
    const type = (RANK[a.type] ?? 0) >= (RANK[b.type] ?? 0) ? a.type : b.type;
    if (['=', '<>', '<', '>', '<=', '>='].includes(op)) return { k: 'bin', type: 'BOOL', op, a, b };
    return { k: 'bin', type, op, a, b };
  }
  private unary(): StExpr {
    if (this.isWord('NOT')) {
      this.i++;
      const e = this.unary();
      if (e.type !== 'BOOL') throw new StError(`NOT needs a BOOL here (${e.type})`);
      return { k: 'not', type: 'BOOL', e };
    }
    if (this.isWord('-')) {
      this.i++;
      const t = this.peek();
      if (t?.kind === 'num') {
        this.i++;
        return this.literal(`-${t.text}`);
      }
      const e = this.unary();
      return { k: 'neg', type: e.type, e };
    }
    return this.primary();
  }
  private primary(): StExpr {
    const t = this.peek();
    if (!t) throw new StError('an expression is missing at the end');
    this.i++;
    if (t.text === '(') {
      const e = this.expr();
      this.expect(')');
      return e;
    }
    if (t.kind === 'num') return this.literal(t.text);
    if (t.kind === 'id') {
      const up = t.text.toUpperCase();
      if (up === 'TRUE' || up === 'FALSE') return { k: 'lit', type: 'BOOL', value: up === 'TRUE', text: up };
      if (KEYWORDS.has(up)) throw new StError(`"${t.text}" cannot start an expression`);
      if (this.isWord('(')) throw new StError(`"${t.text}(...)": calls are not supported in chart ST yet`);
      const a = this.access(t.text);
      if (!isElementaryType(a.type)) throw new StError(`"${t.text}" has no value`);
      return { k: 'acc', type: a.type, access: a };
    }
    throw new StError(`unexpected "${t.text}"`);
  }
}

/** A transition condition: one BOOL expression. */
export function parseStCondition(text: string, scope: SymbolTable): StExpr {
  const p = new Parser(lex(text.replace(/;\s*$/, '')), scope);
  const e = p.fit(p.expr(), 'BOOL', 'a transition condition');
  if (!p.done) throw new StError('the condition goes on after its expression');
  return e;
}

/** An action body: statements. */
export function parseStStatements(text: string, scope: SymbolTable): StStmt[] {
  return new Parser(lex(text), scope).statements();
}

/** What the chart's code generation gives the ST writer (a view of codegen's Emitter). */
export interface StWriter {
  readValue(src: { from: 'access'; access: Access }, to: ElementaryType): string;
  writeValue(a: Access, x: string, from: ElementaryType): string;
  constant(v: Value): string;
}

const WRAP: Partial<Record<ElementaryType, (x: string) => string>> = {
  SINT: (x) => `((${x}) << 24 >> 24)`,
  INT: (x) => `((${x}) << 16 >> 16)`,
  DINT: (x) => `((${x}) | 0)`,
  USINT: (x) => `((${x}) & 255)`,
  BYTE: (x) => `((${x}) & 255)`,
  UINT: (x) => `((${x}) & 65535)`,
  WORD: (x) => `((${x}) & 65535)`,
  UDINT: (x) => `((${x}) >>> 0)`,
  DWORD: (x) => `((${x}) >>> 0)`,
  REAL: (x) => `Math.fround(${x})`,
  TIME: (x) => `Math.trunc(${x})`,
};

export function emitExpr(w: StWriter, e: StExpr): string {
  switch (e.k) {
    case 'lit':
      return e.type === 'BOOL' ? (e.value ? 'true' : 'false') : w.constant(e.value);
    case 'acc':
      return w.readValue({ from: 'access', access: e.access }, e.type);
    case 'not':
      return `!(${emitExpr(w, e.e)})`;
    case 'neg':
      return `(-(${emitExpr(w, e.e)}))`;
    case 'bin': {
      const a = emitExpr(w, e.a);
      const b = emitExpr(w, e.b);
      const intDiv = isIntegerType(e.type) || e.type === 'TIME';
      switch (e.op) {
        case 'OR':
          return `(${a} || ${b})`;
        case 'AND':
          return `(${a} && ${b})`;
        case 'XOR':
          return `(${a} !== ${b})`;
        case '=':
          return `(${a} === ${b})`;
        case '<>':
          return `(${a} !== ${b})`;
        case '/':
          return intDiv ? `(${b} === 0 ? 0 : Math.trunc(${a} / ${b}))` : `(${a} / ${b})`;
        case 'MOD':
          return `(${b} === 0 ? 0 : (${a} % ${b}))`;
        default:
          return `(${a} ${e.op} ${b})`;
      }
    }
  }
}

export function emitStatements(w: StWriter, stmts: readonly StStmt[], out: string[]): void {
  for (const s of stmts) {
    if (s.k === 'assign') {
      const x = emitExpr(w, s.e);
      const t = s.dst.type;
      const wrap = isRealType(t) && t === 'LREAL' ? undefined : WRAP[t];
      const plain = (s.e.k === 'acc' || s.e.k === 'lit') && s.e.type === t;
      out.push(w.writeValue(s.dst, plain || !wrap ? x : wrap(x), t));
      continue;
    }
    s.arms.forEach((arm, k) => {
      out.push(`${k ? '} else if' : 'if'} (${emitExpr(w, arm.cond)}) {`);
      emitStatements(w, arm.body, out);
    });
    if (s.other.length) {
      out.push('} else {');
      emitStatements(w, s.other, out);
    }
    out.push('}');
  }
}
