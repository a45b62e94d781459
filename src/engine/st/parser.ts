// Recursive-descent parser of Structured Text statements and expressions. Precedence, highest
// first (IEC 61131-3 table 71): ( ), function call, **, unary - and NOT, * / MOD, + -,
// < > <= >=, = <>, AND &, XOR, OR; operators of one level group left to right.
import {
  StSyntaxError,
  type Arg,
  type BinaryOp,
  type CaseLabel,
  type Expr,
  type PathStep,
  type Pos,
  type Stmt,
} from './ast';
import { ST_OPERATOR_WORDS, ST_STATEMENT_WORDS, tokenize, type Token } from './lexer';

/** Words that end a statement list (and cannot start a statement). */
const ENDERS = new Set([
  'END_IF',
  'ELSIF',
  'ELSE',
  'END_CASE',
  'END_FOR',
  'END_WHILE',
  'UNTIL',
  'END_REPEAT',
]);

const KEYWORDS = new Set<string>([...ST_STATEMENT_WORDS, ...ST_OPERATOR_WORDS]);

/** The pragma MATIEC's timers use to read the clock: `{__SET_VAR(data__->,NAME,,__CURRENT_TIME)}`. */
const CURRENT_TIME_PRAGMA =
  /^\s*__SET_VAR\s*\(\s*data__->\s*,\s*([A-Za-z_][A-Za-z0-9_]*)\s*,\s*,\s*__CURRENT_TIME\s*\)\s*;?\s*$/;

export interface ParseOptions {
  /** Called for a pragma the engine does not run (kept for a warning). */
  readonly onPragma?: (text: string, pos: Pos) => void;
}

export class Parser {
  private k = 0;
  constructor(
    private readonly toks: readonly Token[],
    private readonly opts: ParseOptions = {},
  ) {}

  private get t(): Token {
    return this.toks[this.k]!;
  }
  private peek(n = 1): Token {
    return this.toks[Math.min(this.k + n, this.toks.length - 1)]!;
  }
  private is(word: string): boolean {
    const t = this.t;
    return (t.kind === 'ident' || t.kind === 'symbol') && t.upper === word;
  }
  accept(word: string): boolean {
    if (!this.is(word)) return false;
    this.k++;
    return true;
  }
  private fail(what: string, at: Token = this.t): never {
    const found = at.kind === 'eof' ? 'the end of the text' : `"${at.text}"`;
    throw new StSyntaxError(at.pos, `${what}, found ${found}`);
  }
  private expect(word: string, context?: string): Token {
    const t = this.t;
    if (!this.accept(word)) this.fail(`expected ${word}${context ? ` ${context}` : ''}`);
    return t;
  }

  atEnd(): boolean {
    return this.t.kind === 'eof';
  }
  current(): Token {
    return this.t;
  }
  /** Call arguments `( ... )` from the current token (IL's CAL). */
  callArgs(): Arg[] {
    this.expect('(', 'to open the arguments');
    return this.args();
  }

  /** Statements until a closing word or the end. */
  statements(): Stmt[] {
    const out: Stmt[] = [];
    for (;;) {
      const t = this.t;
      if (t.kind === 'eof' || (t.kind === 'ident' && ENDERS.has(t.upper))) return out;
      if (this.accept(';')) continue; // empty statement
      const s = this.statement();
      if (s) out.push(s);
    }
  }

