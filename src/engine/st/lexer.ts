// Tokens of Structured Text: identifiers and keywords (case-insensitive), literals in their IEC
// forms (42, 1_000, 16#FF, 2#1010, 1.5E3, INT#5, INT#16#FF, T#1s500ms, TIME#-2s, BOOL#TRUE),
// locations (%IX0.0), operators; comments `(* *)` and `//` are skipped, pragmas `{ }` kept.
import { StSyntaxError, type Pos } from './ast';

export type TokenKind = 'ident' | 'literal' | 'location' | 'symbol' | 'pragma' | 'string' | 'eof';

export interface Token {
  readonly kind: TokenKind;
  /** Text as written; identifiers and symbols are compared upper-cased through `upper`. */
  readonly text: string;
  readonly upper: string;
  readonly pos: Pos;
}

/** The operator and punctuation symbols, longest first where one starts another. */
export const SYMBOLS: readonly string[] = [
  '**',
  ':=',
  '=>',
  '<=',
  '>=',
  '<>',
  '..',
  '+',
  '-',
  '*',
  '/',
  '=',
  '<',
  '>',
  '(',
  ')',
  ',',
  ';',
  ':',
  '.',
  '&',
  '[',
  ']',
  '^',
  '#',
];

/** A letter or `_` (by character code: the lexer runs on every keystroke in the ST editor). */
export const isIdentStartCode = (k: number): boolean =>
  (k >= 65 && k <= 90) || (k >= 97 && k <= 122) || k === 95;
const isIdentCode = (k: number): boolean => isIdentStartCode(k) || (k >= 48 && k <= 57);
const isIdentStart = (c: string): boolean => isIdentStartCode(c.charCodeAt(0));
const isIdentChar = (c: string): boolean => isIdentCode(c.charCodeAt(0));
const isDigit = (c: string): boolean => c >= '0' && c <= '9';

// The scanners below give the end (exclusive) of one token starting at `i`; the lexer and the
// editor's highlighter (src/editor/st/stLanguage.ts) share them, so both read literals alike.

/** End of the identifier at `i` (its first character is a letter or `_`). */
export function identEnd(text: string, i: number): number {
  let end = i;
  while (end < text.length && isIdentCode(text.charCodeAt(end))) end++;
  return end;
}

/** End of the number at `i` (a digit): 42, 1_000, 16#FF, 2#1010, 1.5, 1.5E3, 2E-3. */
export function numberEnd(text: string, i: number): number {
  let end = i;
  while (end < text.length && (isDigit(text[end]!) || text[end] === '_')) end++;
  if (text[end] === '#') {
    // based integer 16#FF
    end++;
    while (end < text.length && /[0-9A-Fa-f_]/.test(text[end]!)) end++;
    return end;
  }
  if (text[end] === '.' && isDigit(text[end + 1] ?? '')) {
    end++;
    while (end < text.length && (isDigit(text[end]!) || text[end] === '_')) end++;
  }
  if (
    /[eE]/.test(text[end] ?? '') &&
    (isDigit(text[end + 1] ?? '') || (/[+-]/.test(text[end + 1] ?? '') && isDigit(text[end + 2] ?? '')))
  ) {
    end += 2;
    while (end < text.length && isDigit(text[end]!)) end++;
  }
  return end;
}

/**
 * End of the typed literal whose type name ends at `hash` (`text[hash] === '#'`): INT#5, INT#-5,
 * INT#16#FF, T#1h2m, TIME#-2s, REAL#1.5E-3, BOOL#TRUE.
 */
export function typedLiteralEnd(text: string, hash: number): number {
  let end = hash + 1;
  if (text[end] === '+' || text[end] === '-') end++;
  while (end < text.length) {
    const d = text[end]!;
    if (isIdentChar(d) || d === '#') end++;
    else if (d === '.' && isDigit(text[end + 1] ?? '')) end++;
    else if (
      (d === '+' || d === '-') &&
      /[eE]/.test(text[end - 1]!) &&
      isDigit(text[end - 2] ?? '') &&
      isDigit(text[end + 1] ?? '')
    )
      end++;
    else break;
  }
  return end;
}

/** End of the direct address at `i` (`%`): %IX0.0, %QW3, %MD10. */
export function locationEnd(text: string, i: number): number {
  let end = i + 1;
  while (end < text.length && /[A-Za-z0-9_.*]/.test(text[end]!)) end++;
  return end;
}

/**
 * End (after the closing quote) of the string at `i` (`'` or `"`), or -1 when it is never
 * closed. `$` escapes the next character (`$'`, `$$`, `$L`, `$0A`).
 */
export function stringEnd(text: string, i: number): number {
  const q = text[i];
  let end = i + 1;
  while (end < text.length && text[end] !== q) end += text[end] === '$' ? 2 : 1;
  return end >= text.length ? -1 : end + 1;
}

