// Completion in an ST body at an offset: after `Inst.` the members of its type (FB pins, struct
// members), after `Type#` an enum's values, inside a call's parentheses its parameters by name,
// elsewhere the variables in scope, enum values, functions and function blocks with their
// signatures, and the statements of ST as snippets.
import { ST_OPERATOR_WORDS, ST_STATEMENT_WORDS } from '../lexer';
import { FB_SIGNATURES, FUNCTION_SIGNATURES, type BlockSignature } from '../../../model/blocks';
import type { Project } from '../../../model/project';
import {
  calledBlock,
  chainType,
  classWords,
  declarationWords,
  enumValuesInScope,
  membersOf,
  scopeVariables,
  serviceScope,
  signatureWords,
  type ServiceScope,
} from './scope';
import { inCommentOrString, readAround, tokenBefore, type BodyText, type TextToken } from './text';
import { resolveType } from '../../../model/dataTypes';

export type CompletionKind =
  'variable' | 'member' | 'enum' | 'function' | 'fb' | 'keyword' | 'snippet' | 'parameter' | 'type';

export interface StCompletion {
  /** What the list shows and filters on. */
  readonly label: string;
  readonly kind: CompletionKind;
  /** Short words beside the label: a type, a signature. */
  readonly detail: string;
  /** A longer explanation (comment, description). */
  readonly info?: string;
  /** Text inserted instead of the label; `${}` marks the cursor place of a snippet (first one). */
  readonly apply?: string;
  /** Higher first among equally good matches. */
  readonly boost?: number;
}

export interface StCompletionResult {
  /** Offset where the word being completed starts (the text from there to the cursor is replaced). */
  readonly from: number;
  readonly options: readonly StCompletion[];
  /** True when the list was asked for in a context (after `.`, `#`, `(`): show it even when empty-typed. */
  readonly explicit: boolean;
}

const KEYWORDS = [...ST_STATEMENT_WORDS, ...ST_OPERATOR_WORDS];

/** Statement templates; `${}` is where the cursor goes. */
const SNIPPETS: readonly { label: string; detail: string; apply: string }[] = [
  { label: 'IF', detail: 'IF … THEN … END_IF', apply: 'IF ${} THEN\n\t\nEND_IF;' },
  { label: 'IF ELSE', detail: 'IF … THEN … ELSE … END_IF', apply: 'IF ${} THEN\n\t\nELSE\n\t\nEND_IF;' },
  { label: 'CASE', detail: 'CASE … OF … END_CASE', apply: 'CASE ${} OF\n\t1:\n\t\t\nELSE\n\t\nEND_CASE;' },
  { label: 'FOR', detail: 'FOR i := 1 TO n DO … END_FOR', apply: 'FOR ${} := 1 TO 10 DO\n\t\nEND_FOR;' },
  { label: 'WHILE', detail: 'WHILE … DO … END_WHILE', apply: 'WHILE ${} DO\n\t\nEND_WHILE;' },
  { label: 'REPEAT', detail: 'REPEAT … UNTIL … END_REPEAT', apply: 'REPEAT\n\t${}\nUNTIL TRUE\nEND_REPEAT;' },
];

const isWordChar = (c: string | undefined): boolean => !!c && /[A-Za-z0-9_]/.test(c);

/** The identifiers of a chain ending just before `dot` (`A.B[i].` -> A, B with B indexed). */
function chainBefore(b: BodyText, k: number): { segments: string[]; indexed: boolean[] } | undefined {
  const segments: string[] = [];
  const indexed: boolean[] = [];
  let i = k; // the token before the `.`
  for (;;) {
    let isIndexed = false;
    if (b.tokens[i]?.text === ']') {
      // Skip back over the index list to its `[`.
      let depth = 0;
      for (; i >= 0; i--) {
        const t = b.tokens[i]!.text;
        if (t === ']') depth++;
        else if (t === '[' && --depth === 0) break;
      }
      i--;
      isIndexed = true;
    }
    const t = b.tokens[i];
    if (!t || t.kind !== 'ident') return undefined;
    segments.unshift(t.text);
    indexed.unshift(isIndexed);
    if (b.tokens[i - 1]?.text !== '.') return { segments, indexed };
    i -= 2;
  }
}

