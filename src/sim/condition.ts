// Conditions for "jump to the next time it holds" on the timeline: a small boolean expression over
// recorded values, e.g. `Motor AND NOT Start`, `T1.ET >= T#2s`, `(A OR B) AND Count = 5`.
// Operators: NOT, AND (&), OR, XOR, comparisons = <> < > <= >=, parentheses. Literals: TRUE, FALSE,
// numbers, TIME literals (T#2s, in ms).
import { parseValueText } from '../engine/values/literals';
import type { Value } from '../model/iecTypes';

export type CompiledCondition = (values: readonly Value[]) => boolean;

type Num = (values: readonly Value[]) => number;

const TOKEN_RE = /\s*(<>|<=|>=|[()=<>&]|T(?:IME)?#[^\s()]+|[A-Za-z_%][\w.%]*|-?\d+(?:\.\d+)?)/gy;

export class ConditionError extends Error {}

function tokenize(text: string): string[] {
  const out: string[] = [];
  TOKEN_RE.lastIndex = 0;
  let at = 0;
  while (at < text.length) {
    if (/^\s*$/.test(text.slice(at))) break;
    TOKEN_RE.lastIndex = at;
    const m = TOKEN_RE.exec(text);
    if (!m) throw new ConditionError(`cannot read "${text.slice(at).trim()}" in the condition`);
    out.push(m[1]!);
    at = TOKEN_RE.lastIndex;
  }
  return out;
}

/** Compiles `text` with `indexOf(name)` giving a recorded value's index (undefined: unknown name). */
export function compileCondition(text: string, indexOf: (name: string) => number | undefined): CompiledCondition {
  const tokens = tokenize(text);
  if (tokens.length === 0) throw new ConditionError('the condition is empty');
  let pos = 0;
  const peek = () => tokens[pos]?.toUpperCase();
  const next = () => tokens[pos++];

  const operand = (): Num => {
    const t = next();
    if (t === undefined) throw new ConditionError('the condition ends too early');
    const up = t.toUpperCase();
    if (t === '(') {
      const inner = or();
      if (next() !== ')') throw new ConditionError('a ( is not closed');
      return (v) => (inner(v) ? 1 : 0);
    }
    if (up === 'TRUE' || up === 'FALSE') return up === 'TRUE' ? () => 1 : () => 0;
    if (/^-?\d/.test(t)) {
      const n = Number(t);
      return () => n;
    }
    if (/^T(IME)?#/i.test(t)) {
      const r = parseValueText('TIME', t);
      if (!r.ok) throw new ConditionError(`${t}: ${r.message}`);
      const n = Number(r.value);
      return () => n;
    }
    const i = indexOf(t);
    if (i === undefined) throw new ConditionError(`unknown variable "${t}" in the condition`);
    return (v) => {
      const x = v[i]!;
      return x === true ? 1 : x === false ? 0 : Number(x);
    };
  };

  const comparison = (): CompiledCondition => {
    const a = operand();
    const op = peek();
    if (op && ['=', '<>', '<', '>', '<=', '>='].includes(op)) {
      pos++;
      const b = operand();
      switch (op) {
        case '=':
          return (v) => a(v) === b(v);
        case '<>':
          return (v) => a(v) !== b(v);
        case '<':
          return (v) => a(v) < b(v);
        case '>':
          return (v) => a(v) > b(v);
        case '<=':
          return (v) => a(v) <= b(v);
        default:
          return (v) => a(v) >= b(v);
      }
    }
    return (v) => a(v) !== 0;
  };
  const unary = (): CompiledCondition => {
    if (peek() === 'NOT') {
      pos++;
      const x = unary();
      return (v) => !x(v);
    }
    return comparison();
  };
  const and = (): CompiledCondition => {
    let x = unary();
    while (peek() === 'AND' || peek() === '&') {
      pos++;
      const l = x;
      const r = unary();
      x = (v) => l(v) && r(v);
    }
    return x;
  };
  const xor = (): CompiledCondition => {
    let x = and();
    while (peek() === 'XOR') {
      pos++;
      const l = x;
      const r = and();
      x = (v) => l(v) !== r(v);
    }
    return x;
  };
  function or(): CompiledCondition {
    let x = xor();
    while (peek() === 'OR') {
      pos++;
      const l = x;
      const r = xor();
      x = (v) => l(v) || r(v);
    }
    return x;
  }
  const result = or();
  if (pos < tokens.length) throw new ConditionError(`unexpected "${tokens[pos]}" in the condition`);
  return result;
}
