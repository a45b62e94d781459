// Declarations as IEC 61131-3 text: a POU's variables (VAR_INPUT … END_VAR, VAR_OUTPUT, VAR_IN_OUT,
// VAR, VAR_TEMP, VAR_EXTERNAL) or the project's globals (VAR_GLOBAL), with CONSTANT/RETAIN,
// `Start AT %IX0.0 : BOOL := FALSE; (* comment *)`, FB instances `T1 : TON;`, and types and initial
// values as the model keeps them (text: STRING[20], ARRAY[1..8] OF INT, STRUCT … END_STRUCT,
// [32(0), 30(1)], (X := 1, Y := 2)). The text view of the variables panel prints and parses it.
//
// The tokens are the ST front end's (lexer.ts), so literals, locations and strings read exactly as
// in an ST body; this module lives beside it because src/model may not import the engine. What it
// checks is syntax only: whether a type exists or an initial value fits it is the variable table's
// and the engine's check (LD-E10..E16), which run on the result as on any table edit.
//
// Round trip: parsing the printed text of a list gives the same list (comments trimmed). Comments
// `(* … *)` and `//` inside a declaration, after it on the line of its `;`, or on the lines just
// above it become its comment; others belong to no variable and are reported (warning), not kept.
import type { Variable, VarClass } from '../../model/project';
import { StSyntaxError } from './ast';
import { tokenize, type Token } from './lexer';

/** Which list the text declares: a POU's variables or the project's globals. */
export type DeclarationSection = 'pou' | 'globals';

/** The rule id of a declaration text that does not parse (docs/ENGINE.md). */
export const DECLARATION_SYNTAX_RULE = 'LD-E18';

export interface DeclarationProblem {
  readonly severity: 'error' | 'warning';
  /** 1-based line and column in the text. */
  readonly line: number;
  readonly col: number;
  readonly message: string;
}

export interface ParsedDeclaration {
  readonly variable: Variable;
  /** Where its name is written (1-based). */
  readonly line: number;
  readonly col: number;
}

export interface DeclarationParse {
  /** True when the text has no syntax error (warnings allowed): `variables` is then what it declares. */
  readonly ok: boolean;
  readonly declarations: readonly ParsedDeclaration[];
  readonly variables: readonly Variable[];
  readonly problems: readonly DeclarationProblem[];
}

const CLASS_KEYWORD: Record<VarClass, string> = {
  input: 'VAR_INPUT',
  output: 'VAR_OUTPUT',
  inOut: 'VAR_IN_OUT',
  local: 'VAR',
  temp: 'VAR_TEMP',
  external: 'VAR_EXTERNAL',
};
const POU_HEADERS: Record<string, VarClass> = {
  VAR_INPUT: 'input',
  VAR_OUTPUT: 'output',
  VAR_IN_OUT: 'inOut',
  VAR: 'local',
  VAR_TEMP: 'temp',
  VAR_EXTERNAL: 'external',
};
const HEADERS = new Set([...Object.keys(POU_HEADERS), 'VAR_GLOBAL', 'VAR_ACCESS', 'VAR_CONFIG']);
const QUALIFIERS = new Set(['CONSTANT', 'RETAIN', 'NON_RETAIN', 'PERSISTENT']);
/** Words that end or open a block: a name or type running into them misses its `;` or END_VAR. */
const STRUCTURE = new Set([...HEADERS, 'END_VAR', 'AT']);

// ---------------------------------------------------------------------------------------------
// Printing

/** A comment as IEC text: `(* … *)`, or `// …` when the text holds `*)` on one line. */
function commentText(comment: string): string {
  const c = comment.trim();
  if (!c.includes('*)')) return `(* ${c} *)`;
  if (!c.includes('\n')) return `// ${c}`;
  return `(* ${c.replaceAll('*)', '* )')} *)`;
}

