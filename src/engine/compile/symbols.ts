// The variables a program sees (its POU's variables, then the project's globals), where each one
// lives at run time, and how operand text (`Start`, `T1.Q`, `Status.3`, `%IX0.0`, `T#5s`) resolves.
// A POU's table is built by pouSymbols.ts; struct, array and enum variables are declared by
// aggregates.ts; the syntax of a path is split by operandPath.ts.
import { blockSignature } from '../../model/blocks';
import { STANDARD_LIBRARY, type BlockLibrary } from '../../model/library';
import {
  IDENTIFIER_RE,
  INT_INFO,
  STRING_MAX_LEN,
  isElementaryType,
  locationAdmits,
  parseLocation,
  locationText,
  parseSizedString,
  DATE_TYPE_ALIASES,
  type ElementaryType,
  type ParsedLocation,
  type Value,
} from '../../model/iecTypes';
import type { Pou, Project, Variable } from '../../model/project';
import { type Dim } from '../../model/dataTypes';
import { declareDataTyped, describeNode, elementAt, memberOf, type AggNode, type AggSymbol, type IndexTerm } from './aggregates';
import { parseLiteral } from '../values/literals';
import { defaultValue, isBigIntType, isStringType } from '../values/types';
import type { Reporter } from './report';
import { splitPath } from './operandPath';

/**
 * b: BOOL bytes (Uint8Array); n: other numbers (Float64Array); g: values held as JavaScript objects
 * in a plain array: 64-bit integers (bigint) and STRING/WSTRING (string).
 */
export type Store = 'b' | 'n' | 'g';

export const storeOf = (t: ElementaryType): Store =>
  t === 'BOOL' ? 'b' : isBigIntType(t) || isStringType(t) ? 'g' : 'n';

/**
 * The elementary type a declared type text names, or undefined. `STRING[20]` or `STRING(20)` (a
 * declared length, 1 to STRING_MAX_LEN) names STRING: as in MATIEC, whose C STRING always has room
 * for STRING_MAX_LEN characters, the length is kept in the declaration (and exported) but does not
 * cut the values.
 */
export function declaredElementaryType(text: string): { type: ElementaryType } | { error: string } | undefined {
  const upper = text.trim().toUpperCase();
  if (isElementaryType(upper)) return { type: upper };
  if (DATE_TYPE_ALIASES[upper]) return { type: DATE_TYPE_ALIASES[upper] };
  const sized = parseSizedString(upper);
  if (!sized) return undefined;
  if (sized.length < 1 || sized.length > STRING_MAX_LEN)
    return { error: `the length ${sized.length} of ${sized.type} is out of range: a ${sized.type} holds 1 to ${STRING_MAX_LEN} characters` };
  return { type: sized.type };
}

export interface VarSymbol {
  readonly kind: 'var';
  readonly name: string;
  readonly type: ElementaryType;
  readonly store: Store;
  readonly slot: number;
  readonly initial: Value;
  readonly retain: boolean;
  readonly constant: boolean;
  readonly location?: ParsedLocation;
  /** Canonical location text (%IX0.0) when located. */
  readonly locationText?: string;
  /** Declared in the project's globals rather than the POU. */
  readonly global: boolean;
  /** Created for a location used in the program but declared nowhere. */
  readonly implicit: boolean;
  /** A function call's own variable (not listed among the program's variables). */
  readonly hidden?: boolean;
  /** Declared VAR_TEMP (re-initialised on every call of its FB). */
  readonly temp?: boolean;
  /** Declared with a data type (enum, subrange, alias) or a leaf of a struct/array variable. */
  readonly dataType?: DataTypeInfo;
}

/** What a variable's data type adds to its elementary type (aggregates.ts). */
export interface DataTypeInfo {
  /** The declared type name of the value (`Color`, `Percent`, `HMI_BOOL`, `INT` for a struct member). */
  readonly name: string;
  /** An enum: its values (stored as their index). */
  readonly enumValues?: readonly string[];
  /** A subrange: its declared range (checked on literals at compile time; not at run time, as in MATIEC). */
  readonly range?: Dim;
}

export interface FbSymbol {
  readonly kind: 'fb';
  readonly name: string;
  readonly type: string;
  readonly index: number;
  readonly retain: boolean;
}

/**
 * An instance of a user FUNCTION_BLOCK (or a program instance of a configuration): its variables
 * live in the program's stores under path names (`Motor1.Run`, `Motor1.T1`, `Motor1.Inner.Q`);
 * `scope` maps the POU's own names to them.
 */
