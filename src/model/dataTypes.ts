// User data types (Project.dataTypes): how a type name resolves and what a variable of such a
// type holds. Pure functions over the project, shared by the engine (storage of a variable is its
// leaves), PLCopen import/export and the editor (type picker, watch table expansion).
//
// API
// - `findDataType(project, name)` -> DataType | undefined: the project's own type, else a vendor
//   type (vendorTypes.ts: SVGHMI's HMI_BOOL ...). Case-insensitive.
// - `resolveType(project, text)` -> `{ ok: true, shape }` | `{ ok: false, message }`: a type text
//   (elementary, STRING[n], a function block type, a data type, an alias chain, or an anonymous
//   type written in a declaration: `ARRAY[1..3, 0..1] OF T`, `STRUCT X : INT; Y : INT := 5;
//   END_STRUCT`, `(Idle, Run, Fault)`, `INT (0..100)`) as a TypeShape tree; unknown names and cycles
//   are errors. An anonymous type's shape is named by its canonical text (`anonymousText`).
// - `anonymousType(text)` -> the definition an anonymous STRUCT / enum / subrange text declares
//   (`DataTypeDef`), a message, or undefined (not such a text); `anonymousText(def)` writes one back.
// - `isFbTypeName(project, name)`: standard FB, user FUNCTION_BLOCK (`fb` shapes).
// - `checkDataTypes(project)` -> `{ name, message }[]`: every problem of the declared types
//   (unknown names, cycles, empty/duplicate enum values, bad ranges, bad initial values).
// - `leafPaths(project, variable)` -> `{ ok: true, leaves }` | `{ ok: false, message }`: the
//   elementary values a variable of a struct/array type is made of, in storage order, as paths
//   (`P.X`, `A[1]`, `G[2,3]`, `S.Pts[1].X`), each with its elementary type, the declared type name,
//   enum values or subrange, and its initial value text (variable initial, else the type's, else
//   the member's declaration, else the element type's; absent: the type's default, which is an
//   enum's first value and a subrange's lower bound). A variable of
//   an elementary, enum, subrange or alias type has one leaf: its own name.
// - `enumValues(project, typeName)` -> the values of an enum type (or undefined).
// - `parseInitial(text)` / `formatInitial(value)`: IEC initial values: `5`, `GREEN`, `'a,b'`,
//   `[32(0), 30(1)]` (array, `n(v)` repeats v n times), `(X := 1, Y := 2)` (struct), nested.
// Enum values are stored as their index (0 for the first value) in an INT.
import { FB_SIGNATURES } from './blocks';
import { DATE_TYPE_ALIASES, IDENTIFIER_RE, isElementaryType, parseSizedString, type ElementaryType } from './iecTypes';
import type { DataType, DataTypeDef, Pou, Project, ProjectLibrary } from './project';
import { vendorType } from './vendorTypes';

export interface Dim {
  readonly lower: number;
  readonly upper: number;
}

/** A resolved type. `initial` is the type's own initial value text (absent: its default). */
export type TypeShape =
  | { readonly kind: 'elementary'; readonly name: string; readonly type: ElementaryType; readonly initial?: string }
  | { readonly kind: 'enum'; readonly name: string; readonly values: readonly string[]; readonly initial?: string }
  | {
      readonly kind: 'subrange';
      readonly name: string;
      readonly base: ElementaryType;
      readonly lower: number;
      readonly upper: number;
      readonly initial?: string;
    }
  | {
      readonly kind: 'struct';
      readonly name: string;
      readonly members: readonly { readonly name: string; readonly type: TypeShape; readonly initial?: string }[];
      readonly initial?: string;
    }
  | { readonly kind: 'array'; readonly name: string; readonly dims: readonly Dim[]; readonly of: TypeShape; readonly initial?: string }
  | { readonly kind: 'fb'; readonly name: string };

export type Resolution = { ok: true; shape: TypeShape } | { ok: false; message: string };

/** The elementary type used to store an enum value (its index). */
export const ENUM_STORAGE: ElementaryType = 'INT';

