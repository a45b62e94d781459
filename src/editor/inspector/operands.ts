// What an element or pin binds to, and which declared names fit there. Pure: used by the
// completion list, the inspector and the "declare it?" offer.
import { findVariable } from '../../model/factory';
import { blockLibrary, declaredPinType } from '../../model/library';
import type { PinSignature } from '../../model/blocks';
import {
  GENERIC_MEMBERS,
  INT_INFO,
  isElementaryType,
  type ElementaryType,
  type GenericType,
  type PinType,
} from '../../model/iecTypes';
import type { Pou, Project, Variable } from '../../model/project';
import { parseLiteral } from '../../engine/values/literals';
import { canWiden } from '../../engine/values/types';
import { isAggregateVariable, memberCandidates, resolveMemberPath } from '../dataTypes/operandPaths';

/** The place a name is typed into. */
export type BindingRole =
  | { readonly kind: 'contact' }
  | { readonly kind: 'coil' }
  | { readonly kind: 'instance'; readonly blockType: string }
  | {
      readonly kind: 'pin';
      readonly pinType: PinType;
      readonly direction: 'input' | 'output';
      /** A user block's pin declared with a data type (`Point`): its pinType is ANY. */
      readonly declaredType?: string;
    };

/**
 * The role of a block pin's operand, keeping a user pin's declared data type (see declaredPinType);
 * `pinType`: the pin's type as placed, when the box narrowed it.
 */
export function pinRole(pin: PinSignature, direction: 'input' | 'output', pinType: PinType = pin.type): BindingRole {
  const declared = declaredPinType(pin);
  return { kind: 'pin', pinType, direction, ...(declared !== pin.type ? { declaredType: declared } : {}) };
}

/** The elementary types a pin type admits. */
export function pinTypeMembers(type: PinType): readonly ElementaryType[] {
  return isElementaryType(type) ? [type] : GENERIC_MEMBERS[type as GenericType];
}

/** Types a name bound in this role may have; undefined means "any declared variable". */
export function acceptedTypes(role: BindingRole): readonly string[] {
  switch (role.kind) {
    case 'contact':
    case 'coil':
      return ['BOOL'];
    case 'instance':
      return [role.blockType.toUpperCase()];
    case 'pin':
      // A data type pin takes its type; an alias/enum/subrange pin also its elementary type.
      if (!role.declaredType) return pinTypeMembers(role.pinType);
      return [role.declaredType.toUpperCase(), ...(role.pinType === 'ANY' ? [] : pinTypeMembers(role.pinType))];
  }
}

export interface Candidate {
  /** The text inserted: `Start`, `T1.Q`. */
  readonly text: string;
  readonly type: string;
  /** Address, class or comment shown beside the name. */
  readonly detail: string;
}

const describe = (v: Variable): string =>
  [v.location, v.comment].filter((s) => s && s.trim() !== '').join('  ');

/** Declared variables, FB instance pins (`T1.Q`) and struct/array members (`P.X`) whose type fits the role. */
export function candidatesFor(project: Project, pou: Pou, role: BindingRole): Candidate[] {
  const accepted = new Set(acceptedTypes(role));
  const local = new Set(pou.variables.map((v) => v.name.toUpperCase()));
  const all = [...pou.variables, ...project.globals.filter((g) => !local.has(g.name.toUpperCase()))];
  const out: Candidate[] = [];
  const lib = blockLibrary(project);
  for (const v of all) {
    const type = v.type.toUpperCase();
    if (accepted.has(type)) out.push({ text: v.name, type, detail: describe(v) });
    // An elementary variable (most of them) has no members and is no FB instance.
    if (isElementaryType(type)) continue;
    if (role.kind !== 'instance' && isAggregateVariable(project, v))
      out.push(...memberCandidates(project, [v], accepted));
    if (role.kind === 'instance' || !lib.isFbType(type)) continue;
    const sig = lib.signature(type);
    if (!sig) continue;
    // Contacts read any pin; coils and input pins write, so only FB inputs make sense for coils.
    const pins = role.kind === 'coil' ? sig.inputs : [...sig.inputs, ...sig.outputs];
    for (const pin of pins) {
      if (isElementaryType(pin.type) && accepted.has(pin.type))
        out.push({ text: `${v.name}.${pin.name}`, type: pin.type, detail: `${type} pin` });
    }
  }
  return out;
}