export interface UfbSymbol {
  readonly kind: 'ufb';
  /** Path as declared: `Motor1`, `Motor1.Inner`. */
  readonly name: string;
  /** The POU's name as declared. */
  readonly type: string;
  readonly pou: Pou;
  readonly scope: SymbolTable;
  readonly retain: boolean;
}

/** A VAR_IN_OUT inside a flattened body: the caller's variable, by reference. */
export interface RefSymbol {
  readonly kind: 'ref';
  readonly name: string;
  readonly access: Access;
}

export type Sym = VarSymbol | FbSymbol | UfbSymbol | RefSymbol | AggSymbol;
export type { AggNode, AggSymbol, IndexTerm } from './aggregates';

/** Storage shared by every scope of one program: variable slots, FB instances, locations, globals. */
export class Storage {
  readonly vars: VarSymbol[] = [];
  readonly fbs: FbSymbol[] = [];
  readonly ufbs: UfbSymbol[] = [];
  readonly counts = { b: 0, n: 0, g: 0 };
  readonly byLocation = new Map<string, VarSymbol>();
  readonly globals = new Map<string, VarSymbol | FbSymbol | UfbSymbol | AggSymbol>();
  /** Struct and array variables of the program (all scopes), in declaration order. */
  readonly aggs: AggSymbol[] = [];
  /**
   * Two variables at one location: a warning (LD-W02, IEC and CODESYS allow it), or under profile
   * openplc an error (LD-E17), as MATIEC refuses it ("invalid location in global location declaration").
   */
  sharedLocation: 'warning' | 'error' = 'warning';
  constructor(
    /** Where data type names resolve (Project.dataTypes; user FB types from its POUs). */
    readonly types: Pick<Project, 'dataTypes' | 'pous'> = { pous: [] },
  ) {}
}

export type Access =
  | { readonly kind: 'var'; readonly v: VarSymbol; readonly type: ElementaryType }
  | { readonly kind: 'bit'; readonly v: VarSymbol; readonly bit: number; readonly type: 'BOOL' }
  | {
      readonly kind: 'pin';

      readonly fb: FbSymbol;
      readonly pin: string;
      readonly type: ElementaryType;
      readonly dir: 'in' | 'out';
    }
  | { readonly kind: 'const'; readonly type: ElementaryType; readonly value: Value; readonly text: string }
  /**
   * ST: an element of an array reached through variable indexes: the slot of `v` (the leaf at the
   * lower bounds) plus, per index, (index - lower) * mult[store]; out of bounds faults (LD-E62).
   */
  | { readonly kind: 'elem'; readonly v: VarSymbol; readonly type: ElementaryType; readonly terms: readonly IndexTerm[]; readonly text: string };

/** The name an access is shown under (the instance's own names: `Out`, `A[i]`, `T1.Q`; a constant's text). */
export function accessName(a: Access): string {
  switch (a.kind) {
    case 'var':
      return a.v.name;
    case 'bit':
      return `${a.v.name}.${a.bit}`;
    case 'pin':
      return `${a.fb.name}.${a.pin}`;
    case 'const':
    case 'elem':
      return a.text;
  }
}

export type Resolved =
  | { ok: true; access: Access }
  /** `aggregate`: the text names a whole struct or array (ST assigns those as a whole). */
  | { ok: false; message: string; unknown?: boolean; aggregate?: AggNode };

export const canonicalLocation = (loc: ParsedLocation): string => locationText(loc);

export class SymbolTable {
  private readonly byName = new Map<string, Sym>();
  /** FB types being instantiated around this scope (an instance of one of them inside would never end). */
  instantiating: ReadonlySet<string> = new Set();

  constructor(
    readonly storage: Storage = new Storage(),
    /** Path prefix of this scope's variables (`Motor1.`), empty for the program. */
    readonly prefix = '',
    readonly library: BlockLibrary = STANDARD_LIBRARY,
    /** Variables of this scope are a function call's own (hidden from the variable list). */
    readonly hidden = false,
  ) {}

