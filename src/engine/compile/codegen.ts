// Networks -> JavaScript over preallocated storage (BOOL variables in a Uint8Array, other numbers
// in a Float64Array, 64-bit integers in an array of bigints, FB instances as objects).
//
// Each network becomes a straight-line block whose operands are parameters: every variable slot,
// edge memory, FB instance, numeric literal and jump target is read from `P[p + k]` (integers) or
// `V[p + k]` (numbers), where p is the network's offset in the parameter tables. Networks with the
// same structure therefore produce the same text (a *shape*) and share one piece of code; see
// dispatch.ts, which turns the shapes into `switch` cases of a few dispatch loops. Power-flow nets
// are locals (0/1); nothing is allocated while a scan runs.
// This file writes the statements of each element (emitOp); operands are read and written through
// the Emitter (emitter.ts); what a program's code shares (constants, units, straight bodies) is in
// programConstants.ts.
import type { ArgIR, NetworkIR, Op, OutIR, Source } from './ir';
import type { Access } from './symbols';
import { defaultValue } from '../values/types';
import { emitChart } from '../sfc/codegen';
import { emitSt } from '../st/emit';
import { singleWriterNets, writtenNets } from './nets';
import type { ProgramConstants } from './programConstants';
import { Emitter, type CodeMode, type WriteParam } from './emitter';

/** Power-flow nets packed per 32-bit word of the snapshot array W. */
export const NETS_PER_WORD = 31;

/** The statement running units [first, end) (rewritten to `yield* X.stepLate(` for stepping). */
export const LATE_TEXT = 'X.late(';
export const STEP_LATE_TEXT = 'yield* X.stepLate(';

export interface NetworkCode {
  /** The network's statements; identical for networks of the same shape. */
  readonly text: string;
  /** Parameter k: P value (slots, indices) and V value (numeric literals). */
  readonly ints: readonly number[];
  readonly reals: readonly number[];
  readonly writes: readonly WriteParam[];
  /** Sizes of the argument arrays `$A0`, `$A1`... the text fills before `impl` calls. */
  readonly arrays: readonly number[];
}

/**
 * Most operations of one ST body with the bodies it calls written in place (as a segment of LD
 * networks, segments.ts SEGMENT_OPS): past it, its calls run their bodies as nested ranges, so the
 * JavaScript function stays small enough for V8 to optimise.
 */
export const ST_INLINE_OPS = 400;

/**
 * The code of one network, run inside a dispatch loop where `i` is the network, `p` its parameter
 * offset and `t`, `r`, `eno`, `go`, `next` scratch locals. A powered jump or RETURN returns the
 * target (or -1) once the whole network has been evaluated, with S[0] = this network. The network packs its power-flow nets into W (NETS_PER_WORD bits per word).
 */
export function generateNetwork(
  ir: NetworkIR,
  pc: ProgramConstants,
  firstWord: number,
  mode: CodeMode = { kind: 'shared' },
): NetworkCode {
  const em = new Emitter(pc, mode);
  emitNetwork(em, ir, firstWord, mode.kind === 'inline' ? String(ir.index) : 'i');
  return codeOf(em);
}

/**
 * openplc profile: the code of a unit (see bodyUnits): operations of network `ir` run elsewhere in
 * its POU body. The network's nets are read back from its power words (a late block may read a
 * BOOL output computed by its coils; an early segment one computed by an earlier segment), updated,
 * and written back for the power display. An early unit runs before the network's own code in the
 * scan: the nets it writes start at 0, not at the previous scan's values.
 */
