// How the generated code reads and writes operands (codegen.ts writes the statements): the Emitter
// of one network's code turns variable slots, FB pins, bits, literals and power-flow nets into
// parameters (`P[p + k]`, `V[p + k]`) or literals (CodeMode), and records the slots it writes
// (WriteParam, keyed by slotKey) so forcing can redirect them. st/emit.ts and sfc/codegen.ts
// write their statements through it too.
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { Source } from './ir';
import type { ProgramConstants } from './programConstants';
import { isBigIntType } from '../values/types';
import { storeOf, type Access, type Store } from './symbols';

export const slotKey = (store: string, slot: number): string => `${store}:${slot}`;

/** A parameter holding a variable slot the network writes (pointed elsewhere while the variable is forced). */
export interface WriteParam {
  readonly at: number;
  readonly store: Store;
  readonly slot: number;
}

/**
 * How operands are written: `shared` as parameters (dispatch loops), or `inline` as literals with
 * writes to forced variables sent to the spare slot (straight-line functions, see segments.ts).
 */
export type CodeMode =
  | { readonly kind: 'shared' }
  | {
      readonly kind: 'inline';
      readonly forced: ReadonlySet<string>;
      readonly sink: { readonly b: number; readonly n: number; readonly g: number };
    };

export class Emitter {
  lines: string[] = [];
  readonly ints: number[] = [];
  readonly reals: number[] = [];
  readonly writes: WriteParam[] = [];
  readonly arrays: number[] = [];
  fbLocals = new Map<number, string>();
  /** Prefix of FB locals: bodies written in place declare theirs in a block of their own. */
  fbPrefix = 'F';
  depth = 0;
  /** Per network: nets holding a left-rail point (constant 1) and nets with one unconditional writer. */
  rails: ReadonlySet<number> = new Set();
  single: ReadonlySet<number> = new Set();

  constructor(
    readonly pc: ProgramConstants,
    readonly mode: CodeMode,
  ) {}

  private param(int: number, real = 0): number {
    this.ints.push(int);
    this.reals.push(real);
    return this.ints.length - 1;
  }
  /** An integer parameter (slot, index): `P[p + k]`. */
  p(int: number): string {
    return this.mode.kind === 'inline' ? String(int) : `P[p + ${this.param(int)}]`;
  }
  /** A slot written by the network. */
  w(store: Store, slot: number): string {
    if (this.mode.kind === 'inline')
      return String(this.mode.forced.has(slotKey(store, slot)) ? this.mode.sink[store] : slot);
    const at = this.param(slot);
    this.writes.push({ at, store, slot });
    return `P[p + ${at}]`;
  }

  /** The expression of a power-flow net. */
  net(i: number): string {
    return this.rails.has(i) ? '1' : `n${i}`;
  }
  /** Statement driving a net: `=` when it is the net's only writer, else OR-ed in; nothing on a rail net. */
  setNet(i: number, expr: string): string {
    if (this.rails.has(i)) return '';
    return this.single.has(i) ? `n${i} = ${expr};` : `n${i} |= ${expr};`;
  }

  constant(v: Value): string {
    if (typeof v === 'boolean') return v ? 'true' : 'false';
    if (typeof v === 'number' && Number.isFinite(v) && !Object.is(v, -0))
      return this.mode.kind === 'inline' ? String(v) : `V[p + ${this.param(0, v)}]`;
    if (typeof v === 'bigint') return `${v}n`;
    return this.pc.constant(v);
  }
  argArray(n: number): string {
    this.arrays.push(n);
    return `$A${this.arrays.length - 1}`;
  }
  /** A local holding an FB instance (its type is part of the text, so a shape's sites see one class). */
  fbRef(index: number): string {
    if (this.mode.kind === 'inline') {
      this.pc.fbsUsed.add(index);
      return `F${index}`;
    }
    let name = this.fbLocals.get(index);
    if (!name) {
      name = `${this.fbPrefix}${this.fbLocals.size}`;
      this.fbLocals.set(index, name);
      this.lines.push(`const ${name} = fb[${this.p(index)}]; // ${this.pc.fbTypes[index]}`);
    }
    return name;
  }