  /** Every variable of the program (all scopes), in allocation order. */
  get vars(): VarSymbol[] {
    return this.storage.vars;
  }
  /** Every standard FB instance of the program. */
  get fbs(): FbSymbol[] {
    return this.storage.fbs;
  }
  get counts(): { b: number; n: number; g: number } {
    return this.storage.counts;
  }
  /** Names declared in this scope (not the globals). */
  ownNames(): IterableIterator<[string, Sym]> {
    return this.byName.entries();
  }
  /** A name of this scope only. */
  own(name: string): Sym | undefined {
    return this.byName.get(name.trim().toUpperCase());
  }
  /** A scope with the same names plus `extra` (in-out references of one call). */
  withRefs(extra: ReadonlyMap<string, Sym>): SymbolTable {
    const t = new SymbolTable(this.storage, this.prefix, this.library, this.hidden);
    for (const [k, v] of this.byName) t.byName.set(k, v);
    for (const [k, v] of extra) t.byName.set(k.toUpperCase(), v);
    return t;
  }
  /** Binds a name of this scope to an existing symbol. */
  bind(name: string, sym: Sym): void {
    this.byName.set(name.trim().toUpperCase(), sym);
  }

  /** Adds a declaration; returns false (after reporting) when it cannot be used. */
  declare(decl: Variable, global: boolean, r: Reporter, temp = false): void {
    const what = `the variable "${decl.name}"`;
    if (!IDENTIFIER_RE.test(decl.name) || /__/.test(decl.name) || /_$/.test(decl.name)) {
      r.error(
        'LD-E11',
        `${what} has an invalid name; use a letter or _, then letters, digits and single underscores`,
      );
      return;
    }
    if (['TRUE', 'FALSE'].includes(decl.name.toUpperCase())) {
      r.error('LD-E11', `${what} uses the reserved word ${decl.name.toUpperCase()} as its name`);
      return;
    }
    const key = decl.name.toUpperCase();
    const existing = global ? this.storage.globals.get(key) ?? this.byName.get(key) : this.byName.get(key);
    if (existing && (!global || existing.kind !== 'var' || existing.global)) {
      r.error('LD-E10', `${what} is declared twice; variable names must be unique (case does not count)`);
      return;
    }
    if (existing) return; // a POU variable hides the global of the same name
    const typeText = decl.type.toUpperCase();
    const user = this.library.userPou(typeText);
    if (user && user.kind === 'FUNCTION_BLOCK') {
      if (decl.location) r.error('LD-E13', `${what} is a ${user.name} instance and cannot have a location`);
      if (decl.initial) r.error('LD-E14', `${what} is a ${user.name} instance and cannot have an initial value`);
      if (this.instantiating.has(user.name.toUpperCase())) return; // recursive: LD-E21 reports it
      const u = this.instantiate(user, decl.name, decl.retain);
      if (global) this.storage.globals.set(key, u);
      else this.byName.set(key, u);
      return;
    }
    if (this.library.isFbType(typeText)) {
      if (decl.location) r.error('LD-E13', `${what} is a ${typeText} instance and cannot have a location`);
      if (decl.initial) r.error('LD-E14', `${what} is a ${typeText} instance and cannot have an initial value`);
      const fb: FbSymbol = {
        kind: 'fb',
        name: this.prefix + decl.name,
        type: typeText,
        index: this.fbs.length,
        retain: decl.retain,
      };
      this.fbs.push(fb);
      if (global) this.storage.globals.set(key, fb);
      else this.byName.set(key, fb);
      return;
    }
    const elementary = declaredElementaryType(typeText);
    if (elementary && 'error' in elementary) {
      r.error('LD-E15', `${what}: ${elementary.error}`);
      return;
    }
    if (!elementary) {
      const sym = declareDataTyped(this, decl, global, r, temp);
      if (!sym) return;
      if (global) this.storage.globals.set(key, sym);
      else this.byName.set(key, sym);
      if (sym.kind === 'var') this.noteLocation(sym, what, r);
      return;
    }
    const type = elementary.type;
    const location = this.declaredLocation(decl, type, r);
    if (location === false) return;
    let initial = defaultValue(type);
    if (decl.initial !== undefined && decl.initial.trim() !== '') {
      const lit = parseLiteral(decl.initial, type);
      if (!lit.ok) {
        r.error('LD-E14', `${what} has a bad initial value: ${lit.message}`);
        return;
      }
      initial = lit.value;
    }
    const v = this.addVar(
      this.prefix + decl.name,
      type,
      initial,
      decl.retain,
      decl.constant === true,
      location,
      global,
      false,
      temp,
    );
    if (global) this.storage.globals.set(key, v);
    else this.byName.set(key, v);
    this.noteLocation(v, what, r);
  }