/** The project's data type of that name, else a vendor type. */
export function findDataType(project: Pick<Project, 'dataTypes'>, name: string): DataType | undefined {
  const key = name.trim().toUpperCase();
  const same = (d: DataType) => d.name.toUpperCase() === key;
  return (
    project.dataTypes?.find(same) ??
    librariesOf(project)
      .flatMap((l) => l.dataTypes ?? [])
      .find(same) ??
    vendorType(key)
  );
}

/** The libraries kept with the project (libraries.ts), when the object given is a whole project. */
const librariesOf = (project: object): readonly ProjectLibrary[] => (project as Pick<Project, 'libraries'>).libraries ?? [];

export function isFbTypeName(project: Pick<Project, 'pous'>, name: string): boolean {
  const key = name.trim().toUpperCase();
  const fb = (p: Pou) => p.kind === 'FUNCTION_BLOCK' && p.name.toUpperCase() === key;
  return FB_SIGNATURES.some((s) => s.name === key) || project.pous.some(fb) || librariesOf(project).some((l) => l.pous.some(fb));
}

const ARRAY_RE = /^ARRAY\s*\[(.*?)\]\s*OF\s+(.+)$/is;
const STRUCT_RE = /^STRUCT\b([\s\S]*)\bEND_STRUCT\s*;?$/i;
const ENUM_RE = /^\(\s*[A-Za-z_][A-Za-z0-9_]*\s*(,\s*[A-Za-z_][A-Za-z0-9_]*\s*)*\)$/;
const SUBRANGE_RE = /^([A-Za-z_][A-Za-z0-9_]*)\s*\(\s*([+-]?\d+)\s*\.\.\s*([+-]?\d+)\s*\)$/;

type AnonymousDef = Extract<DataTypeDef, { kind: 'struct' | 'enum' | 'subrange' }>;

/**
 * The definition an anonymous type text declares: `STRUCT X : INT; Y : INT := 5; END_STRUCT`,
 * `(Idle, Run, Fault)`, `INT (0..100)`; a message when it is such a text but malformed; undefined
 * otherwise (a type name, an elementary type, an ARRAY).
 */
export function anonymousType(text: string): AnonymousDef | string | undefined {
  const t = text.trim();
  if (ENUM_RE.test(t)) return { kind: 'enum', values: t.slice(1, -1).split(',').map((v) => v.trim()) };
  const sub = SUBRANGE_RE.exec(t);
  if (sub) return { kind: 'subrange', base: sub[1]!.toUpperCase(), lower: Number(sub[2]), upper: Number(sub[3]) };
  const st = STRUCT_RE.exec(t);
  if (!st) return /^STRUCT\b/i.test(t) ? `${t}: a structure ends with END_STRUCT` : undefined;
  const members: { name: string; type: string; initial?: string }[] = [];
  for (const part of splitTop(st[1]!, ';')) {
    if (part.trim() === '') continue;
    const m = /^\s*([A-Za-z_][A-Za-z0-9_]*)\s*:(?!=)([\s\S]*)$/.exec(part);
    if (!m) return `"${part.trim()}" is not a member like X : INT`;
    const [type, ...init] = splitTop(m[2]!, ':=');
    if (!type || type.trim() === '') return `the member ${m[1]} has no type`;
    members.push({ name: m[1]!, type: type.trim(), ...(init.length ? { initial: init.join(':=').trim() } : {}) });
  }
  if (members.length === 0) return `${t}: a structure has at least one member`;
  return { kind: 'struct', members };
}

/** The canonical text of an anonymous definition (the inverse of `anonymousType`). */
export function anonymousText(def: AnonymousDef): string {
  switch (def.kind) {
    case 'enum':
      return `(${def.values.join(', ')})`;
    case 'subrange':
      return `${def.base} (${def.lower}..${def.upper})`;
    case 'struct':
      return `STRUCT ${def.members.map((m) => `${m.name} : ${m.type}${m.initial !== undefined ? ` := ${m.initial}` : ''}; `).join('')}END_STRUCT`;
  }
}

