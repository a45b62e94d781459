// The variables a program sees (its POU's variables, then the project's globals), where each one
// lives at run time, and how operand text (`Start`, `T1.Q`, `Status.3`, `%IX0.0`, `T#5s`) resolves.
import { blockSignature, isFbType } from '../../model/blocks';
import {
  IDENTIFIER_RE,
  INT_INFO,
  isElementaryType,
  locationAdmits,
  parseLocation,
  type ElementaryType,
  type ParsedLocation,
  type Value,
} from '../../model/iecTypes';
import type { Pou, Project, Variable } from '../../model/project';
import { parseLiteral } from '../values/literals';
import { defaultValue, isBigIntType } from '../values/types';
import type { Reporter } from './report';

/** b: BOOL bytes (Uint8Array); n: other numbers (Float64Array); g: 64-bit integers (bigint[]). */
export type Store = 'b' | 'n' | 'g';

export const storeOf = (t: ElementaryType): Store => (t === 'BOOL' ? 'b' : isBigIntType(t) ? 'g' : 'n');

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
}

export interface FbSymbol {
  readonly kind: 'fb';
  readonly name: string;
  readonly type: string;
  readonly index: number;
  readonly retain: boolean;
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
  | { readonly kind: 'const'; readonly type: ElementaryType; readonly value: Value; readonly text: string };

export type Resolved = { ok: true; access: Access } | { ok: false; message: string; unknown?: boolean };

export const canonicalLocation = (loc: ParsedLocation): string =>
  `%${loc.area}${loc.size}${loc.index}${loc.bit !== undefined ? `.${loc.bit}` : ''}`;

export class SymbolTable {
  readonly vars: VarSymbol[] = [];
  readonly fbs: FbSymbol[] = [];
  readonly counts = { b: 0, n: 0, g: 0 };
  private readonly byName = new Map<string, VarSymbol | FbSymbol>();
  private readonly byLocation = new Map<string, VarSymbol>();

  /** Adds a declaration; returns false (after reporting) when it cannot be used. */
  declare(decl: Variable, global: boolean, r: Reporter): void {
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
    const existing = this.byName.get(key);
    if (existing && (!global || existing.kind === 'fb' || existing.global)) {
      r.error('LD-E10', `${what} is declared twice; variable names must be unique (case does not count)`);
      return;
    }
    if (existing) return; // a POU variable hides the global of the same name
    const type = decl.type.toUpperCase();
    if (isFbType(type)) {
      if (decl.location) r.error('LD-E13', `${what} is a ${type} instance and cannot have a location`);
      if (decl.initial) r.error('LD-E14', `${what} is a ${type} instance and cannot have an initial value`);
      const fb: FbSymbol = { kind: 'fb', name: decl.name, type, index: this.fbs.length, retain: decl.retain };
      this.fbs.push(fb);
      this.byName.set(key, fb);
      return;
    }
    if (!isElementaryType(type)) {
      r.error(
        'LD-E15',
        `${what} has the unknown type "${decl.type}"; use an elementary type (BOOL, INT, TIME, ...) or a standard block (TON, CTU, ...)`,
      );
      return;
    }
    let location: ParsedLocation | undefined;
    if (decl.location !== undefined && decl.location.trim() !== '') {
      location = parseLocation(decl.location);
      if (!location) {
        r.error(
          'LD-E12',
          `${what} has the invalid location "${decl.location}"; write it like %IX0.0, %QX1.7, %MW3 or %ID2`,
        );
        return;
      }
      if (!locationAdmits(location, type)) {
        r.error(
          'LD-E13',
          `${what} is ${type} but its location ${decl.location} holds ${sizeWords(location)}`,
        );
        return;
      }
    }
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
      decl.name,
      type,
      initial,
      decl.retain,
      decl.constant === true,
      location,
      global,
      false,
    );
    if (v.locationText) {
      const other = this.byLocation.get(v.locationText);
      if (other)
        r.warning(
          'LD-W02',
          `${what} shares the location ${v.locationText} with "${other.name}"; both name the same memory`,
        );
      else this.byLocation.set(v.locationText, v);
    }
  }