/** The symbol at `i`, or undefined. */
export const symbolAt = (text: string, i: number): string | undefined =>
  SYMBOLS.find((s) => text.startsWith(s, i));

export function tokenize(text: string): Token[] {
  const out: Token[] = [];
  let i = 0;
  let line = 1;
  let lineStart = 0;
  const pos = (at: number): Pos => ({ line, col: at - lineStart + 1 });
  const advanceTo = (end: number): void => {
    for (let k = i; k < end; k++)
      if (text[k] === '\n') {
        line++;
        lineStart = k + 1;
      }
    i = end;
  };
  const push = (kind: TokenKind, start: number, end: number, at: Pos): void => {
    const t = text.slice(start, end);
    out.push({ kind, text: t, upper: t.toUpperCase(), pos: at });
  };
  while (i < text.length) {
    const c = text[i]!;
    if (c === ' ' || c === '\t' || c === '\r' || c === '\n' || c === '\f' || c === '\v') {
      advanceTo(i + 1);
      continue;
    }
    const at = pos(i);
    if (c === '(' && text[i + 1] === '*') {
      const end = text.indexOf('*)', i + 2);
      if (end < 0) throw new StSyntaxError(at, 'this comment "(*" is never closed with "*)"');
      advanceTo(end + 2);
      continue;
    }
    if (c === '/' && text[i + 1] === '/') {
      const end = text.indexOf('\n', i);
      advanceTo(end < 0 ? text.length : end);
      continue;
    }
    if (c === '{' && text[i + 1] === '{') {
      // MATIEC's C code block `{{ ... }}` (braces of C inside): ends at the first "}}".
      const end = text.indexOf('}}', i + 2);
      if (end < 0) throw new StSyntaxError(at, 'this C code block "{{" is never closed with "}}"');
      push('pragma', i + 2, end, at);
      advanceTo(end + 2);
      continue;
    }
    if (c === '{') {
      const end = text.indexOf('}', i + 1);
      if (end < 0) throw new StSyntaxError(at, 'this pragma "{" is never closed with "}"');
      push('pragma', i + 1, end, at);
      advanceTo(end + 1);
      continue;
    }
    if (c === "'" || c === '"') {
      // The string ends at the first unescaped quote of its kind; the literal's value is read by
      // parseStringLiteral.
      const end = stringEnd(text, i);
      if (end < 0) throw new StSyntaxError(at, 'this string is never closed');
      push('string', i, end, at);
      advanceTo(end);
      continue;
    }
    if (c === '%') {
      const end = locationEnd(text, i);
      push('location', i, end, at);
      advanceTo(end);
      continue;
    }
    if (isDigit(c)) {
      const end = numberEnd(text, i);
      push('literal', i, end, at);
      advanceTo(end);
      continue;
    }
    if (isIdentStart(c)) {
      let end = identEnd(text, i);
      if (text[end] === '#') {
        end = typedLiteralEnd(text, end);
        push('literal', i, end, at);
        advanceTo(end);
        continue;
      }
      push('ident', i, end, at);
      advanceTo(end);
      continue;
    }
    const sym = symbolAt(text, i);
    if (!sym) throw new StSyntaxError(at, `unexpected character "${c}"`);
    push('symbol', i, i + sym.length, at);
    advanceTo(i + sym.length);
  }
  out.push({ kind: 'eof', text: '', upper: '', pos: pos(i) });
  return out;
}

/** ST's statement words (IEC 61131-3, 3.3.2). */
export const ST_STATEMENT_WORDS = [
  'IF',
  'THEN',
  'ELSIF',
  'ELSE',
  'END_IF',
  'CASE',
  'OF',
  'END_CASE',
  'FOR',
  'TO',
  'BY',
  'DO',
  'END_FOR',
  'WHILE',
  'END_WHILE',
  'REPEAT',
  'UNTIL',
  'END_REPEAT',
  'EXIT',
  'CONTINUE',
  'RETURN',
] as const;
/** Operators and Boolean literals written as words. */
export const ST_OPERATOR_WORDS = ['AND', 'OR', 'XOR', 'NOT', 'MOD', 'TRUE', 'FALSE'] as const;
/** Words of declarations and program organisation units. */
export const IEC_DECLARATION_WORDS = [
  'VAR',
  'VAR_INPUT',
  'VAR_OUTPUT',
  'VAR_IN_OUT',
  'VAR_TEMP',
  'VAR_EXTERNAL',
  'VAR_GLOBAL',
  'END_VAR',
  'CONSTANT',
  'RETAIN',
  'NON_RETAIN',
  'AT',
  'PROGRAM',
  'END_PROGRAM',
  'FUNCTION',
  'END_FUNCTION',
  'FUNCTION_BLOCK',
  'END_FUNCTION_BLOCK',
  'TYPE',
  'END_TYPE',
  'STRUCT',
  'END_STRUCT',
  'ARRAY',
  'STRING',
  'WSTRING',
] as const;
