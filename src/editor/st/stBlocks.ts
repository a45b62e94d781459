// The block structure of an ST text for the editor: which keyword opens a block (IF, CASE, FOR,
// WHILE, REPEAT, VAR..., STRUCT...), its middle keywords (THEN, ELSIF, ELSE, OF, DO, UNTIL...) and
// the END_* that closes it, and where the multi-line comments are. Read tolerantly (an unclosed
// comment or string runs to the end, a stray END_* is kept as unmatched) so it works on text being
// typed. Used by keyword matching and folding (stLanguage.ts). Pure: no DOM, no CodeMirror.
import {
  identEnd,
  isIdentStartCode,
  locationEnd,
  numberEnd,
  stringEnd,
  typedLiteralEnd,
} from '../../engine/st/lexer';

export interface Word {
  readonly from: number;
  readonly to: number;
  /** Upper-cased. */
  readonly word: string;
}

export interface Block {
  readonly open: Word;
  /** THEN, ELSIF, ELSE, OF, DO, TO, BY, UNTIL of this block (not of blocks nested in it). */
  readonly middles: readonly Word[];
  /** Undefined while the block is not closed. */
  readonly close?: Word;
}

export interface StStructure {
  /** Every block, in the order of their opening keywords. */
  readonly blocks: readonly Block[];
  /** END_* (and middle) keywords that belong to no open block. */
  readonly stray: readonly Word[];
  /** `(* ... *)` comments and `{ ... }` pragmas: from the opening to after the closing (or the end). */
  readonly comments: readonly { readonly from: number; readonly to: number }[];
}

/** The keywords that open a section of variables (closed by END_VAR). */
export const VAR_SECTIONS: readonly string[] = [
  'VAR',
  'VAR_INPUT',
  'VAR_OUTPUT',
  'VAR_IN_OUT',
  'VAR_GLOBAL',
  'VAR_EXTERNAL',
  'VAR_TEMP',
  'VAR_ACCESS',
  'VAR_CONFIG',
  'VAR_STAT',
  'VAR_INST',
];

/** The keyword that opens a block, by the END_* that closes it. */
const CLOSERS: Readonly<Record<string, readonly string[]>> = {
  END_IF: ['IF'],
  END_CASE: ['CASE'],
  END_FOR: ['FOR'],
  END_WHILE: ['WHILE'],
  END_REPEAT: ['REPEAT'],
  END_VAR: VAR_SECTIONS,
  END_STRUCT: ['STRUCT'],
  END_TYPE: ['TYPE'],
  END_PROGRAM: ['PROGRAM'],
  END_FUNCTION_BLOCK: ['FUNCTION_BLOCK'],
  END_FUNCTION: ['FUNCTION'],
};

const OPENERS = new Set(Object.values(CLOSERS).flat());

/** Middle keywords, by the opening keyword of the block they belong to. */
const MIDDLES: Readonly<Record<string, readonly string[]>> = {
  IF: ['THEN', 'ELSIF', 'ELSE'],
  CASE: ['OF', 'ELSE'],
  FOR: ['TO', 'BY', 'DO'],
  WHILE: ['DO'],
  REPEAT: ['UNTIL'],
};

/** Opening keywords that begin an indented block (the ones statements and declarations nest in). */
export const OPENING_WORDS: ReadonlySet<string> = OPENERS;
export const CLOSING_WORDS: ReadonlySet<string> = new Set(Object.keys(CLOSERS));

interface Open {
  readonly open: Word;
  readonly middles: Word[];
}

