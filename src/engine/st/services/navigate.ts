// What the name at an offset of an ST body is (a variable, a member of an instance or a struct, a
// call's parameter, a function or function block, an enum value), and from that the hover text
// and the place its definition is.
import type { PouId } from '../../../model/ids';
import type { BlockSignature } from '../../../model/blocks';
import { resolveType } from '../../../model/dataTypes';
import type { Pou, Project, Variable } from '../../../model/project';
import {
  calledBlock,
  chainMember,
  classWords,
  declarationWords,
  enumValuesInScope,
  lookupVariable,
  serviceScope,
  signatureWords,
  type Member,
  type ScopeVariable,
  type ServiceScope,
} from './scope';
import { inCommentOrString, readAround, sameName, tokenAt, type BodyText } from './text';

export type StSymbol =
  | { readonly k: 'variable'; readonly v: ScopeVariable }
  /** `Inst.Pin`, `S.Member`: the member, and the POU declaring it when it is a user FB's variable. */
  | {
      readonly k: 'member';
      readonly m: Member;
      readonly decl?: { readonly pou: Pou; readonly variable: Variable };
    }
  /** `F(In := …)`: an input or output of the called block, named in the call. */
  | {
      readonly k: 'parameter';
      readonly name: string;
      readonly sig: BlockSignature;
      readonly decl?: { readonly pou: Pou; readonly variable: Variable };
    }
  | { readonly k: 'block'; readonly sig: BlockSignature; readonly pou?: Pou }
  | { readonly k: 'enum'; readonly value: string; readonly type: string }
  | { readonly k: 'result'; readonly pou: Pou };

export interface Located<T> {
  /** The name's offsets in the text. */
  readonly from: number;
  readonly to: number;
  readonly symbol: T;
}

/** Segments of the chain ending at token `k` (`A.B[i].C` at C -> A, B, C with B indexed). */
function chainAt(b: BodyText, k: number): { segments: string[]; indexed: boolean[] } {
  const segments = [b.tokens[k]!.text];
  const indexed = [false];
  let i = k - 1;
  while (b.tokens[i]?.text === '.') {
    let j = i - 1;
    let isIndexed = false;
    if (b.tokens[j]?.text === ']') {
      let depth = 0;
      for (; j >= 0; j--) {
        const t = b.tokens[j]!.text;
        if (t === ']') depth++;
        else if (t === '[' && --depth === 0) break;
      }
      j--;
      isIndexed = true;
    }
    const t = b.tokens[j];
    if (!t || t.kind !== 'ident') break;
    segments.unshift(t.text);
    indexed.unshift(isIndexed);
    i = j - 1;
  }
  return { segments, indexed };
}

/** The callee of the argument list holding token `k`, when `k` names a parameter (`In :=`, `Q =>`). */
function parameterCall(b: BodyText, k: number): string | undefined {
  const next = b.tokens[k + 1]?.text;
  const prev = b.tokens[k - 1];
  if (next !== ':=' && next !== '=>') return undefined;
  if (!prev || !(prev.text === '(' || prev.text === ',' || (prev.upper === 'NOT' && next === '=>')))
    return undefined;
  let depth = 0;
  for (let i = k - 1; i >= 0; i--) {
    const t = b.tokens[i]!.text;
    if (t === ';') return undefined;
    if (t === ')') depth++;
    else if (t === '(') {
      if (depth-- > 0) continue;
      const callee = b.tokens[i - 1];
      return callee?.kind === 'ident' ? callee.text : undefined;
    }
  }
  return undefined;
}

const declOf = (
  s: ServiceScope,
  blockName: string,
  name: string,
): { pou: Pou; variable: Variable } | undefined => {
  const pou = s.library.userPou(blockName);
  const variable = pou?.variables.find((v) => sameName(v.name, name));
  return pou && variable && s.project.pous.includes(pou) ? { pou, variable } : undefined;
};

/** The name at `offset` of the body `text` of `pou`, and what it is. */
export function symbolAt(s: ServiceScope, text: string, offset: number): Located<StSymbol> | undefined {
  const b = readAround(text, offset);
  if (inCommentOrString(b, offset)) return undefined;
  const k = tokenAt(b, offset);
  const t = k >= 0 ? b.tokens[k] : undefined;
  if (!t) return undefined;
  const at = { from: t.from, to: t.to };
  if (t.kind === 'literal') {
    const m = /^([A-Za-z_]\w*)#([A-Za-z_]\w*)$/.exec(t.text);
    const r = m && resolveType(s.project, m[1]!);
    if (r?.ok && r.shape.kind === 'enum')
      return { ...at, symbol: { k: 'enum', value: m![2]!, type: r.shape.name } };
    return undefined;
  }
  if (t.kind !== 'ident') return undefined;
  const callee = parameterCall(b, k);
  if (callee) {
    const called = calledBlock(s, callee);
    if (!called) return undefined;
    const decl = declOf(s, called.sig.name, t.text);
    return { ...at, symbol: { k: 'parameter', name: t.text, sig: called.sig, ...(decl ? { decl } : {}) } };
  }
  const chain = chainAt(b, k);
  if (chain.segments.length > 1) {
    const m = chainMember(s, chain.segments, chain.indexed);
    if (m) {
      const decl = declOf(s, m.of, m.name);
      return { ...at, symbol: { k: 'member', m, ...(decl ? { decl } : {}) } };
    }
    // CODESYS's `E_State.IDLE`.
    const r =
      chain.segments.length === 2 && !lookupVariable(s, chain.segments[0]!)
        ? resolveType(s.project, chain.segments[0]!)
        : undefined;
    if (r?.ok && r.shape.kind === 'enum')
      return { ...at, symbol: { k: 'enum', value: t.text, type: r.shape.name } };
    return undefined;
  }
  const v = lookupVariable(s, t.text);
  // `T1(…)` calls the instance; `F(…)` the function F.
  if (v) return { ...at, symbol: { k: 'variable', v } };
  if (s.pou.kind === 'FUNCTION' && sameName(t.text, s.pou.name))
    return { ...at, symbol: { k: 'result', pou: s.pou } };
  const sig = s.library.signature(t.text);
  if (sig) {
    const pou = s.library.userPou(t.text);
    return { ...at, symbol: { k: 'block', sig, ...(pou ? { pou } : {}) } };
  }
  const e = enumValuesInScope(s).find((x) => sameName(x.value, t.text));
  if (e) return { ...at, symbol: { k: 'enum', value: e.value, type: e.type } };
  return undefined;
}

