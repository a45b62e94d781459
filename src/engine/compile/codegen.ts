// Networks -> straight-line JavaScript over preallocated storage (BOOL variables in a Uint8Array,
// other numbers in a Float64Array, 64-bit integers in an array of bigints, FB instances as
// objects). A run of networks becomes one function returning the index of the next network to
// run (jumps, RETURN). Power-flow nets are locals (0/1); nothing is allocated while a scan runs.
import type { ElementaryType, Value } from '../../model/iecTypes';
import type { ResolvedFunction } from '../library/fnTypes';
import type { ArgIR, NetworkIR, Op, OutIR, Source } from './ir';
import { storeOf, type Access } from './symbols';

/** What the generated factory receives, in this order. */
export const FACTORY_PARAMS = ['b', 'n', 'g', 'fb', 'fns', 'e', 'W', 'K', 'ctx', 'R', 'C'] as const;

/** Power-flow nets packed per 32-bit word of the snapshot array W. */
export const NETS_PER_WORD = 31;

export interface GeneratedNetwork {
  /** Body of `new Function(...FACTORY_PARAMS, body)`; returns the segment function `(now, scan) => next`. */
  readonly body: string;
  /** Values the code reads from K (bigints and non-finite numbers). */
  readonly constants: readonly Value[];
}

/** Slots whose program writes are suppressed because the variable is forced: `b:3`, `n:12`, `g:0`. */
export type ForcedSlots = ReadonlySet<string>;

export const slotKey = (store: string, slot: number): string => `${store}:${slot}`;

class Emitter {
  readonly head: string[] = [];
  readonly lines: string[] = [];
  readonly constants: Value[] = [];
  private readonly hoisted = new Map<string, string>();
  private argArrays = 0;
  constructor(
    private readonly forced: ForcedSlots,
    readonly functions: readonly ResolvedFunction[],
  ) {}

  /** Per network: nets holding a left-rail point (constant 1) and nets with one unconditional writer. */
  rails: ReadonlySet<number> = new Set();
  single: ReadonlySet<number> = new Set();

  /** The expression of a power-flow net. */
  net(i: number): string {
    return this.rails.has(i) ? '1' : `n${i}`;
  }
  /** Statement driving a net: `=` when it is the net's only writer, else OR-ed in; nothing on a rail net. */
  setNet(i: number, expr: string): string {
    if (this.rails.has(i)) return '';
    return this.single.has(i) ? `n${i} = ${expr};` : `n${i} |= ${expr};`;
  }

  /** A closure constant for an FB instance, a function or a K value. */
  hoist(expr: string, prefix: string): string {
    let name = this.hoisted.get(expr);
    if (!name) {
      name = `${prefix}${this.hoisted.size}`;
      this.hoisted.set(expr, name);
      this.head.push(`const ${name} = ${expr};`);
    }
    return name;
  }
  constant(v: Value): string {
    if (typeof v === 'boolean') return v ? 'true' : 'false';
    if (typeof v === 'number' && Number.isFinite(v) && !Object.is(v, -0)) return String(v);
    if (typeof v === 'bigint') return `${v}n`;
    this.constants.push(v);
    return this.hoist(`K[${this.constants.length - 1}]`, 'k');
  }
  argArray(n: number): string {
    const name = `A${this.argArrays++}`;
    this.head.push(`const ${name} = new Array(${n}).fill(0);`);
    return name;
  }
  isForced(a: Access): boolean {
    return (a.kind === 'var' || a.kind === 'bit') && this.forced.has(slotKey(a.v.store, a.v.slot));
  }
  fbRef(index: number): string {
    return this.hoist(`fb[${index}]`, 'F');
  }

  /** A BOOL access read as 0/1. */
  readBit(a: Access): string {
    switch (a.kind) {
      case 'var':
        return `b[${a.v.slot}]`;
      case 'bit':
        return a.v.store === 'g'
          ? `Number((g[${a.v.slot}] >> ${a.bit}n) & 1n)`
          : `((n[${a.v.slot}] >>> ${a.bit}) & 1)`;
      case 'pin':
        return `(${this.fbRef(a.fb.index)}.${a.pin} ? 1 : 0)`;
      case 'const':
        return a.value === true ? '1' : '0';
    }
  }

  /** Statement writing a 0/1 expression to a BOOL access (empty when the variable is forced). */
  writeBit(a: Access, x: string): string {
    if (this.isForced(a)) return '';
    switch (a.kind) {
      case 'var':
        return `b[${a.v.slot}] = ${x};`;
      case 'bit': {
        if (a.v.store === 'g') {
          const mask = 1n << BigInt(a.bit);
          return `g[${a.v.slot}] = (${x}) ? (g[${a.v.slot}] | ${mask}n) : (g[${a.v.slot}] & ${BigInt.asUintN(64, ~mask)}n);`;
        }
        const mask = 2 ** a.bit;
        return `n[${a.v.slot}] = (${x}) ? ((n[${a.v.slot}] | ${mask}) >>> 0) : ((n[${a.v.slot}] & ${~mask >>> 0}) >>> 0);`;
      }
      case 'pin':
        return `${this.fbRef(a.fb.index)}.${a.pin} = (${x}) !== 0;`;
      case 'const':
        return '';
    }
  }