export function generateUnit(ir: NetworkIR, ops: readonly Op[], early: boolean, pc: ProgramConstants, firstWord: number): NetworkCode {
  const em = new Emitter(pc, { kind: 'shared' });
  const L = em.lines;
  em.rails = new Set(ir.railNets);
  em.single = singleWriterNets(ir, ops);
  const live = Array.from({ length: ir.netCount }, (_, i) => i).filter((i) => !em.rails.has(i));
  const fresh = early ? writtenNets(ops) : new Set<number>();
  for (let w = 0; w * NETS_PER_WORD < ir.netCount; w++) {
    const mine = live.filter((i) => Math.floor(i / NETS_PER_WORD) === w);
    if (!mine.length) continue;
    L.push(`const w${w} = W[${em.p(firstWord + w)}];`);
    L.push(`let ${mine.map((i) => (fresh.has(i) ? `n${i} = 0` : `n${i} = (w${w} >>> ${i % NETS_PER_WORD}) & 1`)).join(', ')};`);
  }
  const { rails, single } = em;
  for (const op of ops) {
    emitOp(em, op);
    em.rails = rails;
    em.single = single;
  }
  packWords(em, live, ir.netCount, firstWord);
  return codeOf(em);
}

function codeOf(em: Emitter): NetworkCode {
  return {
    text: em.lines.filter((l) => l !== '').join('\n'),
    ints: em.ints,
    reals: em.reals,
    writes: em.writes,
    arrays: em.arrays,
  };
}

/** A network's statements, into `em.lines` (`idx`: the expression of its index, for jumps). */
function emitNetwork(em: Emitter, ir: NetworkIR, firstWord: number, idx: string): void {
  const L = em.lines;
  const rails = new Set(ir.railNets);
  const single = singleWriterNets(ir);
  em.rails = rails;
  em.single = single;
  const live = Array.from({ length: ir.netCount }, (_, i) => i).filter((i) => !rails.has(i));
  // openplc: the instances with an executionOrderId, before everything else of the body (their units, see bodyUnits).
  if (ir.runEarly?.length) {
    const [first, end] = em.pc.units(ir.index, 'early');
    L.push(`${LATE_TEXT}${em.p(first)}, ${em.p(end)}, now, scan);`);
  }
  // Nets an early unit of this network wrote this scan are read back from the power words.
  const before = ir.early?.length ? writtenNets(ir.early.flat()) : undefined;
  const word = (i: number) => `((W[${em.p(firstWord + Math.floor(i / NETS_PER_WORD))}] >>> ${i % NETS_PER_WORD}) & 1)`;
  if (live.length) L.push(`let ${live.map((i) => `n${i} = ${before?.has(i) ? word(i) : '0'}`).join(', ')};`);
  const controls = ir.ops.some((op) => op.op === 'jump' || op.op === 'return');
  if (controls) L.push(`go = 0; next = ${idx} + 1;`);
  for (const op of ir.ops) {
    emitOp(em, op);
    // A body written in place changed the per-network facts: restore this network's.
    em.rails = rails;
    em.single = single;
  }
  packWords(em, live, ir.netCount, firstWord);
  // openplc: the body's late blocks, after every coil of the body (their units, see bodyUnits).
  if (ir.runLate?.length) {
    const [first, end] = em.pc.units(ir.index, 'late');
    L.push(`${LATE_TEXT}${em.p(first)}, ${em.p(end)}, now, scan);`);
  }
  if (controls) L.push(`if (next !== ${idx} + 1) { S[0] = ${idx}; return next; }`);
}

/** Packs nets [0, count) minus rails into snapshot words `W[first + w]`. */
function packWords(em: Emitter, live: readonly number[], count: number, firstWord: number): void {
  for (let w = 0; w * NETS_PER_WORD < count; w++) {
    const bits = live
      .filter((i) => Math.floor(i / NETS_PER_WORD) === w)
      .map((i) => (i % NETS_PER_WORD ? `(n${i} << ${i % NETS_PER_WORD})` : `n${i}`));
    em.lines.push(`W[${em.p(firstWord + w)}] = ${bits.length ? bits.join(' | ') : '0'};`);
  }
}