  /** The location of a declaration of `type` (undefined: none; false: reported as an error). */
  declaredLocation(decl: Variable, type: ElementaryType, r: Reporter): ParsedLocation | undefined | false {
    if (decl.location === undefined || decl.location.trim() === '') return undefined;
    const what = `the variable "${decl.name}"`;
    const location = parseLocation(decl.location);
    if (!location) {
      r.error('LD-E12', `${what} has the invalid location "${decl.location}"; write it like %IX0.0, %QX1.7, %MW3 or %ID2`);
      return false;
    }
    if (!locationAdmits(location, type)) {
      r.error('LD-E13', `${what} is ${type} but its location ${decl.location} holds ${sizeWords(location)}`);
      return false;
    }
    if (location.size === 'X' && (location.bit ?? 0) > 7 && !location.levels && location.area !== 'M')
      r.warning(
        'LD-W04',
        `${what} is at bit ${location.bit} of byte ${location.index} (${decl.location}): IEC allows it and MATIEC compiles it, and the simulator keeps it apart from %${location.area}X${location.index + Math.floor(location.bit! / 8)}.${location.bit! % 8}; but OpenPLC's I/O map and the gateway have bits 0..7 only, so no device drives it`,
      );
    return location;
  }

  private noteLocation(v: VarSymbol, what: string, r: Reporter): void {
    if (!v.locationText) return;
    const other = this.storage.byLocation.get(v.locationText);
    if (other && this.storage.sharedLocation === 'error')
      r.error(
        'LD-E17',
        `${what} shares the location ${v.locationText} with "${other.name}": MATIEC refuses two variables at one location ("invalid location in global location declaration"); give each its own address, or use one variable`,
      );
    else if (other)
      r.warning('LD-W02', `${what} shares the location ${v.locationText} with "${other.name}"; both name the same memory`);
    else this.storage.byLocation.set(v.locationText, v);
  }

  /**
   * Allocates an instance of a user FUNCTION_BLOCK (or a program instance): its VAR_INPUT,
   * VAR_OUTPUT, VAR, VAR_TEMP and FB instances, under `path.`. VAR_IN_OUT has no storage (the
   * caller's variable is used) and VAR_EXTERNAL is the global. Declaration errors are reported by
   * the check of the POU itself, so they are not repeated here.
   */
  instantiate(pou: Pou, name: string, retain: boolean): UfbSymbol {
    const scope = new SymbolTable(this.storage, `${this.prefix}${name}.`, this.library, this.hidden);
    scope.instantiating = new Set([...this.instantiating, pou.name.toUpperCase()]);
    const u: UfbSymbol = { kind: 'ufb', name: this.prefix + name, type: pou.name, pou, scope, retain };
    this.storage.ufbs.push(u); // before its nested instances
    const quiet = new QuietReporter();
    for (const v of pou.variables)
      if (v.varClass !== 'external' && v.varClass !== 'inOut')
        scope.declare(retain && !v.retain ? { ...v, retain: true } : v, false, quiet as unknown as Reporter, v.varClass === 'temp');
    return u;
  }

  addVar(
    name: string,
    type: ElementaryType,
    initial: Value,
    retain: boolean,
    constant: boolean,
    location: ParsedLocation | undefined,
    global: boolean,
    implicit: boolean,
    temp = false,
    dataType?: DataTypeInfo,
  ): VarSymbol {
    const store = storeOf(type);
    const v: VarSymbol = {
      kind: 'var',
      name,
      type,
      store,
      slot: this.counts[store]++,
      initial,
      retain,
      constant,
      ...(location ? { location, locationText: canonicalLocation(location) } : {}),
      global,
      implicit,
      ...(this.hidden ? { hidden: true } : {}),
      ...(temp ? { temp: true } : {}),
      ...(dataType ? { dataType } : {}),
    };
    this.storage.vars.push(v);
    return v;
  }

  /** A name of this scope, else a global. */
  lookup(name: string): Sym | undefined {
    const key = name.trim().toUpperCase();
    return this.byName.get(key) ?? this.storage.globals.get(key);
  }

  /** The variable at a location, declaring an implicit one (like %IX0.0 used directly) when none is. */
  atLocation(text: string, createImplicit: boolean): VarSymbol | undefined {
    const loc = parseLocation(text);
    if (!loc) return undefined;
    const key = canonicalLocation(loc);
    const hit = this.storage.byLocation.get(key);
    if (hit || !createImplicit) return hit;
    const type = implicitType(loc);
    const v = this.addVar(key, type, defaultValue(type), false, false, loc, false, true);
    this.storage.byLocation.set(key, v);
    return v;
  }