  /** A value expression (engine representation: boolean, number or bigint) of the given source. */
  readValue(src: Source, to: ElementaryType): string {
    let expr: string;
    let from: ElementaryType;
    if (src.from === 'power') return this.rails.has(src.net) ? 'true' : `(n${src.net} === 1)`;
    if (src.from === 'data') {
      expr = `${src.store}[${src.slot}]`;
      from = src.type;
    } else {
      const a = src.access;
      from = a.type;
      switch (a.kind) {
        case 'var':
          expr = a.v.store === 'b' ? `(b[${a.v.slot}] === 1)` : `${a.v.store}[${a.v.slot}]`;
          break;
        case 'bit':
          expr = `(${this.readBit(a)} === 1)`;
          break;
        case 'pin':
          expr = `${this.fbRef(a.fb.index)}.${a.pin}`;
          break;
        case 'const':
          return this.constant(a.value);
      }
    }
    return storeOf(from) === 'n' && storeOf(to) === 'g' ? `BigInt(${expr})` : expr;
  }

  /** Statement writing a value expression of type `from` to an access. */
  writeValue(a: Access, x: string, from: ElementaryType): string {
    if (a.type === 'BOOL') return this.writeBit(a, `(${x}) ? 1 : 0`);
    if (this.isForced(a)) return '';
    const v = storeOf(from) === 'n' && storeOf(a.type) === 'g' ? `BigInt(${x})` : x;
    switch (a.kind) {
      case 'var':
        return `${a.v.store}[${a.v.slot}] = ${v};`;
      case 'pin':
        return `${this.fbRef(a.fb.index)}.${a.pin} = ${v};`;
      default:
        return '';
    }
  }
}

/**
 * One function for a run of consecutive networks (a segment): `(now, scan) => next network`.
 * Networks are inlined one after another, so a scan makes one call per segment, not per network.
 * A network whose jump or RETURN fires leaves the segment early. For the watchdog and the
 * snapshot, R[first] records the scan and C[first] how many networks ran; each network packs its
 * power-flow nets into W[words[index]...] (NETS_PER_WORD bits per word).
 */
export function generateSegment(
  irs: readonly NetworkIR[],
  functions: readonly ResolvedFunction[],
  forced: ForcedSlots,
  words: ArrayLike<number>,
): GeneratedNetwork {
  const em = new Emitter(forced, functions);
  const L = em.lines;
  const first = irs[0]!.index;
  L.push('let t = 0, r, eno = 0, next = 0;');
  L.push(`R[${first}] = scan;`);
  irs.forEach((ir, k) => {
    const rails = new Set(ir.railNets);
    em.rails = rails;
    em.single = singleWriterNets(ir);
    const live = Array.from({ length: ir.netCount }, (_, i) => i).filter((i) => !rails.has(i));
    const controls = ir.ops.some((op) => op.op === 'jump' || op.op === 'return');
    L.push(`{ // network ${ir.index + 1}`);
    if (live.length) L.push(`let ${live.map((i) => `n${i} = 0`).join(', ')};`);
    if (controls) L.push(`let go = 0; next = ${ir.index + 1};`);
    for (const op of ir.ops) emitOp(em, op);
    for (let w = 0; w * NETS_PER_WORD < ir.netCount; w++) {
      const bits = live
        .filter((i) => Math.floor(i / NETS_PER_WORD) === w)
        .map((i) => (i % NETS_PER_WORD ? `(n${i} << ${i % NETS_PER_WORD})` : `n${i}`));
      L.push(`W[${words[ir.index]! + w}] = ${bits.length ? bits.join(' | ') : '0'};`);
    }
    if (controls) L.push(`if (next !== ${ir.index + 1}) { C[${first}] = ${k + 1}; return next; }`);
    L.push('}');
  });
  L.push(`C[${first}] = ${irs.length};`);
  L.push(`return ${irs[irs.length - 1]!.index + 1};`);
  const body = [
    '"use strict";',
    ...em.head,
    `return function networks_${first + 1}_to_${irs[irs.length - 1]!.index + 1}(now, scan) {`,
    ...L.filter((l) => l !== '').map((l) => `  ${l}`),
    '};',
  ].join('\n');
  return { body, constants: em.constants };
}

const and = (a: string, b: string): string => (a === '1' ? b : b === '1' ? a : `${a} & ${b}`);

/** Nets written exactly once, unconditionally (function outputs are written only when EN is ON). */
function singleWriterNets(ir: NetworkIR): Set<number> {
  const writes = new Map<number, number>();
  const add = (net: number | undefined, n = 1) => {
    if (net !== undefined) writes.set(net, (writes.get(net) ?? 0) + n);
  };
  for (const op of ir.ops) {
    if (op.op === 'contact') {
      add(op.outNet);
      add(op.ownNet);
    } else if (op.op === 'coil' && op.outNet !== op.inNet) add(op.outNet);
    else if (op.op === 'fb') for (const o of op.outs) add(o.net);
    else if (op.op === 'function') {
      add(op.out.net, 2);
      add(op.eno.net, 2);
    }
  }
  return new Set([...writes].filter(([, n]) => n === 1).map(([net]) => net));
}