  private statement(): Stmt | undefined {
    const t = this.t;
    const pos = t.pos;
    if (t.kind === 'pragma') {
      this.k++;
      const m = CURRENT_TIME_PRAGMA.exec(t.text);
      if (m) return { k: 'now', target: { k: 'name', text: m[1]!, pos }, pos };
      this.opts.onPragma?.(t.text, pos);
      return undefined;
    }
    if (t.kind === 'ident') {
      switch (t.upper) {
        case 'IF':
          return this.ifStatement();
        case 'CASE':
          return this.caseStatement();
        case 'FOR':
          return this.forStatement();
        case 'WHILE': {
          this.k++;
          const cond = this.expression();
          this.expect('DO', 'after the WHILE condition');
          const body = this.statements();
          this.expect('END_WHILE', 'to close the WHILE');
          this.endStatement();
          return { k: 'while', cond, body, pos };
        }
        case 'REPEAT': {
          this.k++;
          const body = this.statements();
          this.expect('UNTIL', 'to close the REPEAT');
          const until = this.expression();
          this.expect('END_REPEAT', 'after the UNTIL condition');
          this.endStatement();
          return { k: 'repeat', body, until, pos };
        }
        case 'EXIT':
          this.k++;
          this.endStatement();
          return { k: 'exit', pos };
        case 'CONTINUE':
          this.k++;
          this.endStatement();
          return { k: 'continue', pos };
        case 'RETURN':
          this.k++;
          this.endStatement();
          return { k: 'return', pos };
      }
      if (KEYWORDS.has(t.upper)) this.fail('expected a statement');
      // An assignment or a call.
      if (this.peek().kind === 'symbol' && this.peek().text === '(') {
        this.k += 2;
        const args = this.args();
        this.endStatement();
        return { k: 'call', name: t.text, args, pos };
      }
      const target = this.variable();
      if (this.is('(')) this.fail('a call names an instance or a function directly (like T1(IN := x))');
      if (this.is('=')) this.fail('expected ":=" (assignment); "=" compares');
      this.expect(':=', `after "${target.k === 'name' ? target.text : ''}" (an assignment)`);
      const value = this.expression();
      this.endStatement();
      return { k: 'assign', target, value, pos };
    }
    if (t.kind === 'location') {
      const target = this.variable();
      this.expect(':=', 'after the location (an assignment)');
      const value = this.expression();
      this.endStatement();
      return { k: 'assign', target, value, pos };
    }
    if (t.kind === 'symbol' && t.text === '[') this.fail('arrays are not supported');
    this.fail('expected a statement');
  }

  private endStatement(): void {
    if (this.accept(';')) return;
    const t = this.t;
    this.fail('expected ";" to end the statement', t);
  }

  private ifStatement(): Stmt {
    const pos = this.t.pos;
    this.k++;
    const branches: { cond: Expr; body: Stmt[] }[] = [];
    const cond = this.expression();
    this.expect('THEN', 'after the IF condition');
    branches.push({ cond, body: this.statements() });
    let otherwise: Stmt[] | undefined;
    for (;;) {
      if (this.accept('ELSIF')) {
        const c = this.expression();
        this.expect('THEN', 'after the ELSIF condition');
        branches.push({ cond: c, body: this.statements() });
        continue;
      }
      if (this.accept('ELSE')) otherwise = this.statements();
      break;
    }
    this.expect('END_IF', 'to close the IF');
    this.endStatement();
    return { k: 'if', branches, ...(otherwise ? { otherwise } : {}), pos };
  }

  private caseStatement(): Stmt {
    const pos = this.t.pos;
    this.k++;
    const selector = this.expression();
    this.expect('OF', 'after the CASE selector');
    const arms: { labels: CaseLabel[]; body: Stmt[]; pos: Pos }[] = [];
    let otherwise: Stmt[] | undefined;
    for (;;) {
      if (this.accept('ELSE')) {
        otherwise = this.statements();
        break;
      }
      if (this.is('END_CASE')) break;
      const armPos = this.t.pos;
      const labels: CaseLabel[] = [];
      do {
        const lo = this.caseValue();
        if (this.accept('..')) labels.push({ lo, hi: this.caseValue() });
        else labels.push({ lo });
      } while (this.accept(','));
      this.expect(':', 'after the CASE labels');
      arms.push({ labels, body: this.caseBody(), pos: armPos });
    }
    this.expect('END_CASE', 'to close the CASE');
    this.endStatement();
    return { k: 'case', selector, arms, ...(otherwise ? { otherwise } : {}), pos };
  }

  /** Statements of a CASE arm: until the next label list, ELSE or END_CASE. */
  private caseBody(): Stmt[] {
    const out: Stmt[] = [];
    for (;;) {
      const t = this.t;
      if (t.kind === 'eof' || (t.kind === 'ident' && (t.upper === 'ELSE' || t.upper === 'END_CASE')))
        return out;
      if (this.accept(';')) continue;
      if (this.startsCaseLabel()) return out;
      if (t.kind === 'ident' && ENDERS.has(t.upper)) this.fail('expected END_CASE');
      const s = this.statement();
      if (s) out.push(s);
    }
  }