/** The call whose argument list holds the token after `k` (innermost), with the arguments named so far. */
function enclosingCall(b: BodyText, k: number): { name: string; named: Set<string> } | undefined {
  let depth = 0;
  const named = new Set<string>();
  for (let i = k; i >= 0; i--) {
    const t = b.tokens[i]!;
    if (t.text === ';' && depth === 0) return undefined;
    if (t.text === ')') depth++;
    else if (t.text === '(') {
      if (depth > 0) {
        depth--;
        continue;
      }
      const callee = b.tokens[i - 1];
      return callee?.kind === 'ident' ? { name: callee.text, named } : undefined;
    } else if (
      depth === 0 &&
      t.kind === 'ident' &&
      (b.tokens[i + 1]?.text === ':=' || b.tokens[i + 1]?.text === '=>')
    )
      named.add(t.upper);
  }
  return undefined;
}

function blockCompletion(sig: BlockSignature, boost = 0): StCompletion {
  return {
    label: sig.name,
    kind: sig.kind === 'fb' ? 'fb' : 'function',
    detail: signatureWords(sig),
    info: sig.description,
    ...(sig.kind === 'function' ? { apply: `${sig.name}(\${})` } : {}),
    boost,
  };
}

function parameterCompletions(s: ServiceScope, callName: string, named: Set<string>): StCompletion[] {
  const called = calledBlock(s, callName);
  if (!called) return [];
  const out: StCompletion[] = [];
  const sig = called.sig;
  for (const p of sig.inputs) {
    if (named.has(p.name.toUpperCase()) || (sig.extensible && p === sig.inputs[sig.inputs.length - 1]))
      continue;
    out.push({
      label: `${p.name} :=`,
      kind: 'parameter',
      detail: `input ${p.type}`,
      apply: `${p.name} := `,
      boost: 2,
    });
  }
  // Outputs are read by name into a variable: only an FB call (and a function's extra outputs) has them.
  for (const p of sig.outputs) {
    if (named.has(p.name.toUpperCase()) || (sig.kind === 'function' && p.name === 'OUT')) continue;
    if (sig.inputs.some((i) => i.name === p.name)) continue;
    out.push({
      label: `${p.name} =>`,
      kind: 'parameter',
      detail: `output ${p.type}`,
      apply: `${p.name} => `,
      boost: 1,
    });
  }
  return out;
}

/** The standard functions and FBs, the same for every body (made once). */
let standard: readonly StCompletion[] | undefined;
const standardCompletions = (): readonly StCompletion[] =>
  (standard ??= [
    ...FUNCTION_SIGNATURES.map((sig) => blockCompletion(sig)),
    ...FB_SIGNATURES.map((sig) => blockCompletion(sig, -1)),
  ]);

/** The names of a scope, kept per POU object and project (both immutable): typing in a body reuses them. */
const scopeCache = new WeakMap<
  object,
  { project: Project; statement: StCompletion[]; value: StCompletion[] }
>();

/** The names usable where a value or a statement starts. */
function scopeCompletions(s: ServiceScope, statementStart: boolean): StCompletion[] {
  const hit = scopeCache.get(s.pou);
  if (hit && hit.project === s.project) return statementStart ? hit.statement : hit.value;
  const value = makeScopeCompletions(s, false);
  const statement = makeScopeCompletions(s, true);
  scopeCache.set(s.pou, { project: s.project, statement, value });
  return statementStart ? statement : value;
}

function makeScopeCompletions(s: ServiceScope, statementStart: boolean): StCompletion[] {
  const out: StCompletion[] = [];
  const seen = new Set<string>();
  const add = (c: StCompletion) => {
    const key = `${c.kind}:${c.label.toUpperCase()}`;
    if (seen.has(key)) return;
    seen.add(key);
    out.push(c);
  };
  for (const v of scopeVariables(s)) {
    const fb = s.library.signature(v.variable.type.trim());
    add({
      label: v.variable.name,
      kind: 'variable',
      detail: `${v.variable.type}${fb?.kind === 'fb' ? ` — ${signatureWords(fb)}` : ''}`,
      info: `${classWords(v)} ${declarationWords(v.variable)}${v.variable.comment ? `\n${v.variable.comment}` : ''}`,
      boost: v.owner === 'globals' ? 3 : 4,
    });
  }
  if (s.pou.kind === 'FUNCTION')
    add({
      label: s.pou.name,
      kind: 'variable',
      detail: `${s.pou.returnType ?? 'BOOL'} — the function's result`,
      boost: 3,
    });
  for (const e of enumValuesInScope(s)) add({ label: e.value, kind: 'enum', detail: e.type, boost: 1 });
  for (const sig of [...s.library.userBlocks, ...s.library.libraryBlocks]) {
    if (sig.name.toUpperCase() === s.pou.name.toUpperCase()) continue;
    // A user FB is called through an instance; its type name is still offered (with its pins).
    add(blockCompletion(sig, 1));
  }
  for (const c of standardCompletions()) add(c);
  for (const sig of s.library.externalBlocks) add(blockCompletion(sig, -2));
  if (statementStart)
    for (const sn of SNIPPETS)
      add({ label: sn.label, kind: 'snippet', detail: sn.detail, apply: sn.apply, boost: 2 });
  for (const k of KEYWORDS) add({ label: k, kind: 'keyword', detail: 'keyword', boost: -1 });
  return out;
}