function emitOp(em: Emitter, op: Op): void {
  const L = em.lines;
  switch (op.op) {
    case 'contact': {
      const i = em.net(op.inNet);
      const v = op.src ? em.readBit(op.src) : '0';
      // With an own result (other outputs join its right side): `nK = ...; nOut |= nK;`.
      const o = op.ownNet ?? op.outNet;
      const tail = op.ownNet !== undefined ? em.setNet(op.outNet, em.net(op.ownNet)) : '';
      switch (op.contact) {
        case 'NO':
          return void L.push(em.setNet(o, and(i, v)), tail);
        case 'NC':
          return void L.push(em.setNet(o, and(i, `(${v} ^ 1)`)), tail);
        case 'NOT':
          return void L.push(em.setNet(o, `${i} ^ 1`), tail);
        case 'P':
          return void L.push(
            `t = ${v};`,
            em.setNet(o, and(i, `t & (e[${op.edge}] ^ 1)`)),
            `e[${op.edge}] = t;`,
            tail,
          );
        case 'N':
          return void L.push(
            `t = ${v} ^ 1;`,
            em.setNet(o, and(i, `t & (e[${op.edge}] ^ 1)`)),
            `e[${op.edge}] = t;`,
            tail,
          );
      }
      return;
    }
    case 'coil': {
      const i = em.net(op.inNet);
      switch (op.coil) {
        case 'COIL':
        case 'M':
          L.push(em.writeBit(op.dst, i));
          break;
        case 'NEG':
          L.push(em.writeBit(op.dst, `${i} ^ 1`));
          break;
        case 'SET':
        case 'SM':
          L.push(`if (${i}) { ${em.writeBit(op.dst, '1')} }`);
          break;
        case 'RESET':
        case 'RM':
          L.push(`if (${i}) { ${em.writeBit(op.dst, '0')} }`);
          break;
        case 'P':
          L.push(`t = ${i} & (e[${op.edge}] ^ 1); e[${op.edge}] = ${i}; ${em.writeBit(op.dst, 't')}`);
          break;
        case 'N':
          L.push(`t = ${i} ^ 1; r = t & (e[${op.edge}] ^ 1); e[${op.edge}] = t; ${em.writeBit(op.dst, 'r')}`);
          break;
      }
      if (op.outNet !== op.inNet) L.push(em.setNet(op.outNet, i));
      return;
    }
    case 'jump':
      return void L.push(`if (${em.net(op.inNet)} && go === 0) { go = 1; next = ${op.target}; }`);
    case 'return':
      return void L.push(`if (${em.net(op.inNet)} && go === 0) { go = 1; next = -1; }`);
    case 'function':
      return emitFunction(em, op);
    case 'fb':
      return emitFb(em, op);
  }
}

function argExprs(em: Emitter, args: readonly ArgIR[]): string[] {
  return args.map((a) => em.readValue(a.src, a.type));
}

function emitOutput(em: Emitter, out: OutIR, value: string, lines: string[]): void {
  if (out.net !== undefined) lines.push(em.setNet(out.net, `(${value}) ? 1 : 0`));
  if (out.data) lines.push(`${out.data.store}[${out.data.slot}] = ${value};`);
  if (out.dst) lines.push(em.writeValue(out.dst, value, out.type));
}

function emitFunction(em: Emitter, op: Extract<Op, { op: 'function' }>): void {
  const L = em.lines;
  const fn = em.hoist(`fns[${op.fn}]`, 'C');
  const args = argExprs(em, op.args);
  const resolved = em.functions[op.fn]!;
  let call: string;
  // The call form is fixed per function: picked here so the scan has no test and no array to build.
  if (args.length === 1 && resolved.impl1) call = `${fn}.impl1(ctx, ${args[0]})`;
  else if (args.length === 2 && resolved.impl2) call = `${fn}.impl2(ctx, ${args[0]}, ${args[1]})`;
  else {
    const arr = em.argArray(args.length);
    args.forEach((a, i) => L.push(`${arr}[${i}] = ${a};`));
    call = `${fn}.impl(ctx, ${arr})`;
  }
  const en = op.en ? (op.en.from === 'power' ? em.net(op.en.net) : em.readValue(op.en, 'BOOL')) : undefined;
  const body: string[] = ['ctx.error = false;', `r = ${call};`, 'eno = ctx.error ? 0 : 1;'];
  emitOutput(em, op.out, 'r', body);
  if (en === undefined) L.push(...body);
  else L.push(`if (${en}) { ${body.join(' ')} } else { eno = 0; }`);
  emitOutput(em, op.eno, 'eno', L);
}

function emitFb(em: Emitter, op: Extract<Op, { op: 'fb' }>): void {
  const L = em.lines;
  const f = em.fbRef(op.fb);
  for (const a of op.args) L.push(`${f}.${a.pin} = ${em.readValue(a.src, a.type)};`);
  L.push(`${f}.execute(now);`);
  for (const out of op.outs) emitOutput(em, out, `${f}.${out.pin}`, L);
}
