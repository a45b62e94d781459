// Instruction List (IEC 61131-3 section 7.2) translated into the ST syntax tree, so one checker
// and one code generator serve both languages. The current result is the expression `cr` (slot
// 0); a deferred operator `AND(` saves it and opens slot 1, its `)` combines the two. Labels and
// jumps become `label`/`goto` statements; conditional forms (JMPC, CALCN, RETC, S, R) `if`s.
//
//   LD x / LDN x      cr := x / NOT x          ST x / STN x    x := cr / NOT cr
//   S x / R x         IF cr THEN x := TRUE / FALSE
//   AND OR XOR (N, &) cr := cr op [NOT] x      NOT             cr := NOT cr
//   ADD SUB MUL DIV MOD, GT GE EQ NE LE LT     cr := cr op x
//   JMP(C,CN) L, CAL(C,CN) inst(args), RET(C,CN); any other name: a function, cr := F(cr, operands)
import { StSyntaxError, type BinaryOp, type Expr, type Pos, type Stmt } from '../st/ast';
import { tokenize, type Token } from '../st/lexer';
import { Parser } from '../st/parser';

const LOGIC: Record<string, BinaryOp> = { AND: 'AND', '&': 'AND', OR: 'OR', XOR: 'XOR' };
const ARITH: Record<string, BinaryOp> = {
  ADD: '+',
  SUB: '-',
  MUL: '*',
  DIV: '/',
  MOD: 'MOD',
  GT: '>',
  GE: '>=',
  EQ: '=',
  NE: '<>',
  LE: '<=',
  LT: '<',
};

/** Comments blanked out (lines and columns kept), so the text can be read line by line. */
function blankComments(text: string): string {
  let out = '';
  let i = 0;
  while (i < text.length) {
    if (text.startsWith('(*', i)) {
      const end = text.indexOf('*)', i + 2);
      if (end < 0) throw new StSyntaxError(posAt(text, i), 'this comment "(*" is never closed with "*)"');
      out += text.slice(i, end + 2).replace(/[^\n]/g, ' ');
      i = end + 2;
    } else if (text.startsWith('//', i)) {
      const end = text.indexOf('\n', i);
      const stop = end < 0 ? text.length : end;
      out += ' '.repeat(stop - i);
      i = stop;
    } else out += text[i++];
  }
  return out;
}

function posAt(text: string, at: number): Pos {
  const before = text.slice(0, at).split('\n');
  return { line: before.length, col: before[before.length - 1]!.length + 1 };
}

interface Deferred {
  readonly op: string;
  readonly negated: boolean;
  readonly pos: Pos;
}

