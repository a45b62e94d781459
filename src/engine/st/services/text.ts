// The text of an ST body as the language services read it: offsets <-> 1-based line/column, and
// the lexer's tokens (lexer.ts) with their offsets. Text being typed is often unfinished: a comment
// or string left open stops the lexer, so the tokens are then those before it (`open` says where).
import { StSyntaxError } from '../ast';
import { tokenize, type Token } from '../lexer';

export interface TextToken extends Token {
  /** Offset of its first character and just past its last. */
  readonly from: number;
  readonly to: number;
}

export interface BodyText {
  readonly text: string;
  /** Offsets where each line starts (line n at lineStarts[n - 1]). */
  readonly lineStarts: readonly number[];
  /** Tokens in order, without the end-of-text token. */
  readonly tokens: readonly TextToken[];
  /** Where an unclosed comment, string or pragma starts (the tokens stop there); else undefined. */
  readonly open?: number;
}

/** Offsets where lines start. */
export function lineStartsOf(text: string): number[] {
  const out = [0];
  for (let i = text.indexOf('\n'); i >= 0; i = text.indexOf('\n', i + 1)) out.push(i + 1);
  return out;
}

/** The offset of a 1-based line and column (clamped to the text). */
export function offsetOf(b: Pick<BodyText, 'text' | 'lineStarts'>, line: number, col: number): number {
  const start = b.lineStarts[Math.max(0, Math.min(line - 1, b.lineStarts.length - 1))]!;
  return Math.min(b.text.length, start + Math.max(0, col - 1));
}

/** The 1-based line and column of an offset. */
export function positionOf(b: Pick<BodyText, 'lineStarts'>, offset: number): { line: number; col: number } {
  let lo = 0;
  let hi = b.lineStarts.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (b.lineStarts[mid]! <= offset) lo = mid;
    else hi = mid - 1;
  }
  return { line: lo + 1, col: offset - b.lineStarts[lo]! + 1 };
}

function withOffsets(text: string, tokens: readonly Token[], starts: readonly number[]): TextToken[] {
  const out: TextToken[] = [];
  for (const t of tokens) {
    if (t.kind === 'eof') break;
    const from = starts[t.pos.line - 1]! + t.pos.col - 1;
    // A pragma's text is what is inside its braces; `{{ }}` blocks have two braces each side.
    const to = t.kind === 'pragma' ? from + t.text.length + (text[from + 1] === '{' ? 4 : 2) : from + t.text.length;
    out.push({ ...t, from, to });
  }
  return out;
}

let last: BodyText | undefined;

/** The body's lines and tokens (the last text read is kept: services asked in turn share it). */
export function readBody(text: string): BodyText {
  if (last?.text === text) return last;
  const lineStarts = lineStartsOf(text);
  let tokens: TextToken[];
  let open: number | undefined;
  try {
    tokens = withOffsets(text, tokenize(text), lineStarts);
  } catch (e) {
    if (!(e instanceof StSyntaxError)) throw e;
    open = offsetOf({ text, lineStarts }, e.pos.line, e.pos.col);
    try {
      tokens = withOffsets(text, tokenize(text.slice(0, open)), lineStarts);
    } catch {
      tokens = [];
    }
  }
  last = { text, lineStarts, tokens, ...(open !== undefined ? { open } : {}) };
  return last;
}

/** Index of the last token starting before `offset` (-1 when none). */
export function tokenBefore(b: BodyText, offset: number): number {
  let lo = 0;
  let hi = b.tokens.length - 1;
  let found = -1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    if (b.tokens[mid]!.from < offset) {
      found = mid;
      lo = mid + 1;
    } else hi = mid - 1;
  }
  return found;
}

/** Index of the token covering `offset` (touching its end counts), preferring an identifier. */
export function tokenAt(b: BodyText, offset: number): number {
  const i = tokenBefore(b, offset + 1);
  if (i < 0) return -1;
  const t = b.tokens[i]!;
  if (offset >= t.from && offset < t.to) {
    // The cursor just after an identifier and before a symbol: the identifier.
    if (offset === t.from && t.kind !== 'ident' && i > 0 && b.tokens[i - 1]!.to === offset && b.tokens[i - 1]!.kind === 'ident') return i - 1;
    return i;
  }
  if (offset === t.to) return i;
  return -1;
}

/** True when `offset` is inside a comment, a string or a pragma (no completion or hover there). */
export function inCommentOrString(b: BodyText, offset: number): boolean {
  if (b.open !== undefined && offset > b.open) return true;
  const i = tokenBefore(b, offset);
  const prev = i >= 0 ? b.tokens[i]! : undefined;
  if (prev && offset < prev.to && (prev.kind === 'string' || prev.kind === 'pragma')) return true;
  // Between tokens: a comment opened there and not closed before the offset.
  const gap = b.text.slice(prev ? prev.to : 0, offset);
  const block = gap.lastIndexOf('(*');
  if (block >= 0 && gap.indexOf('*)', block + 2) < 0) return true;
  const lineStart = gap.lastIndexOf('\n');
  return gap.indexOf('//', lineStart + 1) >= 0;
}

/** Same name, as IEC compares identifiers. */
export const sameName = (a: string, b: string): boolean => a.toUpperCase() === b.toUpperCase();