/** Candidates matching what was typed: names starting with it first, then names containing it. */
export function rankCandidates(query: string, candidates: readonly Candidate[], limit = 12): Candidate[] {
  const q = query.trim().toUpperCase();
  if (q === '') return candidates.slice(0, limit);
  const starts: Candidate[] = [];
  const contains: Candidate[] = [];
  for (const c of candidates) {
    const name = c.text.toUpperCase();
    if (name.startsWith(q)) starts.push(c);
    else if (name.includes(q)) contains.push(c);
  }
  const byLength = (a: Candidate, b: Candidate) =>
    a.text.length - b.text.length || a.text.localeCompare(b.text);
  return [...starts.sort(byLength), ...contains.sort(byLength)].slice(0, limit);
}

export type Resolution =
  | { readonly status: 'empty' }
  | { readonly status: 'declared'; readonly type: string }
  | { readonly status: 'undeclared'; readonly name: string }
  | { readonly status: 'other'; readonly message: string };

/** Whether a typed name refers to something declared (plain name, `Instance.Pin`, `Word.3`, `P.X`, `A[3]`). */
export function resolveName(project: Project, pou: Pou, text: string): Resolution {
  const name = text.trim();
  if (name === '') return { status: 'empty' };
  const memberPath = resolveMemberPath(project, pou, name);
  if (memberPath) return memberPath;
  const [base = '', member, ...rest] = name.split('.');
  const v = findVariable(project, pou, base);
  if (member === undefined)
    return v ? { status: 'declared', type: v.type.toUpperCase() } : { status: 'undeclared', name };
  if (!v) return { status: 'other', message: `"${base}" is not declared` };
  if (rest.length > 0) return { status: 'other', message: `"${name}" has too many dots` };
  const type = v.type.toUpperCase();
  const lib = blockLibrary(project);
  const sig = lib.isFbType(type) ? lib.signature(type) : undefined;
  if (sig) {
    const pin = [...sig.inputs, ...sig.outputs].find((p) => p.name.toUpperCase() === member.toUpperCase());
    return pin
      ? { status: 'declared', type: pin.type }
      : { status: 'other', message: `${type} has no pin ${member}` };
  }
  if (/^\d+$/.test(member) && type !== 'BOOL' && type in INT_INFO) {
    const bits = INT_INFO[type as keyof typeof INT_INFO].bits;
    return Number(member) < bits
      ? { status: 'declared', type: 'BOOL' }
      : { status: 'other', message: `${type} ${base} has bits 0..${bits - 1}` };
  }
  return { status: 'other', message: `"${base}" is a ${type} and has no member ${member}` };
}

/**
 * What a literal operand is ("literal TIME"), or why it is not a valid one for the pin; undefined
 * when the text is a name (starts with a letter or _ and is not a typed literal like T#5s).
 */
export function describeLiteral(text: string, pinType: PinType): { ok: boolean; text: string } | undefined {
  const members = pinTypeMembers(pinType);
  const expected = members.length === 1 ? members[0] : undefined;
  const literal = parseLiteral(text, expected);
  if (literal.ok) {
    const fits = members.includes(literal.type) || members.some((m) => canWiden(literal.type, m));
    return fits
      ? { ok: true, text: `literal ${literal.type}` }
      : {
          ok: false,
          text: `${text} is a ${literal.type} literal; this pin takes ${members.length > 4 ? pinType : members.join(' or ')}`,
        };
  }
  const looksLikeName = /^[A-Za-z_][A-Za-z0-9_.]*(\[[-+0-9, ]+\][A-Za-z0-9_.]*)*$/.test(text) && !text.includes('#');
  return looksLikeName ? undefined : { ok: false, text: literal.message };
}