/** Is the token before the word the end of a statement (so a statement starts here)? */
function startsStatement(prev: TextToken | undefined): boolean {
  if (!prev) return true;
  return (
    prev.text === ';' ||
    ['THEN', 'ELSE', 'DO', 'REPEAT', 'OF'].includes(prev.upper) ||
    (prev.text === ':' && prev.kind === 'symbol')
  );
}

/** Completion at `offset` of the body `text` of POU `pouId`; undefined where none makes sense (a comment, a string). */
export function stCompletions(
  project: Project,
  pouId: string,
  text: string,
  offset: number,
  explicit = false,
): StCompletionResult | undefined {
  const pou = project.pous.find((p) => p.id === pouId);
  if (!pou) return undefined;
  const b = readAround(text, offset);
  if (inCommentOrString(b, offset)) return undefined;
  let from = offset;
  while (from > 0 && isWordChar(text[from - 1])) from--;
  // A number or a literal being typed (16#FF, T#5s) completes nothing.
  if (/^[0-9]/.test(text.slice(from, offset))) return undefined;
  const s = serviceScope(project, pou);
  // The token just before the word being typed.
  const k = tokenBefore(b, from);
  const prev = k >= 0 ? b.tokens[k] : undefined;
  // Whitespace before the word: no `.`/`#` attached.
  const touching = prev !== undefined && prev.to === from;
  if (prev && touching && prev.text === '.' && prev.kind === 'symbol') {
    const chain = chainBefore(b, k - 1);
    if (!chain) return { from, options: [], explicit: true };
    const info = chainType(s, chain.segments, chain.indexed);
    // In declaration order (outputs first for an FB): the boost keeps it in the list.
    const members = membersOf(s, info).map<StCompletion>((m, i) => ({
      label: m.name,
      kind: 'member',
      detail: `${m.type} — ${m.kind === 'member' ? `member of ${m.of}` : `${m.kind === 'inOut' ? 'in-out' : m.kind} of ${m.of}`}`,
      ...(m.comment ? { info: m.comment } : {}),
      boost: Math.max(-99, 50 - i),
    }));
    // `E_State.` on an enum type's name (CODESYS writes enum values so).
    if (members.length === 0 && chain.segments.length === 1) {
      const r = resolveType(s.project, chain.segments[0]!);
      if (r.ok && r.shape.kind === 'enum')
        return {
          from,
          options: r.shape.values.map((v) => ({ label: v, kind: 'enum', detail: r.shape.name })),
          explicit: true,
        };
    }
    return { from, options: members, explicit: true };
  }
  // `Color#` (a typed literal being written): the token is the literal `Color#…` itself.
  const hash = /([A-Za-z_][A-Za-z0-9_]*)#([A-Za-z0-9_]*)$/.exec(text.slice(Math.max(0, from - 64), offset));
  if (hash) {
    const r = resolveType(s.project, hash[1]!);
    if (!r.ok || r.shape.kind !== 'enum') return undefined;
    return {
      from: offset - hash[2]!.length,
      options: r.shape.values.map((v) => ({ label: v, kind: 'enum', detail: r.shape.name })),
      explicit: true,
    };
  }
  const call = prev && (prev.text === '(' || prev.text === ',') ? enclosingCall(b, k) : undefined;
  const names = scopeCompletions(s, startsStatement(prev));
  const options = call ? [...parameterCompletions(s, call.name, call.named), ...names] : names;
  return { from, options, explicit: explicit || !!call };
}