/** Splits at `sep` outside brackets, parentheses, quotes and nested STRUCT ... END_STRUCT. */
function splitTop(text: string, sep: string): string[] {
  const out: string[] = [];
  let depth = 0;
  let start = 0;
  for (let i = 0; i < text.length; i++) {
    const c = text[i]!;
    if (c === "'" || c === '"') {
      i++;
      while (i < text.length && text[i] !== c) i += text[i] === '$' ? 2 : 1;
      continue;
    }
    if (c === '(' || c === '[') depth++;
    else if (c === ')' || c === ']') depth--;
    else if (/[A-Za-z_]/.test(c) && (i === 0 || !/[A-Za-z0-9_]/.test(text[i - 1]!))) {
      const word = /^[A-Za-z_][A-Za-z0-9_]*/.exec(text.slice(i))![0].toUpperCase();
      if (word === 'STRUCT') depth++;
      else if (word === 'END_STRUCT') depth--;
      i += word.length - 1;
      continue;
    }
    if (depth === 0 && text.startsWith(sep, i)) {
      out.push(text.slice(start, i));
      start = i + sep.length;
      i += sep.length - 1;
    }
  }
  out.push(text.slice(start));
  return out;
}

/** `1..8, 0..3` -> dims, or an error message. */
export function parseDims(text: string): Dim[] | string {
  const dims: Dim[] = [];
  for (const part of text.split(',')) {
    const m = /^\s*([+-]?\d+)\s*\.\.\s*([+-]?\d+)\s*$/.exec(part);
    if (!m) return `"${part.trim()}" is not a range like 1..10`;
    const lower = Number(m[1]);
    const upper = Number(m[2]);
    if (upper < lower) return `the range ${lower}..${upper} is empty (the upper bound is below the lower)`;
    dims.push({ lower, upper });
  }
  return dims;
}

/** The elementary type a type text names (`INT`, `STRING[20]`, `TIME_OF_DAY`). */
export function elementaryOf(text: string): ElementaryType | undefined {
  const upper = text.trim().toUpperCase();
  if (isElementaryType(upper)) return upper;
  if (DATE_TYPE_ALIASES[upper]) return DATE_TYPE_ALIASES[upper];
  return parseSizedString(upper)?.type;
}

const INTEGER_TYPES = new Set(['SINT', 'INT', 'DINT', 'LINT', 'USINT', 'UINT', 'UDINT', 'ULINT', 'BYTE', 'WORD', 'DWORD', 'LWORD']);

/** Resolves a type text over the project's data types (cycles and unknown names are errors). */
export function resolveType(project: Pick<Project, 'dataTypes' | 'pous'>, text: string): Resolution {
  try {
    return { ok: true, shape: resolveIn(project, text.trim(), []) };
  } catch (e) {
    if (e instanceof TypeError_) return { ok: false, message: e.message };
    throw e;
  }
}

class TypeError_ extends Error {}

function resolveIn(project: Pick<Project, 'dataTypes' | 'pous'>, text: string, stack: readonly string[]): TypeShape {
  const elementary = elementaryOf(text);
  if (elementary) return { kind: 'elementary', name: text.toUpperCase(), type: elementary };
  const arr = ARRAY_RE.exec(text);
  if (arr) {
    const dims = parseDims(arr[1]!);
    if (typeof dims === 'string') throw new TypeError_(`${text}: ${dims}`);
    return { kind: 'array', name: text, dims, of: resolveIn(project, arr[2]!.trim(), stack) };
  }
  const anonymous = anonymousType(text);
  if (typeof anonymous === 'string') throw new TypeError_(anonymous);
  if (anonymous) return resolveDef(project, anonymousText(anonymous), anonymous, {}, stack);
  if (isFbTypeName(project, text)) return { kind: 'fb', name: text.toUpperCase() };
  const dt = findDataType(project, text);
  if (!dt) throw new TypeError_(`"${text}" is not a type: not elementary, not a function block and not a data type of the project`);
  const key = dt.name.toUpperCase();
  if (stack.includes(key)) throw new TypeError_(`the data type ${dt.name} contains itself (${[...stack, key].join(' -> ')})`);
  const inner = [...stack, key];
  const initial = dt.initial !== undefined && dt.initial.trim() !== '' ? { initial: dt.initial.trim() } : {};
  return resolveDef(project, dt.name, dt.def, initial, inner);
}