  private addVar(
    name: string,
    type: ElementaryType,
    initial: Value,
    retain: boolean,
    constant: boolean,
    location: ParsedLocation | undefined,
    global: boolean,
    implicit: boolean,
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
    };
    this.vars.push(v);
    this.byName.set(name.toUpperCase(), v);
    return v;
  }

  lookup(name: string): VarSymbol | FbSymbol | undefined {
    return this.byName.get(name.trim().toUpperCase());
  }

  /** The variable at a location, declaring an implicit one (like %IX0.0 used directly) when none is. */
  atLocation(text: string, createImplicit: boolean): VarSymbol | undefined {
    const loc = parseLocation(text);
    if (!loc) return undefined;
    const key = canonicalLocation(loc);
    const hit = this.byLocation.get(key);
    if (hit || !createImplicit) return hit;
    const type = implicitType(loc);
    const v = this.addVar(key, type, defaultValue(type), false, false, loc, false, true);
    this.byLocation.set(key, v);
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
    const dot = t.lastIndexOf('.');
    if (dot > 0 && IDENTIFIER_RE.test(t.slice(0, dot)) && /^[A-Za-z_0-9]+$/.test(t.slice(dot + 1))) {
      const head = this.lookup(t.slice(0, dot));
      const tail = t.slice(dot + 1);
      if (head?.kind === 'fb') {
        const sig = blockSignature(head.type)!;
        const pinName = tail.toUpperCase();
        const inPin = sig.inputs.find((p) => p.name === pinName);
        const outPin = sig.outputs.find((p) => p.name === pinName);
        const pin = inPin ?? outPin;
        if (!pin)
          return {
            ok: false,
            message: `${head.type} "${head.name}" has no pin ${tail} (pins: ${[...sig.inputs, ...sig.outputs].map((p) => p.name).join(', ')})`,
          };
        return {
          ok: true,
          access: {
            kind: 'pin',
            fb: head,
            pin: pin.name,
            type: pin.type as ElementaryType,
            dir: inPin ? 'in' : 'out',
          },
        };
      }
      if (head?.kind === 'var' && /^\d+$/.test(tail)) {
        const width = head.type in INT_INFO && head.type !== 'BOOL' ? bitWidth(head.type) : 0;
        if (!['BYTE', 'WORD', 'DWORD', 'LWORD'].includes(head.type))
          return {
            ok: false,
            message: `"${head.name}" is ${head.type}; only BYTE, WORD, DWORD and LWORD have addressable bits`,
          };
        const bit = Number(tail);
        if (bit >= width)
          return { ok: false, message: `${head.type} "${head.name}" has bits 0 to ${width - 1}, not ${bit}` };
        return { ok: true, access: { kind: 'bit', v: head, bit, type: 'BOOL' } };
      }
      if (!head) return { ok: false, message: `"${t.slice(0, dot)}" is not declared`, unknown: true };
    }
    const sym = this.lookup(t);
    if (sym?.kind === 'var') return { ok: true, access: { kind: 'var', v: sym, type: sym.type } };
    if (sym?.kind === 'fb')
      return {
        ok: false,
        message: `"${sym.name}" is a ${sym.type} instance, not a value; name one of its pins like ${sym.name}.Q`,
      };
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

/**
 * Builds the symbol table of a POU: its variables first, then the project's globals. A VAR_EXTERNAL
 * declares no storage: it names a global (LD-E16 when there is none, or it has another type).
 */
export function buildSymbols(
  project: Project,
  pou: Pou,
  r: Reporter,
  globalsReporter: Reporter,
): SymbolTable {
  const table = new SymbolTable();
  for (const v of pou.variables) if (v.varClass !== 'external') table.declare(v, false, r);
  for (const v of project.globals) table.declare(v, true, globalsReporter);
  for (const v of pou.variables) if (v.varClass === 'external') checkExternal(table, project, pou, v, r);
  return table;
}

function checkExternal(table: SymbolTable, project: Project, pou: Pou, decl: Variable, r: Reporter): void {
  const what = `the VAR_EXTERNAL "${decl.name}"`;
  const key = decl.name.trim().toUpperCase();
  if (pou.variables.some((v) => v.varClass !== 'external' && v.name.toUpperCase() === key)) {
    r.error(
      'LD-E10',
      `${what} has the name of a variable of the POU; variable names must be unique (case does not count)`,
    );
    return;
  }
  const global = project.globals.find((g) => g.name.toUpperCase() === key);
  if (!global) {
    r.error('LD-E16', `${what} names no global variable; declare "${decl.name}" in the global variables`);
    return;
  }
  const sym = table.lookup(key);
  if (!sym) return; // the global's own declaration is in error (reported with the globals)
  const type = decl.type.trim().toUpperCase();
  if (type !== sym.type)
    r.error('LD-E16', `${what} is declared ${type} but the global variable "${global.name}" is ${sym.type}`);
}