/** The networks of a straight body, each in a block of its own, marked as run in this scan. */
function inlineBody(em: Emitter, first: number, end: number): string[] {
  const { networks, words } = em.pc.program!;
  const saved = { lines: em.lines, fbLocals: em.fbLocals, fbPrefix: em.fbPrefix, rails: em.rails, single: em.single };
  em.lines = [];
  em.depth++;
  em.fbLocals = new Map();
  em.fbPrefix = `F${em.depth}_`;
  for (let i = first; i < end; i++) {
    // Each network is a block of its own: its FB locals are declared in it (not reused from the previous one).
    em.fbLocals = new Map();
    em.lines.push(`{ R[${em.p(i)}] = scan;`);
    emitNetwork(em, networks[i]!, words[i]!, String(i));
    em.lines.push('}');
  }
  const out = em.lines;
  em.lines = saved.lines;
  em.fbLocals = saved.fbLocals;
  em.fbPrefix = saved.fbPrefix;
  // The caller's network facts: its EN and outputs are written after the body.
  em.rails = saved.rails;
  em.single = saved.single;
  em.depth--;
  return out;
}

const and = (a: string, b: string): string => (a === '1' ? b : b === '1' ? a : `${a} & ${b}`);

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
        case 'N': {
          const e = em.p(op.edge!);
          return void L.push(
            op.contact === 'P' ? `t = ${v};` : `t = ${v} ^ 1;`,
            em.setNet(o, and(i, `t & (e[${e}] ^ 1)`)),
            `e[${e}] = t;`,
            tail,
          );
        }
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
        case 'P': {
          const e = em.p(op.edge!);
          L.push(`t = ${i} & (e[${e}] ^ 1); e[${e}] = ${i}; ${em.writeBit(op.dst, 't')}`);
          break;
        }
        case 'N': {
          const e = em.p(op.edge!);
          L.push(`t = ${i} ^ 1; r = t & (e[${e}] ^ 1); e[${e}] = t; ${em.writeBit(op.dst, 'r')}`);
          break;
        }
      }
      if (op.outNet !== op.inNet) L.push(em.setNet(op.outNet, i));
      return;
    }
    case 'pass':
      return void L.push(em.setNet(op.outNet, em.net(op.inNet)));
    case 'jump':
      return void L.push(`if (${em.net(op.inNet)} && go === 0) { go = 1; next = ${em.p(op.target)}; }`);
    case 'return':
      return void L.push(`if (${em.net(op.inNet)} && go === 0) { go = 1; next = -1; }`);
    case 'function':
      return emitFunction(em, op);
    case 'fb':
      return emitFb(em, op);
    case 'call':
      return emitCall(em, op);
    case 'st': {
      let budget = ST_INLINE_OPS - op.weight;
      return emitSt(em, op, (first, end) => {
        const ops = em.pc.inlinedOps(first, end);
        if (ops !== undefined && (budget -= ops) >= 0) return inlineBody(em, first, end);
        return [`${CALL_TEXT}${em.p(first)}, ${em.p(end)}, now, scan);`];
      }, !em.pc.inlineCalls);
    }
    case 'sfc':
      return emitChart(em, op.chart, (b) => runBody(em, b.first, b.end), L);
  }
}

/** The statement running a body [first, end) (rewritten to `yield* X.stepCall(` for stepping). */
export const CALL_TEXT = 'X.call(';
export const STEP_CALL_TEXT = 'yield* X.stepCall(';

/** The statements running a body [first, end): written in place when straight, else through `X.call`. */
function runBody(em: Emitter, first: number, end: number): string[] {
  return em.pc.inlines(first, end) ? inlineBody(em, first, end) : [`${CALL_TEXT}${em.p(first)}, ${em.p(end)}, now, scan);`];
}

function emitCall(em: Emitter, op: Extract<Op, { op: 'call' }>): void {
  const L = em.lines;
  const body: string[] = [];
  // An FB call assigns its inputs whatever EN is (they are the instance's, as EN is); the body tests EN.
  const inputs = op.kind === 'fb' ? L : body;
  for (const a of op.assigns) inputs.push(em.writeValue(a.dst, em.readValue(a.src, a.dst.type), a.dst.type));
  for (const i of op.inits) body.push(em.writeValue(i.dst, em.constant(i.value), i.dst.type));
  if (em.pc.inlines(op.first, op.end)) body.push(...inlineBody(em, op.first, op.end));
  else body.push(`${CALL_TEXT}${em.p(op.first)}, ${em.p(op.end)}, now, scan);`);
  const outs: string[] = [];
  for (const o of op.outs)
    emitOutput(em, o.out, em.readValue({ from: 'access', access: o.src }, o.out.type), outs);
  // A function's outputs are assigned only when it ran; an FB's are read after the call either way.
  if (op.kind === 'function') body.push(...outs);
  const en = enOf(em, op.en, op.enMemory, L);
  if (en === undefined) L.push(...body, op.eno ? 'eno = 1;' : '');
  else L.push(`if (${en}) {`, ...body, 'eno = 1; } else { eno = 0; }');
  if (op.kind === 'fb') L.push(...outs);
  if (op.eno) emitOutput(em, op.eno, 'eno', L);
}