/** The shape of a definition named `name` (a data type's, or an anonymous type's text). */
function resolveDef(
  project: Pick<Project, 'dataTypes' | 'pous'>,
  name: string,
  def: DataTypeDef,
  initial: { initial?: string },
  inner: readonly string[],
): TypeShape {
  switch (def.kind) {
    case 'enum':
      return { kind: 'enum', name, values: def.values, ...initial };
    case 'subrange': {
      const base = resolveIn(project, def.base, inner);
      if (base.kind !== 'elementary' || !INTEGER_TYPES.has(base.type))
        throw new TypeError_(`the subrange ${name} must be of an integer type, not ${def.base}`);
      return { kind: 'subrange', name, base: base.type, lower: def.lower, upper: def.upper, ...initial };
    }
    case 'struct':
      return {
        kind: 'struct',
        name,
        members: def.members.map((m) => ({
          name: m.name,
          type: resolveIn(project, m.type, inner),
          ...(m.initial !== undefined && m.initial.trim() !== '' ? { initial: m.initial.trim() } : {}),
        })),
        ...initial,
      };
    case 'array':
      return { kind: 'array', name, dims: def.dims, of: resolveIn(project, def.of, inner), ...initial };
    case 'alias': {
      const base = resolveIn(project, def.base, inner);
      if (base.kind === 'fb') throw new TypeError_(`the data type ${name} names the function block ${base.name}; declare an instance instead`);
      const own = initial.initial ?? base.initial;
      return { ...base, name, ...(own !== undefined ? { initial: own } : {}) };
    }
  }
}

/** The values of an enum type, or undefined when the name is not an enum. */
export function enumValues(project: Pick<Project, 'dataTypes' | 'pous'>, typeName: string): readonly string[] | undefined {
  const r = resolveType(project, typeName);
  return r.ok && r.shape.kind === 'enum' ? r.shape.values : undefined;
}

// ---- initial values ----

export type InitValue =
  | { readonly k: 'simple'; readonly text: string }
  | { readonly k: 'array'; readonly items: readonly { readonly count: number; readonly value?: InitValue }[] }
  | { readonly k: 'struct'; readonly members: readonly { readonly name: string; readonly value: InitValue }[] };

/** Reads an initial value text; throws nothing, returns a message on error. */
export function parseInitial(text: string): InitValue | { error: string } {
  const p = new InitParser(text);
  try {
    const v = p.value();
    p.skip();
    if (p.i < text.length) return { error: `unexpected "${text.slice(p.i)}" in the initial value ${text}` };
    return v;
  } catch (e) {
    return { error: `${(e as Error).message} in the initial value ${text}` };
  }
}