/** One declaration line, without indentation: `Start AT %IX0.0 : BOOL := FALSE; (* comment *)`. */
export function declarationLine(v: Variable): string {
  const at = v.location?.trim() ? ` AT ${v.location.trim()}` : '';
  const init = v.initial?.trim() ? ` := ${v.initial.trim()}` : '';
  const comment = v.comment.trim() ? ` ${commentText(v.comment)}` : '';
  return `${v.name}${at} : ${v.type.trim()}${init};${comment}`;
}

const blockKey = (v: Variable, section: DeclarationSection) =>
  `${section === 'globals' ? 'VAR_GLOBAL' : CLASS_KEYWORD[v.varClass]}${v.constant ? ' CONSTANT' : ''}${v.retain ? ' RETAIN' : ''}`;

/**
 * The list as IEC text, in its order: consecutive variables of one class and qualifiers share a
 * block. An empty list prints an empty VAR (VAR_GLOBAL) block to type into.
 */
export function printDeclarations(vars: readonly Variable[], section: DeclarationSection): string {
  if (vars.length === 0) return section === 'globals' ? 'VAR_GLOBAL\nEND_VAR\n' : 'VAR\nEND_VAR\n';
  const blocks: string[] = [];
  let open: string | undefined;
  let lines: string[] = [];
  for (const v of vars) {
    const key = blockKey(v, section);
    if (key !== open) {
      if (open !== undefined) blocks.push([open, ...lines, 'END_VAR'].join('\n'));
      open = key;
      lines = [];
    }
    lines.push(`\t${declarationLine(v)}`);
  }
  if (open !== undefined) blocks.push([open, ...lines, 'END_VAR'].join('\n'));
  return `${blocks.join('\n\n')}\n`;
}

// ---------------------------------------------------------------------------------------------
// Parsing

interface Comment {
  readonly start: number;
  readonly line: number;
  readonly text: string;
}

/** Offsets of each line's first character. */
function lineStarts(text: string): number[] {
  const out = [0];
  for (let i = 0; i < text.length; i++) if (text[i] === '\n') out.push(i + 1);
  return out;
}

/** The comments in a stretch of text between two tokens (only whitespace and comments there). */
function commentsIn(gap: string, base: number, lineOf: (offset: number) => number, into: Comment[]): void {
  let i = 0;
  while (i < gap.length) {
    if (gap.startsWith('(*', i)) {
      const end = gap.indexOf('*)', i + 2);
      const stop = end < 0 ? gap.length : end;
      into.push({ start: base + i, line: lineOf(base + i), text: gap.slice(i + 2, stop).trim() });
      i = stop + 2;
    } else if (gap.startsWith('//', i)) {
      const end = gap.indexOf('\n', i);
      const stop = end < 0 ? gap.length : end;
      into.push({ start: base + i, line: lineOf(base + i), text: gap.slice(i + 2, stop).trim() });
      i = stop;
    } else i++;
  }
}

interface Tok extends Token {
  readonly start: number;
  readonly end: number;
}

