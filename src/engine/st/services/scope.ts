// What a name in an ST body can be, seen from the POU whose body it is: its variables, the
// project's globals (visible in every POU, as buildSymbols declares them), the members of a
// variable's type (FB pins, struct members, array elements), enum values, the standard and the
// project's functions and function blocks. Shared by completion, hover, go to definition and rename.
import { blockSignature, type BlockSignature, type PinSignature } from '../../../model/blocks';
import { resolveType, type TypeShape } from '../../../model/dataTypes';
import { blockLibrary, declaredPinType, isInOutPin, type BlockLibrary } from '../../../model/library';
import { withLibraries } from '../../../model/libraries';
import type { Pou, Project, Variable, VarClass } from '../../../model/project';
import { sameName } from './text';

/** A declared variable seen from a POU: its own, or a global. */
export interface ScopeVariable {
  readonly variable: Variable;
  /** The POU declaring it, or 'globals'. */
  readonly owner: Pou | 'globals';
}

/** The project as the services resolve names in it (libraries' blocks and types included). */
export interface ServiceScope {
  readonly project: Project;
  readonly pou: Pou;
  readonly library: BlockLibrary;
}

export function serviceScope(project: Project, pou: Pou): ServiceScope {
  const full = withLibraries(project);
  return { project: full, pou, library: blockLibrary(full) };
}

/** The POU's variables (VAR_EXTERNAL ones resolve to the global), then globals it does not hide. */
export function scopeVariables(s: ServiceScope): ScopeVariable[] {
  const out: ScopeVariable[] = [];
  const own = new Set<string>();
  for (const v of s.pou.variables) {
    if (v.varClass === 'external') continue;
    out.push({ variable: v, owner: s.pou });
    own.add(v.name.toUpperCase());
  }
  for (const g of s.project.globals)
    if (!own.has(g.name.toUpperCase())) out.push({ variable: g, owner: 'globals' });
  return out;
}

/** The variable a name means in the POU (its own first, then a global); undefined when none. */
export function lookupVariable(s: ServiceScope, name: string): ScopeVariable | undefined {
  const own = s.pou.variables.find((v) => v.varClass !== 'external' && sameName(v.name, name));
  if (own) return { variable: own, owner: s.pou };
  const g = s.project.globals.find((v) => sameName(v.name, name));
  if (g) return { variable: g, owner: 'globals' };
  const ext = s.pou.variables.find((v) => sameName(v.name, name));
  return ext ? { variable: ext, owner: s.pou } : undefined;
}

/** A member of a value: an FB pin, a struct member, or an array's elements (by index). */
export interface Member {
  readonly name: string;
  /** Type as declared. */
  readonly type: string;
  readonly kind: 'input' | 'output' | 'inOut' | 'member';
  /** The FB type or struct type it belongs to. */
  readonly of: string;
  readonly initial?: string;
  readonly comment?: string;
  /** The shape of the member's own type, when it is a data type (for further members). */
  readonly shape?: TypeShape;
}

/** What a type is, for members: an FB (its signature) or a resolved data type shape. */
export type TypeInfo =
  { readonly fb: BlockSignature; readonly pou?: Pou } | { readonly shape: TypeShape } | undefined;

export function typeInfo(s: ServiceScope, type: string): TypeInfo {
  const t = type.trim();
  const sig = s.library.signature(t);
  if (sig && sig.kind === 'fb') {
    const pou = s.library.userPou(t);
    return pou ? { fb: sig, pou } : { fb: sig };
  }
  const r = resolveType(s.project, t);
  return r.ok ? { shape: r.shape } : undefined;
}

function shapeInfo(s: ServiceScope, shape: TypeShape): TypeInfo {
  if (shape.kind === 'fb') return typeInfo(s, shape.name);
  return { shape };
}

const pinKind = (pin: PinSignature, dir: 'in' | 'out'): Member['kind'] =>
  isInOutPin(pin) ? 'inOut' : dir === 'in' ? 'input' : 'output';

/** The members `Value.` offers: an FB's inputs and outputs (in-outs once), a struct's members. */
export function membersOf(_s: ServiceScope, info: TypeInfo): Member[] {
  if (!info) return [];
  if ('fb' in info) {
    const out: Member[] = [];
    const seen = new Set<string>();
    const decl = (name: string) => info.pou?.variables.find((v) => sameName(v.name, name));
    const add = (pin: PinSignature, dir: 'in' | 'out') => {
      const key = pin.name.toUpperCase();
      if (seen.has(key) || (info.fb.kind === 'function' && pin.name === 'OUT')) return;
      seen.add(key);
      const v = decl(pin.name);
      out.push({
        name: pin.name,
        type: declaredPinType(pin),
        kind: pinKind(pin, dir),
        of: info.fb.name,
        ...(v?.initial ? { initial: v.initial } : {}),
        ...(v?.comment ? { comment: v.comment } : {}),
      });
    };
    // Outputs first: reading Q or ET is what `T1.` is most often typed for.
    info.fb.outputs.forEach((p) => add(p, 'out'));
    info.fb.inputs.forEach((p) => add(p, 'in'));
    return out;
  }
  const shape = info.shape;
  if (shape.kind !== 'struct') return [];
  return shape.members.map((m) => ({
    name: m.name,
    type: m.type.name,
    kind: 'member' as const,
    of: shape.name,
    ...(m.initial ? { initial: m.initial } : {}),
    shape: m.type,
  }));
}

