// IEC 61131-3 Structured Text for CodeMirror 6: highlighting (keywords, types, literals such as
// T#5s, TIME#1h2m, 16#FF, INT#5, 1.5E3, strings, direct addresses %IX0.0, comments, pragmas),
// smart indentation (indent after IF/CASE/FOR/WHILE/REPEAT/VAR..., dedent END_*, ELSE, ELSIF,
// UNTIL as they are typed), folding of blocks and multi-line comments, and matching of a block's
// keywords (IF ... THEN ... ELSE ... END_IF) beside the brackets.
//
// Literals, strings and addresses are read by the engine's own scanners (engine/st/lexer.ts), so the
// editor colours a literal exactly as far as the compiler reads it. Classes: `cm-st-<kind>`
// (keyword, type, number, time, bool, string, comment, pragma, address, call, member, operator,
// invalid); colours in st.css, for the light and dark themes.
import { RangeSetBuilder, StateField, type EditorState, type Extension, type Text } from '@codemirror/state';
import { Decoration, EditorView, type DecorationSet } from '@codemirror/view';
import { foldService, StreamLanguage, syntaxHighlighting, type StreamParser } from '@codemirror/language';
import { Tag, tagHighlighter, tags } from '@lezer/highlight';
import {
  identEnd,
  locationEnd,
  numberEnd,
  stringEnd,
  symbolAt,
  typedLiteralEnd,
  ST_STATEMENT_WORDS,
} from '../../engine/st/lexer';
import { ELEMENTARY_TYPES } from '../../model/iecTypes';
import {
  blockAt,
  CLOSING_WORDS,
  OPENING_WORDS,
  stStructure,
  VAR_SECTIONS,
  type StStructure,
} from './stBlocks';

const CONTROL = new Set<string>([...ST_STATEMENT_WORDS, 'JMP']);
const DEFINITION = new Set([
  'PROGRAM',
  'END_PROGRAM',
  'FUNCTION',
  'END_FUNCTION',
  'FUNCTION_BLOCK',
  'END_FUNCTION_BLOCK',
  ...VAR_SECTIONS,
  'END_VAR',
  'TYPE',
  'END_TYPE',
  'STRUCT',
  'END_STRUCT',
  'ARRAY',
  'AT',
  'CONSTANT',
  'RETAIN',
  'NON_RETAIN',
  'PERSISTENT',
  'R_EDGE',
  'F_EDGE',
  'REF_TO',
  'POINTER',
  'REFERENCE',
  'ACTION',
  'END_ACTION',
  'METHOD',
  'END_METHOD',
  'EXTENDS',
  'IMPLEMENTS',
  'THIS',
  'SUPER',
]);
const OPERATOR_WORDS = new Set(['AND', 'OR', 'XOR', 'NOT', 'MOD', 'AND_THEN', 'OR_ELSE', 'REF']);
const TYPES = new Set<string>([
  ...ELEMENTARY_TYPES,
  'TIME_OF_DAY',
  'DATE_AND_TIME',
  'LTIME',
  'LDATE',
  'LTOD',
  'LDT',
  'LTIME_OF_DAY',
  'LDATE_AND_TIME',
  'CHAR',
  'WCHAR',
  'ANY',
  'ANY_DERIVED',
  'ANY_ELEMENTARY',
  'ANY_MAGNITUDE',
  'ANY_NUM',
  'ANY_REAL',
  'ANY_INT',
  'ANY_BIT',
  'ANY_STRING',
  'ANY_DATE',
]);
/** Type prefixes of duration and date literals: T#5s, TIME#1h2m, TOD#12:00:00, D#2024-01-01. */
const TIME_PREFIXES = new Set([
  'T',
  'TIME',
  'LT',
  'LTIME',
  'TOD',
  'TIME_OF_DAY',
  'LTOD',
  'D',
  'DATE',
  'LD',
  'LDATE',
  'DT',
  'DATE_AND_TIME',
  'LDT',
]);

/** Duration and date literals (a kind of number). */
export const timeLiteralTag = Tag.define(tags.number);
/** Direct addresses: %IX0.0, %QW3, %MD10. */
export const addressTag = Tag.define(tags.variableName);

/** Words after which the next line is indented, besides the block openers (ELSE, THEN, DO, OF...). */
const DEDENT = /^\s*([A-Za-z_][A-Za-z0-9_]*)/;
const dedents = (w: string): boolean =>
  CLOSING_WORDS.has(w) || w === 'ELSE' || w === 'ELSIF' || w === 'UNTIL';