export interface StHover {
  readonly from: number;
  readonly to: number;
  /** The declaration or signature, as IEC text. */
  readonly title: string;
  /** What it is in words, and its comment. */
  readonly lines: readonly string[];
}

/** The hover text of the name at `offset`. */
export function stHover(project: Project, pouId: string, text: string, offset: number): StHover | undefined {
  const pou = project.pous.find((p) => p.id === pouId);
  if (!pou) return undefined;
  const s = serviceScope(project, pou);
  const found = symbolAt(s, text, offset);
  if (!found) return undefined;
  const { from, to, symbol: sym } = found;
  switch (sym.k) {
    case 'variable': {
      const v = sym.v.variable;
      const where = sym.v.owner === 'globals' ? 'global variable' : `variable of ${sym.v.owner.name}`;
      const fb = s.library.signature(v.type.trim());
      const lines = [`${classWords(sym.v)} — ${where}`];
      if (fb?.kind === 'fb') lines.push(`instance of ${signatureWords(fb)}`);
      if (v.comment.trim()) lines.push(v.comment.trim());
      return { from, to, title: declarationWords(v), lines };
    }
    case 'member': {
      const m = sym.m;
      const lines = [
        m.kind === 'member' ? `member of ${m.of}` : `${m.kind === 'inOut' ? 'in-out' : m.kind} of ${m.of}`,
      ];
      const comment = sym.decl?.variable.comment.trim() || m.comment?.trim();
      if (comment) lines.push(comment);
      return { from, to, title: `${m.name} : ${m.type}${m.initial ? ` := ${m.initial}` : ''}`, lines };
    }
    case 'parameter': {
      const pin = [...sym.sig.inputs, ...sym.sig.outputs].find((p) => sameName(p.name, sym.name));
      const dir = sym.sig.inputs.some((p) => sameName(p.name, sym.name)) ? 'input' : 'output';
      const lines = [`${dir} of ${signatureWords(sym.sig)}`];
      const comment = sym.decl?.variable.comment.trim();
      if (comment) lines.push(comment);
      return {
        from,
        to,
        title: `${pin?.name ?? sym.name} : ${sym.decl?.variable.type ?? pin?.type ?? '?'}`,
        lines,
      };
    }
    case 'block':
      return {
        from,
        to,
        title: signatureWords(sym.sig),
        lines: [
          `${sym.sig.kind === 'fb' ? 'function block' : 'function'}${sym.pou ? (sym.sig.library ? ` of the library ${sym.sig.library}` : ' of this project') : sym.sig.category === 'external' ? ' (external: not run by the simulator)' : ' (standard)'}`,
          sym.sig.description,
        ],
      };
    case 'enum':
      return { from, to, title: `${sym.type}#${sym.value}`, lines: [`value of the enumeration ${sym.type}`] };
    case 'result':
      return {
        from,
        to,
        title: `${sym.pou.name} : ${sym.pou.returnType ?? 'BOOL'}`,
        lines: [`the result of the function ${sym.pou.name}`],
      };
  }
}

/** Where a definition is: a variable's row in a variables table, a POU, a data type. */
export type StDefinition =
  | { readonly kind: 'variable'; readonly scope: PouId | 'globals'; readonly name: string }
  | { readonly kind: 'pou'; readonly pouId: PouId }
  | { readonly kind: 'dataType'; readonly name: string };

/** The definition of the name at `offset`; undefined for a standard block or an unknown name. */
export function stDefinition(
  project: Project,
  pouId: string,
  text: string,
  offset: number,
): StDefinition | undefined {
  const pou = project.pous.find((p) => p.id === pouId);
  if (!pou) return undefined;
  const s = serviceScope(project, pou);
  const found = symbolAt(s, text, offset)?.symbol;
  if (!found) return undefined;
  switch (found.k) {
    case 'variable':
      return {
        kind: 'variable',
        scope: found.v.owner === 'globals' ? 'globals' : found.v.owner.id,
        name: found.v.variable.name,
      };
    case 'member':
    case 'parameter':
      if (found.decl) return { kind: 'variable', scope: found.decl.pou.id, name: found.decl.variable.name };
      if (found.k === 'member' && found.m.kind === 'member')
        return (project.dataTypes ?? []).some((d) => sameName(d.name, found.m.of))
          ? { kind: 'dataType', name: found.m.of }
          : undefined;
      return undefined;
    case 'block':
      return found.pou && project.pous.includes(found.pou) ? { kind: 'pou', pouId: found.pou.id } : undefined;
    case 'enum': {
      const dt = (project.dataTypes ?? []).find((d) => sameName(d.name, found.type));
      return dt ? { kind: 'dataType', name: dt.name } : undefined;
    }
    case 'result':
      return { kind: 'pou', pouId: found.pou.id };
  }
}