/**
 * The type of a chain of names `A.B[i].C` (segments without their indexes; `indexed[k]` when
 * segment k is followed by an index list): undefined when a link does not resolve.
 */
export function chainType(
  s: ServiceScope,
  segments: readonly string[],
  indexed: readonly boolean[],
): TypeInfo {
  const head = lookupVariable(s, segments[0] ?? '');
  if (!head) return undefined;
  let info = typeInfo(s, head.variable.type);
  for (let k = 0; k < segments.length; k++) {
    if (k > 0) {
      const m = membersOf(s, info).find((x) => sameName(x.name, segments[k]!));
      if (!m) return undefined;
      info = m.shape ? shapeInfo(s, m.shape) : typeInfo(s, m.type);
    }
    if (indexed[k]) {
      if (!info || 'fb' in info || info.shape.kind !== 'array') return undefined;
      info = shapeInfo(s, info.shape.of);
    }
  }
  return info;
}

/** A member named in a chain (`Motor1.Q`): the member and the type it belongs to. */
export function chainMember(
  s: ServiceScope,
  segments: readonly string[],
  indexed: readonly boolean[],
): Member | undefined {
  if (segments.length < 2) return undefined;
  const owner = chainType(s, segments.slice(0, -1), indexed.slice(0, -1));
  return membersOf(s, owner).find((m) => sameName(m.name, segments[segments.length - 1]!));
}

/** Enum values visible in a POU: of the project's enum types and the anonymous enums of its declarations. */
export function enumValuesInScope(s: ServiceScope): { value: string; type: string }[] {
  const out: { value: string; type: string }[] = [];
  for (const dt of s.project.dataTypes ?? [])
    if (dt.def.kind === 'enum') for (const v of dt.def.values) out.push({ value: v, type: dt.name });
  for (const { variable } of scopeVariables(s)) {
    const m = /^\s*\(([^)]*)\)\s*$/.exec(variable.type);
    if (m)
      for (const v of m[1]!.split(','))
        if (v.trim()) out.push({ value: v.trim(), type: variable.type.trim() });
  }
  return out;
}

const CLASS_WORDS: Record<VarClass, string> = {
  local: 'VAR',
  input: 'VAR_INPUT',
  output: 'VAR_OUTPUT',
  inOut: 'VAR_IN_OUT',
  temp: 'VAR_TEMP',
  external: 'VAR_EXTERNAL',
};

/** `VAR_INPUT`, `VAR_GLOBAL`, `VAR CONSTANT`, `VAR RETAIN`. */
export function classWords(v: ScopeVariable): string {
  const base = v.owner === 'globals' ? 'VAR_GLOBAL' : CLASS_WORDS[v.variable.varClass];
  return `${base}${v.variable.constant ? ' CONSTANT' : ''}${v.variable.retain ? ' RETAIN' : ''}`;
}

/** `Start AT %IX0.0 : BOOL := FALSE` */
export function declarationWords(v: Variable): string {
  return `${v.name}${v.location ? ` AT ${v.location}` : ''} : ${v.type}${v.initial ? ` := ${v.initial}` : ''}`;
}

/** `TON(IN : BOOL, PT : TIME) => (Q : BOOL, ET : TIME)`, `SCALE(In : REAL) : REAL`. */
export function signatureWords(sig: BlockSignature): string {
  const pin = (p: PinSignature) => `${p.name} : ${declaredPinType(p)}`;
  const inputs = sig.inputs.map((p, i) =>
    sig.extensible && i === sig.inputs.length - 1
      ? `${pin(p)}, …`
      : isInOutPin(p)
        ? `VAR_IN_OUT ${pin(p)}`
        : pin(p),
  );
  if (sig.kind === 'function') {
    const result = sig.outputs.find((p) => p.name === 'OUT') ?? sig.outputs[0];
    const outs = sig.outputs.filter((p) => p !== result && !isInOutPin(p));
    return `${sig.name}(${inputs.join(', ')})${outs.length ? ` => (${outs.map(pin).join(', ')})` : ''}${result ? ` : ${declaredPinType(result)}` : ''}`;
  }
  const outs = sig.outputs.filter((p) => !isInOutPin(p));
  return `${sig.name}(${inputs.join(', ')}) => (${outs.map(pin).join(', ')})`;
}

/** The block a call names: a function (standard or user) or an instance's FB type. */
export function calledBlock(
  s: ServiceScope,
  name: string,
): { sig: BlockSignature; instance?: ScopeVariable } | undefined {
  const v = lookupVariable(s, name);
  if (v) {
    const sig = s.library.signature(v.variable.type.trim());
    return sig && sig.kind === 'fb' ? { sig, instance: v } : undefined;
  }
  const sig = s.library.signature(name) ?? blockSignature(name);
  return sig ? { sig } : undefined;
}