  /**
   * Resolves operand text: a variable, `Instance.Pin`, a bit `Word.3`, a location, or (when
   * literals are allowed) a literal of the expected type.
   */
  resolve(
    text: string,
    opts: { expected?: ElementaryType; literals: boolean; implicitLocations: boolean },
  ): Resolved {
    const t = text.trim();
    if (t === '') return { ok: false, message: 'no variable is given' };
    if (t.startsWith('%')) {
      const v = this.atLocation(t, opts.implicitLocations);
      if (v) return { ok: true, access: { kind: 'var', v, type: v.type } };
      return parseLocation(t)
        ? { ok: false, message: `no variable is declared at ${t}`, unknown: true }
        : { ok: false, message: `"${t}" is not a valid location (like %IX0.0 or %MW3)` };
    }
    const segs = splitPath(t);
    const first = segs?.[0];
    if (segs && segs.length > 1 && typeof first === 'string' && IDENTIFIER_RE.test(first)) {
      let head: Sym | undefined = this.lookup(first);
      if (!head) return { ok: false, message: `"${first}" is not declared`, unknown: true };
      let path = first;
      for (let k = 1; k < segs.length; k++) {
        const seg = segs[k]!;
        if (head.kind === 'agg') return walkStatic(head.node, path, segs.slice(k));
        if (typeof seg !== 'string') return { ok: false, message: `"${path}" is not an array; it has no elements [${seg.join(',')}]` };
        const tail = seg;
        const last = k === segs.length - 1;
        if (head.kind === 'ref' && head.access.kind === 'var') head = head.access.v;
        if (head.kind === 'ufb') {
          const member: Sym | undefined = head.scope.own(tail);
          if (!member)
            return {
              ok: false,
              message: `${head.type} "${path}" has no variable ${tail} (it has: ${[...head.scope.ownNames()].map(([, m]) => m.name.slice(m.name.lastIndexOf('.') + 1)).join(', ')})`,
            };
          head = member;
          path += `.${tail}`;
          continue;
        }
        if (head.kind === 'fb') {
          if (!last) return { ok: false, message: `"${path}.${tail}" is a pin of ${head.type} "${path}"; it has no members` };
          const sig = blockSignature(head.type)!;
          const pinName = tail.toUpperCase();
          const inPin = sig.inputs.find((p) => p.name === pinName);
          const outPin = sig.outputs.find((p) => p.name === pinName);
          const pin = inPin ?? outPin;
          if (!pin)
            return {
              ok: false,
              message: `${head.type} "${path}" has no pin ${tail} (pins: ${[...sig.inputs, ...sig.outputs].map((p) => p.name).join(', ')})`,
            };
          return {
            ok: true,
            access: { kind: 'pin', fb: head, pin: pin.name, type: pin.type as ElementaryType, dir: inPin ? 'in' : 'out' },
          };
        }
        if (head.kind === 'var' && last && /^\d+$/.test(tail)) {
          const width = head.type in INT_INFO && head.type !== 'BOOL' ? bitWidth(head.type) : 0;
          if (!['BYTE', 'WORD', 'DWORD', 'LWORD'].includes(head.type))
            return {
              ok: false,
              message: `"${path}" is ${head.type}; only BYTE, WORD, DWORD and LWORD have addressable bits`,
            };
          const bit = Number(tail);
          if (bit >= width)
            return { ok: false, message: `${head.type} "${path}" has bits 0 to ${width - 1}, not ${bit}` };
          return { ok: true, access: { kind: 'bit', v: head, bit, type: 'BOOL' } };
        }
        return { ok: false, message: `"${path}" has no member ${tail}` };
      }
      return accessOf(head, path);
    }
    const sym = this.lookup(t);
    if (sym) return accessOf(sym, t);
    if (!opts.literals) {
      return IDENTIFIER_RE.test(t) && !/^(TRUE|FALSE)$/i.test(t)
        ? { ok: false, message: `"${t}" is not declared`, unknown: true }
        : { ok: false, message: `"${t}" is a constant, not a variable` };
    }
    if (IDENTIFIER_RE.test(t) && !/^(TRUE|FALSE)$/i.test(t))
      return { ok: false, message: `"${t}" is not declared`, unknown: true };
    const lit = parseLiteral(t, opts.expected);
    if (!lit.ok) return { ok: false, message: lit.message };
    return { ok: true, access: { kind: 'const', type: lit.type, value: lit.value, text: t } };
  }
}