interface StState {
  /** Inside a comment or pragma that spans lines: what closes it. */
  inside: '*)' | '}' | '}}' | null;
  /** Open blocks before the current position (the indentation level of the next line). */
  depth: number;
}

function skipTo(
  stream: { string: string; pos: number; skipToEnd(): void },
  state: StState,
  close: string,
): void {
  const end = stream.string.indexOf(close, stream.pos);
  if (end < 0) stream.skipToEnd();
  else {
    stream.pos = end + close.length;
    state.inside = null;
  }
}

const parser: StreamParser<StState> = {
  name: 'iec-st',
  startState: () => ({ inside: null, depth: 0 }),
  copyState: (s) => ({ inside: s.inside, depth: s.depth }),
  token(stream, state) {
    if (state.inside) {
      const close = state.inside;
      skipTo(stream, state, close);
      return close === '*)' ? 'blockComment' : 'meta';
    }
    if (stream.eatSpace()) return null;
    const text = stream.string;
    const i = stream.pos;
    const c = text[i]!;
    if (c === '(' && text[i + 1] === '*') {
      stream.pos += 2;
      state.inside = '*)';
      skipTo(stream, state, '*)');
      return 'blockComment';
    }
    if (c === '/' && text[i + 1] === '/') {
      stream.skipToEnd();
      return 'lineComment';
    }
    if (c === '{') {
      const close = text[i + 1] === '{' ? '}}' : '}';
      stream.pos += close.length;
      state.inside = close;
      skipTo(stream, state, close);
      return 'meta';
    }
    if (c === "'" || c === '"') {
      const end = stringEnd(text, i);
      if (end < 0) stream.skipToEnd();
      else stream.pos = end;
      return 'string';
    }
    if (c === '%') {
      stream.pos = locationEnd(text, i);
      return 'address';
    }
    if (c >= '0' && c <= '9') {
      stream.pos = Math.max(i + 1, numberEnd(text, i));
      return 'number';
    }
    if (/[A-Za-z_]/.test(c)) {
      const end = identEnd(text, i);
      const word = text.slice(i, end).toUpperCase();
      if (text[end] === '#') {
        stream.pos = typedLiteralEnd(text, end);
        return TIME_PREFIXES.has(word) ? 'timeLiteral' : word === 'BOOL' ? 'bool' : 'number';
      }
      stream.pos = end;
      if (i > 0 && text[i - 1] === '.') return 'propertyName';
      if (OPENING_WORDS.has(word)) state.depth++;
      else if (CLOSING_WORDS.has(word)) state.depth = Math.max(0, state.depth - 1);
      if (word === 'TRUE' || word === 'FALSE') return 'bool';
      if (CONTROL.has(word)) return 'controlKeyword';
      if (DEFINITION.has(word)) return 'definitionKeyword';
      if (OPERATOR_WORDS.has(word)) return 'operatorKeyword';
      if (TYPES.has(word)) return 'typeName';
      if (stream.match(/^\s*\(/, false)) return 'variableName.function';
      return 'variableName';
    }
    const sym = symbolAt(text, i);
    if (sym) {
      stream.pos += sym.length;
      if (sym === '(' || sym === ')') return 'paren';
      if (sym === '[' || sym === ']') return 'squareBracket';
      if (sym === ';' || sym === ',' || sym === '.' || sym === '..' || sym === ':') return 'punctuation';
      return 'operator';
    }
    stream.next();
    return 'invalid';
  },
  indent(state, textAfter, cx) {
    if (state.inside) return null;
    const w = DEDENT.exec(textAfter)?.[1]?.toUpperCase();
    return Math.max(0, state.depth - (w && dedents(w) ? 1 : 0)) * cx.unit;
  },
  languageData: {
    commentTokens: { line: '//', block: { open: '(*', close: '*)' } },
    indentOnInput: /^\s*(?:END_[A-Za-z_]*|ELSE|ELSIF|UNTIL)$/i,
    closeBrackets: { brackets: ['(', '[', "'", '"'] },
  },
  tokenTable: { timeLiteral: timeLiteralTag, address: addressTag },
};

/** The ST language (highlighting tokens and indentation). */
export const stStreamLanguage = StreamLanguage.define(parser);

/** `cm-st-*` classes for the highlighting tags (colours in st.css). */
export const stHighlighter = tagHighlighter([
  { tag: tags.keyword, class: 'cm-st-keyword' },
  { tag: tags.typeName, class: 'cm-st-type' },
  { tag: timeLiteralTag, class: 'cm-st-time' },
  { tag: tags.number, class: 'cm-st-number' },
  { tag: tags.bool, class: 'cm-st-bool' },
  { tag: tags.string, class: 'cm-st-string' },
  { tag: tags.comment, class: 'cm-st-comment' },
  { tag: tags.meta, class: 'cm-st-pragma' },
  { tag: addressTag, class: 'cm-st-address' },
  { tag: tags.function(tags.variableName), class: 'cm-st-call' },
  { tag: tags.propertyName, class: 'cm-st-member' },
  { tag: tags.variableName, class: 'cm-st-name' },
  { tag: tags.operator, class: 'cm-st-operator' },
  { tag: tags.invalid, class: 'cm-st-invalid' },
]);

// ---- block structure (keyword matching and folding) ----

const structures = new WeakMap<Text, StStructure>();

/** The block structure of the editor's text (computed once per document version). */
export function stStructureOf(state: EditorState): StStructure {
  let s = structures.get(state.doc);
  if (!s) {
    s = stStructure(state.doc.toString());
    structures.set(state.doc, s);
  }
  return s;
}

const matchMark = Decoration.mark({ class: 'cm-st-blockMatch' });
const noMatchMark = Decoration.mark({ class: 'cm-st-blockNoMatch' });

function keywordMatches(state: EditorState): DecorationSet {
  const head = state.selection.main;
  if (!head.empty) return Decoration.none;
  const s = stStructureOf(state);
  const hit = blockAt(s, head.head);
  const builder = new RangeSetBuilder<Decoration>();
  if (hit) {
    const { block } = hit;
    const mark = block.close ? matchMark : noMatchMark;
    for (const w of [block.open, ...block.middles, ...(block.close ? [block.close] : [])])
      builder.add(w.from, w.to, mark);
    return builder.finish();
  }
  const stray = s.stray.find((w) => head.head >= w.from && head.head <= w.to);
  if (stray) builder.add(stray.from, stray.to, noMatchMark);
  return builder.finish();
}

/** The keywords of the block at the cursor (IF, THEN, ELSIF, ELSE, END_IF...) marked together. */
const keywordMatching = StateField.define<DecorationSet>({
  create: keywordMatches,
  update: (deco, tr) => (tr.docChanged || tr.selection ? keywordMatches(tr.state) : deco),
  provide: (f) => EditorView.decorations.from(f),
});

/** The index of the first of `items` (sorted by `from`) starting at or after `pos`. */
function firstFrom<T>(items: readonly T[], from: (t: T) => number, pos: number): number {
  let lo = 0;
  let hi = items.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (from(items[mid]!) < pos) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

/** Folding: a block from the end of its opening line to the end of the line before its END_*; a multi-line comment. */
const stFolding = foldService.of((state, lineStart, lineEnd) => {
  const s = stStructureOf(state);
  for (let k = firstFrom(s.comments, (c) => c.from, lineStart); k < s.comments.length; k++) {
    const c = s.comments[k]!;
    if (c.from >= lineEnd) break;
    const last = state.doc.lineAt(c.to).number;
    if (last > state.doc.lineAt(lineStart).number) {
      const closes = state.sliceDoc(c.to - 2, c.to) === '*)' ? c.to - 2 : c.to;
      return { from: Math.min(lineEnd, c.from + 2), to: closes };
    }
  }
  for (let k = firstFrom(s.blocks, (b) => b.open.from, lineStart); k < s.blocks.length; k++) {
    const b = s.blocks[k]!;
    if (b.open.from >= lineEnd) break;
    if (!b.close) continue;
    const closeLine = state.doc.lineAt(b.close.from);
    if (closeLine.number <= state.doc.lineAt(lineStart).number + 1) continue;
    const to = state.doc.line(closeLine.number - 1).to;
    return { from: lineEnd, to };
  }
  return null;
});

/** Highlighting, indentation, keyword matching and folding of ST. */
export function stLanguage(): Extension {
  return [stStreamLanguage, syntaxHighlighting(stHighlighter), keywordMatching, stFolding];
}