/** Parses declaration text. Never throws: problems are located (line, column) in `problems`. */
export function parseDeclarations(text: string, section: DeclarationSection): DeclarationParse {
  const problems: DeclarationProblem[] = [];
  const error = (line: number, col: number, message: string) =>
    problems.push({ severity: 'error', line, col, message });
  const warn = (line: number, col: number, message: string) =>
    problems.push({ severity: 'warning', line, col, message });
  let raw: Token[];
  try {
    raw = tokenize(text);
  } catch (e) {
    if (!(e instanceof StSyntaxError)) throw e;
    error(e.pos.line, e.pos.col, e.detail);
    return { ok: false, declarations: [], variables: [], problems };
  }
  const starts = lineStarts(text);
  const lineOf = (offset: number) => {
    let lo = 0;
    let hi = starts.length - 1;
    while (lo < hi) {
      const mid = (lo + hi + 1) >> 1;
      if (starts[mid]! <= offset) lo = mid;
      else hi = mid - 1;
    }
    return lo + 1;
  };
  const all: Tok[] = raw.map((t) => {
    const start = starts[t.pos.line - 1]! + t.pos.col - 1;
    return { kind: t.kind, text: t.text, upper: t.upper, pos: t.pos, start, end: start + t.text.length };
  });
  const comments: Comment[] = [];
  let prevEnd = 0;
  for (const t of all) {
    commentsIn(text.slice(prevEnd, t.start), prevEnd, lineOf, comments);
    prevEnd = t.kind === 'pragma' ? t.end + (text.startsWith('{{', t.start) ? 2 : 1) : t.end;
  }
  const toks = all.filter((t) => {
    if (t.kind !== 'pragma') return true;
    warn(t.pos.line, t.pos.col, `the pragma {${t.text.trim()}} is not kept: Rungsmith declarations have no attributes`);
    return false;
  });

  interface Decl {
    names: Tok[];
    location?: string;
    type: string;
    initial?: string;
    varClass: VarClass;
    retain: boolean;
    constant: boolean;
    first: number;
    semi: Tok;
  }
  const decls: Decl[] = [];
  /** Token ends of block headers (with qualifiers): comments on their line belong to no variable. */
  const headerLines = new Set<number>();
  let i = 0;
  const peek = () => toks[i]!;
  const at = (t: Token) => `line ${t.pos.line}, column ${t.pos.col}`;
  const word = (t: Token) => (t.kind === 'eof' ? 'the end of the text' : `"${t.text}"`);
  /** Joins tokens as written, one space where the text had whitespace or a comment. */
  const joined = (from: number, to: number) => {
    let s = '';
    for (let k = from; k < to; k++) {
      if (k > from && toks[k]!.start > toks[k - 1]!.end) s += ' ';
      s += toks[k]!.text;
    }
    return s;
  };
  /** Skips to after the next `;` or to END_VAR / a header / the end (error recovery). */
  const recover = () => {
    while (peek().kind !== 'eof') {
      const t = peek();
      if (t.kind === 'symbol' && t.text === ';') {
        i++;
        return;
      }
      if (t.kind === 'ident' && (t.upper === 'END_VAR' || HEADERS.has(t.upper))) return;
      i++;
    }
  };
  /**
   * A ":" outside brackets ends the next declaration's names: the ";" before them is missing.
   * Backs up to those names and reports it right after the token before them; parsing goes on there.
   */
  const missingSemicolon = (from: number, name: string): number | undefined => {
    const colon = toks[i]!;
    if (colon.kind !== 'symbol' || colon.text !== ':') return undefined;
    let j = i - 1;
    while (j - 2 >= from && toks[j - 1]!.text === ',' && toks[j - 2]!.kind === 'ident') j -= 2;
    if (j <= from || toks[j]!.kind !== 'ident') return undefined;
    const last = toks[j - 1]!;
    const line = lineOf(last.end);
    error(line, last.end - starts[line - 1]! + 1, `";" missing at the end of the declaration of ${name} (the next declaration, ${toks[j]!.text}, starts at ${at(toks[j]!)})`);
    i = j;
    return j;
  };
  /** Tokens of a type or an initial value: up to a `;` or `:=` outside brackets and STRUCT … END_STRUCT. */
  const scanUntil = (stops: readonly string[]): { from: number; to: number; stop: Tok } => {
    const from = i;
    let depth = 0;
    while (true) {
      const t = peek();
      if (t.kind === 'eof') return { from, to: i, stop: t };
      if (t.kind === 'symbol') {
        if (t.text === '(' || t.text === '[') depth++;
        else if (t.text === ')' || t.text === ']') depth = Math.max(0, depth - 1);
        else if (depth === 0 && (stops.includes(t.text) || t.text === ':')) return { from, to: i, stop: t };
      } else if (t.kind === 'ident') {
        if (t.upper === 'STRUCT') depth++;
        else if (t.upper === 'END_STRUCT') depth = Math.max(0, depth - 1);
        else if (depth === 0 && STRUCTURE.has(t.upper)) return { from, to: i, stop: t };
      }
      i++;
    }
  };

  const parseDecl = (varClass: VarClass, retain: boolean, constant: boolean): void => {
    const first = peek();
    const names: Tok[] = [];
    while (true) {
      const t = peek();
      if (t.kind !== 'ident' || STRUCTURE.has(t.upper) || QUALIFIERS.has(t.upper)) {
        error(t.pos.line, t.pos.col, `expected a variable name, found ${word(t)}`);
        return recover();
      }
      names.push(t);
      i++;
      if (peek().kind === 'symbol' && peek().text === ',') {
        i++;
        continue;
      }
      break;
    }
    let location: string | undefined;
    if (peek().kind === 'ident' && peek().upper === 'AT') {
      const atTok = peek();
      i++;
      const loc = peek();
      if (loc.kind !== 'location') {
        error(loc.pos.line, loc.pos.col, `AT needs an address such as %IX0.0, %QW1 or %MW10, found ${word(loc)}`);
        return recover();
      }
      if (names.length > 1) {
        error(atTok.pos.line, atTok.pos.col, `${names.map((n) => n.text).join(', ')} cannot share one address: declare them one by one`);
        return recover();
      }
      location = loc.text;
      i++;
    }
    const colon = peek();
    if (colon.kind !== 'symbol' || colon.text !== ':') {
      error(colon.pos.line, colon.pos.col, `expected ":" and a type after ${names[names.length - 1]!.text}, found ${word(colon)}`);
      return recover();
    }
    i++;
    const typeToks = scanUntil([';', ':=']);
    if (typeToks.to === typeToks.from) {
      error(typeToks.stop.pos.line, typeToks.stop.pos.col, `${names[0]!.text} needs a type after ":", found ${word(typeToks.stop)}`);
      return recover();
    }
    if (missingSemicolon(typeToks.from, names[0]!.text) !== undefined) return;
    let initial: string | undefined;
    if (typeToks.stop.kind === 'symbol' && typeToks.stop.text === ':=') {
      i++;
      const initToks = scanUntil([';']);
      if (initToks.to === initToks.from) {
        error(initToks.stop.pos.line, initToks.stop.pos.col, `an initial value is missing after ":=", found ${word(initToks.stop)}`);
        return recover();
      }
      if (missingSemicolon(initToks.from, names[0]!.text) !== undefined) return;
      initial = joined(initToks.from, initToks.to);
    }
    const semi = peek();
    if (semi.kind !== 'symbol' || semi.text !== ';') {
      const before = toks[i - 1]!;
      // Located where the ";" belongs: right after the declaration's last token.
      const line = lineOf(before.end);
      error(line, before.end - starts[line - 1]! + 1, `";" missing at the end of the declaration of ${names[0]!.text} (before ${word(semi)} at ${at(semi)})`);
      return recover();
    }
    i++;
    decls.push({
      names,
      ...(location !== undefined ? { location } : {}),
      type: joined(typeToks.from, typeToks.to),
      ...(initial !== undefined ? { initial } : {}),
      varClass,
      retain,
      constant,
      first: first.start,
      semi,
    });
  };

  while (peek().kind !== 'eof') {
    const head = peek();
    if (head.kind !== 'ident' || !HEADERS.has(head.upper)) {
      error(head.pos.line, head.pos.col, `expected ${section === 'globals' ? 'VAR_GLOBAL' : 'VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_TEMP or VAR_EXTERNAL'} to open a block of declarations, found ${word(head)}`);
      // Skip to the next block header.
      i++;
      while (peek().kind !== 'eof' && !(peek().kind === 'ident' && HEADERS.has(peek().upper))) i++;
      continue;
    }
    i++;
    let varClass: VarClass = 'local';
    let usable = true;
    if (section === 'globals') {
      if (head.upper !== 'VAR_GLOBAL') {
        error(head.pos.line, head.pos.col, `the global variables are declared in VAR_GLOBAL … END_VAR, not ${head.upper}`);
        usable = false;
      }
    } else if (head.upper in POU_HEADERS) varClass = POU_HEADERS[head.upper]!;
    else {
      error(head.pos.line, head.pos.col, head.upper === 'VAR_GLOBAL'
        ? 'VAR_GLOBAL declares global variables: write them in the Global view (a POU reaches them with VAR_EXTERNAL or by name)'
        : `${head.upper} is not a block of a POU's variables: use VAR, VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR_TEMP or VAR_EXTERNAL`);
      usable = false;
    }
    headerLines.add(head.pos.line);
    let retain = false;
    let constant = false;
    while (peek().kind === 'ident' && QUALIFIERS.has(peek().upper)) {
      const q = peek();
      headerLines.add(q.pos.line);
      if (q.upper === 'CONSTANT') constant = true;
      else if (q.upper === 'RETAIN') retain = true;
      else if (q.upper === 'PERSISTENT')
        warn(q.pos.line, q.pos.col, 'PERSISTENT is not kept: Rungsmith keeps RETAIN variables over a warm restart only');
      i++;
    }
    const before = decls.length;
    while (true) {
      const t = peek();
      if (t.kind === 'ident' && t.upper === 'END_VAR') {
        i++;
        break;
      }
      if (t.kind === 'eof' || (t.kind === 'ident' && HEADERS.has(t.upper))) {
        error(t.pos.line, t.pos.col, `END_VAR missing: the block ${head.upper} opened at ${at(head)} is not closed before ${word(t)}`);
        break;
      }
      parseDecl(varClass, retain, constant);
    }
    if (!usable) decls.splice(before);
  }

  // Comments: inside a declaration, after its ";" on that line, or on the lines just above it.
  const owner = new Map<Decl, { lead: string[]; own: string[] }>();
  const slot = (d: Decl) => {
    let s = owner.get(d);
    if (!s) owner.set(d, (s = { lead: [], own: [] }));
    return s;
  };
  // Comments and declarations both run in text order: one pass with two pointers.
  const byFirst = new Map(decls.map((x) => [x.first, x]));
  let k = 0; // first declaration whose ";" ends after the comment's start
  let n = 0; // first token after the comment's start
  for (const c of comments) {
    while (k < decls.length && decls[k]!.semi.end <= c.start) k++;
    while (n < toks.length && toks[n]!.start <= c.start) n++;
    const inside = decls[k] && decls[k]!.first <= c.start ? decls[k] : undefined;
    const before = k > 0 ? decls[k - 1] : undefined;
    const next = toks[n];
    const below = next ? byFirst.get(next.start) : undefined;
    if (inside) slot(inside).own.push(c.text);
    else if (before && before.semi.pos.line === c.line) slot(before).own.push(c.text);
    else if (below && !headerLines.has(c.line)) slot(below).lead.push(c.text);
    else if (c.text !== '') {
      const col = c.start - starts[c.line - 1]! + 1;
      warn(c.line, col, 'this comment belongs to no variable and is not kept (write it after a declaration, or on the line above it)');
    }
  }

  const declarations: ParsedDeclaration[] = [];
  const seen = new Map<string, Tok>();
  for (const decl of decls) {
    const s = owner.get(decl);
    const comment = s ? [...s.lead, ...s.own].filter((x) => x !== '').join(' ') : '';
    for (const n of decl.names) {
      const key = n.upper;
      const earlier = seen.get(key);
      if (earlier) {
        error(n.pos.line, n.pos.col, `"${n.text}" is already declared at line ${earlier.pos.line} (names ignore upper/lower case)`);
        continue;
      }
      seen.set(key, n);
      const variable: Variable = {
        name: n.text,
        type: decl.type,
        varClass: decl.varClass,
        ...(decl.location !== undefined ? { location: decl.location } : {}),
        ...(decl.initial !== undefined ? { initial: decl.initial } : {}),
        retain: decl.retain,
        ...(decl.constant ? { constant: true } : {}),
        comment,
      };
      declarations.push({ variable, line: n.pos.line, col: n.pos.col });
    }
  }
  problems.sort((a, b) => a.line - b.line || a.col - b.col);
  return {
    ok: !problems.some((p) => p.severity === 'error'),
    declarations,
    variables: declarations.map((x) => x.variable),
    problems,
  };
}

