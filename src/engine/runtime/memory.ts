// The PLC's memory: variable storage, FB instances, edge memories, and access by name
// (`Motor`, `T1.ET`, `Status.3`, `%QX0.0`) for read/write/force.
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { FbInstance } from '../library/fbs';
import { createFb } from '../library/fbs';
import { defaultValue, isSingleByte, isStringType, isValueOfType, normalize, numberRange } from '../values/types';
import type { CompiledProgram } from '../compile/program';
import type { Access, VarSymbol } from '../compile/symbols';

export class Memory {
  readonly b: Uint8Array;
  readonly n: Float64Array;
  /** 64-bit integers (bigint) and STRING/WSTRING values (string): symbols.ts Store 'g'. */
  readonly g: (bigint | string)[];
  readonly fbs: FbInstance[];
  readonly edges: Uint8Array;
  /** A spare slot per store, after the variables: writes to a forced variable land there. */
  readonly sink: { readonly b: number; readonly n: number; readonly g: number };

  constructor(readonly program: CompiledProgram) {
    const { counts, fbs } = program.symbols;
    this.sink = { b: counts.b, n: counts.n, g: counts.g };
    this.b = new Uint8Array(counts.b + 1);
    this.n = new Float64Array(counts.n + 1);
    this.g = new Array<bigint | string>(counts.g + 1).fill(0n);
    this.fbs = fbs.map((f) => {
      const inst = createFb(f.type, program.profile);
      if (!inst) throw new Error(`no implementation for the function block ${f.type}`);
      return inst;
    });
    this.edges = new Uint8Array(Math.max(1, program.edgeCount));
  }

  /** Cold restart: every variable to its initial value, every FB and edge memory reset. With `keep`, a warm restart. */
  initialise(keep?: { vars: ReadonlySet<VarSymbol>; fbs: ReadonlySet<number> }): void {
    for (const v of this.program.symbols.vars) if (!keep?.vars.has(v)) this.store(v, v.initial);
    this.fbs.forEach((fb, i) => {
      if (!keep?.fbs.has(i)) fb.reset();
    });
    this.edges.fill(0);
    for (const d of this.program.dataSlots) {
      const v = defaultValue(d.type);
      // g holds bigints and strings (symbols.ts Store).
      if (d.store === 'g') this.g[d.slot] = v as bigint | string;
      else if (d.store === 'b') this.b[d.slot] = v === true ? 1 : 0;
      else this.n[d.slot] = v as number;
    }
  }

  load(v: VarSymbol): Value {
    switch (v.store) {
      case 'b':
        return this.b[v.slot] === 1;
      case 'n':
        return this.n[v.slot]!;
      case 'g':
        return this.g[v.slot]!;
    }
  }

  /** Stores a value already in the variable's representation. */
  store(v: VarSymbol, value: Value): void {
    switch (v.store) {
      case 'b':
        this.b[v.slot] = value === true ? 1 : 0;
        return;
      case 'n':
        this.n[v.slot] = value as number;
        return;
      case 'g':
        this.g[v.slot] = value as bigint | string;
    }
  }

  read(a: Access): Value {
    switch (a.kind) {
      case 'var':
        return this.load(a.v);
      case 'bit': {
        const word = this.load(a.v);
        return typeof word === 'bigint'
          ? ((word >> BigInt(a.bit)) & 1n) === 1n
          : ((Number(word) >>> a.bit) & 1) === 1;
      }
      case 'pin':
        return this.fbs[a.fb.index]!.get(a.pin);
      case 'const':
        return a.value;
      case 'elem':
        throw new Error(`${a.text}: an element chosen by a variable index has no fixed place`);
    }
  }

  write(a: Access, value: Value): void {
    switch (a.kind) {
      case 'var':
        return this.store(a.v, value);
      case 'bit': {
        const word = this.load(a.v);
        if (typeof word === 'bigint') {
          const mask = 1n << BigInt(a.bit);
          this.store(a.v, value === true ? word | mask : BigInt.asUintN(64, word & ~mask));
        } else {
          const mask = 2 ** a.bit;
          const w = Number(word);
          this.store(a.v, value === true ? (w | mask) >>> 0 : (w & ~mask) >>> 0);
        }
        return;
      }
      case 'pin':
        return this.fbs[a.fb.index]!.set(a.pin, value);
      case 'const':
        throw new Error(`${a.text} is a constant`);
      case 'elem':
        throw new Error(`${a.text}: an element chosen by a variable index has no fixed place`);
    }
  }
}

/**
 * Brings a value given by a user or a tool into a type's representation: BOOL takes booleans
 * (or 0/1), numbers and bigints are wrapped or rounded like a PLC store, strings are cut at
 * STRING_MAX_LEN characters. Throws on a wrong kind.
 */
export function coerce(type: ElementaryType, value: Value, what: string): Value {
  // The usual case first (an input or a sensor written every scan): a whole number in the range of
  // an 8/16/32-bit type is stored as it is (what the steps below give it, -0 as 0).
  if (typeof value === 'number') {
    const range = numberRange(type);
    if (range !== undefined && Number.isInteger(value) && value >= range.min && value <= range.max) return value === 0 ? 0 : value;
  }
  if (isStringType(type)) {
    if (typeof value !== 'string') throw new Error(`${what} is ${type}; ${String(value)} is not text (give a string)`);
    if (type === 'STRING' && !isSingleByte(value))
      throw new Error(`${what} is STRING; it holds single-byte characters (codes 0-255), not ${JSON.stringify(value)}`);
    return normalize(type, value);
  }
  if (typeof value === 'string') throw new Error(`${what} is ${type}; the text ${JSON.stringify(value)} is not a ${type} value`);
  if (type === 'BOOL') {
    if (typeof value === 'boolean') return value;
    if (value === 0 || value === 1 || value === 0n || value === 1n) return value === 1 || value === 1n;
    throw new Error(`${what} is BOOL; ${String(value)} is not a BOOL value (use true/false)`);
  }
  if (typeof value === 'boolean')
    throw new Error(`${what} is ${type}; ${String(value)} is not a ${type} value`);
  if (typeof value === 'number' && Number.isNaN(value) && type !== 'REAL' && type !== 'LREAL')
    throw new Error(`${what} is ${type}; NaN is not a ${type} value`);
  const v = normalize(type, value);
  if (!isValueOfType(type, v)) throw new Error(`${what} is ${type}; ${String(value)} is not a ${type} value`);
  return v;
}