/**
 * The expression of an FB call's EN (undefined: it always runs). With the instance's kept EN
 * (`memory`, "EN was OFF"): a call given EN stores it first, one without reads what was kept.
 */
function enOf(em: Emitter, en: Source | undefined, memory: Access | undefined, L: string[]): string | undefined {
  const given = en ? (en.from === 'power' ? em.net(en.net) : em.readValue(en, 'BOOL')) : undefined;
  if (!memory) return given;
  if (given !== undefined) L.push(em.writeValue(memory, `!(${given})`, 'BOOL'));
  return `!${em.readValue({ from: 'access', access: memory }, 'BOOL')}`;
}

function argExprs(em: Emitter, args: readonly ArgIR[]): string[] {
  return args.map((a) => em.readValue(a.src, a.type));
}

function emitOutput(em: Emitter, out: OutIR, value: string, lines: string[]): void {
  if (out.net !== undefined) lines.push(em.setNet(out.net, `(${value}) ? 1 : 0`));
  if (out.data) lines.push(`${out.data.store}[${em.p(out.data.slot)}] = ${value};`);
  if (out.dst) lines.push(em.writeValue(out.dst, value, out.type));
}

function emitFunction(em: Emitter, op: Extract<Op, { op: 'function' }>): void {
  const L = em.lines;
  em.pc.functionsUsed.add(op.fn);
  const fn = `Cfn${op.fn}`;
  const args = argExprs(em, op.args);
  const resolved = em.pc.functions[op.fn]!;
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
  // A function's output variable is assigned only when ENO is ON: an error (DIV by zero, MUX out of
  // range) leaves the variable as it was. openplc: Beremiz writes that `IF ENO` only when EN is
  // connected; without EN, MATIEC's error value (the type's initial value) is written.
  const { dst, ...wired } = op.out;
  emitOutput(em, wired, 'r', body);
  if (dst) {
    const write = em.writeValue(dst, 'r', op.out.type);
    body.push(op.matiecOutputs && en === undefined ? write : `if (eno) { ${write} }`);
  }
  // openplc, EN OFF: MATIEC's function returned its initial value, which a block wired to the
  // output reads (a BOOL output's net is OFF already).
  const off: string[] = ['eno = 0;'];
  if (op.matiecOutputs && wired.data) emitOutput(em, { pin: wired.pin, type: wired.type, data: wired.data }, em.constant(defaultValue(op.out.type)), off);
  if (en === undefined) L.push(...body);
  else L.push(`if (${en}) { ${body.filter((l) => l !== '').join(' ')} } else { ${off.join(' ')} }`);
  emitOutput(em, op.eno, 'eno', L);
}

function emitFb(em: Emitter, op: Extract<Op, { op: 'fb' }>): void {
  const L = em.lines;
  const f = em.fbRef(op.fb);
  const body: string[] = [];
  // The inputs are assigned whatever EN is (they are the instance's, as EN is); the body tests EN.
  for (const a of op.args) L.push(`${f}.${a.pin} = ${em.readValue(a.src, a.type)};`);
  body.push(`${f}.execute(now);`);
  // EN OFF (execution control): not executed, outputs kept, ENO OFF.
  const en = enOf(em, op.en, op.enMemory, L);
  if (en === undefined) L.push(...body, op.eno ? 'eno = 1;' : '');
  else L.push(`if (${en}) {`, ...body, 'eno = 1; } else { eno = 0; }');
  for (const out of op.outs) emitOutput(em, out, `${f}.${out.pin}`, L);
  if (op.eno) emitOutput(em, op.eno, 'eno', L);
}