/** Reads the structure of `text` (see StStructure). */
export function stStructure(text: string): StStructure {
  const blocks: Block[] = [];
  const stray: Word[] = [];
  const comments: { from: number; to: number }[] = [];
  const stack: { open: Open; index: number }[] = [];
  let i = 0;
  const n = text.length;
  while (i < n) {
    const code = text.charCodeAt(i);
    // Spaces, operators and punctuation: nothing to read (the common case, by character code).
    if (
      code <= 32 ||
      code === 59 ||
      code === 58 ||
      code === 61 ||
      code === 44 ||
      code === 41 ||
      code === 43 ||
      code === 45 ||
      code === 62 ||
      code === 60
    ) {
      i++;
      continue;
    }
    const c = text[i]!;
    if (c === '(' && text[i + 1] === '*') {
      const end = text.indexOf('*)', i + 2);
      const to = end < 0 ? n : end + 2;
      comments.push({ from: i, to });
      i = to;
      continue;
    }
    if (c === '/' && text[i + 1] === '/') {
      const end = text.indexOf('\n', i);
      i = end < 0 ? n : end;
      continue;
    }
    if (c === '{') {
      const close = text[i + 1] === '{' ? '}}' : '}';
      const end = text.indexOf(close, i + close.length);
      const to = end < 0 ? n : end + close.length;
      comments.push({ from: i, to });
      i = to;
      continue;
    }
    if (c === "'" || c === '"') {
      const end = stringEnd(text, i);
      // An unclosed string runs to the end of its line (the user is typing it).
      if (end < 0) {
        const nl = text.indexOf('\n', i);
        i = nl < 0 ? n : nl;
      } else i = end;
      continue;
    }
    if (c === '%') {
      i = locationEnd(text, i);
      continue;
    }
    if (c >= '0' && c <= '9') {
      i = Math.max(i + 1, numberEnd(text, i));
      continue;
    }
    if (isIdentStartCode(code)) {
      const end = identEnd(text, i);
      if (text[end] === '#') {
        i = typedLiteralEnd(text, end);
        continue;
      }
      // A member after a dot (`Cfg.Type`) is a name, never a keyword.
      const member = i > 0 && text[i - 1] === '.';
      const word = text.slice(i, end).toUpperCase();
      i = end;
      if (member) continue;
      const at: Word = { from: end - word.length, to: end, word };
      if (OPENERS.has(word)) {
        const open: Open = { open: at, middles: [] };
        stack.push({ open, index: blocks.length });
        blocks.push({ open: at, middles: open.middles });
        continue;
      }
      const openers = CLOSERS[word];
      if (openers) {
        // Close the innermost block this END_* belongs to; blocks left open inside it stay unclosed.
        let k = stack.length - 1;
        while (k >= 0 && !openers.includes(stack[k]!.open.open.word)) k--;
        if (k < 0) {
          stray.push(at);
          continue;
        }
        const { open, index } = stack[k]!;
        blocks[index] = { open: open.open, middles: open.middles, close: at };
        stack.length = k;
        continue;
      }
      const top = stack[stack.length - 1];
      const middles = top ? MIDDLES[top.open.open.word] : undefined;
      if (middles?.includes(word)) {
        // OF belongs to CASE only once (CASE x OF); the ARRAY [..] OF of a declaration is no middle.
        if (!(word === 'OF' && top!.open.middles.some((m) => m.word === 'OF'))) top!.open.middles.push(at);
      } else if (word === 'THEN' || word === 'ELSIF' || word === 'ELSE' || word === 'UNTIL') stray.push(at);
      continue;
    }
    i++;
  }
  return { blocks, stray, comments };
}

/**
 * The block whose opening, middle or closing keyword covers `pos` (innermost first), and that
 * keyword; undefined when `pos` is on no block keyword.
 */
export function blockAt(s: StStructure, pos: number): { block: Block; word: Word } | undefined {
  const on = (w: Word | undefined) => w && pos >= w.from && pos <= w.to;
  for (let k = s.blocks.length - 1; k >= 0; k--) {
    const b = s.blocks[k]!;
    if (b.open.from > pos) continue;
    if (on(b.open)) return { block: b, word: b.open };
    if (on(b.close)) return { block: b, word: b.close! };
    const m = b.middles.find(on);
    if (m) return { block: b, word: m };
  }
  return undefined;
}