  /** A label list starts here: a literal (or -literal, or a constant name) followed by `:`, `,` or `..`. */
  private startsCaseLabel(): boolean {
    let n = 0;
    if (this.t.kind === 'symbol' && (this.t.text === '-' || this.t.text === '+')) n++;
    const v = this.peek(n);
    if (v.kind !== 'literal' && v.kind !== 'ident') return false;
    const after = this.peek(n + 1);
    return after.kind === 'symbol' && (after.text === ':' || after.text === ',' || after.text === '..');
  }

  private caseValue(): Expr {
    const t = this.t;
    if (t.kind === 'symbol' && (t.text === '-' || t.text === '+') && this.peek().kind === 'literal') {
      this.k += 2;
      return { k: 'lit', text: `${t.text}${this.toks[this.k - 1]!.text}`, pos: t.pos };
    }
    if (t.kind === 'literal') {
      this.k++;
      return { k: 'lit', text: t.text, pos: t.pos };
    }
    if (t.kind === 'ident' && !KEYWORDS.has(t.upper)) {
      this.k++;
      return { k: 'name', text: t.text, pos: t.pos };
    }
    this.fail('expected a CASE label (an integer like 3, a range like 1..5)');
  }

  private forStatement(): Stmt {
    const pos = this.t.pos;
    this.k++;
    const control = this.variable();
    this.expect(':=', 'after the FOR control variable');
    const from = this.expression();
    this.expect('TO', 'in the FOR statement');
    const to = this.expression();
    const by = this.accept('BY') ? this.expression() : undefined;
    this.expect('DO', 'in the FOR statement');
    const body = this.statements();
    this.expect('END_FOR', 'to close the FOR');
    this.endStatement();
    return { k: 'for', control, from, to, ...(by ? { by } : {}), body, pos };
  }

  /** A variable as a target: `x`, `T1.Q`, `w.3`, `%QX0.1`. */
  variable(): Expr {
    const t = this.t;
    if (t.kind === 'location') {
      this.k++;
      return { k: 'name', text: t.text, pos: t.pos };
    }
    if (t.kind !== 'ident' || KEYWORDS.has(t.upper)) this.fail('expected a variable');
    this.k++;
    let text = t.text;
    let head: string | undefined;
    const steps: PathStep[] = [];
    let constant = true;
    while (this.is('.') || this.is('[')) {
      if (this.accept('[')) {
        head ??= text;
        const index: Expr[] = [];
        do index.push(this.expression());
        while (this.accept(','));
        this.expect(']', 'to close the index list');
        steps.push({ index });
        if (!index.every((e) => e.k === 'lit' && /^[+-]?\d+$/.test(e.text))) constant = false;
        text += `[${index.map(exprText).join(',')}]`;
        continue;
      }
      const part = this.peek();
      if (part.kind !== 'ident' && !(part.kind === 'literal' && /^\d+$/.test(part.text)))
        this.fail('expected a member name or a bit number after "."', part);
      this.k += 2;
      text += `.${part.text}`;
      if (head !== undefined) steps.push({ member: part.text });
    }
    if (this.is('^')) this.fail('pointers (^) are not supported');
    if (head === undefined || constant) return { k: 'name', text, pos: t.pos };
    return { k: 'path', head, steps, text, pos: t.pos };
  }

  /** Arguments after `(`, through the closing `)`. */
  private args(): Arg[] {
    const out: Arg[] = [];
    if (this.accept(')')) return out;
    do {
      const t = this.t;
      const pos = t.pos;
      if (
        t.kind === 'ident' &&
        t.upper === 'NOT' &&
        this.peek().kind === 'ident' &&
        this.peek(2).text === '=>'
      ) {
        const name = this.peek().text;
        this.k += 3;
        out.push({ name, out: true, negated: true, value: this.variable(), pos });
      } else if (
        t.kind === 'ident' &&
        this.peek().kind === 'symbol' &&
        (this.peek().text === ':=' || this.peek().text === '=>')
      ) {
        const isOut = this.peek().text === '=>';
        this.k += 2;
        if (isOut) out.push({ name: t.text, out: true, value: this.variable(), pos });
        else out.push({ name: t.text, value: this.expression(), pos });
      } else out.push({ value: this.expression(), pos });
    } while (this.accept(','));
    this.expect(')', 'to close the call');
    return out;
  }

  expression(): Expr {
    return this.binary(0);
  }