  /** A BOOL access read as 0/1. */
  readBit(a: Access): string {
    switch (a.kind) {
      case 'var':
        return `b[${this.p(a.v.slot)}]`;
      case 'bit':
        return a.v.store === 'g'
          ? `Number((g[${this.p(a.v.slot)}] >> ${a.bit}n) & 1n)`
          : `((n[${this.p(a.v.slot)}] >>> ${a.bit}) & 1)`;
      case 'pin':
        return `(${this.fbRef(a.fb.index)}.${a.pin} ? 1 : 0)`;
      case 'const':
        return a.value === true ? '1' : '0';
      case 'elem':
        return `b[${this.elemSlot(a)}]`;
    }
  }

  /** Slot expression of an element chosen by variable indexes (set by the ST emitter, which writes the index code). */
  elemSlot: (a: Extract<Access, { kind: 'elem' }>) => string = (a) => {
    throw new Error(`${a.text}: variable indexes are only compiled in ST bodies`);
  };

  /** Statement writing a 0/1 expression to a BOOL access. */
  writeBit(a: Access, x: string): string {
    switch (a.kind) {
      case 'var':
        return `b[${this.w('b', a.v.slot)}] = ${x};`;
      case 'bit': {
        const s = a.v.slot;
        if (a.v.store === 'g') {
          const mask = 1n << BigInt(a.bit);
          const r = this.p(s);
          return `g[${this.w('g', s)}] = (${x}) ? (g[${r}] | ${mask}n) : (g[${r}] & ${BigInt.asUintN(64, ~mask)}n);`;
        }
        const mask = 2 ** a.bit;
        const r = this.p(s);
        return `n[${this.w('n', s)}] = (${x}) ? ((n[${r}] | ${mask}) >>> 0) : ((n[${r}] & ${~mask >>> 0}) >>> 0);`;
      }
      case 'pin':
        return `${this.fbRef(a.fb.index)}.${a.pin} = (${x}) !== 0;`;
      case 'const':
        return '';
      case 'elem':
        return `b[X.ws('b', ${this.elemSlot(a)})] = ${x};`;
    }
  }

  /** A value expression (engine representation: boolean, number or bigint) of the given source. */
  readValue(src: Source, to: ElementaryType): string {
    let expr: string;
    let from: ElementaryType;
    if (src.from === 'power') return this.rails.has(src.net) ? 'true' : `(n${src.net} === 1)`;
    if (src.from === 'data') {
      expr = `${src.store}[${this.p(src.slot)}]`;
      from = src.type;
    } else {
      const a = src.access;
      from = a.type;
      switch (a.kind) {
        case 'var':
          expr = a.v.store === 'b' ? `(b[${this.p(a.v.slot)}] === 1)` : `${a.v.store}[${this.p(a.v.slot)}]`;
          break;
        case 'bit':
          expr = `(${this.readBit(a)} === 1)`;
          break;
        case 'pin':
          expr = `${this.fbRef(a.fb.index)}.${a.pin}`;
          break;
        case 'const':
          return this.constant(a.value);
        case 'elem':
          expr = a.v.store === 'b' ? `(b[${this.elemSlot(a)}] === 1)` : `${a.v.store}[${this.elemSlot(a)}]`;
          break;
      }
    }
    return storeOf(from) === 'n' && isBigIntType(to) ? `BigInt(${expr})` : expr;
  }

  /** Statement writing a value expression of type `from` to an access. */
  writeValue(a: Access, x: string, from: ElementaryType): string {
    if (a.type === 'BOOL') return this.writeBit(a, `(${x}) ? 1 : 0`);
    const v = storeOf(from) === 'n' && isBigIntType(a.type) ? `BigInt(${x})` : x;
    switch (a.kind) {
      case 'var':
        return `${a.v.store}[${this.w(a.v.store, a.v.slot)}] = ${v};`;
      case 'pin':
        return `${this.fbRef(a.fb.index)}.${a.pin} = ${v};`;
      case 'elem':
        return `${a.v.store}[X.ws('${a.v.store}', ${this.elemSlot(a)})] = ${v};`;
      default:
        return '';
    }
  }
}