/** Translates an IL body. Throws StSyntaxError (located) at the first error. */
export function translateIl(text: string): Stmt[] {
  const lines = blankComments(text).split('\n');
  const out: Stmt[] = [];
  const stack: Deferred[] = [];
  const cr = (pos: Pos): Expr => ({ k: 'cr', slot: stack.length, pos });
  const setcr = (value: Expr, pos: Pos): void => void out.push({ k: 'setcr', slot: stack.length, value, pos });
  lines.forEach((lineText, li) => {
    let toks = tokenize(lineText).map((t) => ({ ...t, pos: { line: li + 1, col: t.pos.col } }));
    // A label (possibly alone on its line).
    if (toks.length >= 3 && toks[0]!.kind === 'ident' && toks[1]!.text === ':' && toks[1]!.kind === 'symbol') {
      out.push({ k: 'label', name: toks[0]!.text, pos: toks[0]!.pos });
      toks = toks.slice(2);
    }
    const first = toks[0]!;
    if (first.kind === 'eof') return;
    if (first.kind === 'pragma') return;
    const pos = first.pos;
    if (first.kind === 'symbol' && first.text === ')') {
      const d = stack.pop();
      if (!d) throw new StSyntaxError(pos, '")" closes no deferred operator like "AND("');
      const inner: Expr = { k: 'cr', slot: stack.length + 1, pos };
      const value = binary(d.op, cr(pos), d.negated ? { k: 'unary', op: 'NOT', a: inner, pos } : inner, d.pos);
      setcr(value, pos);
      expectEnd(toks, 1);
      return;
    }
    let op = first.upper;
    let rest = toks.slice(1);
    if (first.kind === 'symbol' && first.text === '&') {
      // `&` is AND; `&N` is lexed as & then N
      if (rest[0]?.kind === 'ident' && rest[0].upper === 'N' && rest[0].pos.col === first.pos.col + 1) {
        op = '&N';
        rest = rest.slice(1);
      }
    } else if (first.kind !== 'ident')
      throw new StSyntaxError(pos, `expected an IL operator (LD, ST, AND, JMP, CAL...), found "${first.text}"`);
    const deferred = rest[0]?.kind === 'symbol' && rest[0].text === '(';
    if (deferred) rest = rest.slice(1);
    const operand = (): Expr => {
      if (rest[0]?.kind === 'eof') throw new StSyntaxError(rest[0].pos, `${first.text} needs an operand`);
      return parseOperand(rest);
    };
    const negated = /^(LDN|STN|ANDN|&N|ORN|XORN)$/.test(op);
    const base = negated ? op.slice(0, -1) : op;
    const operandValue = (): Expr => {
      const x = operand();
      return negated ? { k: 'unary', op: 'NOT', a: x, pos } : x;
    };
    if (deferred) {
      // AND( x ... ) : the operand (if any) is the first load of the deferred result.
      if (!LOGIC[base] && !ARITH[base]) throw new StSyntaxError(pos, `${first.text} cannot be deferred with "("`);
      stack.push({ op: base, negated, pos });
      if (rest[0]?.kind !== 'eof') setcr(parseOperand(rest), pos);
      return;
    }
    switch (base) {
      case 'LD':
        setcr(operandValue(), pos);
        return;
      case 'ST': {
        const target = operand();
        out.push({ k: 'assign', target, value: negated ? { k: 'unary', op: 'NOT', a: cr(pos), pos } : cr(pos), pos });
        return;
      }
      case 'S':
      case 'R': {
        const target = operand();
        const value: Expr = { k: 'lit', text: base === 'S' ? 'TRUE' : 'FALSE', pos };
        out.push({ k: 'if', branches: [{ cond: cr(pos), body: [{ k: 'assign', target, value, pos }] }], pos });
        return;
      }
      case 'NOT':
        expectEnd(rest, 0);
        setcr({ k: 'unary', op: 'NOT', a: cr(pos), pos }, pos);
        return;
      case 'JMP':
      case 'JMPC':
      case 'JMPCN': {
        const label = rest[0];
        if (label?.kind !== 'ident') throw new StSyntaxError(label?.pos ?? pos, `${first.text} needs a label`);
        expectEnd(rest, 1);
        conditional(out, op, cr(pos), { k: 'goto', label: label.text, pos }, pos);
        return;
      }
      case 'RET':
      case 'RETC':
      case 'RETCN':
        expectEnd(rest, 0);
        conditional(out, op, cr(pos), { k: 'return', pos }, pos);
        return;
      case 'CAL':
      case 'CALC':
      case 'CALCN': {
        const name = rest[0];
        if (name?.kind !== 'ident') throw new StSyntaxError(name?.pos ?? pos, `${first.text} needs an instance to call`);
        const p = new Parser([...rest.slice(1)]);
        const args = rest[1]?.kind === 'symbol' && rest[1].text === '(' ? p.callArgs() : [];
        if (!p.atEnd()) throw new StSyntaxError(p.current().pos, `unexpected "${p.current().text}" after the call`);
        conditional(out, op, cr(pos), { k: 'call', name: name.text, args, pos }, pos);
        return;
      }
    }
    if (LOGIC[base] || ARITH[base]) {
      setcr(binary(base, cr(pos), operandValue(), pos), pos);
      return;
    }
    if (negated) throw new StSyntaxError(pos, `unknown IL operator ${first.text}`);
    // A function: the current result is its first input, the operands the others.
    const args: Expr[] = [cr(pos)];
    if (rest[0]?.kind !== 'eof') {
      const p = new Parser(rest);
      do args.push(p.expression());
      while (acceptComma(p));
      if (!p.atEnd()) throw new StSyntaxError(p.current().pos, `unexpected "${p.current().text}" after the operands`);
    }
    setcr({ k: 'call', name: first.text, args: args.map((value) => ({ value, pos })), pos }, pos);
  });
  if (stack.length) throw new StSyntaxError(stack[stack.length - 1]!.pos, `"${stack[stack.length - 1]!.op}(" is never closed with ")"`);
  return out;
}

function acceptComma(p: Parser): boolean {
  return p.accept(',');
}

function binary(op: string, a: Expr, b: Expr, pos: Pos): Expr {
  return { k: 'binary', op: LOGIC[op] ?? ARITH[op]!, a, b, pos };
}

function conditional(out: Stmt[], op: string, cr: Expr, s: Stmt, pos: Pos): void {
  if (op.endsWith('CN')) out.push({ k: 'if', branches: [{ cond: { k: 'unary', op: 'NOT', a: cr, pos }, body: [s] }], pos });
  else if (op.endsWith('C')) out.push({ k: 'if', branches: [{ cond: cr, body: [s] }], pos });
  else out.push(s);
}

function parseOperand(toks: readonly Token[]): Expr {
  const p = new Parser(toks);
  const e = p.expression();
  if (!p.atEnd()) throw new StSyntaxError(p.current().pos, `unexpected "${p.current().text}" after the operand`);
  return e;
}

function expectEnd(toks: readonly Token[], at: number): void {
  const t = toks[at];
  if (t && t.kind !== 'eof') throw new StSyntaxError(t.pos, `unexpected "${t.text}"`);
}