  private static readonly LEVELS: readonly (readonly string[])[] = [
    ['OR'],
    ['XOR'],
    ['AND', '&'],
    ['=', '<>'],
    ['<', '>', '<=', '>='],
    ['+', '-'],
    ['*', '/', 'MOD'],
  ];

  private binary(level: number): Expr {
    if (level >= Parser.LEVELS.length) return this.unary();
    let a = this.binary(level + 1);
    const ops = Parser.LEVELS[level]!;
    for (;;) {
      const t = this.t;
      if ((t.kind !== 'symbol' && t.kind !== 'ident') || !ops.includes(t.upper)) return a;
      this.k++;
      const b = this.binary(level + 1);
      const op = (t.upper === '&' ? 'AND' : t.upper) as BinaryOp;
      a = { k: 'binary', op, a, b, pos: t.pos };
    }
  }

  private unary(): Expr {
    const t = this.t;
    if (this.accept('NOT')) return { k: 'unary', op: 'NOT', a: this.unary(), pos: t.pos };
    if (t.kind === 'symbol' && t.text === '-') {
      this.k++;
      const next = this.t;
      // -5, -1.5: a negative literal (so -32768 fits INT), unless ** binds to it.
      if (
        next.kind === 'literal' &&
        /^\d/.test(next.text) &&
        !/#/.test(next.text) &&
        !(this.peek().text === '**')
      ) {
        this.k++;
        return { k: 'lit', text: `-${next.text}`, pos: t.pos };
      }
      return { k: 'unary', op: '-', a: this.unary(), pos: t.pos };
    }
    if (t.kind === 'symbol' && t.text === '+') {
      this.k++;
      return this.unary();
    }
    return this.power();
  }

  private power(): Expr {
    let a = this.primary();
    while (this.is('**')) {
      const t = this.t;
      this.k++;
      const b = this.primary();
      a = { k: 'binary', op: '**', a, b, pos: t.pos };
    }
    return a;
  }

  private primary(): Expr {
    const t = this.t;
    if (this.accept('(')) {
      const e = this.expression();
      this.expect(')', 'to close "("');
      return e;
    }
    if (t.kind === 'literal') {
      this.k++;
      return { k: 'lit', text: t.text, pos: t.pos };
    }
    if (t.kind === 'string') {
      this.k++;
      return { k: 'lit', text: t.text, pos: t.pos };
    }
    if (t.kind === 'ident' && (t.upper === 'TRUE' || t.upper === 'FALSE')) {
      this.k++;
      return { k: 'lit', text: t.upper, pos: t.pos };
    }
    if (
      t.kind === 'ident' &&
      !KEYWORDS.has(t.upper) &&
      this.peek().kind === 'symbol' &&
      this.peek().text === '('
    ) {
      this.k += 2;
      return { k: 'call', name: t.text, args: this.args(), pos: t.pos };
    }
    if ((t.kind === 'ident' && !KEYWORDS.has(t.upper)) || t.kind === 'location') return this.variable();
    this.fail('expected a value (a variable, a literal, a call or "(")');
  }
}

/** An index expression as text, for names and messages (`i`, `3`, `i + 1`). */
function exprText(e: Expr): string {
  switch (e.k) {
    case 'lit':
    case 'name':
    case 'path':
      return e.text;
    case 'binary':
      return `${exprText(e.a)} ${e.op} ${exprText(e.b)}`;
    case 'unary':
      return `${e.op === 'NOT' ? 'NOT ' : '-'}${exprText(e.a)}`;
    case 'call':
      return `${e.name}(...)`;
    case 'cr':
      return 'CR';
  }
}

/** Parses a whole ST body. Throws StSyntaxError at the first error. */
export function parseStatements(text: string, opts: ParseOptions = {}): Stmt[] {
  const p = new Parser(tokenize(text), opts);
  const out = p.statements();
  if (!p.atEnd()) {
    const t = p.current();
    throw new StSyntaxError(t.pos, `"${t.text}" closes nothing that is open here`);
  }
  return out;
}

/** Parses one expression (an SFC transition condition, a test). Throws StSyntaxError. */
export function parseExpression(text: string): Expr {
  const toks = tokenize(text);
  const p = new Parser(toks);
  const e = p.expression();
  if (!p.atEnd()) {
    const t = p.current();
    throw new StSyntaxError(t.pos, `unexpected "${t.text}" after the expression`);
  }
  return e;
}