class InitParser {
  i = 0;
  constructor(private readonly s: string) {}
  skip(): void {
    while (this.i < this.s.length && /\s/.test(this.s[this.i]!)) this.i++;
  }
  private peek(): string {
    this.skip();
    return this.s[this.i] ?? '';
  }
  private expect(c: string): void {
    if (this.peek() !== c) throw new Error(`expected "${c}"`);
    this.i++;
  }
  value(): InitValue {
    const c = this.peek();
    if (c === '[') return this.array();
    if (c === '(' && this.isStruct()) return this.struct();
    return { k: 'simple', text: this.simple() };
  }
  /** `(` starting `(Name :=`. */
  private isStruct(): boolean {
    return /^\(\s*[A-Za-z_][A-Za-z0-9_]*\s*:=/.test(this.s.slice(this.i)) || /^\(\s*\)/.test(this.s.slice(this.i));
  }
  private simple(): string {
    const start = this.i;
    let depth = 0;
    while (this.i < this.s.length) {
      const c = this.s[this.i]!;
      if (c === "'" || c === '"') {
        this.i++;
        while (this.i < this.s.length && this.s[this.i] !== c) this.i += this.s[this.i] === '$' ? 2 : 1;
        this.i++;
        continue;
      }
      if (c === '(') depth++;
      else if (c === ')') {
        if (depth === 0) break;
        depth--;
      } else if ((c === ',' || c === ']') && depth === 0) break;
      this.i++;
    }
    const text = this.s.slice(start, this.i).trim();
    if (text === '') throw new Error('a value is missing');
    return text;
  }
  private array(): InitValue {
    this.expect('[');
    const items: { count: number; value?: InitValue }[] = [];
    if (this.peek() === ']') {
      this.i++;
      return { k: 'array', items };
    }
    for (;;) {
      this.skip();
      const rep = /^(\d+)\s*\(/.exec(this.s.slice(this.i));
      if (rep) {
        this.i += rep[0].length;
        const count = Number(rep[1]);
        if (this.peek() === ')') {
          this.i++;
          items.push({ count });
        } else {
          const value = this.value();
          this.expect(')');
          items.push({ count, value });
        }
      } else items.push({ count: 1, value: this.value() });
      const c = this.peek();
      this.i++;
      if (c === ']') return { k: 'array', items };
      if (c !== ',') throw new Error('expected "," or "]"');
    }
  }
  private struct(): InitValue {
    this.expect('(');
    const members: { name: string; value: InitValue }[] = [];
    if (this.peek() === ')') {
      this.i++;
      return { k: 'struct', members };
    }
    for (;;) {
      this.skip();
      const m = /^([A-Za-z_][A-Za-z0-9_]*)\s*:=/.exec(this.s.slice(this.i));
      if (!m) throw new Error('expected "Member :="');
      this.i += m[0].length;
      members.push({ name: m[1]!, value: this.value() });
      const c = this.peek();
      this.i++;
      if (c === ')') return { k: 'struct', members };
      if (c !== ',') throw new Error('expected "," or ")"');
    }
  }
}

export function formatInitial(v: InitValue): string {
  switch (v.k) {
    case 'simple':
      return v.text;
    case 'array':
      return `[${v.items.map((it) => (it.count === 1 && it.value ? formatInitial(it.value) : `${it.count}(${it.value ? formatInitial(it.value) : ''})`)).join(', ')}]`;
    case 'struct':
      return `(${v.members.map((m) => `${m.name} := ${formatInitial(m.value)}`).join(', ')})`;
  }
}

// ---- leaves ----

export interface Leaf {
  /** `P.X`, `A[1]`, `G[2,3]`, `S.Pts[1].X` (starting with the variable's name). */
  readonly path: string;
  readonly type: ElementaryType;
  /** The declared type name of the leaf (`INT`, `Color`, `Percent`, `HMI_BOOL`). */
  readonly typeName: string;
  readonly enumValues?: readonly string[];
  readonly range?: Dim;
  /** Initial value text; absent: the type's default (the first value of an enum). */
  readonly initial?: string;
}

export type LeafResult = { ok: true; leaves: Leaf[]; shape: TypeShape } | { ok: false; message: string };

/** Number of elements of an array shape. */
export const elementCount = (dims: readonly Dim[]): number => dims.reduce((n, d) => n * (d.upper - d.lower + 1), 1);

/** The index text of element k (row-major, the last index fastest): `2,3`. */
export function indexText(dims: readonly Dim[], k: number): string {
  const out: number[] = [];
  for (let d = dims.length - 1; d >= 0; d--) {
    const size = dims[d]!.upper - dims[d]!.lower + 1;
    out.unshift(dims[d]!.lower + (k % size));
    k = Math.floor(k / size);
  }
  return out.join(',');
}

/** Elements above this many make a variable an error (a guard against typing 1..1000000). */
export const MAX_LEAVES = 100_000;

/** The leaves of a variable (a single leaf for elementary-like types; none for FB instances). */
export function leafPaths(
  project: Pick<Project, 'dataTypes' | 'pous'>,
  variable: { readonly name: string; readonly type: string; readonly initial?: string },
): LeafResult {
  const r = resolveType(project, variable.type);
  if (!r.ok) return r;
  const overlays: InitValue[] = [];
  if (variable.initial !== undefined && variable.initial.trim() !== '') {
    const v = parseInitial(variable.initial);
    if ('error' in v) return { ok: false, message: v.error };
    overlays.push(v);
  }
  const leaves: Leaf[] = [];
  try {
    collect(r.shape, variable.name, overlays, leaves);
  } catch (e) {
    if (e instanceof TypeError_) return { ok: false, message: e.message };
    throw e;
  }
  return { ok: true, leaves, shape: r.shape };
}

function withOwn(shape: TypeShape, overlays: readonly InitValue[]): InitValue[] {
  if (shape.kind === 'fb' || shape.initial === undefined) return [...overlays];
  const v = parseInitial(shape.initial);
  if ('error' in v) throw new TypeError_(`${shape.name}: ${v.error}`);
  return [...overlays, v];
}

function collect(shape: TypeShape, path: string, given: readonly InitValue[], out: Leaf[]): void {
  const overlays = withOwn(shape, given);
  switch (shape.kind) {
    case 'fb':
      return;
    case 'elementary':
    case 'enum':
    case 'subrange': {
      const simple = overlays.find((o) => o.k === 'simple');
      const other = overlays.find((o) => o.k !== 'simple');
      if (!simple && other && overlays.indexOf(other) === 0)
        throw new TypeError_(`${path} is ${shape.name}; its initial value cannot be ${other.k === 'array' ? 'an array' : 'a structure'}`);
      out.push({
        path,
        type: shape.kind === 'elementary' ? shape.type : shape.kind === 'subrange' ? shape.base : ENUM_STORAGE,
        typeName: shape.name,
        ...(shape.kind === 'enum' ? { enumValues: shape.values } : {}),
        ...(shape.kind === 'subrange' ? { range: { lower: shape.lower, upper: shape.upper } } : {}),
        ...(simple && simple.k === 'simple' ? { initial: simple.text } : {}),
      });
      return;
    }
    case 'struct': {
      for (const m of shape.members) {
        const inner: InitValue[] = [];
        for (const o of overlays) {
          if (o.k === 'simple') throw new TypeError_(`${path} is the structure ${shape.name}; write its initial value like (${m.name} := ...)`);
          if (o.k !== 'struct') throw new TypeError_(`${path} is the structure ${shape.name}; its initial value cannot be an array`);
          const hit = o.members.find((x) => x.name.toUpperCase() === m.name.toUpperCase());
          if (hit) inner.push(hit.value);
        }
        if (m.initial !== undefined) {
          const v = parseInitial(m.initial);
          if ('error' in v) throw new TypeError_(`${shape.name}.${m.name}: ${v.error}`);
          inner.push(v);
        }
        collect(m.type, `${path}.${m.name}`, inner, out);
      }
      for (const o of overlays)
        if (o.k === 'struct')
          for (const x of o.members)
            if (!shape.members.some((m) => m.name.toUpperCase() === x.name.toUpperCase()))
              throw new TypeError_(`${path}: the structure ${shape.name} has no member ${x.name}`);
      return;
    }
    case 'array': {
      const n = elementCount(shape.dims);
      if (n > MAX_LEAVES) throw new TypeError_(`${path}: the array ${shape.name} has ${n} elements; the simulator holds at most ${MAX_LEAVES}`);
      const lists = overlays.map((o) => {
        if (o.k !== 'array') throw new TypeError_(`${path} is the array ${shape.name}; write its initial value like [1, 2, 3(0)]`);
        const flat: (InitValue | undefined)[] = [];
        for (const it of o.items) for (let c = 0; c < it.count; c++) flat.push(it.value);
        if (flat.length > n) throw new TypeError_(`${path}: the initial value gives ${flat.length} elements; the array ${shape.name} has ${n}`);
        return flat;
      });
      for (let k = 0; k < n; k++) {
        const inner: InitValue[] = [];
        for (const l of lists) {
          const v = l[k];
          if (v) inner.push(v);
        }
        collect(shape.of, `${path}[${indexText(shape.dims, k)}]`, inner, out);
      }
      return;
    }
  }
}

// ---- checks ----

/** Every problem of the project's declared data types. */
export function checkDataTypes(project: Pick<Project, 'dataTypes' | 'pous'>): { name: string; message: string }[] {
  const out: { name: string; message: string }[] = [];
  const seen = new Set<string>();
  for (const dt of project.dataTypes ?? []) {
    const add = (message: string): void => void out.push({ name: dt.name, message });
    const key = dt.name.toUpperCase();
    if (!IDENTIFIER_RE.test(dt.name)) add(`"${dt.name}" is not a valid type name`);
    if (seen.has(key)) add(`the data type ${dt.name} is declared twice`);
    seen.add(key);
    if (elementaryOf(dt.name) || isFbTypeName(project, dt.name)) add(`the data type ${dt.name} has the name of an elementary type or a function block`);
    const def = dt.def;
    if (def.kind === 'enum') {
      if (def.values.length === 0) add(`the enumeration ${dt.name} has no values`);
      const names = new Set<string>();
      for (const v of def.values) {
        if (!IDENTIFIER_RE.test(v)) add(`the enumeration ${dt.name} has the invalid value "${v}"`);
        if (names.has(v.toUpperCase())) add(`the enumeration ${dt.name} has the value ${v} twice`);
        names.add(v.toUpperCase());
      }
    }
    if (def.kind === 'subrange' && def.upper < def.lower) add(`the subrange ${dt.name} (${def.lower}..${def.upper}) is empty`);
    if (def.kind === 'array' && def.dims.length === 0) add(`the array ${dt.name} has no dimension`);
    if (def.kind === 'array') for (const d of def.dims) if (d.upper < d.lower) add(`the array ${dt.name} has the empty range ${d.lower}..${d.upper}`);
    if (def.kind === 'struct') {
      const names = new Set<string>();
      for (const m of def.members) {
        if (names.has(m.name.toUpperCase())) add(`the structure ${dt.name} has the member ${m.name} twice`);
        names.add(m.name.toUpperCase());
      }
    }
    const r = resolveType(project, dt.name);
    if (!r.ok) {
      add(r.message);
      continue;
    }
    const leaves = leafPaths(project, { name: dt.name, type: dt.name });
    if (!leaves.ok) add(leaves.message);
    else
      for (const l of leaves.leaves) {
        // (An initial value outside a subrange is only a warning where a variable uses it: MATIEC keeps it.)
        if (l.enumValues && l.initial !== undefined && !enumIndexOf(l, l.initial)) add(`${l.path}: ${l.initial} is not a value of ${l.typeName} (${l.enumValues.join(', ')})`);
      }
  }
  return out;
}

/** The index of an enum value text (`GREEN` or `Color#GREEN`) in a leaf's values, 1-based (0: not one). */
export function enumIndexOf(leaf: { readonly enumValues?: readonly string[]; readonly typeName: string }, text: string): number {
  const t = text.trim().toUpperCase();
  // CODESYS qualifies an enum value with a dot: E_STATE.IDLE is E_STATE#IDLE.
  const type = leaf.typeName.toUpperCase();
  if (t.startsWith(`${type}.`)) return enumIndexOf(leaf, `${type}#${t.slice(type.length + 1)}`);
  const hash = t.indexOf('#');
  if (hash >= 0 && t.slice(0, hash) !== leaf.typeName.toUpperCase()) return 0;
  const name = hash >= 0 ? t.slice(hash + 1) : t;
  return (leaf.enumValues?.findIndex((v) => v.toUpperCase() === name) ?? -1) + 1;
}