// ---------------------------------------------------------------------------------------------
// From the old list to the new one

/** Two declarations say the same (empty and absent fields alike, spacing of comments aside). */
export function sameDeclaration(a: Variable, b: Variable): boolean {
  return (
    a.name === b.name &&
    a.type.trim() === b.type.trim() &&
    a.varClass === b.varClass &&
    (a.location?.trim() ?? '') === (b.location?.trim() ?? '') &&
    (a.initial?.trim() ?? '') === (b.initial?.trim() ?? '') &&
    a.retain === b.retain &&
    !!a.constant === !!b.constant &&
    a.comment.trim() === b.comment.trim()
  );
}

export interface DeclarationEdit {
  /** Names changed at the same position, the rest of the list in place: renames (uses follow). */
  readonly renames?: readonly { readonly from: string; readonly to: string }[];
  /** Old variables the text no longer declares (after the renames). */
  readonly removed: readonly string[];
  /** Existing variables (by their name after the rename) whose declaration changed, with the new one. */
  readonly updated: readonly { readonly name: string; readonly after: Variable }[];
  /** New variables, in text order. */
  readonly added: readonly Variable[];
  /** The names in the text's order (to order the list as written). */
  readonly order: readonly string[];
}

/**
 * What turns `before` into `after`. Variables are matched by name (case-insensitive). When the old
 * names gone and the new names that appear are as many, each new one at the position of an old one
 * in both lists (Start → StartBtn and Motor → Pump in one edit), they are renames. For globals,
 * `after` takes `scope` (configuration/resource) of the variable it matches.
 */