/** Resolves the rest of a path under a struct/array node: every index constant. */
function walkStatic(start: AggNode, path: string, segs: readonly (string | number[])[]): Resolved {
  let node = start;
  for (const seg of segs) {
    if (node.kind === 'leaf') {
      // a bit of a word member: `P.Flags.3`
      if (typeof seg === 'string' && /^\d+$/.test(seg)) {
        const v = node.v;
        if (!['BYTE', 'WORD', 'DWORD', 'LWORD'].includes(v.type))
          return { ok: false, message: `"${path}" is ${v.type}; only BYTE, WORD, DWORD and LWORD have addressable bits` };
        const bit = Number(seg);
        if (bit >= bitWidth(v.type)) return { ok: false, message: `${v.type} "${path}" has bits 0 to ${bitWidth(v.type) - 1}, not ${bit}` };
        return segs.indexOf(seg) === segs.length - 1
          ? { ok: true, access: { kind: 'bit', v, bit, type: 'BOOL' } }
          : { ok: false, message: `"${path}.${seg}" is a bit; it has no members` };
      }
      return { ok: false, message: `"${path}" is ${describeNode(node)}; it has no ${typeof seg === 'string' ? `member ${seg}` : 'elements'}` };
    }
    if (typeof seg === 'string') {
      if (node.kind !== 'struct') return { ok: false, message: `"${path}" is ${describeNode(node)}; it has no member ${seg} (name an element like ${path}[${node.dims.map((d) => d.lower).join(',')}])` };
      const m = memberOf(node, seg);
      if (!m) return { ok: false, message: `${node.type} "${path}" has no member ${seg} (it has: ${node.members.map((x) => x.name).join(', ')})` };
      node = m;
      path += `.${seg}`;
      continue;
    }
    if (node.kind !== 'array') return { ok: false, message: `"${path}" is ${describeNode(node)}, not an array` };
    const k = elementAt(node, seg, path);
    if (typeof k === 'string') return { ok: false, message: k };
    node = node.elems[k]!;
    path += `[${seg.join(',')}]`;
  }
  if (node.kind === 'leaf') return { ok: true, access: { kind: 'var', v: node.v, type: node.v.type } };
  return { ok: false, message: `"${path}" is ${describeNode(node)}, not a single value; name one of its ${node.kind === 'struct' ? 'members' : 'elements'}`, aggregate: node };
}

function accessOf(sym: Sym, path: string): Resolved {
  switch (sym.kind) {
    case 'agg':
      return {
        ok: false,
        message: `"${path}" is ${describeNode(sym.node)}, not a single value; name one of its ${sym.node.kind === 'struct' ? 'members' : 'elements'}`,
        aggregate: sym.node,
      };
    case 'var':
      return { ok: true, access: { kind: 'var', v: sym, type: sym.type } };
    case 'ref':
      return { ok: true, access: sym.access };
    case 'fb':
      return {
        ok: false,
        message: `"${path}" is a ${sym.type} instance, not a value; name one of its pins like ${path}.Q`,
      };
    case 'ufb':
      return {
        ok: false,
        message: `"${path}" is a ${sym.type} instance, not a value; name one of its variables like ${path}.${sym.scope.ownNames().next().value?.[1].name.split('.').pop() ?? 'X'}`,
      };
  }
}

/** Swallows the diagnostics of an instance's declarations (the POU's own check reports them). */
class QuietReporter {
  errors = 0;
  error(): void {
    this.errors++;
  }
  warning(): void {}
}

const bitWidth = (t: ElementaryType): number =>
  t in INT_INFO ? INT_INFO[t as keyof typeof INT_INFO].bits : 1;

function implicitType(loc: ParsedLocation): ElementaryType {
  switch (loc.size) {
    case 'X':
      return 'BOOL';
    case 'B':
      return 'BYTE';
    case 'W':
      return 'WORD';
    case 'D':
      return 'DWORD';
    case 'L':
      return 'LWORD';
  }
}

function sizeWords(loc: ParsedLocation): string {
  return {
    X: 'one bit (BOOL)',
    B: 'a byte (BYTE, SINT, USINT)',
    W: 'a word (WORD, INT, UINT)',
    D: 'a double word (DWORD, DINT, UDINT, REAL, TIME)',
    L: 'a long word (LWORD, LINT, ULINT, LREAL)',
  }[loc.size];
}
