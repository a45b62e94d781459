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

function withOffsets(
  text: string,
  tokens: readonly Token[],
  starts: readonly number[],
  base = 0,
): TextToken[] {
  const out: TextToken[] = [];
  for (const t of tokens) {
    if (t.kind === 'eof') break;
    const from = base + starts[t.pos.line - 1]! + t.pos.col - 1;
    // A pragma's text is what is inside its braces; `{{ }}` blocks have two braces each side.
    const to =
      t.kind === 'pragma' ? from + t.text.length + (text[from + 1] === '{' ? 4 : 2) : from + t.text.length;
    out.push({ kind: t.kind, text: t.text, upper: t.upper, pos: t.pos, from, to });
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

/**
 * The statement around `offset` (from the `;` before it to the one after it, comments and strings
 * skipped), read like readBody but in a fraction of the time on a long body: what completion,
 * hover and go to definition need. Token offsets are the whole text's; `open` is set when `offset`
 * is in a comment, string or pragma.
 */
export function readAround(text: string, offset: number): BodyText {
  let start = 0;
  let open: number | undefined;
  let i = 0;
  while (i < offset) {
    const c = text.charCodeAt(i);
    // Only ( / { ' " can start a comment, a pragma or a string.
    if (c === 40 || c === 47 || c === 123 || c === 39 || c === 34) {
      const e = skipAt(text, i);
      if (e >= 0) {
        if (e > offset) {
          open = i;
          break;
        }
        i = e;
        continue;
      }
    } else if (c === 59) start = i + 1;
    i++;
  }
  let end = offset;
  if (open === undefined)
    while (end < text.length) {
      const c = text.charCodeAt(end);
      if (c === 40 || c === 47 || c === 123 || c === 39 || c === 34) {
        const e = skipAt(text, end);
        if (e >= 0) {
          end = Math.min(e, text.length);
          continue;
        }
      }
      end++;
      if (c === 59) break;
    }
  const slice = text.slice(start, open ?? end);
  let tokens: TextToken[] = [];
  try {
    tokens = withOffsets(text, tokenize(slice), lineStartsOf(slice), start);
  } catch {
    tokens = [];
  }
  return { text, lineStarts: lineStartsOf(text), tokens, ...(open !== undefined ? { open } : {}) };
}

/**
 * The end of the comment, string or pragma starting at `at` (past the text's end when it is not
 * closed; a line comment counts its line break), or -1 when none starts there.
 */
function skipAt(text: string, at: number): number {
  const c = text[at];
  const d = text[at + 1];
  const after = (e: number, len: number) => (e < 0 ? text.length + 1 : e + len);
  if (c === '(' && d === '*') return after(text.indexOf('*)', at + 2), 2);
  if (c === '/' && d === '/') return after(text.indexOf('\n', at), 1);
  if (c === '{')
    return d === '{' ? after(text.indexOf('}}', at + 2), 2) : after(text.indexOf('}', at + 1), 1);
  if (c === "'" || c === '"') {
    let e = at + 1;
    while (e < text.length && text[e] !== c) e += text[e] === '$' ? 2 : 1;
    return e < text.length ? e + 1 : text.length + 1;
  }
  return -1;
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
    if (
      offset === t.from &&
      t.kind !== 'ident' &&
      i > 0 &&
      b.tokens[i - 1]!.to === offset &&
      b.tokens[i - 1]!.kind === 'ident'
    )
      return i - 1;
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