export function planDeclarationEdit(before: readonly Variable[], after: readonly Variable[]): DeclarationEdit {
  const key = (v: Variable) => v.name.toUpperCase();
  const oldByKey = new Map(before.map((v) => [key(v), v]));
  const newKeys = new Set(after.map(key));
  const gone = before.filter((v) => !newKeys.has(key(v)));
  const fresh = after.filter((v) => !oldByKey.has(key(v)));
  const renames =
    gone.length > 0 && gone.length === fresh.length && gone.every((from, i) => before.indexOf(from) === after.indexOf(fresh[i]!))
      ? gone.map((from, i) => ({ from: from.name, to: fresh[i]!.name }))
      : [];
  /** New name (upper case) -> the old variable it renames. */
  const renamedFrom = new Map(renames.map((r) => [r.to.toUpperCase(), oldByKey.get(r.from.toUpperCase())!]));
  const updated: { name: string; after: Variable }[] = [];
  const added: Variable[] = [];
  for (const v of after) {
    const from = renamedFrom.get(key(v));
    const old = from ?? oldByKey.get(key(v));
    if (!old) {
      added.push(v);
      continue;
    }
    const next: Variable = old.scope !== undefined ? { ...v, scope: old.scope } : v;
    const renamedOld = from ? { ...old, name: v.name } : old;
    if (!sameDeclaration(renamedOld, next))
      updated.push({ name: renamedOld.name, after: next });
  }
  return {
    ...(renames.length ? { renames } : {}),
    removed: gone.filter((v) => !renames.some((r) => r.from === v.name)).map((v) => v.name),
    updated,
    added,
    order: after.map((v) => v.name),
  };
}
